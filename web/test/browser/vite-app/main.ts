// The package as an application bundles it: a bare `polysweep` import (resolved through node_modules, a link
// to pkg/, by the package's browser export), with Vite emitting and rewriting the .wasm asset the package locates via
// `new URL(…, import.meta.url)`.
//
// TypeScript rather than main.js on purpose: `node --test web/test/` loads every .js file under a `test` directory
// as a test file, and Node cannot resolve the bare 'polysweep' specifier, so a main.js would fail that run. Vite
// compiles .ts entries out of the box (its vanilla-ts template is the same shape).
import { union, intersection, difference, xor } from 'polysweep';
import { runFixtures } from '../run-fixtures.js';

const page = window as unknown as { results?: unknown; failure?: string };
try {
  page.results = await runFixtures({ union, intersection, difference, xor });
} catch (error) {
  page.failure = String((error as Error)?.stack ?? error);
}
