#!/usr/bin/env node
// The wasm/JS benchmark: the npm package `polysweep` end to end (GeoJSON coordinate arrays in, arrays out)
// against polygon-clipping, martinez-polygon-clipping, polyclip-ts, clipper2-wasm, js-angusj-clipper, clipper2-ts
// and ishape_wasm, on the workloads of the native benchmark: land ∩ N squares for every N of the series, land ∪ and
// − 3,895 squares.
//
//   node web/bench/wasm.mjs [--quick] [--engines a,b,...] [--sizes 8,162,...] [--limit SECONDS]
//
// --quick: 3 timed runs per pair; --engines, --sizes: a subset (the output is then marked partial).
//
// Timing (runner.mjs): per (engine, workload) a warm-up run, then 5 to 15 timed runs (fewer after a slow warm-up),
// the engines taken in turns; each engine in a worker thread of its own, restarted after a crash or a run past the
// limit (60 s; the pair is then recorded as skipped, and the engine's larger intersections are skipped too, their
// inputs only growing). Timed: the engine's conversions in, the operation, its conversions out. Not timed: the area
// (shoelace, exteriors minus holes), compared with polysweep's to 1e-6 relative and, at 8/162/974/3895, with the
// reference areas of tests/data/README.md. Fill rule: each engine's even-odd (polysweep: the package default).
//
// Writes target/bench/wasm.json; progress goes to stderr.

import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import {
  BENCH_DIR, FULL_N, REFERENCE_AREAS, REFERENCE_TOLERANCE, SQUARE_COUNTS, loadLand, loadSquares,
} from './data.mjs';
import { CLIPPER1_SCALE, CLIPPER2_PRECISION, ENGINES } from './engines.mjs';
import { EngineHost, engineInfo, fmt, machineLine, timeWorkload } from './runner.mjs';

const tooSlowAt = new Map(); // engine -> N at which an intersection went past the limit
let LIMIT_MS = 60_000; // a run longer than this is stopped and the pair skipped (--limit SECONDS)
const AGREEMENT = 1e-6; // relative area difference allowed against polysweep

// ---------------------------------------------------------------- main ------------------------------------------

function parseArgs(argv) {
  const args = { quick: false, engines: ENGINES, sizes: SQUARE_COUNTS };
  for (let i = 0; i < argv.length; i++) {
    if (argv[i] === '--quick') args.quick = true;
    else if (argv[i] === '--engines') args.engines = argv[++i].split(',');
    else if (argv[i] === '--sizes') args.sizes = argv[++i].split(',').map(Number);
    else if (argv[i] === '--limit') LIMIT_MS = 1000 * Number(argv[++i]);
    else throw new Error(`unknown argument ${argv[i]} (use --quick, --engines a,b, --sizes 8,162, --limit SECONDS)`);
  }
  for (const e of args.engines) if (!ENGINES.includes(e)) throw new Error(`unknown engine ${e}; known: ${ENGINES.join(', ')}`);
  if (!(LIMIT_MS > 0)) throw new Error('--limit takes a number of seconds');
  return args;
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  const log = (s) => process.stderr.write(`${s}\n`);
  const land = loadLand();
  log(`land: ${land.source}`);

  const workloads = args.sizes.map((n) => ({ operation: 'intersection', n }));
  if (args.sizes.includes(FULL_N) || args.sizes === SQUARE_COUNTS) {
    workloads.push({ operation: 'union', n: FULL_N }, { operation: 'difference', n: FULL_N });
  }
  const sources = {};
  for (const n of new Set(workloads.map((w) => w.n))) sources[n] = loadSquares(n).source;

  const hosts = new Map(args.engines.map((e) => [e, new EngineHost(e, LIMIT_MS)]));
  const runs = [];
  const started = Date.now();

  for (const { operation, n } of workloads) {
    log(`\n${operation} land × ${n} squares (${sources[n]})`);
    const timed = await timeWorkload(hosts, args.engines, { input: { kind: 'table1', n }, operation }, {
      base: { operation, squares: n },
      quick: args.quick,
      skip: (engine) => (operation === 'intersection' && tooSlowAt.has(engine)
        ? `a run took more than ${LIMIT_MS / 1000} s at ${tooSlowAt.get(engine)} squares` : null),
    });
    let psArea = null;
    for (const { record, timedOut } of timed) {
      const { engine } = record;
      if (timedOut && operation === 'intersection') tooSlowAt.set(engine, n);
      if (engine === 'polysweep' && record.status === 'ok') psArea = record.area;
      const reference = REFERENCE_AREAS[operation]?.[n];
      if (reference !== undefined) {
        record.reference_area = reference;
        if (record.area !== null) {
          // The reference is printed to 6 decimals: agreement to 1e-6 relative plus that rounding.
          const diff = Math.abs(record.area - reference);
          record.reference_rel_diff = diff / reference;
          record.reference_ok = diff <= AGREEMENT * reference + REFERENCE_TOLERANCE;
        }
      }
      if (record.area !== null && psArea !== null) {
        record.area_rel_diff = Math.abs(record.area - psArea) / Math.abs(psArea);
        record.area_agrees = record.area_rel_diff <= AGREEMENT;
      }
      runs.push(record);
      const what = record.status === 'ok'
        ? `${fmt(record.median_ms).padStart(8)} ms (median of ${record.runs})  area ${record.area.toFixed(6)}${record.area_agrees === false ? `  MISMATCH (${record.area_rel_diff.toExponential(2)} relative)` : ''}`
        : `${record.status.toUpperCase()}: ${record.error}`;
      log(`  ${engine.padEnd(26)} ${what}`);
    }
  }
  await Promise.all([...hosts.values()].map((h) => h.stop()));

  const engines = engineInfo(args.engines);
  const result = {
    machine: machineLine(),
    date: new Date().toISOString(),
    node: process.version,
    partial: args.quick || args.engines !== ENGINES || args.sizes !== SQUARE_COUNTS || LIMIT_MS !== 60_000,
    settings: {
      run_limit_ms: LIMIT_MS, area_agreement: AGREEMENT, clipper2_precision: CLIPPER2_PRECISION,
      clipper1_scale: CLIPPER1_SCALE, quick: args.quick,
    },
    data: { land: land.source, squares: sources },
    engines,
    total_s: (Date.now() - started) / 1000,
    runs,
  };
  mkdirSync(BENCH_DIR, { recursive: true });
  const out = join(BENCH_DIR, 'wasm.json');
  writeFileSync(out, `${JSON.stringify(result, null, 2)}\n`);
  log(`\nwrote ${out} (${result.total_s.toFixed(0)} s)`);
  const failed = runs.filter((r) => r.status !== 'ok');
  const mismatched = runs.filter((r) => r.area_agrees === false || r.reference_ok === false);
  for (const r of failed) log(`  ${r.status}: ${r.engine} ${r.operation} ${r.squares}: ${r.error}`);
  for (const r of mismatched) log(`  area mismatch: ${r.engine} ${r.operation} ${r.squares}: ${r.area} (polysweep ${runs.find((x) => x.engine === 'polysweep' && x.operation === r.operation && x.squares === r.squares)?.area}, reference ${r.reference_area ?? '-'})`);
}

await main();
