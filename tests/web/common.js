// What the browser tests and benchmarks share (tests/web, docs/web.md): a static server for the
// page on a loopback port, Debian's chromium launched headless with a fresh profile and WebGL2
// on SwiftShader, and helpers that drive the page through its controls.
'use strict';

const fs = require('fs');
const http = require('http');
const os = require('os');
const path = require('path');
const { chromium } = require('playwright-core');

const types = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.wasm': 'application/wasm', '.json': 'application/json' };

/** Serves `root` on 127.0.0.1 (a free port); resolves to { server, url }. */
function serve(root) {
  const server = http.createServer((request, response) => {
    const name = decodeURIComponent(new URL(request.url, 'http://127.0.0.1').pathname);
    const file = path.join(root, name === '/' ? 'index.html' : name);
    if (!file.startsWith(root) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      response.writeHead(404);
      return response.end();
    }
    response.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    fs.createReadStream(file).pipe(response);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve({ server, url: `http://127.0.0.1:${server.address().port}/` })));
}

/** Debian's chromium, headless, as root, with WebGL2 on SwiftShader and nothing of its own online. */
async function launch(downloads) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'sansui-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.SANSUI_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    acceptDownloads: true,
    downloadsPath: downloads,
    viewport: { width: 1280, height: 800 },
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  context.profile = profile;
  return context;
}

async function close(context) {
  await context.close();
  fs.rmSync(context.profile, { recursive: true, force: true });
}

/** Waits until the page has finished more than `builds` builds (or shows a new message). */
async function waitForBuild(page, builds, timeout = 120000) {
  await page.waitForFunction((n) => window.sansuiPage && window.sansuiPage.builds > n && !window.sansuiPage.building,
    builds, { timeout, polling: 50 });
}

async function builds(page) {
  return page.evaluate(() => window.sansuiPage.builds);
}

/** Sets a control the way a user does: types or picks the value, then the change event. */
async function setControl(page, key, value) {
  const selector = `[data-key="${key}"]`;
  const tag = await page.$eval(selector, (e) => `${e.tagName}:${e.type}`);
  if (tag.startsWith('SELECT')) {
    await page.selectOption(selector, String(value));
  } else if (tag.endsWith(':range')) {
    await page.$eval(selector, (e, v) => { e.value = v; e.dispatchEvent(new Event('input')); e.dispatchEvent(new Event('change')); }, String(value));
  } else {
    await page.fill(selector, String(value));
    await page.$eval(selector, (e) => e.dispatchEvent(new Event('change')));
  }
}

/** Sets a control and waits for the world it makes. Returns the seconds from change to picture. */
async function setAndWait(page, key, value) {
  const before = await builds(page);
  const start = Date.now();
  await setControl(page, key, value);
  await waitForBuild(page, before);
  return (Date.now() - start) / 1000;
}

/** The heights the page shows, as the bytes of their float32 samples. */
async function pageHeights(page) {
  const base64 = await page.evaluate(() => {
    const bytes = new Uint8Array(window.sansuiPage.heights.buffer);
    let text = '';
    for (let k = 0; k < bytes.length; k += 0x8000) text += String.fromCharCode.apply(null, bytes.subarray(k, k + 0x8000));
    return btoa(text);
  });
  return Buffer.from(base64, 'base64');
}

function median(values) {
  const sorted = values.slice().sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

module.exports = { serve, launch, close, waitForBuild, builds, setControl, setAndWait, pageHeights, median };
