// The calls the lines-and-layers fixtures (tests/fixtures/lines-and-layers) make of the package, as one function of
// a fixture and the package's API, so that Node (lines-and-layers.test.mjs) and the browser pages (plain.html) make
// the same calls; ../lines-and-layers-check.mjs compares their outcome with the fixture's expectations.
//
// This file only defines functions: `node --test web/test/` loads every .js file under a `test` directory as a test
// file, and this one must do nothing there.

const feature = (geometry, properties = null) => ({ type: 'Feature', properties, geometry });
const collection = (features) => ({ type: 'FeatureCollection', features });
const multiPolygon = (coordinates) => ({ type: 'MultiPolygon', coordinates });
const layer = (features) => collection(features.map((coordinates, i) => feature(multiPolygon(coordinates), { i })));
export const LAYER_MODES = ['union', 'intersection', 'identity', 'difference', 'xor'];

/** The outcome of `fixture`'s calls of `api` ({clip, split, overlayLayers, dissolve}): the results, by call. */
export function runLinesAndLayers(fixture, api) {
  const fillRule = fixture.fill_rule;
  switch (fixture.operation) {
    case 'clip': {
      const outcome = {};
      for (const keep of ['inside', 'outside']) {
        // Line by line (the coordinates of one line give that line's parts), and all at once as a FeatureCollection.
        outcome[keep] = fixture.lines.map((line) => api.clip(line, fixture.polygon, { keep, fillRule }));
        const lines = collection(fixture.lines.map((coordinates, i) => feature({ type: 'LineString', coordinates }, { i })));
        outcome[`${keep}Features`] = api.clip(lines, fixture.polygon, { keep, fillRule });
      }
      return outcome;
    }
    case 'split': {
      // Coordinates in, Polygon coordinates out; a Feature in, Polygon features out.
      const lines = { type: 'MultiLineString', coordinates: fixture.lines };
      return {
        pieces: api.split(fixture.polygon, lines, { fillRule }),
        features: api.split(feature(multiPolygon(fixture.polygon), { id: 7 }), lines, { fillRule }),
      };
    }
    case 'overlay_layers': {
      const [a, b] = [layer(fixture.layer_a), layer(fixture.layer_b)];
      return Object.fromEntries(LAYER_MODES.map((mode) => [mode, api.overlayLayers(a, b, { mode, fillRule })]));
    }
    case 'dissolve': {
      const features = collection(fixture.features.map((f) => feature(multiPolygon(f.polygon), { zone: f.key })));
      return { dissolved: api.dissolve(features, 'zone', { fillRule }) };
    }
    default:
      throw new Error(`unknown operation ${fixture.operation}`);
  }
}

/** In a browser page: every fixture of /lines-fixtures-index.json run, `{ [name]: outcome or { error } }`. */
export async function runLinesAndLayersFixtures(api) {
  const response = await fetch('/lines-fixtures-index.json');
  if (!response.ok) throw new Error(`GET /lines-fixtures-index.json: ${response.status}`);
  const results = {};
  for (const file of await response.json()) {
    const fixtureResponse = await fetch(`/tests/fixtures/lines-and-layers/${encodeURIComponent(file)}`);
    if (!fixtureResponse.ok) throw new Error(`GET /tests/fixtures/lines-and-layers/${file}: ${fixtureResponse.status}`);
    const fixture = await fixtureResponse.json();
    try {
      results[fixture.name] = runLinesAndLayers(fixture, api);
    } catch (error) {
      results[fixture.name] = { error: String(error?.stack ?? error) };
    }
  }
  return results;
}
