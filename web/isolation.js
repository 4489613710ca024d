// A service worker for static hosts that cannot send headers (GitHub Pages, most course sites):
// the page's threads need it cross-origin isolated, which takes two headers on every response,
//   Cross-Origin-Opener-Policy: same-origin   and   Cross-Origin-Embedder-Policy: require-corp.
// Registered by index.html when the page comes without them, this worker answers the page's own
// requests with those headers added; the page then reloads once and is isolated. A server that
// sends the headers itself (./web.sh, tools/serve_web.py) never needs it.
self.addEventListener('install', () => self.skipWaiting());
self.addEventListener('activate', (event) => event.waitUntil(self.clients.claim()));

self.addEventListener('fetch', (event) => {
  const request = event.request;
  // Only what the page loads from its own origin; a cache-only request from elsewhere cannot be
  // answered by a fetch and is left to the browser.
  if (new URL(request.url).origin !== self.location.origin) return;
  if (request.cache === 'only-if-cached' && request.mode !== 'same-origin') return;
  event.respondWith(fetch(request).then((response) => {
    if (response.status === 0) return response;  // opaque: its headers cannot be changed
    const headers = new Headers(response.headers);
    headers.set('Cross-Origin-Opener-Policy', 'same-origin');
    headers.set('Cross-Origin-Embedder-Policy', 'require-corp');
    headers.set('Cross-Origin-Resource-Policy', 'same-origin');
    return new Response(response.body, {status: response.status, statusText: response.statusText, headers: headers});
  }));
});
