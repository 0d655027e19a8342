// Bad input, hand-written and generated from a fixed seed. Every call must either return a well-formed result or
// throw an Error with a message of its own (naming operand, polygon, ring and vertex when one vertex is to blame),
// never a wasm trap or an engine message, and the module must keep working afterwards.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { union, intersection, difference, xor, overlayFlat } from '../../pkg/polysweep.node.js';
import { area } from './normalise.mjs';

const OPERATIONS = { union, intersection, difference, xor };
const square = (x, y, s = 2) => [[[x, y], [x + s, y], [x + s, y + s], [x, y + s], [x, y]]];
const A = square(0, 0);
// `member` names the feature or geometry of a collection operand the polygon is in, such as ', feature 1'.
const at = (o, p, r, v, member = '') => new RegExp(`operand ${o}${member}, polygon ${p}, ring ${r}, vertex ${v}\\b`);
// Messages V8 or wasm make up themselves: they say nothing about which input was wrong.
const ENGINE_MESSAGE =
  /unreachable|out of bounds|call stack|is not a function|is not iterable|Cannot read propert|Cannot convert|Invalid typed array length|serialize a BigInt/;

// Shoelace, signed: exteriors come counter-clockwise and holes clockwise, so the sum is the area.
function assertMultiPolygon(mp) {
  assert.ok(Array.isArray(mp), 'coordinates are an array of polygons');
  for (const polygon of mp) {
    assert.ok(Array.isArray(polygon) && polygon.length > 0, 'a polygon is a non-empty array of rings');
    for (const ring of polygon) {
      assert.ok(Array.isArray(ring) && ring.length >= 4, 'a ring has at least 4 positions');
      for (const p of ring) assert.ok(Array.isArray(p) && p.length === 2 && p.every(Number.isFinite), `position ${p}`);
      assert.deepEqual(ring[0], ring[ring.length - 1], 'rings are closed');
    }
  }
}

/** The flat form as nested coordinates, checking its offsets on the way. */
function nestedOf({ coords, ringOffsets, polygonOffsets }) {
  assert.ok(coords instanceof Float64Array && ringOffsets instanceof Uint32Array && polygonOffsets instanceof Uint32Array);
  assert.deepEqual([polygonOffsets[0], polygonOffsets.at(-1), ringOffsets[0], 2 * ringOffsets.at(-1)], [0, ringOffsets.length - 1, 0, coords.length]);
  return Array.from({ length: polygonOffsets.length - 1 }, (_, p) => {
    assert.ok(polygonOffsets[p] <= polygonOffsets[p + 1], 'polygon offsets do not decrease');
    return Array.from({ length: polygonOffsets[p + 1] - polygonOffsets[p] }, (_, i) => {
      const [start, end] = [ringOffsets[polygonOffsets[p] + i], ringOffsets[polygonOffsets[p] + i + 1]];
      assert.ok(start <= end, 'ring offsets do not decrease');
      return Array.from({ length: end - start }, (_, v) => [coords[2 * (start + v)], coords[2 * (start + v) + 1]]);
    });
  });
}

/** The MultiPolygon coordinates of any result: coordinates, a MultiPolygon geometry, a Feature, a FeatureCollection
 * of one Feature, or the flat form. */
function coordinatesOf(result) {
  if (Array.isArray(result)) return result;
  if (result?.coords) return nestedOf(result);
  if (result?.type === 'FeatureCollection') {
    assert.equal(result.features.length, 1, 'a FeatureCollection result holds one feature');
    result = result.features[0];
  }
  const geometry = result?.type === 'Feature' ? result.geometry : result;
  assert.equal(geometry?.type, 'MultiPolygon', 'a result is coordinates, a geometry or a feature');
  return geometry.coordinates;
}

const flatOf = (mp) => ({
  coords: Float64Array.from(mp.flat(3)),
  ringOffsets: Uint32Array.from([0, ...mp.flat(1).map((_, i, rings) => rings.slice(0, i + 1).flat(1).length)]),
  polygonOffsets: Uint32Array.from([0, ...mp.map((_, i) => mp.slice(0, i + 1).flat(1).length)]),
});

function assertStillWorks() {
  assert.equal(area(union(square(0, 0), square(1, 1))), 7);
  assert.equal(area(nestedOf(overlayFlat('union', [flatOf([square(0, 0)]), flatOf([square(1, 1)])]))), 7);
}

/**
 * Runs one case. `expect`: 'returns' (a well-formed result), a number (a well-formed result of that area), a RegExp
 * (an error whose message matches), or {ifThrows: RegExp} (either; an error's message must match). Says if it threw.
 */
function check(name, call, expect) {
  let result, error;
  try {
    result = call();
  } catch (thrown) {
    error = thrown;
  }
  if (error === undefined) {
    assert.ok(!(expect instanceof RegExp), `${name}: returned instead of throwing ${expect}`);
    const coordinates = coordinatesOf(result);
    assertMultiPolygon(coordinates);
    if (typeof expect === 'number') assert.equal(area(coordinates), expect, `${name}: area`);
    return false;
  }
  assert.ok(error instanceof Error && !(error instanceof WebAssembly.RuntimeError), `${name}: threw ${String(error)}`);
  assert.ok(typeof error.message === 'string' && error.message.length > 0, `${name}: empty message`);
  assert.doesNotMatch(error.message, ENGINE_MESSAGE, `${name}: unhelpful message`);
  assert.ok(expect !== 'returns' && typeof expect !== 'number', `${name}: threw ${error.message}`);
  assert.match(error.message, expect instanceof RegExp ? expect : (expect?.ifThrows ?? /./), name);
  assert.doesNotThrow(assertStillWorks, `the module no longer works after ${name}`);
  return true;
}

// ---- Values to put where they do not belong ----
const JUNK = [null, undefined, 0, -1, NaN, '', 'x', true, 1n, Symbol('junk'), () => 0, {}, { length: 2, 0: 0, 1: 0 },
  new Float64Array(4), new Map(), [[[[]]]], [null], [[1, 2]], Object.create(null)];
// Not numbers, not finite, or out of the range the exact predicates cover (magnitude 0 or 2^-200..2^200).
const BAD_COORDINATES = [NaN, Infinity, -Infinity, 1e308, -1e308, 5e-324, -5e-324, 2 ** 201, 1e-61, 'x', '1', '',
  null, undefined, true, 1n, {}, [], [1], Symbol('c'), new Number(1), () => 1];
const ODD_VALID_COORDINATES = [-0, 1e60, -1e60, 2 ** 200, 2 ** -200, -(2 ** -200), 1e-60, 0.1 + 0.2, -123456789.987654321];
// Positions that are not arrays of two numbers (and not read as a deeper level of nesting either).
const BAD_POSITIONS = [null, undefined, 0, 'xy', [], [1], [, 1], [1, ,], ['1', '2'], new Float64Array([1, 2]),
  { 0: 1, 1: 2, length: 2 }, Symbol('p'), {}, [1n, 2n]];
const GOOD_FILL_RULES = ['evenodd', 'nonzero', 'positive', 'negative', 'structure'];
const BAD_FILL_RULES = ['winding', 'EvenOdd', '', 'toString', 'constructor', '__proto__', 'hasOwnProperty', 0, 1, true,
  Symbol('rule'), ['nonzero'], { toString: () => 'nonzero' }, 1n];
const BAD_OPERATION_NAMES = ['Union', '', 'toString', 'constructor', '__proto__', 'valueOf', 0, 1, null, undefined,
  Symbol('op'), ['union'], { toString: () => 'union' }, 1n];

// A 3 x 3 square ring with `value` as vertex `v`, as Polygon coordinates.
const withVertex = (value, v = 2) => { const ring = [[0, 0], [3, 0], [3, 3], [0, 3]]; ring[v] = value; return [ring]; };
const throwingArray = () => Object.defineProperty([], 0, { get() { throw new Error('getter threw'); }, enumerable: true });
const deep = (n) => { let a = [[0, 0]]; for (let i = 0; i < n; i++) a = [a]; return a; };
const hugeSparseRing = () => { const ring = []; ring.length = 2 ** 32 - 1; return ring; };
const selfFeature = () => { const f = { type: 'Feature', properties: null }; f.geometry = f; return f; };
const selfCollection = () => { const c = { type: 'GeometryCollection' }; c.geometries = [c]; return c; };
const nestedCollections = (n) => { let g = { type: 'Polygon', coordinates: A }; for (let i = 0; i < n; i++) g = { type: 'GeometryCollection', geometries: [g] }; return g; };
const feature = (geometry) => ({ type: 'Feature', properties: null, geometry });
const featureCollection = (...geometries) => ({ type: 'FeatureCollection', features: geometries.map(feature) });
const lineString = { type: 'LineString', coordinates: [[0, 0], [1, 1]] };
const flatSquare = (x, y) => flatOf([square(x, y)]);

const HAND_CASES = [
  ['no operand', () => union(), /operand/],
  ...JUNK.flatMap((j, i) => [
    [`junk ${i} alone`, () => union(j), { ifThrows: /operand 0/ }],
    [`junk ${i} first`, () => intersection(j, A), /operand 0/],
    [`junk ${i} in n-ary`, () => xor(A, A, j, A), /operand 2/],
    [`junk ${i} as a polygon`, () => difference(A, [square(0, 0), j]), { ifThrows: /operand 1/ }],
    [`junk ${i} as a ring`, () => union(A, [[...square(5, 5), j]]), { ifThrows: /operand 1/ }],
  ]),
  ...BAD_COORDINATES.flatMap((c, i) => [
    [`bad x ${i}`, () => union(A, withVertex([c, 1])), at(1, 0, 0, 2)],
    [`bad y ${i}`, () => union(A, withVertex([1, c])), at(1, 0, 0, 2)],
    [`bad first x ${i}`, () => union(A, withVertex([c, 1], 0)), at(1, 0, 0, 0)],
  ]),
  ...ODD_VALID_COORDINATES.map((c, i) => [`odd valid coordinate ${i}`, () => union(A, withVertex([c, c])), 'returns']),
  ...BAD_POSITIONS.flatMap((p, i) => [
    [`bad position ${i}`, () => union(A, withVertex(p)), at(1, 0, 0, 2)],
    [`bad first position ${i}`, () => union(A, withVertex(p, 0)), at(1, 0, 0, 0)],
    [`bad position ${i} in a MultiPolygon`, () => union(A, [square(5, 5), [square(9, 9)[0], withVertex(p)[0]]]), at(1, 1, 1, 2)],
  ]),
  ['sparse ring', () => union(A, [[[0, 0], , [1, 1], [0, 1]]]), at(1, 0, 0, 1)],
  ['sparse polygon', () => union(A, [, [[0, 0], [1, 1], [0, 1]]]), { ifThrows: /operand 1/ }],
  // Valid though odd; areas worked out by hand (A is 2 x 2, withVertex's ring 3 x 3 around it).
  ['position with altitude', () => union(A, withVertex([3, 3, 7])), 9],
  ['-0 coordinates', () => union(A, [[[-0, -0], [3, -0], [3, 3], [-0, 3]]]), 9],
  ['coordinates of 2^-200', () => union(A, square(2 ** -200, 2 ** -200, 2 ** -200)), 4],
  ['coordinates of 2^199', () => intersection(square(-(2 ** 199), -(2 ** 199), 2 ** 200), A), 4],
  ['rings of 0, 1, 2 positions', () => union([[]], [[[0, 0]]], [[[0, 0], [1, 1]]]), 0],
  ['empty at every level', () => xor([], [[]], [[[]]], [[], [[]]]), 0],
  // (Read by its structure, the default, a polygon is its exterior less its holes: nothing here. Even-odd reads
  // the remaining ring alone.)
  ['Polygon whose first ring is empty', () => union([[], [[5, 5], [7, 5], [7, 7], [5, 7]]]), 0],
  ['Polygon whose first ring is empty, even-odd', () => union([[], [[5, 5], [7, 5], [7, 7], [5, 7]]], { fillRule: 'evenodd' }), 4],
  ['position with two extra ordinates', () => union(A, withVertex([3, 3, 7, 1e300])), 9],
  // Collections, null geometries and skipped members (A is 2 x 2 at 0,0; square(1, 1) 2 x 2 at 1,1: 7 together).
  ['empty GeometryCollection', () => union(A, { type: 'GeometryCollection', geometries: [] }, square(1, 1)), 7],
  ['empty FeatureCollection', () => union(A, { type: 'FeatureCollection', features: [] }, square(1, 1)), 7],
  ['FeatureCollection of A', () => union(A, featureCollection({ type: 'Polygon', coordinates: A }), square(1, 1)), 7],
  ['Feature with null geometry', () => union(A, feature(null), square(1, 1)), 7],
  ['Feature with null geometry alone', () => union(feature(null)), 0],
  ['null geometries in a FeatureCollection', () => union(featureCollection(null, { type: 'Polygon', coordinates: A }, null)), 4],
  ['GeometryCollections 32 deep', () => union(nestedCollections(32)), 4],
  ['LineString skipped', () => union(A, lineString, { skipNonPolygonal: true }), 4],
  ['Point member skipped', () => union(featureCollection({ type: 'Point', coordinates: [9, 9] }, { type: 'Polygon', coordinates: A }), { skipNonPolygonal: true }), 4],
  ['skipNonPolygonal null means the default', () => union(A, { skipNonPolygonal: null }), 4],
  ['positive fill rule', () => union(A, square(1, 1), { fillRule: 'positive' }), 7],
  ['negative fill rule', () => union(A, square(1, 1), { fillRule: 'negative' }), 0],
  ['fillRule null means the default', () => union(A, { fillRule: null }), 4],
  ['flat with no operands', () => overlayFlat('union', []), 0],
  // Wrong as operand 1, whatever the kind.
  ...[
    ['ring of length 2^32 - 1, all holes', [[hugeSparseRing()]]], ['10,000 levels deep', deep(10000)],
    ['a ring without nesting', [[0, 0], [1, 0], [1, 1]]], ['a position without nesting', [0, 0]], ['5 levels deep', [[square(0, 0)]]],
    ['Polygon without coordinates', { type: 'Polygon' }], ['MultiPolygon with null coordinates', { type: 'MultiPolygon', coordinates: null }],
    ['MultiPolygon coordinates as a Polygon', { type: 'Polygon', coordinates: [A] }],
    ['Polygon coordinates as a MultiPolygon', { type: 'MultiPolygon', coordinates: A }],
    ['lower-case type', { type: 'polygon', coordinates: A }], ['Point', { type: 'Point', coordinates: [0, 0] }],
    ['type that is a BigInt', { type: 1n, coordinates: A }],
    ['Feature without geometry', { type: 'Feature', properties: {} }], ['Feature of itself', selfFeature()],
    ['LineString', lineString], ['Feature of a LineString', feature(lineString)],
    ['GeometryCollection without geometries', { type: 'GeometryCollection' }], ['FeatureCollection with null features', { type: 'FeatureCollection', features: null }],
    ['GeometryCollection holding itself', selfCollection()], ['GeometryCollections 33 deep', nestedCollections(33)],
    ['FeatureCollection of a geometry', { type: 'FeatureCollection', features: [{ type: 'Polygon', coordinates: A }] }],
    ['FeatureCollection of a FeatureCollection', { type: 'FeatureCollection', features: [featureCollection()] }],
    ['GeometryCollection of a Feature', { type: 'GeometryCollection', geometries: [feature(null)] }],
    ['GeometryCollection with a null member', { type: 'GeometryCollection', geometries: [null] }],
  ].map(([name, operand]) => [name, () => union(A, operand, square(1, 1)), /operand 1/]),
  ['Feature with a bad vertex', () => union(A, A, { type: 'Feature', geometry: { type: 'MultiPolygon', coordinates: [A, withVertex([NaN, 0])] } }), at(2, 1, 0, 2)],
  // In a collection, the member is named and the polygon counted within it, for the core's errors (NaN, range)
  // and the package's own (shape) alike.
  ...[[NaN, 0], [1e300, 0], [0, 'x'], [0]].flatMap((bad, i) => [
    [`bad vertex ${i} in feature 2`, () => union(A, featureCollection(null, { type: 'Polygon', coordinates: A }, { type: 'MultiPolygon', coordinates: [A, withVertex(bad)] })), at(1, 1, 0, 2, ', feature 2')],
    [`bad vertex ${i} in a nested geometry`, () => xor(A, A, { type: 'GeometryCollection', geometries: [{ type: 'Polygon', coordinates: A }, { type: 'GeometryCollection', geometries: [{ type: 'Polygon', coordinates: withVertex(bad) }] }] }), at(2, 0, 0, 2, ', geometry 1, geometry 0')],
    [`bad vertex ${i} in a feature's GeometryCollection`, () => union(featureCollection({ type: 'GeometryCollection', geometries: [{ type: 'MultiPolygon', coordinates: [A, A, withVertex(bad)] }] })), at(0, 2, 0, 2, ', feature 0, geometry 0')],
  ]),
  ['LineString in a FeatureCollection', () => union(A, featureCollection(null, null, null, lineString)), /^operand 1, feature 3: a LineString is not a polygon/],
  ['Point in a GeometryCollection', () => union(A, { type: 'GeometryCollection', geometries: [{ type: 'Point', coordinates: [0, 0] }] }), /^operand 1, geometry 0: a Point is not a polygon/],
  ['bad member type in a collection', () => union(A, featureCollection({ type: 'Polygon', coordinates: A }, { type: 'Circle' })), /^operand 1, feature 1: expected a Polygon/],
  ['a junk member is not skipped', () => union(A, featureCollection({ type: 'polygon', coordinates: A }), { skipNonPolygonal: true }), /^operand 1, feature 0: expected a Polygon/],
  ...[0, 1, 'yes', {}, 1n].map((value, i) => [`skipNonPolygonal ${i}`, () => union(A, lineString, { skipNonPolygonal: value }), /skipNonPolygonal/]),
  ['skipNonPolygonal between operands', () => union(A, { skipNonPolygonal: true }, A), /operand 1: options/],
  ['getter that throws, as a ring', () => union(A, [throwingArray()]), /getter threw/],
  ['getter that throws, as a position', () => union(A, [[[0, 0], [1, 0], throwingArray()]]), /getter threw/],
  ['geometry type getter that throws', () => union(A, { get type() { throw new Error('getter threw'); } }), /getter threw/],
  ['fillRule getter that throws', () => union(A, { get fillRule() { throw new Error('getter threw'); } }), /getter threw/],
  ...BAD_FILL_RULES.map((rule, i) => [`fillRule ${i}`, () => union(A, square(1, 1), { fillRule: rule }), /fillRule/]),
  ['options between operands', () => union(A, { fillRule: 'nonzero' }, A), /operand 1/], ['options first', () => union({ fillRule: 'nonzero' }, A), /operand 0/],
  ['options only', () => union({ fillRule: 'nonzero' }), /operand 0/], ['options twice', () => union(A, { fillRule: 'nonzero' }, {}), /operand 1/],
  ...BAD_OPERATION_NAMES.map((op, i) => [`operation name ${i}`, () => overlayFlat(op, [flatSquare(0, 0), flatSquare(1, 1)]), /operation/]),
  ...[null, undefined, 'x', {}, flatSquare(0, 0)].map((ops, i) => [`operands ${i}`, () => overlayFlat('union', ops), /operands/]),
  ...BAD_FILL_RULES.map((rule, i) => [`flat fillRule ${i}`, () => overlayFlat('union', [flatSquare(0, 0)], { fillRule: rule }), /fillRule/]),
  ...['nonzero', 1, true].map((options, i) => [`flat options ${i}`, () => overlayFlat('xor', [flatSquare(0, 0)], options), /options/]),
  ['flat NaN', () => overlayFlat('union', [flatSquare(0, 0), { ...flatSquare(1, 1), coords: Float64Array.of(1, 1, 3, 1, NaN, 3, 1, 3, 1, 1) }]), at(1, 0, 0, 2)],
  // Wrong as operand 1 of 3, so that nothing may spill over into a neighbour.
  ...[null, {}, [], { coords: [0, 0] }].map((operand, i) => [`flat operand ${i}`, () => overlayFlat('union', [flatSquare(0, 0), operand, flatSquare(9, 9)]), /operand 1\b/]),
  ...[
    ['coords of odd length', { coords: Float64Array.of(1, 1, 3, 1, 3, 3, 1, 3, 1, 1, 1) }],
    ['coords as an Array', { coords: [1, 1, 3, 1, 3, 3, 1, 3, 1, 1] }], ['coords as a Float32Array', { coords: new Float32Array(10) }],
    ['ring offsets as an Int32Array', { ringOffsets: Int32Array.of(0, 5) }], ['ring offsets empty', { ringOffsets: new Uint32Array(0) }],
    ['polygon offsets as a Uint16Array', { polygonOffsets: Uint16Array.of(0, 1) }], ['polygon offsets empty', { polygonOffsets: new Uint32Array(0) }],
    ['ring offsets not from 0', { ringOffsets: Uint32Array.of(1, 5) }], ['ring offset 2^32 - 1', { ringOffsets: Uint32Array.of(0, 2 ** 32 - 1) }],
    ['ring offsets short of the end', { ringOffsets: Uint32Array.of(0, 4) }], ['ring offsets past the end', { ringOffsets: Uint32Array.of(0, 6) }],
    ['ring offsets decreasing', { ringOffsets: Uint32Array.of(0, 4, 3, 5), polygonOffsets: Uint32Array.of(0, 3) }],
    ['ring offsets 2^31 apart', { ringOffsets: Uint32Array.of(0, 2 ** 31, 2 ** 31 + 5), polygonOffsets: Uint32Array.of(0, 2) }],
    ['polygon offsets not from 0', { polygonOffsets: Uint32Array.of(1, 1) }], ['polygon offsets past the rings', { polygonOffsets: Uint32Array.of(0, 2) }],
    ['polygon offset 2^32 - 1', { polygonOffsets: Uint32Array.of(0, 2 ** 32 - 1) }],
  ].map(([name, changes]) => [`flat ${name}`, () => overlayFlat('union', [flatSquare(0, 0), { ...flatSquare(1, 1), ...changes }, flatSquare(9, 9)]), /operand 1\b/]),
];

// No timed assertions (these machines are noisy): a call that hangs blocks the run, which CI's time limit fails.
test(`${HAND_CASES.length} hand-written bad inputs`, () => {
  for (const [name, call, expect] of HAND_CASES) check(name, call, expect);
});

// ---- Generated cases (mulberry32: small, seeded, the same cases every run) ----
let seed = 20240611;
function random() {
  seed = (seed + 0x6d2b79f5) | 0;
  let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
}
const below = (n) => Math.floor(random() * n);
const pick = (list) => list[below(list.length)];
const randomMultiPolygon = () => Array.from({ length: 1 + below(3) }, () =>
  Array.from({ length: 1 + below(2) }, () => Array.from({ length: 3 + below(4) }, () => [below(9) - 4, below(9) - 4])));

const FORMS = ['polygon', 'multipolygon', 'geometry', 'feature', 'featureCollection', 'geometryCollection'];
/** A form to pass MultiPolygon coordinates in (Polygon coordinates only when there is one polygon). */
const randomForm = (mp) => pick(mp.length === 1 ? FORMS : FORMS.slice(1));
// What errors call the collection member the polygons are put in by inForm.
const MEMBER = { featureCollection: ', feature 1', geometryCollection: ', geometry 1' };

/** MultiPolygon coordinates in `form`; a collection holds them as its second member, after an empty one. */
function inForm(mp, form) {
  if (form === 'polygon' || form === 'multipolygon') return form === 'polygon' ? mp[0] : mp;
  const geometry = { type: 'MultiPolygon', coordinates: mp };
  if (form === 'geometry') return geometry;
  if (form === 'feature') return { type: 'Feature', properties: { form }, geometry };
  if (form === 'featureCollection') return { type: 'FeatureCollection', features: [{ type: 'Feature', properties: null, geometry: null }, { type: 'Feature', properties: null, geometry }] };
  return { type: 'GeometryCollection', geometries: [{ type: 'GeometryCollection', geometries: [] }, geometry] };
}

/**
 * Puts one bad (or oddly valid) thing somewhere in operand `o`'s polygons `mp`, and says what must happen;
 * `member` names the collection member they are in, if any.
 */
function mutate(mp, o, member) {
  const p = below(mp.length), r = below(mp[p].length), v = below(mp[p][r].length);
  switch (below(5)) {
    case 0: mp[p][r][v] = [...mp[p][r][v]]; mp[p][r][v][below(2)] = pick(BAD_COORDINATES); return at(o, p, r, v, member);
    case 1: mp[p][r][v] = pick(BAD_POSITIONS); return at(o, p, r, v, member);
    case 2: mp[p][r][v] = mp[p][r][v].map((c) => (random() < 0.5 ? c : pick(ODD_VALID_COORDINATES))); return 'returns';
    case 3: if (random() < 0.5) mp[p][r] = pick(JUNK); else delete mp[p][r]; return { ifThrows: new RegExp(`operand ${o}\\b`) };
    default: mp[p] = random() < 0.5 ? pick(JUNK) : [mp[p]]; return { ifThrows: new RegExp(`operand ${o}\\b`) };
  }
}

test('3,000 generated nested calls, one bad thing each', () => {
  let threw = 0;
  for (let i = 0; i < 3000; i++) {
    const polygons = Array.from({ length: 1 + below(4) }, randomMultiPolygon);
    const bad = below(polygons.length);
    const forms = polygons.map(randomForm);
    let expect = mutate(polygons[bad], bad, MEMBER[forms[bad]] ?? '');
    const operands = polygons.map((mp, o) => inForm(mp, forms[o]));
    if (random() < 0.2) {
      const rule = random() < 0.5 ? pick([...GOOD_FILL_RULES, undefined]) : pick(BAD_FILL_RULES);
      operands.push({ fillRule: rule });
      if (![...GOOD_FILL_RULES, undefined].includes(rule)) expect = /fillRule/;
    }
    const name = pick(Object.keys(OPERATIONS));
    threw += check(`generated ${i}: ${name}`, () => OPERATIONS[name](...operands), expect);
  }
  assert.ok(threw > 1000 && threw < 3000, `${threw} of 3000 threw: the generator mixes good and bad as meant`);
});

test('1,000 generated flat calls, one bad thing each', () => {
  for (let i = 0; i < 1000; i++) {
    const operands = Array.from({ length: 1 + below(3) }, () => flatOf(randomMultiPolygon()));
    const o = below(operands.length);
    const { coords, ringOffsets, polygonOffsets } = operands[o];
    let expect = new RegExp(`operand ${o}\\b`);
    switch (below(6)) {
      case 0: { // A bad number at a vertex: find its polygon and ring.
        const v = below(coords.length / 2);
        const r = ringOffsets.findLastIndex((start) => start <= v && start < ringOffsets.at(-1));
        const p = polygonOffsets.findLastIndex((start) => start <= r && start < polygonOffsets.at(-1));
        coords[2 * v + below(2)] = pick([NaN, Infinity, -Infinity, 1e308, 5e-324]);
        expect = at(o, p, r - polygonOffsets[p], v - ringOffsets[r]);
        break;
      }
      case 1: { // Odd length, or one vertex too few or too many for the ring offsets.
        const changed = [...coords];
        pick([() => changed.push(1), () => changed.pop(), () => changed.splice(-2), () => changed.unshift(0, 0)])();
        operands[o].coords = Float64Array.from(changed);
        break;
      }
      case 2: case 3: { // Offsets not from 0, not to the end (moving an inner one by 1 can be valid), or far out.
        const offsets = pick([ringOffsets, polygonOffsets]);
        const k = random() < 0.5 ? pick([0, offsets.length - 1]) : below(offsets.length);
        offsets[k] = k === 0 || k === offsets.length - 1 ? offsets[k] + pick([1, -1]) : pick([offsets[k] + 2 ** 31, 2 ** 32 - 1]);
        break;
      }
      case 4: operands[o][pick(['coords', 'ringOffsets', 'polygonOffsets'])] = pick([[], new Int32Array(2), new Float32Array(2), null, {}]); break;
      default: operands[o] = pick(JUNK);
    }
    check(`flat ${i}`, () => overlayFlat(pick(Object.keys(OPERATIONS)), operands, pick([undefined, { fillRule: pick(GOOD_FILL_RULES) }])), expect);
  }
});

// Running out of memory (issue 24): 1,000 × 1,000 crossing bars need about 1 GiB; in a Node limited to 256 MiB of
// wasm memory (`--wasm-max-mem-pages`, standing in for wasm32's 4 GiB) the operation fails with a RangeError that
// says so and gives the sizes, and the module answers the next call.
test('running out of memory is a named error, and the module keeps working', async () => {
  const { spawnSync } = await import('node:child_process');
  const script = `
    import { intersection, union } from ${JSON.stringify(new URL('../../pkg/polysweep.node.js', import.meta.url).href)};
    const n = 1000, length = 2 * n;
    const bars = (vertical) => Array.from({ length: n }, (_, i) => {
      const ring = [[0, 2 * i], [length, 2 * i], [length, 2 * i + 1], [0, 2 * i + 1], [0, 2 * i]];
      return [vertical ? ring.map(([a, b]) => [b, a]) : ring];
    });
    let failure = null;
    try { intersection(bars(false), bars(true)); } catch (error) { failure = { name: error.constructor.name, message: error.message }; }
    const after = union([[[0, 0], [1, 0], [1, 1], [0, 1]]], [[[1, 0], [2, 0], [2, 1], [1, 1]]]);
    console.log(JSON.stringify({ failure, after }));
  `;
  const child = spawnSync(process.execPath, ['--wasm-max-mem-pages=4096', '--input-type=module', '-e', script], {
    encoding: 'utf8',
  });
  assert.equal(child.status, 0, child.stderr);
  const { failure, after } = JSON.parse(child.stdout);
  assert.equal(failure?.name, 'RangeError', JSON.stringify(failure));
  assert.match(failure.message, /^out of memory: the operation on 8000 edges ran out of memory with \d+ crossings found$/);
  assert.doesNotMatch(failure.message, ENGINE_MESSAGE);
  assertMultiPolygon(after);
  assert.equal(after.length, 1);
  assert.equal(area(after), 2);
});
