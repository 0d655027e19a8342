// The GeoJSON a map app holds, as operands: FeatureCollections and GeometryCollections (their polygons together
// are one operand), Features with a null geometry, positions with altitude, non-polygonal members (an error, or
// skipped on request), the kind of each result; and the four fill rules. Every expectation is worked out by hand
// on unit squares and rectangles (results compared after normalise: rings started at their smallest vertex, without
// the closing point or vertices where they go straight on; orientation kept).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { union, intersection, difference, xor } from 'polysweep';
import { normalise, area } from './normalise.mjs';

/** A counter-clockwise w x h rectangle's ring with its lower left corner at x, y. */
const rect = (x, y, w = 1, h = w) => [[x, y], [x + w, y], [x + w, y + h], [x, y + h], [x, y]];
const polygon = (...rings) => ({ type: 'Polygon', coordinates: rings });
const multiPolygon = (...polygons) => ({ type: 'MultiPolygon', coordinates: polygons });
const feature = (geometry, properties = null) => ({ type: 'Feature', properties, geometry });
const featureCollection = (...features) => ({ type: 'FeatureCollection', features });
const geometryCollection = (...geometries) => ({ type: 'GeometryCollection', geometries });
const lineString = { type: 'LineString', coordinates: [[0, 0], [5, 5]] };
const point = { type: 'Point', coordinates: [9, 9] };

/** Asserts that MultiPolygon coordinates are `expected` (a list of polygons, each a list of rings). */
const assertShape = (actual, expected, message) => assert.deepEqual(normalise(actual), normalise(expected), message);
/** The MultiPolygon geometry of a FeatureCollection result, checking that it is one Feature with no properties. */
function onlyGeometry(collection) {
  assert.equal(collection.type, 'FeatureCollection');
  assert.equal(collection.features.length, 1, 'one Feature holds the whole result');
  const [only] = collection.features;
  assert.equal(only.type, 'Feature');
  assert.equal(only.properties, null);
  assert.equal(only.geometry.type, 'MultiPolygon');
  return only.geometry;
}

// Two unit squares a unit apart, and the 4 x 1 strip across both.
const left = rect(0, 0);
const right = rect(2, 0);
const strip = rect(-1, 0.5, 5, 0.25);

test('a FeatureCollection is one operand: its features’ polygons together', () => {
  const squares = featureCollection(feature(polygon(left), { side: 'left' }), feature(multiPolygon([right]), { side: 'right' }));
  assertShape(onlyGeometry(union(squares)).coordinates, [[left], [right]]);
  // The strip across both: each square keeps its middle quarter of height.
  assertShape(onlyGeometry(intersection(squares, [strip])).coordinates, [[rect(0, 0.5, 1, 0.25)], [rect(2, 0.5, 1, 0.25)]]);
  // As a later operand, subtracted as one: the strip loses the two squares' middles.
  assertShape(difference([strip], squares), [[rect(-1, 0.5, 1, 0.25)], [rect(1, 0.5, 1, 0.25)], [rect(3, 0.5, 1, 0.25)]]);
  // The squares' xor with the strip: the strip outside them, and the squares with their middles cut out (each in
  // two pieces).
  assert.equal(area(onlyGeometry(xor(squares, [strip])).coordinates), 2 - 0.5 + (1.25 - 0.5));
});

test('a FeatureCollection operand with holes: a 6 x 6 square minus two unit squares inside it', () => {
  const holes = featureCollection(feature(polygon(rect(1, 1))), feature(polygon(rect(3, 3))));
  const holeRing = (x, y) => [[x, y], [x, y + 1], [x + 1, y + 1], [x + 1, y], [x, y]]; // clockwise
  assertShape(difference([rect(0, 0, 6)], holes), [[rect(0, 0, 6), holeRing(1, 1), holeRing(3, 3)]]);
});

test('a GeometryCollection is one operand, nested ones too; its result is a MultiPolygon geometry', () => {
  const nested = geometryCollection(polygon(left), geometryCollection(multiPolygon([right]), geometryCollection()));
  const result = union(nested);
  assert.equal(result.type, 'MultiPolygon');
  assertShape(result.coordinates, [[left], [right]]);
  assertShape(intersection([strip], nested), [[rect(0, 0.5, 1, 0.25)], [rect(2, 0.5, 1, 0.25)]]);
  // A Feature whose geometry is a GeometryCollection: a Feature with the feature's properties.
  const out = union(feature(nested, { id: 4 }), [rect(1, 0)]);
  assert.equal(out.type, 'Feature');
  assert.deepEqual(out.properties, { id: 4 });
  assertShape(out.geometry.coordinates, [[rect(0, 0, 3, 1)]]);
});

test('a Feature with a null geometry is an empty operand; in a collection it adds nothing', () => {
  const unlocated = feature(null, { name: 'nowhere' });
  const alone = union(unlocated);
  assert.deepEqual(alone, { type: 'Feature', properties: { name: 'nowhere' }, geometry: { type: 'MultiPolygon', coordinates: [] } });
  assertShape(union(unlocated, [left]).geometry.coordinates, [[left]]);
  assert.deepEqual(intersection([left], unlocated), []);
  assertShape(difference([left], unlocated), [[left]]);
  assertShape(onlyGeometry(union(featureCollection(unlocated, feature(polygon(left)), unlocated))).coordinates, [[left]]);
  // Empty collections are empty operands too.
  assert.deepEqual(onlyGeometry(union(featureCollection())).coordinates, []);
  assert.deepEqual(union(geometryCollection()), { type: 'MultiPolygon', coordinates: [] });
});

test('positions with a third or fourth ordinate are read as x, y; results are two-dimensional', () => {
  const withAltitude = [[0, 0, 100], [1, 0, 100], [1, 1, 120, 7], [0, 1, 100]];
  const result = union([withAltitude]);
  assertShape(result, [[left]]);
  for (const position of result[0][0]) assert.equal(position.length, 2);
  assertShape(intersection(polygon(withAltitude), [rect(0.5, 0.5)]).coordinates, [[rect(0.5, 0.5, 0.5)]]);
});

test('non-polygonal members: an error naming them, or skipped with {skipNonPolygonal: true}', () => {
  const mixed = featureCollection(feature(polygon(left)), feature(null), feature(point), feature(lineString));
  assert.throws(() => union([right], mixed), {
    name: 'TypeError',
    message: 'operand 1, feature 2: a Point is not a polygon (pass {skipNonPolygonal: true} to skip it)',
  });
  assertShape(union([right], mixed, { skipNonPolygonal: true }), [[left], [right]]);
  const inGeometries = geometryCollection(polygon(left), geometryCollection({ type: 'MultiLineString', coordinates: [] }));
  assert.throws(() => union(inGeometries), { name: 'TypeError', message: /^operand 0, geometry 1, geometry 0: a MultiLineString is not a polygon/ });
  assertShape(union(inGeometries, { skipNonPolygonal: true }).coordinates, [[left]]);
  // A non-polygonal geometry or Feature as the whole operand: skipped, it is an empty operand.
  assert.throws(() => union([left], lineString), { name: 'TypeError', message: /^operand 1: a LineString is not a polygon/ });
  assertShape(union([left], lineString, feature({ type: 'MultiPoint', coordinates: [[0, 0]] }), { skipNonPolygonal: true }), [[left]]);
  assert.deepEqual(union(feature(lineString, { id: 1 }), [left], { skipNonPolygonal: true, fillRule: 'nonzero' }).properties, { id: 1 });
  // Only valid GeoJSON geometries are skipped, never malformed ones.
  assert.throws(() => union(featureCollection(feature({ type: 'Circle', radius: 1 })), { skipNonPolygonal: true }), {
    name: 'TypeError',
    message: 'operand 0, feature 0: expected a Polygon, MultiPolygon or GeometryCollection, not GeoJSON type "Circle"',
  });
  assert.throws(() => union([left], { skipNonPolygonal: 'yes' }), { name: 'TypeError', message: 'options.skipNonPolygonal must be true or false, not "yes"' });
});

test('errors name the operand, the member, and the polygon, ring and vertex within it', () => {
  const bad = (position) =>
    featureCollection(feature(polygon(right)), feature(null), feature(multiPolygon([left], [rect(5, 5), [[0, 0], [1, 0], position]])));
  // The core's errors (bad numbers), the polygon counted within the feature although the core numbers the
  // operand's polygons straight through (feature 0's is its polygon 0, so this one is its polygon 2).
  assert.throws(() => union([left], bad([1, NaN])), {
    name: 'RangeError',
    message: 'operand 1, feature 2, polygon 1, ring 1, vertex 2: coordinate NaN is not a finite number',
  });
  assert.throws(() => xor(bad([1e300, 0])), { name: 'RangeError', message: /^operand 0, feature 2, polygon 1, ring 1, vertex 2: coordinate 1e300 is out of range/ });
  // The package's own (shapes).
  assert.throws(() => union([left], bad(['1', 1])), {
    name: 'TypeError',
    message: 'operand 1, feature 2, polygon 1, ring 1, vertex 2: a position must be an array of two (or more) numbers',
  });
  assert.throws(() => union(geometryCollection(polygon(left), geometryCollection(polygon(left, 7)))), {
    name: 'TypeError',
    message: 'operand 0, geometry 1, geometry 0, polygon 0, ring 1: must be an array of positions',
  });
  assert.throws(() => union(featureCollection(feature(polygon(left)), polygon(right))), {
    name: 'TypeError',
    message: 'operand 0, feature 1: expected a Feature, not GeoJSON type "Polygon"',
  });
  assert.throws(() => union({ type: 'FeatureCollection' }), { name: 'TypeError', message: "operand 0: the FeatureCollection's features must be an array" });
  const loop = geometryCollection();
  loop.geometries.push(loop);
  assert.throws(() => union([left], loop), { name: 'RangeError', message: /^operand 1, geometry 0, .*: GeometryCollections nested more than 32 deep$/ });
  // Still usable, and single operands are named as before.
  assert.throws(() => union([left], [[[0, 0], [1, NaN], [1, 1]]]), { message: /^operand 1, polygon 0, ring 0, vertex 1: / });
  assertShape(union([left], [right]), [[left], [right]]);
});

test('results in the kind of the first operand', () => {
  const collection = featureCollection(feature(polygon(left), { id: 1 }));
  // FeatureCollection: a FeatureCollection of one Feature with null properties, also when empty.
  assertShape(onlyGeometry(union(collection, [right])).coordinates, [[left], [right]]);
  assert.deepEqual(onlyGeometry(intersection(collection, [right])).coordinates, []);
  // GeometryCollection: a MultiPolygon geometry. Feature: a Feature with its own properties.
  assert.equal(union(geometryCollection(polygon(left)), collection).type, 'MultiPolygon');
  assert.deepEqual(union(feature(polygon(right), { id: 2 }), collection).properties, { id: 2 });
  // Coordinates: coordinates, whatever comes after.
  assert.ok(Array.isArray(union([left], collection, geometryCollection())));
});

// Two squares in one operand overlapping in [1, 2]^2: P = [0, 2]^2 counter-clockwise and Q = [1, 3]^2 clockwise.
// The winding number is +1 in P alone, -1 in Q alone, 0 in the overlap.
const P = rect(0, 0, 2);
const Q = [[1, 1], [1, 3], [3, 3], [3, 1], [1, 1]];
const Qccw = rect(1, 1, 2);
const pAlone = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]; // P minus the overlap, counter-clockwise
const qAlone = [[2, 1], [3, 1], [3, 3], [1, 3], [1, 2], [2, 2]]; // Q minus the overlap, counter-clockwise

test('fill rules on two squares wound oppositely', () => {
  const both = [[P], [Q]];
  assertShape(union(both, { fillRule: 'positive' }), [[pAlone]], 'positive: where the winding number is above 0');
  assertShape(union(both, { fillRule: 'negative' }), [[qAlone]], 'negative: where it is below 0');
  // Even-odd and non-zero agree here: both leave out the overlap (winding 0), keeping the two L shapes, which touch
  // at (1, 2) and (2, 1).
  for (const fillRule of ['evenodd', 'nonzero']) assert.equal(area(union(both, { fillRule })), 6, fillRule);
  // The default reads each polygon by its structure, orientation aside: the union of the two squares.
  assert.equal(area(union(both)), 7, 'structure by default');
});

test('fill rules on two squares wound alike, and on one square wound clockwise', () => {
  const alike = [[P], [Qccw]];
  const unionOfBoth = [[[0, 0], [2, 0], [2, 1], [3, 1], [3, 3], [1, 3], [1, 2], [0, 2]]];
  assertShape(union(alike, { fillRule: 'nonzero' }), [unionOfBoth]);
  assertShape(union(alike, { fillRule: 'positive' }), [unionOfBoth]);
  assert.deepEqual(union(alike, { fillRule: 'negative' }), []);
  assert.equal(area(union(alike, { fillRule: 'evenodd' })), 6, 'even-odd: the overlap is covered twice, so out');
  // A clockwise ring alone: empty under positive, full under negative (and the result counter-clockwise).
  const clockwise = [Q];
  assert.deepEqual(union(clockwise, { fillRule: 'positive' }), []);
  assertShape(union(clockwise, { fillRule: 'negative' }), [[Qccw]]);
  assertShape(union(clockwise, { fillRule: 'evenodd' }), [[Qccw]]);
  assertShape(union(clockwise, { fillRule: 'nonzero' }), [[Qccw]]);
  // The rule reads each operand on its own: the clockwise operand is empty under positive, so only P is left.
  assertShape(union([P], clockwise, { fillRule: 'positive' }), [[P]]);
  assertShape(intersection([P], clockwise, { fillRule: 'negative' }), [], 'P is empty under negative');
  // The same square twice: winding number 2.
  const twice = [[P], [P]];
  assertShape(union(twice, { fillRule: 'positive' }), [[P]]);
  assert.deepEqual(union(twice, { fillRule: 'negative' }), []);
  assert.deepEqual(union(twice, { fillRule: 'evenodd' }), []);
});

test('the fill rule applies to collection operands as to any other', () => {
  // A FeatureCollection whose features overlap is one operand, so its overlap counts twice: out under even-odd,
  // in under non-zero (both squares counter-clockwise).
  const overlapping = featureCollection(feature(polygon(P)), feature(polygon(Qccw)));
  assert.equal(area(onlyGeometry(union(overlapping, { fillRule: 'evenodd' })).coordinates), 6);
  assert.equal(area(onlyGeometry(union(overlapping, { fillRule: 'nonzero' })).coordinates), 7);
  // Features passed as separate operands are unioned whatever the rule.
  // By structure the parts of one operand are unioned, as polygon-clipping reads them.
  assert.equal(area(onlyGeometry(union(overlapping, { fillRule: 'structure' })).coordinates), 7);
  assert.equal(area(union(...overlapping.features, { fillRule: 'evenodd' }).geometry.coordinates), 7);
  assert.throws(() => union(overlapping, { fillRule: 'winding' }), {
    name: 'TypeError',
    message: /^options\.fillRule must be 'evenodd', 'nonzero', 'positive', 'negative' or 'structure', not "winding"$/,
  });
});

