// The expectations of the lines-and-layers fixtures (tests/fixtures/lines-and-layers, from GEOS and exact rationals),
// checked on the outcome of their calls (browser/lines-and-layers.js), made in Node or in a browser.
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { normalise } from './normalise.mjs';
import { LAYER_MODES } from './browser/lines-and-layers.js';

const dir = new URL('../../tests/fixtures/lines-and-layers/', import.meta.url);
export const lineFixtureFiles = readdirSync(dir).filter((f) => f.endsWith('.json')).sort();
export const lineFixtures = lineFixtureFiles.map((f) => JSON.parse(readFileSync(new URL(f, dir), 'utf8')));

const feature = (geometry, properties = null) => ({ type: 'Feature', properties, geometry });
const collection = (features) => ({ type: 'FeatureCollection', features });

/** The faces' features in the fixtures' order: by the indices of layer A, then of layer B. */
function byTags(x, y) {
  const lists = (f) => [f.properties.aIndices, f.properties.bIndices];
  const [p, q] = [lists(x), lists(y)];
  for (let k = 0; k < 2; k++) {
    for (let i = 0; i < Math.max(p[k].length, q[k].length); i++) {
      if (p[k][i] === undefined || q[k][i] === undefined) return p[k][i] === undefined ? -1 : 1;
      if (p[k][i] !== q[k][i]) return p[k][i] - q[k][i];
    }
  }
  return 0;
}

const KEEPS = {
  intersection: (a, b) => a && b,
  union: (a, b) => a || b,
  identity: (a) => a,
  difference: (a, b) => a && !b,
  xor: (a, b) => a !== b,
};

/** Asserts that `outcome` (of runLinesAndLayers) meets `fixture`'s expectations. */
export function checkLinesAndLayers(fixture, outcome) {
  assert.equal(outcome.error, undefined, `the calls threw: ${outcome.error}`);
  const expected = fixture.expected;
  switch (fixture.operation) {
    case 'clip':
      for (const keep of ['inside', 'outside']) {
        assert.deepEqual(outcome[keep], expected[keep], keep);
        const features = expected[keep].flatMap((parts, i) => (parts.length > 0 ? [feature({ type: 'MultiLineString', coordinates: parts }, { i })] : []));
        assert.deepEqual(outcome[`${keep}Features`], collection(features), `${keep}, as features`);
      }
      return;
    case 'split': {
      assert.deepEqual(normalise(outcome.pieces), normalise(expected.pieces));
      const pieces = outcome.features.features;
      assert.deepEqual(normalise(pieces.map((f) => f.geometry.coordinates)), normalise(expected.pieces));
      assert.ok(pieces.every((f) => f.properties.id === 7 && f.geometry.type === 'Polygon'), 'Polygon features with their properties');
      return;
    }
    case 'overlay_layers': {
      const faces = [...outcome.union.features].sort(byTags);
      assert.deepEqual(faces.map((f) => [f.properties.aIndices, f.properties.bIndices]), expected.faces.map((e) => [e.a, e.b]));
      faces.forEach((face, k) => {
        const e = expected.faces[k];
        assert.deepEqual(normalise(face.geometry.coordinates), normalise(e.polygon));
        // The properties of the first covering feature of each layer.
        assert.deepEqual(face.properties.a, e.a.length > 0 ? { i: e.a[0] } : null);
        assert.deepEqual(face.properties.b, e.b.length > 0 ? { i: e.b[0] } : null);
      });
      // Every mode is a filter over the same faces.
      for (const mode of LAYER_MODES) {
        const kept = faces.filter((f) => KEEPS[mode](f.properties.aIndices.length > 0, f.properties.bIndices.length > 0));
        assert.deepEqual([...outcome[mode].features].sort(byTags).map((f) => f.properties), kept.map((f) => f.properties), mode);
      }
      return;
    }
    case 'dissolve': {
      const merged = [...outcome.dissolved.features].sort((x, y) => (x.properties.zone < y.properties.zone ? -1 : 1));
      assert.deepEqual(merged.map((f) => f.properties), expected.groups.map((g) => ({ zone: g.key })));
      merged.forEach((f, k) => assert.deepEqual(normalise(f.geometry.coordinates), normalise(expected.groups[k].polygon)));
      return;
    }
    default:
      assert.fail(`unknown operation ${fixture.operation}`);
  }
}
