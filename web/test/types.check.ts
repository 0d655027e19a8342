// Compiled by tsc (never run): the shipped types accept what apps hold, typed with @types/geojson, without casts,
// type results in the kind of the first operand, and reject what the functions reject (the @ts-expect-error lines:
// tsc fails if one of them typechecks after all).
import { union, intersection, difference, xor, overlayFlat } from 'polysweep';
import type { FlatMultiPolygon, MultiPolygonCoordinates, Operand, Options } from 'polysweep';
import type {
  Feature,
  FeatureCollection,
  Geometry,
  GeometryCollection,
  LineString,
  MultiPolygon,
  Point,
  Polygon,
  Position,
} from 'geojson';

/** Compiles only when `T` is exactly `U`: the results are the types written here, not just assignable to them. */
type Exactly<T, U> = (<V>() => V extends T ? 1 : 2) extends <V>() => V extends U ? 1 : 2 ? true : false;
const exactly = <T, U>(check: Exactly<T, U>) => check;

// ---- The forms an app holds ----
const ring: Position[] = [[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]];
const polygonCoordinates: Position[][] = [ring];
const multiPolygonCoordinates: Position[][][] = [[ring]];
const polygon: Polygon = { type: 'Polygon', coordinates: [[[1, 1], [3, 1], [3, 3], [1, 3], [1, 1, 5]]] };
const multiPolygon: MultiPolygon = { type: 'MultiPolygon', coordinates: multiPolygonCoordinates };
const geometryCollection: GeometryCollection = { type: 'GeometryCollection', geometries: [polygon, multiPolygon] };
const lineString: LineString = { type: 'LineString', coordinates: [[0, 0], [1, 1]] };
const point: Point = { type: 'Point', coordinates: [0, 0] };
interface Parcel {
  name: string;
  area?: number;
}
const lineFeature: Feature<LineString> = { type: 'Feature', properties: null, geometry: lineString };
const parcel: Feature<Polygon | MultiPolygon, Parcel> = { type: 'Feature', properties: { name: 'a' }, geometry: polygon };
const polygonFeature: Feature<Polygon> = { type: 'Feature', properties: null, geometry: polygon };
const unlocated: Feature<null, Parcel> = { type: 'Feature', properties: { name: 'b' }, geometry: null };
const collectionFeature: Feature<GeometryCollection> = { type: 'Feature', properties: {}, geometry: geometryCollection };
const featureCollection: FeatureCollection = { type: 'FeatureCollection', features: [parcel, lineFeature] };
const withUnlocated: FeatureCollection<Geometry | null> = { type: 'FeatureCollection', features: [parcel, unlocated] };
const parcels: FeatureCollection<Polygon | MultiPolygon, Parcel> = { type: 'FeatureCollection', features: [parcel] };
const anyFeature: Feature = lineFeature;
const anyGeometry: Geometry = lineString;

// ---- Results in kind ----
const fromCoordinates = union(polygonCoordinates, multiPolygonCoordinates, { fillRule: 'nonzero' });
exactly<typeof fromCoordinates, MultiPolygonCoordinates>(true);
exactly<typeof fromCoordinates, Position[][][]>(true);
const fromPolygon = intersection(polygon, multiPolygonCoordinates);
exactly<typeof fromPolygon, MultiPolygon>(true);
const fromMultiPolygon = xor(multiPolygon, polygon, parcel);
exactly<typeof fromMultiPolygon, MultiPolygon>(true);
const fromGeometryCollection = union(geometryCollection);
exactly<typeof fromGeometryCollection, MultiPolygon>(true);
const fromParcel = difference(parcel, polygon, featureCollection, { fillRule: 'positive' });
exactly<typeof fromParcel, Feature<MultiPolygon, Parcel>>(true);
const name: string = fromParcel.properties.name;
const fromFeature = union(polygonFeature, collectionFeature);
exactly<typeof fromFeature, Feature<MultiPolygon, Feature<Polygon>['properties']>>(true);
const fromUnlocated = union(unlocated, polygon);
exactly<typeof fromUnlocated, Feature<MultiPolygon, Parcel>>(true);
const fromFeatureCollection = union(featureCollection);
exactly<typeof fromFeatureCollection, FeatureCollection<MultiPolygon, null>>(true);
const fromParcels = intersection(parcels, geometryCollection, withUnlocated, { fillRule: 'negative' });
exactly<typeof fromParcels, FeatureCollection<MultiPolygon, null>>(true);
// A first operand whose type is a union of kinds gives the union of their results.
const either = Math.random() < 0.5 ? polygon : parcel;
const fromEither = union(either, polygon);
exactly<typeof fromEither, MultiPolygon | Feature<MultiPolygon, Parcel>>(true);
// A function generic in the properties keeps them.
function merge<P>(feature: Feature<Polygon | MultiPolygon, P>, other: Operand): Feature<MultiPolygon, P> {
  return union(feature, other);
}
// Inline literals, as in the README.
union([[[0, 0], [2, 0], [2, 2], [0, 2]]], [[[[1, 1], [3, 1], [3, 3], [1, 3]]]], { fillRule: 'evenodd' });
union({ type: 'Feature', properties: { id: 7 }, geometry: { type: 'Polygon', coordinates: polygonCoordinates } }).properties.id;
const options: Options = { fillRule: 'nonzero', skipNonPolygonal: false };
union(polygon, polygon, options);

// ---- Non-polygonal members: accepted inside collections (checked when read), skipped with the option ----
union({ type: 'GeometryCollection', geometries: [polygon, lineString] }, { skipNonPolygonal: true });
union(featureCollection, { type: 'FeatureCollection', features: [lineFeature] });
const skipped = union(lineFeature, point, anyFeature, anyGeometry, polygon, { skipNonPolygonal: true });
exactly<typeof skipped, Feature<MultiPolygon, Feature<LineString>['properties']>>(true);
exactly<ReturnType<typeof lineStringAlone>, MultiPolygon>(true);
function lineStringAlone() {
  return xor(lineString, { skipNonPolygonal: true, fillRule: 'nonzero' });
}

// ---- What must not typecheck ----
// @ts-expect-error a LineString Feature holds no polygon
union(lineFeature, polygon);
// @ts-expect-error nor does a Point, as a later operand
intersection(polygon, point);
// @ts-expect-error a Feature of any geometry may hold a LineString: narrow it, or pass { skipNonPolygonal: true }
union(anyFeature);
// @ts-expect-error the option must say true to widen what is accepted
union(lineFeature, { skipNonPolygonal: false });
// @ts-expect-error an unknown fill rule
union(polygon, { fillRule: 'winding' });
// @ts-expect-error fill rule names are lower case
union(polygon, polygon, { fillRule: 'NonZero' });
// @ts-expect-error options go last
union(polygon, { fillRule: 'nonzero' }, polygon);
// @ts-expect-error options are not an operand
union({ fillRule: 'nonzero' });
// @ts-expect-error at least one operand
union();
// @ts-expect-error positions are numbers
union([[['0', '0']]]);
// @ts-expect-error a FeatureCollection result is not a Feature
const notAFeature: Feature<MultiPolygon> = union(featureCollection);
// @ts-expect-error a geometry result is not coordinates
const notCoordinates: MultiPolygonCoordinates = union(polygon);
// @ts-expect-error a Feature's result keeps the properties' type
const wrongProperties: Feature<MultiPolygon, { id: number }> = union(parcel);

// ---- The flat form ----
const flat: FlatMultiPolygon = overlayFlat(
  'xor',
  [{ coords: new Float64Array(8), ringOffsets: new Uint32Array([0, 4]), polygonOffsets: new Uint32Array([0, 1]) }],
  { fillRule: 'positive' },
);
// @ts-expect-error an unknown operation
overlayFlat('subtract', []);

export { fromCoordinates, name, merge, flat, skipped, notAFeature, notCoordinates, wrongProperties };

// ---- Lines and layers ----
import { clip, split, overlayLayers, dissolve } from 'polysweep';
import type { LayerFaceProperties } from 'polysweep';
import type { MultiLineString } from 'geojson';

const road: Feature<LineString, { name: string }> = { type: 'Feature', properties: { name: 'A1' }, geometry: lineString };
exactly<Feature<MultiLineString, { name: string }>, typeof clippedRoad>(true);
const clippedRoad = clip(road, polygon, { keep: 'outside', boundary: 'inside' });
exactly<MultiLineString, ReturnType<typeof clip<LineString>>>(true);
exactly<Position[][], ReturnType<typeof clip<Position[]>>>(true);
// @ts-expect-error: keep is 'inside' or 'outside'
clip(lineString, polygon, { keep: 'middle' });

type Lot = { parcel: string };
type Zone = { zone: number };
const lots: FeatureCollection<Polygon, Lot> = { type: 'FeatureCollection', features: [{ type: 'Feature', properties: { parcel: 'P1' }, geometry: polygon }] };
const zones: Feature<MultiPolygon, Zone>[] = [{ type: 'Feature', properties: { zone: 3 }, geometry: multiPolygon }];
const pieces = split(lots, lineString);
exactly<FeatureCollection<Polygon, Lot>, typeof pieces>(true);
exactly<Position[][][], ReturnType<typeof split<Position[][]>>>(true);
const faces = overlayLayers(lots, zones, { mode: 'identity' });
exactly<FeatureCollection<MultiPolygon, LayerFaceProperties<Lot, Zone>>, typeof faces>(true);
const merged = overlayLayers(lots, zones, { properties: (a, b) => ({ parcel: a[0]?.parcel, zone: b[0]?.zone }) });
exactly<FeatureCollection<MultiPolygon, { parcel: string; zone: number }>, typeof merged>(true);
// @ts-expect-error: no such mode
overlayLayers(lots, zones, { mode: 'cut' });
dissolve(lots, 'parcel');
dissolve(lots, (f) => f.properties.parcel.slice(0, 1));

// ---- Map editing: clipLayer, splitAntimeridian and the worker ----
import { clipLayer, splitAntimeridian } from 'polysweep';
import { createWorker } from 'polysweep/worker';

const clipped = clipLayer(lots, polygon, { onProgress: (done, total) => done / total });
exactly<FeatureCollection<MultiPolygon, Lot>, typeof clipped>(true);
exactly<Feature<MultiPolygon, Lot>, ReturnType<typeof splitAntimeridian<Feature<Polygon, Lot>>>>(true);
const ps = createWorker();
async function inWorker(signal: AbortSignal) {
  const layer = await ps.clipLayer(lots, polygon, { signal, onProgress: () => {} });
  exactly<FeatureCollection<MultiPolygon, Lot>, typeof layer>(true);
  const merged = await ps.union(polygon, multiPolygon, { signal });
  const flat = await ps.overlayFlat('xor', [], { signal });
  exactly<FlatMultiPolygon, typeof flat>(true);
  // @ts-expect-error: the worker's promise, not a result
  const notAwaited: MultiPolygon = ps.union(polygon, polygon);
  return [merged, notAwaited];
}
void inWorker;

// ---- The sweep's trace ----
import { trace, type TraceStep } from 'polysweep';
const steps: TraceStep[] = trace('intersection', [[[0, 0], [1, 0], [0, 1]]], [[[0, 0], [1, 1], [0, 1]]]);
for (const step of steps) {
  if (step.type === 'status') step.edges.forEach((edge) => edge.left[0] + edge.winding[1]);
  if (step.type === 'selection') exactly<'inside-other' | 'outside-other' | 'same-transition' | 'different-transition' | 'no-transition', typeof step.reason>(true);
}
