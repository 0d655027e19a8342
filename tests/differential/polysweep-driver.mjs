// Runs polysweep on every case of a JSON file in one Node process, for tests/differential/run.py.
// Usage: node polysweep-driver.mjs cases.json results.json
// A case is { steps: [{ op, operands, fill }] }; an operand is Polygon or MultiPolygon coordinates, or { ref: k },
// the result of step k of the same case (chained operations). fill 'default' calls without options.
// Each step is also run through overlayFlat, whose result must be the nested result's coordinates exactly.
// Errors are caught per step and reported as strings.
import { readFileSync, writeFileSync } from 'node:fs';
import { union, intersection, difference, xor, overlayFlat } from 'polysweep';

const operations = { union, intersection, difference, xor };
const [, , inPath, outPath] = process.argv;
const cases = JSON.parse(readFileSync(inPath, 'utf8'));

const isNumber = (v) => typeof v === 'number';
const asMulti = (operand) => (operand.length && isNumber(operand[0][0][0]) ? [operand] : operand);

function toFlat(operand) {
  const coords = [];
  const ringOffsets = [0];
  const polygonOffsets = [0];
  for (const polygon of asMulti(operand)) {
    for (const ring of polygon) {
      for (const p of ring) coords.push(p[0], p[1]);
      ringOffsets.push(coords.length / 2);
    }
    polygonOffsets.push(ringOffsets.length - 1);
  }
  return {
    coords: new Float64Array(coords),
    ringOffsets: new Uint32Array(ringOffsets),
    polygonOffsets: new Uint32Array(polygonOffsets),
  };
}

function fromFlat({ coords, ringOffsets, polygonOffsets }) {
  const out = [];
  for (let p = 0; p + 1 < polygonOffsets.length; p++) {
    const polygon = [];
    for (let r = polygonOffsets[p]; r < polygonOffsets[p + 1]; r++) {
      const ring = [];
      for (let v = ringOffsets[r]; v < ringOffsets[r + 1]; v++) ring.push([coords[2 * v], coords[2 * v + 1]]);
      polygon.push(ring);
    }
    out.push(polygon);
  }
  return out;
}

const sameCoords = (a, b) => JSON.stringify(a) === JSON.stringify(b);

const started = performance.now();
const results = cases.map((c) => {
  const steps = [];
  for (const step of c.steps) {
    const operands = [];
    let missing = false;
    for (const o of step.operands) {
      if (o && !Array.isArray(o) && 'ref' in o) {
        const prior = steps[o.ref];
        if (!prior || !('result' in prior)) missing = true;
        else operands.push(prior.result);
      } else operands.push(o);
    }
    if (missing) {
      steps.push({ error: 'not run: an earlier step failed' });
      continue;
    }
    const out = {};
    try {
      const fn = operations[step.op];
      out.result = step.fill === 'default' ? fn(...operands) : fn(...operands, { fillRule: step.fill });
    } catch (e) {
      out.error = `${e && e.name}: ${e && e.message}`;
    }
    try {
      const opts = step.fill === 'default' ? undefined : { fillRule: step.fill };
      const flat = fromFlat(overlayFlat(step.op, operands.map(toFlat), opts));
      if ('result' in out && !sameCoords(flat, out.result)) out.flatMismatch = flat;
      if ('error' in out) out.flatResultDespiteError = true;
    } catch (e) {
      if ('result' in out) out.flatError = `${e && e.name}: ${e && e.message}`;
    }
    steps.push(out);
  }
  return { steps };
});
writeFileSync(outPath, JSON.stringify({ results, ms: performance.now() - started }));
