// polysweep: Boolean operations on polygons (intersection, union, difference, xor) by the Martínez–Rueda–Feito
// plane sweep with exact predicates, compiled to WebAssembly.
//
// This file is the package's API: GeoJSON in and out, polygon-clipping's calling convention, and the flat
// typed-array form. The entry files (polysweep.js for browsers and bundlers, polysweep.node.js for Node) load the
// wasm module once, by top-level await, before anything here runs; after that every call is synchronous and
// nothing needs freeing.

import { clip_flat, overlay_flat, overlay_layers_flat, split_flat } from './polysweep_wasm.js';

const OPERATIONS = { intersection: 0, union: 1, difference: 2, xor: 3 };
// The codes the wasm side maps to the core's FillRule (crates/polysweep-wasm).
const FILL_RULES = { evenodd: 0, nonzero: 1, positive: 2, negative: 3, structure: 4 };
// Valid GeoJSON geometries that hold no area: an error where an operand's polygons are read, unless
// {skipNonPolygonal: true} says to read them as nothing (a map app's collections mix them with polygons).
const NON_POLYGONAL = new Set(['Point', 'MultiPoint', 'LineString', 'MultiLineString']);
// GeometryCollections may hold GeometryCollections (RFC 7946 §3.1.8 advises against it); the bound keeps one that
// holds itself from running the reader out of stack.
const MAX_NESTING = 32;
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

/** What a value that should have been a GeoJSON object is, for an error message. */
function describeGeoJSON(value) {
  return value && typeof value === 'object' && !Array.isArray(value) ? `GeoJSON type ${describe(value.type)}` : describe(value);
}

/** Is `key` one of `table`'s own names (not an inherited one such as 'toString', nor a non-string)? */
const isKeyOf = (table, key) => typeof key === 'string' && Object.hasOwn(table, key);

function isOptions(arg) {
  return arg !== null && typeof arg === 'object' && !Array.isArray(arg) && !('type' in arg);
}

/** The options object read and checked: `{fillRule}` as the core's code, and `{skipNonPolygonal}`. */
function optionsOf(options) {
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
function addFeature(feature, where, parts, skip) {
  if (feature.geometry !== null) addGeometry(feature.geometry, where, parts, skip, 0);
}

/**
 * One operand read: `parts`, its polygons as MultiPolygon coordinates, one per geometry found (members of a
 * collection are named in errors: `operand 1, feature 3`); the GeoJSON `kind` it came as, which the result answers
 * in; and a Feature's properties.
 */
function readOperand(geom, o, skip) {
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
function toFlat(parts) {
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

/**
 * Calls the wasm core; its errors (bad coordinates) become RangeErrors with the core's message. The core numbers
 * an operand's polygons straight through; `labels` (per operand, from toFlat) turn its "operand o, polygon p" (the
 * Location format of crates/polysweep/src/error.rs) into the member and polygon of the caller's input, such as
 * "operand 1, feature 3, polygon 0".
 */
function run(operation, fillRule, operands, labels) {
  const flat = concatenate(operands);
  try {
    return overlay_flat(operation, fillRule, flat.coords, flat.ringOffsets, flat.polygonOffsets, flat.operandOffsets);
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

/** The result's coordinates in the kind of the first operand (see pkg/README.md, "Input and output contract"). */
function inKind(first, coordinates) {
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

// --- Lines and layers: clip, split, overlayLayers, dissolve ---

const LAYER_MODES = { intersection: 0, union: 1, identity: 2, difference: 3, xor: 4 };

/** Are these LineString coordinates (positions) rather than MultiLineString ones (lines of positions)? */
function isLineCoordinates(geom) {
  const first = geom.find((item) => Array.isArray(item));
  return first === undefined || typeof first[0] === 'number';
}

/** Adds a LineString's or MultiLineString's lines to `lines` as `{coordinates, where, owner}`. */
function addLines(geom, where, owner, lines) {
  const type = geom?.type;
  if (type === 'LineString' || type === 'MultiLineString') {
    if (!Array.isArray(geom.coordinates)) throw new TypeError(`${where}: the ${type}'s coordinates must be an array`);
    const list = type === 'LineString' ? [geom.coordinates] : geom.coordinates;
    list.forEach((coordinates, i) => lines.push({ coordinates, where: type === 'LineString' ? where : `${where}, line ${i}`, owner }));
  } else {
    throw new TypeError(`${where}: expected a LineString or MultiLineString, not ${describeGeoJSON(geom)}`);
  }
}

/**
 * The lines of an operand of clip or split: `lines` ({coordinates, where, owner}), the GeoJSON `kind` it came as,
 * and `owners`, the properties of the feature each line's `owner` indexes (one, null, for a bare geometry).
 */
function readLines(geom, name) {
  const lines = [];
  if (Array.isArray(geom)) {
    const list = isLineCoordinates(geom) ? [geom] : geom;
    list.forEach((coordinates, i) => lines.push({ coordinates, where: `${name}, line ${i}`, owner: 0 }));
    return { lines, kind: 'coordinates', owners: [null] };
  }
  const type = geom?.type;
  if (type === 'Feature') {
    if (geom.geometry !== null) addLines(geom.geometry, name, 0, lines);
    return { lines, kind: 'feature', owners: [geom.properties ?? null] };
  }
  if (type === 'FeatureCollection') {
    if (!Array.isArray(geom.features)) throw new TypeError(`${name}: the FeatureCollection's features must be an array`);
    const owners = geom.features.map((feature, i) => {
      if (feature?.type !== 'Feature') throw new TypeError(`${name}, feature ${i}: expected a Feature, not ${describeGeoJSON(feature)}`);
      if (feature.geometry !== null) addLines(feature.geometry, `${name}, feature ${i}`, i, lines);
      return feature.properties ?? null;
    });
    return { lines, kind: 'featureCollection', owners };
  }
  if (geom === null || typeof geom !== 'object') {
    throw new TypeError(`${name}: expected LineString or MultiLineString coordinates, a geometry, a Feature or a FeatureCollection, not ${describe(geom)}`);
  }
  addLines(geom, name, 0, lines);
  return { lines, kind: 'geometry', owners: [null] };
}

/** Lines in the flat form: x, y pairs and each line's vertex offsets. */
function linesToFlat(lines) {
  let vertices = 0;
  for (const { coordinates, where } of lines) {
    if (!Array.isArray(coordinates)) throw new TypeError(`${where}: must be an array of positions`);
    vertices += coordinates.length;
    if (vertices > MAX_VERTICES) throw new RangeError(`${where}: more than ${MAX_VERTICES} vertices, more than wasm memory holds`);
  }
  const coords = new Float64Array(2 * vertices);
  const lineOffsets = new Uint32Array(lines.length + 1);
  let v = 0;
  lines.forEach(({ coordinates, where }, l) => {
    coordinates.forEach((position, i) => {
      if (!Array.isArray(position) || typeof position[0] !== 'number' || typeof position[1] !== 'number') {
        throw new TypeError(`${where}, vertex ${i}: a position must be an array of two (or more) numbers`);
      }
      coords[2 * v] = position[0];
      coords[2 * v + 1] = position[1];
      v++;
    });
    lineOffsets[l + 1] = v;
  });
  return { coords, lineOffsets };
}

/**
 * Calls a wasm function of lines and a polygon set, whose errors name the polygon set as the core's operand 0 and a
 * line as its operand 1 (polygon = the line, ring 0): they become RangeErrors naming the caller's feature and line.
 */
function runWithLines(call, polygonLabels, lines) {
  try {
    return call();
  } catch (error) {
    let message = error?.message ?? String(error);
    const onPolygon = /^operand 0, polygon (\d+), /.exec(message);
    const onLine = /^operand 1, polygon (\d+), ring 0, /.exec(message);
    if (onPolygon) {
      const p = Number(onPolygon[1]);
      const label = polygonLabels.find(({ first, end }) => first <= p && p < end);
      if (label) message = `${label.where}, polygon ${p - label.first}, ${message.slice(onPolygon[0].length)}`;
    } else if (onLine && lines[Number(onLine[1])]) {
      message = `${lines[Number(onLine[1])].where}, ${message.slice(onLine[0].length)}`;
    }
    throw new RangeError(message);
  }
}

/** The polygon-set operand of clip or split, read and flattened, named `name` in errors. */
function readPolygonSet(geom, name, skipNonPolygonal) {
  const input = readOperand(geom, 0, skipNonPolygonal);
  for (const part of input.parts) part.where = part.where.replace(/^operand 0/, name);
  return { input, flat: toFlat(input.parts) };
}

/** A choice among `names` in `options[key]`, as its index, `fallback` when not given. */
function choice(options, key, names, fallback) {
  const value = options?.[key] ?? fallback;
  const index = names.indexOf(value);
  if (index < 0) {
    throw new TypeError(`options.${key} must be ${names.slice(0, -1).map((n) => `'${n}'`).join(', ')} or '${names.at(-1)}', not ${describe(value)}`);
  }
  return index;
}

/**
 * The parts of the lines inside (or outside) a polygon set. `lines`: LineString or MultiLineString coordinates, a
 * geometry, a Feature or a FeatureCollection of them; `polygon`: any operand of the Boolean operations. Options:
 * `keep` ('inside' or 'outside'), `boundary` (parts along the polygon set's boundary count as 'inside', the
 * default, as GEOS's intersection and difference have it, or 'outside'), `fillRule`, `skipNonPolygonal`. The result
 * comes in the kind of `lines`: MultiLineString coordinates, a MultiLineString, a Feature with its properties, or
 * a FeatureCollection with a feature per input feature that keeps any part.
 */
export function clip(lines, polygon, options) {
  const { fillRule, skipNonPolygonal } = optionsOf(options);
  const keep = choice(options, 'keep', ['inside', 'outside'], 'inside');
  const boundary = choice(options, 'boundary', ['inside', 'outside'], 'inside');
  const read = readLines(lines, 'operand 0');
  const flatLines = linesToFlat(read.lines);
  const { flat } = readPolygonSet(polygon, 'operand 1', skipNonPolygonal);
  const packed = runWithLines(
    () => clip_flat(keep, boundary, fillRule, flatLines.coords, flatLines.lineOffsets, flat.coords, flat.ringOffsets, flat.polygonOffsets),
    flat.labels,
    read.lines,
  );
  // Unpacked: per line its parts, each a list of positions.
  const lineCount = packed[0];
  const partStart = 1;
  const vertexStart = partStart + lineCount + 1;
  const partCount = packed[partStart + lineCount];
  const xy = vertexStart + partCount + 1;
  const byOwner = read.owners.map(() => []);
  for (let l = 0; l < lineCount; l++) {
    for (let part = packed[partStart + l]; part < packed[partStart + l + 1]; part++) {
      const positions = [];
      for (let v = packed[vertexStart + part]; v < packed[vertexStart + part + 1]; v++) {
        positions.push([packed[xy + 2 * v], packed[xy + 2 * v + 1]]);
      }
      byOwner[read.lines[l].owner].push(positions);
    }
  }
  const geometry = (coordinates) => ({ type: 'MultiLineString', coordinates });
  switch (read.kind) {
    case 'coordinates':
      return byOwner[0];
    case 'geometry':
      return geometry(byOwner[0]);
    case 'feature':
      return { type: 'Feature', properties: read.owners[0], geometry: geometry(byOwner[0]) };
    default:
      return {
        type: 'FeatureCollection',
        features: byOwner.flatMap((parts, i) => (parts.length > 0 ? [{ type: 'Feature', properties: read.owners[i], geometry: geometry(parts) }] : [])),
      };
  }
}

/**
 * A polygon set cut along lines into pieces. `polygon`: any operand (a FeatureCollection is cut feature by
 * feature, each piece keeping its feature's properties); `lines`: as for clip. Only the lines' parts that cross a
 * polygon from boundary to boundary cut it; dangling ends and parts along the boundary cut nothing. The result: an
 * array of Polygon coordinates for coordinates, otherwise a FeatureCollection of Polygon features.
 */
export function split(polygon, lines, options) {
  const { fillRule, skipNonPolygonal } = optionsOf(options);
  const read = readLines(lines, 'operand 1');
  const flatLines = linesToFlat(read.lines);
  const cut = (geom, name) => {
    const { flat } = readPolygonSet(geom, name, skipNonPolygonal);
    const packed = runWithLines(
      () => split_flat(fillRule, flat.coords, flat.ringOffsets, flat.polygonOffsets, flatLines.coords, flatLines.lineOffsets),
      flat.labels,
      read.lines,
    );
    return toCoordinates(unpack(packed));
  };
  if (Array.isArray(polygon)) return cut(polygon, 'operand 0');
  const pieces = (coordinates, properties) => coordinates.map((c) => ({ type: 'Feature', properties, geometry: { type: 'Polygon', coordinates: c } }));
  if (polygon?.type === 'FeatureCollection' && Array.isArray(polygon.features)) {
    return {
      type: 'FeatureCollection',
      features: polygon.features.flatMap((feature, i) => {
        if (feature?.type !== 'Feature') throw new TypeError(`operand 0, feature ${i}: expected a Feature, not ${describeGeoJSON(feature)}`);
        return pieces(cut(feature, `operand 0, feature ${i}`), feature.properties ?? null);
      }),
    };
  }
  const properties = polygon?.type === 'Feature' ? (polygon.properties ?? null) : null;
  return { type: 'FeatureCollection', features: pieces(cut(polygon, 'operand 0'), properties) };
}

/** The features of a layer (a FeatureCollection or an array of Features), each as its polygons' parts. */
function readLayer(layer, name, skip) {
  const features = Array.isArray(layer) ? layer : layer?.type === 'FeatureCollection' ? layer.features : undefined;
  if (!Array.isArray(features)) throw new TypeError(`${name}: expected a FeatureCollection or an array of Features, not ${describeGeoJSON(layer)}`);
  return features.map((feature, i) => {
    const where = `${name}, feature ${i}`;
    if (feature?.type !== 'Feature') throw new TypeError(`${where}: expected a Feature, not ${describeGeoJSON(feature)}`);
    const parts = [];
    addFeature(feature, where, parts, skip);
    return { parts, properties: feature.properties ?? null };
  });
}

/**
 * The overlay of two layers (FeatureCollections, or arrays of Features, of polygons) in one sweep: the faces of
 * their arrangement that `options.mode` keeps ('intersection', the default: covered by a feature of each layer;
 * 'union'; 'identity': every face of layer A; 'difference': of A and no feature of B; 'xor'), as a FeatureCollection
 * of MultiPolygon features, one per set of covering features, whose properties are `{a, b, aIndex, bIndex,
 * aIndices, bIndices}`: the properties and index of the covering feature of each layer (the first, where several
 * of one layer overlap; null where none) and the indices of all. `options.properties(a, b)`, given the arrays of
 * covering features' properties of each layer, makes the properties instead.
 */
export function overlayLayers(layerA, layerB, options) {
  const { fillRule, skipNonPolygonal } = optionsOf(options);
  const mode = choice(options, 'mode', Object.keys(LAYER_MODES), 'intersection');
  const makeProperties = options?.properties;
  if (makeProperties !== undefined && typeof makeProperties !== 'function') {
    throw new TypeError(`options.properties must be a function (a, b) => properties, not ${describe(makeProperties)}`);
  }
  const layers = [readLayer(layerA, 'layer A', skipNonPolygonal), readLayer(layerB, 'layer B', skipNonPolygonal)];
  // All features of both layers, in one flat operand list: the core numbers a layer's polygons straight through.
  const features = layers.flat();
  const flats = features.map((feature) => toFlat(feature.parts));
  const flat = concatenate(flats);
  const layerOffsets = new Uint32Array([0, layers[0].length, features.length]);
  const featureOffsets = flat.operandOffsets;
  let packed;
  try {
    packed = overlay_layers_flat(mode, fillRule, flat.coords, flat.ringOffsets, flat.polygonOffsets, featureOffsets, layerOffsets);
  } catch (error) {
    let message = error?.message ?? String(error);
    const at = /^operand (\d+), polygon (\d+), /.exec(message);
    if (at) {
      // The polygon's index through the layer, back to its feature.
      const first = Number(at[1]) === 0 ? 0 : layers[0].length;
      const p = Number(at[2]) + featureOffsets[first];
      let f = first;
      while (featureOffsets[f + 1] <= p) f++;
      message = `${features[f].parts[0]?.where ?? `feature ${f}`}, polygon ${p - featureOffsets[f]}, ${message.slice(at[0].length)}`;
    }
    throw new RangeError(message);
  }
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
  const all = toCoordinates(unpack(packed.subarray(k)));
  let p = 0;
  return {
    type: 'FeatureCollection',
    features: faces.map(({ a, b, polygons }) => {
      const coordinates = all.slice(p, (p += polygons));
      const [aProps, bProps] = [a.map((i) => layers[0][i].properties), b.map((i) => layers[1][i].properties)];
      const properties = makeProperties
        ? makeProperties(aProps, bProps)
        : { a: aProps[0] ?? null, b: bProps[0] ?? null, aIndex: a[0] ?? null, bIndex: b[0] ?? null, aIndices: a, bIndices: b };
      return { type: 'Feature', properties, geometry: { type: 'MultiPolygon', coordinates } };
    }),
  };
}

/**
 * Features merged by a key: `key` a property name, a function (feature, index) => value, or undefined (all into
 * one). One MultiPolygon feature per distinct value, in the order values first appear, with properties
 * `{[key]: value}` (`{key: value}` for a function): the union of that value's features, so neighbours that share
 * an edge or overlap become one polygon. Features whose union is empty are left out.
 */
export function dissolve(featureCollection, key, options) {
  const features = Array.isArray(featureCollection) ? featureCollection : featureCollection?.features;
  if (!Array.isArray(features)) throw new TypeError(`operand 0: expected a FeatureCollection or an array of Features, not ${describeGeoJSON(featureCollection)}`);
  if (key !== undefined && typeof key !== 'string' && typeof key !== 'function') {
    throw new TypeError(`key must be a property name, a function (feature, index) => value, or undefined, not ${describe(key)}`);
  }
  const valueOf = typeof key === 'function' ? key : (feature) => (key === undefined ? null : feature?.properties?.[key]);
  const groups = new Map();
  features.forEach((feature, i) => {
    if (feature?.type !== 'Feature') throw new TypeError(`operand 0, feature ${i}: expected a Feature, not ${describeGeoJSON(feature)}`);
    const value = valueOf(feature, i);
    if (!groups.has(value)) groups.set(value, []);
    groups.get(value).push({ feature, i });
  });
  const { fillRule, skipNonPolygonal } = optionsOf(options);
  const name = typeof key === 'string' ? key : 'key';
  const out = [];
  for (const [value, members] of groups) {
    // Each feature an operand of its own, read by the fill rule alone (features that overlap do not cancel).
    const flats = members.map(({ feature, i }) => {
      const parts = [];
      addFeature(feature, `operand 0, feature ${i}`, parts, skipNonPolygonal);
      return toFlat(parts);
    });
    const packed = run(OPERATIONS.union, fillRule, flats, flats.map((flat) => flat.labels));
    const coordinates = toCoordinates(unpack(packed));
    if (coordinates.length > 0) {
      out.push({ type: 'Feature', properties: key === undefined ? {} : { [name]: value }, geometry: { type: 'MultiPolygon', coordinates } });
    }
  }
  return { type: 'FeatureCollection', features: out };
}
