// The package's contract beyond the fixtures: argument forms, results in kind, options, the flat form, errors,
// and that the module keeps working after an error.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { union, intersection, difference, xor, overlayFlat } from 'polysweep';

const square = (x, y, s = 2) => [[[x, y], [x + s, y], [x + s, y + s], [x, y + s], [x, y]]];
const area = (mp) =>
  mp.reduce(
    (sum, polygon) =>
      sum +
      polygon.reduce((s, ring, i) => {
        let twice = 0;
        for (let k = 0; k + 1 < ring.length; k++) twice += ring[k][0] * ring[k + 1][1] - ring[k + 1][0] * ring[k][1];
        return s + twice / 2 * (i === 0 ? 1 : 1);
      }, 0),
    0,
  );

test('polygon-clipping calling convention on coordinates', () => {
  const a = square(0, 0);
  const b = square(1, 1);
  assert.equal(area(intersection(a, b)), 1);
  assert.equal(area(union(a, b)), 7);
  assert.equal(area(difference(a, b)), 3);
  assert.equal(area(xor(a, b)), 6);
  // More than two operands, Polygon and MultiPolygon coordinates mixed, open rings accepted.
  const open = [[[4, 0], [6, 0], [6, 2], [4, 2]]];
  assert.equal(area(union(a, [b], open)), 11);
  assert.equal(area(difference(square(0, 0, 10), a, [square(4, 4)], open)), 100 - 12);
  assert.deepEqual(intersection(a, square(5, 5)), []);
});

test('exteriors counter-clockwise, holes clockwise, rings closed', () => {
  const [[exterior, hole]] = difference(square(0, 0, 4), square(1, 1, 1));
  assert.ok(area([[exterior]]) > 0);
  let twice = 0;
  for (let k = 0; k + 1 < hole.length; k++) twice += hole[k][0] * hole[k + 1][1] - hole[k + 1][0] * hole[k][1];
  assert.ok(twice < 0);
  assert.deepEqual(hole[0], hole[hole.length - 1]);
});

test('GeoJSON geometries and features answer in kind', () => {
  const geometry = { type: 'Polygon', coordinates: square(0, 0)[0] ? square(0, 0) : [] };
  const result = union(geometry, square(1, 1));
  assert.equal(result.type, 'MultiPolygon');
  assert.equal(area(result.coordinates), 7);
  const feature = { type: 'Feature', properties: { name: 'a' }, geometry: { type: 'MultiPolygon', coordinates: [square(0, 0)] } };
  const other = { type: 'Feature', properties: { name: 'b' }, geometry: { type: 'Polygon', coordinates: square(1, 1) } };
  const out = intersection(feature, other);
  assert.equal(out.type, 'Feature');
  assert.deepEqual(out.properties, { name: 'a' }, 'a feature keeps the first operand’s properties');
  assert.equal(out.geometry.type, 'MultiPolygon');
  assert.equal(area(out.geometry.coordinates), 1);
  // Coordinates first: coordinates out, whatever comes after.
  assert.ok(Array.isArray(union(square(0, 0), feature)));
});

test('fill rule option', () => {
  // Two overlapping counter-clockwise squares in one operand: a hole under even-odd, filled under non-zero and under
  // the default, polygon-clipping's structural reading (the union of the operand's polygons).
  const both = [square(0, 0), square(1, 1)];
  assert.equal(area(union(both, [])), 7);
  assert.equal(area(union(both, [], { fillRule: 'evenodd' })), 6);
  assert.equal(area(union(both, [], { fillRule: 'nonzero' })), 7);
  assert.throws(() => union(both, [], { fillRule: 'winding' }), TypeError);
});

test('flat typed-array form, in and out', () => {
  const flat = (x, y) => ({
    coords: new Float64Array([x, y, x + 2, y, x + 2, y + 2, x, y + 2, x, y]),
    ringOffsets: new Uint32Array([0, 5]),
    polygonOffsets: new Uint32Array([0, 1]),
  });
  const out = overlayFlat('union', [flat(0, 0), flat(1, 1)]);
  assert.ok(out.coords instanceof Float64Array);
  assert.deepEqual([...out.polygonOffsets], [0, 1]);
  assert.equal(out.ringOffsets.length, 2);
  assert.equal(out.coords.length / 2, out.ringOffsets[1]);
  const nested = union(square(0, 0), square(1, 1));
  assert.deepEqual([...out.coords], nested[0][0].flat());
  assert.throws(() => overlayFlat('union', [{ coords: [0, 1] }]), TypeError);
  assert.throws(() => overlayFlat('nope', []), TypeError);
});

test('bad input throws an error naming operand, polygon, ring and vertex, and the module keeps working', () => {
  const bad = [[[0, 0], [1, 0], [1, NaN], [0, 1]]];
  assert.throws(() => union(square(0, 0), [square(5, 5)[0], ...bad]), (e) => {
    assert.ok(e instanceof RangeError);
    assert.match(e.message, /operand 1, polygon 0, ring 1, vertex 2/);
    return true;
  });
  assert.throws(() => union(square(0, 0), [[[0, 0], [1, 'x']]]), (e) => {
    assert.ok(e instanceof TypeError);
    assert.match(e.message, /operand 1, polygon 0, ring 0, vertex 1/);
    return true;
  });
  assert.throws(() => union(square(0, 0), [[[0, 0], [1e300, 0], [0, 1]]]), RangeError);
  assert.throws(() => union({ type: 'LineString', coordinates: [] }), TypeError);
  // Still usable.
  assert.equal(area(union(square(0, 0), square(1, 1))), 7);
});
