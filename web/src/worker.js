// The core runs here, off the page's thread (issue 41): typing never waits for a check or a run.
// klueng.js (emscripten's loader, beside this file) makes the module; every request is one
// call of the C API (api.js) and one reply with the same id.
/* global importScripts, createKlueng */
import { handle, makeApi } from './api.js';

importScripts('klueng.js');
const ready = createKlueng().then(makeApi);

self.onmessage = (event) => {
  const r = event.data;
  ready
    .then((k) => {
      const result = handle(k, r);
      const transfer = result && result.profile ? [result.profile.buffer] : [];
      self.postMessage({ id: r.id, result }, transfer);
    })
    .catch((e) => self.postMessage({ id: r.id, error: String((e && e.stack) || e) }));
};
