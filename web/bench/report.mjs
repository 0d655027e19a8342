#!/usr/bin/env node
// The benchmark report: reads target/bench/native.json (crates/polysweep-bench: Table 1's runs and, under "dense",
// the dense workloads'), target/bench/wasm.json (web/bench/wasm.mjs) and target/bench/dense-wasm.json
// (web/bench/dense.mjs), and writes docs/benchmarks.md (tables) and docs/benchmarks.svg (a log-log chart of Table 1
// and a panel of the dense workloads' ratios, written by hand: no chart library), then prints where polysweep stands
// against each target of the benchmark issues (5: Table 1; 25: the dense workloads). The dense workloads' data,
// target, section and panel are in report-dense.mjs; what both parts format alike, in report-common.mjs.
//
//   node web/bench/report.mjs [--native FILE] [--wasm FILE] [--dense FILE] [--out DIR]
//
// Ratios are polysweep's time divided by the other's: below 1 polysweep is faster. A missing input file or a
// failed run is reported as such; a target that cannot be evaluated is not counted as met.

import { existsSync, mkdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { BENCH_DIR, FULL_N, REFERENCE_AREAS, ROOT } from './data.mjs';
import {
  AGREEMENT, INFO_ENGINES, NATIVE_PEERS, WASM_PEERS, areaNote, cell, enginesOf, escapeXml, fastestPeer, logSteps, ms, niceBound,
  ok, ratio, table,
} from './report-common.mjs';
import { DENSE_PANEL_H, denseData, densePanel, denseSection, denseTargets } from './report-dense.mjs';

/** The line of docs/benchmarks.md after which the page is written by hand; regenerating keeps that part. */
const HAND_WRITTEN = '<!-- The section below is written by hand';

const TARGETS = { native: 0.8, wasm: 0.5, floor: 3 };
const TAIL_FROM = 2048; // the tail of the series, where the squares dominate the land's fixed cost

// ---------------------------------------------------------------- input -----------------------------------------

function parseArgs(argv) {
  const args = { native: join(BENCH_DIR, 'native.json'), wasm: join(BENCH_DIR, 'wasm.json'), dense: join(BENCH_DIR, 'dense-wasm.json'), out: join(ROOT, 'docs') };
  for (let i = 0; i < argv.length; i++) {
    const key = argv[i].replace(/^--/, '');
    if (!(key in args) || i + 1 >= argv.length) throw new Error(`usage: report.mjs [--native FILE] [--wasm FILE] [--dense FILE] [--out DIR]`);
    args[key] = argv[++i];
  }
  return args;
}

function readReport(path) {
  if (!existsSync(path)) return null;
  const data = JSON.parse(readFileSync(path, 'utf8'));
  if (!Array.isArray(data.runs)) throw new Error(`${path}: no "runs" array`);
  data.mtime = statSync(path).mtime;
  // Runs of the native benchmark carry no status: a number is a success.
  for (const r of data.runs) {
    r.status ??= Number.isFinite(r.median_ms) ? 'ok' : 'failed';
    if (r.status === 'ok' && !Number.isFinite(r.median_ms)) r.status = 'failed';
  }
  return data;
}

/** Lookup of runs by engine, operation and N. */
function indexRuns(data) {
  const map = new Map();
  for (const r of data?.runs ?? []) map.set(`${r.engine}|${r.operation}|${r.squares}`, r);
  return (engine, operation, n) => map.get(`${engine}|${operation}|${n}`) ?? null;
}


function seriesOf(data) {
  const ns = new Set((data?.runs ?? []).filter((r) => r.operation === 'intersection').map((r) => r.squares));
  return [...ns].sort((a, b) => a - b);
}

// ---------------------------------------------------------------- numbers ---------------------------------------





/** Least-squares slope of ln(time) against ln(N). */
function slope(points) {
  if (points.length < 2) return NaN;
  const xs = points.map(([n]) => Math.log(n));
  const ys = points.map(([, t]) => Math.log(t));
  const mx = xs.reduce((a, b) => a + b, 0) / xs.length;
  const my = ys.reduce((a, b) => a + b, 0) / ys.length;
  let sxy = 0;
  let sxx = 0;
  for (let i = 0; i < xs.length; i++) {
    sxy += (xs[i] - mx) * (ys[i] - my);
    sxx += (xs[i] - mx) ** 2;
  }
  return sxy / sxx;
}

function slopes(get, engine, series) {
  const points = series.map((n) => [n, get(engine, 'intersection', n)]).filter(([, r]) => ok(r)).map(([n, r]) => [n, r.median_ms]);
  return {
    all: points.length === series.length ? slope(points) : NaN,
    tail: slope(points.filter(([n]) => n >= TAIL_FROM)),
    points: points.length,
  };
}



function maxRelDiff(get, engines, operation, n) {
  const ps = get('polysweep', operation, n);
  if (!ps || !Number.isFinite(ps.area)) return NaN;
  let worst = 0;
  for (const e of engines) {
    const r = get(e, operation, n);
    if (e !== 'polysweep' && r && Number.isFinite(r.area)) worst = Math.max(worst, Math.abs(r.area - ps.area) / Math.abs(ps.area));
  }
  return worst;
}

// ---------------------------------------------------------------- targets ---------------------------------------

/** The workloads that a benchmark file has runs of: the intersection series ascending, then union, difference. */
/**
 * The sort floor of each workload, timed in the same rounds as its engines: keyed by `operation|squares`. Files written
 * before the floor was timed for every operation give it for the intersection only, which then stands for all three.
 */
function floorsOf(native) {
  const floors = new Map();
  for (const f of native?.sort_floor ?? []) floors.set(`${f.operation ?? 'intersection'}|${f.squares}`, f.median_ms);
  return {
    size: floors.size,
    of: (w) => floors.get(`${w.operation}|${w.n}`) ?? floors.get(`intersection|${w.n}`),
  };
}

function workloadsIn(data) {
  const order = { intersection: 0, union: 1, difference: 2 };
  const seen = new Map();
  for (const r of data?.runs ?? []) seen.set(`${r.operation}|${r.squares}`, { operation: r.operation, n: r.squares });
  return [...seen.values()].sort((a, b) => (order[a.operation] ?? 9) - (order[b.operation] ?? 9) || a.n - b.n);
}

function label({ operation, n }) {
  return operation === 'intersection' ? `∩ ${n}` : `${operation === 'union' ? '∪' : '−'} ${n}`;
}

function evaluateTargets(native, wasm) {
  const nGet = indexRuns(native);
  const wGet = indexRuns(wasm);
  const targets = [];

  // 1. native ≤ 0.8× i_overlay at every N.
  {
    const t = { name: `native ≤ ${TARGETS.native}× i_overlay at every N`, met: false, worst: null, misses: [], detail: '' };
    if (!native) Object.assign(t, { detail: 'no native.json', na: true });
    else {
      const rows = workloadsIn(native).map((w) => {
        const p = nGet('polysweep', w.operation, w.n);
        const q = nGet('i_overlay', w.operation, w.n);
        return { w, r: ok(p) && ok(q) ? p.median_ms / q.median_ms : NaN };
      }).filter(({ w }) => nGet('polysweep', w.operation, w.n) || nGet('i_overlay', w.operation, w.n));
      const bad = rows.filter(({ r }) => !(r <= TARGETS.native));
      const finite = rows.filter(({ r }) => Number.isFinite(r));
      t.met = rows.length > 0 && bad.length === 0;
      t.best = finite.length ? Math.min(...finite.map(({ r }) => r)) : NaN;
      t.worst = finite.length ? Math.max(...finite.map(({ r }) => r)) : NaN;
      t.misses = bad.map(({ w }) => label(w));
      t.detail = `polysweep ÷ i_overlay from ${ratio(t.best)} to ${ratio(t.worst)}; ${bad.length ? `missed at ${bad.length} of ${rows.length} workloads` : `met at all ${rows.length} workloads`}`;
    }
    targets.push(t);
  }

  // 2. wasm end to end ≤ 0.5× the fastest JS/wasm peer at every N.
  {
    const t = { name: `wasm end to end ≤ ${TARGETS.wasm}× the fastest JS/wasm peer at every N`, met: false, misses: [], detail: '' };
    if (!wasm) Object.assign(t, { detail: 'no wasm.json', na: true });
    else {
      const peers = enginesOf(wasm, WASM_PEERS).filter((e) => e !== 'polysweep' && !INFO_ENGINES.includes(e));
      const rows = workloadsIn(wasm).filter((w) => wGet('polysweep', w.operation, w.n)).map((w) => {
        const p = wGet('polysweep', w.operation, w.n);
        const f = fastestPeer(wGet, peers, w.operation, w.n);
        return { w, f, r: ok(p) && f ? p.median_ms / f.ms : NaN };
      });
      const bad = rows.filter(({ r }) => !(r <= TARGETS.wasm));
      const finite = rows.filter(({ r }) => Number.isFinite(r));
      t.met = rows.length > 0 && bad.length === 0;
      t.best = finite.length ? Math.min(...finite.map(({ r }) => r)) : NaN;
      t.worst = finite.length ? Math.max(...finite.map(({ r }) => r)) : NaN;
      t.misses = bad.map(({ w }) => label(w));
      const fastest = [...new Set(rows.filter(({ f }) => f).map(({ f }) => f.engine))].join(', ');
      t.detail = `polysweep ÷ fastest peer (${fastest}) from ${ratio(t.best)} to ${ratio(t.worst)}; ${bad.length ? `missed at ${bad.length} of ${rows.length} workloads` : `met at all ${rows.length} workloads`}`;
      const incomplete = wasm.runs.filter((r) => r.status !== 'ok' && r.engine !== 'polysweep' && !INFO_ENGINES.includes(r.engine)).length;
      if (incomplete) t.detail += ` (${incomplete} peer runs failed or skipped: the fastest of the others counts)`;
      if (wasm.partial) {
        t.detail += ' — partial run (--quick, --engines, --sizes or --limit): not a verdict';
        t.met = false;
        t.na = true;
      }
    }
    targets.push(t);
  }

  // 3. scaling no steeper than i_overlay's.
  {
    const t = { name: 'scaling slope (log time vs log N) no steeper than i_overlay’s', met: false, misses: [], detail: '' };
    if (!native) Object.assign(t, { detail: 'no native.json', na: true });
    else {
      const series = seriesOf(native);
      const ps = slopes(nGet, 'polysweep', series);
      const io = slopes(nGet, 'i_overlay', series);
      t.met = Number.isFinite(ps.all) && Number.isFinite(io.all) && ps.all <= io.all;
      t.detail = `native slope over N = ${series[0]}…${series[series.length - 1]}: polysweep ${ps.all.toFixed(3)}, i_overlay ${io.all.toFixed(3)}`
        + `; over N ≥ ${TAIL_FROM}: polysweep ${ps.tail.toFixed(3)}, i_overlay ${io.tail.toFixed(3)}`;
      if (!t.met) t.misses = ['slope'];
      t.values = { ps, io };
    }
    targets.push(t);
  }

  // 4. total ≤ 3× the sort floor.
  {
    const t = { name: `total ≤ ${TARGETS.floor}× the sort floor`, met: false, misses: [], detail: '' };
    const floor = floorsOf(native);
    if (!native || floor.size === 0) Object.assign(t, { detail: 'no sort floor in native.json', na: true });
    else {
      const rows = workloadsIn(native).filter((w) => floor.of(w) !== undefined).map((w) => {
        const p = nGet('polysweep', w.operation, w.n);
        return { w, r: ok(p) ? p.median_ms / floor.of(w) : NaN };
      });
      const bad = rows.filter(({ r }) => !(r <= TARGETS.floor));
      const finite = rows.filter(({ r }) => Number.isFinite(r));
      const series = seriesOf(native).filter((n) => floor.of({ operation: 'intersection', n }) !== undefined);
      const sumPs = series.reduce((s, n) => s + (nGet('polysweep', 'intersection', n)?.median_ms ?? NaN), 0);
      const sumFloor = series.reduce((s, n) => s + floor.of({ operation: 'intersection', n }), 0);
      t.met = rows.length > 0 && bad.length === 0;
      t.best = finite.length ? Math.min(...finite.map(({ r }) => r)) : NaN;
      t.worst = finite.length ? Math.max(...finite.map(({ r }) => r)) : NaN;
      t.misses = bad.map(({ w }) => label(w));
      t.detail = `native polysweep ÷ sort floor from ${ratio(t.best)} to ${ratio(t.worst)} (whole series summed: ${ratio(sumPs / sumFloor)}); ${bad.length ? `missed at ${bad.length} of ${rows.length} workloads` : `met at all ${rows.length} workloads`}`;
    }
    targets.push(t);
  }
  return targets;
}

// ---------------------------------------------------------------- markdown --------------------------------------


function perfSection({ title, data, peers, info, floor, workloads, note, native }) {
  const get = indexRuns(data);
  const nativeGet = native ? indexRuns(native) : null;
  const engines = ['polysweep', ...info, ...peers];
  const header = ['workload', 'polysweep ms', ...info.map((e) => `${e} ms`), ...peers.map((e) => `${e} ms (ratio)`), 'fastest peer', 'ratio to fastest'];
  if (floor) header.push('sort floor ms', 'ratio to floor');
  if (nativeGet) header.push('polysweep wasm ÷ native');
  header.push('areas');
  const rows = workloads.map((w) => {
    const p = get('polysweep', w.operation, w.n);
    const row = [label(w), cell(p), ...info.map((e) => cell(get(e, w.operation, w.n)))];
    for (const e of peers) {
      const r = get(e, w.operation, w.n);
      row.push(ok(r) && ok(p) ? `${ms(r.median_ms)} (${ratio(p.median_ms / r.median_ms)})` : cell(r));
    }
    const f = fastestPeer(get, peers, w.operation, w.n);
    row.push(f ? f.engine : '–', f && ok(p) ? ratio(p.median_ms / f.ms) : '–');
    if (floor) {
      const fl = floor.of(w);
      row.push(ms(fl), Number.isFinite(fl) && ok(p) ? ratio(p.median_ms / fl) : '–');
    }
    if (nativeGet) {
      const q = nativeGet('polysweep', w.operation, w.n);
      row.push(ok(p) && ok(q) ? ratio(p.median_ms / q.median_ms) : '–');
    }
    row.push(areaNote(get, engines, w.operation, w.n).text);
    return row;
  });
  const out = [`### ${title}`, '', note, '', table(header, rows, ['fastest peer', 'areas'])];
  const problems = (data.runs ?? []).filter((r) => r.status !== 'ok');
  if (problems.length) {
    out.push('', 'Runs that did not complete:', '');
    for (const r of problems) out.push(`- ${r.engine}, ${label({ operation: r.operation, n: r.squares })}: ${r.status}${r.error ? ` — ${r.error}` : ''}`);
  }
  return out.join('\n');
}

function slopeTable(native, wasm) {
  const rows = [];
  for (const [side, data, peers] of [['native', native, NATIVE_PEERS], ['wasm/JS', wasm, WASM_PEERS]]) {
    if (!data) continue;
    const get = indexRuns(data);
    const series = seriesOf(data);
    for (const e of ['polysweep', ...(side === 'wasm/JS' ? INFO_ENGINES : []), ...peers]) {
      if (!enginesOf(data, []).includes(e)) continue;
      const s = slopes(get, e, series);
      const first = get(e, 'intersection', series[0]);
      const last = get(e, 'intersection', series[series.length - 1]);
      rows.push([
        `${e} (${side})`,
        Number.isFinite(s.all) ? s.all.toFixed(3) : `– (${s.points} of ${series.length} sizes)`,
        Number.isFinite(s.tail) ? s.tail.toFixed(3) : '–',
        ok(first) && ok(last) ? ratio(last.median_ms / first.median_ms) : '–',
      ]);
    }
  }
  return table(['engine', 'slope, whole series', `slope, N ≥ ${TAIL_FROM}`, 'time at the largest N ÷ time at the smallest'], rows);
}

function markdown(native, wasm, dense, targets) {
  const series = [...new Set([...seriesOf(native), ...seriesOf(wasm)])].sort((a, b) => a - b);
  const floor = floorsOf(native);
  const date = (wasm?.date ?? new Date().toISOString()).slice(0, 10);
  const parts = [];
  parts.push('# Benchmarks: the paper\'s Table 1 on real land data, and dense workloads', '');
  parts.push('<!-- Generated by web/bench/report.mjs from target/bench/native.json, target/bench/wasm.json and target/bench/dense-wasm.json; do not edit by hand. -->', '');
  parts.push(`Machine: native — ${native?.machine ?? 'not run'}; wasm/JS — ${wasm?.machine ?? 'not run'}.  `);
  parts.push(`Date: ${date} (native.json written ${native ? native.mtime.toISOString().slice(0, 16).replace('T', ' ') : '–'} UTC, wasm.json ${wasm ? wasm.date.slice(0, 16).replace('T', ' ') : '–'} UTC).`, '');
  parts.push('Workload: Natural Earth 1:50m land (1,420 polygons, 59,212 vertices) intersected with N equal squares on a grid over '
    + 'its bounding box, N = ' + series.join(', ') + '; union and difference (land minus squares) at N = ' + FULL_N + '. '
    + 'Data and provenance: [tests/data/README.md](../tests/data/README.md). Times are medians of several runs after a warm-up, in one run of '
    + 'each benchmark; a ratio is polysweep\'s time divided by the other\'s (below 1×: polysweep is faster). '
    + `Areas: every engine's result area (shoelace, exteriors minus holes) against polysweep's, flagged beyond ${AGREEMENT.toExponential(0)} relative; `
    + 'polysweep\'s against the reference areas of tests/data/README.md.', '');
  parts.push('![Median time against the number of squares, log-log, native and wasm/JS](benchmarks.svg)', '');

  parts.push('## Where polysweep stands', '');
  parts.push(table(['target', 'status', 'figures of this run'], targets.map((t) => [t.name, t.met ? 'met' : t.na ? 'not evaluated' : '**missed**', t.detail]), ['status', 'figures of this run']), '');

  parts.push('## Native (Rust, release build)', '');
  if (native) {
    parts.push(perfSection({
      title: 'Intersection series, union and difference at ' + FULL_N, data: native, peers: enginesOf(native, NATIVE_PEERS).filter((e) => e !== 'polysweep'),
      info: [], floor, workloads: workloadsIn(native),
      note: 'One process (crates/polysweep-bench). Every round takes every engine at every size, in a shuffled order, each timed run right after a warm-up run of the same, so that a slow phase of the machine falls on all sizes alike. Sort floor: the time to sort the workload\'s 2n event points, timed in the same rounds (the same inputs, so the same floor in principle, for ∩, ∪ and − at ' + FULL_N + ', but each timed as a run of its own).',
    }), '');
  } else parts.push('native.json missing: run the native benchmark (crates/polysweep-bench).', '');

  parts.push('## wasm / JavaScript (Node, end to end)', '');
  if (wasm) {
    const engines = wasm.engines ?? {};
    parts.push(perfSection({
      title: 'Intersection series, union and difference at ' + FULL_N, data: wasm, peers: enginesOf(wasm, WASM_PEERS).filter((e) => e !== 'polysweep' && !INFO_ENGINES.includes(e)),
      info: enginesOf(wasm, INFO_ENGINES).filter((e) => INFO_ENGINES.includes(e)), floor: null, workloads: workloadsIn(wasm), native,
      note: `Node ${wasm.node ?? ''}, one worker thread per engine (web/bench/wasm.mjs). End to end: GeoJSON coordinate arrays in, arrays out, `
        + 'each engine\'s conversions included. polysweep-flat (the same package\'s typed-array form, input already flat) is shown for the cost of the JS boundary; it is not a peer.'
        + (wasm.partial ? ' **Partial run** (options limited the engines, sizes or runs).' : ''),
    }), '');
    parts.push('Engines:', '');
    for (const [name, e] of Object.entries(engines)) parts.push(`- ${name} ${e.version}: ${e.notes}`);
    parts.push('');
  } else parts.push('wasm.json missing: run `node web/bench/wasm.mjs`.', '');

  parts.push('## Scaling', '');
  parts.push('Least-squares slope of log time against log N over the intersection series (1 would be linear in N; the land\'s '
    + `59,212 vertices are a fixed cost that flattens the small sizes, hence also the slope over N ≥ ${TAIL_FROM}).`, '');
  parts.push(slopeTable(native, wasm), '');

  parts.push('## Area agreement', '');
  const agreeRows = [];
  for (const [side, data] of [['native', native], ['wasm/JS', wasm]]) {
    if (!data) continue;
    const get = indexRuns(data);
    const engines = enginesOf(data, []);
    for (const w of workloadsIn(data)) {
      const ps = get('polysweep', w.operation, w.n);
      const ref = REFERENCE_AREAS[w.operation]?.[w.n];
      agreeRows.push([`${side} ${label(w)}`, ps && Number.isFinite(ps.area) ? ps.area.toFixed(6) : '–', ref !== undefined ? ref.toFixed(6) : '–',
        Number.isFinite(maxRelDiff(get, engines, w.operation, w.n)) ? maxRelDiff(get, engines, w.operation, w.n).toExponential(1) : '–',
        areaNote(get, engines, w.operation, w.n).text]);
    }
  }
  parts.push(table(['workload', 'polysweep area', 'reference', 'largest relative difference of a peer', 'verdict'], agreeRows, ['verdict']), '');
  parts.push(denseSection(dense), '');
  parts.push(`Regenerate: \`node web/bench/wasm.mjs && node web/bench/dense.mjs && node web/bench/report.mjs\` after the native benchmark has written target/bench/native.json and target/bench/dense/ (or all of it: \`./bench.sh\`).`, '');
  return parts.join('\n');
}

// ---------------------------------------------------------------- chart -----------------------------------------

const COLORS = {
  'polysweep|native': '#c0392b', 'polysweep|wasm': '#c0392b', 'polysweep-flat|wasm': '#e67e22',
  'i_overlay|native': '#2471a3', 'geo|native': '#17a589', 'clipper2|native': '#7d3c98',
  'clipper2-wasm|wasm': '#7d3c98', 'js-angusj-clipper|wasm': '#b7950b', 'martinez-polygon-clipping|wasm': '#1e8449',
  'clipper2-ts|wasm': '#c39bd3', 'ishape_wasm|wasm': '#2471a3', // ishape_wasm is i_overlay: its colour, dashed
  'polygon-clipping|wasm': '#2e86c1', 'polyclip-ts|wasm': '#6e2c00', 'floor|native': '#7f8c8d',
};
const FALLBACK = ['#34495e', '#d35400', '#8e44ad', '#16a085', '#f39c12', '#2c3e50'];



function svgChart(native, wasm, dense) {
  const lines = [];
  let fallback = 0;
  const add = (data, side, engine, name, dash, width) => {
    const get = indexRuns(data);
    const pts = seriesOf(data).map((n) => [n, get(engine, 'intersection', n)]);
    if (!pts.some(([, r]) => ok(r))) return;
    lines.push({ name, dash, width, color: COLORS[`${engine}|${side}`] ?? FALLBACK[fallback++ % FALLBACK.length], points: pts.map(([n, r]) => [n, ok(r) ? r.median_ms : null]) });
  };
  if (native) {
    add(native, 'native', 'polysweep', 'polysweep (native)', '', 3);
    for (const e of enginesOf(native, NATIVE_PEERS).filter((x) => x !== 'polysweep')) add(native, 'native', e, `${e} (native)`, '', 1.6);
    const floor = (native.sort_floor ?? []).filter((f) => (f.operation ?? 'intersection') === 'intersection').sort((a, b) => a.squares - b.squares);
    if (floor.length) lines.push({ name: 'sort floor (native)', dash: '2 4', width: 1.6, color: COLORS['floor|native'], points: floor.map((f) => [f.squares, f.median_ms]) });
  }
  if (wasm) {
    add(wasm, 'wasm', 'polysweep', 'polysweep (wasm, end to end)', '8 4', 3);
    for (const e of enginesOf(wasm, INFO_ENGINES).filter((x) => INFO_ENGINES.includes(x))) add(wasm, 'wasm', e, `${e} (wasm, typed arrays)`, '3 3', 1.6);
    for (const e of enginesOf(wasm, WASM_PEERS).filter((x) => x !== 'polysweep' && !INFO_ENGINES.includes(x))) add(wasm, 'wasm', e, `${e} (JS/wasm)`, '8 4', 1.6);
  }

  const W = 980;
  const TABLE1_H = 600;
  const H = TABLE1_H + (dense.workloads.length ? DENSE_PANEL_H : 0);
  const plot = { left: 78, top: 48, right: 660, bottom: 530 };
  const all = lines.flatMap((l) => l.points.filter(([, t]) => t !== null));
  const nMin = Math.min(...all.map(([n]) => n), 8);
  const nMax = Math.max(...all.map(([n]) => n), 32768);
  // Time axis bounds on the 1-2-5 steps just outside the data.
  const tMin = niceBound(Math.min(...all.map(([, t]) => t)), false);
  const tMax = niceBound(Math.max(...all.map(([, t]) => t)), true);
  const lx0 = Math.log(nMin) - 0.15;
  const lx1 = Math.log(nMax) + 0.15;
  const x = (n) => plot.left + ((Math.log(n) - lx0) / (lx1 - lx0)) * (plot.right - plot.left);
  const y = (t) => plot.bottom - ((Math.log10(t) - Math.log10(tMin)) / (Math.log10(tMax) - Math.log10(tMin))) * (plot.bottom - plot.top);

  const s = [];
  s.push(`<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}" font-family="Helvetica, Arial, sans-serif" font-size="12">`);
  s.push(`<rect width="${W}" height="${H}" fill="#ffffff"/>`);
  s.push(`<text x="${(plot.left + plot.right) / 2}" y="26" text-anchor="middle" font-size="15" font-weight="bold">Land ∩ N squares: median time (log-log)</text>`);
  // Grid and ticks.
  for (const { value: t, m } of logSteps(tMin, tMax)) {
    const yy = y(t).toFixed(1);
    s.push(`<line x1="${plot.left}" y1="${yy}" x2="${plot.right}" y2="${yy}" stroke="${m === 1 ? '#cccccc' : '#eeeeee'}"/>`);
    if (m === 1 || tMax / tMin <= 1e4) {
      const text = t >= 1000 ? `${t / 1000} s` : `${t} ms`;
      s.push(`<text x="${plot.left - 6}" y="${(+yy + 4).toFixed(1)}" text-anchor="end" fill="${m === 1 ? '#000' : '#777'}">${text}</text>`);
    }
  }
  const ticks = [...new Set(lines.flatMap((l) => l.points.map(([n]) => n)))].sort((a, b) => a - b);
  for (const n of ticks) {
    const xx = x(n).toFixed(1);
    const major = Number.isInteger(Math.log2(n) / 2) || n === 8 || [8, 32, 128, 512, 2048, 8192, 32768].includes(n);
    s.push(`<line x1="${xx}" y1="${plot.top}" x2="${xx}" y2="${plot.bottom}" stroke="${major ? '#dddddd' : '#f0f0f0'}"/>`);
    s.push(`<text x="${xx}" y="${plot.bottom + (major ? 16 : 28)}" text-anchor="middle" fill="${major ? '#000' : '#777'}">${n}</text>`);
  }
  s.push(`<rect x="${plot.left}" y="${plot.top}" width="${plot.right - plot.left}" height="${plot.bottom - plot.top}" fill="none" stroke="#333333"/>`);
  s.push(`<text x="${(plot.left + plot.right) / 2}" y="${TABLE1_H - 22}" text-anchor="middle" font-size="13">number of squares N (land: 59,212 vertices; squares: 4N)</text>`);
  s.push(`<text transform="translate(20 ${(plot.top + plot.bottom) / 2}) rotate(-90)" text-anchor="middle" font-size="13">median time per operation (ms, log scale)</text>`);
  // Lines (gaps where a run failed or was skipped).
  for (const l of lines) {
    let d = '';
    let pen = false;
    for (const [n, t] of l.points) {
      if (t === null) {
        pen = false;
        continue;
      }
      d += `${pen ? 'L' : 'M'}${x(n).toFixed(1)},${y(t).toFixed(1)} `;
      pen = true;
    }
    s.push(`<path d="${d.trim()}" fill="none" stroke="${l.color}" stroke-width="${l.width}"${l.dash ? ` stroke-dasharray="${l.dash}"` : ''} stroke-linejoin="round"><title>${escapeXml(l.name)}</title></path>`);
    for (const [n, t] of l.points) {
      if (t !== null) s.push(`<circle cx="${x(n).toFixed(1)}" cy="${y(t).toFixed(1)}" r="${l.width > 2 ? 3 : 2.2}" fill="${l.color}"><title>${escapeXml(`${l.name}: N = ${n}, ${ms(t)} ms`)}</title></circle>`);
    }
  }
  // Legend.
  const lx = plot.right + 24;
  let ly = plot.top + 8;
  s.push(`<text x="${lx}" y="${ly}" font-weight="bold">solid: native Rust · dashed: Node (wasm/JS)</text>`);
  ly += 22;
  for (const l of lines) {
    s.push(`<line x1="${lx}" y1="${ly - 4}" x2="${lx + 34}" y2="${ly - 4}" stroke="${l.color}" stroke-width="${l.width}"${l.dash ? ` stroke-dasharray="${l.dash}"` : ''}/>`);
    s.push(`<text x="${lx + 42}" y="${ly}">${escapeXml(l.name)}</text>`);
    ly += 20;
  }
  const missing = [];
  for (const [side, data] of [['native', native], ['wasm', wasm]]) {
    for (const r of data?.runs ?? []) if (r.operation === 'intersection' && r.status !== 'ok') missing.push(`${r.engine} (${side}) at ${r.squares}: ${r.status}`);
    if (!data) missing.push(`no ${side} data`);
  }
  if (missing.length) {
    ly += 8;
    s.push(`<text x="${lx}" y="${ly}" fill="#555">missing points:</text>`);
    for (const m of missing.slice(0, 10)) {
      ly += 16;
      s.push(`<text x="${lx}" y="${ly}" fill="#555">${escapeXml(m)}</text>`);
    }
    if (missing.length > 10) s.push(`<text x="${lx}" y="${ly + 16}" fill="#555">and ${missing.length - 10} more</text>`);
  }
  if (dense.workloads.length) s.push(...densePanel(dense, TABLE1_H, W));
  s.push('</svg>');
  return `${s.join('\n')}\n`;
}

// ---------------------------------------------------------------- main ------------------------------------------

function main() {
  const args = parseArgs(process.argv.slice(2));
  const native = readReport(args.native);
  const wasm = readReport(args.wasm);
  const dense = denseData(native, readReport(args.dense));
  if (!native && !wasm) {
    console.error(`neither ${args.native} nor ${args.wasm} exists: run the native benchmark and node web/bench/wasm.mjs first`);
    process.exit(1);
  }
  const targets = [...evaluateTargets(native, wasm), ...denseTargets(dense)];
  mkdirSync(args.out, { recursive: true });
  const md = join(args.out, 'benchmarks.md');
  const svg = join(args.out, 'benchmarks.svg');
  // The hand-written part of the page (how polysweep got fast) follows HAND_WRITTEN and is kept as it is.
  const kept = existsSync(md) ? readFileSync(md, 'utf8') : '';
  const handWritten = kept.includes(HAND_WRITTEN) ? kept.slice(kept.indexOf(HAND_WRITTEN)) : '';
  writeFileSync(md, markdown(native, wasm, dense, targets).trimEnd() + '\n\n' + handWritten);
  writeFileSync(svg, svgChart(native, wasm, dense));

  const rel = (p) => relative(process.cwd(), p) || p;
  console.log(`Benchmarks (native: ${native ? native.machine : 'missing'}; wasm: ${wasm ? wasm.machine : 'missing'})`);
  for (const t of targets) console.log(`  ${t.met ? 'MET   ' : t.na ? 'N/A   ' : 'MISSED'}  ${t.name}: ${t.detail}`);
  const met = targets.filter((t) => t.met).length;
  console.log(`  ${met} of ${targets.length} targets met.`);
  const flagged = [];
  for (const [side, data] of [['native', native], ['wasm', wasm]]) {
    if (!data) continue;
    const get = indexRuns(data);
    for (const w of workloadsIn(data)) {
      const note = areaNote(get, enginesOf(data, []), w.operation, w.n);
      if (note.bad) flagged.push(`${side} ${label(w)}: ${note.text.replace(/\*\*/g, '')}`);
    }
    for (const r of data.runs) if (r.status !== 'ok') flagged.push(`${side} ${r.engine} ${label({ operation: r.operation, n: r.squares })}: ${r.status}${r.error ? ` (${r.error})` : ''}`);
  }
  for (const [key, side] of Object.entries(dense.sides)) {
    if (!side) continue;
    for (const w of dense.workloads) {
      const note = areaNote(side.get, side.engines, w.workload, w.n);
      if (note.bad && side.get('polysweep', w.workload, w.n)) flagged.push(`dense ${key} ${w.workload} ${w.n}: ${note.text.replace(/\*\*/g, '')}`);
    }
    for (const r of side.runs) if (r.status === 'failed') flagged.push(`dense ${key} ${r.engine} ${r.workload} ${r.n}: failed${r.error ? ` (${r.error})` : ''}`);
  }
  if (flagged.length) {
    console.log('  Flagged:');
    for (const f of flagged) console.log(`    ${f}`);
  }
  console.log(`Wrote ${rel(md)} and ${rel(svg)}.`);
}

main();
