// Benchmark inputs: Natural Earth land and the grids of N squares (tests/data/README.md gives the rule).
//
// The native benchmark (crates/polysweep-bench) writes them to target/bench/; when a file is there it is used as
// is, so both benchmarks run on the same bytes. Otherwise land comes from tests/data/land-50m.json.gz and the
// squares are generated here by the same rule (checked against the shipped squares-{8,162,974,3895}.json.gz).

import { existsSync, readFileSync } from 'node:fs';
import { gunzipSync } from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

export const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const BENCH_DIR = join(ROOT, 'target', 'bench');
export const TEST_DATA = join(ROOT, 'tests', 'data');

/** The scaling series and the paper's three sizes, ascending. */
export const SQUARE_COUNTS = [8, 32, 128, 162, 512, 974, 2048, 3895, 8192, 32768];
/** Union and difference are measured at this N only. */
export const FULL_N = 3895;

/** Reference areas from tests/data/README.md (all exact float engines agree to these digits). */
export const REFERENCE_AREAS = {
  intersection: { 8: 12707.833308, 162: 13044.967019, 974: 13451.382211, 3895: 13307.146280 },
  union: { 3895: 46913.956575 },
  difference: { 3895: 8110.128937 },
};
/** The reference areas are printed to 6 decimals: half a unit of the last digit (absolute). */
export const REFERENCE_TOLERANCE = 5e-7;

/** Bounding box of the raw land data, as the rule states it. */
export const BBOX = [-180, -89.999, 180, 83.59960937500003];

function readJson(path) {
  const bytes = readFileSync(path);
  const text = path.endsWith('.gz') ? gunzipSync(bytes).toString('utf8') : bytes.toString('utf8');
  return JSON.parse(text);
}

/** MultiPolygon coordinates of a GeoJSON geometry object (MultiPolygon or Polygon). */
function coordinatesOf(geometry, what) {
  if (geometry.type === 'MultiPolygon') return geometry.coordinates;
  if (geometry.type === 'Polygon') return [geometry.coordinates];
  throw new Error(`${what}: expected a MultiPolygon or Polygon geometry, got ${geometry.type}`);
}

/** Land as MultiPolygon coordinates, and where it came from. */
export function loadLand() {
  const fromBench = join(BENCH_DIR, 'land.json');
  const path = existsSync(fromBench) ? fromBench : join(TEST_DATA, 'land-50m.json.gz');
  return { coordinates: coordinatesOf(readJson(path), path), source: path };
}

/** The grid of n squares as MultiPolygon coordinates: closed, counter-clockwise rings. */
export function generateSquares(n) {
  const [xmin, ymin, xmax, ymax] = BBOX;
  const w = xmax - xmin;
  const h = ymax - ymin;
  const cols = Math.max(1, Math.round(Math.sqrt((n * w) / h)));
  const rows = Math.ceil(n / cols);
  const cw = w / cols;
  const ch = h / rows;
  const side = 0.8 * Math.min(cw, ch);
  const polygons = [];
  for (let i = 0; i < n; i++) {
    const cell = Math.floor((i * cols * rows) / n);
    const col = cell % cols;
    const row = Math.floor(cell / cols);
    const cx = xmin + (col + 0.5) * cw;
    const cy = ymin + (row + 0.5) * ch;
    const x0 = cx - side / 2;
    const x1 = cx + side / 2;
    const y0 = cy - side / 2;
    const y1 = cy + side / 2;
    polygons.push([[[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]]]);
  }
  return polygons;
}

/** The n squares, from target/bench when the native benchmark wrote them, else generated. */
export function loadSquares(n) {
  const fromBench = join(BENCH_DIR, `squares-${n}.json`);
  if (existsSync(fromBench)) return { coordinates: coordinatesOf(readJson(fromBench), fromBench), source: fromBench };
  return { coordinates: generateSquares(n), source: 'generated (web/bench/data.mjs)' };
}

/** The shipped squares file for n, when there is one (for checking the generator). */
export function shippedSquares(n) {
  const path = join(TEST_DATA, `squares-${n}.json.gz`);
  return existsSync(path) ? coordinatesOf(readJson(path), path) : null;
}

/**
 * Signed area of a ring (closed or not), shoelace about its first vertex (as GEOS computes it: no cancellation at
 * large coordinates).
 */
export function ringArea(ring) {
  const n = ring.length;
  if (n < 3) return 0;
  const ox = ring[0][0];
  const oy = ring[0][1];
  let s = 0;
  let px = ring[n - 1][0] - ox;
  let py = ring[n - 1][1] - oy;
  for (let i = 0; i < n; i++) {
    const x = ring[i][0] - ox;
    const y = ring[i][1] - oy;
    s += px * y - x * py;
    px = x;
    py = y;
  }
  return s / 2;
}

/** Area of MultiPolygon coordinates: exteriors minus holes, whatever the rings' orientation. */
export function multiPolygonArea(polygons) {
  let area = 0;
  for (const polygon of polygons) {
    for (let r = 0; r < polygon.length; r++) {
      const a = Math.abs(ringArea(polygon[r]));
      area += r === 0 ? a : -a;
    }
  }
  return area;
}

/** Number of vertices (closing vertex not counted) of MultiPolygon coordinates. */
export function vertexCount(polygons) {
  let n = 0;
  for (const polygon of polygons) for (const ring of polygon) n += ring.length - 1;
  return n;
}

// ---------------------------------------------------------------- dense workloads (issue 25) --------------------
//
// The native benchmark writes them (crates/polysweep-bench/src/dense.rs is their generator): an index of every
// workload at every size, and one file per workload and size holding both operands.

export const DENSE_DIR = join(BENCH_DIR, 'dense');

/** The index: [{workload, n, operation, fill_rule, file, edges}], in the native benchmark's order; null when absent. */
export function loadDenseIndex() {
  const path = join(DENSE_DIR, 'index.json');
  return existsSync(path) ? readJson(path) : null;
}

/** One dense workload at one size: {workload, n, operation, fill_rule, edges, subject, clip}. */
export function loadDense(file) {
  return readJson(join(DENSE_DIR, file));
}

/**
 * The two operands of a benchmark input: {kind: 'table1', n} is land and the n squares, {kind: 'dense', file} a
 * dense workload's subject and clip. Land is read once per process (callers copy what they hand to an engine).
 */
let land = null;
export function loadOperands(input) {
  if (input.kind === 'dense') {
    const { subject, clip } = loadDense(input.file);
    return [subject, clip];
  }
  land ??= loadLand().coordinates;
  return [land, loadSquares(input.n).coordinates];
}
