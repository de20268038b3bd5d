// The page's benchmarks (docs/web.md), in Debian's headless chromium, median of 5 each, for the
// threaded module (the page as served: isolated by its service worker) and the serial one (?serial):
//   node bench.js SITE_DIR SANSUI_CLI [RUNS]
// - page load to a 513 x 513 eroded world shown (a fresh browser profile each run: nothing cached,
//   so the threaded page's load includes registering its service worker and loading once more);
// - a change of H (midpoint.hurst) to the 513 world shown again;
// - a 1025 x 1025 world with the default erosion in the page's module against `sansui run` of the
//   same recipe (the CLI with one thread, as the module, and with all of the machine's);
// - the .wasm's size, gzip -9 and as served.
'use strict';

const { execFileSync } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');
const zlib = require('zlib');
const { serve, launch, close, waitForBuild, setAndWait, median } = require('./common');

const [site, cli, runsText] = process.argv.slice(2);
const runs = Number(runsText || 5);
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'sansui-web-bench-'));

async function measure(url, runs) {
  const load = [], redraw = [], erosion = [];
  let recipe = null;
  for (let run = 0; run < runs; ++run) {
    const context = await launch(work);
    const page = await context.newPage();
    const start = Date.now();
    await page.goto(url);
    await waitForBuild(page, 0);
    load.push((Date.now() - start) / 1000);
    redraw.push(await setAndWait(page, 'midpoint.hurst', [0.6, 0.7, 0.75, 0.65, 0.55][run % 5]));
    // The module's own time for the 1025 world (from the change to the heights, without drawing).
    await setAndWait(page, 'world.size', 1025);
    erosion.push(await page.evaluate(() => window.sansuiPage.facts.heights_seconds));
    if (run === 0) {
      await page.click('#prepare');
      await page.waitForSelector('#download-links a[download="recipe.toml"]', { timeout: 120000 });
      const [file] = await Promise.all([page.waitForEvent('download'), page.click('#download-links a[download="recipe.toml"]')]);
      recipe = path.join(work, 'recipe.toml');
      await file.saveAs(recipe);
    }
    await close(context);
  }
  return { load, redraw, erosion, recipe };
}

(async () => {
  const { server, url } = await serve(path.resolve(site));
  const threaded = await measure(url, runs);
  const serial = await measure(`${url}?serial`, runs);
  const recipe = serial.recipe;
  server.close();
  const native = (threads) => {
    const times = [];
    for (let run = 0; run < runs; ++run) {
      const start = process.hrtime.bigint();
      execFileSync(cli, ['--threads', String(threads), 'run', recipe], { cwd: work, stdio: 'pipe' });
      times.push(Number(process.hrtime.bigint() - start) / 1e9);
    }
    return median(times);
  };
  const cliOne = native(1), cliAll = native(0);
  const m = (values) => `${median(values).toFixed(2)} s (runs: ${values.map((v) => v.toFixed(2)).join(', ')})`;
  for (const [name, figures] of [['threaded module', threaded], ['serial module', serial]]) {
    console.log(`${name}:`);
    console.log(`  page load to a 513 eroded world shown: ${m(figures.load)}`);
    console.log(`  change of H to the 513 world shown again: ${m(figures.redraw)}`);
    console.log(`  1025 default erosion in the module: ${m(figures.erosion)}`);
    console.log(`  ratio module / CLI: ${(median(figures.erosion) / cliOne).toFixed(2)}x (CLI on 1 thread), ${(median(figures.erosion) / cliAll).toFixed(2)}x (all)`);
  }
  console.log(`sansui run of the same recipe (writes heightmap.png and .r32): ${cliOne.toFixed(2)} s with 1 thread, ${cliAll.toFixed(2)} s with all`);
  for (const name of ['sansui.wasm', 'sansui-threads.wasm']) {
    const wasm = fs.readFileSync(path.join(site, name));
    console.log(`${name}: ${(wasm.length / 1e6).toFixed(2)} MB, gzip -9 ${(zlib.gzipSync(wasm, { level: 9 }).length / 1e6).toFixed(2)} MB`);
  }
  fs.rmSync(work, { recursive: true, force: true });
})().catch((error) => {
  console.error(error);
  process.exit(1);
});
