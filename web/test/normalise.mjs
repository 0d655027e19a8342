// Result normalisation shared by the package's tests, the same rule as the Rust harness
// (crates/polysweep/tests/common/mod.rs) and tests/fixtures/README.md: rings without their closing point and
// without vertices where they go straight on, started at their smallest vertex; holes and polygons sorted.
// Orientation is kept. The fixtures use small integer and dyadic coordinates, so float orientation is exact here.

function orient(a, b, c) {
  return Math.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

function same(a, b) {
  return a[0] === b[0] && a[1] === b[1];
}

function lexicographic(a, b) {
  return a[0] - b[0] || a[1] - b[1];
}

function normaliseRing(ring) {
  const points = ring.map((p) => [p[0] + 0, p[1] + 0]); // -0 → 0
  if (points.length > 1 && same(points[0], points[points.length - 1])) points.pop();
  for (;;) {
    const n = points.length;
    if (n < 3) break;
    const straight = points.findIndex((b, i) => {
      const a = points[(i + n - 1) % n];
      const c = points[(i + 1) % n];
      const forward = (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]) > 0;
      return same(a, b) || (orient(a, b, c) === 0 && forward);
    });
    if (straight < 0) break;
    points.splice(straight, 1);
  }
  let start = 0;
  points.forEach((p, i) => {
    if (lexicographic(p, points[start]) < 0) start = i;
  });
  return [...points.slice(start), ...points.slice(0, start)];
}

function compareArrays(a, b) {
  return JSON.stringify(a) < JSON.stringify(b) ? -1 : JSON.stringify(a) > JSON.stringify(b) ? 1 : 0;
}

export function normalise(multiPolygon) {
  return multiPolygon
    .map((polygon) => {
      const [exterior, ...holes] = polygon.map(normaliseRing);
      return [exterior, ...holes.sort(compareArrays)];
    })
    .sort(compareArrays);
}

/** Signed shoelace area of MultiPolygon coordinates: positive for counter-clockwise exteriors and clockwise holes. */
export function area(multiPolygon) {
  let twice = 0;
  for (const ring of multiPolygon.flat(1)) {
    for (let k = 0; k + 1 < ring.length; k++) twice += ring[k][0] * ring[k + 1][1] - ring[k + 1][0] * ring[k][1];
  }
  return twice / 2;
}
