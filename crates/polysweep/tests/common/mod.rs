//! Test support shared by the integration tests: fixture loading, result normalisation and independent oracles
//! (none of them uses the sweep).
#![allow(dead_code)] // each test binary uses part of it

use polysweep::{MultiPolygon, Operation, Point};
use serde_json::Value;
use std::cmp::Ordering;
use std::path::{Path, PathBuf};

pub const OPERATIONS: [(&str, Operation); 4] = [
    ("intersection", Operation::Intersection),
    ("union", Operation::Union),
    ("difference", Operation::Difference),
    ("xor", Operation::Xor),
];

/// The repository's shared fixtures directory.
pub fn fixtures_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/fixtures")
}

pub fn multipolygon(value: &Value) -> MultiPolygon {
    let coordinates: Vec<Vec<Vec<[f64; 2]>>> =
        serde_json::from_value(value.clone()).expect("MultiPolygon coordinates");
    MultiPolygon::from_coordinates(&coordinates)
}

pub fn orient(a: Point, b: Point, c: Point) -> Ordering {
    robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    )
    .partial_cmp(&0.0)
    .unwrap()
}

/// A canonical form for comparing results: rings without their closing point, without vertices where the ring
/// goes straight on, started at their smallest vertex; holes and polygons sorted. Orientation is kept.
pub fn normalise(m: &MultiPolygon) -> Vec<Vec<Vec<[f64; 2]>>> {
    let mut polygons: Vec<Vec<Vec<[f64; 2]>>> =
        m.0.iter()
            .map(|p| {
                let mut rings: Vec<Vec<[f64; 2]>> = p.rings().map(|r| normalise_ring(r)).collect();
                rings[1..].sort_by(|a, b| a.partial_cmp(b).unwrap());
                rings
            })
            .collect();
    polygons.sort_by(|a, b| a.partial_cmp(b).unwrap());
    polygons
}

fn normalise_ring(ring: &[Point]) -> Vec<[f64; 2]> {
    let mut points: Vec<Point> = ring.to_vec();
    if points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
    // Drop repeated points and vertices where the ring goes straight on, until none is left.
    loop {
        let n = points.len();
        if n < 3 {
            break;
        }
        let straight = (0..n).find(|&i| {
            let (a, b, c) = (points[(i + n - 1) % n], points[i], points[(i + 1) % n]);
            a == b
                || (orient(a, b, c) == Ordering::Equal
                    && (b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) > 0.0)
        });
        match straight {
            Some(i) => {
                points.remove(i);
            }
            None => break,
        }
    }
    let start = (0..points.len())
        .min_by(|&i, &j| {
            points[i]
                .x
                .total_cmp(&points[j].x)
                .then(points[i].y.total_cmp(&points[j].y))
        })
        .unwrap_or(0);
    points.rotate_left(start);
    points.iter().map(|p| [p.x, p.y]).collect()
}

/// Even-odd membership of `p` in a polygon set by casting a ray to +x: the number of ring edges crossed (each
/// edge counted half-open in y, so vertices are not counted twice).
pub fn inside_even_odd(m: &MultiPolygon, p: Point) -> bool {
    winding_or_parity(m, p, false) != 0
}

/// Winding number of `p` with respect to all rings of `m`.
pub fn winding_number(m: &MultiPolygon, p: Point) -> i32 {
    winding_or_parity(m, p, true)
}

fn winding_or_parity(m: &MultiPolygon, p: Point, winding: bool) -> i32 {
    let mut count = 0i32;
    for ring in m.0.iter().flat_map(|poly| poly.rings()) {
        let n = ring.len();
        for i in 0..n {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            if (a.y > p.y) != (b.y > p.y) {
                let upward = b.y > a.y;
                // The edge crosses the ray when p is on its left going up, or on its right going down.
                if (orient(a, b, p) == Ordering::Greater) == upward {
                    count += if winding {
                        if upward {
                            1
                        } else {
                            -1
                        }
                    } else {
                        1
                    };
                }
            }
        }
    }
    if winding {
        count
    } else {
        count % 2
    }
}

/// Is `p` exactly on an edge of `m`?
pub fn on_boundary(m: &MultiPolygon, p: Point) -> bool {
    m.0.iter().flat_map(|poly| poly.rings()).any(|ring| {
        let n = ring.len();
        (0..n).any(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            orient(a, b, p) == Ordering::Equal
                && a.x.min(b.x) <= p.x
                && p.x <= a.x.max(b.x)
                && a.y.min(b.y) <= p.y
                && p.y <= a.y.max(b.y)
        })
    })
}

/// Applies `f` to every vertex.
pub fn map_points(m: &MultiPolygon, f: impl Fn(Point) -> Point) -> MultiPolygon {
    let mut out = m.clone();
    for poly in &mut out.0 {
        for p in poly
            .exterior
            .iter_mut()
            .chain(poly.holes.iter_mut().flatten())
        {
            *p = f(*p);
        }
    }
    out
}

/// Reverses every ring's vertex order.
pub fn reverse_rings(m: &MultiPolygon) -> MultiPolygon {
    let mut out = m.clone();
    for poly in &mut out.0 {
        poly.exterior.reverse();
        for h in &mut poly.holes {
            h.reverse();
        }
    }
    out
}
