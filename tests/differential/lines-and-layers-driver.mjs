// Runs polysweep's clip, split, overlayLayers and dissolve on every case of a JSON file in one Node process, for
// tests/differential/lines_and_layers.py. Usage: node lines-and-layers-driver.mjs cases.json results.json
// A case is one of (fill 'default' calls without a fillRule):
//   { op: 'clip', lines: [line, ...], polygon, fill }  -> { inside, outside, insideOpen, outsideOpen }: per line its
//       parts, for keep 'inside' and 'outside' with the default boundary rule (parts along the boundary inside) and
//       with boundary: 'outside' ("Open"); the lines go in as a FeatureCollection of LineStrings, one per line.
//   { op: 'split', polygon, lines, fill }               -> { pieces: [Polygon coordinates, ...] }
//   (clip and split under the structural reading also give readAs: the polygon set as union(polygon) writes it)
//   { op: 'overlay', layerA: [MultiPolygon, ...], layerB, fill } -> { faces: [{ a, b, coordinates }, ...] } (mode
//       'union': aIndices, bIndices, MultiPolygon coordinates)
//   { op: 'dissolve', features: [{ key, polygon }], fill } -> { groups: [{ key, coordinates }, ...] }
// Errors are caught per case and reported as strings.
import { readFileSync, writeFileSync } from 'node:fs';
import { clip, dissolve, overlayLayers, split, union } from 'polysweep';

const [, , inPath, outPath] = process.argv;
const cases = JSON.parse(readFileSync(inPath, 'utf8'));

const feature = (geometry, properties) => ({ type: 'Feature', properties, geometry });
const collection = (features) => ({ type: 'FeatureCollection', features });
const fillOf = (c) => (c.fill === 'default' ? {} : { fillRule: c.fill });

// Under the structural reading (the default) the polygon set is first made valid and written in doubles, as the
// union of it alone writes it: returned as readAs, to check clip and split against what they read.
const readAs = (c) => (c.fill === 'structure' || c.fill === 'default' ? { readAs: union(c.polygon) } : {});

const run = {
  clip(c) {
    const lines = collection(c.lines.map((coordinates, i) => feature({ type: 'LineString', coordinates }, { i })));
    const out = {};
    for (const [name, keep, boundary] of [['inside', 'inside', 'inside'], ['outside', 'outside', 'inside'],
      ['insideOpen', 'inside', 'outside'], ['outsideOpen', 'outside', 'outside']]) {
      const perLine = c.lines.map(() => []);
      for (const f of clip(lines, c.polygon, { keep, boundary, ...fillOf(c) }).features) perLine[f.properties.i].push(...f.geometry.coordinates);
      out[name] = perLine;
    }
    return Object.assign(out, readAs(c));
  },
  split(c) {
    return { pieces: split(c.polygon, c.lines, fillOf(c)), ...readAs(c) };
  },
  overlay(c) {
    const layer = (features) => collection(features.map((coordinates, i) => feature({ type: 'MultiPolygon', coordinates }, { i })));
    const result = overlayLayers(layer(c.layerA), layer(c.layerB), { mode: 'union', ...fillOf(c) });
    return { faces: result.features.map((f) => ({ a: f.properties.aIndices, b: f.properties.bIndices, coordinates: f.geometry.coordinates })) };
  },
  dissolve(c) {
    const features = collection(c.features.map((f) => feature({ type: 'MultiPolygon', coordinates: f.polygon }, { k: f.key })));
    return { groups: dissolve(features, 'k', fillOf(c)).features.map((f) => ({ key: f.properties.k, coordinates: f.geometry.coordinates })) };
  },
};

const started = performance.now();
const results = cases.map((c) => {
  try {
    return run[c.op](c);
  } catch (e) {
    return { error: `${e && e.name}: ${e && e.message}` };
  }
});
writeFileSync(outPath, JSON.stringify({ results, ms: performance.now() - started }));
