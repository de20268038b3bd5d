// The page's benchmarks (docs/web.md), in Debian's headless chromium, median of 5 each:
//   node bench.js SITE_DIR SANSUI_CLI [RUNS]
// - page load to a 513 x 513 eroded world shown (a fresh browser profile each run: nothing cached);
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

(async () => {
  const { server, url } = await serve(path.resolve(site));
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
  const wasm = fs.readFileSync(path.join(site, 'sansui.wasm'));
  const cliOne = native(1), cliAll = native(0);
  const m = (values) => `${median(values).toFixed(2)} s (runs: ${values.map((v) => v.toFixed(2)).join(', ')})`;
  console.log(`page load to a 513 eroded world shown: ${m(load)}`);
  console.log(`change of H to the 513 world shown again: ${m(redraw)}`);
  console.log(`1025 default erosion in the module: ${m(erosion)}`);
  console.log(`sansui run of the same recipe (writes heightmap.png and .r32): ${cliOne.toFixed(2)} s with 1 thread, ${cliAll.toFixed(2)} s with all`);
  console.log(`ratio module / CLI: ${(median(erosion) / cliOne).toFixed(2)}x (1 thread), ${(median(erosion) / cliAll).toFixed(2)}x (all threads)`);
  console.log(`sansui.wasm: ${(wasm.length / 1e6).toFixed(2)} MB, gzip -9 ${(zlib.gzipSync(wasm, { level: 9 }).length / 1e6).toFixed(2)} MB`);
  fs.rmSync(work, { recursive: true, force: true });
})().catch((error) => {
  console.error(error);
  process.exit(1);
});
