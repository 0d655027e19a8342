#!/usr/bin/env node
// The dense workloads in Node (issue 25): the npm package `polysweep` end to end against the JS/wasm peers on the
// inputs the native benchmark wrote to target/bench/dense/ (crates/polysweep-bench/src/dense.rs generates them:
// grids of squares sharing edges and corners, crossing bars, a self-crossing spiral, nested frames).
//
//   node web/bench/dense.mjs [--quick] [--engines a,b,...] [--workloads a,b,...] [--sizes 50,100,...]
//                            [--limit SECONDS] [--no-memory]
//
// --quick: 3 timed runs per pair; --engines, --workloads, --sizes: a subset; --no-memory: no peak-memory runs (any
// of these marks the output partial).
//
// Timing as web/bench/wasm.mjs's (runner.mjs: a warm-up, then 5 to 15 timed runs taken in turns, each engine in a
// worker of its own); every engine reads the operands by the workload's fill rule. A run over the limit skips the
// pair and the engine's larger sizes of that workload. The engines without a fill rule (engines.mjs:
// READS_RINGS_ONLY) are skipped on the non-zero workloads. Areas are compared with polysweep's to 1e-6 relative.
// Then the peak memory of one operation of each engine that ran, in a fresh process (peak.mjs).
//
// Writes target/bench/dense-wasm.json; progress goes to stderr.

import { execFile } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { promisify } from 'node:util';
import { BENCH_DIR, DENSE_DIR, loadDenseIndex } from './data.mjs';
import { CLIPPER1_SCALE, CLIPPER2_PRECISION, ENGINES, takesFillRule } from './engines.mjs';
import { EngineHost, engineInfo, fmt, machineLine, timeWorkload } from './runner.mjs';

/**
 * The engines by default: polysweep and the JS/wasm peers that finish these workloads. polygon-clipping, martinez
 * and polyclip-ts are slower by orders of magnitude here and can be added with --engines.
 */
const DENSE_ENGINES = ['polysweep', 'clipper2-wasm', 'js-angusj-clipper', 'clipper2-ts', 'ishape_wasm'];
const DEFAULT_LIMIT_MS = 60_000;
const AGREEMENT = 1e-6; // relative area difference allowed against polysweep
const PEAK_LOAD_MS = 120_000; // a peak-memory process's time to load the engine and the input, on top of the limit

function parseArgs(argv) {
  const args = { quick: false, engines: DENSE_ENGINES, workloads: null, sizes: null, limitMs: DEFAULT_LIMIT_MS, memory: true };
  for (let i = 0; i < argv.length; i++) {
    if (argv[i] === '--quick') args.quick = true;
    else if (argv[i] === '--engines') args.engines = argv[++i].split(',');
    else if (argv[i] === '--workloads') args.workloads = argv[++i].split(',');
    else if (argv[i] === '--sizes') args.sizes = argv[++i].split(',').map(Number);
    else if (argv[i] === '--limit') args.limitMs = 1000 * Number(argv[++i]);
    else if (argv[i] === '--no-memory') args.memory = false;
    else throw new Error(`unknown argument ${argv[i]} (use --quick, --engines a,b, --workloads a,b, --sizes 50,100, --limit SECONDS, --no-memory)`);
  }
  for (const e of args.engines) if (!ENGINES.includes(e)) throw new Error(`unknown engine ${e}; known: ${ENGINES.join(', ')}`);
  if (!args.engines.includes('polysweep')) throw new Error('--engines must include polysweep (areas are compared with its)');
  if (!(args.limitMs > 0)) throw new Error('--limit takes a number of seconds');
  return args;
}

/** Peak memory of one operation in a fresh process: {peak_bytes} or {peak_error}. */
async function peakMemory(engine, entry, limitMs) {
  const script = new URL('./peak.mjs', import.meta.url).pathname;
  try {
    const { stdout } = await promisify(execFile)(process.execPath,
      ['--expose-gc', script, engine, entry.file, entry.operation, entry.fill_rule],
      { timeout: limitMs + PEAK_LOAD_MS, maxBuffer: 1 << 20 });
    return { peak_bytes: JSON.parse(stdout).peak_bytes };
  } catch (error) {
    const why = error.killed ? `no answer in ${(limitMs + PEAK_LOAD_MS) / 1000} s` : (error.stderr || error.message).trim().split('\n').slice(-1)[0];
    return { peak_bytes: null, peak_error: why };
  }
}

function mib(bytes) {
  return bytes === null || bytes === undefined ? '–' : `${(bytes / 2 ** 20).toFixed(1)} MiB`;
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  const log = (s) => process.stderr.write(`${s}\n`);
  const index = loadDenseIndex();
  if (!index) throw new Error(`${join(DENSE_DIR, 'index.json')} is missing: run the native benchmark in full first (cargo run --release -p polysweep-bench; a run narrowed to some engines, workloads or sizes writes no index)`);
  const entries = index.filter((e) => (!args.workloads || args.workloads.includes(e.workload)) && (!args.sizes || args.sizes.includes(e.n)));
  if (!entries.length) throw new Error('no dense workload matches --workloads and --sizes');
  for (const w of args.workloads ?? []) if (!index.some((e) => e.workload === w)) throw new Error(`unknown workload ${w}`);

  const hosts = new Map(args.engines.map((e) => [e, new EngineHost(e, args.limitMs)]));
  const tooSlow = new Map(); // `${engine}|${workload}` -> the size at which a run went past the limit
  const runs = [];
  const started = Date.now();

  for (const entry of entries) {
    const { workload, n, operation, fill_rule: fillRule, edges, file } = entry;
    log(`\n${workload} ${n} (${operation}, ${fillRule}, ${edges} edges)`);
    const timed = await timeWorkload(hosts, args.engines, { input: { kind: 'dense', file }, operation, fillRule }, {
      base: { workload, n, operation, fill_rule: fillRule, edges },
      quick: args.quick,
      skip(engine) {
        if (!takesFillRule(engine, fillRule)) return `takes no fill rule: cannot read its operands by ${fillRule}`;
        const at = tooSlow.get(`${engine}|${workload}`);
        return at ? `a run took more than ${args.limitMs / 1000} s at ${workload} ${at}` : null;
      },
    });
    const psArea = timed.find(({ record }) => record.engine === 'polysweep')?.record.area ?? null;
    for (const { record, timedOut } of timed) {
      if (timedOut) tooSlow.set(`${record.engine}|${workload}`, n);
      if (record.area !== null && psArea !== null) {
        record.area_rel_diff = Math.abs(record.area - psArea) / Math.abs(psArea);
        record.area_agrees = record.area_rel_diff <= AGREEMENT;
      }
      if (args.memory && record.status === 'ok') Object.assign(record, await peakMemory(record.engine, entry, args.limitMs));
      runs.push(record);
      const what = record.status === 'ok'
        ? `${fmt(record.median_ms).padStart(8)} ms (median of ${record.runs})  area ${record.area.toFixed(6)}`
          + `${record.area_agrees === false ? `  MISMATCH (${record.area_rel_diff.toExponential(2)} relative)` : ''}`
          + (args.memory ? `  peak ${record.peak_bytes !== null ? mib(record.peak_bytes) : `– (${record.peak_error})`}` : '')
        : `${record.status.toUpperCase()}: ${record.error}`;
      log(`  ${record.engine.padEnd(26)} ${what}`);
    }
  }
  await Promise.all([...hosts.values()].map((h) => h.stop()));

  const engines = engineInfo(args.engines);
  const result = {
    machine: machineLine(),
    date: new Date().toISOString(),
    node: process.version,
    partial: args.quick || args.engines !== DENSE_ENGINES || !!args.workloads || !!args.sizes || args.limitMs !== DEFAULT_LIMIT_MS || !args.memory,
    settings: {
      run_limit_ms: args.limitMs, area_agreement: AGREEMENT, clipper2_precision: CLIPPER2_PRECISION,
      clipper1_scale: CLIPPER1_SCALE, quick: args.quick, memory: args.memory,
    },
    data: DENSE_DIR,
    engines,
    total_s: (Date.now() - started) / 1000,
    runs,
  };
  mkdirSync(BENCH_DIR, { recursive: true });
  const out = join(BENCH_DIR, 'dense-wasm.json');
  writeFileSync(out, `${JSON.stringify(result, null, 2)}\n`);
  log(`\nwrote ${out} (${result.total_s.toFixed(0)} s)`);
  for (const r of runs.filter((x) => x.status === 'failed')) log(`  failed: ${r.engine} ${r.workload} ${r.n}: ${r.error}`);
  for (const r of runs.filter((x) => x.area_agrees === false)) {
    log(`  area mismatch: ${r.engine} ${r.workload} ${r.n}: ${r.area} (polysweep ${runs.find((x) => x.engine === 'polysweep' && x.workload === r.workload && x.n === r.n)?.area})`);
  }
  for (const r of runs.filter((x) => x.peak_error)) log(`  no peak memory: ${r.engine} ${r.workload} ${r.n}: ${r.peak_error}`);
}

await main();
