// trace(): the steps of the Martínez–Rueda–Feito sweep on two operands, for pages that teach or debug the
// algorithm (the playground's explorer shows the same steps). See crates/polysweep/src/trace.rs.

import { OPERATIONS, describe, isKeyOf, optionsOf, readOperand, run, toFlat } from './geojson.js';
import { trace_flat } from './polysweep_wasm.js';

/**
 * The steps of the sweep of `operation` ('intersection', 'union', 'difference' or 'xor') on `subject` and
 * `clipping` (GeoJSON, as the Boolean operations take them), as the paper runs it (none of polysweep's shortcuts),
 * in order. Each step is a plain object with a `type`:
 * - `event`: an event taken from Q: `point`, `left` (whether it is its edge's left endpoint) and `edge`;
 * - `meeting`: possibleInter found neighbours `lower` and `upper` in S meet, `meeting` being 'crossing',
 *   'vertex-on-edge' or 'overlap', at `at`;
 * - `subdivision`: `edge` split at `at`;
 * - `flags`: the flags of Fig. 9 `edge` got on entering S: `inOut`, `insideOther`, `inResult`, and the winding
 *   numbers below it they were read from, `coverageBelow` (per operand);
 * - `selection`: `edge` left S, in the result or not (`inResult`), and why (`reason`: 'inside-other',
 *   'outside-other', 'same-transition', 'different-transition' or 'no-transition', the rows of Fig. 10);
 * - `status`: S after an event, `edges` bottom to top;
 * - `ring`: a ring of the result closed by the connection step: its `polygon`, `ring` (0 the exterior) and
 *   `points`.
 * An edge is `{left, right, operand, winding}`: its endpoints in sweep order, the operand of its input edge (0 the
 * subject, 1 the clipping operand) and its winding per operand (both non-zero where overlapping edges merged).
 * Under the structural reading (the default fill rule) the trace is of the even-odd sweep that reading starts with,
 * which for valid polygon sets is the whole operation. Errors are those of the Boolean operations. Every step is
 * kept: for teaching-sized input, not for big data.
 */
export function trace(operation, subject, clipping, options) {
  if (!isKeyOf(OPERATIONS, operation)) {
    throw new TypeError(`operation must be one of ${Object.keys(OPERATIONS).join(', ')}, not ${describe(operation)}`);
  }
  const { fillRule, skipNonPolygonal } = optionsOf(options);
  const flats = [subject, clipping].map((geom, o) => toFlat(readOperand(geom, o, skipNonPolygonal).parts));
  const json = run(OPERATIONS[operation], fillRule, flats, flats.map((flat) => flat.labels), trace_flat);
  return JSON.parse(json);
}
