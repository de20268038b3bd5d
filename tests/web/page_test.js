// Browser tests of the page (docs/web.md), run by CTest (label web) through tests/web/run:
//   node page_test.js SITE_DIR SANSUI_CLI
// Loads build-web/web/ in Debian's headless chromium, sets parameters through the controls,
// waits for the picture, reads back the heights and compares them with what `sansui run` makes
// from the page's recipe, bit for bit; checks the 3-D view and the top view are drawn without
// WebGL errors; clicks the downloads; feeds bad input (a broken GeoJSON, a huge size) and checks
// for one message and a page that goes on working; cancels a long step.
'use strict';

const assert = require('assert');
const { execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { serve, launch, close, waitForBuild, builds, setControl, setAndWait, pageHeights } = require('./common');

const [site, cli] = process.argv.slice(2);
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'sansui-web-test-'));
const results = [];

async function test(name, body) {
  const start = Date.now();
  try {
    await body();
    results.push([name, true]);
    console.log(`PASS ${name} (${((Date.now() - start) / 1000).toFixed(1)} s)`);
  } catch (error) {
    results.push([name, false]);
    console.log(`FAIL ${name}: ${error && error.stack ? error.stack : error}`);
  }
}

/** Clicks "Downloads", then the link named `name`; returns the downloaded bytes. Preparing the
 * files took over 60 s once on the 2-core machine under full load: the waits allow 240 s. */
async function download(page, name) {
  if (!(await page.$(`#download-links a[download="${name}"]`))) {
    await page.click('#prepare');
    await page.waitForSelector(`#download-links a[download="${name}"]`, { timeout: 240000 });
  }
  const [file] = await Promise.all([page.waitForEvent('download'), page.click(`#download-links a[download="${name}"]`)]);
  const target = path.join(work, 'page', name);
  fs.mkdirSync(path.dirname(target), { recursive: true });
  await file.saveAs(target);
  return fs.readFileSync(target);
}

/** The spread of the canvas's pixel values: 0 for a blank canvas. */
async function canvasSpread(page, id) {
  return page.evaluate((canvasId) => {
    const source = document.getElementById(canvasId);
    const copy = document.createElement('canvas');
    copy.width = 64;
    copy.height = 64;
    const context = copy.getContext('2d');
    context.drawImage(source, 0, 0, 64, 64);
    const data = context.getImageData(0, 0, 64, 64).data;
    const seen = new Set();
    for (let k = 0; k < data.length; k += 4) seen.add((data[k] >> 3) * 1024 + (data[k + 1] >> 3) * 32 + (data[k + 2] >> 3));
    return seen.size;
  }, id);
}

async function message(page) {
  return page.evaluate(() => (document.getElementById('message').hidden ? '' : document.getElementById('message').textContent));
}

(async () => {
  const { server, url } = await serve(path.resolve(site));
  const context = await launch(path.join(work, 'downloads'));
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('console', (line) => { if (line.type() === 'error') problems.push(`console: ${line.text()}`); });

  await test('the page loads and shows an eroded world', async () => {
    await page.goto(url);
    await waitForBuild(page, 0);
    const facts = await page.evaluate(() => window.sansuiPage.facts);
    assert.strictEqual(facts.width, 513);
    assert.ok(facts.max_m > facts.min_m, 'the heights are not flat');
    const keys = await page.$$eval('[data-key]', (inputs) => inputs.map((i) => i.dataset.key));
    for (const key of ['world.size', 'midpoint.seed', 'midpoint.hurst', 'climate.koppen', 'season.season', 'time.time', 'shape.stage', 'world.sea_level'])
      assert.ok(keys.includes(key), `no control for ${key} (controls: ${keys.join(', ')})`);
  });

  await test('the page isolates itself through its service worker and runs the threaded module', async () => {
    assert.strictEqual(await page.evaluate(() => window.crossOriginIsolated), true, 'not cross-origin isolated');
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    assert.strictEqual(await page.evaluate(() => window.sansuiPage.facts.threads), Math.min(cores, 16));
  });

  let threadedHeights = null;
  await test('controls set the recipe and the heights equal sansui run of the downloaded recipe, bit for bit', async () => {
    await setAndWait(page, 'world.size', 257);
    await setAndWait(page, 'midpoint.seed', 11);
    await setAndWait(page, 'midpoint.hurst', 0.65);
    await setAndWait(page, 'climate.koppen', 'Df');
    await setAndWait(page, 'shape.stage', 'old');
    await setAndWait(page, 'world.sea_level', 12.5);
    const heights = await pageHeights(page);
    assert.strictEqual(heights.length, 257 * 257 * 4);
    const recipe = await download(page, 'recipe.toml');
    assert.match(recipe.toString(), /seed = 11/);
    const r32 = await download(page, 'heightmap.r32');
    const png = await download(page, 'heightmap.png');
    const sidecar = JSON.parse((await download(page, 'heightmap.r32.json')).toString());
    assert.ok(sidecar.provenance && sidecar.provenance.recipe, 'the sidecar holds the recipe');
    assert.ok(r32.equals(heights), 'the downloaded .r32 is the heights the page shows');
    const cliDir = path.join(work, 'cli');
    fs.mkdirSync(cliDir, { recursive: true });
    fs.writeFileSync(path.join(cliDir, 'recipe.toml'), recipe);
    execFileSync(cli, ['run', 'recipe.toml'], { cwd: cliDir, stdio: 'pipe' });
    const native = fs.readFileSync(path.join(cliDir, 'heightmap.r32'));
    assert.strictEqual(native.length, heights.length);
    let differing = 0;
    for (let k = 0; k < native.length; k += 4) if (native.readUInt32LE(k) !== heights.readUInt32LE(k)) differing++;
    assert.strictEqual(differing, 0, `${differing} of ${native.length / 4} samples differ from sansui run's`);
    assert.ok(png.equals(fs.readFileSync(path.join(cliDir, 'heightmap.png'))), "the 16-bit PNG is byte for byte sansui run's");
    threadedHeights = heights;
  });

  await test('the serial module (?serial, as without isolation) makes the same bytes on one thread', async () => {
    const serial = await context.newPage();
    await serial.goto(`${url}?serial`);
    await waitForBuild(serial, 0);
    for (const [key, value] of [['world.size', 257], ['midpoint.seed', 11], ['midpoint.hurst', 0.65], ['climate.koppen', 'Df'], ['shape.stage', 'old'],
      ['world.sea_level', 12.5]])
      await setAndWait(serial, key, value);
    assert.strictEqual(await serial.evaluate(() => window.sansuiPage.facts.threads), 1);
    assert.ok(threadedHeights && (await pageHeights(serial)).equals(threadedHeights), 'the serial and threaded modules differ');
    await serial.close();
  });

  await test('the 3-D view and the top view are drawn, without WebGL errors', async () => {
    await page.evaluate(() => window.SansuiView.draw());
    assert.ok(await canvasSpread(page, 'view') > 20, 'the 3-D view is blank');
    assert.ok(await canvasSpread(page, 'top') > 20, 'the top view is blank');
    assert.deepStrictEqual(await page.evaluate(() => window.SansuiView.errors()), []);
    // Walking: the view changes and stays error-free.
    await page.keyboard.press('w');
    for (let k = 0; k < 5; ++k) await page.keyboard.press('ArrowUp');
    await page.evaluate(() => window.SansuiView.draw());
    assert.ok(await canvasSpread(page, 'view') > 20, 'the walking view is blank');
    await page.keyboard.press('Escape');
    assert.deepStrictEqual(await page.evaluate(() => window.SansuiView.errors()), []);
  });

  await test('the trees the module places are drawn, instanced, once the world has settled', async () => {
    await page.waitForFunction(() => window.sansuiPage.plants > 0, null, { timeout: 60000, polling: 100 });
    const drawn = await page.evaluate(() => window.SansuiView.treesDrawn());
    assert.ok(drawn > 100, `only ${drawn} trees drawn`);
    assert.ok(drawn <= await page.evaluate(() => window.SansuiView.plantBudget()), 'more trees than the view draws well');
    await page.evaluate(() => window.SansuiView.draw());
    assert.deepStrictEqual(await page.evaluate(() => window.SansuiView.errors()), []);
  });

  await test('a huge size shows one message and the page goes on', async () => {
    const before = await builds(page);
    await setControl(page, 'world.size', 16385);
    await page.waitForFunction(() => !document.getElementById('message').hidden);
    assert.match(await message(page), /16385/);
    assert.strictEqual(await page.$eval('[data-key="world.size"]', (e) => e.value), '257', 'the control keeps its value');
    await setAndWait(page, 'midpoint.seed', 12);
    assert.ok((await builds(page)) > before);
    assert.strictEqual(await message(page), '', 'the message goes once a value is accepted');
  });

  await test('a broken GeoJSON shows one message and the page goes on', async () => {
    await page.setInputFiles('#drop-file', { name: 'broken.geojson', mimeType: 'application/geo+json', buffer: Buffer.from('{"type": "Feature", "geometry": {') });
    await page.waitForFunction(() => !document.getElementById('message').hidden);
    assert.match(await message(page), /broken|drawing|JSON|json/);
    await setAndWait(page, 'midpoint.seed', 13);
    assert.strictEqual(await page.evaluate(() => window.sansuiPage.facts.source), 'midpoint');
  });

  await test('a contour drawing grows a mountain', async () => {
    const ring = [];
    for (let k = 0; k < 24; ++k) {
      const a = (2 * Math.PI * k) / 24, r = 1500 + 300 * Math.sin(3 * a);
      ring.push([2000 + r * Math.cos(a), 2000 + r * Math.sin(a)]);
    }
    ring.push(ring[0]);
    const geojson = { type: 'Feature', properties: { elevation: 100 }, geometry: { type: 'Polygon', coordinates: [ring] } };
    const before = await builds(page);
    await page.setInputFiles('#drop-file', { name: 'island.geojson', mimeType: 'application/geo+json', buffer: Buffer.from(JSON.stringify(geojson)) });
    await waitForBuild(page, before);
    const facts = await page.evaluate(() => window.sansuiPage.facts);
    assert.strictEqual(facts.source, 'contour');
    assert.ok(facts.max_m > facts.min_m + 50, `the mountain rises (${facts.min_m}..${facts.max_m} m)`);
  });

  await test('a long step shows progress and cancels', async () => {
    await page.reload();
    await waitForBuild(page, 0);
    await setControl(page, 'world.size', 1025);
    await page.waitForFunction(() => !document.getElementById('progress').hidden && /[1-9]/.test(document.getElementById('progress-text').textContent),
      null, { timeout: 240000 });
    await page.click('#cancel');
    await page.waitForFunction(() => document.getElementById('progress').hidden);
    assert.match(await page.textContent('#status'), /cancelled/);
    // The page goes on, with the values set before the cancel.
    await setAndWait(page, 'world.size', 129);
    assert.strictEqual(await page.evaluate(() => window.sansuiPage.facts.width), 129);
  });

  await test('no page errors', async () => {
    assert.deepStrictEqual(problems, []);
  });

  await close(context);
  server.close();
  fs.rmSync(work, { recursive: true, force: true });
  const passed = results.filter(([, ok]) => ok).length;
  console.log(`${passed} passed, ${results.length - passed} failed`);
  process.exit(passed === results.length ? 0 : 1);
})().catch((error) => {
  console.log(`FAIL the test run: ${error && error.stack ? error.stack : error}`);
  process.exit(1);
});
