// Offline: the page's files are cached when it is installed, and served
// from the cache first (a new build changes VERSION, set by build.sh).
const VERSION = "pendulum-dev";
const FILES = ["./", "index.html", "style.css", "app.js", "lab.js", "figure.js", "pendulum.js", "pendulum.wasm", "listener-worker.js",
  "capture-worklet.js", "manifest.webmanifest", "icon.svg"];

self.addEventListener("install", (e) => {
  e.waitUntil(caches.open(VERSION).then((c) => c.addAll(FILES)).then(() => self.skipWaiting()));
});

self.addEventListener("activate", (e) => {
  e.waitUntil(caches.keys()
    .then((keys) => Promise.all(keys.filter((k) => k !== VERSION).map((k) => caches.delete(k))))
    .then(() => self.clients.claim()));
});

self.addEventListener("fetch", (e) => {
  if (e.request.method !== "GET") return;
  e.respondWith(caches.match(e.request, { ignoreSearch: true })
    .then((hit) => hit ?? fetch(e.request)));
});
