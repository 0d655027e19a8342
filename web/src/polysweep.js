// Entry for browsers, workers and bundlers: fetches the wasm next to this file (bundlers such as Vite emit it as
// an asset and rewrite the URL), then exposes the API.
import init from './polysweep_wasm.js';

await init({ module_or_path: new URL('./polysweep_wasm_bg.wasm', import.meta.url) });

export * from './api.js';
