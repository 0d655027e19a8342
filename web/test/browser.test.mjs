// The built npm package in a real browser (headless Chromium driven by playwright-core): as a plain ES module, in a
// module Web Worker, and bundled by Vite. ../serve.mjs serves the repository (and the Vite build under /vite/); the
// pages run the shared fixtures of tests/fixtures and Node compares their results, normalised, with the expected
// ones, exactly as fixtures.test.mjs does.
//
// Needs /usr/bin/chromium and a built pkg/ (web/build.sh). The browser-side files are in ./browser/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve, stopServer } from '../serve.mjs';
import { launchChromium, runPage as openPage } from './chromium.mjs';
import { build, createLogger } from 'vite';
import { normalise, area } from './normalise.mjs';
import { checkLinesAndLayers, lineFixtureFiles, lineFixtures } from './lines-and-layers-check.mjs';

const root = fileURLToPath(new URL('../../', import.meta.url));
const fixturesDir = path.join(root, 'tests', 'fixtures');
const packageWasm = fileURLToPath(new URL('../../pkg/polysweep_wasm_bg.wasm', import.meta.url));
const viteApp = fileURLToPath(new URL('./browser/vite-app/', import.meta.url));

const TIMEOUT = 120_000;
const PAGE_TIMEOUT = 60_000;
const OPERATIONS = ['intersection', 'union', 'difference', 'xor'];

const fixtureFiles = readdirSync(fixturesDir).filter((f) => f.endsWith('.json')).sort();
const fixtures = fixtureFiles.map((f) => JSON.parse(readFileSync(path.join(fixturesDir, f), 'utf8')));

/** URL prefix → directory served under it, besides the repository root at '/'. */
const mounts = new Map();
const temporary = [];
let server;
let origin;
let context;
let closeChromium;

function temporaryDir(prefix) {
  const dir = mkdtempSync(path.join(tmpdir(), prefix));
  temporary.push(dir);
  return dir;
}

before(async () => {
  for (const file of [path.join(root, "pkg", "polysweep.js"), packageWasm]) {
    assert.ok(existsSync(file), `${path.relative(root, file)} is missing: build the package first (web/build.sh)`);
  }
  const generated = new Map([
    ['/fixtures-index.json', () => fixtureFiles],
    ['/lines-fixtures-index.json', () => lineFixtureFiles],
  ]);
  ({ server, origin } = await serve({ mounts, generated }));
  ({ context, close: closeChromium } = await launchChromium());
});

after(async () => {
  await closeChromium?.();
  await stopServer(server);
  for (const dir of temporary) rmSync(dir, { recursive: true, force: true });
});

/** [`openPage`] in this file's browser, with its timeout. */
const runPage = (url) => openPage(context, url, PAGE_TIMEOUT);

/** Fails with everything the page reported when it did not finish cleanly. */
function assertClean({ failure, problems }) {
  assert.equal(failure, undefined, `the page failed: ${failure}`);
  assert.deepEqual(problems, [], `the page reported errors:\n${problems.join('\n')}`);
}

/** One subtest per fixture: the four results, normalised, equal the expected ones, and every ring is closed. */
async function checkFixtureResults(t, results) {
  assert.deepEqual(Object.keys(results).sort(), fixtures.map((f) => f.name).sort(), 'a result for every fixture');
  for (const fixture of fixtures) {
    await t.test(fixture.name, () => {
      for (const operation of OPERATIONS) {
        const result = results[fixture.name][operation];
        assert.ok(Array.isArray(result), `${operation} threw in the browser: ${result?.error}`);
        assert.deepEqual(normalise(result), normalise(fixture.expected[operation]), operation);
        for (const polygon of result) {
          for (const ring of polygon) assert.deepEqual(ring[0], ring[ring.length - 1], `${operation}: rings are closed`);
        }
      }
    });
  }
}

test('plain ES module: every fixture in Chromium', { timeout: TIMEOUT }, async (t) => {
  const outcome = await runPage(`${origin}/web/test/browser/plain.html`);
  assertClean(outcome);
  assert.ok(outcome.requests.includes(`${origin}/pkg/polysweep_wasm_bg.wasm`), 'the page fetched the .wasm');
  await checkFixtureResults(t, outcome.results);
  // The lines-and-layers fixtures too (clip, split, overlayLayers, dissolve).
  assert.deepEqual(Object.keys(outcome.lineResults).sort(), lineFixtures.map((f) => f.name).sort());
  for (const fixture of lineFixtures) {
    await t.test(`${fixture.operation}: ${fixture.name}`, () => checkLinesAndLayers(fixture, outcome.lineResults[fixture.name]));
  }
});

test('polysweep/worker: jobs in a module worker, errors, transfer, progress and abort', { timeout: TIMEOUT }, async () => {
  const outcome = await runPage(`${origin}/web/test/browser/worker.html`);
  assertClean(outcome);
  const r = outcome.results;
  assert.equal(area(r.union), 7);
  // The trace of [0, 2]² ∩ [1, 3]², in the worker: 8 edges, two crossings ((1, 2) and (2, 1)) splitting two edges
  // each: 12 edges, 24 events; one ring, the unit square [1, 2]².
  assert.equal(r.trace.events, 24);
  assert.equal(r.trace.rings.length, 1);
  assert.equal(area([[r.trace.rings[0]]]), 1);
  assert.deepEqual(r.error, { error: r.syncError }, 'the worker rejects with the error the sync call throws');
  assert.equal(r.syncError.name, 'TypeError');
  assert.equal(r.coordinateError.error.name, 'RangeError');
  assert.match(r.coordinateError.error.message, /^polygon, polygon 0, ring 0, vertex 1: /);
  assert.equal(r.functionOption.error.name, 'TypeError');
  assert.match(r.functionOption.error.message, /options\.properties is a function/);
  // The intersection of [0, 2]² and [1, 3]²: the unit square [1, 2]², from the transferred arrays.
  assert.equal(r.flat.callerCoordsLeft, 0, 'the caller\'s arrays were transferred');
  assert.deepEqual(r.flat.polygonOffsets, [0, 1]);
  const ring = r.flat.coords.reduce((positions, c, i) => (i % 2 ? positions.at(-1).push(c) : positions.push([c]), positions), []);
  assert.equal(area([[ring]]), 1);
  // [10.5, 40.5]² over the unit cells of a 60 × 60 grid: 31 × 31 cells meet it; its area 900 is theirs.
  const { features, progress } = r.clipLayer;
  assert.equal(features.length, 31 * 31);
  assert.ok(Math.abs(features.reduce((sum, f) => sum + area(f.geometry.coordinates), 0) - 900) < 1e-9);
  const corner = features.find((f) => f.id === 'cell-610');
  assert.deepEqual(corner.properties, { row: 10, column: 10 });
  assert.equal(area(corner.geometry.coordinates), 0.25, 'the corner cell keeps a quarter');
  assert.deepEqual(progress[0], [0, 31 * 31]);
  assert.deepEqual(progress.at(-1), [31 * 31, 31 * 31]);
  assert.ok(progress.every(([done], i) => i === 0 || done > progress[i - 1][0]), 'progress only grows');
  for (const aborted of [r.abortedRunning, r.abortedQueued, r.preAborted]) assert.equal(aborted.error?.name, 'AbortError');
  assert.equal(area(r.afterAbort), 1, 'the worker runs jobs again after an abort');
  assert.equal(area(r.afterTerminate), 6);
});

test('bundled by Vite: every fixture in Chromium', { timeout: TIMEOUT }, async (t) => {
  const outDir = temporaryDir('polysweep-vite-out-');
  const warnings = [];
  const logger = createLogger('warn');
  logger.warn = (message) => {
    warnings.push(message);
  };
  await build({
    root: viteApp,
    base: './',
    configFile: false,
    logLevel: 'warn',
    customLogger: logger,
    cacheDir: temporaryDir('polysweep-vite-cache-'),
    build: { target: 'es2022', outDir, emptyOutDir: true },
  });
  // The package resolves through node_modules (a link to pkg/) by its browser export: no warning expected.
  assert.deepEqual(warnings, [], 'Vite builds the package without warnings');

  const files = readdirSync(outDir, { recursive: true }).filter((f) => statSync(path.join(outDir, f)).isFile());
  const wasmAssets = files.filter((f) => f.endsWith('.wasm'));
  assert.equal(wasmAssets.length, 1, `one .wasm asset in the build, got: ${files.join(', ')}`);
  assert.ok(readFileSync(path.join(outDir, wasmAssets[0])).equals(readFileSync(packageWasm)), 'the asset is pkg’s .wasm');
  assert.ok(files.includes('index.html'));

  mounts.set('/vite/', outDir);
  const outcome = await runPage(`${origin}/vite/`);
  assertClean(outcome);
  const wasmUrl = `${origin}/vite/${wasmAssets[0].split(path.sep).join('/')}`;
  assert.ok(outcome.requests.includes(wasmUrl), `the page fetched the bundled .wasm (${wasmUrl})`);
  assert.ok(!outcome.requests.some((url) => url.startsWith(`${origin}/pkg/`)), 'nothing came from /pkg/');
  await checkFixtureResults(t, outcome.results);
});
