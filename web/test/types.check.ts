// Compiled by tsc (never run): the shipped types accept what the README shows and type results by their kind.
import { union, intersection, difference, xor, overlayFlat } from 'polysweep';
import type { MultiPolygon, MultiPolygonGeometry, MultiPolygonFeature, FlatMultiPolygon } from 'polysweep';

const a: MultiPolygon = [[[[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]]]];
const polygon = [[[1, 1], [3, 1], [3, 3], [1, 3], [1, 1]]];
const coordinates: MultiPolygon = union(a, polygon, { fillRule: 'nonzero' });
const geometry: MultiPolygonGeometry = intersection({ type: 'Polygon', coordinates: polygon }, a);
const feature: MultiPolygonFeature<{ name: string }> = difference(
  { type: 'Feature', properties: { name: 'a' }, geometry: { type: 'MultiPolygon', coordinates: a } },
  polygon,
);
const flat: FlatMultiPolygon = overlayFlat('xor', [
  { coords: new Float64Array(8), ringOffsets: new Uint32Array([0, 4]), polygonOffsets: new Uint32Array([0, 1]) },
]);
xor(a, polygon);
export { coordinates, geometry, feature, flat };
