// The page's worker: runs the WebAssembly module (from web/src/bindings.cpp) off the page's
// thread, so long steps (erosion) never freeze the page. The page cancels a step by ending this
// worker and starting another (web/page/app.js). Where the page is cross-origin isolated, the
// module is the threaded one (sansui-threads.js, whose own workers run the parallel loops), else
// the serial one (sansui.js); worker.js?serial asks for the serial one anyway.
/* global importScripts, createSansui */
'use strict';
const moduleName = self.crossOriginIsolated && !new URL(self.location.href).searchParams.has('serial') ? 'sansui-threads.js' : 'sansui.js';
importScripts(moduleName);

let session = null;

function reply(id, body, transfer = []) {
  postMessage(Object.assign({ id }, body), transfer);
}

// mainScriptUrlOrBlob: the script the module's thread workers load (a worker has no script tag to
// find it by).
const ready = createSansui({ mainScriptUrlOrBlob: moduleName }).then((module) => {
  session = new module.Session();
  session.setProgress((stage, fraction) => postMessage({ type: 'progress', stage, fraction }));
});

const handlers = {
  controls: () => ({ controls: JSON.parse(session.controls()) }),
  set: ({ key, text }) => ({ error: session.set(key, text) }),
  build: () => {
    const facts = JSON.parse(session.build());
    if (facts.error) return { facts };
    // Copies out of the module's memory, handed over without another copy.
    const heights = session.heights().slice();
    const colours = session.colours().slice();
    const sky = session.sky().slice();
    return { facts, heights, colours, sky, transfer: [heights.buffer, colours.buffer, sky.buffer] };
  },
  plants: ({ strip, strips }) => {
    const view = session.plants(strip, strips);
    if (!view) return { plants: null };
    const plants = view.slice();
    return { plants, transfer: [plants.buffer] };
  },
  recipe: () => ({ text: session.recipeToml() }),
  downloads: () => {
    const result = JSON.parse(session.writeDownloads());
    if (result.error) return result;
    const files = {};
    const transfer = [];
    for (const name of result.files) {
      files[name] = session.download(name).slice();
      transfer.push(files[name].buffer);
    }
    files['recipe.toml'] = new TextEncoder().encode(session.recipeToml());
    return { files, transfer };
  },
  contour: ({ name, text }) => ({ error: session.useContour(name, text) }),
};

onmessage = async (event) => {
  await ready;
  const { id, type } = event.data;
  try {
    const result = handlers[type](event.data);
    const transfer = result.transfer || [];
    delete result.transfer;
    reply(id, result, transfer);
  } catch (error) {
    reply(id, { error: `internal error in ${type}: ${error && error.message ? error.message : error}` });
  }
};
