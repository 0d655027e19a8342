// A module worker using the package: served as /web/test/browser/worker.js, so this relative specifier is
// /pkg/polysweep.js, the same module plain.html imports. The package's top-level await (loading the .wasm) runs
// before this module's body.
//
// `node --test web/test/` also loads this file as a test file (every .js under a `test` directory), hence the
// relative specifier (an absolute '/pkg/…' would be a file-system path in Node) and the guard: outside a worker it
// does nothing.
import { union } from '../../../pkg/polysweep.js';

if (typeof WorkerGlobalScope !== 'undefined' && self instanceof WorkerGlobalScope) {
  const square = (x, y) => [[[x, y], [x + 2, y], [x + 2, y + 2], [x, y + 2], [x, y]]];
  try {
    self.postMessage({ union: union(square(0, 0), square(1, 1)) });
  } catch (error) {
    self.postMessage({ error: String(error?.stack ?? error) });
  }
}
