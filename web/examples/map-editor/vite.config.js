// Vite's settings for the map editor (run.sh and web/test/map-editor.test.mjs build with them).
import { defineConfig } from 'vite';

export default defineConfig({
  base: './',
  build: {
    target: 'es2022', // polysweep loads its wasm with a top-level await
    outDir: 'dist',
    emptyOutDir: true,
    chunkSizeWarningLimit: 2000, // MapLibre alone is about 1.1 MB
    assetsInlineLimit: 0, // the wasm, the land data and MapLibre's worker stay files
  },
  worker: { format: 'es' }, // the package's worker is a module worker
  optimizeDeps: { exclude: ['polysweep'] }, // `vite` (dev): keep the package's wasm and worker URLs as they are
});
