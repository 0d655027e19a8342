//! The public geometry types: points, rings, polygons and polygon sets.
//!
//! They follow GeoJSON's model: a [`Polygon`] is one exterior ring plus holes, a [`MultiPolygon`] is a polygon
//! set. Input rings may be given closed (first point repeated last) or open; output rings are always closed.

use std::borrow::Cow;

/// A point of the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point {
    pub x: f64,
    pub y: f64,
}

impl Point {
    pub const fn new(x: f64, y: f64) -> Self {
        Point { x, y }
    }
}

impl From<[f64; 2]> for Point {
    fn from([x, y]: [f64; 2]) -> Self {
        Point { x, y }
    }
}

impl From<(f64, f64)> for Point {
    fn from((x, y): (f64, f64)) -> Self {
        Point { x, y }
    }
}

impl From<Point> for [f64; 2] {
    fn from(p: Point) -> Self {
        [p.x, p.y]
    }
}

/// A ring: a closed chain of vertices. The closing edge from the last vertex back to the first is implied, so the
/// first vertex may or may not be repeated at the end.
pub type Ring = Vec<Point>;

/// A polygon: an exterior ring and zero or more holes.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Polygon {
    pub exterior: Ring,
    pub holes: Vec<Ring>,
}

impl Polygon {
    pub fn new(exterior: Ring, holes: Vec<Ring>) -> Self {
        Polygon { exterior, holes }
    }

    /// The rings, exterior first: the index used by error locations.
    pub fn rings(&self) -> impl Iterator<Item = &Ring> {
        std::iter::once(&self.exterior).chain(&self.holes)
    }

    /// Area of the exterior minus the areas of the holes (by the shoelace formula, orientation ignored).
    pub fn area(&self) -> f64 {
        ring_area(&self.exterior).abs() - self.holes.iter().map(|h| ring_area(h).abs()).sum::<f64>()
    }
}

/// A polygon set. The empty set is an empty vector.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MultiPolygon(pub Vec<Polygon>);

impl MultiPolygon {
    pub fn new(polygons: Vec<Polygon>) -> Self {
        MultiPolygon(polygons)
    }

    /// Builds a polygon set from GeoJSON MultiPolygon coordinates: polygons of rings of `[x, y]`.
    pub fn from_coordinates(coordinates: &[Vec<Vec<[f64; 2]>>]) -> Self {
        let ring = |r: &Vec<[f64; 2]>| r.iter().map(|&p| Point::from(p)).collect::<Ring>();
        MultiPolygon(
            coordinates
                .iter()
                .map(|rings| Polygon {
                    exterior: rings.first().map(ring).unwrap_or_default(),
                    holes: rings.iter().skip(1).map(ring).collect(),
                })
                .collect(),
        )
    }

    /// GeoJSON MultiPolygon coordinates of this polygon set.
    pub fn to_coordinates(&self) -> Vec<Vec<Vec<[f64; 2]>>> {
        self.0
            .iter()
            .map(|polygon| {
                polygon
                    .rings()
                    .map(|r| r.iter().map(|&p| p.into()).collect())
                    .collect()
            })
            .collect()
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Total area of the polygons (each polygon's exterior minus its holes).
    pub fn area(&self) -> f64 {
        self.0.iter().map(Polygon::area).sum()
    }

    /// Number of vertices, counting each ring's closing vertex once.
    pub fn vertex_count(&self) -> usize {
        self.0
            .iter()
            .flat_map(Polygon::rings)
            .map(|r| open_len(r))
            .sum()
    }
}

impl From<Polygon> for MultiPolygon {
    fn from(polygon: Polygon) -> Self {
        MultiPolygon(vec![polygon])
    }
}

/// Number of vertices of a ring without its closing repetition.
pub(crate) fn open_len(ring: &[Point]) -> usize {
    match ring {
        [first, .., last] if first == last => ring.len() - 1,
        _ => ring.len(),
    }
}

/// The index after `i` around a ring of `n` vertices (`i < n`): `(i + 1) % n` without the division, which passes
/// over every vertex took on their own.
#[inline(always)]
pub(crate) fn next_around(i: usize, n: usize) -> usize {
    if i + 1 < n {
        i + 1
    } else {
        0
    }
}

/// Exact orientation of three points (Shewchuk's adaptive predicate): `Greater` when counter-clockwise.
pub(crate) fn orient(a: Point, b: Point, c: Point) -> std::cmp::Ordering {
    let p = |v: Point| robust::Coord { x: v.x, y: v.y };
    robust::orient2d(p(a), p(b), p(c))
        .partial_cmp(&0.0)
        .unwrap_or(std::cmp::Ordering::Equal)
}

/// The smaller of two floats that are not NaN, by one comparison. `f64::min` also sorts out NaN, which in wasm,
/// where that is not one instruction, costs a call to libm's `fmin` (a large part of the npm package's time with
/// `fmax`, before these).
pub(crate) fn smaller(a: f64, b: f64) -> f64 {
    if b < a {
        b
    } else {
        a
    }
}

/// The larger of two floats that are not NaN (see [`smaller`]).
pub(crate) fn larger(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// Signed area of a ring by the shoelace formula: positive when counter-clockwise.
pub fn ring_area(ring: &[Point]) -> f64 {
    let n = open_len(ring);
    if n < 3 {
        return 0.0;
    }
    // Relative to the first vertex, so that large coordinates do not cancel the digits of small rings.
    let o = ring[0];
    let twice: f64 = (1..n - 1)
        .map(|i| {
            let (a, b) = (ring[i], ring[i + 1]);
            (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y)
        })
        .sum();
    twice / 2.0
}

#[cfg(feature = "geo-types")]
mod geo_interop {
    use super::*;

    impl From<&geo_types::Polygon<f64>> for Polygon {
        fn from(p: &geo_types::Polygon<f64>) -> Self {
            let ring =
                |l: &geo_types::LineString<f64>| l.0.iter().map(|c| Point::new(c.x, c.y)).collect();
            Polygon {
                exterior: ring(p.exterior()),
                holes: p.interiors().iter().map(ring).collect(),
            }
        }
    }

    impl From<&geo_types::MultiPolygon<f64>> for MultiPolygon {
        fn from(m: &geo_types::MultiPolygon<f64>) -> Self {
            MultiPolygon(m.0.iter().map(Polygon::from).collect())
        }
    }

    impl From<&MultiPolygon> for geo_types::MultiPolygon<f64> {
        fn from(m: &MultiPolygon) -> Self {
            let line = |r: &Ring| {
                geo_types::LineString::from(r.iter().map(|p| (p.x, p.y)).collect::<Vec<_>>())
            };
            geo_types::MultiPolygon(
                m.0.iter()
                    .map(|p| {
                        geo_types::Polygon::new(
                            line(&p.exterior),
                            p.holes.iter().map(line).collect(),
                        )
                    })
                    .collect(),
            )
        }
    }
}

/// `ring` closed: itself if it is (its first point repeated last), else a closed copy.
pub(crate) fn closed(ring: &[Point]) -> Cow<'_, [Point]> {
    if ring.len() > open_len(ring) {
        Cow::Borrowed(ring)
    } else {
        Cow::Owned(ring.iter().chain(ring.first()).copied().collect())
    }
}

/// Largest coordinate magnitude accepted: 2^200. Within it (and above [`MIN_COORDINATE`]) the products formed by
/// the exact predicates neither overflow nor underflow, which their proofs assume.
pub const MAX_COORDINATE: f64 = (1u128 << 100) as f64 * (1u128 << 100) as f64;

/// Smallest non-zero coordinate magnitude accepted: 2^-200.
pub const MIN_COORDINATE: f64 = 1.0 / MAX_COORDINATE;
