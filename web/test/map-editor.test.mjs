// The map editor example (web/examples/map-editor) in headless Chromium: built with Vite into a temporary directory,
// served on 127.0.0.1, and driven like a user, with the mouse (clicks at the pixels of lon/lat positions, from
// map.project through window.editor.project) and the buttons. window.editor is only read: the features drawn and
// made, the status text, the parcel-clip summary.
//
// Every expected figure is computed here, independently of polysweep: rectangle overlaps from the drawn vertices,
// a shoelace area over each result, lengths by hand, the parcel clip's count and area from the grid's parameters.
// The page must stay offline (any request not to 127.0.0.1, blob: or data: fails the test), without page errors,
// console errors or failed requests.
//
// Needs /usr/bin/chromium and a built pkg/ with polysweep/worker (web/build.sh).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { build, createLogger } from 'vite';
import { PNG } from 'pngjs';
import { serve, stopServer } from '../serve.mjs';
import { launchChromium } from './chromium.mjs';

const root = fileURLToPath(new URL('../../', import.meta.url));
const example = path.join(root, 'web', 'examples', 'map-editor');
const VIEWPORT = { width: 1200, height: 800 };

// The colours of web/examples/map-editor/style.js, and the parcel grid of data.js, restated. A result is filled with
// RESULT at RESULT_OPACITY over the map, so where a result must be, the pixel is that blend of RESULT and the map
// as it was before anything was drawn (`baseline`, a screenshot taken at start; the view never moves).
const RESULT = [0xd6, 0x24, 0x7f];
const RESULT_OPACITY = 0.7;
const GRID = { west: 0, south: 40, perDegree: 10, cols: 100, rows: 100 };
const USES = ['residential', 'commercial', 'farmland', 'forest', 'park'];

const temporary = [];
let server;
let origin;
let context;
let closeChromium;
let page;
let baseline;
const problems = [];

const temporaryDir = (prefix) => {
  const dir = mkdtempSync(path.join(tmpdir(), prefix));
  temporary.push(dir);
  return dir;
};

before(async () => {
  for (const file of ['pkg/polysweep.js', 'pkg/polysweep_wasm_bg.wasm', 'pkg/worker.js']) {
    assert.ok(existsSync(path.join(root, file)), `${file} is missing: build the package first (web/build.sh)`);
  }
  const outDir = temporaryDir('polysweep-map-editor-');
  const warnings = [];
  const logger = createLogger('warn');
  logger.warn = (message) => warnings.push(message);
  await build({
    root: example,
    configFile: path.join(example, 'vite.config.js'),
    logLevel: 'warn',
    customLogger: logger,
    cacheDir: temporaryDir('polysweep-map-editor-cache-'),
    build: { outDir, emptyOutDir: true },
  });
  assert.deepEqual(warnings, [], 'Vite builds the editor without warnings');
  ({ server, origin } = await serve({ root: outDir }));
  ({ context, close: closeChromium } = await launchChromium());

  page = await context.newPage();
  await page.setViewportSize(VIEWPORT);
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console.error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.stack ?? error.message}`));
  page.on('request', (request) => {
    const url = request.url();
    if (!url.startsWith(`${origin}/`) && !url.startsWith('blob:') && !url.startsWith('data:')) problems.push(`request off 127.0.0.1: ${url}`);
  });
  page.on('requestfailed', (request) => problems.push(`request failed: ${request.url()}: ${request.failure()?.errorText}`));
  page.on('response', (response) => {
    if (response.status() >= 400) problems.push(`HTTP ${response.status()}: ${response.url()}`);
  });
  page.on('worker', (worker) =>
    worker.on('console', (message) => {
      if (message.type() === 'error') problems.push(`worker console.error: ${message.text()}`);
    }),
  );
  await page.goto(`${origin}/`);
  await page.waitForFunction(() => window.editor?.ready === true, null, { timeout: 30_000 });
  baseline = PNG.sync.read(await page.screenshot());
});

after(async () => {
  await page?.close();
  await closeChromium?.();
  await stopServer(server);
  for (const dir of temporary) rmSync(dir, { recursive: true, force: true });
});

// ---- independent geometry ---------------------------------------------------------------------------------------

const ringArea = (ring) => {
  let sum = 0;
  for (let i = 0; i + 1 < ring.length; i++) sum += ring[i][0] * ring[i + 1][1] - ring[i + 1][0] * ring[i][1];
  return Math.abs(sum) / 2;
};
/** Shoelace area of a Polygon or MultiPolygon geometry: outer rings less holes. */
const area = (g) =>
  (g.type === 'Polygon' ? [g.coordinates] : g.coordinates).reduce(
    (sum, [outer, ...holes]) => sum + ringArea(outer) - holes.reduce((h, r) => h + ringArea(r), 0),
    0,
  );
const length = (g) =>
  (g.type === 'LineString' ? [g.coordinates] : g.coordinates).reduce(
    (sum, line) => sum + line.slice(1).reduce((s, p, i) => s + Math.hypot(p[0] - line[i][0], p[1] - line[i][1]), 0),
    0,
  );
/** The box [x0, y0, x1, y1] of a drawn rectangle, checked to be one (five positions, axis-aligned, closed). */
function rectangleOf(feature) {
  const ring = feature.geometry.coordinates[0];
  assert.equal(ring.length, 5, 'a drawn rectangle has four corners');
  const xs = ring.map((p) => p[0]);
  const ys = ring.map((p) => p[1]);
  const box = [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
  for (const [x, y] of ring) assert.ok((x === box[0] || x === box[2]) && (y === box[1] || y === box[3]), 'corners only');
  return box;
}
const boxArea = ([x0, y0, x1, y1]) => Math.max(0, x1 - x0) * Math.max(0, y1 - y0);
const overlap = (a, b) => [Math.max(a[0], b[0]), Math.max(a[1], b[1]), Math.min(a[2], b[2]), Math.min(a[3], b[3])];
const close = (actual, expected, what, relative = 1e-9) =>
  assert.ok(Math.abs(actual - expected) <= relative * Math.max(1, Math.abs(expected)), `${what}: ${actual}, expected ${expected}`);

// ---- driving the page -----------------------------------------------------------------------------------------------

function assertClean() {
  assert.deepEqual(problems, [], `the page reported problems:\n${problems.join('\n')}`);
}

/** Page pixel of a lon/lat position, rounded to whole pixels (the editor snaps clicks to 0.05°). */
async function pixel(lon, lat) {
  const [x, y] = await page.evaluate(([a, b]) => window.editor.project(a, b), [lon, lat]);
  return [Math.round(x), Math.round(y)];
}
async function clickAt(lon, lat) {
  await page.mouse.click(...(await pixel(lon, lat)));
}
const press = (id) => page.click(`#${id}`);
const features = () => page.evaluate(() => window.editor.features);
const statusText = () => page.locator('#status').textContent();

/** Draws a rectangle with the Polygon tool, finishing it in the way given ('first' vertex, 'enter' or 'dblclick'). */
async function drawRectangle([x0, y0, x1, y1], finish = 'enter') {
  await press('tool-polygon');
  const corners = [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
  for (const [i, [x, y]] of corners.entries()) {
    if (finish === 'dblclick' && i === corners.length - 1) await page.mouse.dblclick(...(await pixel(x, y)));
    else await clickAt(x, y);
  }
  if (finish === 'first') await clickAt(x0, y0);
  if (finish === 'enter') await page.keyboard.press('Enter');
}
/** Draws a line through `points` with the Line tool, finishing with a double-click on the last one. */
async function drawLine(points) {
  await press('tool-line');
  for (const [i, [x, y]] of points.entries()) {
    if (i === points.length - 1) await page.mouse.dblclick(...(await pixel(x, y)));
    else await clickAt(x, y);
  }
}
/** Selects features with the Select tool by clicking the given lon/lat positions, in order. */
async function select(...positions) {
  await press('tool-select');
  for (const [lon, lat] of positions) await clickAt(lon, lat);
  assert.equal((await page.evaluate(() => window.editor.selection)).length, positions.length, `each click selected one: ${await statusText()} ${JSON.stringify(await features())}`);
}
async function clear() {
  await press('clear');
  assert.deepEqual(await features(), []);
}

const near = (c, [r, g, b], tolerance = 8) => Math.abs(c[0] - r) <= tolerance && Math.abs(c[1] - g) <= tolerance && Math.abs(c[2] - b) <= tolerance;
const colourAt = (png, x, y) => {
  const i = (y * png.width + x) * 4;
  return [png.data[i], png.data[i + 1], png.data[i + 2]];
};
/** The colour of a result over the map's pixel (x, y). */
const resultOver = (x, y) => colourAt(baseline, x, y).map((c, i) => RESULT_OPACITY * RESULT[i] + (1 - RESULT_OPACITY) * c);

/** Polls screenshots until the result colour shows at exactly the `filled` positions among `probes` (lon/lat). */
async function expectResultColour(probes, filled, label) {
  const points = await Promise.all(probes.map(([lon, lat]) => pixel(lon, lat)));
  let seen;
  for (let attempt = 0; attempt < 40; attempt++) {
    const png = PNG.sync.read(await page.screenshot());
    seen = points.map(([x, y]) => colourAt(png, x, y));
    if (seen.every((c, i) => near(c, resultOver(...points[i])) === filled.includes(i))) return;
    await page.waitForTimeout(150);
  }
  const wanted = points.map((p) => resultOver(...p).map(Math.round));
  assert.fail(`${label}: the result colour expected at probes ${JSON.stringify(filled)} of ${JSON.stringify(probes)} only (there: ${JSON.stringify(wanted)}); pixels were ${JSON.stringify(seen)}`);
}

// ---- the tests (in order, on one page) ------------------------------------------------------------------------------

test('merge, cut, intersect and xor of two rectangles drawn with the mouse', { timeout: 60_000 }, async () => {
  await drawRectangle([1, 41, 3, 43], 'first');
  await drawRectangle([2, 42, 4, 44], 'enter');
  const drawn = await features();
  assert.equal(drawn.length, 2);
  const [a, b] = drawn.map(rectangleOf);
  assert.deepEqual([a, b], [[1, 41, 3, 43], [2, 42, 4, 44]], 'the clicks snapped to the corners meant');
  const both = boxArea(overlap(a, b));
  const expected = {
    merge: boxArea(a) + boxArea(b) - both,
    intersect: both,
    'a-b': boxArea(a) - both,
    'b-a': boxArea(b) - both,
    xor: boxArea(a) + boxArea(b) - 2 * both,
  };
  assert.deepEqual(expected, { merge: 7, intersect: 1, 'a-b': 3, 'b-a': 3, xor: 6 }, 'the hand computation');

  // Probes: only in A, in both, only in B, in neither (inside the union's box); mid-parcel, off the grid's lines.
  const inA = [1.55, 41.55];
  const inB = [3.55, 43.55];
  const probes = [inA, [2.55, 42.55], inB, [1.55, 43.55]];
  const cases = [
    { button: 'op-merge', order: [inA, inB], area: expected.merge, filled: [0, 1, 2] },
    { button: 'op-intersect', order: [inA, inB], area: expected.intersect, filled: [1] },
    { button: 'op-cut', order: [inA, inB], area: expected['a-b'], filled: [0] },
    { button: 'op-cut', order: [inB, inA], area: expected['b-a'], filled: [2] },
    { button: 'op-xor', order: [inA, inB], area: expected.xor, filled: [0, 2] },
  ];
  for (const { button, order, area: want, filled } of cases) {
    const label = `${button} (${order === cases[3].order ? 'B then A' : 'A then B'})`;
    await select(...order);
    await press(button);
    const after = await features();
    assert.equal(after.length, 1, `${label}: the operands are replaced by one result`);
    assert.equal(after[0].geometry.type, 'MultiPolygon');
    close(area(after[0].geometry), want, `${label}: area`);
    await expectResultColour(probes, filled, label);
    await press('undo');
    assert.deepEqual((await features()).map(rectangleOf), [a, b], `${label}: Undo restores both operands`);
  }
  assertClean();
});

test('split a rectangle along a line', { timeout: 30_000 }, async () => {
  await clear();
  await drawRectangle([1, 41, 4, 43], 'dblclick');
  await drawLine([[2, 40.5], [2, 43.5]]);
  const [polygon, line] = await features();
  const box = rectangleOf(polygon);
  assert.deepEqual(line.geometry.coordinates, [[2, 40.5], [2, 43.5]]);
  await select([3, 42], [2, 40.75]);
  await press('op-split');
  const after = await features();
  const pieces = after.filter((f) => f.geometry.type === 'Polygon');
  assert.equal(pieces.length, 2, 'two pieces');
  assert.equal(after.filter((f) => f.geometry.type === 'LineString').length, 1, 'the line stays');
  const x = line.geometry.coordinates[0][0];
  const wanted = [(x - box[0]) * (box[3] - box[1]), (box[2] - x) * (box[3] - box[1])]; // 2 and 4
  const areas = pieces.map((p) => area(p.geometry)).sort((p, q) => p - q);
  close(areas[0], Math.min(...wanted), 'the smaller piece');
  close(areas[1], Math.max(...wanted), 'the larger piece');
  close(areas[0] + areas[1], boxArea(box), 'the pieces make the polygon');
  await expectResultColour([[1.55, 42.05], [3.05, 42.05], [5.05, 42.05]], [0, 1], 'split');
  assertClean();
});

test('clip a line by a rectangle', { timeout: 30_000 }, async () => {
  await clear();
  await drawRectangle([1, 41, 4, 43]);
  const path = [[0.5, 41.5], [2.5, 41.5], [2.5, 42.5], [5, 42.5]];
  await drawLine(path);
  const [polygon, line] = await features();
  assert.deepEqual(line.geometry.coordinates, path);
  const box = rectangleOf(polygon);
  await select([0.75, 41.5], [3, 41.75]);
  await press('op-clip-lines');
  const after = await features();
  const lines = after.filter((f) => f.geometry.type !== 'Polygon');
  assert.equal(lines.length, 1, 'one clipped line');
  assert.equal(after.length, 2, 'the polygon stays');
  // Inside the box the path runs from x = box[0] to the corner (2.5, 41.5), up to (2.5, 42.5), on to x = box[2].
  const wanted = 2.5 - box[0] + (42.5 - 41.5) + (box[2] - 2.5); // 4
  close(length(lines[0].geometry), wanted, 'the clipped length');
  for (const part of lines[0].geometry.type === 'LineString' ? [lines[0].geometry.coordinates] : lines[0].geometry.coordinates) {
    for (const [x, y] of part) assert.ok(x >= box[0] && x <= box[2] && y >= box[1] && y <= box[3], 'the parts lie inside');
  }
  assertClean();
});

test('clip the 10,000-parcel layer in a worker', { timeout: 60_000 }, async (t) => {
  await clear();
  const clipBox = [2.35, 41.25, 5.65, 44.75];
  await drawRectangle(clipBox);
  assert.deepEqual(rectangleOf((await features())[0]), clipBox);
  assert.equal(await page.evaluate(() => window.editor.parcelCount), GRID.cols * GRID.rows);
  await select([4, 43]);
  await press('op-clip-parcels');
  await page.waitForFunction(() => window.editor.layerClip !== null || /error|failed/i.test(window.editor.status), null, { timeout: 30_000 });
  const summary = await page.evaluate(() => window.editor.layerClip);
  assert.ok(summary, `the clip finished: ${await statusText()}`);

  // The expectation from the grid: the cells the box meets, and the box's area (it lies inside the grid).
  const [x0, y0, x1, y1] = clipBox;
  const d = 1 / GRID.perDegree;
  const colsMet = Math.ceil((x1 - GRID.west) / d - 1e-9) - Math.floor((x0 - GRID.west) / d + 1e-9);
  const rowsMet = Math.ceil((y1 - GRID.south) / d - 1e-9) - Math.floor((y0 - GRID.south) / d + 1e-9);
  assert.equal(summary.count, colsMet * rowsMet, 'one piece per parcel the box meets');
  assert.equal(summary.count, 34 * 36);
  close(summary.totalArea, boxArea(clipBox), 'total area', 1e-9);
  assert.equal(await page.evaluate(() => window.editor.parcelCount), summary.count, 'the layer shown is the clipped one');
  const status = await statusText();
  assert.match(status, new RegExp(`${summary.count} parcels, total area ${boxArea(clipBox).toFixed(4).replace(/\.?0+$/, '')}`));

  // Properties survive: a parcel well inside, and a corner one cut to a 0.05° × 0.05° square.
  for (const [row, col, wantArea] of [[20, 30, d * d], [12, 23, 0.05 * 0.05], [47, 56, 0.05 * 0.05]]) {
    const piece = await page.evaluate((id) => window.editor.parcel(id), row * GRID.cols + col);
    assert.ok(piece, `parcel (${row}, ${col}) is in the result`);
    assert.deepEqual(piece.properties, {
      id: row * GRID.cols + col,
      owner: `owner ${(row * 31 + col * 17) % 97}`,
      use: USES[(row * 7 + col * 3) % USES.length],
    });
    close(area(piece.geometry), wantArea, `parcel (${row}, ${col}) area`);
  }
  assert.equal(await page.evaluate((id) => window.editor.parcel(id), 0), null, 'a parcel outside is gone');

  const [value, max] = await page.evaluate(() => [document.querySelector('#progress').value, document.querySelector('#progress').max]);
  assert.ok(max > 0 && value === max, `the progress bar reached its end (${value} of ${max})`);
  t.diagnostic(`layer clip: ${summary.count} pieces in ${Math.round(summary.ms)} ms; longest main-thread frame ${summary.longestFrameMs.toFixed(1)} ms over ${summary.frames} frames`);
  assert.ok(summary.frames >= 2, `the page drew frames while the worker ran (${summary.frames})`);

  await page.keyboard.press('Control+z');
  assert.equal(await page.evaluate(() => window.editor.parcelCount), GRID.cols * GRID.rows, 'Ctrl+Z restores the whole layer');
  assertClean();
});

test('Cancel aborts the parcel clip, and a new request aborts a stale one', { timeout: 30_000 }, async () => {
  // Continues from the previous test: the clip rectangle is drawn, and the whole layer is shown again.
  const before = await page.evaluate(() => window.editor.layerClip);
  await select([4, 43]);
  // Both buttons in one task, so that Cancel surely comes while the clip runs.
  await page.evaluate(() => {
    document.querySelector('#op-clip-parcels').click();
    document.querySelector('#cancel').click();
  });
  await page.waitForFunction(() => /cancelled/i.test(window.editor.status), null, { timeout: 10_000 });
  assert.equal(await page.evaluate(() => window.editor.parcelCount), GRID.cols * GRID.rows, 'the layer is unchanged');
  assert.deepEqual(await page.evaluate(() => window.editor.layerClip), before, 'no new result');
  assert.equal(await page.locator('#cancel').isDisabled(), true, 'Cancel is off again');
  assert.equal((await page.evaluate(() => window.editor.selection)).length, 1, 'the polygon is still selected');

  await page.evaluate(() => {
    document.querySelector('#op-clip-parcels').click();
    document.querySelector('#op-clip-parcels').click();
  });
  await page.waitForFunction((old) => window.editor.layerClip?.ms !== old, before.ms, { timeout: 30_000 });
  assert.equal(await page.evaluate(() => window.editor.layerClip.count), 34 * 36, 'the newer request finished');
  assert.match(await statusText(), /^1224 parcels/, 'the aborted one reported nothing');
  await press('undo');
  assert.equal(await page.evaluate(() => window.editor.parcelCount), GRID.cols * GRID.rows, 'one edit to undo');
  assertClean();
});

test('an empty result is reported in the status element, and Undo still works', { timeout: 30_000 }, async () => {
  await clear();
  await drawRectangle([6, 41, 7, 42]);
  await drawRectangle([8, 41, 9, 42]);
  const before = await features();
  await select([6.5, 41.5], [8.5, 41.5]);
  await press('op-intersect');
  await assert.doesNotReject(page.locator('#status').waitFor({ state: 'visible' }));
  assert.match(await statusText(), /the result is empty/i);
  assert.deepEqual(await features(), before, 'nothing changed');
  await press('undo');
  assert.deepEqual(await features(), before.slice(0, 1), 'Undo takes back the last edit (the second rectangle)');
  assert.match(await statusText(), /Undone/);
  assertClean();
});
