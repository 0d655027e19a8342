// What web/bench/wasm.mjs (Table 1) and web/bench/dense.mjs (the dense workloads) share: the engines' worker
// threads, the timing of one workload across engines, and the summary lines.
//
// Each engine runs in a worker thread of its own (worker.mjs), so that a run past the time limit can be stopped
// (the worker is terminated and a new one started) and a crash is recorded instead of ending the script. Per
// (engine, workload): one warm-up run, then 5 timed runs or more for fast pairs (up to 15, about 3 s in all), 3
// when the warm-up took over 10 s, 1 over 20 s, the engines' runs taken in turns (round by round) so that they
// share the machine's drifts in speed; a run over the limit stops the pair, recorded as skipped.

import { Worker } from 'node:worker_threads';
import os from 'node:os';
import { NOTES, PACKAGE_OF, packageVersion } from './engines.mjs';

const SLOW_MS = 10_000; // warm-up above this: fewer timed runs

/** One engine's worker; restarted after a timeout or a crash. */
export class EngineHost {
  constructor(name, limitMs) {
    this.name = name;
    this.limitMs = limitMs;
    this.worker = null;
    this.pending = null;
  }

  async start() {
    if (this.worker) return;
    const worker = new Worker(new URL('./worker.mjs', import.meta.url), { workerData: { engine: this.name } });
    this.worker = worker;
    // Events of a worker that was replaced (terminated after a timeout) must not reach the new one's request.
    const current = () => this.worker === worker;
    worker.on('message', (msg) => current() && this.pending?.onMessage(msg));
    worker.on('error', (error) => current() && this.pending?.onCrash(`worker crashed: ${error?.message ?? error}`));
    worker.on('exit', (code) => current() && this.pending?.onCrash(`worker exited with code ${code}`));
    await this.request(null, 'loading the engine');
  }

  /** Sends a task (or waits for 'ready' when task is null); resolves with the reply, rejects on timeout or crash. */
  request(task, what) {
    const limitMs = this.limitMs;
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
    return this.request(task, 'a run');
  }

  stop() {
    const worker = this.worker;
    this.worker = null;
    this.pending = null;
    return worker?.terminate();
  }
}

export function median(values) {
  const s = [...values].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

function timedRuns(warmupMs, quick) {
  if (quick) return 3;
  if (warmupMs > 2 * SLOW_MS) return 1;
  if (warmupMs > SLOW_MS) return 3;
  return Math.min(15, Math.max(5, Math.floor(3000 / Math.max(warmupMs, 1))));
}

/**
 * Times one workload on every engine: each engine's warm-up first (it also gives the area), then the timed runs in
 * rounds, one run of each engine per round, so that a change in the machine's speed over the minutes of a workload
 * falls on all engines alike. `task` is the workers' task ({input, operation, fillRule}); `base` the fields each
 * record starts with; `skip(engine)` a reason not to run an engine, or null. Returns, per engine in order,
 * {record, timedOut}: the record has status 'ok' (median_ms, min_ms, max_ms, times_ms, runs), 'skipped' (a run
 * went past the limit, or skip gave a reason) or 'failed', with the error.
 */
export async function timeWorkload(hosts, engines, task, { base, quick, skip = () => null }) {
  const pairs = [];
  const fail = (pair, error) => {
    pair.record.status = error.timeout || error.skip ? 'skipped' : 'failed';
    pair.record.error = error.message;
    pair.timedOut = !!error.timeout;
    pair.count = 0;
  };
  for (const engine of engines) {
    const record = { engine, ...base, median_ms: null, area: null, status: 'ok', runs: 0 };
    const pair = { engine, record, times: [], count: 0, timedOut: false };
    pairs.push(pair);
    try {
      const reason = skip(engine);
      if (reason) throw Object.assign(new Error(reason), { skip: true });
      const warm = await hosts.get(engine).run({ ...task, measure: true });
      record.area = warm.area;
      record.vertices_out = warm.vertices;
      record.warmup_ms = warm.ms;
      pair.count = timedRuns(warm.ms, quick);
    } catch (error) {
      fail(pair, error);
    }
  }
  while (pairs.some((p) => p.times.length < p.count)) {
    for (const pair of pairs.filter((p) => p.times.length < p.count)) {
      try {
        pair.times.push((await hosts.get(pair.engine).run({ ...task, measure: false })).ms);
      } catch (error) {
        fail(pair, error);
      }
    }
  }
  for (const { record, times } of pairs) {
    if (record.status !== 'ok') continue;
    record.runs = times.length;
    record.median_ms = median(times);
    record.min_ms = Math.min(...times);
    record.max_ms = Math.max(...times);
    record.times_ms = times.map((t) => Math.round(t * 1000) / 1000);
  }
  return pairs.map(({ record, timedOut }) => ({ record, timedOut }));
}

export function machineLine() {
  const cpus = os.cpus();
  const model = cpus[0]?.model?.trim() ?? 'unknown CPU';
  const gib = (os.totalmem() / 2 ** 30).toFixed(0);
  return `${model}, ${cpus.length} cores, ${gib} GiB, ${os.type()} ${os.release()}, Node ${process.version}`;
}

export function fmt(ms) {
  return ms >= 100 ? ms.toFixed(0) : ms >= 10 ? ms.toFixed(1) : ms.toFixed(2);
}

/** Each engine's package, version and notes, for a benchmark's output. */
export function engineInfo(names) {
  return Object.fromEntries(names.map((e) => [e, { package: PACKAGE_OF[e], version: packageVersion(PACKAGE_OF[e]), notes: NOTES[e] }]));
}
