// polysweep: Boolean operations on polygons (intersection, union, difference, xor) by the Martínez–Rueda–Feito
// plane sweep with exact predicates, compiled to WebAssembly.
//
// This file is the package's API: GeoJSON in and out, polygon-clipping's calling convention, and the flat
// typed-array form. The entry files (polysweep.js for browsers and bundlers, polysweep.node.js for Node) load the
// wasm module once, by top-level await, before anything here runs; after that every call is synchronous and
// nothing needs freeing.

import { OPERATIONS, checkOffsets, describe, inKind, isKeyOf, isOptions, optionsOf, readOperand, run, toCoordinates, toFlat, unpack } from './geojson.js';

function operate(name, args) {
  const options = args.length > 1 && isOptions(args[args.length - 1]) ? args.pop() : undefined;
  const { fillRule, skipNonPolygonal } = optionsOf(options);
  if (args.length === 0) throw new TypeError(`${name}: at least one operand is required`);
  const inputs = args.map((geom, o) => readOperand(geom, o, skipNonPolygonal));
  const flats = inputs.map((input) => toFlat(input.parts));
  const packed = run(OPERATIONS[name], fillRule, flats, flats.map((flat) => flat.labels));
  return inKind(inputs[0], toCoordinates(unpack(packed)));
}

/** The union of all operands. */
export function union(geom, ...geoms) {
  return operate('union', [geom, ...geoms]);
}

/** The intersection of all operands. */
export function intersection(geom, ...geoms) {
  return operate('intersection', [geom, ...geoms]);
}

/** `subject` minus every clip. */
export function difference(subject, ...clips) {
  return operate('difference', [subject, ...clips]);
}

/** The points inside an odd number of operands. */
export function xor(geom, ...geoms) {
  return operate('xor', [geom, ...geoms]);
}

/**
 * The flat form, for big data: each operand `{coords, ringOffsets, polygonOffsets}` (x, y pairs; vertex offsets of
 * each ring; ring offsets of each polygon, exterior first), and the result in the same form.
 */
export function overlayFlat(operation, operands, options) {
  if (!isKeyOf(OPERATIONS, operation)) {
    throw new TypeError(`operation must be one of ${Object.keys(OPERATIONS).join(', ')}, not ${describe(operation)}`);
  }
  const { fillRule } = optionsOf(options);
  if (!Array.isArray(operands)) {
    throw new TypeError(`operands must be an array of {coords, ringOffsets, polygonOffsets}, not ${describe(operands)}`);
  }
  operands.forEach((o, i) => {
    if (!(o?.coords instanceof Float64Array) || !(o.ringOffsets instanceof Uint32Array) || !(o.polygonOffsets instanceof Uint32Array)) {
      throw new TypeError(`operand ${i}: expected {coords: Float64Array, ringOffsets: Uint32Array, polygonOffsets: Uint32Array}`);
    }
    // The operands are concatenated, so offsets that do not start at 0 and end at the count would silently take
    // in the neighbouring operand's rings or vertices.
    if (o.coords.length % 2 !== 0) throw new RangeError(`operand ${i}: coords must hold x, y pairs, not ${o.coords.length} numbers`);
    checkOffsets(o.ringOffsets, o.coords.length / 2, `operand ${i}: ringOffsets`, 'the vertex count (coords.length / 2)');
    checkOffsets(o.polygonOffsets, o.ringOffsets.length - 1, `operand ${i}: polygonOffsets`, 'the ring count (ringOffsets.length - 1)');
  });
  const packed = run(OPERATIONS[operation], fillRule, operands);
  const out = unpack(packed);
  return { coords: Float64Array.from(out.coords), ringOffsets: out.ringOffsets, polygonOffsets: out.polygonOffsets };
}

export { clip, split } from './lines.js';
export { clipLayer, dissolve, overlayLayers } from './layers.js';
export { splitAntimeridian } from './antimeridian.js';
export { trace } from './trace.js';
