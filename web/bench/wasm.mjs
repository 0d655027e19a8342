#!/usr/bin/env node
// The wasm/JS benchmark: the npm package `polysweep` end to end (GeoJSON coordinate arrays in, arrays out)
// against polygon-clipping, martinez-polygon-clipping, polyclip-ts, clipper2-wasm and js-angusj-clipper, on the
// workloads of the native benchmark: land ∩ N squares for every N of the series, land ∪ and − 3,895 squares.
//
//   node web/bench/wasm.mjs [--quick] [--engines a,b,...] [--sizes 8,162,...] [--limit SECONDS]
//
// --quick: 3 timed runs per pair; --engines, --sizes: a subset (the output is then marked partial).
//
// Each engine runs in a worker thread of its own, so that a run past the time limit can be stopped (the worker is
// terminated and a new one started) and a crash is recorded instead of ending the script. Per (engine, workload):
// one warm-up run, then 5 timed runs or more for fast pairs (up to 15, about 3 s in all), 3 when the warm-up took
// over 10 s, 1 over 20 s, the engines' runs taken in turns (round by round) so that they share the machine's
// drifts in speed; a run over 60 s stops the pair, recorded as skipped, and the engine's larger
// intersections are skipped too (their inputs only grow). Inputs are fresh copies for every run (made before the
// clock starts, so no engine sees what an earlier run did to them), and the worker's heap is collected before the
// clock starts. Timed: the engine's conversions in, the operation, its conversions out. Not timed: the area
// (shoelace, exteriors minus holes), compared with polysweep's to 1e-6 relative and, at 8/162/974/3895, with the
// reference areas of tests/data/README.md.
//
// Writes target/bench/wasm.json; progress goes to stderr.

import { Worker, isMainThread, parentPort, workerData } from 'node:worker_threads';
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import os from 'node:os';
import v8 from 'node:v8';
import vm from 'node:vm';
import {
  BENCH_DIR, FULL_N, REFERENCE_AREAS, REFERENCE_TOLERANCE, SQUARE_COUNTS, loadLand, loadSquares, vertexCount,
} from './data.mjs';
import { CLIPPER1_SCALE, CLIPPER2_PRECISION, ENGINES, NOTES, PACKAGE_OF, loadEngine, packageVersion } from './engines.mjs';

const tooSlowAt = new Map(); // engine -> N at which an intersection went past the limit
let LIMIT_MS = 60_000; // a run longer than this is stopped and the pair skipped (--limit SECONDS)
const SLOW_MS = 10_000; // warm-up above this: fewer timed runs
const AGREEMENT = 1e-6; // relative area difference allowed against polysweep

// ---------------------------------------------------------------- worker ----------------------------------------

async function workerMain() {
  v8.setFlagsFromString('--expose-gc');
  const gc = vm.runInNewContext('gc');
  const engine = await loadEngine(workerData.engine);
  const land = loadLand().coordinates;
  const squares = new Map();
  parentPort.postMessage({ type: 'ready' });
  parentPort.on('message', (task) => {
    try {
      if (!squares.has(task.n)) {
        squares.clear();
        squares.set(task.n, loadSquares(task.n).coordinates);
      }
      const a = structuredClone(land);
      const b = structuredClone(squares.get(task.n));
      const input = engine.prepare ? engine.prepare(a, b) : [a, b];
      gc();
      parentPort.postMessage({ type: 'started' });
      const t0 = performance.now();
      const output = engine.run(task.operation, ...input);
      const ms = performance.now() - t0;
      const reply = { type: 'done', ms };
      if (task.measure) {
        reply.area = engine.area(output);
        reply.vertices = Array.isArray(output) ? vertexCount(output) : output.coords.length / 2 - (output.ringOffsets.length - 1);
      }
      parentPort.postMessage(reply);
    } catch (error) {
      parentPort.postMessage({ type: 'error', message: String(error?.message ?? error) });
    }
  });
}

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

/** One engine's worker; restarted after a timeout or a crash. */
class EngineHost {
  constructor(name) {
    this.name = name;
    this.worker = null;
    this.pending = null;
  }

  async start() {
    if (this.worker) return;
    const worker = new Worker(new URL(import.meta.url), { workerData: { engine: this.name } });
    this.worker = worker;
    // Events of a worker that was replaced (terminated after a timeout) must not reach the new one's request.
    const current = () => this.worker === worker;
    worker.on('message', (msg) => current() && this.pending?.onMessage(msg));
    worker.on('error', (error) => current() && this.pending?.onCrash(`worker crashed: ${error?.message ?? error}`));
    worker.on('exit', (code) => current() && this.pending?.onCrash(`worker exited with code ${code}`));
    await this.request(null, LIMIT_MS, 'loading the engine');
  }

  /** Sends a task (or waits for 'ready' when task is null); resolves with the reply, rejects on timeout or crash. */
  request(task, limitMs, what) {
    return new Promise((resolve, reject) => {
      let timer = null;
      const finish = (fn, value) => {
        clearTimeout(timer);
        this.pending = null;
        fn(value);
      };
      const kill = (error) => {
        clearTimeout(timer);
        const worker = this.worker;
        this.worker = null;
        this.pending = null;
        worker?.terminate();
        reject(error);
      };
      const arm = () => {
        clearTimeout(timer);
        timer = setTimeout(() => kill(Object.assign(new Error(`${what} took more than ${limitMs / 1000} s (stopped)`), { timeout: true })), limitMs);
      };
      this.pending = {
        onMessage: (msg) => {
          if (msg.type === 'started') arm(); // the clock is on: the limit counts from here
          else if (msg.type === 'ready' || msg.type === 'done') finish(resolve, msg);
          else if (msg.type === 'error') finish(reject, new Error(msg.message));
        },
        onCrash: (message) => {
          this.worker = null;
          finish(reject, Object.assign(new Error(message), { crash: true }));
        },
      };
      // Before the clock starts (loading the engine, reading and copying inputs) a generous limit of its own.
      timer = setTimeout(() => kill(Object.assign(new Error(`${what}: no answer in 10 minutes`), { crash: true })), 600_000);
      if (task) this.worker.postMessage(task);
    });
  }

  async run(task) {
    await this.start();
    return this.request(task, LIMIT_MS, 'a run');
  }

  stop() {
    const worker = this.worker;
    this.worker = null;
    this.pending = null;
    return worker?.terminate();
  }
}

function median(values) {
  const s = [...values].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

/** Records that a pair's warm-up or a timed run failed or went past the limit; the pair runs no more. */
function fail(pair, error) {
  pair.record.status = error.timeout || error.skip ? 'skipped' : 'failed';
  pair.record.error = error.message;
  pair.count = 0;
  if (error.timeout && pair.record.operation === 'intersection') tooSlowAt.set(pair.engine, pair.record.squares);
}

function timedRuns(warmupMs, quick) {
  if (quick) return 3;
  if (warmupMs > 2 * SLOW_MS) return 1;
  if (warmupMs > SLOW_MS) return 3;
  return Math.min(15, Math.max(5, Math.floor(3000 / Math.max(warmupMs, 1))));
}

function machineLine() {
  const cpus = os.cpus();
  const model = cpus[0]?.model?.trim() ?? 'unknown CPU';
  const gib = (os.totalmem() / 2 ** 30).toFixed(0);
  return `${model}, ${cpus.length} cores, ${gib} GiB, ${os.type()} ${os.release()}, Node ${process.version}`;
}

function fmt(ms) {
  return ms >= 100 ? ms.toFixed(0) : ms >= 10 ? ms.toFixed(1) : ms.toFixed(2);
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

  const hosts = new Map(args.engines.map((e) => [e, new EngineHost(e)]));
  const runs = [];
  const started = Date.now();

  for (const { operation, n } of workloads) {
    log(`\n${operation} land × ${n} squares (${sources[n]})`);
    // Every engine's warm-up first, then the timed runs in rounds, one run of each engine per round, so that a
    // change in the machine's speed over the minutes of a workload falls on all engines alike.
    const pairs = [];
    for (const engine of args.engines) {
      const record = { engine, operation, squares: n, median_ms: null, area: null, status: 'ok', runs: 0 };
      const pair = { engine, record, times: [], count: 0 };
      pairs.push(pair);
      try {
        if (operation === 'intersection' && tooSlowAt.has(engine)) {
          throw Object.assign(new Error(`a run took more than ${LIMIT_MS / 1000} s at ${tooSlowAt.get(engine)} squares`), { skip: true });
        }
        const warm = await hosts.get(engine).run({ operation, n, measure: true });
        record.area = warm.area;
        record.vertices_out = warm.vertices;
        record.warmup_ms = warm.ms;
        pair.count = timedRuns(warm.ms, args.quick);
      } catch (error) {
        fail(pair, error);
      }
    }
    while (pairs.some((p) => p.times.length < p.count)) {
      for (const pair of pairs.filter((p) => p.times.length < p.count)) {
        try {
          pair.times.push((await hosts.get(pair.engine).run({ operation, n, measure: false })).ms);
        } catch (error) {
          fail(pair, error);
        }
      }
    }
    let psArea = null;
    for (const { engine, record, times } of pairs) {
      if (record.status === 'ok') {
        record.runs = times.length;
        record.median_ms = median(times);
        record.min_ms = Math.min(...times);
        record.max_ms = Math.max(...times);
        record.times_ms = times.map((t) => Math.round(t * 1000) / 1000);
      }
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

  const engines = {};
  for (const e of args.engines) engines[e] = { package: PACKAGE_OF[e], version: packageVersion(PACKAGE_OF[e]), notes: NOTES[e] };
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

// Declarations above; dispatch last (a class is not initialised before its line runs).
if (isMainThread) {
  await main();
} else {
  await workerMain();
}
