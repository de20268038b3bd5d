// The page (docs/web.md): controls made from the library's parameter tables, a worker running
// the WebAssembly module, the 3-D and top views, progress and cancel, downloads, and the drop
// zone for contour drawings. Every number the page shows or downloads comes from the module.
/* global SansuiView */
'use strict';

const page = {
  worker: null,
  nextId: 1,
  pending: new Map(),
  values: [],          // [key, text] the user set, in order: replayed into a new worker after a cancel
  building: false,
  again: false,        // a change arrived during a build: build once more
  builds: 0,           // finished builds (the tests wait on it)
  plants: 0,           // trees drawn with the world last shown (after it, as the module places them)
  plantTimer: null,
  facts: null,
  heights: null,
  contour: null,       // the dropped drawing, while the world is grown from it
  lastError: '',
  ready: null,
};
window.sansuiPage = page;

const $ = (id) => document.getElementById(id);

function showMessage(text) {
  page.lastError = text;
  $('message').textContent = text;
  $('message').hidden = !text;
}

// ?serial: the serial module even where the page could run threads (to compare, or to save memory).
const serialWanted = new URL(window.location.href).searchParams.has('serial');

/**
 * Makes the page cross-origin isolated, so that its worker can run the threaded module, on a
 * server that does not send the headers: registers the page's service worker (isolation.js), which
 * adds them, and loads the page once more under it. Resolves (without isolation) where the browser
 * cannot: no service workers (file://, plain http to another host) or the reload did not isolate.
 */
async function isolate() {
  if (window.crossOriginIsolated || serialWanted || !window.isSecureContext || !navigator.serviceWorker) return;
  if (sessionStorage.getItem('sansui-isolation-tried')) return;
  try {
    await navigator.serviceWorker.register('isolation.js');
    await navigator.serviceWorker.ready;
  } catch (error) {
    return;  // refused (private mode, a policy): serial
  }
  sessionStorage.setItem('sansui-isolation-tried', '1');
  window.location.reload();
  await new Promise(() => {});  // the page is going away
}

function startWorker() {
  page.worker = new Worker(serialWanted ? 'worker.js?serial' : 'worker.js');
  page.worker.onmessage = (event) => {
    const data = event.data;
    if (data.type === 'progress') return showProgress(data.stage, data.fraction);
    const resolve = page.pending.get(data.id);
    page.pending.delete(data.id);
    if (resolve) resolve(data);
  };
  page.worker.onerror = (event) => {
    showMessage(`The module stopped: ${event.message || 'out of memory?'} The page starts it again.`);
    event.preventDefault();
    restartWorker();
  };
}

function call(type, data = {}) {
  const id = page.nextId++;
  return new Promise((resolve) => {
    page.pending.set(id, resolve);
    page.worker.postMessage(Object.assign({ id, type }, data));
  });
}

/** Ends the worker (and the step it runs) and starts a fresh one with the user's values. */
async function restartWorker() {
  page.worker.terminate();
  for (const resolve of page.pending.values()) resolve({ cancelled: true, facts: { error: 'cancelled' } });
  page.pending.clear();
  startWorker();
  if (page.contour) await call('contour', page.contour);
  for (const [key, text] of page.values) await call('set', { key, text });
}

// ---- progress and cancel ----------------------------------------------------------------------

function showProgress(stage, fraction) {
  $('progress').hidden = false;
  $('progress-fill').style.width = `${Math.round(100 * Math.max(0, Math.min(1, fraction)))}%`;
  $('progress-text').textContent = `${stage} ${Math.round(100 * fraction)} %`;
}

$('cancel').addEventListener('click', async () => {
  page.again = false;
  $('status').textContent = 'cancelled: the world shown is the last one finished';
  await restartWorker();
  $('progress').hidden = true;
});

// ---- building ---------------------------------------------------------------------------------

async function build() {
  if (page.building) {
    page.again = true;
    return;
  }
  page.building = true;
  showProgress('starting', 0);
  const started = performance.now();
  const result = await call('build');
  page.building = false;
  $('progress').hidden = true;
  if (result.cancelled) return;
  if (result.facts.error) {
    showMessage(result.facts.error);
  } else {
    page.facts = result.facts;
    page.heights = result.heights;
    SansuiView.setWorld(result.facts, result.heights, result.colours, result.sky);
    drawTopView(result.facts, result.heights);
    const f = result.facts;
    $('status').textContent = `${f.width}×${f.height} samples, ${f.cell_m} m apart, ${f.min_m.toFixed(0)}..${f.max_m.toFixed(0)} m; ` +
      `made in ${f.heights_seconds.toFixed(2)} s on ${f.threads} thread${f.threads > 1 ? 's' : ''}, shown in ${((performance.now() - started) / 1000).toFixed(2)} s`;
    page.builds++;
  }
  if (page.again) {
    page.again = false;
    build();
  } else if (!result.facts.error) {
    // The trees come once the world has settled: a change right after one costs nothing extra.
    clearTimeout(page.plantTimer);
    page.plantTimer = setTimeout(showPlants, SansuiView.plantDelay());
  }
}

/**
 * The trees of the world shown, placed by the module after the world is drawn, strip by strip:
 * a change made meanwhile waits for one strip, and the trees of an old world are never shown.
 * Where there are more than the view draws well, every k-th.
 */
async function showPlants() {
  const started = performance.now(), builds = page.builds, strips = 8;
  const parts = [];
  page.stripSeconds = [];
  for (let strip = 0; strip < strips; ++strip) {
    const before = performance.now();
    const result = await call('plants', { strip, strips });
    page.stripSeconds.push((performance.now() - before) / 1000);
    if (result.cancelled || !result.plants || page.building || page.builds !== builds) return;
    parts.push(result.plants);
  }
  const total = parts.reduce((sum, part) => sum + part.length, 0) / 9;
  const every = Math.max(1, Math.ceil(total / SansuiView.plantBudget()));
  const kept = new Float32Array(Math.ceil(total / every) * 9);
  let k = 0, n = 0;
  for (const part of parts)
    for (let t = 0; t < part.length; t += 9, ++k)
      if (k % every === 0) kept.set(part.subarray(t, t + 9), 9 * n++);
  SansuiView.setPlants(kept.subarray(0, 9 * n));
  page.plants = n;
  page.plantSeconds = (performance.now() - started) / 1000;
}

function drawTopView(facts, heights) {
  const canvas = $('top');
  const side = Math.min(facts.width, 512);
  canvas.width = side;
  canvas.height = side;
  const context = canvas.getContext('2d');
  const image = context.createImageData(side, side);
  const span = Math.max(facts.max_m - facts.sea_level_m, 1);
  for (let y = 0; y < side; ++y) {
    const row = Math.floor((y * facts.height) / side);
    for (let x = 0; x < side; ++x) {
      const h = heights[row * facts.width + Math.floor((x * facts.width) / side)];
      const k = 4 * (y * side + x);
      if (facts.sea && h < facts.sea_level_m) {
        image.data.set([40, 80, 140, 255], k);
      } else {
        const grey = Math.round(40 + 215 * Math.max(0, (h - facts.sea_level_m) / span));
        image.data.set([grey, grey, grey, 255], k);
      }
    }
  }
  context.putImageData(image, 0, 0);
}

// ---- controls, from the parameter tables -------------------------------------------------------

function hoursText(hours) {
  const minutes = Math.round(hours * 60) % (24 * 60);
  return `${String(Math.floor(minutes / 60)).padStart(2, '0')}:${String(minutes % 60).padStart(2, '0')}`;
}

function sizeChoices(row) {
  const sizes = [];
  for (let size = 129; size <= row.page_max; size = 2 * size - 1) sizes.push(size);
  return sizes;
}

/** The editor of one row: its kind, limits and choices say which. */
function makeInput(row) {
  const value = row.value || row.derived;
  const limits = row.limits;
  if (row.key === 'time.time') {
    // Time of day as a slider over the HH:MM key, as the viewer shows it.
    const input = Object.assign(document.createElement('input'), { type: 'range', min: 0, max: 23.75, step: 0.25 });
    const [h, m] = value.split(':').map(Number);
    input.value = h + m / 60;
    input.toText = () => hoursText(Number(input.value));
    return input;
  }
  if (row.kind === 'choice') {
    const input = document.createElement('select');
    if (row.optional) input.append(new Option(`derived (${row.derived || row.unset_means})`, ''));
    for (const choice of limits.choices) input.append(new Option(choice, choice));
    input.value = row.value;
    input.toText = () => input.value;
    return input;
  }
  if (row.kind === 'real' && Number.isFinite(limits.min) && Number.isFinite(limits.max)) {
    const input = Object.assign(document.createElement('input'), { type: 'range', min: limits.min, max: limits.max,
      step: (limits.max - limits.min) / 100 });
    input.value = value;
    input.toText = () => String(Number(input.value));
    return input;
  }
  const input = Object.assign(document.createElement('input'), { type: row.kind === 'integer' || row.kind === 'real' ? 'number' : 'text' });
  if (row.kind === 'real') input.step = 'any';
  if (row.key === 'world.size') {
    const list = document.createElement('datalist');
    list.id = 'sizes';
    for (const size of sizeChoices(row)) list.append(new Option(String(size)));
    document.body.append(list);
    input.setAttribute('list', 'sizes');
  }
  input.value = value;
  input.toText = () => input.value.trim();
  return input;
}

$('controls').addEventListener('submit', (event) => event.preventDefault());  // Enter applies a value, never reloads

function renderControls(rows) {
  const form = $('controls');
  form.textContent = '';
  for (const row of rows) {
    const div = document.createElement('div');
    div.className = 'control';
    const label = document.createElement('label');
    const name = row.key === 'time.time' ? 'time of day' : row.key;
    label.textContent = name;
    if (row.unit) label.append(Object.assign(document.createElement('span'), { className: 'unit', textContent: ` (${row.unit})` }));
    const input = makeInput(row);
    input.name = row.key;
    input.dataset.key = row.key;
    input.id = `control-${row.key.replace(/\./g, '-')}`;
    label.htmlFor = input.id;
    div.title = `${row.help}${row.allowed ? `\nallowed: ${row.allowed}` : ''}`;
    const shown = document.createElement('output');
    const show = () => { shown.textContent = input.type === 'range' ? input.toText() : ''; };
    show();
    input.addEventListener('input', show);
    let previous = input.value;
    input.addEventListener('change', async () => {
      const text = input.toText();
      const result = await call('set', { key: row.key, text });
      if (result.cancelled) return;
      if (result.error) {
        showMessage(result.error);
        input.value = previous;
        show();
        return;
      }
      showMessage('');
      previous = input.value;
      page.values = page.values.filter(([key]) => key !== row.key).concat([[row.key, text]]);
      build();
    });
    div.append(label, input, shown);
    form.append(div);
  }
}

// ---- downloads ---------------------------------------------------------------------------------

$('prepare').addEventListener('click', async () => {
  const list = $('download-links');
  list.textContent = 'writing…';
  const result = await call('downloads');
  list.textContent = '';
  if (result.cancelled) return;
  if (result.error) return showMessage(result.error);
  for (const [name, bytes] of Object.entries(result.files)) {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([bytes]));
    link.download = name;
    link.textContent = `${name} (${bytes.length.toLocaleString()} bytes)`;
    const item = document.createElement('li');
    item.append(link);
    list.append(item);
  }
});

// ---- the drop zone -----------------------------------------------------------------------------

async function useDrawing(file) {
  if (file.size > 16 * 1024 * 1024) return showMessage(`${file.name} is ${(file.size / 1e6).toFixed(0)} MB: a drawing of at most 16 MB, please`);
  const contour = { name: file.name, text: await file.text() };
  showProgress('contour mountain', 0);
  const result = await call('contour', contour);
  $('progress').hidden = true;
  if (result.cancelled) return;
  if (result.error) return showMessage(result.error);
  showMessage('');
  page.contour = contour;
  build();
}

const drop = $('drop');
drop.addEventListener('dragover', (event) => { event.preventDefault(); drop.classList.add('over'); });
drop.addEventListener('dragleave', () => drop.classList.remove('over'));
drop.addEventListener('drop', (event) => {
  event.preventDefault();
  drop.classList.remove('over');
  if (event.dataTransfer.files.length) useDrawing(event.dataTransfer.files[0]);
});
$('drop-file').addEventListener('change', (event) => { if (event.target.files.length) useDrawing(event.target.files[0]); });

// ---- start -------------------------------------------------------------------------------------

page.ready = (async () => {
  await isolate();
  SansuiView.init($('view'));
  startWorker();
  const { controls } = await call('controls');
  renderControls(controls);
  await build();
})();
