// Layers of features: overlayLayers (the faces of two layers' arrangement, each with the features covering it),
// dissolve (features merged by a key) and clipLayer (each feature of a layer clipped to a polygon, keeping its
// properties), GeoJSON in and out.

import { overlay_layers_flat } from './polysweep_wasm.js';
import { OPERATIONS, addFeature, choice, concatenate, describe, describeGeoJSON, optionsOf, readFaces, run, toCoordinates, toFlat, unpack } from './geojson.js';
import { computeClipLayer, finishClipLayer, prepareClipLayer } from './layer-clip.js';

const LAYER_MODES = { intersection: 0, union: 1, identity: 2, difference: 3, xor: 4 };

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
  const { faces, flat: out } = readFaces(packed);
  const all = toCoordinates(out);
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

/**
 * Each feature of `layer` (a FeatureCollection or an array of Features of polygons) clipped to `polygon` (any
 * operand of the Boolean operations), as QGIS's Clip: a FeatureCollection of one MultiPolygon feature per feature
 * that meets the polygon's interior, in the layer's order, keeping its id and properties. Options: `fillRule`,
 * `skipNonPolygonal`, and `onProgress(done, total)`, called as batches of features finish (the worker's clipLayer
 * runs the same steps off the main thread).
 */
export function clipLayer(layer, polygon, options) {
  const onProgress = options?.onProgress;
  if (onProgress !== undefined && typeof onProgress !== 'function') {
    throw new TypeError(`options.onProgress must be a function (done, total) => void, not ${describe(onProgress)}`);
  }
  const { features, job } = prepareClipLayer(layer, polygon, options);
  return finishClipLayer(features, computeClipLayer(job, onProgress));
}
