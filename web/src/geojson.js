// The reading of GeoJSON operands into the flat form the wasm core takes, the call of the core, and the way back:
// the internals that api.js (the Boolean operations), lines.js (clip, split) and layers.js (overlayLayers, dissolve,
// clipLayer) share. Not part of the package's API.

import { overlay_flat } from './polysweep_wasm.js';

export const OPERATIONS = { intersection: 0, union: 1, difference: 2, xor: 3 };
// The codes the wasm side maps to the core's FillRule (crates/polysweep-wasm).
export const FILL_RULES = { evenodd: 0, nonzero: 1, positive: 2, negative: 3, structure: 4 };
// Valid GeoJSON geometries that hold no area: an error where an operand's polygons are read, unless
// {skipNonPolygonal: true} says to read them as nothing (a map app's collections mix them with polygons).
const NON_POLYGONAL = new Set(['Point', 'MultiPoint', 'LineString', 'MultiLineString']);
// GeometryCollections may hold GeometryCollections (RFC 7946 §3.1.8 advises against it); the bound keeps one that
// holds itself from running the reader out of stack.
const MAX_NESTING = 32;
// 2^28 vertices are 4 GiB of coordinates, all of wasm32's memory: no call with more can succeed.
export const MAX_VERTICES = 2 ** 28;

/** `value` for an error message. Never throws, as JSON.stringify does on a BigInt or a cycle. */
export function describe(value) {
  if (typeof value === 'string') return JSON.stringify(value);
  if (Array.isArray(value)) return 'an array';
  if (typeof value === 'object' && value !== null) return 'an object';
  if (typeof value === 'function') return 'a function';
  if (typeof value === 'bigint') return `${value}n`;
  return String(value);
}

/** What a value that should have been a GeoJSON object is, for an error message. */
export function describeGeoJSON(value) {
  return value && typeof value === 'object' && !Array.isArray(value) ? `GeoJSON type ${describe(value.type)}` : describe(value);
}

/** Is `key` one of `table`'s own names (not an inherited one such as 'toString', nor a non-string)? */
export const isKeyOf = (table, key) => typeof key === 'string' && Object.hasOwn(table, key);

export function isOptions(arg) {
  return arg !== null && typeof arg === 'object' && !Array.isArray(arg) && !('type' in arg);
}

/** The options object read and checked: `{fillRule}` as the core's code, and `{skipNonPolygonal}`. */
export function optionsOf(options) {
  if (options !== undefined && options !== null && typeof options !== 'object') {
    throw new TypeError(`options must be an object such as {fillRule: 'nonzero'}, not ${describe(options)}`);
  }
  const rule = options?.fillRule ?? 'structure';
  if (!isKeyOf(FILL_RULES, rule)) {
    const names = Object.keys(FILL_RULES).map((name) => `'${name}'`);
    throw new TypeError(`options.fillRule must be ${names.slice(0, -1).join(', ')} or ${names.at(-1)}, not ${describe(rule)}`);
  }
  const skipNonPolygonal = options?.skipNonPolygonal ?? false;
  if (typeof skipNonPolygonal !== 'boolean') {
    throw new TypeError(`options.skipNonPolygonal must be true or false, not ${describe(skipNonPolygonal)}`);
  }
  return { fillRule: FILL_RULES[rule], skipNonPolygonal };
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

/**
 * Adds the polygons of GeoJSON geometry `geom` to `parts` as `{coordinates, where}` (MultiPolygon coordinates, and
 * the operand and member they came from, for errors): a Polygon or MultiPolygon as itself, a GeometryCollection as
 * its members' polygons, a non-polygonal geometry as an error or, with `skip`, as nothing.
 */
function addGeometry(geom, where, parts, skip, depth) {
  const type = geom?.type;
  if (type === 'Polygon' || type === 'MultiPolygon') {
    if (!Array.isArray(geom.coordinates)) throw new TypeError(`${where}: the ${type}'s coordinates must be an array`);
    parts.push({ coordinates: type === 'Polygon' ? [geom.coordinates] : geom.coordinates, where });
  } else if (type === 'GeometryCollection') {
    const members = geom.geometries;
    if (!Array.isArray(members)) throw new TypeError(`${where}: the GeometryCollection's geometries must be an array`);
    if (depth === MAX_NESTING) throw new RangeError(`${where}: GeometryCollections nested more than ${MAX_NESTING} deep`);
    for (let i = 0; i < members.length; i++) addGeometry(members[i], `${where}, geometry ${i}`, parts, skip, depth + 1);
  } else if (NON_POLYGONAL.has(type)) {
    if (!skip) throw new TypeError(`${where}: a ${type} is not a polygon (pass {skipNonPolygonal: true} to skip it)`);
  } else {
    throw new TypeError(`${where}: expected a Polygon, MultiPolygon or GeometryCollection, not ${describeGeoJSON(geom)}`);
  }
}

/** Adds a Feature's polygons to `parts`. A feature whose geometry is null (an unlocated feature) adds none. */
export function addFeature(feature, where, parts, skip) {
  if (feature.geometry !== null) addGeometry(feature.geometry, where, parts, skip, 0);
}

/**
 * One operand read: `parts`, its polygons as MultiPolygon coordinates, one per geometry found (members of a
 * collection are named in errors: `operand 1, feature 3`); the GeoJSON `kind` it came as, which the result answers
 * in; and a Feature's properties.
 */
export function readOperand(geom, o, skip) {
  const where = `operand ${o}`;
  if (Array.isArray(geom)) {
    return { parts: [{ coordinates: isPolygonCoordinates(geom) ? [geom] : geom, where }], kind: 'coordinates' };
  }
  if (geom === null || typeof geom !== 'object') {
    throw new TypeError(`${where}: expected GeoJSON Polygon or MultiPolygon coordinates, a geometry, a Feature or a FeatureCollection, not ${describe(geom)}`);
  }
  const parts = [];
  const type = geom.type;
  if (type === 'Feature') {
    addFeature(geom, where, parts, skip);
    return { parts, kind: 'feature', properties: geom.properties ?? null };
  }
  if (type === 'FeatureCollection') {
    const features = geom.features;
    if (!Array.isArray(features)) throw new TypeError(`${where}: the FeatureCollection's features must be an array`);
    for (let i = 0; i < features.length; i++) {
      const feature = features[i];
      if (feature?.type !== 'Feature') throw new TypeError(`${where}, feature ${i}: expected a Feature, not ${describeGeoJSON(feature)}`);
      addFeature(feature, `${where}, feature ${i}`, parts, skip);
    }
    return { parts, kind: 'featureCollection' };
  }
  if (!('type' in geom) && ('fillRule' in geom || 'skipNonPolygonal' in geom)) {
    throw new TypeError(`${where}: options such as {fillRule} go after the last operand`);
  }
  addGeometry(geom, where, parts, skip, 0);
  return { parts, kind: 'geometry' };
}

/**
 * One operand's parts in the flat form, checking their shape on the way, and where each part's polygons start
 * (`labels`, to name the member in the core's errors). Plain loops: this runs over every vertex of the input, and
 * is most of the cost of a call outside the core.
 */
export function toFlat(parts) {
  let vertices = 0;
  let rings = 0;
  let polygons = 0;
  for (const { coordinates, where } of parts) {
    polygons += coordinates.length;
    for (let p = 0; p < coordinates.length; p++) {
      const polygon = coordinates[p];
      if (!Array.isArray(polygon)) throw new TypeError(`${where}, polygon ${p}: must be an array of rings`);
      for (let r = 0; r < polygon.length; r++) {
        const ring = polygon[r];
        if (!Array.isArray(ring)) throw new TypeError(`${where}, polygon ${p}, ring ${r}: must be an array of positions`);
        rings++;
        vertices += ring.length;
        if (vertices > MAX_VERTICES) {
          throw new RangeError(`${where}, polygon ${p}, ring ${r}: more than ${MAX_VERTICES} vertices, more than wasm memory holds`);
        }
      }
    }
  }
  const coords = new Float64Array(2 * vertices);
  const ringOffsets = new Uint32Array(rings + 1);
  const polygonOffsets = new Uint32Array(polygons + 1);
  const labels = [];
  let v = 0;
  let r = 0;
  let p = 0;
  for (const { coordinates, where } of parts) {
    labels.push({ where, first: p, end: p + coordinates.length });
    for (let pi = 0; pi < coordinates.length; pi++) {
      const polygon = coordinates[pi];
      for (let ri = 0; ri < polygon.length; ri++) {
        const ring = polygon[ri];
        for (let vi = 0; vi < ring.length; vi++) {
          // Positions may carry more ordinates (altitude, measure): only x and y are read.
          const position = ring[vi];
          if (!Array.isArray(position) || typeof position[0] !== 'number' || typeof position[1] !== 'number') {
            throw new TypeError(`${where}, polygon ${pi}, ring ${ri}, vertex ${vi}: a position must be an array of two (or more) numbers`);
          }
          coords[2 * v] = position[0];
          coords[2 * v + 1] = position[1];
          v++;
        }
        ringOffsets[++r] = v;
      }
      polygonOffsets[++p] = r;
    }
  }
  return { coords, ringOffsets, polygonOffsets, labels };
}

/** Operands in the flat form, concatenated, with the polygon offsets of each operand. */
export function concatenate(operands) {
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

/**
 * Calls the wasm core (`overlay_flat`, or another function of the same arguments: `trace_flat`); its errors (bad coordinates) become RangeErrors with the core's message. The core numbers
 * an operand's polygons straight through; `labels` (per operand, from toFlat) turn its "operand o, polygon p" (the
 * Location format of crates/polysweep/src/error.rs) into the member and polygon of the caller's input, such as
 * "operand 1, feature 3, polygon 0".
 */
export function run(operation, fillRule, operands, labels, core = overlay_flat) {
  const flat = concatenate(operands);
  try {
    return core(operation, fillRule, flat.coords, flat.ringOffsets, flat.polygonOffsets, flat.operandOffsets);
  } catch (error) {
    let message = error?.message ?? String(error);
    const at = /^operand (\d+), polygon (\d+), /.exec(message);
    if (at && labels) {
      const p = Number(at[2]);
      const label = labels[Number(at[1])]?.find(({ first, end }) => first <= p && p < end);
      if (label) message = `${label.where}, polygon ${p - label.first}, ${message.slice(at[0].length)}`;
    }
    throw new RangeError(message);
  }
}

/** Offsets must run from 0 to `end` without decreasing. */
export function checkOffsets(offsets, end, what, endName) {
  if (offsets.length === 0 || offsets[0] !== 0 || offsets[offsets.length - 1] !== end) {
    const found = offsets.length === 0 ? 'it is empty' : `it runs from ${offsets[0]} to ${offsets[offsets.length - 1]}`;
    throw new RangeError(`${what} must start at 0 and end at ${endName}, ${end}; ${found}`);
  }
  for (let k = 1; k < offsets.length; k++) {
    if (offsets[k] < offsets[k - 1]) throw new RangeError(`${what} decrease at ${k}: ${offsets[k - 1]}, then ${offsets[k]}`);
  }
}

/** Splits the packed result of the core into the flat form (views, no copies). */
export function unpack(packed) {
  const polygons = packed[0];
  const rings = packed[1];
  const polygonOffsets = Uint32Array.from(packed.subarray(2, 3 + polygons));
  const ringStart = 3 + polygons;
  const ringOffsets = Uint32Array.from(packed.subarray(ringStart, ringStart + rings + 1));
  const coords = packed.subarray(ringStart + rings + 1);
  return { coords, ringOffsets, polygonOffsets };
}

export function toCoordinates({ coords, ringOffsets, polygonOffsets }) {
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

/** A choice among `names` in `options[key]`, as its index, `fallback` when not given. */
export function choice(options, key, names, fallback) {
  const value = options?.[key] ?? fallback;
  const index = names.indexOf(value);
  if (index < 0) {
    throw new TypeError(`options.${key} must be ${names.slice(0, -1).map((n) => `'${n}'`).join(', ')} or '${names.at(-1)}', not ${describe(value)}`);
  }
  return index;
}

/**
 * The faces of a layer overlay's packed result (crates/polysweep-wasm, overlay_layers_flat): per face the indices of
 * the covering features of each layer (`a`, `b`) and how many of the result's polygons are the face's, then the
 * polygons of all faces in the flat form.
 */
export function readFaces(packed) {
  let k = 1;
  const faces = [];
  for (let face = 0; face < packed[0]; face++) {
    const lists = [];
    for (let side = 0; side < 2; side++) {
      const n = packed[k++];
      lists.push(Array.from(packed.subarray(k, k + n)));
      k += n;
    }
    faces.push({ a: lists[0], b: lists[1], polygons: packed[k++] });
  }
  return { faces, flat: unpack(packed.subarray(k)) };
}

/** The result's coordinates in the kind of the first operand (see pkg/README.md, "Input and output contract"). */
export function inKind(first, coordinates) {
  const multiPolygon = { type: 'MultiPolygon', coordinates };
  switch (first.kind) {
    case 'feature':
      return { type: 'Feature', properties: first.properties, geometry: multiPolygon };
    case 'featureCollection':
      // One feature holding the whole result: the features' areas are merged, so no one feature's properties fit.
      return { type: 'FeatureCollection', features: [{ type: 'Feature', properties: null, geometry: multiPolygon }] };
    case 'geometry':
      return multiPolygon;
    default:
      return coordinates;
  }
}
