// The worker thread of one engine for the timed runs of web/bench/wasm.mjs and web/bench/dense.mjs (started by
// EngineHost in runner.mjs). Each task names its input, operation and fill rule; the worker answers 'started' when
// the clock starts (the host's time limit counts from there) and 'done' with the time. Inputs are fresh copies for
// every run, made before the clock starts so that no engine sees what an earlier run did to them, and the heap is
// collected before the clock starts. With `measure`, the area and the output's vertex count (not timed) too.

import { parentPort, workerData } from 'node:worker_threads';
import v8 from 'node:v8';
import vm from 'node:vm';
import { loadOperands, vertexCount } from './data.mjs';
import { loadEngine } from './engines.mjs';

v8.setFlagsFromString('--expose-gc');
const gc = vm.runInNewContext('gc');
const engine = await loadEngine(workerData.engine);
let cached = { key: null, operands: null }; // the last input: a workload's runs come one after another
parentPort.postMessage({ type: 'ready' });
parentPort.on('message', (task) => {
  try {
    const key = JSON.stringify(task.input);
    if (cached.key !== key) {
      cached = { key: null, operands: null }; // let the previous input go before reading the next
      cached = { key, operands: loadOperands(task.input) };
    }
    const [a, b] = cached.operands.map((operand) => structuredClone(operand));
    const input = engine.prepare ? engine.prepare(a, b) : [a, b];
    gc();
    parentPort.postMessage({ type: 'started' });
    const t0 = performance.now();
    const output = engine.run(task.operation, ...input, task.fillRule);
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
