// Entry for Node (the "node" export condition): Node's fetch cannot read file: URLs, so the wasm comes from the
// file system.
import { readFile } from 'node:fs/promises';
import init from './polysweep_wasm.js';

await init({ module_or_path: await readFile(new URL('./polysweep_wasm_bg.wasm', import.meta.url)) });

export * from './api.js';
