// Types of the polysweep package. GeoJSON objects are typed with @types/geojson, the types map apps and turf already
// use, so that an app's own Feature<Polygon, P>, FeatureCollection or coordinates pass without casts.
import type {
  Feature,
  FeatureCollection,
  Geometry,
  GeometryCollection,
  LineString,
  MultiLineString,
  MultiPolygon,
  Polygon,
  Position,
} from 'geojson';

/** GeoJSON Polygon coordinates: the exterior ring, then holes; rings closed or open, positions [x, y, ...]. */
export type PolygonCoordinates = Position[][];
/** GeoJSON MultiPolygon coordinates. */
export type MultiPolygonCoordinates = Position[][][];

/** The geometries whose polygons an operand is: Polygon, MultiPolygon, or a GeometryCollection of them. */
export type PolygonalGeometry = Polygon | MultiPolygon | GeometryCollection;

/**
 * An operand: Polygon or MultiPolygon coordinates; a Polygon, MultiPolygon or GeometryCollection; a Feature of one
 * (or with a null geometry, an empty operand); or a FeatureCollection, whose features' polygons together are one
 * operand. A collection's members are checked as they are read: one that is not polygonal (a LineString, say) is
 * an error unless `{ skipNonPolygonal: true }` is passed, and with that option any geometry or Feature is accepted.
 */
export type Operand =
  | PolygonCoordinates
  | MultiPolygonCoordinates
  | PolygonalGeometry
  | Feature<PolygonalGeometry | null, any>
  | FeatureCollection<Geometry | null, any>;

/** Any GeoJSON geometry, Feature or FeatureCollection, or coordinates: what `{ skipNonPolygonal: true }` accepts. */
export type AnyOperand = Operand | Geometry | Feature<Geometry | null, any>;

/**
 * How an operand's rings define its interior: 'structure' (the default), polygon-clipping's reading of GeoJSON:
 * each ring's own region (orientation does not matter), a polygon its exterior less its holes, an operand the union
 * of its polygons; 'evenodd' (inside an odd number of rings, the paper's rule), 'nonzero' (winding number not 0),
 * 'positive' (winding number above 0: counter-clockwise rings fill, clockwise ones cut) or 'negative' (below 0),
 * as in Clipper2. On valid input every rule gives the same result at the same cost; 'structure' costs about three
 * times as much only on operands that are not valid polygon sets.
 */
export type FillRule = 'evenodd' | 'nonzero' | 'positive' | 'negative' | 'structure';

export interface Options {
  /** How an operand's rings define its interior; 'structure' (polygon-clipping's reading) by default. */
  fillRule?: FillRule;
  /** Read Points, LineStrings and their Multi forms as nothing instead of throwing. */
  skipNonPolygonal?: boolean;
}

/**
 * The result, in the kind of the first operand: a FeatureCollection gives a FeatureCollection of one Feature
 * (properties null); a Feature a Feature with its properties; any geometry a MultiPolygon; coordinates
 * MultiPolygon coordinates.
 */
export type Result<G> =
  G extends FeatureCollection<any, any>
    ? FeatureCollection<MultiPolygon, null>
    : G extends Feature<any, infer P>
      ? Feature<MultiPolygon, P>
      : G extends Geometry
        ? MultiPolygon
        : MultiPolygonCoordinates;

/** The call of each operation: one or more operands, then options (only last, as the function reads them). */
export interface Operation {
  <G extends Operand>(geom: G, ...more: Operand[] | [...Operand[], Options]): Result<G>;
  <G extends AnyOperand>(geom: G, ...more: [...AnyOperand[], Options & { skipNonPolygonal: true }]): Result<G>;
}

/** The union of all operands. */
export declare const union: Operation;
/** The intersection of all operands. */
export declare const intersection: Operation;
/** The first operand minus every other. */
export declare const difference: Operation;
/** The points inside an odd number of operands. */
export declare const xor: Operation;

/** The flat (GeoArrow / earcut) layout: x, y pairs; each ring's vertex offsets; each polygon's ring offsets. */
export interface FlatMultiPolygon {
  coords: Float64Array;
  ringOffsets: Uint32Array;
  polygonOffsets: Uint32Array;
}

export function overlayFlat(
  operation: 'intersection' | 'union' | 'difference' | 'xor',
  operands: FlatMultiPolygon[],
  options?: Pick<Options, 'fillRule'>,
): FlatMultiPolygon;

// --- Lines and layers ---

/** GeoJSON LineString coordinates. */
export type LineStringCoordinates = Position[];
/** GeoJSON MultiLineString coordinates. */
export type MultiLineStringCoordinates = Position[][];
/** Lines: LineString or MultiLineString coordinates, a geometry, a Feature of one, or a FeatureCollection of them. */
export type Lines =
  | LineStringCoordinates
  | MultiLineStringCoordinates
  | LineString
  | MultiLineString
  | Feature<LineString | MultiLineString | null, any>
  | FeatureCollection<LineString | MultiLineString | null, any>;

export interface ClipOptions extends Options {
  /** The parts to keep: 'inside' the polygon set (the default) or 'outside' it. */
  keep?: 'inside' | 'outside';
  /** Parts running along the polygon set's boundary count as 'inside' (the default, as GEOS has it) or 'outside'. */
  boundary?: 'inside' | 'outside';
}

/** clip's result, in the kind of its lines. */
export type ClipResult<L> =
  L extends FeatureCollection<any, infer P>
    ? FeatureCollection<MultiLineString, P>
    : L extends Feature<any, infer P>
      ? Feature<MultiLineString, P>
      : L extends LineString | MultiLineString
        ? MultiLineString
        : MultiLineStringCoordinates;

/**
 * The parts of `lines` inside (or outside) `polygon`, cut only where they pass through its boundary; input
 * vertices bit for bit, cut points the exact crossings rounded to the nearest floats.
 */
export function clip<L extends Lines>(lines: L, polygon: Operand, options?: ClipOptions): ClipResult<L>;

/** split's result: Polygon coordinates for coordinates; otherwise Polygon features with their feature's properties. */
export type SplitResult<G> = G extends PolygonCoordinates | MultiPolygonCoordinates
  ? PolygonCoordinates[]
  : FeatureCollection<Polygon, G extends Feature<any, infer P> | FeatureCollection<any, infer P> ? P : null>;

/**
 * `polygon` cut into pieces along `lines`: each piece a valid polygon, together the polygon. Dangling ends and
 * lines along the boundary cut nothing; a FeatureCollection is cut feature by feature.
 */
export function split<G extends Operand>(polygon: G, lines: Lines, options?: Options): SplitResult<G>;

/** A layer: a FeatureCollection or an array of polygon Features. */
export type Layer<P = any> = FeatureCollection<PolygonalGeometry | null, P> | Feature<PolygonalGeometry | null, P>[];

/** Which faces overlayLayers returns, by the features covering them. */
export type LayerMode = 'intersection' | 'union' | 'identity' | 'difference' | 'xor';

/** The properties of a face of overlayLayers (without `options.properties`). */
export interface LayerFaceProperties<A, B> {
  /** The covering feature of layer A (the first, where several overlap), or null. */
  a: A | null;
  b: B | null;
  aIndex: number | null;
  bIndex: number | null;
  /** Every covering feature of each layer, by index, in increasing order. */
  aIndices: number[];
  bIndices: number[];
}

export interface LayerOptions<A, B, R> extends Options {
  mode?: LayerMode;
  /** Makes a face's properties from the covering features' properties of each layer. */
  properties?: (a: A[], b: B[]) => R;
}

/**
 * The overlay of two layers in one sweep: the faces `options.mode` keeps, one MultiPolygon feature per set of
 * covering features, with their properties.
 */
export function overlayLayers<A, B>(
  layerA: Layer<A>,
  layerB: Layer<B>,
  options?: LayerOptions<A, B, never> & { properties?: undefined },
): FeatureCollection<MultiPolygon, LayerFaceProperties<A, B>>;
export function overlayLayers<A, B, R>(
  layerA: Layer<A>,
  layerB: Layer<B>,
  options: LayerOptions<A, B, R> & { properties: (a: A[], b: B[]) => R },
): FeatureCollection<MultiPolygon, R>;

/**
 * Features merged by `key` (a property name, a function of the feature, or undefined for all into one): one
 * MultiPolygon feature per distinct value, the union of its features, with properties `{[key]: value}`.
 */
export function dissolve<P>(
  features: Layer<P>,
  key?: string | ((feature: Feature<any, P>, index: number) => unknown),
  options?: Options,
): FeatureCollection<MultiPolygon, Record<string, unknown>>;

export interface ClipLayerOptions extends Options {
  /** Called with the count of features done and their total (those whose bounding box meets the polygon's). */
  onProgress?: (done: number, total: number) => void;
}

/**
 * Each feature of `layer` clipped to `polygon` (QGIS's Clip): one MultiPolygon feature per feature that meets the
 * polygon's interior, in the layer's order, keeping its id and properties.
 */
export function clipLayer<P>(layer: Layer<P>, polygon: Operand, options?: ClipLayerOptions): FeatureCollection<MultiPolygon, P>;

/**
 * Polygons in longitude/latitude that cross the antimeridian (an edge from 179° to -179°, say) cut there into
 * pieces within [-180, 180], in the kind of `geom`; a ring that goes round a pole is closed over it.
 */
export function splitAntimeridian<G extends Operand>(geom: G, options?: Options): Result<G>;

/** An edge of a trace: endpoints in sweep order, the operand of its input edge, its winding per operand. */
export interface TraceEdge {
  left: Position;
  right: Position;
  operand: 0 | 1;
  winding: [number, number];
}

/** One step of the sweep (see `trace`). */
export type TraceStep =
  | { type: 'event'; point: Position; left: boolean; edge: TraceEdge }
  | { type: 'meeting'; lower: TraceEdge; upper: TraceEdge; meeting: 'crossing' | 'vertex-on-edge' | 'overlap'; at: Position }
  | { type: 'subdivision'; edge: TraceEdge; at: Position }
  | { type: 'flags'; edge: TraceEdge; coverageBelow: [number, number]; inOut: boolean; insideOther: boolean; inResult: boolean }
  | {
      type: 'selection';
      edge: TraceEdge;
      inResult: boolean;
      reason: 'inside-other' | 'outside-other' | 'same-transition' | 'different-transition' | 'no-transition';
    }
  | { type: 'status'; edges: TraceEdge[] }
  | { type: 'ring'; polygon: number; ring: number; points: Position[] };

/**
 * The steps of the Martínez–Rueda–Feito sweep of `operation` on `subject` and `clipping`, as the paper runs it:
 * each event, S after it, what possibleInter found, each subdivision, the flags of Fig. 9, the selection of Fig. 10
 * and the rings the connection step closed. For teaching-sized input: every step is kept.
 */
export function trace(operation: 'intersection' | 'union' | 'difference' | 'xor', subject: Operand, clipping: Operand, options?: Options): TraceStep[];
