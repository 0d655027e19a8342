// The data of the layer-overlay benchmark (web/bench/layers.mjs): a cadastre of parcels and a zoning map over the
// same extent, both exact planar partitions, generated deterministically from a seed.
//
// Parcels: a cols × rows grid of quadrilaterals, GRID_STEP metres apart, whose shared grid vertices are jittered
// (up to 0.2 of the step in x and in y, so every quadrilateral stays convex); neighbours share every edge exactly.
// The vertices on the outer boundary move along it only, so the extent is the exact rectangle
// [x0, x0 + cols·step] × [y0, y0 + rows·step].
//
// Zones: a zc × zr grid over the same rectangle whose corners are jittered (up to 0.1 of a zone's width/height) and
// whose edges are jagged polylines of ZONE_EDGE_SEGMENTS segments: the inner vertices are moved across the edge by
// up to ZONE_AMPLITUDE (tapered by sin(πt) towards the corners, so no zone's boundary crosses itself) and a little
// along it. Each edge's vertices are computed once and used by both zones it separates, so the zones are an exact
// partition too; on the outer boundary the vertices lie exactly on the rectangle's sides.
//
// Coordinates are metres with a projected-CRS-like origin (default 600000, 5300000, a UTM-like easting/northing),
// full doubles, not rounded. Rings are closed and counter-clockwise (RFC 7946), one Polygon feature per parcel/zone.

import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { BENCH_DIR, multiPolygonArea } from './data.mjs';

export const LAYERS_DIR = join(BENCH_DIR, 'layers');
export const GRID_STEP = 20; // metres between parcel grid lines
export const ZONE_EDGE_SEGMENTS = 20; // segments of each zone boundary edge
export const DEFAULT_ORIGIN = [600000, 5300000];
const PARCEL_JITTER = 0.2; // of GRID_STEP
const ZONE_CORNER_JITTER = 0.1; // of a zone's width / height
const ZONE_AMPLITUDE = 0.3 * GRID_STEP; // metres across a zone edge, at most (also ≤ 4 % of a zone's side)
const ZONE_CLASSES = ['R1', 'R2', 'R3', 'C1', 'C2', 'I1', 'AG', 'OS'];
const LAND_USES = ['residential', 'commercial', 'industrial', 'agricultural', 'vacant'];

/** mulberry32: a small deterministic PRNG, uniform in [0, 1). */
function prng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** cols × rows as close to square as possible with cols·rows ≈ n. */
export function gridShape(n) {
  if (!(n >= 1)) throw new Error(`a layer needs at least one feature (got ${n})`);
  const cols = Math.max(1, Math.round(Math.sqrt(n)));
  const rows = Math.max(1, Math.round(n / cols));
  return { cols, rows };
}

/**
 * Both layers: {parcels, zones, info} with parcels and zones GeoJSON FeatureCollections of Polygon features.
 * `parcels` and `zones` are the wanted counts (rounded to a grid: 900 → 30 × 30, 100 → 10 × 10).
 */
export function generateLayers({ parcels = 10_000, zones = 100, seed = 1, origin = DEFAULT_ORIGIN } = {}) {
  const p = gridShape(parcels);
  const z = gridShape(zones);
  const [X0, Y0] = origin;
  const XMAX = X0 + p.cols * GRID_STEP;
  const YMAX = Y0 + p.rows * GRID_STEP;
  const rand = prng(seed);
  const u = () => 2 * rand() - 1; // uniform in [-1, 1)

  // ---- parcels: the jittered (cols+1) × (rows+1) vertex grid
  const J = PARCEL_JITTER * GRID_STEP;
  const vx = [];
  for (let r = 0; r <= p.rows; r++) {
    const row = [];
    for (let c = 0; c <= p.cols; c++) {
      const onX = c === 0 || c === p.cols; // on the left/right side: x fixed
      const onY = r === 0 || r === p.rows;
      const x = c === 0 ? X0 : c === p.cols ? XMAX : X0 + c * GRID_STEP + (onY && onX ? 0 : J * u());
      const y = r === 0 ? Y0 : r === p.rows ? YMAX : Y0 + r * GRID_STEP + (onX && onY ? 0 : J * u());
      row.push([x, y]);
    }
    vx.push(row);
  }
  const parcelFeatures = [];
  for (let r = 0; r < p.rows; r++) {
    for (let c = 0; c < p.cols; c++) {
      const k = r * p.cols + c;
      const ring = [vx[r][c], vx[r][c + 1], vx[r + 1][c + 1], vx[r + 1][c], vx[r][c]].map((q) => [q[0], q[1]]);
      parcelFeatures.push({
        type: 'Feature',
        properties: {
          parcel_id: `P${String(k + 1).padStart(6, '0')}`,
          owner: `Owner ${1 + Math.floor(rand() * 2500)}`,
          land_use: LAND_USES[Math.floor(rand() * LAND_USES.length)],
          assessed_value: 50_000 + Math.round(rand() * 950_000),
        },
        geometry: { type: 'Polygon', coordinates: [ring] },
      });
    }
  }

  // ---- zones: jittered corners, jagged shared edges
  const zw = (XMAX - X0) / z.cols;
  const zh = (YMAX - Y0) / z.rows;
  const corner = [];
  for (let r = 0; r <= z.rows; r++) {
    const row = [];
    for (let c = 0; c <= z.cols; c++) {
      const x = c === 0 ? X0 : c === z.cols ? XMAX : X0 + c * zw + ZONE_CORNER_JITTER * zw * u();
      const y = r === 0 ? Y0 : r === z.rows ? YMAX : Y0 + r * zh + ZONE_CORNER_JITTER * zh * u();
      row.push([x, y]);
    }
    corner.push(row);
  }
  const amplitude = Math.min(ZONE_AMPLITUDE, 0.04 * Math.min(zw, zh));
  const K = ZONE_EDGE_SEGMENTS;
  /** The K + 1 vertices from a to b; `side`: null for an inner edge, else 'x' or 'y', the coordinate held fixed. */
  const edge = (a, b, side) => {
    const pts = [[a[0], a[1]]];
    const dx = b[0] - a[0];
    const dy = b[1] - a[1];
    const len = Math.hypot(dx, dy);
    const nx = -dy / len;
    const ny = dx / len;
    for (let k = 1; k < K; k++) {
      const t = (k + 0.3 * u()) / K;
      if (side === 'x') pts.push([a[0], a[1] + t * dy]);
      else if (side === 'y') pts.push([a[0] + t * dx, a[1]]);
      else {
        const d = amplitude * Math.sin(Math.PI * t) * u();
        pts.push([a[0] + t * dx + d * nx, a[1] + t * dy + d * ny]);
      }
    }
    pts.push([b[0], b[1]]);
    return pts;
  };
  // horizontal[r][c]: corner[r][c] → corner[r][c+1]; vertical[r][c]: corner[r][c] → corner[r+1][c]
  const horizontal = [];
  for (let r = 0; r <= z.rows; r++) {
    const row = [];
    for (let c = 0; c < z.cols; c++) row.push(edge(corner[r][c], corner[r][c + 1], r === 0 || r === z.rows ? 'y' : null));
    horizontal.push(row);
  }
  const vertical = [];
  for (let r = 0; r < z.rows; r++) {
    const row = [];
    for (let c = 0; c <= z.cols; c++) row.push(edge(corner[r][c], corner[r + 1][c], c === 0 || c === z.cols ? 'x' : null));
    vertical.push(row);
  }
  const zoneFeatures = [];
  for (let r = 0; r < z.rows; r++) {
    for (let c = 0; c < z.cols; c++) {
      const ring = [
        ...horizontal[r][c].slice(0, -1), // bottom, left to right
        ...vertical[r][c + 1].slice(0, -1), // right, upwards
        ...horizontal[r + 1][c].slice().reverse().slice(0, -1), // top, right to left
        ...vertical[r][c].slice().reverse(), // left, downwards, closing the ring
      ].map((q) => [q[0], q[1]]);
      zoneFeatures.push({
        type: 'Feature',
        properties: {
          zone_id: `Z${String(r * z.cols + c + 1).padStart(4, '0')}`,
          zone_class: ZONE_CLASSES[Math.floor(rand() * ZONE_CLASSES.length)],
        },
        geometry: { type: 'Polygon', coordinates: [ring] },
      });
    }
  }

  const count = (fc) => fc.reduce((n, f) => n + f.geometry.coordinates[0].length - 1, 0);
  return {
    parcels: { type: 'FeatureCollection', features: parcelFeatures },
    zones: { type: 'FeatureCollection', features: zoneFeatures },
    info: {
      seed,
      extent: [X0, Y0, XMAX, YMAX],
      parcels: { count: parcelFeatures.length, grid: [p.cols, p.rows], step_m: GRID_STEP, vertices: count(parcelFeatures) },
      zones: {
        count: zoneFeatures.length, grid: [z.cols, z.rows], edge_segments: K, amplitude_m: amplitude,
        vertices: count(zoneFeatures),
      },
    },
  };
}

/** Area of a Polygon or MultiPolygon geometry (exteriors minus holes, whatever the orientation); 0 for null. */
export function geometryArea(geometry) {
  if (!geometry) return 0;
  if (geometry.type === 'Polygon') return multiPolygonArea([geometry.coordinates]);
  if (geometry.type === 'MultiPolygon') return multiPolygonArea(geometry.coordinates);
  throw new Error(`expected a Polygon or MultiPolygon, got ${geometry.type}`);
}

/** Generates both layers and writes them to target/bench/layers/<tag>/; returns {dir, files, tag, ...layers}. */
export function writeLayers(options) {
  const layers = generateLayers(options);
  const { info } = layers;
  const origin = options.origin ?? DEFAULT_ORIGIN;
  const tag = `p${info.parcels.count}-z${info.zones.count}-s${info.seed}`
    + (origin[0] === DEFAULT_ORIGIN[0] && origin[1] === DEFAULT_ORIGIN[1] ? '' : `-o${origin[0]}_${origin[1]}`);
  const dir = join(LAYERS_DIR, tag);
  mkdirSync(dir, { recursive: true });
  const files = { parcels: join(dir, 'parcels.geojson'), zones: join(dir, 'zones.geojson') };
  writeFileSync(files.parcels, JSON.stringify(layers.parcels));
  writeFileSync(files.zones, JSON.stringify(layers.zones));
  writeFileSync(join(dir, 'info.json'), `${JSON.stringify(info, null, 2)}\n`);
  return { dir, files, tag, ...layers };
}
