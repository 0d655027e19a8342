/** A position: [x, y]. */
export type Position = [number, number] | number[];
/** A ring: positions, closed (first repeated last) or open. */
export type Ring = Position[];
/** GeoJSON Polygon coordinates: the exterior ring, then holes. */
export type Polygon = Ring[];
/** GeoJSON MultiPolygon coordinates. */
export type MultiPolygon = Polygon[];

export interface PolygonGeometry {
  type: 'Polygon';
  coordinates: Polygon;
}
export interface MultiPolygonGeometry {
  type: 'MultiPolygon';
  coordinates: MultiPolygon;
}
export type Geometry = PolygonGeometry | MultiPolygonGeometry;
export interface Feature<P = Record<string, unknown> | null> {
  type: 'Feature';
  geometry: Geometry;
  properties: P;
}
export interface MultiPolygonFeature<P = Record<string, unknown> | null> {
  type: 'Feature';
  geometry: MultiPolygonGeometry;
  properties: P;
}

export interface Options {
  /** How an operand's rings define its interior: 'evenodd' (default) or 'nonzero'. */
  fillRule?: 'evenodd' | 'nonzero';
}

/** An operand: GeoJSON coordinates, a Polygon or MultiPolygon geometry, or a Feature of one. */
export type Geom = Polygon | MultiPolygon | Geometry | Feature;

/** Results come in the kind of the first operand: coordinates, a MultiPolygon geometry, or a Feature with its properties. */
export type Result<G> = G extends Feature<infer P>
  ? MultiPolygonFeature<P>
  : G extends Geometry
    ? MultiPolygonGeometry
    : MultiPolygon;

export function union<G extends Geom>(geom: G, ...geoms: (Geom | Options)[]): Result<G>;
export function intersection<G extends Geom>(geom: G, ...geoms: (Geom | Options)[]): Result<G>;
export function difference<G extends Geom>(subject: G, ...clips: (Geom | Options)[]): Result<G>;
export function xor<G extends Geom>(geom: G, ...geoms: (Geom | Options)[]): Result<G>;

/** The flat (GeoArrow / earcut) layout: x, y pairs; each ring's vertex offsets; each polygon's ring offsets. */
export interface FlatMultiPolygon {
  coords: Float64Array;
  ringOffsets: Uint32Array;
  polygonOffsets: Uint32Array;
}

export function overlayFlat(
  operation: 'intersection' | 'union' | 'difference' | 'xor',
  operands: FlatMultiPolygon[],
  options?: Options,
): FlatMultiPolygon;
