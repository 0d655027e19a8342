// Formatting and lookups shared by the sections of the benchmark report (web/bench/report.mjs and
// web/bench/report-dense.mjs): the engines, times and ratios as the tables print them, area agreement, markdown
// tables, and the chart's helpers.

import { REFERENCE_AREAS, REFERENCE_TOLERANCE } from './data.mjs';

export const NATIVE_PEERS = ['i_overlay', 'geo', 'clipper2'];
export const WASM_PEERS = ['clipper2-wasm', 'js-angusj-clipper', 'clipper2-ts', 'ishape_wasm', 'martinez-polygon-clipping', 'polygon-clipping', 'polyclip-ts'];
export const INFO_ENGINES = ['polysweep-flat']; // measured, shown, never a peer
export const AGREEMENT = 1e-6;

export function enginesOf(data, preferred) {
  const seen = new Set((data?.runs ?? []).map((r) => r.engine));
  const ordered = preferred.filter((e) => seen.has(e));
  for (const e of seen) if (!ordered.includes(e)) ordered.push(e);
  return ordered;
}
export const ok = (r) => r && r.status === 'ok' && Number.isFinite(r.median_ms);

export function ms(value) {
  if (!Number.isFinite(value)) return '–';
  return value >= 100 ? value.toFixed(0) : value >= 10 ? value.toFixed(1) : value.toFixed(2);
}

export function ratio(value) {
  return Number.isFinite(value) ? `${value >= 10 ? value.toFixed(1) : value.toFixed(2)}×` : '–';
}

export function cell(r) {
  if (!r) return 'not run';
  if (r.status !== 'ok') return r.status;
  return ms(r.median_ms);
}

/** The fastest successful peer of a workload: {engine, ms} or null. */

export function fastestPeer(get, peers, operation, n) {
  let best = null;
  for (const e of peers) {
    const r = get(e, operation, n);
    if (ok(r) && (!best || r.median_ms < best.ms)) best = { engine: e, ms: r.median_ms };
  }
  return best;
}

/** Area agreement of a workload against polysweep's area (and the reference, where there is one). */

export function areaNote(get, engines, operation, n) {
  const ps = get('polysweep', operation, n);
  const base = ok(ps) || Number.isFinite(ps?.area) ? ps.area : null;
  const reference = REFERENCE_AREAS[operation]?.[n];
  const notes = [];
  if (base !== null && reference !== undefined && Math.abs(base - reference) > REFERENCE_TOLERANCE) {
    notes.push(`polysweep ${base.toFixed(6)} ≠ reference ${reference.toFixed(6)}`);
  }
  if (base === null) return { text: ps ? `no polysweep area (${ps.status})` : 'polysweep not run', bad: !!ps };
  for (const e of engines) {
    if (e === 'polysweep') continue;
    const r = get(e, operation, n);
    if (!r || !Number.isFinite(r.area)) continue;
    const rel = Math.abs(r.area - base) / Math.abs(base);
    if (rel > AGREEMENT) notes.push(`${e} off by ${rel.toExponential(1)}`);
  }
  return notes.length ? { text: `**${notes.join('; ')}**`, bad: true } : { text: 'agree', bad: false };
}

/** A markdown table; `left` lists the columns (besides the first) that hold text rather than figures. */

export function table(header, rows, left = []) {
  const align = header.map((h, i) => (i === 0 || left.includes(h) ? '---' : '---:'));
  const lines = [`| ${header.join(' | ')} |`, `|${align.join('|')}|`];
  for (const row of rows) lines.push(`| ${row.join(' | ')} |`);
  return lines.join('\n');
}

export function escapeXml(s) {
  return String(s).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
}

/** The 1-2-5 step just below (or, with `up`, just above) t: the bounds of a log axis. */

export function niceBound(t, up) {
  const e = Math.floor(Math.log10(t));
  const candidates = [1, 2, 5, 10].map((m) => m * 10 ** e);
  return up ? candidates.find((c) => c >= t * 0.999) : [...candidates].reverse().find((c) => c <= t * 1.001);
}

/** The 1-2-5 steps from `lo` to `hi` (a log axis's grid lines), each with its mantissa `m` (1, 2 or 5). */
export function logSteps(lo, hi) {
  const steps = [];
  for (let e = Math.floor(Math.log10(lo)); e <= Math.log10(hi) + 1e-9; e++) {
    for (const m of [1, 2, 5]) {
      const value = m * 10 ** e;
      if (value <= hi * 1.0001 && value >= lo * 0.9999) steps.push({ value, m });
    }
  }
  return steps;
}
