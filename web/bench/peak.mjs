#!/usr/bin/env node
// Peak memory of one operation, for web/bench/dense.mjs, which runs this in a fresh process per engine and workload
// (a worker would share the process's memory with the others, and a second run would find a wasm engine's memory
// already grown):
//
//   node --expose-gc web/bench/peak.mjs ENGINE FILE OPERATION FILL_RULE    (FILE: a file of target/bench/dense)
//
// The engine is loaded and the input read and converted as for a timed run (prepare, if the engine has one), the
// heap collected, then the peak resident set size reset (writing 5 to /proc/self/clear_refs sets VmHWM to VmRSS, a
// Linux facility) and VmRSS read; after the operation, whose output is still held, VmHWM. Prints one line of JSON:
// {peak_bytes: VmHWM after − VmRSS before, rss_before_bytes, area}. Everything the operation touched counts: its
// conversions in and out, the JS heap it grew, the wasm memory it grew.

import { readFileSync, writeFileSync } from 'node:fs';
import { loadOperands } from './data.mjs';
import { loadEngine } from './engines.mjs';

function statusBytes(field) {
  const line = readFileSync('/proc/self/status', 'utf8').split('\n').find((l) => l.startsWith(`${field}:`));
  if (!line) throw new Error(`no ${field} in /proc/self/status`);
  const [, kib] = line.match(/(\d+)\s*kB/);
  return Number(kib) * 1024;
}

const [name, file, operation, fillRule] = process.argv.slice(2);
if (!fillRule) throw new Error('usage: node --expose-gc web/bench/peak.mjs ENGINE FILE OPERATION FILL_RULE');
if (typeof globalThis.gc !== 'function') throw new Error('run with node --expose-gc');

const engine = await loadEngine(name);
const [a, b] = loadOperands({ kind: 'dense', file });
const input = engine.prepare ? engine.prepare(a, b) : [a, b];
globalThis.gc();
writeFileSync('/proc/self/clear_refs', '5');
const before = statusBytes('VmRSS');
const output = engine.run(operation, ...input, fillRule);
const peak = statusBytes('VmHWM');
process.stdout.write(`${JSON.stringify({ peak_bytes: Math.max(0, peak - before), rss_before_bytes: before, area: engine.area(output) })}\n`);
