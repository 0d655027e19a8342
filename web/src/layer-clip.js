// clipLayer in three steps, apart so that the middle one can run in a Web Worker (worker.js):
// - prepare, on the caller's thread: the layer's features and the clipping polygon read into the flat form (typed
//   arrays, which a worker takes without copying);
// - compute, where the wasm core is: the features whose bounding box misses the polygon's left out, the others
//   clipped in batches, one layer overlay (one sweep) per batch, so that a big polygon is swept once per batch
//   rather than once per feature, with progress after each batch;
// - finish, on the caller's thread: a feature per clipped input feature, with its id and properties.

import { overlay_layers_flat } from './polysweep_wasm.js';
import { OPERATIONS, addFeature, concatenate, describeGeoJSON, optionsOf, readFaces, readOperand, run, toCoordinates, toFlat, unpack } from './geojson.js';

// A batch ends at whichever bound comes first. Each batch sweeps the polygon once more and reports progress once:
// batches of about 1,000 parcels keep both the extra sweeps and the time between reports small.
const BATCH_FEATURES = 1000;
const BATCH_VERTICES = 20000;

/** The bounding box [minX, minY, maxX, maxY] of x, y pairs; NaN ones where a coordinate is not finite. */
function bounds(coords) {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let i = 0; i < coords.length; i += 2) {
    const x = coords[i];
    const y = coords[i + 1];
    if (!Number.isFinite(x) || !Number.isFinite(y)) return [NaN, NaN, NaN, NaN];
    if (x < minX) minX = x;
    if (x > maxX) maxX = x;
    if (y < minY) minY = y;
    if (y > maxY) maxY = y;
  }
  return [minX, minY, maxX, maxY];
}

/**
 * Can these boxes share a point? Yes where either is NaN (a coordinate that is not finite): such a feature goes to
 * the core, whose error names its vertex.
 */
function mayMeet(a, b) {
  return !(a[0] > b[2] || b[0] > a[2] || a[1] > b[3] || b[1] > a[3]);
}

/**
 * Reads `layer` (a FeatureCollection or an array of Features) and `polygon` (any operand of the Boolean operations).
 * Returns the layer's `features` and the `job` for computeClipLayer: all features in one flat form, with
 * `featureOffsets` (each feature's first polygon), and the polygon. One pass, one set of arrays: on the main
 * thread, this is what a big layer costs before the worker takes over.
 */
export function prepareClipLayer(layer, polygon, options) {
  const { fillRule, skipNonPolygonal } = optionsOf(options);
  const features = Array.isArray(layer) ? layer : layer?.type === 'FeatureCollection' ? layer.features : undefined;
  if (!Array.isArray(features)) throw new TypeError(`layer: expected a FeatureCollection or an array of Features, not ${describeGeoJSON(layer)}`);
  const clipInput = readOperand(polygon, 0, skipNonPolygonal);
  for (const part of clipInput.parts) part.where = part.where.replace(/^operand 0/, 'polygon');
  const clip = toFlat(clipInput.parts);
  const parts = [];
  const featureOffsets = new Uint32Array(features.length + 1);
  let polygons = 0;
  for (let i = 0; i < features.length; i++) {
    const feature = features[i];
    const where = `layer, feature ${i}`;
    if (feature?.type !== 'Feature') throw new TypeError(`${where}: expected a Feature, not ${describeGeoJSON(feature)}`);
    const first = parts.length;
    addFeature(feature, where, parts, skipNonPolygonal);
    for (let k = first; k < parts.length; k++) polygons += parts[k].coordinates.length;
    featureOffsets[i + 1] = polygons;
  }
  const flat = toFlat(parts);
  const job = {
    fillRule,
    layer: { coords: flat.coords, ringOffsets: flat.ringOffsets, polygonOffsets: flat.polygonOffsets, featureOffsets },
    clip: { coords: clip.coords, ringOffsets: clip.ringOffsets, polygonOffsets: clip.polygonOffsets, labels: clip.labels },
  };
  return { features, job };
}

/**
 * The features of `layer` whose bounding box may meet `box`: `ids`, their indices, and `layer`, them alone in the
 * flat form with their `featureOffsets`.
 */
function featuresMeeting({ coords, ringOffsets, polygonOffsets, featureOffsets }, box) {
  const vertexOf = (f) => ringOffsets[polygonOffsets[featureOffsets[f]]];
  const ids = [];
  let vertices = 0;
  let rings = 0;
  for (let f = 0; f + 1 < featureOffsets.length; f++) {
    const [v0, v1] = [vertexOf(f), vertexOf(f + 1)];
    if (v1 > v0 && mayMeet(bounds(coords.subarray(2 * v0, 2 * v1)), box)) {
      ids.push(f);
      vertices += v1 - v0;
      rings += polygonOffsets[featureOffsets[f + 1]] - polygonOffsets[featureOffsets[f]];
    }
  }
  const polygons = ids.reduce((sum, f) => sum + featureOffsets[f + 1] - featureOffsets[f], 0);
  const out = {
    coords: new Float64Array(2 * vertices),
    ringOffsets: new Uint32Array(rings + 1),
    polygonOffsets: new Uint32Array(polygons + 1),
    featureOffsets: new Uint32Array(ids.length + 1),
  };
  let [v, r, p] = [0, 0, 0];
  ids.forEach((f, k) => {
    const [p0, p1] = [featureOffsets[f], featureOffsets[f + 1]];
    const [r0, r1] = [polygonOffsets[p0], polygonOffsets[p1]];
    const v0 = ringOffsets[r0];
    out.coords.set(coords.subarray(2 * v0, 2 * ringOffsets[r1]), 2 * v);
    for (let i = p0 + 1; i <= p1; i++) out.polygonOffsets[++p] = r + polygonOffsets[i] - r0;
    for (let i = r0 + 1; i <= r1; i++) out.ringOffsets[++r] = v + ringOffsets[i] - v0;
    v += ringOffsets[r1] - v0;
    out.featureOffsets[k + 1] = p;
  });
  return { ids: Uint32Array.from(ids), layer: out };
}

/** The typed arrays' buffers of a flat form (or several), to transfer to or from a worker. */
export function buffersOf(...flats) {
  const buffers = new Set();
  for (const flat of flats) {
    for (const value of Object.values(flat)) if (ArrayBuffer.isView(value)) buffers.add(value.buffer);
  }
  return [...buffers];
}

/** Polygons `first` to `end` of a flat form, as a flat form of their own (offsets from 0). */
function slicePolygons({ coords, ringOffsets, polygonOffsets }, first, end) {
  const r0 = polygonOffsets[first];
  const r1 = polygonOffsets[end];
  const v0 = ringOffsets[r0];
  return {
    coords: coords.slice(2 * v0, 2 * ringOffsets[r1]),
    ringOffsets: ringOffsets.slice(r0, r1 + 1).map((v) => v - v0),
    polygonOffsets: polygonOffsets.slice(first, end + 1).map((r) => r - r0),
  };
}

/**
 * Clips the job's features `start` to `end` to the polygon in one layer overlay (the features layer A, the polygon
 * layer B) and stores each feature's pieces in `results`. A face covered by one feature is that feature's piece;
 * features that overlap another of the batch are split by the overlay into several faces, so they are clipped
 * again on their own, one intersection each.
 */
function clipBatch({ fillRule, ids, layer, clip }, start, end, results) {
  const first = layer.featureOffsets[start];
  const batch = slicePolygons(layer, first, layer.featureOffsets[end]);
  const both = concatenate([batch, clip]);
  const count = end - start;
  const featureOffsets = new Uint32Array(count + 2);
  for (let f = 0; f <= count; f++) featureOffsets[f] = layer.featureOffsets[start + f] - first;
  featureOffsets[count + 1] = both.operandOffsets[2];
  let packed;
  try {
    packed = overlay_layers_flat(0, fillRule, both.coords, both.ringOffsets, both.polygonOffsets, featureOffsets, new Uint32Array([0, count, count + 1]));
  } catch (error) {
    throw new RangeError(relabel(error?.message ?? String(error), ids, start, featureOffsets, clip.labels));
  }
  const { faces, flat } = readFaces(packed);
  const overlapping = new Set();
  let p = 0;
  for (const { a, polygons } of faces) {
    if (a.length === 1) results[start + a[0]] = slicePolygons(flat, p, p + polygons);
    else for (const f of a) overlapping.add(f);
    p += polygons;
  }
  for (const f of overlapping) {
    const feature = slicePolygons(batch, featureOffsets[f], featureOffsets[f + 1]);
    results[start + f] = unpack(run(OPERATIONS.intersection, fillRule, [feature, clip]));
  }
}

/**
 * The core's "operand o, polygon p, …" of a batch (operand 0 the batch's features, numbered straight through;
 * operand 1 the polygon) as the caller's feature or polygon.
 */
function relabel(message, ids, start, featureOffsets, clipLabels) {
  const at = /^operand (\d+), polygon (\d+), /.exec(message);
  if (!at) return message;
  const p = Number(at[2]);
  const rest = message.slice(at[0].length);
  if (at[1] === '1') {
    const label = clipLabels.find(({ first, end }) => first <= p && p < end);
    return label ? `${label.where}, polygon ${p - label.first}, ${rest}` : `polygon, polygon ${p}, ${rest}`;
  }
  let f = 0;
  while (featureOffsets[f + 1] <= p) f++;
  return `layer, feature ${ids[start + f]}, polygon ${p - featureOffsets[f]}, ${rest}`;
}

/**
 * Clips the job's features to its polygon, calling `onProgress(done, total)` (features) before the first batch and
 * after each. Returns the flat form of the pieces with `ids` (the layer indices of the features that kept any) and
 * `featureOffsets` (each one's first polygon).
 */
export function computeClipLayer(job, onProgress) {
  const { clip, fillRule } = job;
  const box = bounds(clip.coords);
  // A polygon with a coordinate that is not finite: the core names its vertex.
  if (Number.isNaN(box[0])) run(OPERATIONS.union, fillRule, [clip], [clip.labels]);
  const { ids, layer } = featuresMeeting(job.layer, box);
  const meeting = { fillRule, ids, layer, clip };
  const total = ids.length;
  const results = new Array(total);
  const vertexOfFeature = (f) => layer.ringOffsets[layer.polygonOffsets[layer.featureOffsets[f]]];
  onProgress?.(0, total);
  for (let start = 0; start < total; ) {
    let end = start + 1;
    while (end < total && end - start < BATCH_FEATURES && vertexOfFeature(end + 1) - vertexOfFeature(start) <= BATCH_VERTICES) end++;
    clipBatch(meeting, start, end, results);
    start = end;
    onProgress?.(start, total);
  }
  const kept = [];
  const pieces = [];
  results.forEach((flat, k) => {
    if (flat !== undefined && flat.polygonOffsets.length > 1) {
      kept.push(ids[k]);
      pieces.push(flat);
    }
  });
  const out = concatenate(pieces);
  return { ids: Uint32Array.from(kept), coords: out.coords, ringOffsets: out.ringOffsets, polygonOffsets: out.polygonOffsets, featureOffsets: out.operandOffsets };
}

/** The FeatureCollection of computeClipLayer's `result`: each clipped feature with its id and properties. */
export function finishClipLayer(features, result) {
  const { ids, coords, ringOffsets, polygonOffsets, featureOffsets } = result;
  const out = new Array(ids.length);
  for (let k = 0; k < ids.length; k++) {
    const feature = features[ids[k]];
    const coordinates = toCoordinates({ coords, ringOffsets, polygonOffsets: polygonOffsets.subarray(featureOffsets[k], featureOffsets[k + 1] + 1) });
    const piece = feature.id === undefined ? { type: 'Feature' } : { type: 'Feature', id: feature.id };
    piece.properties = feature.properties ?? null;
    piece.geometry = { type: 'MultiPolygon', coordinates };
    out[k] = piece;
  }
  return { type: 'FeatureCollection', features: out };
}
