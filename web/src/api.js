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
// 2^28 vertices are 4 GiB of coordinates, all of wasm32's memory: no call with more can succeed.
const MAX_VERTICES = 2 ** 28;

/** `value` for an error message. Never throws, as JSON.stringify does on a BigInt or a cycle. */
function describe(value) {
  if (typeof value === 'string') return JSON.stringify(value);
  if (Array.isArray(value)) return 'an array';
  if (typeof value === 'object' && value !== null) return 'an object';
  if (typeof value === 'function') return 'a function';
  if (typeof value === 'bigint') return `${value}n`;
  return String(value);
}

/** Is `key` one of `table`'s own names (not an inherited one such as 'toString', nor a non-string)? */
const isKeyOf = (table, key) => typeof key === 'string' && Object.hasOwn(table, key);

function isOptions(arg) {
  return arg !== null && typeof arg === 'object' && !Array.isArray(arg) && !('type' in arg);
}

function fillRuleOf(options) {
  if (options !== undefined && options !== null && typeof options !== 'object') {
    throw new TypeError(`options must be an object such as {fillRule: 'nonzero'}, not ${describe(options)}`);
  }
  const rule = options?.fillRule ?? 'evenodd';
  if (!isKeyOf(FILL_RULES, rule)) {
    throw new TypeError(`options.fillRule must be 'evenodd' or 'nonzero', not ${describe(rule)}`);
  }
  return FILL_RULES[rule];
}

/**
 * Are these Polygon coordinates (rings of positions) rather than MultiPolygon ones (polygons of rings)? Three
 * levels down a Polygon has numbers and a MultiPolygon positions; the first of those found decides, so that an
 * empty ring or a bad first position neither flips the reading nor misplaces the error. (A bounded look: a huge
 * sparse array must not make this a long loop.)
 */
function isPolygonCoordinates(geom) {
  let budget = 64;
  for (let i = 0; i < geom.length && budget > 0; i++) {
    const outer = geom[i];
    if (!Array.isArray(outer)) continue;
    for (let j = 0; j < outer.length && budget > 0; j++) {
      const inner = outer[j];
      if (!Array.isArray(inner)) continue;
      for (let k = 0; k < inner.length && budget-- > 0; k++) {
        if (typeof inner[k] === 'number') return true;
        if (Array.isArray(inner[k])) return false;
      }
    }
  }
  return false;
}

/** The MultiPolygon coordinates of a Polygon or MultiPolygon geometry; `what` names it in errors. */
function geometryCoordinates(geom, what) {
  if (geom?.type !== 'Polygon' && geom?.type !== 'MultiPolygon') {
    const found = geom && typeof geom === 'object' ? `GeoJSON type ${describe(geom.type)}` : describe(geom);
    throw new TypeError(`${what}: expected a Polygon or MultiPolygon, not ${found}`);
  }
  if (!Array.isArray(geom.coordinates)) throw new TypeError(`${what}: the ${geom.type}'s coordinates must be an array`);
  return geom.type === 'Polygon' ? [geom.coordinates] : geom.coordinates;
}

/** The MultiPolygon coordinates of one operand, and the GeoJSON kind it came as. */
function coordinatesOf(geom, operand) {
  if (Array.isArray(geom)) {
    return { coordinates: isPolygonCoordinates(geom) ? [geom] : geom, kind: 'coordinates' };
  }
  if (geom && typeof geom === 'object') {
    if (geom.type === 'Feature') {
      const coordinates = geometryCoordinates(geom.geometry, `operand ${operand}: the feature's geometry`);
      return { coordinates, kind: 'feature', properties: geom.properties ?? null };
    }
    if (!('type' in geom) && 'fillRule' in geom) {
      throw new TypeError(`operand ${operand}: options such as {fillRule} go after the last operand`);
    }
    return { coordinates: geometryCoordinates(geom, `operand ${operand}`), kind: 'geometry' };
  }
  throw new TypeError(`operand ${operand}: expected GeoJSON Polygon or MultiPolygon coordinates, geometry or feature, not ${describe(geom)}`);
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
      if (vertices > MAX_VERTICES) {
        throw new RangeError(`operand ${o}, polygon ${p}, ring ${r}: more than ${MAX_VERTICES} vertices, more than wasm memory holds`);
      }
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

/** Offsets must run from 0 to `end` without decreasing. */
function checkOffsets(offsets, end, what, endName) {
  if (offsets.length === 0 || offsets[0] !== 0 || offsets[offsets.length - 1] !== end) {
    const found = offsets.length === 0 ? 'it is empty' : `it runs from ${offsets[0]} to ${offsets[offsets.length - 1]}`;
    throw new RangeError(`${what} must start at 0 and end at ${endName}, ${end}; ${found}`);
  }
  for (let k = 1; k < offsets.length; k++) {
    if (offsets[k] < offsets[k - 1]) throw new RangeError(`${what} decrease at ${k}: ${offsets[k - 1]}, then ${offsets[k]}`);
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
  if (!isKeyOf(OPERATIONS, operation)) {
    throw new TypeError(`operation must be one of ${Object.keys(OPERATIONS).join(', ')}, not ${describe(operation)}`);
  }
  const fillRule = fillRuleOf(options);
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
  const packed = run(OPERATIONS[operation], fillRule, concatenate(operands));
  const out = unpack(packed);
  return { coords: Float64Array.from(out.coords), ringOffsets: out.ringOffsets, polygonOffsets: out.polygonOffsets };
}
