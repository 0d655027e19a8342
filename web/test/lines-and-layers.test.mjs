// Lines and layers through the built npm package: every shared fixture of tests/fixtures/lines-and-layers (the files
// the Rust tests read; expectations from GEOS and exact rationals), the GeoJSON kinds in and out, the properties
// kept, and errors that name the feature, line and vertex.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import * as api from 'polysweep';
import { clip, dissolve, overlayLayers, split, union } from 'polysweep';
import { runLinesAndLayers } from './browser/lines-and-layers.js';
import { checkLinesAndLayers, lineFixtures } from './lines-and-layers-check.mjs';

const feature = (geometry, properties = null) => ({ type: 'Feature', properties, geometry });
const collection = (features) => ({ type: 'FeatureCollection', features });

test('the fixtures are there', () => {
  for (const operation of ['clip', 'split', 'overlay_layers', 'dissolve']) {
    const count = lineFixtures.filter((f) => f.operation === operation).length;
    assert.ok(count >= 4, `only ${count} ${operation} fixtures`);
  }
});

for (const fixture of lineFixtures) {
  test(`${fixture.operation}: ${fixture.name}`, () => checkLinesAndLayers(fixture, runLinesAndLayers(fixture, api)));
}

const square = { type: 'Polygon', coordinates: [[[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]]] };
const road = { type: 'LineString', coordinates: [[-1, 1], [5, 1]] };

test('clip answers in the kind of its lines, with the boundary rule', () => {
  assert.deepEqual(clip(road.coordinates, square), [[[0, 1], [4, 1]]]);
  assert.deepEqual(clip(road, square), { type: 'MultiLineString', coordinates: [[[0, 1], [4, 1]]] });
  assert.deepEqual(clip(feature(road, { name: 'A1' }), square, { keep: 'outside' }), feature({ type: 'MultiLineString', coordinates: [[[-1, 1], [0, 1]], [[4, 1], [5, 1]]] }, { name: 'A1' }));
  const along = { type: 'LineString', coordinates: [[0, -2], [0, 6]] };
  assert.deepEqual(clip(along, square).coordinates, [[[0, 0], [0, 4]]]);
  assert.deepEqual(clip(along, square, { boundary: 'outside' }).coordinates, []);
  assert.deepEqual(clip(along, square, { keep: 'outside', boundary: 'outside' }).coordinates, [[[0, -2], [0, 6]]]);
});

test('split keeps each feature\'s properties, and a line that does not cross leaves the polygon whole', () => {
  const parcels = collection([feature(square, { id: 1 }), feature({ type: 'Polygon', coordinates: [[[10, 0], [12, 0], [12, 2], [10, 2], [10, 0]]] }, { id: 2 })]);
  const cut = split(parcels, { type: 'LineString', coordinates: [[2, -1], [2, 5]] });
  assert.deepEqual(cut.features.map((f) => f.properties.id), [1, 1, 2]);
  assert.deepEqual(cut.features.map((f) => f.geometry.type), ['Polygon', 'Polygon', 'Polygon']);
  const dangling = split(square.coordinates, [[2, -1], [2, 2]]);
  assert.equal(dangling.length, 1);
});

test('overlayLayers makes properties with options.properties, and accepts arrays of features', () => {
  const parcels = [feature(square, { parcel: 'P1' })];
  const zones = [feature({ type: 'Polygon', coordinates: [[[2, 2], [6, 2], [6, 6], [2, 6], [2, 2]]] }, { zone: 'Z9' })];
  const faces = overlayLayers(parcels, zones, { properties: (a, b) => ({ ...a[0], ...b[0] }) });
  assert.deepEqual(faces.features.map((f) => f.properties), [{ parcel: 'P1', zone: 'Z9' }]);
  assert.deepEqual(faces.features[0].geometry.coordinates, [[[[2, 2], [4, 2], [4, 4], [2, 4], [2, 2]]]]);
});

test('dissolve without a key merges everything, with a function key groups by its value', () => {
  const cells = collection([0, 1, 2].map((x) => feature({ type: 'Polygon', coordinates: [[[x, 0], [x + 1, 0], [x + 1, 1], [x, 1], [x, 0]]] }, { x })));
  assert.equal(dissolve(cells).features.length, 1);
  const byParity = dissolve(cells, (f) => f.properties.x % 2);
  assert.deepEqual(byParity.features.map((f) => f.properties), [{ key: 0 }, { key: 1 }]);
  assert.equal(byParity.features[0].geometry.coordinates.length, 2);
});

test('bad input names the operand, feature, line and vertex, and the module stays usable', () => {
  const lines = collection([feature(road), feature({ type: 'MultiLineString', coordinates: [[[0, 0], [1, 1]], [[0, 0], [1, Infinity]]] })]);
  assert.throws(() => clip(lines, square), { name: 'RangeError', message: /^operand 0, feature 1, line 1, vertex 1: coordinate inf/ });
  assert.throws(() => clip(road, { type: 'Polygon', coordinates: [[[0, 0], [NaN, 0], [1, 1]]] }), { name: 'RangeError', message: /^operand 1, polygon 0, ring 0, vertex 1: coordinate NaN/ });
  assert.throws(() => split(square, { type: 'Point', coordinates: [0, 0] }), { name: 'TypeError', message: /operand 1: expected a LineString or MultiLineString, not GeoJSON type "Point"/ });
  assert.throws(() => clip(road, square, { keep: 'middle' }), { name: 'TypeError', message: /options.keep must be 'inside' or 'outside', not "middle"/ });
  const bad = collection([feature(square), feature({ type: 'Polygon', coordinates: [[[0, 0], [1, 0], [1, 1e300]]] })]);
  assert.throws(() => overlayLayers(collection([feature(square)]), bad), { name: 'RangeError', message: /^layer B, feature 1, polygon 0, ring 0, vertex 2: coordinate 1e300 is out of range/ });
  assert.throws(() => overlayLayers(square, bad), { name: 'TypeError', message: /layer A: expected a FeatureCollection or an array of Features/ });
  assert.throws(() => overlayLayers(collection([]), collection([]), { mode: 'cut' }), { name: 'TypeError', message: /options.mode must be/ });
  assert.throws(() => dissolve(collection([feature(square), feature({ type: 'Polygon', coordinates: [[[0, 0], [1, 0], [1, NaN]]] })])), { name: 'RangeError', message: /^operand 0, feature 1, polygon 0, ring 0, vertex 2/ });
  // Usable after every error.
  assert.deepEqual(clip(road.coordinates, square), [[[0, 1], [4, 1]]]);
  assert.equal(union(square, square).type, 'MultiPolygon');
});
