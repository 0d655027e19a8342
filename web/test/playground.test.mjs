// The playground (index.html, built by web/build-playground.sh) in headless Chromium: it starts without console
// errors, two squares are drawn with the mouse, each operation is chosen with its key, and the screenshot must be
// filled with the result colour exactly where that operation's result is and nowhere else; a vertex drag and undo
// update it.
//
// Expectations are independent of the app: which of four probe points lies in each result follows from the two
// squares by hand. The probes sit mid-region, away from edges, so antialiasing cannot touch them.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { repositoryRoot, serve } from '../serve.mjs';
import { launchChromium } from './chromium.mjs';

const VIEWPORT = { width: 1200, height: 800 };
/** Layout of the app's first frame (app.rs, view.rs): a 280-point side panel; the canvas shows (5, 5) at its centre
 *  at 30 points per unit, y up, with grid snapping to whole units on. */
const PANEL = 280;
const screen = ([x, y]) => ({
  x: PANEL + (VIEWPORT.width - PANEL) / 2 + (x - 5) * 30,
  y: VIEWPORT.height / 2 - (y - 5) * 30,
});
const RESULT_FILL = [250, 190, 40]; // app.rs RESULT_FILL

const SUBJECT = [[0, 0], [4, 0], [4, 4], [0, 4]];
const CLIPPING = [[2, 2], [6, 2], [6, 6], [2, 6]];
const PROBES = { both: [3, 3], onlyP: [1, 1], onlyQ: [5, 5], neither: [8, 1] };
const OPERATIONS = [
  { key: 'Digit1', name: 'intersection', filled: ['both'] },
  { key: 'Digit2', name: 'union', filled: ['both', 'onlyP', 'onlyQ'] },
  { key: 'Digit3', name: 'P − Q', filled: ['onlyP'] },
  { key: 'Digit4', name: 'Q − P', filled: ['onlyQ'] },
  { key: 'Digit5', name: 'xor', filled: ['onlyP', 'onlyQ'] },
];

let server;
let origin;
let context;
let closeChromium;

before(async () => {
  const glue = path.join(repositoryRoot, 'target', 'playground', 'polysweep_playground.js');
  assert.ok(existsSync(glue), 'the playground is not built: run web/build-playground.sh');
  ({ server, origin } = await serve());
  ({ context, close: closeChromium } = await launchChromium());
});

after(async () => {
  await closeChromium?.();
  server?.closeAllConnections();
  await new Promise((resolve) => (server ? server.close(resolve) : resolve()));
});

const isResultColour = ([r, g, b]) =>
  Math.abs(r - RESULT_FILL[0]) <= 12 && Math.abs(g - RESULT_FILL[1]) <= 12 && Math.abs(b - RESULT_FILL[2]) <= 12;

async function pixelsAt(page, points) {
  const png = PNG.sync.read(await page.screenshot());
  return points.map(({ x, y }) => {
    const i = (Math.round(y) * png.width + Math.round(x)) * 4;
    return [png.data[i], png.data[i + 1], png.data[i + 2]];
  });
}

/** Polls the screenshot until the probes show `filled` (egui repaints on input, a frame or two later). */
async function expectFill(page, filled, label) {
  const names = Object.keys(PROBES);
  let seen;
  for (let attempt = 0; attempt < 40; attempt++) {
    const colours = await pixelsAt(page, names.map((n) => screen(PROBES[n])));
    seen = Object.fromEntries(names.map((n, i) => [n, colours[i]]));
    if (names.every((n) => isResultColour(seen[n]) === filled.includes(n))) return;
    await page.waitForTimeout(250);
  }
  assert.fail(`${label}: expected the result colour at ${JSON.stringify(filled)} only; pixels were ${JSON.stringify(seen)}`);
}

test('the playground draws two squares with the mouse and fills each operation correctly', { timeout: 180_000 }, async () => {
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
    assert.ok(await page.isHidden('#status'), 'the loading message is gone');
    await page.waitForTimeout(500);
    await expectFill(page, [], 'before drawing');

    // P: four clicks and a click on the first vertex to close it; then Q (key Q), closed with Enter. Clicks are
    // spaced so that none pairs with the next into a double-click.
    for (const corner of [...SUBJECT, SUBJECT[0]]) {
      await page.mouse.click(screen(corner).x, screen(corner).y);
      await page.waitForTimeout(400);
    }
    await page.keyboard.press('KeyQ');
    for (const corner of CLIPPING) {
      await page.mouse.click(screen(corner).x, screen(corner).y);
      await page.waitForTimeout(400);
    }
    await page.keyboard.press('Enter');

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
    await expectFill(page, ['both', 'onlyP', 'onlyQ', 'neither'], 'union after the drag');
    await page.keyboard.press('Control+KeyZ');
    await expectFill(page, ['both', 'onlyP', 'onlyQ'], 'union after undoing the drag');
    await page.keyboard.press('Control+KeyZ');
    await expectFill(page, ['both', 'onlyP'], 'union after undoing Q');
    assert.equal(await page.evaluate(() => window.playgroundFailure), undefined);
    assert.deepEqual(problems, [], `the page reported errors:\n${problems.join('\n')}`);
  } finally {
    await page.close();
  }
});
