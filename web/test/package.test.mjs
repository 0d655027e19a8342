// The package as `npm pack` makes it, installed into a throw-away project (under the system's temporary directory)
// and used there as its users would: Node ESM, Node CommonJS (require), TypeScript for both, a Vite build (with a
// module worker of its own), an esbuild bundle, a webpack 5 bundle, and the unbundled package in a module Web
// Worker; the browser ones in headless Chromium. Each computes the union of two overlapping 2×2 squares (area 7) and
// checks its coordinates. The tarball's file list is checked exactly, and its sizes are printed.
//
// Only the tarball is installed into the project (with its one dependency, @types/geojson, from npm's cache when
// there): the bundlers and TypeScript are the repository's devDependencies, run from here on the project's files,
// so that the package resolves from the project's node_modules and nothing else from outside is needed.
//
// Needs a built pkg/ (web/build.sh), npm, and /usr/bin/chromium.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import {
  copyFileSync,
  existsSync,
  mkdirSync,
  mkdtempSync,
  readdirSync,
  readFileSync,
  rmSync,
  statSync,
  writeFileSync,
} from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { gzipSync } from 'node:zlib';
import * as esbuild from 'esbuild';
import { build as viteBuild, createLogger } from 'vite';
import webpack from 'webpack';
import { serve, stopServer } from '../serve.mjs';
import { launchChromium, runPage as openPage } from './chromium.mjs';
import { normalise, area } from './normalise.mjs';

const execFileAsync = promisify(execFile);
const root = fileURLToPath(new URL('../../', import.meta.url));
const pkgDir = path.join(root, 'pkg');
const tsc = path.join(root, 'node_modules', 'typescript', 'bin', 'tsc');

const TIMEOUT = 120_000;
const PAGE_TIMEOUT = 60_000;

/** Exactly what the tarball holds: the entries, the API, the glue, the wasm, the declarations, the README. */
const TARBALL_FILES = [
  'README.md',
  'antimeridian.js',
  'api.js',
  'geojson.js',
  'layer-clip.js',
  'layers.js',
  'lines.js',
  'package.json',
  'polysweep.cjs',
  'polysweep.d.cts',
  'polysweep.d.ts',
  'polysweep.js',
  'polysweep.node.js',
  'polysweep_wasm.js',
  'polysweep_wasm_bg.wasm',
  'trace.js',
  'worker-script.js',
  'worker.d.ts',
  'worker.js',
].sort();
/** Names every entry exports (among any others the API gains: the entries must agree on those too). */
const API = ['clip', 'clipLayer', 'difference', 'dissolve', 'intersection', 'overlayFlat', 'overlayLayers', 'split', 'splitAntimeridian', 'trace', 'union', 'xor'];
const assertApi = (names, what) => {
  for (const name of API) assert.ok(names.includes(name), `${what} exports ${name}: ${names.join(', ')}`);
};

// Every app computes the union of these two squares, as Polygon coordinates.
const SQUARES = '[[[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]]], [[[1, 1], [3, 1], [3, 3], [1, 3], [1, 1]]]';
const UNION = [[[[0, 0], [2, 0], [2, 1], [3, 1], [3, 3], [1, 3], [1, 2], [0, 2], [0, 0]]]];

/** The files of the throw-away project, by path inside it. */
const PROJECT_FILES = {
  'package.json': JSON.stringify({ name: 'polysweep-package-test', private: true, version: '0.0.0' }, null, 2),

  // --- Node ---
  'node/esm.mjs': `import { union } from 'polysweep';
import * as api from 'polysweep';
const resolved = typeof import.meta.resolve === 'function' ? import.meta.resolve('polysweep') : null;
console.log(JSON.stringify({ resolved, exports: Object.keys(api).sort(), union: union(${SQUARES}) }));
`,
  // Synchronous use, right after require(); then the same package by import(), for the list of exports.
  'node/cjs.cjs': `'use strict';
const { union } = require('polysweep');
const result = union(${SQUARES});
const api = require('polysweep');
import('polysweep').then((esm) => {
  console.log(JSON.stringify({
    resolved: require.resolve('polysweep'),
    exports: Object.keys(api).sort(),
    esmExports: Object.keys(esm).sort(),
    union: result,
  }));
});
`,

  // --- TypeScript (node16 resolution: require() of an ES module's declarations would be an error there) ---
  'types/tsconfig.json': JSON.stringify(
    {
      compilerOptions: {
        module: 'node16',
        moduleResolution: 'node16',
        target: 'es2022',
        lib: ['es2022'],
        types: [],
        strict: true,
        noEmit: true,
        skipLibCheck: false,
      },
      files: ['check.cts', 'check.mts'],
    },
    null,
    2,
  ),
  'types/check.cts': `import polysweep = require('polysweep');
import { union } from 'polysweep';
const square = [[[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]]];
const x: number = union(square, square)[0][0][0][0];
const n: number = polysweep.intersection(square, square).length;
// @ts-expect-error the result is typed (not any): not a string
const s: string = union(square, square);
export { x, n, s };
`,
  'types/check.mts': `import { union, intersection } from 'polysweep';
import * as polysweep from 'polysweep';
const square = [[[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]]];
const x: number = union(square, square)[0][0][0][0];
const n: number = polysweep.xor(square, intersection(square, square)).length;
// @ts-expect-error the result is typed (not any): not a string
const s: string = union(square, square);
export { x, n, s };
`,

  // --- Browser apps: each page sets window.results, or window.failure ---
  'vite/index.html': page('bundled by Vite', '<script type="module" src="./main.js"></script>'),
  'vite/main.js': `import { union } from 'polysweep';
const result = union(${SQUARES});
// A module worker bundled by Vite too (worker.format 'es': the package uses top-level await).
const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
worker.onmessage = (event) => {
  if (event.data.error !== undefined) window.failure = event.data.error;
  else window.results = { union: result, workerUnion: event.data.union };
};
worker.onerror = (event) => {
  window.failure = \`worker error: \${event.message || '(the worker module failed to load)'}\`;
};
`,
  'vite/worker.js': worker("import { union } from 'polysweep';"),
  'esbuild/main.js': `import { union } from 'polysweep';
window.results = { union: union(${SQUARES}) };
`,
  'esbuild-dist/index.html': page('bundled by esbuild', '<script type="module" src="./main.js"></script>'),
  'webpack/main.js': `import { union } from 'polysweep';
window.results = { union: union(${SQUARES}) };
`,
  'webpack-dist/index.html': page('bundled by webpack 5', '<script src="./main.js"></script>'),
  // The package as it is installed, no bundler: the worker imports the entry file by its path.
  'worker/index.html': page(
    'module Web Worker',
    `<script type="module">
  const worker = new Worker('./worker.js', { type: 'module' });
  worker.onmessage = (event) => {
    if (event.data.error !== undefined) window.failure = event.data.error;
    else window.results = event.data;
  };
  worker.onerror = (event) => {
    window.failure = \`worker error: \${event.message || '(the worker module failed to load)'}\`;
  };
</script>`,
  ),
  'worker/worker.js': worker("import { union } from '../node_modules/polysweep/polysweep.js';"),
};

function page(title, body) {
  return `<!doctype html>
<html lang="en">
<head><meta charset="utf-8"><link rel="icon" href="data:,"><title>polysweep: ${title}</title></head>
<body>
${body}
</body>
</html>
`;
}

function worker(importLine) {
  return `${importLine}
try {
  self.postMessage({ union: union(${SQUARES}) });
} catch (error) {
  self.postMessage({ error: String(error?.stack ?? error) });
}
`;
}

let temporary;
let project;
let packed;
let server;
let origin;
let context;
let closeChromium;

/** The environment for npm and node children, without the npm_* variables of an enclosing `npm test`. */
function childEnv() {
  const env = Object.fromEntries(Object.entries(process.env).filter(([name]) => !/^npm_/i.test(name)));
  return { ...env, npm_config_audit: 'false', npm_config_fund: 'false', npm_config_update_notifier: 'false' };
}

async function run(command, args, options = {}) {
  try {
    return await execFileAsync(command, args, { env: childEnv(), maxBuffer: 16 << 20, ...options });
  } catch (error) {
    throw new Error(`${command} ${args.join(' ')} failed:\n${error.stdout ?? ''}${error.stderr ?? ''}`, { cause: error });
  }
}

/** Runs a Node script of the project and parses the JSON line it prints. */
async function runNode(args) {
  const { stdout } = await run(process.execPath, args, { cwd: project });
  return JSON.parse(stdout);
}

/** Files under `dir`, as paths relative to it with '/' separators, sorted. */
function filesUnder(dir) {
  return readdirSync(dir, { recursive: true })
    .filter((f) => statSync(path.join(dir, f)).isFile())
    .map((f) => f.split(path.sep).join('/'))
    .sort();
}

/** `result` is the union of the two squares: its coordinates (up to start vertex and order), area 7, closed rings. */
function assertUnion(result, what) {
  assert.ok(Array.isArray(result), `${what}: a result (got ${JSON.stringify(result)})`);
  assert.deepEqual(normalise(result), normalise(UNION), `${what}: the union's coordinates`);
  assert.equal(area(result), 7, `${what}: area 7`);
  for (const polygon of result) {
    for (const ring of polygon) assert.deepEqual(ring[0], ring[ring.length - 1], `${what}: rings are closed`);
  }
}

before(async () => {
  for (const file of ['polysweep.js', 'polysweep.cjs', 'polysweep_wasm_bg.wasm']) {
    assert.ok(existsSync(path.join(pkgDir, file)), `pkg/${file} is missing: build the package first (web/build.sh)`);
  }
  temporary = mkdtempSync(path.join(tmpdir(), 'polysweep-package-'));
  project = path.join(temporary, 'project');
  for (const [file, text] of Object.entries(PROJECT_FILES)) {
    mkdirSync(path.dirname(path.join(project, file)), { recursive: true });
    writeFileSync(path.join(project, file), text);
  }
  const { stdout } = await run('npm', ['pack', pkgDir, '--pack-destination', temporary, '--json'], { cwd: temporary });
  [packed] = JSON.parse(stdout);
  // --prefer-offline: @types/geojson comes from npm's cache when the repository's `npm install` has put it there.
  const tarball = path.join(temporary, packed.filename);
  await run('npm', ['install', '--prefix', project, '--prefer-offline', '--no-package-lock', tarball], { cwd: project });
  ({ server, origin } = await serve({ root: project }));
  ({ context, close: closeChromium } = await launchChromium());
});

after(async () => {
  await closeChromium?.();
  await stopServer(server);
  await esbuild.stop?.();
  if (temporary) rmSync(temporary, { recursive: true, force: true, maxRetries: 5, retryDelay: 200 });
});

/** Opens `url` (see chromium.mjs) and fails with everything it reported if it did not finish cleanly. */
async function runPage(url) {
  const { results, failure, problems, requests } = await openPage(context, url, PAGE_TIMEOUT);
  assert.equal(failure, undefined, `the page failed: ${failure}`);
  assert.deepEqual(problems, [], `the page reported errors:\n${problems.join('\n')}`);
  return { results, requests };
}

/** A bundle's page: the union, computed from the bundle's own files (its .wasm included), none from node_modules. */
async function checkBundlePage(dir, what) {
  const { results, requests } = await runPage(`${origin}/${dir}/`);
  assertUnion(results.union, what);
  const wasm = requests.filter((url) => url.endsWith('.wasm'));
  assert.ok(wasm.length >= 1, `${what}: the page fetched a .wasm`);
  for (const url of wasm) assert.ok(url.startsWith(`${origin}/${dir}/`), `${what}: the .wasm comes from the bundle: ${url}`);
  assert.ok(!requests.some((url) => url.includes('/node_modules/')), `${what}: nothing from node_modules`);
  return results;
}

/** Every .wasm of a bundle's output is the package's, byte for byte. Returns their paths. */
function assertWasmAssets(outDir, what) {
  const packageWasm = readFileSync(path.join(project, 'node_modules', 'polysweep', 'polysweep_wasm_bg.wasm'));
  const files = filesUnder(outDir);
  const wasm = files.filter((f) => f.endsWith('.wasm'));
  assert.ok(wasm.length >= 1, `${what}: a .wasm in the output, got: ${files.join(', ')}`);
  for (const f of wasm) {
    assert.ok(readFileSync(path.join(outDir, f)).equals(packageWasm), `${what}: ${f} is the package's .wasm`);
  }
  return wasm;
}

test('the tarball holds exactly the package’s files, and what package.json names is there', (t) => {
  const files = packed.files.map((f) => f.path).sort();
  assert.deepEqual(files, TARBALL_FILES, 'the tarball’s file list');
  const installedDir = path.join(project, 'node_modules', 'polysweep');
  assert.deepEqual(filesUnder(installedDir), TARBALL_FILES, 'the installed package’s files');

  const manifest = JSON.parse(readFileSync(path.join(installedDir, 'package.json'), 'utf8'));
  const named = new Set([manifest.main, manifest.types, ...manifest.sideEffects]);
  const targets = (value) => (typeof value === 'string' ? [value] : Object.values(value).flatMap(targets));
  for (const target of targets(manifest.exports)) named.add(target);
  for (const file of named) {
    assert.ok(TARBALL_FILES.includes(path.posix.normalize(file)), `package.json names ${file}, not in the tarball`);
  }
  assert.deepEqual(manifest.dependencies, { '@types/geojson': '7946.0.16' });
  const geojsonManifest = path.join(project, 'node_modules', '@types', 'geojson', 'package.json');
  const geojson = JSON.parse(readFileSync(geojsonManifest, 'utf8'));
  assert.equal(geojson.version, '7946.0.16', 'the types’ dependency is installed with the package');

  // Sizes as served (each file gzipped on its own, level 9), for the README's figures.
  const gzipped = (file) => gzipSync(readFileSync(path.join(installedDir, file)), { level: 9 }).length;
  const kB = (bytes) => `${(bytes / 1000).toFixed(1)} kB`;
  const sizes = (list) => {
    const raw = list.reduce((sum, f) => sum + statSync(path.join(installedDir, f)).size, 0);
    const gz = list.reduce((sum, f) => sum + gzipped(f), 0);
    return `${kB(raw)}, ${kB(gz)} gzipped`;
  };
  t.diagnostic(`tarball ${packed.filename}: ${kB(packed.size)} (${kB(packed.unpackedSize)} unpacked), ${files.length} files`);
  t.diagnostic(`wasm (polysweep_wasm_bg.wasm): ${sizes(['polysweep_wasm_bg.wasm'])}`);
  const esm = ['polysweep.js', 'api.js', 'geojson.js', 'lines.js', 'layers.js', 'layer-clip.js', 'antimeridian.js', 'trace.js', 'polysweep_wasm.js'];
  t.diagnostic(`JS of the ES module entries (polysweep.js or .node.js, the API's modules, polysweep_wasm.js): ${sizes(esm)}`);
  t.diagnostic(`JS of the CommonJS entry (polysweep.cjs): ${sizes(['polysweep.cjs'])}`);
});

test('Node, ES module: import', { timeout: TIMEOUT }, async () => {
  const out = await runNode(['node/esm.mjs']);
  if (out.resolved !== null) assert.ok(out.resolved.endsWith('/node_modules/polysweep/polysweep.node.js'), out.resolved);
  assertApi(out.exports, 'the ES module entry');
  assertUnion(out.union, 'ESM');
});

test('Node, CommonJS: require, synchronously', { timeout: TIMEOUT }, async () => {
  // Without require() of ES modules (Node 20.19+ and 22.12+ have it; Node 18 does not), as in Node 18.
  const flag = '--no-experimental-require-module';
  const args = process.allowedNodeEnvironmentFlags.has('--experimental-require-module') ? [flag] : [];
  const out = await runNode([...args, 'node/cjs.cjs']);
  assert.ok(out.resolved.endsWith(`${path.sep}node_modules${path.sep}polysweep${path.sep}polysweep.cjs`), out.resolved);
  assertApi(out.exports, 'the CommonJS entry');
  assert.deepEqual(out.exports, out.esmExports, 'the CommonJS entry exports what the ES module entry does');
  assertUnion(out.union, 'CJS');
});

test('TypeScript: the declarations for import and for require (node16 resolution)', { timeout: TIMEOUT }, async () => {
  const { stdout } = await run(process.execPath, [tsc, '-p', 'types/tsconfig.json', '--listFiles'], { cwd: project });
  const read = stdout.split('\n').map((line) => line.trim().split(path.sep).join('/'));
  for (const file of ['polysweep.d.cts', 'polysweep.d.ts']) {
    assert.ok(read.some((f) => f.endsWith(`/node_modules/polysweep/${file}`)), `tsc read ${file}:\n${stdout}`);
  }
});

test('bundled by Vite, with a module worker: in Chromium', { timeout: TIMEOUT }, async () => {
  const outDir = path.join(project, 'vite-dist');
  const warnings = [];
  const logger = createLogger('warn');
  logger.warn = (message) => warnings.push(message);
  await viteBuild({
    root: path.join(project, 'vite'),
    base: './',
    configFile: false,
    logLevel: 'warn',
    customLogger: logger,
    cacheDir: path.join(temporary, 'vite-cache'),
    worker: { format: 'es' },
    build: { target: 'es2022', outDir, emptyOutDir: true },
  });
  assert.deepEqual(warnings, [], 'Vite builds the package without warnings');
  assertWasmAssets(outDir, 'Vite');
  const results = await checkBundlePage('vite-dist', 'Vite');
  assertUnion(results.workerUnion, 'Vite, in its worker');
});

test('bundled by esbuild: in Chromium', { timeout: TIMEOUT }, async () => {
  const outDir = path.join(project, 'esbuild-dist');
  const result = await esbuild.build({
    absWorkingDir: project,
    entryPoints: ['esbuild/main.js'],
    bundle: true,
    format: 'esm',
    platform: 'browser',
    target: 'es2022',
    outdir: outDir,
    logLevel: 'silent',
  });
  assert.deepEqual(result.errors, []);
  assert.deepEqual(result.warnings, [], 'esbuild bundles the package without warnings');
  // esbuild keeps `new URL('./polysweep_wasm_bg.wasm', import.meta.url)` as it is: the .wasm goes next to the bundle.
  const wasm = 'polysweep_wasm_bg.wasm';
  copyFileSync(path.join(project, 'node_modules', 'polysweep', wasm), path.join(outDir, wasm));
  await checkBundlePage('esbuild-dist', 'esbuild');
});

test('bundled by webpack 5: in Chromium', { timeout: TIMEOUT }, async () => {
  const outDir = path.join(project, 'webpack-dist');
  const compiler = webpack({
    mode: 'production',
    context: project,
    entry: './webpack/main.js',
    output: { path: outDir, filename: 'main.js' },
    target: ['web', 'es2022'],
    devtool: false,
    cache: false,
    // The size hints judge an app's budget (the .wasm is near webpack's 244 KiB), not whether the bundle works.
    performance: { hints: false },
    infrastructureLogging: { level: 'error' },
  });
  const stats = await new Promise((resolve, reject) => compiler.run((error, s) => (error ? reject(error) : resolve(s))));
  await new Promise((resolve) => compiler.close(resolve));
  assert.ok(!stats.hasErrors(), stats.toString('errors-only'));
  assert.deepEqual(stats.compilation.warnings.map(String), [], 'webpack bundles the package without warnings');
  assert.equal(assertWasmAssets(outDir, 'webpack').length, 1, 'webpack emits the .wasm once');
  await checkBundlePage('webpack-dist', 'webpack');
});

test('module Web Worker, the installed package unbundled: in Chromium', { timeout: TIMEOUT }, async () => {
  const { results, requests } = await runPage(`${origin}/worker/`);
  assertUnion(results.union, 'worker');
  const wasm = `${origin}/node_modules/polysweep/polysweep_wasm_bg.wasm`;
  assert.ok(requests.includes(wasm), 'the worker fetched the package’s .wasm');
});
