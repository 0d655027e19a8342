// polysweep/worker: the package's operations in a Web Worker, as promises, so that long work (a layer of thousands
// of features) leaves the page's main thread free to draw the map.
//
// One job runs at a time, in the order asked; a job's options may hold an AbortSignal. An aborted job that waits is
// dropped; an aborted job that runs is stopped by terminating the worker (wasm cannot be interrupted), and the next
// job starts a new one. GeoJSON goes to the worker by structured clone; the flat form's typed arrays and clipLayer's
// are transferred, not copied. clipLayer reads the layer and builds the result features on this thread
// (layer-clip.js) and clips in the worker, reporting progress.

import { buffersOf, finishClipLayer, prepareClipLayer } from './layer-clip.js';

const ERRORS = { TypeError, RangeError };
// The operations that take GeoJSON (or the flat form) and run as they are in the worker.
const CLONED = ['union', 'intersection', 'difference', 'xor', 'overlayFlat', 'clip', 'split', 'overlayLayers', 'dissolve', 'splitAntimeridian', 'trace'];

const abortError = () => new DOMException('The polysweep job was aborted', 'AbortError');

/**
 * The job's AbortSignal and progress callback, taken out of the options (its last argument, an object that is not
 * GeoJSON), which go to the worker without them: functions cannot be cloned.
 */
function takeControls(method, args) {
  const last = args.at(-1);
  if (args.length < 2 || last === null || typeof last !== 'object' || Array.isArray(last) || 'type' in last || ArrayBuffer.isView(last)) {
    return { args };
  }
  const { signal, onProgress, ...options } = last;
  if (signal !== undefined && !(signal instanceof AbortSignal)) throw new TypeError(`${method}: options.signal must be an AbortSignal`);
  if (onProgress !== undefined && typeof onProgress !== 'function') throw new TypeError(`${method}: options.onProgress must be a function (done, total) => void`);
  for (const [key, value] of Object.entries(options)) {
    if (typeof value === 'function') throw new TypeError(`${method}: options.${key} is a function, which cannot go to a worker; call ${method} from 'polysweep' instead`);
  }
  return { args: [...args.slice(0, -1), options], signal, onProgress };
}

/**
 * A polysweep worker. `spawn` makes the Worker (a module worker running this package's worker-script.js, by
 * default); pass your own where a bundler needs the worker's URL spelled out.
 */
export function createWorker({ spawn } = {}) {
  const start = spawn ?? (() => new Worker(new URL('./worker-script.js', import.meta.url), { type: 'module' }));
  const queue = [];
  let worker = null;
  let ready = false;
  let running = null;

  function stop() {
    worker?.terminate();
    worker = null;
    ready = false;
  }

  function settle(job, outcome) {
    job.signal?.removeEventListener('abort', job.onAbort);
    if (running === job) running = null;
    outcome(job);
    next();
  }

  function next() {
    if (running !== null || queue.length === 0) return;
    if (worker === null) {
      worker = start();
      worker.onmessage = ({ data }) => {
        if (data.ready) {
          ready = true;
          next();
        } else if (data.progress) {
          running?.onProgress?.(...data.progress);
        } else if (running !== null && data.error) {
          // Anything but the API's TypeErrors and RangeErrors (a wasm trap, memory exhausted) may leave the wasm
          // instance broken: the next job gets a new worker.
          const Type = ERRORS[data.error.name];
          if (Type === undefined) stop();
          settle(running, (job) => job.reject(new (Type ?? Error)(data.error.message)));
        } else if (running !== null) {
          settle(running, (job) => job.resolve(data.result));
        }
      };
      worker.onerror = (event) => {
        // The worker could not load (the script or the wasm not found) or died: the job fails, the next starts anew.
        event.preventDefault?.();
        const message = `polysweep worker failed: ${event.message || 'the worker script or its wasm could not be loaded'}`;
        stop();
        const failed = running ?? queue.shift();
        if (failed) settle(failed, (job) => job.reject(new Error(message)));
      };
    }
    if (!ready) return;
    running = queue.shift();
    worker.postMessage({ method: running.method, args: running.args }, running.transfer);
  }

  function submit(method, args, { signal, onProgress, transfer = [] } = {}) {
    return new Promise((resolve, reject) => {
      if (signal?.aborted) throw abortError();
      const job = { method, args, transfer, signal, onProgress, resolve, reject };
      job.onAbort = () => {
        const waiting = queue.indexOf(job);
        if (running === job) stop();
        else if (waiting >= 0) queue.splice(waiting, 1);
        else return; // settled already: nothing to abort
        settle(job, () => reject(abortError()));
      };
      signal?.addEventListener('abort', job.onAbort, { once: true });
      queue.push(job);
      next();
    });
  }

  const api = {
    /**
     * Each feature of `layer` clipped to `polygon`, as clipLayer of 'polysweep'; `options.onProgress(done, total)`
     * is called as the worker finishes batches of features, `options.signal` aborts.
     */
    async clipLayer(layer, polygon, options) {
      const { signal, onProgress } = takeControls('clipLayer', [layer, polygon, options ?? {}]);
      if (signal?.aborted) throw abortError();
      const { features, job } = prepareClipLayer(layer, polygon, options);
      const transfer = buffersOf(job.layer, job.clip);
      return finishClipLayer(features, await submit('clipLayer', [job], { signal, onProgress, transfer }));
    },
    /** Stops the worker; jobs not finished are rejected with an AbortError. */
    terminate() {
      const jobs = [running, ...queue.splice(0)].filter(Boolean);
      running = null;
      stop();
      for (const job of jobs) {
        job.signal?.removeEventListener('abort', job.onAbort);
        job.reject(abortError());
      }
    },
  };
  for (const method of CLONED) {
    api[method] = async (...all) => {
      const { args, signal } = takeControls(method, all);
      // The flat form's arrays are moved to the worker: the caller's become empty (pass copies to keep them).
      const transfer = method === 'overlayFlat' && Array.isArray(args[1]) ? buffersOf(...args[1]) : [];
      return submit(method, args, { signal, transfer });
    };
  }
  return api;
}
