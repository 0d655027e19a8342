// The playground (index.html, built by web/build-playground.sh) in headless Chromium: it starts without console
// errors, two squares are drawn with the mouse, each operation is chosen with its key, and the screenshot must be
// filled with the result colour exactly where that operation's result is and nowhere else; a vertex drag and undo
// update it; pasted GeoJSON loads, and a bad coordinate shows an error without breaking the app; a line drawn with
// the line tool splits the result into pieces of distinct colours and shows its part inside, and undo removes it.
// All of it twice: on WebGL2 and on WebGPU, each checked to be the renderer the app chose. Then, on both again,
// concave shapes with a hole, overlapping rings and a self-crossing ring, under even-odd and non-zero.
//
// Expectations are independent of the app: which of four probe points lies in each result follows from the two
// squares by hand. The probes sit mid-region, away from edges, so antialiasing cannot touch them.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { repositoryRoot, serve, stopServer } from '../serve.mjs';
import { launchChromium } from './chromium.mjs';

const VIEWPORT = { width: 1200, height: 800 };
/** Layout of the app's first frame (app.rs, view.rs): a 280-point side panel; the canvas shows (5, 5) at its centre
 *  at 30 points per unit, y up, with grid snapping to whole units on. */
const PANEL = 280;
const CANVAS = { width: VIEWPORT.width - PANEL, height: VIEWPORT.height };
/** World → page coordinates for a view centred on `center` at `scale` points per unit. */
const viewOf = (center, scale) => ([x, y]) => ({
  x: PANEL + CANVAS.width / 2 + (x - center[0]) * scale,
  y: CANVAS.height / 2 - (y - center[1]) * scale,
});
const screen = viewOf([5, 5], 30);
/** The view after loading data (and after F): the data's box, centred, filling 90% of the canvas (view.rs). */
const fitted = ([x0, y0], [x1, y1]) =>
  viewOf([(x0 + x1) / 2, (y0 + y1) / 2], 0.9 * Math.min(CANVAS.width / (x1 - x0), CANVAS.height / (y1 - y0)));
const ERROR_TEXT = [255, 64, 64]; // app.rs ERROR_TEXT: errors in the side panel
const RESULT_FILL = [250, 190, 40]; // app.rs RESULT_FILL
const PIECE_FILLS = [
  RESULT_FILL, [70, 200, 170], [175, 140, 250], [150, 215, 90], [245, 125, 185], [110, 190, 245], [240, 140, 70],
  [215, 225, 120],
]; // app.rs PIECE_FILLS
const LINE_INSIDE = [255, 255, 255]; // app.rs LINE_INSIDE

const SUBJECT = [[0, 0], [4, 0], [4, 4], [0, 4]];
const CLIPPING = [[2, 2], [6, 2], [6, 6], [2, 6]];
// qCorner lies in Q next to its last corner (2, 6), outside the triangle Q would be without that corner.
const PROBES = { both: [3, 3], onlyP: [1, 1], onlyQ: [5, 5], qCorner: [2.5, 5.5], neither: [8, 1] };
const OPERATIONS = [
  { key: 'Digit1', name: 'intersection', filled: ['both'] },
  { key: 'Digit2', name: 'union', filled: ['both', 'onlyP', 'onlyQ', 'qCorner'] },
  { key: 'Digit3', name: 'P − Q', filled: ['onlyP'] },
  { key: 'Digit4', name: 'Q − P', filled: ['onlyQ', 'qCorner'] },
  { key: 'Digit5', name: 'xor', filled: ['onlyP', 'onlyQ', 'qCorner'] },
];

let server;
let origin;

before(async () => {
  const glue = path.join(repositoryRoot, 'target', 'playground', 'polysweep_playground.js');
  assert.ok(existsSync(glue), 'the playground is not built: run web/build-playground.sh');
  ({ server, origin } = await serve());
});

after(async () => {
  await stopServer(server);
});

const near = (colour, [r, g, b], tolerance) =>
  Math.abs(colour[0] - r) <= tolerance && Math.abs(colour[1] - g) <= tolerance && Math.abs(colour[2] - b) <= tolerance;
const isResultColour = (colour) => near(colour, RESULT_FILL, 12);

async function screenshot(page) {
  const png = PNG.sync.read(await page.screenshot());
  const at = (x, y) => {
    const i = (Math.round(y) * png.width + Math.round(x)) * 4;
    return [png.data[i], png.data[i + 1], png.data[i + 2]];
  };
  /** How many pixels of the box [x0, x1) × [y0, y1) are within `tolerance` of `colour`. */
  const count = (x0, y0, x1, y1, colour, tolerance) => {
    let n = 0;
    for (let y = y0; y < y1; y++) for (let x = x0; x < x1; x++) n += near(at(x, y), colour, tolerance) ? 1 : 0;
    return n;
  };
  return { at, count };
}

/** Polls the screenshot until `check` holds (egui repaints on input, a frame or two later); fails with `describe`. */
async function expectScreen(page, check, describe) {
  let shot;
  for (let attempt = 0; attempt < 40; attempt++) {
    shot = await screenshot(page);
    if (check(shot)) return;
    await page.waitForTimeout(250);
  }
  assert.fail(describe(shot));
}

/** Expects the result colour at exactly the probes named in `filled` (of `probes`), in `view`. */
async function expectFill(page, filled, label, view = screen, probes = PROBES) {
  const names = Object.keys(probes);
  let seen;
  for (let attempt = 0; attempt < 40; attempt++) {
    const shot = await screenshot(page);
    const colours = names.map((n) => view(probes[n])).map(({ x, y }) => shot.at(x, y));
    seen = Object.fromEntries(names.map((n, i) => [n, colours[i]]));
    if (names.every((n) => isResultColour(seen[n]) === filled.includes(n))) return;
    await page.waitForTimeout(250);
  }
  assert.fail(`${label}: expected the result colour at ${JSON.stringify(filled)} only; pixels were ${JSON.stringify(seen)}`);
}

// The same steps on each of the browser's paths: WebGPU where the browser offers it (real browsers take it first),
// WebGL2 otherwise. Both run on SwiftShader here, the CPU renderer of a machine without a GPU.
for (const renderer of ['WebGL2', 'WebGPU']) {
  test(`${renderer}: the playground draws two squares with the mouse and fills each operation correctly`, { timeout: 180_000 }, () => drawAndCheck(renderer));
}

// Shapes that test the fill: P is a square A = [0, 8]² with a hole H = [1, 3]² (a ring started inside A becomes
// its hole, wound the other way) and a square B = [4, 12]² overlapping A, drawn the same way round as A; Q is a
// self-crossing bow-tie (2, 2), (10, 10), (10, 2), (2, 10), whose lobes, left L and right R, meet at (6, 6).
// Under even-odd, P is A ⊕ H ⊕ B (the overlap of A and B is empty); under non-zero, (A − H) ∪ B. Both rules fill
// both lobes of Q (winding +1 and −1). Each probe's membership, worked out from the shapes by hand:
const SHAPES = {
  A: [[0, 0], [8, 0], [8, 8], [0, 8]],
  H: [[1, 1], [3, 1], [3, 3], [1, 3]],
  B: [[12, 12], [4, 12], [4, 4], [12, 4]],
  Q: [[2, 2], [10, 10], [10, 2], [2, 10]],
};
const SHAPE_PROBES = {
  // name: [position, in P under even-odd, in P under non-zero, in Q]
  hole: [[1.5, 2.5], false, false, false],
  aOnly: [[0.5, 5], true, true, false],
  aAndL: [[3, 6], true, true, true],
  overlapAndL: [[5, 5.5], false, true, true],
  overlap: [[7, 4.5], false, true, false],
  bAndR: [[9, 6], true, true, true],
  bOnly: [[11, 11], true, true, false],
  rOnly: [[9.5, 3], false, false, true],
  nothing: [[15, 1], false, false, false],
};
const RESULTS = [
  { key: 'Digit1', name: 'intersection', holds: (p, q) => p && q },
  { key: 'Digit2', name: 'union', holds: (p, q) => p || q },
  { key: 'Digit3', name: 'P − Q', holds: (p, q) => p && !q },
  { key: 'Digit4', name: 'Q − P', holds: (p, q) => q && !p },
  { key: 'Digit5', name: 'xor', holds: (p, q) => p !== q },
];

for (const renderer of ['WebGL2', 'WebGPU']) {
  test(`${renderer}: a holed, overlapping P and a self-crossing Q, every operation under even-odd and non-zero`, { timeout: 180_000 }, () =>
    drawShapesAndCheck(renderer));
}

async function drawShapesAndCheck(renderer) {
  const { context, close } = await launchChromium({ webgpu: renderer === 'WebGPU' });
  const page = await context.newPage();
  await page.setViewportSize(VIEWPORT);
  try {
    await page.goto(`${origin}/index.html`);
    await page.waitForFunction(() => window.playgroundReady || window.playgroundFailure, null, { timeout: 120_000 });
    assert.equal(await page.evaluate(() => window.playgroundRenderer), renderer);
    await page.waitForTimeout(500);
    // Each ring: its corners, then a click on its first corner to close it.
    const drawRing = async (corners) => {
      for (const corner of [...corners, corners[0]]) {
        await page.mouse.click(screen(corner).x, screen(corner).y);
        await page.waitForTimeout(400);
      }
    };
    for (const ring of [SHAPES.A, SHAPES.H, SHAPES.B]) await drawRing(ring);
    await page.keyboard.press('KeyQ');
    await drawRing(SHAPES.Q);
    const probes = Object.fromEntries(Object.entries(SHAPE_PROBES).map(([name, [at]]) => [name, at]));
    for (const [ruleKey, rule, inP] of [['KeyE', 'even-odd', 1], ['KeyN', 'non-zero', 2]]) {
      await page.keyboard.press(ruleKey);
      for (const { key, name, holds } of RESULTS) {
        await page.keyboard.press(key);
        const filled = Object.keys(SHAPE_PROBES).filter((n) => holds(SHAPE_PROBES[n][inP], SHAPE_PROBES[n][3]));
        await expectFill(page, filled, `${rule}, ${name}`, screen, probes);
      }
    }
    assert.equal(await page.evaluate(() => window.playgroundFailure), undefined);
  } finally {
    await page.close();
    await close();
  }
}

async function drawAndCheck(renderer) {
  const { context, close } = await launchChromium({ webgpu: renderer === 'WebGPU' });
  const page = await context.newPage();
  await page.setViewportSize(VIEWPORT);
  const problems = [];
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console.error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.stack ?? error.message}`));
  page.on('response', (response) => {
    if (response.status() >= 400) problems.push(`HTTP ${response.status()}: ${response.url()}`);
  });
  try {
    await page.goto(`${origin}/index.html`);
    await page.waitForFunction(() => window.playgroundReady || window.playgroundFailure, null, { timeout: 120_000 });
    assert.equal(await page.evaluate(() => window.playgroundFailure), undefined);
    assert.equal(await page.evaluate(() => window.playgroundRenderer), renderer);
    assert.ok(await page.isHidden('#status'), 'the loading message is gone');
    await page.waitForTimeout(500);
    await expectFill(page, [], 'before drawing');

    // P: four clicks and a click on the first vertex to close it; then Q (key Q): three clicks and a double-click
    // on its last corner, which closes the ring with that corner in it. Clicks are spaced so that none pairs with
    // the next into a double-click.
    for (const corner of [...SUBJECT, SUBJECT[0]]) {
      await page.mouse.click(screen(corner).x, screen(corner).y);
      await page.waitForTimeout(400);
    }
    await page.keyboard.press('KeyQ');
    for (const corner of CLIPPING.slice(0, 3)) {
      await page.mouse.click(screen(corner).x, screen(corner).y);
      await page.waitForTimeout(400);
    }
    await page.mouse.dblclick(screen(CLIPPING[3]).x, screen(CLIPPING[3]).y);

    for (const { key, name, filled } of OPERATIONS) {
      await page.keyboard.press(key);
      await expectFill(page, filled, name);
    }

    // Dragging P's corner (4, 0) to (10, 0) stretches P over the fourth probe (its edge to (4, 4) crosses y = 1 at
    // x = 8.5); the union follows the drag. One Ctrl+Z undoes the whole drag, a second one removes Q.
    await page.keyboard.press('Digit2');
    const [from, to] = [screen([4, 0]), screen([10, 0])];
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move(to.x, to.y, { steps: 12 });
    await page.mouse.up();
    await expectFill(page, ['both', 'onlyP', 'onlyQ', 'qCorner', 'neither'], 'union after the drag');
    await page.keyboard.press('Control+KeyZ');
    await expectFill(page, ['both', 'onlyP', 'onlyQ', 'qCorner'], 'union after undoing the drag');
    await page.keyboard.press('Control+KeyZ');
    await expectFill(page, ['both', 'onlyP'], 'union after undoing Q');

    // GeoJSON pasted (Ctrl+V reaches the app as the document's paste event) replaces Q and fits the view to the
    // data, here the box (0, 0)–(9, 4).
    const paste = (text) =>
      page.evaluate((t) => {
        const data = new DataTransfer();
        data.setData('text', t);
        document.dispatchEvent(new ClipboardEvent('paste', { clipboardData: data, bubbles: true }));
      }, text);
    const panelErrorPixels = (shot) => shot.count(0, 0, PANEL - 10, VIEWPORT.height, ERROR_TEXT, 20);
    await page.keyboard.press('KeyQ');
    await paste(JSON.stringify({ type: 'Polygon', coordinates: [[[7, 0], [9, 0], [9, 2], [7, 2], [7, 0]]] }));
    const afterPaste = fitted([0, 0], [9, 4]);
    await expectFill(page, ['both', 'onlyP', 'neither'], 'union with the pasted Q', afterPaste);
    assert.equal(panelErrorPixels(await screenshot(page)), 0, 'no error is shown yet');

    // A coordinate beyond the core's range: the error is shown in the panel (in red), there is no result, nothing
    // crashes; undo and F (fit) bring the previous Q and the union back.
    await paste(JSON.stringify({ type: 'Polygon', coordinates: [[[7, 0], [1e300, 0], [9, 2], [7, 0]]] }));
    await expectScreen(
      page,
      (shot) => panelErrorPixels(shot) > 20 && shot.count(PANEL, 0, VIEWPORT.width, VIEWPORT.height, RESULT_FILL, 12) === 0,
      (shot) => `expected the error in the panel and no result: ${panelErrorPixels(shot)} red pixels`,
    );
    await page.keyboard.press('Control+KeyZ');
    await page.keyboard.press('KeyF');
    await expectFill(page, ['both', 'onlyP', 'neither'], 'union after undoing the bad paste', afterPaste);
    assert.equal(panelErrorPixels(await screenshot(page)), 0, 'the error is gone');

    // The line tool (key L): a click at (2, -1) and a double-click at (2, 5) draw a line down the middle of P, which
    // cuts P into two pieces of different colours, each holding one of the probes (1, 1) and (3, 1); the line's
    // part inside the result is drawn in its own colour. Ctrl+Z removes the line, and the union is one colour again.
    await page.keyboard.press('KeyL');
    const [lineStart, lineEnd] = [afterPaste([2, -1]), afterPaste([2, 5])];
    await page.mouse.click(lineStart.x, lineStart.y);
    await page.waitForTimeout(400);
    await page.mouse.dblclick(lineEnd.x, lineEnd.y);
    const pieceOf = (colour) => PIECE_FILLS.findIndex((fill) => near(colour, fill, 12));
    const halves = [[1, 1], [3, 1]].map(afterPaste);
    const onLine = afterPaste([2, 2]);
    await expectScreen(
      page,
      (shot) => {
        const [left, right] = halves.map(({ x, y }) => pieceOf(shot.at(x, y)));
        return left >= 0 && right >= 0 && left !== right && near(shot.at(onLine.x, onLine.y), LINE_INSIDE, 30);
      },
      (shot) =>
        `expected two piece colours either side of the line and the line on them: pixels were ` +
        `${JSON.stringify([...halves, onLine].map(({ x, y }) => shot.at(x, y)))}`,
    );
    await page.keyboard.press('Control+KeyZ');
    await expectFill(page, ['both', 'onlyP', 'neither'], 'union after undoing the line', afterPaste);
    assert.equal(await page.evaluate(() => window.playgroundFailure), undefined);
    assert.deepEqual(problems, [], `the page reported errors:\n${problems.join('\n')}`);
  } finally {
    await page.close();
    await close();
  }
}

// The land preset (Natural Earth land × 8 squares, ?preset=land-8), intersection: the bottom-right corner of the
// top-left square, (−100.28, 5.48), open Pacific far from any island, is dragged to (−60, −10) with snapping off
// (key G). The square becomes the quadrilateral (−169.72, 5.48), (−60, −10), (−100.28, 74.92), (−169.72, 74.92),
// which now also covers northern South America. The probes, from the geography and that quadrilateral by hand
// (each several degrees from a coast and from the quadrilateral's edges):
const LAND_PROBES = {
  // name: [position, in the intersection before the drag, after it]
  canada: [[-110, 60], true, true], // land, in the square before and after
  amazonas: [[-70, -5], false, true], // Brazil, inland: under the new bottom edge's sweep
  colombia: [[-74, 4], false, true], // inland, south of the square's old bottom edge (5.48)
  pacific: [[-110, 0], false, false], // ocean inside the quadrilateral
  para: [[-50, -8], false, false], // Brazil, inland, right of the new edge to (−100.28, 74.92)
};
const LAND_CORNER = [-100.280278125, 5.480235156250018];
const LAND_TARGET = [-60, -10];
const landView = fitted([-180, -90], [180, 83.59960937500003]);
const counters = (page) => page.evaluate(() => Array.from(window.playgroundHandle.counters()));

for (const renderer of ['WebGL2', 'WebGPU']) {
  test(`${renderer}: dragging a square of the land preset, the canvas keeps drawing while the worker computes`, { timeout: 240_000 }, () =>
    dragLandAndCheck(renderer));
}

async function dragLandAndCheck(renderer) {
  const { context, close } = await launchChromium({ webgpu: renderer === 'WebGPU' });
  const page = await context.newPage();
  await page.setViewportSize(VIEWPORT);
  const problems = [];
  page.on('pageerror', (error) => problems.push(`page error: ${error.stack ?? error.message}`));
  page.on('console', (message) => {
    if (message.type() === 'error' || message.text().includes('worker')) problems.push(`console: ${message.text()}`);
  });
  try {
    await page.goto(`${origin}/index.html?preset=land-8`);
    await page.waitForFunction(() => window.playgroundReady || window.playgroundFailure, null, { timeout: 120_000 });
    assert.equal(await page.evaluate(() => window.playgroundRenderer), renderer);
    const probes = Object.fromEntries(Object.entries(LAND_PROBES).map(([name, [at]]) => [name, at]));
    const filled = (i) => Object.keys(LAND_PROBES).filter((name) => LAND_PROBES[name][i]);
    await expectFill(page, filled(1), 'land ∩ 8 squares', landView, probes);
    await page.waitForFunction(() => !window.playgroundHandle.pending(), null, { timeout: 60_000 });
    await page.keyboard.press('KeyG');

    const [from, to] = [landView(LAND_CORNER), landView(LAND_TARGET)];
    const [framesBefore, , resultsBefore] = await counters(page);
    const started = Date.now();
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    const steps = 10;
    for (let i = 1; i <= steps; i++) {
      await page.mouse.move(from.x + ((to.x - from.x) * i) / steps, from.y + ((to.y - from.y) * i) / steps);
      await page.waitForTimeout(50);
    }
    await page.mouse.up();
    const [framesAtRelease, pendingFramesAtRelease, resultsAtRelease] = await counters(page);
    await page.waitForFunction(() => !window.playgroundHandle.pending(), null, { timeout: 60_000 });
    const settled = Date.now();
    const [framesAfter, pendingFrames, resultsAfter, inWorker, operationMs] = await counters(page);
    await expectFill(page, filled(2), 'land ∩ squares after the drag', landView, probes);

    const seconds = (settled - started) / 1000;
    console.log(
      `${renderer}, land × 8 drag: ${framesAfter - framesBefore} frames in ${seconds.toFixed(1)} s ` +
        `(${((framesAfter - framesBefore) / seconds).toFixed(1)} a second; ${pendingFrames} drawn so far while a ` +
        `result was pending), ${resultsAfter - resultsBefore} results from the worker ` +
        `(${((resultsAfter - resultsBefore) / seconds).toFixed(1)} a second; the operation itself took ` +
        `${operationMs.toFixed(0)} ms in the worker, SwiftShader drawing on the same two cores)`,
    );
    // The drag asked for results while it moved; the worker computed them, and the canvas went on drawing
    // meanwhile (not asserted: how many frames, which depends on the machine).
    assert.equal(inWorker, 1, 'the results were computed in the worker');
    assert.ok(resultsAtRelease > resultsBefore, 'results came during the drag');
    assert.ok(resultsAfter > resultsBefore);
    assert.ok(pendingFramesAtRelease > 0, 'frames were drawn while a result was pending');
    assert.ok(framesAtRelease - framesBefore >= steps, 'a frame at least for every move');
    assert.deepEqual(problems, [], `the page reported:\n${problems.join('\n')}`);
  } finally {
    await page.close();
    await close();
  }
}

// The sweep explorer (key X) on the paper's Fig. 7 case (?preset=fig7, tests/fixtures/fig7-sweep-line.json): the
// triangles P = (0,4) (4,0) (8,4) and Q = (0,−1) (12,−1) (6,5). Worked out by hand from §3 (the same reasoning as
// crates/polysweep/tests/trace.rs): events 0–3 are at x = 0 — the left ends of Q's d = (0,−1)–(12,−1) and
// e = (0,−1)–(6,5), then of P's a = (0,4)–(4,0) and c = (0,4)–(8,4); inserting a splits a and e where they cross,
// at i = (2.5, 1.5). After event 3, S bottom to top is d, e up to i, a up to i, c. Events 4–7 are at i: the first
// parts of e and a leave S, their second parts a′ = i–(4,0) and e′ = i–(6,5) enter, and e′ is split where it
// crosses c, at (5, 4): S is d, a′, e′ up to (5,4), c up to (5,4). Event 8, the right end of a′ at (4, 0), selects
// a′ into P ∩ Q (inside Q); e's first part was not selected (outside P). After the last event the connection step
// closes the ring of P ∩ Q.
const STATUS_COLOURS = [[255, 80, 200], [80, 220, 255], [0, 200, 140], [110, 255, 110], [255, 140, 40], [170, 130, 255]]; // explore.rs
const fig7View = fitted([0, -1], [12, 5]);
const EXPLORER_STEPS = [
  // [presses of → from the previous check, [edge midpoint, colour] pairs expected, what it shows]
  [3, [[[6, -1], STATUS_COLOURS[0]], [[1.25, 0.25], STATUS_COLOURS[1]], [[1.25, 2.75], STATUS_COLOURS[2]], [[4, 4], STATUS_COLOURS[3]]], 'S = d, e to i, a to i, c after event 3'],
  [4, [[[6, -1], STATUS_COLOURS[0]], [[3.25, 0.75], STATUS_COLOURS[1]], [[3.75, 2.75], STATUS_COLOURS[2]], [[2.5, 4], STATUS_COLOURS[3]]], 'S = d, a′, e′ to (5,4), c to (5,4) after event 7'],
  [1, [[[3.25, 0.75], RESULT_FILL]], 'a′ selected into P ∩ Q by event 8'],
];

test('WebGL2: the sweep explorer steps through Fig. 7 as §3 describes it', { timeout: 180_000 }, async () => {
  const { context, close } = await launchChromium({ webgpu: false });
  const page = await context.newPage();
  await page.setViewportSize(VIEWPORT);
  try {
    await page.goto(`${origin}/index.html?preset=fig7`);
    await page.waitForFunction(() => window.playgroundReady || window.playgroundFailure, null, { timeout: 120_000 });
    await page.waitForTimeout(500);
    await page.keyboard.press('KeyX');
    for (const [presses, expected, label] of EXPLORER_STEPS) {
      for (let i = 0; i < presses; i++) {
        await page.keyboard.press('ArrowRight');
        await page.waitForTimeout(150);
      }
      const probes = expected.map(([at, colour]) => [fig7View(at), colour]);
      await expectScreen(
        page,
        (shot) => probes.every(([{ x, y }, colour]) => near(shot.at(x, y), colour, 12)),
        (shot) => `${label}: expected ${JSON.stringify(expected)}, pixels ${JSON.stringify(probes.map(([{ x, y }]) => shot.at(x, y)))}`,
      );
    }
    // e's first part, outside P, was not selected: no explorer colour there once it has left S.
    const eFirst = fig7View([1.25, 0.25]);
    const shot = await screenshot(page);
    assert.ok(![RESULT_FILL, ...STATUS_COLOURS].some((c) => near(shot.at(eFirst.x, eFirst.y), c, 12)), `e's first part: ${shot.at(eFirst.x, eFirst.y)}`);
    // After the last event the ring of P ∩ Q is closed and filled: (5, 2) is inside it, (2, 3) in P only.
    await page.keyboard.press('End');
    const [inside, outside] = [fig7View([5, 2]), fig7View([2, 3])];
    await expectScreen(
      page,
      (s) => isResultColour(s.at(inside.x, inside.y)) && !isResultColour(s.at(outside.x, outside.y)),
      (s) => `the closed ring: ${s.at(inside.x, inside.y)} inside, ${s.at(outside.x, outside.y)} outside`,
    );
    assert.equal(await page.evaluate(() => window.playgroundFailure), undefined);
  } finally {
    await page.close();
    await close();
  }
});
