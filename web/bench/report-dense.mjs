// The dense workloads' part of the benchmark report (issue 25), written by web/bench/report.mjs: both sides' runs
// (target/bench/native.json's "dense" records and target/bench/dense-wasm.json), the target of at most 0.8× the
// fastest peer at every size, the section of docs/benchmarks.md and the chart's panel.

import { loadDenseIndex } from './data.mjs';
import {
  INFO_ENGINES, NATIVE_PEERS, WASM_PEERS, areaNote, cell, enginesOf, escapeXml, fastestPeer, logSteps, ms, niceBound, ok, ratio,
  table,
} from './report-common.mjs';

/** Issue 25's target: polysweep at most this times the fastest peer's time, natively and in Node, at each size. */
const DENSE_TARGET = 0.8;
/** The dense workloads in the order of crates/polysweep-bench/src/dense.rs, each shape in one line. */
const DENSE_SHAPES = {
  checkerboard: 'n × n squares of side 20, 30 apart, ⊕ the (n − 1) × (n − 1) of the same shifted by 15 in x and y: each square overlaps four others at its corners, every edge collinear with the others of its row or column',
  'not-overlap': 'as the checkerboard with squares of side 10: no two squares meet; the union is every square (polysweep sweeps none of them: each is a simple ring apart from all others, which a union copies as it is, see copy_apart in docs/architecture.md)',
  'shared-edges': 'the black cells of an n × n board (cells of side 10) ∪ its white cells: every inner edge is shared, four cells meet at every inner corner, and the union is one square (a parcel map\'s shape)',
  'lines-net': 'n vertical bars (width 10, 20 apart) ∩ n horizontal bars: n² crossings of bars, 4n² crossing points',
  spiral: 'one ring of n vertices, a band along an Archimedean spiral whose width swings above and below the spacing of its turns (each turn crosses the next 14 times), ∪ nothing: the region the band covers',
  windows: 'n × n squares of side 20, 30 apart, − a square of side 10 at the centre of each: n² frames',
  'nested-squares': 'n concentric square frames (bars of width 4, 8 apart), their top and bottom bars ⊕ their left and right bars: the frames without their corners',
};
const OPERATION_SIGN = { intersection: '∩', union: '∪', difference: '−', xor: '⊕' };

/**
 * Both sides of the dense benchmark: native.json's "dense" records and dense-wasm.json's runs. Each side (null when
 * not measured) has get(engine, workload, n), its engines and its peers; `workloads` lists every {workload, n,
 * operation, fill_rule, edges} either side ran, in dense.rs's order (edges from target/bench/dense/index.json).
 */
export function denseData(native, denseWasm) {
  const side = (runs, preferred, info = []) => {
    if (!runs?.length) return null;
    for (const r of runs) r.status ??= Number.isFinite(r.median_ms) ? 'ok' : 'failed'; // native records carry none
    const map = new Map(runs.map((r) => [`${r.engine}|${r.workload}|${r.n}`, r]));
    const engines = enginesOf({ runs }, ['polysweep', ...info, ...preferred]);
    return {
      runs,
      engines,
      info: engines.filter((e) => info.includes(e)),
      peers: engines.filter((e) => e !== 'polysweep' && !info.includes(e)),
      get: (engine, workload, n) => map.get(`${engine}|${workload}|${n}`) ?? null,
    };
  };
  const sides = { native: side(native?.dense, NATIVE_PEERS), node: side(denseWasm?.runs, WASM_PEERS, INFO_ENGINES) };
  const edges = new Map((loadDenseIndex() ?? []).map((e) => [`${e.workload}|${e.n}`, e.edges]));
  const seen = new Map();
  for (const r of [...(sides.native?.runs ?? []), ...(sides.node?.runs ?? [])]) {
    const key = `${r.workload}|${r.n}`;
    if (!seen.has(key)) seen.set(key, { workload: r.workload, n: r.n, operation: r.operation, fill_rule: undefined, edges: edges.get(key) });
    const w = seen.get(key);
    w.fill_rule ??= r.fill_rule; // the native records carry neither fill rule nor edges; dense-wasm.json's do
    w.edges ??= r.edges;
  }
  const order = Object.keys(DENSE_SHAPES);
  const rank = (w) => (order.includes(w) ? order.indexOf(w) : order.length);
  const workloads = [...seen.values()].sort((a, b) => rank(a.workload) - rank(b.workload) || a.workload.localeCompare(b.workload) || a.n - b.n);
  return { sides, workloads, partial: !!denseWasm?.partial, denseWasm };
}

/** polysweep's time over the fastest peer's on one side at one workload and size: {r, best} (r NaN if not both). */
function denseRatio(side, w) {
  if (!side) return { r: NaN, best: null };
  const p = side.get('polysweep', w.workload, w.n);
  const best = fastestPeer(side.get, side.peers, w.workload, w.n);
  return { r: ok(p) && best ? p.median_ms / best.ms : NaN, best };
}

/** The two targets of issue 25, in the shape of evaluateTargets' (for the summary table and the console). */
export function denseTargets(dense) {
  return [['native', 'native', 'the fastest native peer'], ['node', 'Node end to end', 'the fastest JS/wasm peer']].map(([key, where, peer]) => {
    const t = { name: `dense workloads: ${where} ≤ ${DENSE_TARGET}× ${peer} at every size`, met: false, misses: [], detail: '' };
    const side = dense.sides[key];
    if (!side) return Object.assign(t, { detail: key === 'native' ? 'not measured (no "dense" in native.json)' : 'not measured (no dense-wasm.json)', na: true });
    const rows = dense.workloads.filter((w) => side.get('polysweep', w.workload, w.n)).map((w) => ({ w, ...denseRatio(side, w) }));
    const bad = rows.filter(({ r }) => !(r <= DENSE_TARGET));
    const finite = rows.filter(({ r }) => Number.isFinite(r)).map(({ r }) => r);
    t.met = rows.length > 0 && bad.length === 0;
    t.misses = bad.map(({ w }) => `${w.workload} ${w.n}`);
    t.detail = `polysweep ÷ fastest peer from ${ratio(Math.min(...finite))} to ${ratio(Math.max(...finite))}; `
      + (bad.length ? `missed at ${bad.length} of ${rows.length}: ${t.misses.join(', ')}` : `met at all ${rows.length}`);
    if (key === 'node' && dense.partial) Object.assign(t, { met: false, na: true, detail: `${t.detail} — partial run (options of dense.mjs): not a verdict` });
    return t;
  });
}

/** Per workload: each side's ratios at its sizes and whether the target holds at every size on both sides. */
function denseVerdictTable(dense) {
  const names = [...new Set(dense.workloads.map((w) => w.workload))];
  const rows = names.map((name) => {
    const sizes = dense.workloads.filter((w) => w.workload === name);
    const row = [name];
    const misses = [];
    let unmeasured = false;
    for (const key of ['native', 'node']) {
      const side = dense.sides[key];
      if (!side) {
        row.push('not measured');
        unmeasured = true;
        continue;
      }
      row.push(sizes.map((w) => {
        const { r, best } = denseRatio(side, w);
        if (!(r <= DENSE_TARGET)) misses.push(`${key === 'node' ? 'Node' : 'native'} at ${w.n}`);
        return `${w.n}: ${Number.isFinite(r) ? `${ratio(r)} (${best.engine})` : 'not run'}`;
      }).join('; '));
    }
    row.push(misses.length ? `**no**: ${misses.join(', ')}` : unmeasured ? 'yes where measured (one side not measured)' : 'yes');
    return row;
  });
  return table(['workload', 'native: polysweep ÷ fastest peer', 'Node: polysweep ÷ fastest peer', `≤ ${DENSE_TARGET}× at every size, both sides?`], rows,
    ['native: polysweep ÷ fastest peer', 'Node: polysweep ÷ fastest peer', `≤ ${DENSE_TARGET}× at every size, both sides?`]);
}

/** Times of one side: polysweep, each peer (ratio), the fastest and polysweep's ratio to it, area agreement. */
function denseTimeTable(dense, key) {
  const side = dense.sides[key];
  const nativeSide = key === 'node' ? dense.sides.native : null;
  const header = ['workload', 'edges', 'polysweep ms', ...side.info.map((e) => `${e} ms`), ...side.peers.map((e) => `${e} ms (ratio)`), 'fastest peer', 'ratio to fastest'];
  if (nativeSide) header.push('polysweep Node ÷ native');
  header.push('areas');
  const rows = dense.workloads.filter((w) => side.engines.some((e) => side.get(e, w.workload, w.n))).map((w) => {
    const p = side.get('polysweep', w.workload, w.n);
    const row = [`${w.workload} ${w.n}`, Number.isFinite(w.edges) ? w.edges.toLocaleString('en-US') : '–', cell(p), ...side.info.map((e) => cell(side.get(e, w.workload, w.n)))];
    for (const e of side.peers) {
      const r = side.get(e, w.workload, w.n);
      row.push(ok(r) && ok(p) ? `${ms(r.median_ms)} (${ratio(p.median_ms / r.median_ms)})` : cell(r));
    }
    const { r, best } = denseRatio(side, w);
    row.push(best ? best.engine : '–', ratio(r));
    if (nativeSide) {
      const q = nativeSide.get('polysweep', w.workload, w.n);
      row.push(ok(p) && ok(q) ? ratio(p.median_ms / q.median_ms) : '–');
    }
    row.push(areaNote(side.get, side.engines, w.workload, w.n).text);
    return row;
  });
  const out = [table(header, rows, ['fastest peer', 'areas'])];
  const problems = side.runs.filter((r) => r.status !== 'ok');
  if (problems.length) {
    out.push('', 'Runs that did not complete:', '');
    for (const r of problems) out.push(`- ${r.engine}, ${r.workload} ${r.n}: ${r.status}${r.error ? ` — ${r.error}` : ''}`);
  }
  return out.join('\n');
}

function mib(bytes) {
  if (!Number.isFinite(bytes)) return '–';
  const m = bytes / 2 ** 20;
  return m >= 100 ? m.toFixed(0) : m >= 10 ? m.toFixed(1) : m.toFixed(2);
}

/** Peak memory of one side, MiB per engine, and polysweep's over the smallest peer's. */
function denseMemoryTable(dense, key) {
  const side = dense.sides[key];
  const engines = ['polysweep', ...side.info, ...side.peers];
  const rows = dense.workloads.filter((w) => side.get('polysweep', w.workload, w.n)).map((w) => {
    const peak = (e) => side.get(e, w.workload, w.n)?.peak_bytes;
    const least = Math.min(...side.peers.map(peak).filter(Number.isFinite));
    return [`${w.workload} ${w.n}`, ...engines.map((e) => mib(peak(e))), Number.isFinite(peak('polysweep')) && Number.isFinite(least) ? ratio(peak('polysweep') / least) : '–'];
  });
  return table(['workload', ...engines.map((e) => `${e} MiB`), 'polysweep ÷ smallest peer'], rows);
}

export function denseSection(dense) {
  const { sides, workloads, denseWasm } = dense;
  const parts = ['## Dense workloads', ''];
  parts.push('Arrangements where edges are collinear, vertices coincide and edges cross densely, after the workloads of i_overlay\'s '
    + 'published comparison with Clipper2 and Boost (the same shapes, sizes and operations, in floats with integer values), plus the '
    + 'edge-sharing board of parcel maps. The native benchmark generates them (crates/polysweep-bench/src/dense.rs) and writes them to '
    + 'target/bench/dense/, which web/bench/dense.mjs reads, so both sides run the same inputs. Every engine reads the operands by '
    + 'the workload\'s fill rule (non-zero for the lines net and the spiral, even-odd elsewhere, where the operands do not overlap '
    + 'themselves and the two agree). A ratio is polysweep\'s time over the other\'s; the target is polysweep at most '
    + `${DENSE_TARGET}× the fastest peer's time, natively and in Node, at each size.`, '');
  const names = [...new Set(workloads.map((w) => w.workload))];
  if (!names.length) return [...parts, 'Not measured: neither native.json nor dense-wasm.json has dense runs.', ''].join('\n');
  parts.push(table(['workload', 'operation', 'fill rule', 'sizes n (edges)', 'shape'], names.map((name) => {
    const ws = workloads.filter((w) => w.workload === name);
    return [name, `${OPERATION_SIGN[ws[0].operation] ?? ''} ${ws[0].operation}`, ws[0].fill_rule ?? '–',
      ws.map((w) => `${w.n} (${Number.isFinite(w.edges) ? w.edges.toLocaleString('en-US') : '?'})`).join(', '), DENSE_SHAPES[name] ?? '–'];
  }), ['operation', 'fill rule', 'sizes n (edges)', 'shape']), '');
  parts.push('Edges: of both operands together.', '');

  parts.push('### Does polysweep meet the target?', '');
  parts.push(denseVerdictTable(dense), '');

  parts.push('### Native (Rust, release build)', '');
  if (sides.native) {
    parts.push('One process (crates/polysweep-bench), medians of several runs after a warm-up.', '');
    parts.push(denseTimeTable(dense, 'native'), '');
  } else parts.push('Not measured: native.json has no "dense" records (run the native benchmark).', '');

  parts.push('### Node (end to end)', '');
  if (sides.node) {
    parts.push(`Node ${denseWasm.node ?? ''}, run ${denseWasm.date.slice(0, 16).replace('T', ' ')} UTC, one worker thread per engine (web/bench/dense.mjs), timed as in Table 1: GeoJSON coordinate arrays in, arrays out, `
      + 'each engine\'s conversions included. polygon-clipping, martinez-polygon-clipping and polyclip-ts take no fill rule and are slower '
      + 'by orders of magnitude here; they run only when named with --engines.'
      + (dense.partial ? ' **Partial run** (options limited the engines, workloads, sizes, runs or memory).' : ''), '');
    parts.push(denseTimeTable(dense, 'node'), '');
    parts.push('Engines:', '');
    for (const [name, e] of Object.entries(denseWasm.engines ?? {})) parts.push(`- ${name} ${e.version}: ${e.notes}`);
    parts.push('');
  } else parts.push('Not measured: dense-wasm.json missing (run `node web/bench/dense.mjs`).', '');

  parts.push('### Peak memory', '');
  parts.push('The peak resident memory of one operation above what the process held before it, in MiB. Native: as the native benchmark '
    + 'measures it (crates/polysweep-bench). Node: one operation in a fresh process per engine and workload (web/bench/peak.mjs), the '
    + 'engine loaded and the input read first, then the peak resident set reset (Linux: /proc/self/clear_refs) and read again after the '
    + 'operation, its output still held: the conversions in and out, the JS heap and the wasm memory the operation grew.', '');
  for (const [key, title] of [['native', 'Native'], ['node', 'Node']]) {
    const side = sides[key];
    if (side && side.runs.some((r) => Number.isFinite(r.peak_bytes))) parts.push(`${title}:`, '', denseMemoryTable(dense, key), '');
    else parts.push(`${title}: not measured.`, '');
  }
  return parts.join('\n');
}

export const DENSE_PANEL_H = 400;
const DENSE_COLORS = { native: '#c0392b', node: '#e59866' };

/**
 * The dense workloads' panel of the chart, below Table 1's: per workload and size, a bar from 1× to polysweep's time
 * over the fastest peer's, natively and in Node, on a log scale (a bar down: polysweep faster), and the target line.
 */
export function densePanel(dense, top, W) {
  const plot = { left: 78, top: top + 70, right: W - 30, bottom: top + DENSE_PANEL_H - 70 };
  const names = [...new Set(dense.workloads.map((w) => w.workload))];
  const bars = [];
  names.forEach((name, g) => {
    const sizes = dense.workloads.filter((w) => w.workload === name);
    const groupW = (plot.right - plot.left) / names.length;
    const pairW = (groupW - 16) / sizes.length; // 8 px of air at each end of a group
    sizes.forEach((w, k) => {
      const x0 = plot.left + g * groupW + 8 + k * pairW;
      for (const [j, key] of ['native', 'node'].entries()) {
        const { r, best } = denseRatio(dense.sides[key], w);
        bars.push({ w, key, r, best, x: x0 + pairW * (0.1 + 0.4 * j), width: pairW * 0.4, center: x0 + pairW / 2 });
      }
    });
  });
  const rs = bars.map((b) => b.r).filter(Number.isFinite);
  const lo = niceBound(Math.min(...rs, DENSE_TARGET) / 1.2, false);
  const hi = niceBound(Math.max(...rs, 1) * 1.2, true);
  const y = (r) => plot.bottom - ((Math.log10(r) - Math.log10(lo)) / (Math.log10(hi) - Math.log10(lo))) * (plot.bottom - plot.top);

  const s = [];
  s.push(`<line x1="0" y1="${top}" x2="${W}" y2="${top}" stroke="#999999"/>`);
  s.push(`<text x="${(plot.left + plot.right) / 2}" y="${top + 28}" text-anchor="middle" font-size="15" font-weight="bold">Dense workloads: polysweep's time ÷ the fastest peer's (log scale)</text>`);
  // Legend on one line under the title.
  const ly = top + 52;
  for (const [k, key] of ['native', 'node'].entries()) {
    const text = `${key === 'native' ? 'native Rust' : 'Node end to end'}${dense.sides[key] ? '' : ': not measured'}`;
    const lx = plot.left + 220 * k;
    s.push(`<rect x="${lx}" y="${ly - 10}" width="14" height="12" fill="${DENSE_COLORS[key]}"/>`);
    s.push(`<text x="${lx + 20}" y="${ly}">${escapeXml(text)}</text>`);
  }
  s.push(`<line x1="${plot.left + 440}" y1="${ly - 4}" x2="${plot.left + 474}" y2="${ly - 4}" stroke="#1e8449" stroke-width="1.6" stroke-dasharray="6 4"/>`);
  s.push(`<text x="${plot.left + 482}" y="${ly}">target ${DENSE_TARGET}× (below 1×: polysweep is faster)</text>`);
  // Grid on the 1-2-5 steps.
  for (const { value: r, m } of logSteps(lo, hi)) {
    const yy = y(r).toFixed(1);
    s.push(`<line x1="${plot.left}" y1="${yy}" x2="${plot.right}" y2="${yy}" stroke="${r === 1 ? '#333333' : '#e4e4e4'}"/>`);
    s.push(`<text x="${plot.left - 6}" y="${(+yy + 4).toFixed(1)}" text-anchor="end" fill="${m === 1 ? '#000' : '#777'}">${r}×</text>`);
  }
  const yt = y(DENSE_TARGET).toFixed(1);
  s.push(`<line x1="${plot.left}" y1="${yt}" x2="${plot.right}" y2="${yt}" stroke="#1e8449" stroke-width="1.6" stroke-dasharray="6 4"/>`);
  s.push(`<rect x="${plot.left}" y="${plot.top}" width="${plot.right - plot.left}" height="${plot.bottom - plot.top}" fill="none" stroke="#333333"/>`);
  s.push(`<text transform="translate(20 ${(plot.top + plot.bottom) / 2}) rotate(-90)" text-anchor="middle" font-size="13">polysweep ÷ fastest peer</text>`);
  for (const b of bars) {
    const side = dense.sides[b.key];
    if (!Number.isFinite(b.r)) {
      s.push(`<text x="${(b.x + b.width / 2).toFixed(1)}" y="${(y(1) - 3).toFixed(1)}" text-anchor="middle" font-size="10" fill="#777">–</text>`);
      continue;
    }
    const p = side.get('polysweep', b.w.workload, b.w.n);
    const title = `${b.w.workload} ${b.w.n}, ${b.key === 'node' ? 'Node' : 'native'}: polysweep ${ms(p.median_ms)} ms, ${b.best.engine} ${ms(b.best.ms)} ms: ${ratio(b.r)}`;
    const [y0, y1] = [y(1), y(b.r)].sort((u, v) => u - v);
    s.push(`<rect x="${b.x.toFixed(1)}" y="${y0.toFixed(1)}" width="${b.width.toFixed(1)}" height="${Math.max(1, y1 - y0).toFixed(1)}" fill="${DENSE_COLORS[b.key]}"><title>${escapeXml(title)}</title></rect>`);
  }
  // Sizes under each pair of bars, workload names under their group.
  for (const b of bars.filter((x) => x.key === 'native')) {
    s.push(`<text x="${b.center.toFixed(1)}" y="${plot.bottom + 14}" text-anchor="middle" font-size="10" fill="#555">${b.w.n}</text>`);
  }
  const groupW = (plot.right - plot.left) / names.length;
  names.forEach((name, g) => {
    const op = dense.workloads.find((w) => w.workload === name).operation;
    s.push(`<text x="${(plot.left + (g + 0.5) * groupW).toFixed(1)}" y="${plot.bottom + 32}" text-anchor="middle" font-size="12">${escapeXml(`${name} ${OPERATION_SIGN[op] ?? op}`)}</text>`);
    if (g > 0) s.push(`<line x1="${(plot.left + g * groupW).toFixed(1)}" y1="${plot.top}" x2="${(plot.left + g * groupW).toFixed(1)}" y2="${plot.bottom}" stroke="#cccccc"/>`);
  });
  s.push(`<text x="${(plot.left + plot.right) / 2}" y="${plot.bottom + 54}" text-anchor="middle" font-size="13">workload and size n (see docs/benchmarks.md: Dense workloads)</text>`);
  return s;
}
