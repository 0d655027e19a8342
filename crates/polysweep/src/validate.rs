//! The output contract, checked. Independent of the sweep: brute-force geometry with exact orientation tests, so
//! that tests can hold every result to the contract written in the crate docs.

use crate::geometry::{orient, MultiPolygon, Point};
use std::cmp::Ordering;

/// Sweep order of points; -0 equals 0.
fn lexicographic(a: &Point, b: &Point) -> Ordering {
    let cmp = |u: f64, v: f64| u.partial_cmp(&v).unwrap_or(Ordering::Equal);
    cmp(a.x, b.x).then(cmp(a.y, b.y))
}

/// Is `p` on the closed segment `a b`, given that it is on its line?
fn within(a: Point, b: Point, p: Point) -> bool {
    a.x.min(b.x) <= p.x && p.x <= a.x.max(b.x) && a.y.min(b.y) <= p.y && p.y <= a.y.max(b.y)
}

#[derive(PartialEq, Debug)]
pub(crate) enum Side {
    Inside,
    Outside,
    Boundary,
}

/// Where `p` is with respect to a closed ring, by counting crossings of a ray to +x with exact orientations.
pub(crate) fn locate(ring: &[Point], p: Point) -> Side {
    let mut inside = false;
    for w in ring.windows(2) {
        let (a, b) = (w[0], w[1]);
        let o = orient(a, b, p);
        if o == Ordering::Equal && within(a, b, p) {
            return Side::Boundary;
        }
        if (a.y > p.y) != (b.y > p.y) {
            // The edge spans p's height; it crosses the ray when p is on its left going up, right going down.
            let upward = b.y > a.y;
            if (o == Ordering::Greater) == upward {
                inside = !inside;
            }
        }
    }
    if inside {
        Side::Inside
    } else {
        Side::Outside
    }
}

/// The vertices and edge midpoints of `ring` that lie in `area`, with where each is with respect to `other`. A
/// ring that touches `other` at several vertices can be partly inside and partly outside it, so one point is not
/// enough. A midpoint is used only where rounding left it exactly on its edge: off the edge, it could be on the
/// wrong side of a neighbour as close as the edge.
fn sides<'a>(
    ring: &'a [Point],
    other: &'a [Point],
    area: [f64; 4],
) -> impl Iterator<Item = (Point, Side)> + 'a {
    let midpoints = ring.windows(2).filter_map(|w| {
        let m = Point::new((w[0].x + w[1].x) / 2.0, (w[0].y + w[1].y) / 2.0);
        (orient(w[0], w[1], m) == Ordering::Equal && m != w[0] && m != w[1]).then_some(m)
    });
    ring.iter()
        .copied()
        .chain(midpoints)
        .filter(move |p| area[0] <= p.x && p.x <= area[2] && area[1] <= p.y && p.y <= area[3])
        .map(move |p| (p, locate(other, p)))
}

fn bbox(ring: &[Point]) -> [f64; 4] {
    ring.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, p| [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)],
    )
}

fn boxes_overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]
}

/// Checks `result` against the output contract; the error says which rule broke where.
pub fn validate(result: &MultiPolygon) -> Result<(), String> {
    let mut edges: Vec<(Point, Point, usize, usize)> = Vec::new();
    for (pi, polygon) in result.0.iter().enumerate() {
        for (ri, ring) in polygon.rings().enumerate() {
            let at = format!("polygon {pi}, ring {ri}");
            if ring.len() < 4 || ring.first() != ring.last() {
                return Err(format!("{at}: not closed or fewer than 3 vertices"));
            }
            if ring.windows(2).any(|w| w[0] == w[1]) {
                return Err(format!("{at}: repeated consecutive point"));
            }
            let mut distinct: Vec<Point> = ring[..ring.len() - 1].to_vec();
            distinct.sort_by(lexicographic);
            if distinct.windows(2).any(|w| w[0] == w[1]) {
                return Err(format!("{at}: the ring passes twice through one vertex"));
            }
            // Orientation at the lowest-leftmost vertex, exactly.
            let n = ring.len() - 1;
            let k = (0..n)
                .min_by(|&i, &j| lexicographic(&ring[i], &ring[j]))
                .expect("ring is not empty");
            let turn = orient(ring[(k + n - 1) % n], ring[k], ring[k + 1]);
            let want = if ri == 0 {
                Ordering::Greater
            } else {
                Ordering::Less
            };
            if turn == Ordering::Equal {
                return Err(format!("{at}: zero area"));
            }
            if turn != want {
                return Err(format!(
                    "{at}: {} ring has the wrong orientation",
                    if ri == 0 { "exterior" } else { "hole" }
                ));
            }
            edges.extend(ring.windows(2).map(|w| (w[0], w[1], pi, ri)));
        }
    }
    check_edges(&mut edges)?;
    check_nesting(result)
}

/// No two edges may meet except at a common endpoint.
fn check_edges(edges: &mut [(Point, Point, usize, usize)]) -> Result<(), String> {
    edges.sort_by(|a, b| a.0.x.min(a.1.x).total_cmp(&b.0.x.min(b.1.x)));
    let mut active: Vec<usize> = Vec::new();
    for i in 0..edges.len() {
        let (a, b, pi, ri) = edges[i];
        let min_x = a.x.min(b.x);
        active.retain(|&j| edges[j].0.x.max(edges[j].1.x) >= min_x);
        for &j in &active {
            let (c, d, pj, rj) = edges[j];
            let (o1, o2) = (orient(a, b, c), orient(a, b, d));
            let (o3, o4) = (orient(c, d, a), orient(c, d, b));
            let shared = |p: Point| p == a || p == b;
            let touches =
                |p: Point, q: Point, r: Point, o: Ordering| o == Ordering::Equal && within(q, r, p);
            let bad = if o1 == Ordering::Equal && o2 == Ordering::Equal {
                // Collinear: they may share one endpoint, nothing more.
                let overlap = [c, d].iter().any(|&p| within(a, b, p) && !shared(p))
                    || [a, b].iter().any(|&p| within(c, d, p) && p != c && p != d)
                    || (shared(c) && shared(d));
                overlap
            } else if o1 != o2
                && o3 != o4
                && o1 != Ordering::Equal
                && o2 != Ordering::Equal
                && o3 != Ordering::Equal
                && o4 != Ordering::Equal
            {
                true // proper crossing
            } else {
                // An endpoint on the other edge is only allowed if it is the other's endpoint too.
                (touches(c, a, b, o1) && !shared(c))
                    || (touches(d, a, b, o2) && !shared(d))
                    || (touches(a, c, d, o3) && a != c && a != d)
                    || (touches(b, c, d, o4) && b != c && b != d)
            };
            if bad {
                return Err(format!(
                    "edges cross or overlap: {a:?}-{b:?} (polygon {pi}, ring {ri}) and {c:?}-{d:?} (polygon {pj}, ring {rj})"
                ));
            }
        }
        active.push(i);
    }
    Ok(())
}

/// Holes inside their shell and not inside each other; polygons' interiors disjoint.
fn check_nesting(result: &MultiPolygon) -> Result<(), String> {
    let boxes: Vec<[f64; 4]> = result.0.iter().map(|p| bbox(&p.exterior)).collect();
    for (pi, polygon) in result.0.iter().enumerate() {
        for (hi, hole) in polygon.holes.iter().enumerate() {
            if sides(
                hole,
                &polygon.exterior,
                [
                    f64::NEG_INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::INFINITY,
                ],
            )
            .any(|(_, side)| side == Side::Outside)
            {
                return Err(format!(
                    "polygon {pi}: hole {} is not inside the exterior",
                    hi + 1
                ));
            }
            for (hj, other) in polygon.holes.iter().enumerate().filter(|&(hj, _)| hj != hi) {
                if sides(hole, other, bbox(other)).any(|(_, side)| side == Side::Inside) {
                    return Err(format!(
                        "polygon {pi}: hole {} overlaps hole {}",
                        hi + 1,
                        hj + 1
                    ));
                }
            }
        }
        for (qi, other) in result.0.iter().enumerate() {
            if qi == pi || !boxes_overlap(&boxes[pi], &boxes[qi]) {
                continue;
            }
            let mut points = sides(&polygon.exterior, &other.exterior, boxes[qi]);
            let overlaps = points.any(|(p, side)| {
                side == Side::Inside && other.holes.iter().all(|h| locate(h, p) == Side::Outside)
            });
            if overlaps {
                return Err(format!("polygon {pi} overlaps polygon {qi}"));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mp(rings: &[&[[f64; 2]]]) -> MultiPolygon {
        MultiPolygon::from_coordinates(&[rings.iter().map(|r| r.to_vec()).collect()])
    }

    #[test]
    fn accepts_a_square_with_a_hole_and_rejects_broken_rings() {
        let shell: &[[f64; 2]] = &[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [0.0, 0.0]];
        let hole: &[[f64; 2]] = &[[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0], [1.0, 1.0]];
        assert_eq!(validate(&mp(&[shell, hole])), Ok(()));
        let reversed: Vec<[f64; 2]> = shell.iter().rev().copied().collect();
        assert!(validate(&mp(&[&reversed]))
            .unwrap_err()
            .contains("orientation"));
        let open = &shell[..4];
        assert!(validate(&mp(&[open])).is_err());
        let bow_tie: &[[f64; 2]] = &[[0.0, 0.0], [2.0, 0.0], [0.0, 2.0], [2.0, 2.0], [0.0, 0.0]];
        assert!(validate(&mp(&[bow_tie])).is_err());
        let outside_hole: &[[f64; 2]] =
            &[[5.0, 5.0], [5.0, 6.0], [6.0, 6.0], [6.0, 5.0], [5.0, 5.0]];
        assert!(validate(&mp(&[shell, outside_hole]))
            .unwrap_err()
            .contains("not inside"));
        // A hole touching the shell at two vertices and bulging out between them.
        let triangle: &[[f64; 2]] = &[[0.0, 1.0], [7.0, 4.0], [7.0, 7.0], [0.0, 1.0]];
        let bulge: &[[f64; 2]] = &[[5.0, 4.0], [7.0, 7.0], [8.0, 4.0], [7.0, 4.0], [5.0, 4.0]];
        assert!(validate(&mp(&[triangle, bulge]))
            .unwrap_err()
            .contains("not inside"));
        let spike: &[[f64; 2]] = &[
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [6.0, 4.0],
            [4.0, 4.0],
            [0.0, 4.0],
            [0.0, 0.0],
        ];
        assert!(validate(&mp(&[spike])).is_err());
    }

    #[test]
    fn rejects_overlapping_polygons_and_accepts_corner_touching_ones() {
        let square = |x: f64, y: f64| {
            vec![vec![
                [x, y],
                [x + 1.0, y],
                [x + 1.0, y + 1.0],
                [x, y + 1.0],
                [x, y],
            ]]
        };
        let touching = MultiPolygon::from_coordinates(&[square(0.0, 0.0), square(1.0, 1.0)]);
        assert_eq!(validate(&touching), Ok(()));
        let overlapping = MultiPolygon::from_coordinates(&[square(0.0, 0.0), square(0.5, 0.5)]);
        assert!(validate(&overlapping).is_err());
        let nested = MultiPolygon::from_coordinates(&[
            vec![vec![
                [0.0, 0.0],
                [9.0, 0.0],
                [9.0, 9.0],
                [0.0, 9.0],
                [0.0, 0.0],
            ]],
            square(2.0, 2.0),
        ]);
        assert!(validate(&nested).unwrap_err().contains("overlaps polygon"));
    }
}
