// Lines against polygon sets: clip (the parts of lines inside or outside) and split (a polygon set cut along lines),
// GeoJSON in and out, over the core's clip_flat and split_flat.

import { clip_flat, split_flat } from './polysweep_wasm.js';
import { MAX_VERTICES, choice, describe, describeGeoJSON, optionsOf, readOperand, toCoordinates, toFlat, unpack } from './geojson.js';

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

