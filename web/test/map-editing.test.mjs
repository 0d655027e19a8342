// clipLayer and splitAntimeridian through the built npm package, against hand-worked expectations: unit grids
// whose clipped areas are quarters and halves, and boxes across the antimeridian whose pieces are known rectangles.
// (The worker API runs the same clipLayer steps in a browser: browser.test.mjs.)
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { clipLayer, splitAntimeridian, union } from 'polysweep';
import { area } from './normalise.mjs';

const box = (x0, y0, x1, y1) => [[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]];
const feature = (coordinates, properties, id) => ({ type: 'Feature', ...(id === undefined ? {} : { id }), properties, geometry: { type: 'Polygon', coordinates } });
/** An n × n grid of unit squares, row by row from the origin, with ids and properties. */
const grid = (n) => ({
  type: 'FeatureCollection',
  features: Array.from({ length: n * n }, (_, k) => feature([box(k % n, Math.floor(k / n), (k % n) + 1, Math.floor(k / n) + 1)], { row: Math.floor(k / n), column: k % n }, k)),
});
const areaOf = (f) => area(f.geometry.coordinates);
/** [minX, minY, maxX, maxY] of a MultiPolygon's coordinates. */
const bounds = (coordinates) => {
  const positions = coordinates.flat(2);
  const xs = positions.map((p) => p[0]);
  const ys = positions.map((p) => p[1]);
  return [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
};

test('clipLayer: each feature clipped, in order, keeping its id and properties', () => {
  const out = clipLayer(grid(3), [box(0.5, 0.5, 2.5, 2.5)]);
  assert.equal(out.type, 'FeatureCollection');
  assert.deepEqual(out.features.map((f) => f.id), [0, 1, 2, 3, 4, 5, 6, 7, 8]);
  // Corners keep a quarter, edges a half, the centre all.
  assert.deepEqual(out.features.map(areaOf), [0.25, 0.5, 0.25, 0.5, 1, 0.5, 0.25, 0.5, 0.25]);
  assert.deepEqual(out.features[5].properties, { row: 1, column: 2 });
  assert.ok(out.features.every((f) => f.geometry.type === 'MultiPolygon'));
});

test('clipLayer: features that only touch the polygon, lie outside it or have no geometry are left out', () => {
  const layer = grid(3);
  layer.features.push({ type: 'Feature', properties: { empty: true }, geometry: null });
  layer.features.push(feature([box(10, 10, 11, 11)], { far: true }));
  const out = clipLayer(layer, { type: 'Polygon', coordinates: [box(1, 1, 2, 2)] });
  assert.deepEqual(out.features.map((f) => f.id), [4]);
  assert.equal(areaOf(out.features[0]), 1);
});

test('clipLayer: overlapping features are each clipped whole, holes and MultiPolygons kept', () => {
  const layer = [
    feature([box(0, 0, 2, 2)], { name: 'a' }),
    feature([box(1, 1, 3, 3)], { name: 'b' }),
    feature([box(0, 0, 3, 3), box(1, 1, 2, 2).reverse()], { name: 'frame' }),
    { type: 'Feature', properties: { name: 'pair' }, geometry: { type: 'MultiPolygon', coordinates: [[box(-1, -1, 0.5, 0.5)], [box(2.5, 2.5, 4, 4)]] } },
  ];
  const out = clipLayer(layer, [box(0, 0, 3, 3)]);
  assert.deepEqual(out.features.map((f) => f.properties.name), ['a', 'b', 'frame', 'pair']);
  // a and b overlap in [1, 2]²: each keeps its own 4; the frame its 9 − 1; the pair a quarter of each square.
  assert.deepEqual(out.features.map(areaOf), [4, 4, 8, 0.5]);
  assert.equal(out.features[2].geometry.coordinates[0].length, 2, 'the frame keeps its hole');
  assert.equal(out.features[3].geometry.coordinates.length, 2);
});

test('clipLayer: a layer in many batches reports progress up to its total', () => {
  const progress = [];
  const out = clipLayer(grid(60), [box(0, 0, 60, 60)], { onProgress: (done, total) => progress.push([done, total]) });
  assert.equal(out.features.length, 3600);
  assert.ok(out.features.every((f, k) => f.id === k && areaOf(f) === 1));
  assert.deepEqual(progress[0], [0, 3600]);
  assert.deepEqual(progress.at(-1), [3600, 3600]);
  assert.ok(progress.length > 3, `${progress.length - 1} batches`);
  assert.ok(progress.every(([done, total], i) => total === 3600 && (i === 0 || done > progress[i - 1][0])));
});

test('clipLayer: errors name the feature or the polygon, and the module stays usable', () => {
  const bad = grid(2);
  bad.features[3].geometry.coordinates[0][2] = [2, Infinity];
  assert.throws(() => clipLayer(bad, [box(0, 0, 2, 2)]), { name: 'RangeError', message: /^layer, feature 3, polygon 0, ring 0, vertex 2: / });
  assert.throws(() => clipLayer(grid(2), [[[0, 0], [NaN, 1], [1, 1]]]), { name: 'RangeError', message: /^polygon, polygon 0, ring 0, vertex 1: / });
  assert.throws(() => clipLayer({ type: 'FeatureCollection', features: [{ type: 'Polygon' }] }, [box(0, 0, 1, 1)]), {
    name: 'TypeError',
    message: 'layer, feature 0: expected a Feature, not GeoJSON type "Polygon"',
  });
  assert.throws(() => clipLayer({ type: 'Polygon', coordinates: [] }, [box(0, 0, 1, 1)]), { name: 'TypeError', message: /^layer: expected a FeatureCollection/ });
  assert.throws(() => clipLayer(grid(1), [box(0, 0, 1, 1)], { onProgress: 1 }), { name: 'TypeError', message: /onProgress must be a function/ });
  assert.equal(area(union([box(0, 0, 2, 2)], [box(1, 1, 3, 3)])), 7);
});

test('splitAntimeridian: a box across ±180° becomes its two halves, in the kind given', () => {
  const fiji = feature([[[170, -10], [-170, -10], [-170, 10], [170, 10], [170, -10]]], { name: 'across' });
  const out = splitAntimeridian(fiji);
  assert.equal(out.type, 'Feature');
  assert.deepEqual(out.properties, { name: 'across' });
  const pieces = out.geometry.coordinates.map((polygon) => ({ bounds: bounds([polygon]), area: area([polygon]) })).sort((a, b) => a.bounds[0] - b.bounds[0]);
  assert.deepEqual(pieces, [
    { bounds: [-180, -10, -170, 10], area: 200 },
    { bounds: [170, -10, 180, 10], area: 200 },
  ]);
});

test('splitAntimeridian: holes follow their exterior, far longitudes come back, a ring round a pole is closed over it', () => {
  const holed = splitAntimeridian({ type: 'Polygon', coordinates: [[[170, -10], [-170, -10], [-170, 10], [170, 10]], [[175, -5], [175, 5], [-175, 5], [-175, -5]]] });
  assert.equal(holed.type, 'MultiPolygon');
  assert.deepEqual(holed.coordinates.map((polygon) => area([polygon])).sort(), [150, 150]);
  const far = splitAntimeridian([box(190, 0, 200, 10)]);
  assert.deepEqual(bounds(far), [-170, 0, -160, 10]);
  assert.equal(area(far), 100);
  const south = splitAntimeridian([[[-120, -80], [0, -80], [120, -80], [-120, -80]]]);
  assert.deepEqual(bounds(south), [-180, -90, 180, -80]);
  assert.equal(area(south), 3600);
  const inside = splitAntimeridian([box(0, 0, 1, 1)]);
  assert.equal(area(inside), 1);
});
