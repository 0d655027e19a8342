#!/usr/bin/env node
// The layer-overlay benchmark: intersect a cadastre with a zoning map, every parcel against every zone it touches,
// each output piece carrying the properties of both (what GIS calls "overlay" / "identity" / "intersect layers").
//
// Workload (web/bench/layers-data.mjs, deterministic from --seed): by default 10,000 parcels, a 100 × 100 grid of
// 20 m quadrilaterals with jittered shared vertices (a planar partition, like a cadastre: every edge is shared by
// two parcels) and 100 zones, a 10 × 10 partition of the same 2 km × 2 km extent whose shared boundaries are jagged
// polylines (20 segments per zone edge, up to 6 m off the straight line), so zone boundaries cut parcels anywhere.
// Coordinates: metres at a UTM-like origin (600000, 5300000), full doubles. Both layers are written as GeoJSON to
// target/bench/layers/p<N>-z<M>-s<seed>/ so the Python side reads the same bytes.
//
// Engines (timed end to end; a warm-up run, then --runs timed runs, fewer when the warm-up is slow; min and median):
//   polysweep  polysweep.overlayLayers(parcels, zones, { mode: 'intersection' }) of the npm package in pkg/: GeoJSON
//              FeatureCollections in (parsed objects), a FeatureCollection out.
//   turf       the usual way in JS: @turf/bbox of every feature, a uniform-grid index of the zones' boxes, then
//              @turf/intersect (turf 7, polyclip-ts inside) on every (parcel, zone) pair whose boxes overlap; a
//              Feature with both properties per non-null result. Objects in, objects out.
//   geos       shapely 2 / GEOS in Python (web/bench/layers_geos.py, run as a child process, its own timing):
//              geopandas.overlay's recipe — STRtree of the zones queried with the parcels (predicate 'intersects'),
//              one vectorised shapely.intersection over the candidate pairs, pieces of positive area kept. Its time
//              is from GeoJSON text to GeoJSON text (GEOS's reader and writer, the properties attached); the table
//              also shows its core (index, query, intersections) alone.
//
// Agreement (not asserted): for every (parcel, zone) pair with positive intersection area in any engine, its area in
// each engine (pieces of a pair summed; polysweep's pieces credited to every pair of aIndices × bIndices; areas by
// the shoelace about each ring's first vertex, as GEOS computes them), compared with GEOS's: the number of pairs,
// the largest absolute and relative difference, the pairs differing by more than 1e-9 relative, and the pairs only
// one side has. Pieces: features returned (polysweep: features of the FeatureCollection; turf: non-null results;
// GEOS: non-empty intersections).
//
//   node web/bench/layers.mjs [--quick] [--parcels N] [--zones M] [--engines polysweep,turf,geos] [--runs R]
//                             [--seed S] [--origin X,Y] [--python PATH]
//
//   node web/bench/layers.mjs                         # 10,000 parcels × 100 zones, all three engines
//   node web/bench/layers.mjs --quick                 # 900 parcels × 16 zones, 3 timed runs (CI)
//   node web/bench/layers.mjs --parcels 2500 --zones 25 --engines turf,geos
//
// --python: the interpreter with shapely (default .venv/bin/python of the repository, else $POLYSWEEP_PYTHON).
// Needs the devDependencies @turf/intersect and @turf/bbox (npm install). Writes target/bench/layers.json; progress
// goes to stderr, the report to stdout. Exits 0 unless the script itself fails (an engine's failure is reported).

import { execFile } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { BENCH_DIR, ROOT } from './data.mjs';
import { DEFAULT_ORIGIN, geometryArea, writeLayers } from './layers-data.mjs';
import { fmt, machineLine } from './runner.mjs';

const ENGINES = ['polysweep', 'turf', 'geos'];
const REFERENCE = 'geos';
const TOLERANCE = 1e-9; // relative area difference counted as a disagreement
const SLOW_MS = 10_000; // a warm-up slower than this: at most 3 timed runs
const PYTHON_TIMEOUT_MS = 30 * 60_000;
const require = createRequire(import.meta.url);
const log = (s) => process.stderr.write(`${s}\n`);

function parseArgs(argv) {
  const args = {
    parcels: 10_000, zones: 100, quick: false, engines: ENGINES, runs: null, seed: 1, origin: DEFAULT_ORIGIN,
    python: process.env.POLYSWEEP_PYTHON ?? join(ROOT, '.venv', 'bin', 'python'),
  };
  let sized = false;
  for (let i = 0; i < argv.length; i++) {
    const value = () => {
      if (i + 1 >= argv.length) throw new Error(`${argv[i]} needs a value`);
      return argv[++i];
    };
    const a = argv[i];
    if (a === '--quick') args.quick = true;
    else if (a === '--parcels') { args.parcels = Number(value()); sized = true; }
    else if (a === '--zones') { args.zones = Number(value()); sized = true; }
    else if (a === '--engines') args.engines = value().split(',').filter(Boolean);
    else if (a === '--runs') args.runs = Number(value());
    else if (a === '--seed') args.seed = Number(value());
    else if (a === '--origin') args.origin = value().split(',').map(Number);
    else if (a === '--python') args.python = value();
    else throw new Error(`unknown argument ${a} (use --quick, --parcels N, --zones M, --engines a,b, --runs R, --seed S, --origin X,Y, --python PATH)`);
  }
  if (args.quick && !sized) { args.parcels = 900; args.zones = 16; }
  args.runs ??= args.quick ? 3 : 5;
  for (const e of args.engines) if (!ENGINES.includes(e)) throw new Error(`unknown engine ${e}; known: ${ENGINES.join(', ')}`);
  if (!(args.parcels >= 1 && args.zones >= 1)) throw new Error('--parcels and --zones take positive counts');
  if (!(Number.isInteger(args.runs) && args.runs >= 1)) throw new Error('--runs takes a positive integer');
  if (!Number.isInteger(args.seed)) throw new Error('--seed takes an integer');
  if (args.origin.length !== 2 || !args.origin.every(Number.isFinite)) throw new Error('--origin takes X,Y');
  return args;
}

function version(name) {
  try {
    const dir = require.resolve(`${name}/package.json`);
    return JSON.parse(readFileSync(dir, 'utf8')).version;
  } catch {
    // packages whose exports hide package.json
    try {
      return JSON.parse(readFileSync(join(ROOT, 'node_modules', name, 'package.json'), 'utf8')).version;
    } catch {
      return null;
    }
  }
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};

/** Warm-up, then timed runs of fn(); returns {runs, min, median, result (of the last run)}. */
function timeRuns(name, fn, runs) {
  global.gc?.();
  let t = performance.now();
  let result = fn();
  const warm = performance.now() - t;
  const n = warm > SLOW_MS ? Math.min(runs, 3) : runs;
  log(`  ${name}: warm-up ${fmt(warm)} ms, ${n} timed run(s)`);
  const times = [];
  for (let i = 0; i < n; i++) {
    result = null;
    global.gc?.();
    t = performance.now();
    result = fn();
    times.push(performance.now() - t);
  }
  return { warmup_ms: warm, runs_ms: times, min_ms: Math.min(...times), median_ms: median(times), result };
}

// ---------------------------------------------------------------- engines ---------------------------------------

/** Per-pair areas of an overlay's FeatureCollection: Map(a * nB + b -> area) and the number of features. */
function pairAreas(collection, nB) {
  const areas = new Map();
  let multi = 0;
  let uncovered = 0;
  for (const f of collection.features) {
    const p = f.properties ?? {};
    const as = Array.isArray(p.aIndices) ? p.aIndices : p.aIndex == null ? [] : [p.aIndex];
    const bs = Array.isArray(p.bIndices) ? p.bIndices : p.bIndex == null ? [] : [p.bIndex];
    if (as.length !== 1 || bs.length !== 1) multi++;
    if (as.length === 0 || bs.length === 0) { uncovered++; continue; }
    const area = geometryArea(f.geometry);
    for (const a of as) for (const b of bs) areas.set(a * nB + b, (areas.get(a * nB + b) ?? 0) + area);
  }
  return { areas, pieces: collection.features.length, multi, uncovered };
}

async function runPolysweep(text, runs) {
  const ps = await import('polysweep');
  const info = { package: 'polysweep (pkg/)', version: version('polysweep') };
  if (typeof ps.overlayLayers !== 'function') {
    return { ...info, status: 'missing', error: 'polysweep.overlayLayers is not in the built package (pkg/): rebuild with web/build.sh' };
  }
  const parcels = JSON.parse(text.parcels);
  const zones = JSON.parse(text.zones);
  const timed = timeRuns('polysweep', () => ps.overlayLayers(parcels, zones, { mode: 'intersection' }), runs);
  const { areas, pieces, multi, uncovered } = pairAreas(timed.result, zones.features.length);
  const types = {};
  for (const f of timed.result.features) types[f.geometry?.type] = (types[f.geometry?.type] ?? 0) + 1;
  return {
    ...info, status: 'ok', ...strip(timed), pieces, piece_types: types, areas,
    notes: { features_not_one_to_one: multi, features_without_a_or_b: uncovered },
  };
}

/** A uniform grid over boxes [minX, minY, maxX, maxY]: query(box) -> indices of boxes that overlap it (closed). */
class GridIndex {
  constructor(boxes) {
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    let w = 0;
    let h = 0;
    for (const b of boxes) {
      x0 = Math.min(x0, b[0]); y0 = Math.min(y0, b[1]); x1 = Math.max(x1, b[2]); y1 = Math.max(y1, b[3]);
      w += b[2] - b[0]; h += b[3] - b[1];
    }
    this.boxes = boxes;
    this.x0 = x0; this.y0 = y0;
    this.cw = Math.max(w / boxes.length, (x1 - x0) / 1024, Number.MIN_VALUE); // cells about a box's size
    this.ch = Math.max(h / boxes.length, (y1 - y0) / 1024, Number.MIN_VALUE);
    this.nx = Math.max(1, Math.ceil((x1 - x0) / this.cw));
    this.ny = Math.max(1, Math.ceil((y1 - y0) / this.ch));
    this.cells = Array.from({ length: this.nx * this.ny }, () => []);
    this.seen = new Int32Array(boxes.length).fill(-1);
    this.stamp = 0;
    boxes.forEach((b, i) => this.forCells(b, (c) => this.cells[c].push(i)));
  }

  forCells(b, fn) {
    const clamp = (v, n) => Math.min(n - 1, Math.max(0, v));
    const cx0 = clamp(Math.floor((b[0] - this.x0) / this.cw), this.nx);
    const cx1 = clamp(Math.floor((b[2] - this.x0) / this.cw), this.nx);
    const cy0 = clamp(Math.floor((b[1] - this.y0) / this.ch), this.ny);
    const cy1 = clamp(Math.floor((b[3] - this.y0) / this.ch), this.ny);
    for (let cy = cy0; cy <= cy1; cy++) for (let cx = cx0; cx <= cx1; cx++) fn(cy * this.nx + cx);
  }

  query(b) {
    const out = [];
    const stamp = ++this.stamp;
    this.forCells(b, (c) => {
      for (const i of this.cells[c]) {
        if (this.seen[i] === stamp) continue;
        this.seen[i] = stamp;
        const o = this.boxes[i];
        if (o[0] <= b[2] && b[0] <= o[2] && o[1] <= b[3] && b[1] <= o[3]) out.push(i);
      }
    });
    return out.sort((x, y) => x - y);
  }
}

async function runTurf(text, runs) {
  const info = { package: '@turf/intersect', version: version('@turf/intersect'), bbox_version: version('@turf/bbox'), polyclip_ts_version: version('polyclip-ts') };
  let intersect;
  let bbox;
  try {
    ({ intersect } = await import('@turf/intersect'));
    ({ bbox } = await import('@turf/bbox'));
  } catch (e) {
    return { ...info, status: 'missing', error: `${e.message} (npm install: @turf/intersect and @turf/bbox are devDependencies)` };
  }
  const parcels = JSON.parse(text.parcels);
  const zones = JSON.parse(text.zones);
  let candidates = 0;
  let errors = [];
  const overlay = (A, B) => {
    const boxesA = A.features.map((f) => bbox(f));
    const index = new GridIndex(B.features.map((f) => bbox(f)));
    const features = [];
    candidates = 0;
    errors = [];
    for (let i = 0; i < A.features.length; i++) {
      const fa = A.features[i];
      for (const j of index.query(boxesA[i])) {
        candidates++;
        const fb = B.features[j];
        let piece;
        try {
          piece = intersect({ type: 'FeatureCollection', features: [fa, fb] });
        } catch (e) {
          errors.push({ a: i, b: j, error: String(e?.message ?? e) });
          continue;
        }
        if (piece) {
          features.push({
            type: 'Feature', geometry: piece.geometry,
            properties: { a: fa.properties, b: fb.properties, aIndex: i, bIndex: j, aIndices: [i], bIndices: [j] },
          });
        }
      }
    }
    return { type: 'FeatureCollection', features };
  };
  const timed = timeRuns('turf', () => overlay(parcels, zones), runs);
  const { areas, pieces } = pairAreas(timed.result, zones.features.length);
  const types = {};
  for (const f of timed.result.features) types[f.geometry.type] = (types[f.geometry.type] ?? 0) + 1;
  return {
    ...info, status: errors.length ? 'errors' : 'ok', ...strip(timed), pieces, piece_types: types, candidates, areas,
    pair_errors: errors.length, pair_error_examples: errors.slice(0, 5),
  };
}

async function runGeos(files, args) {
  const script = new URL('./layers_geos.py', import.meta.url).pathname;
  const info = { package: 'shapely (Python) / GEOS', python_executable: args.python };
  if (!existsSync(args.python)) return { ...info, status: 'missing', error: `no Python at ${args.python} (--python PATH)` };
  log(`  geos: ${args.python} ${script} (warm-up + ${args.runs} runs, in a child process)`);
  let out;
  try {
    const { stdout } = await promisify(execFile)(args.python, [script, files.parcels, files.zones, '--runs', String(args.runs)],
      { timeout: PYTHON_TIMEOUT_MS, maxBuffer: 1 << 30 });
    out = JSON.parse(stdout);
  } catch (e) {
    return { ...info, status: 'error', error: `${e.message}`.slice(0, 2000) };
  }
  const nB = out.count_b;
  const areas = new Map();
  const { a, b, area } = out.pairs;
  for (let k = 0; k < a.length; k++) areas.set(a[k] * nB + b[k], (areas.get(a[k] * nB + b[k]) ?? 0) + area[k]);
  const { pairs: _pairs, ms, ...rest } = out;
  return {
    ...info, version: out.shapely, geos_version: out.geos, status: 'ok',
    runs_ms: ms.total.runs, min_ms: ms.total.min, median_ms: ms.total.median, phases_ms: ms,
    ...rest, areas,
  };
}

function strip({ result: _result, ...rest }) {
  return rest;
}

// ---------------------------------------------------------------- agreement -------------------------------------

function compare(engine, ref, allPairs, nB) {
  let maxAbs = 0;
  let maxRel = 0;
  let worst = null;
  let over = 0;
  let onlyEngine = 0;
  let onlyRef = 0;
  for (const key of allPairs) {
    const x = engine.areas.get(key) ?? 0;
    const y = ref.areas.get(key) ?? 0;
    if (x > 0 && !(y > 0)) onlyEngine++;
    if (y > 0 && !(x > 0)) onlyRef++;
    const abs = Math.abs(x - y);
    const rel = abs === 0 ? 0 : abs / Math.max(Math.abs(x), Math.abs(y));
    if (abs > maxAbs) maxAbs = abs;
    if (rel > TOLERANCE) over++;
    if (rel > maxRel) {
      maxRel = rel;
      worst = { parcel: Math.floor(key / nB), zone: key % nB, area: x, reference_area: y };
    }
  }
  return { pairs: allPairs.size, max_abs: maxAbs, max_rel: maxRel, over_1e9_rel: over, only_engine: onlyEngine, only_reference: onlyRef, worst_rel: worst };
}

// ---------------------------------------------------------------- main ------------------------------------------

async function main() {
  const args = parseArgs(process.argv.slice(2));
  const t0 = performance.now();
  const data = writeLayers({ parcels: args.parcels, zones: args.zones, seed: args.seed, origin: args.origin });
  const { info, files } = data;
  log(`layers: ${info.parcels.count} parcels (${info.parcels.grid.join(' × ')}, ${info.parcels.vertices} vertices) × `
    + `${info.zones.count} zones (${info.zones.grid.join(' × ')}, ${info.zones.vertices} vertices), seed ${info.seed}, `
    + `written to ${data.dir} in ${fmt(performance.now() - t0)} ms`);
  const text = { parcels: readFileSync(files.parcels, 'utf8'), zones: readFileSync(files.zones, 'utf8') };
  const nB = info.zones.count;

  // GEOS first, in its own process, while this one is idle; then the JS engines one after the other.
  const results = {};
  for (const engine of [REFERENCE, ...ENGINES.filter((e) => e !== REFERENCE)]) {
    if (!args.engines.includes(engine)) continue;
    log(`${engine}:`);
    try {
      if (engine === 'geos') results.geos = await runGeos(files, args);
      else if (engine === 'turf') results.turf = await runTurf(text, args.runs);
      else results.polysweep = await runPolysweep(text, args.runs);
    } catch (e) {
      results[engine] = { status: 'error', error: String(e?.stack ?? e) };
    }
    const r = results[engine];
    if (r.error) log(`  ${engine}: ${r.status}: ${r.error.split('\n')[0]}`);
  }

  // ---- agreement
  const ran = ENGINES.filter((e) => results[e]?.areas);
  const partial = ran.length !== ENGINES.length; // --engines, or an engine missing or failed
  const allPairs = new Set();
  for (const e of ran) for (const [key, area] of results[e].areas) if (area > 0) allPairs.add(key);
  const agreement = {};
  if (results[REFERENCE]?.areas) {
    for (const e of ran) if (e !== REFERENCE) agreement[`${e}_vs_${REFERENCE}`] = compare(results[e], results[REFERENCE], allPairs, nB);
  } else if (results.polysweep?.areas && results.turf?.areas) {
    agreement.turf_vs_polysweep = compare(results.turf, results.polysweep, allPairs, nB);
  }

  // ---- report
  const out = [];
  const p = (s = '') => out.push(s);
  p(`Layer overlay (intersection): ${info.parcels.count} parcels × ${info.zones.count} zones, seed ${info.seed}${partial ? ` (partial: ${ran.join(', ') || 'no engine'} only)` : ''}`);
  p(`${machineLine()}`);
  p('');
  const psMedian = results.polysweep?.median_ms;
  const rows = [['engine', 'version', 'pieces', 'min ms', 'median ms', '× polysweep']];
  const ratio = (ms) => (psMedian && ms ? (ms / psMedian).toFixed(2) : '–');
  for (const e of ENGINES) {
    const r = results[e];
    if (!r) continue;
    if (r.median_ms === undefined) { rows.push([e, r.version ?? '', r.status.toUpperCase(), '–', '–', '–']); continue; }
    rows.push([e === 'geos' ? 'geos (end to end)' : e, r.version ?? '', String(r.pieces), fmt(r.min_ms), fmt(r.median_ms), ratio(r.median_ms)]);
    if (e === 'geos') {
      const c = r.phases_ms.core;
      rows.push(['geos (core only)', '', '', fmt(c.min), fmt(c.median), ratio(c.median)]);
    }
  }
  const widths = rows[0].map((_, k) => Math.max(...rows.map((row) => row[k].length)));
  for (const row of rows) p(row.map((cell, k) => (k < 2 ? cell.padEnd(widths[k]) : cell.padStart(widths[k]))).join('  '));
  p('');
  for (const e of ENGINES) {
    const r = results[e];
    if (!r) continue;
    if (r.error) { p(`${e}: ${r.status.toUpperCase()}: ${r.error}`); continue; }
    const parts = [`runs ${r.runs_ms.map(fmt).join(', ')} ms`];
    if (r.candidates !== undefined) parts.push(`${r.candidates} candidate pairs`);
    if (r.piece_types) parts.push(`pieces ${Object.entries(r.piece_types).map(([k, v]) => `${v} ${k}`).join(', ')}`);
    if (e === 'geos') {
      const ph = r.phases_ms;
      parts.push(`phases (median ms) in ${fmt(ph.in.median)}, core ${fmt(ph.core.median)}, out ${fmt(ph.out.median)}`);
      parts.push(`shapely ${r.version}, GEOS ${r.geos_version}, Python ${r.python}`);
      if (r.invalid_a || r.invalid_b) parts.push(`INVALID INPUT: ${r.invalid_a} parcels, ${r.invalid_b} zones`);
    }
    if (e === 'turf') {
      parts.push(`polyclip-ts ${r.polyclip_ts_version}, @turf/bbox ${r.bbox_version}`);
      if (r.pair_errors) parts.push(`${r.pair_errors} PAIRS THREW (e.g. ${r.pair_error_examples[0].error})`);
    }
    if (e === 'polysweep' && (r.notes.features_not_one_to_one || r.notes.features_without_a_or_b)) {
      parts.push(`${r.notes.features_not_one_to_one} features not covered by exactly one feature of each layer, ${r.notes.features_without_a_or_b} with no a or b`);
    }
    p(`${e}: ${parts.join('; ')}`);
  }
  p('');
  const fe = (x) => (x === 0 ? '0' : x.toExponential(2));
  if (Object.keys(agreement).length === 0) p('agreement: fewer than two engines produced areas');
  for (const [name, c] of Object.entries(agreement)) {
    const flag = c.over_1e9_rel || c.only_engine || c.only_reference ? '  <-- DIFFERENCES' : '';
    p(`${name}: ${c.pairs} pairs, max |Δarea| ${fe(c.max_abs)} m², max relative ${fe(c.max_rel)}, `
      + `${c.over_1e9_rel} over 1e-9 relative, ${c.only_engine} only in ${name.split('_vs_')[0]}, `
      + `${c.only_reference} only in ${name.split('_vs_')[1]}${flag}`);
    if (c.worst_rel && c.max_rel > TOLERANCE) {
      const w = c.worst_rel;
      p(`  worst: parcel ${w.parcel} × zone ${w.zone}: ${w.area} vs ${w.reference_area} m²`);
    }
  }
  process.stdout.write(`${out.join('\n')}\n`);

  // ---- JSON summary
  const engines = {};
  for (const [e, r] of Object.entries(results)) {
    const { areas: _areas, ...rest } = r;
    engines[e] = rest;
  }
  const summary = {
    benchmark: 'layers', date: new Date().toISOString(), machine: machineLine(), partial,
    args: { parcels: args.parcels, zones: args.zones, quick: args.quick, engines: args.engines, runs: args.runs, seed: args.seed, origin: args.origin },
    data: { ...info, files }, engines, agreement, tolerance_rel: TOLERANCE, report: out,
  };
  mkdirSync(BENCH_DIR, { recursive: true });
  const path = join(BENCH_DIR, 'layers.json');
  writeFileSync(path, `${JSON.stringify(summary, null, 2)}\n`);
  log(`wrote ${path} (${fmt((performance.now() - t0) / 1000)} s in all)`);
}

main().catch((e) => {
  process.stderr.write(`${e?.stack ?? e}\n`);
  process.exit(1);
});
