// Lines and layers through the built npm package: every shared fixture of tests/fixtures/lines-and-layers (the files
// the Rust tests read; expectations from GEOS and exact rationals), the GeoJSON kinds in and out, the properties
// kept, and errors that name the feature, line and vertex.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { clip, dissolve, overlayLayers, split, union } from 'polysweep';
import { normalise } from './normalise.mjs';

const dir = new URL('../../tests/fixtures/lines-and-layers/', import.meta.url);
const fixtures = readdirSync(dir)
  .filter((f) => f.endsWith('.json'))
  .sort()
  .map((f) => JSON.parse(readFileSync(new URL(f, dir), 'utf8')));
const of = (operation) => fixtures.filter((f) => f.operation === operation);
const feature = (geometry, properties = null) => ({ type: 'Feature', properties, geometry });
const collection = (features) => ({ type: 'FeatureCollection', features });
const multiPolygon = (coordinates) => ({ type: 'MultiPolygon', coordinates });

test('the fixtures are there', () => {
  for (const operation of ['clip', 'split', 'overlay_layers', 'dissolve']) {
    assert.ok(of(operation).length >= 4, `only ${of(operation).length} ${operation} fixtures`);
  }
});

for (const fixture of of('clip')) {
  test(`clip: ${fixture.name}`, () => {
    for (const keep of ['inside', 'outside']) {
      // Line by line (coordinates of one line give that line's parts), and all at once as a FeatureCollection.
      fixture.lines.forEach((line, i) => {
        assert.deepEqual(clip(line, fixture.polygon, { keep, fillRule: fixture.fill_rule }), fixture.expected[keep][i], `${keep}, line ${i}`);
      });
      const lines = collection(fixture.lines.map((coordinates, i) => feature({ type: 'LineString', coordinates }, { i })));
      const clipped = clip(lines, fixture.polygon, { keep, fillRule: fixture.fill_rule });
      const expected = fixture.expected[keep].flatMap((parts, i) => (parts.length > 0 ? [feature({ type: 'MultiLineString', coordinates: parts }, { i })] : []));
      assert.deepEqual(clipped, collection(expected), keep);
    }
  });
}

for (const fixture of of('split')) {
  test(`split: ${fixture.name}`, () => {
    // Coordinates in, Polygon coordinates out; a Feature in, Polygon features out.
    const lines = { type: 'MultiLineString', coordinates: fixture.lines };
    const pieces = split(fixture.polygon, lines, { fillRule: fixture.fill_rule });
    assert.deepEqual(normalise(pieces), normalise(fixture.expected.pieces));
    const features = split(feature(multiPolygon(fixture.polygon), { id: 7 }), lines, { fillRule: fixture.fill_rule }).features;
    assert.deepEqual(normalise(features.map((f) => f.geometry.coordinates)), normalise(fixture.expected.pieces));
    assert.ok(features.every((f) => f.properties.id === 7 && f.geometry.type === 'Polygon'));
  });
}

const layer = (features) => collection(features.map((coordinates, i) => feature(multiPolygon(coordinates), { i })));
const byTags = (x, y) => {
  const lists = (f) => [f.properties.aIndices, f.properties.bIndices];
  const [p, q] = [lists(x), lists(y)];
  for (let k = 0; k < 2; k++) {
    for (let i = 0; i < Math.max(p[k].length, q[k].length); i++) {
      if (p[k][i] === undefined || q[k][i] === undefined) return p[k][i] === undefined ? -1 : 1;
      if (p[k][i] !== q[k][i]) return p[k][i] - q[k][i];
    }
  }
  return 0;
};

for (const fixture of of('overlay_layers')) {
  test(`overlayLayers: ${fixture.name}`, () => {
    const [a, b] = [layer(fixture.layer_a), layer(fixture.layer_b)];
    const faces = overlayLayers(a, b, { mode: 'union', fillRule: fixture.fill_rule }).features.sort(byTags);
    assert.deepEqual(
      faces.map((f) => [f.properties.aIndices, f.properties.bIndices]),
      fixture.expected.faces.map((e) => [e.a, e.b]),
    );
    faces.forEach((face, k) => {
      const e = fixture.expected.faces[k];
      assert.deepEqual(normalise(face.geometry.coordinates), normalise(e.polygon));
      // The properties of the first covering feature of each layer.
      assert.deepEqual(face.properties.a, e.a.length > 0 ? { i: e.a[0] } : null);
      assert.deepEqual(face.properties.b, e.b.length > 0 ? { i: e.b[0] } : null);
    });
    const tagged = (keep) => faces.filter((f) => keep(f.properties.aIndices.length > 0, f.properties.bIndices.length > 0)).map((f) => f.properties);
    for (const [mode, keep] of [
      ['intersection', (x, y) => x && y],
      ['identity', (x) => x],
      ['difference', (x, y) => x && !y],
      ['xor', (x, y) => x !== y],
    ]) {
      const some = overlayLayers(a, b, { mode, fillRule: fixture.fill_rule }).features.sort(byTags);
      assert.deepEqual(some.map((f) => f.properties), tagged(keep), mode);
    }
  });
}

for (const fixture of of('dissolve')) {
  test(`dissolve: ${fixture.name}`, () => {
    const features = collection(fixture.features.map((f) => feature(multiPolygon(f.polygon), { zone: f.key })));
    const merged = dissolve(features, 'zone', { fillRule: fixture.fill_rule }).features;
    merged.sort((x, y) => (x.properties.zone < y.properties.zone ? -1 : 1));
    assert.deepEqual(merged.map((f) => f.properties), fixture.expected.groups.map((g) => ({ zone: g.key })));
    merged.forEach((f, k) => assert.deepEqual(normalise(f.geometry.coordinates), normalise(fixture.expected.groups[k].polygon)));
  });
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
