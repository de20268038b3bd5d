// The page's service worker: serves every file of the site with the two headers that make it
// cross-origin isolated (COOP and COEP), which a browser needs before it shares memory between
// threads. Any static server then hosts the threaded module (sansui-threads.js): app.js registers
// this worker once and loads the page again under it. Every file is the site's own, so requiring
// CORP of embedded resources (COEP require-corp) refuses nothing the page uses.
'use strict';

self.addEventListener('install', () => self.skipWaiting());
self.addEventListener('activate', (event) => event.waitUntil(self.clients.claim()));

self.addEventListener('fetch', (event) => {
  const request = event.request;
  // A request the browser may only answer from its cache, for another origin: left alone.
  if (request.cache === 'only-if-cached' && request.mode !== 'same-origin') return;
  event.respondWith(fetch(request).then((response) => {
    if (response.status === 0) return response;  // opaque: its headers cannot be read or set
    const headers = new Headers(response.headers);
    headers.set('Cross-Origin-Opener-Policy', 'same-origin');
    headers.set('Cross-Origin-Embedder-Policy', 'require-corp');
    return new Response(response.body, { status: response.status, statusText: response.statusText, headers });
  }));
});
