// splitAntimeridian: polygons in longitude/latitude that cross the antimeridian cut there, so that the planar
// operations read them as the map shows them.
//
// GeoJSON draws a polygon across ±180° with an edge that jumps from, say, 179° to -179°; read in the plane, that
// edge runs the long way round the world. Each ring is unwrapped first (every step taken the short way, so the ring
// runs on past 180° or below -180°), the unwrapped polygon is intersected with the three 360°-wide windows that can
// hold it, and each window's piece is shifted back into [-180, 180]. RFC 7946 §3.1.9 asks for the same cut.

import { OPERATIONS, inKind, optionsOf, readOperand, run, toCoordinates, toFlat, unpack } from './geojson.js';

/** `dx` brought into [-180, 180]: the short way between two longitudes. */
const shortWay = (dx) => dx - 360 * Math.round(dx / 360);

/**
 * A ring with every step taken the short way, starting at the longitude nearest `near`. A ring that comes back 360°
 * away from its start goes round a pole: it is closed over that pole (the one on the side of its mean latitude), as
 * a map in longitude/latitude draws it.
 */
function unwrapRing(ring, near) {
  if (ring.length === 0) return ring;
  const out = new Array(ring.length);
  let x = ring[0][0] - 360 * Math.round((ring[0][0] - near) / 360);
  let latitudes = 0;
  for (let i = 0; i < ring.length; i++) {
    if (i > 0) x += shortWay(ring[i][0] - ring[i - 1][0]);
    out[i] = [x, ring[i][1]];
    latitudes += ring[i][1];
  }
  // The ring may be closed (last position = first) or open: compare the end with the start, round trip included.
  const around = x + shortWay(ring[0][0] - ring.at(-1)[0]) - out[0][0];
  if (Math.abs(around) > 180) {
    const pole = latitudes >= 0 ? 90 : -90;
    out.push([out[0][0] + around, ring[0][1]], [out[0][0] + around, pole], [out[0][0], pole]);
  }
  return out;
}

/**
 * `geom` (any operand of the Boolean operations) with every polygon that crosses the antimeridian cut there into
 * pieces within longitudes [-180, 180], in the kind of `geom` (a Feature keeps its properties), as
 * MultiPolygons. Rings are read as taking the short way round between consecutive positions, so no edge may span
 * 180° of longitude or more. Options: `fillRule`, `skipNonPolygonal`.
 */
export function splitAntimeridian(geom, options) {
  const { fillRule, skipNonPolygonal } = optionsOf(options);
  const input = readOperand(geom, 0, skipNonPolygonal);
  const unwrapped = input.parts.map(({ coordinates, where }) => ({
    where,
    coordinates: coordinates.map((polygon) => {
      // Holes unwrapped near their exterior, so that they stay inside it.
      const near = Array.isArray(polygon?.[0]?.[0]) ? shortWay(polygon[0][0][0]) : 0;
      return Array.isArray(polygon) ? polygon.map((ring) => (Array.isArray(ring) ? unwrapRing(ring, near) : ring)) : polygon;
    }),
  }));
  const flat = toFlat(unwrapped);
  // The windows span the polygons' latitudes, whatever they are: cutting at the poles is not this function's job.
  let south = 0;
  let north = 0;
  for (let i = 1; i < flat.coords.length; i += 2) {
    south = Math.min(south, flat.coords[i]);
    north = Math.max(north, flat.coords[i]);
  }
  const pieces = [];
  for (const shift of [-360, 0, 360]) {
    const window = [[[-180 + shift, south - 1], [180 + shift, south - 1], [180 + shift, north + 1], [-180 + shift, north + 1]]];
    const piece = unpack(run(OPERATIONS.intersection, fillRule, [flat, toFlat([{ coordinates: [window], where: 'window' }])], [flat.labels]));
    const coords = Float64Array.from(piece.coords);
    for (let i = 0; i < coords.length; i += 2) coords[i] -= shift;
    pieces.push({ coords, ringOffsets: piece.ringOffsets, polygonOffsets: piece.polygonOffsets });
  }
  // One union of the shifted pieces: pieces of one polygon from different windows do not touch, but polygons of
  // a MultiPolygon may overlap once unwrapped.
  return inKind(input, toCoordinates(unpack(run(OPERATIONS.union, fillRule, pieces))));
}
