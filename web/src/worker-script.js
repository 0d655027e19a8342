// The module a polysweep worker runs (worker.js spawns it): the package loaded once, then one job per message.
// It says {ready: true} when the wasm is loaded; then for each {method, args} it answers {result} (its typed
// arrays transferred, not copied) or {error: {name, message}}, and for clipLayer {progress: [done, total]} on the
// way.

import * as polysweep from './polysweep.js';
import { buffersOf, computeClipLayer } from './layer-clip.js';

const methods = {
  ...polysweep,
  // The middle step of clipLayer: the caller's thread reads the layer and builds the features (layer-clip.js).
  clipLayer: (job) => computeClipLayer(job, (done, total) => self.postMessage({ progress: [done, total] })),
};

self.onmessage = ({ data: { method, args } }) => {
  try {
    if (!Object.hasOwn(methods, method)) throw new TypeError(`polysweep worker: no operation ${String(method)}`);
    const result = methods[method](...args);
    const transfer = result !== null && typeof result === 'object' && !Array.isArray(result) ? buffersOf(result) : [];
    self.postMessage({ result }, transfer);
  } catch (error) {
    self.postMessage({ error: { name: error?.name, message: error?.message ?? String(error) } });
  }
};

self.postMessage({ ready: true });
