// polysweep: Boolean operations on polygons (intersection, union, difference, xor) by the Martínez–Rueda–Feito
// plane sweep with exact predicates, compiled to WebAssembly.
//
// This file is the package's API: GeoJSON in and out, polygon-clipping's calling convention, and the flat
// typed-array form. The entry files (polysweep.js for browsers and bundlers, polysweep.node.js for Node) load the
// wasm module once, by top-level await, before anything here runs; after that every call is synchronous and
// nothing needs freeing.

import { overlay_flat } from './polysweep_wasm.js';

const OPERATIONS = { intersection: 0, union: 1, difference: 2, xor: 3 };
const FILL_RULES = { evenodd: 0, nonzero: 1 };

function isOptions(arg) {
  return arg !== null && typeof arg === 'object' && !Array.isArray(arg) && !('type' in arg);
}

function fillRuleOf(options) {
  const rule = options?.fillRule ?? 'evenodd';
  if (!(rule in FILL_RULES)) {
    throw new TypeError(`options.fillRule must be 'evenodd' or 'nonzero', not ${JSON.stringify(rule)}`);
  }
  return FILL_RULES[rule];
}

/** The MultiPolygon coordinates of one operand, and the GeoJSON kind it came as. */
function coordinatesOf(geom, operand) {
  if (Array.isArray(geom)) {
    // Polygon coordinates are rings of positions; MultiPolygon coordinates are polygons of rings.
    const polygonDepth = Array.isArray(geom[0]?.[0]) && typeof geom[0][0][0] === 'number';
    return { coordinates: polygonDepth ? [geom] : geom, kind: 'coordinates' };
  }
  if (geom && typeof geom === 'object') {
    if (geom.type === 'Feature') {
      const inner = coordinatesOf(geom.geometry, operand);
      return { ...inner, kind: 'feature', properties: geom.properties ?? null };
    }
    if (geom.type === 'Polygon') return { coordinates: [geom.coordinates], kind: 'geometry' };
    if (geom.type === 'MultiPolygon') return { coordinates: geom.coordinates, kind: 'geometry' };
    throw new TypeError(`operand ${operand}: unsupported GeoJSON type ${JSON.stringify(geom.type)}; expected Polygon, MultiPolygon or a Feature of one`);
  }
  throw new TypeError(`operand ${operand}: expected GeoJSON Polygon or MultiPolygon coordinates, geometry or feature`);
}

/** One operand's MultiPolygon coordinates in the flat form, checking their shape on the way. (Plain loops: this
 * runs over every vertex of the input, and is most of the cost of a call outside the core.) */
function toFlat(multiPolygon, o) {
  if (!Array.isArray(multiPolygon)) throw new TypeError(`operand ${o}: coordinates must be an array of polygons`);
  let vertices = 0;
  let rings = 0;
  for (let p = 0; p < multiPolygon.length; p++) {
    const polygon = multiPolygon[p];
    if (!Array.isArray(polygon)) throw new TypeError(`operand ${o}, polygon ${p}: must be an array of rings`);
    for (let r = 0; r < polygon.length; r++) {
      const ring = polygon[r];
      if (!Array.isArray(ring)) throw new TypeError(`operand ${o}, polygon ${p}, ring ${r}: must be an array of positions`);
      rings++;
      vertices += ring.length;
    }
  }
  const coords = new Float64Array(2 * vertices);
  const ringOffsets = new Uint32Array(rings + 1);
  const polygonOffsets = new Uint32Array(multiPolygon.length + 1);
  let v = 0;
  let r = 0;
  for (let p = 0; p < multiPolygon.length; p++) {
    const polygon = multiPolygon[p];
    for (let ri = 0; ri < polygon.length; ri++) {
      const ring = polygon[ri];
      for (let vi = 0; vi < ring.length; vi++) {
        const position = ring[vi];
        if (!Array.isArray(position) || typeof position[0] !== 'number' || typeof position[1] !== 'number') {
          throw new TypeError(`operand ${o}, polygon ${p}, ring ${ri}, vertex ${vi}: a position must be an array of two numbers`);
        }
        coords[2 * v] = position[0];
        coords[2 * v + 1] = position[1];
        v++;
      }
      ringOffsets[++r] = v;
    }
    polygonOffsets[p + 1] = r;
  }
  return { coords, ringOffsets, polygonOffsets };
}

/** Operands in the flat form, concatenated, with the polygon offsets of each operand. */
function concatenate(operands) {
  let vertices = 0;
  let rings = 0;
  let polygons = 0;
  for (const o of operands) {
    vertices += o.coords.length / 2;
    rings += o.ringOffsets.length - 1;
    polygons += o.polygonOffsets.length - 1;
  }
  const coords = new Float64Array(2 * vertices);
  const ringOffsets = new Uint32Array(rings + 1);
  const polygonOffsets = new Uint32Array(polygons + 1);
  const operandOffsets = new Uint32Array(operands.length + 1);
  let v = 0;
  let r = 0;
  let p = 0;
  operands.forEach((o, i) => {
    coords.set(o.coords, 2 * v);
    for (let k = 1; k < o.ringOffsets.length; k++) ringOffsets[r + k] = v + o.ringOffsets[k];
    for (let k = 1; k < o.polygonOffsets.length; k++) polygonOffsets[p + k] = r + o.polygonOffsets[k];
    v += o.coords.length / 2;
    r += o.ringOffsets.length - 1;
    p += o.polygonOffsets.length - 1;
    operandOffsets[i + 1] = p;
  });
  return { coords, ringOffsets, polygonOffsets, operandOffsets };
}

/** Calls the wasm core; its errors (bad coordinates) become RangeErrors with the core's message. */
function run(operation, fillRule, flat) {
  try {
    return overlay_flat(operation, fillRule, flat.coords, flat.ringOffsets, flat.polygonOffsets, flat.operandOffsets);
  } catch (error) {
    throw new RangeError(error?.message ?? String(error));
  }
}

/** Splits the packed result of the core into the flat form (views, no copies). */
function unpack(packed) {
  const polygons = packed[0];
  const rings = packed[1];
  const polygonOffsets = Uint32Array.from(packed.subarray(2, 3 + polygons));
  const ringStart = 3 + polygons;
  const ringOffsets = Uint32Array.from(packed.subarray(ringStart, ringStart + rings + 1));
  const coords = packed.subarray(ringStart + rings + 1);
  return { coords, ringOffsets, polygonOffsets };
}

function toCoordinates({ coords, ringOffsets, polygonOffsets }) {
  const out = new Array(polygonOffsets.length - 1);
  for (let p = 0; p < out.length; p++) {
    const first = polygonOffsets[p];
    const polygon = new Array(polygonOffsets[p + 1] - first);
    for (let r = 0; r < polygon.length; r++) {
      const start = ringOffsets[first + r];
      const ring = new Array(ringOffsets[first + r + 1] - start);
      for (let v = 0; v < ring.length; v++) ring[v] = [coords[2 * (start + v)], coords[2 * (start + v) + 1]];
      polygon[r] = ring;
    }
    out[p] = polygon;
  }
  return out;
}

function operate(name, args) {
  const options = args.length > 1 && isOptions(args[args.length - 1]) ? args.pop() : undefined;
  const fillRule = fillRuleOf(options);
  if (args.length === 0) throw new TypeError(`${name}: at least one operand is required`);
  const inputs = args.map(coordinatesOf);
  const packed = run(OPERATIONS[name], fillRule, concatenate(inputs.map((input, o) => toFlat(input.coordinates, o))));
  const coordinates = toCoordinates(unpack(packed));
  const first = inputs[0];
  if (first.kind === 'feature') {
    return { type: 'Feature', properties: first.properties, geometry: { type: 'MultiPolygon', coordinates } };
  }
  if (first.kind === 'geometry') return { type: 'MultiPolygon', coordinates };
  return coordinates;
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
  if (!(operation in OPERATIONS)) {
    throw new TypeError(`operation must be one of ${Object.keys(OPERATIONS).join(', ')}, not ${JSON.stringify(operation)}`);
  }
  const fillRule = fillRuleOf(options);
  operands.forEach((o, i) => {
    if (!(o?.coords instanceof Float64Array) || !(o.ringOffsets instanceof Uint32Array) || !(o.polygonOffsets instanceof Uint32Array)) {
      throw new TypeError(`operand ${i}: expected {coords: Float64Array, ringOffsets: Uint32Array, polygonOffsets: Uint32Array}`);
    }
  });
  const packed = run(OPERATIONS[operation], fillRule, concatenate(operands));
  const out = unpack(packed);
  return { coords: Float64Array.from(out.coords), ringOffsets: out.ringOffsets, polygonOffsets: out.polygonOffsets };
}
