// Source of the CommonJS entry, pkg/polysweep.cjs (the "require" condition, under "node"), so that
// `const { union } = require('polysweep')` works in Node 18+. A CommonJS module cannot wait for top-level await, so
// this entry loads the wasm synchronously: readFileSync, then wasm-bindgen's initSync (new WebAssembly.Module and
// new WebAssembly.Instance). Every call after that is synchronous, as with the ES module entries.
//
// This file is an ES module like the others, and is never shipped as it is: web/build.sh bundles it, with api.js and
// wasm-bindgen's glue (both ES modules), into the one CommonJS file pkg/polysweep.cjs with esbuild (pinned in the
// root package-lock.json), and fails on any warning of esbuild's. So api.js stays the one source of the API, and the
// conversion is done by a parser that refuses what it cannot convert rather than by text substitution. Why this way:
// - Node 18 cannot require() an ES module, and Node 20.19+/22.12+ can, but not one that uses top-level await (the
//   ES module entries do), so a real CommonJS file is needed;
// - rewriting `export function` / `import` lines by regular expressions would also have to convert the glue, which
//   wasm-bindgen generates (and which uses `import.meta.url`), and would break silently on any new form of export;
// - wasm-bindgen's own CommonJS output (--target nodejs) is a second glue with a second .wasm: twice the package;
// - rewriting api.js as a factory that each entry calls with the wasm exports would change another file's shape for
//   every entry, to save one build step.
// The CommonJS and the ES module entries are separate module instances, each with its own wasm instance: a program
// that both imports and requires the package loads the wasm twice, which costs memory and nothing else (the API has
// no state and no classes shared between calls).
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { initSync } from './polysweep_wasm.js';

// `__dirname`: this code only ever runs in the CommonJS bundle, where it is the directory of polysweep.cjs.
initSync({ module: readFileSync(path.join(__dirname, 'polysweep_wasm_bg.wasm')) });

export * from './api.js';
