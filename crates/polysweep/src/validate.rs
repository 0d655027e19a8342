//! The output contract, checked. Independent of the sweep: brute-force geometry with exact orientation tests, so
//! that tests can hold every result to the contract written in the crate docs.

use crate::geometry::{orient, MultiPolygon, Point};
use std::cmp::Ordering;

/// Sweep order of points; -0 equals 0.
fn lexicographic(a: &Point, b: &Point) -> Ordering {
    let cmp = |u: f64, v: f64| u.partial_cmp(&v).unwrap_or(Ordering::Equal);
    cmp(a.x, b.x).then(cmp(a.y, b.y))
}

/// The index of the first of `points` (not empty) in sweep order: the lowest-leftmost.
pub(crate) fn lowest_leftmost(points: &[Point]) -> usize {
    (0..points.len())
        .min_by(|&i, &j| lexicographic(&points[i], &points[j]))
        .expect("points are not empty")
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

/// How a polygon set breaks the output contract, and where: polygons by index, rings by index within their
/// polygon (0 the exterior, 1.. the holes).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ValidationError {
    /// A ring is not valid on its own.
    Ring {
        polygon: usize,
        ring: usize,
        problem: RingProblem,
    },
    /// An exterior ring is clockwise, or a hole counter-clockwise.
    WrongOrientation { polygon: usize, ring: usize },
    /// Two edges cross, overlap, or one ends on the other; each as its endpoints, polygon and ring.
    EdgesMeet {
        edges: [(Point, Point, usize, usize); 2],
    },
    /// A hole reaches outside its polygon's exterior.
    HoleOutside { polygon: usize, hole: usize },
    /// Two holes of one polygon overlap.
    HolesOverlap { polygon: usize, holes: [usize; 2] },
    /// Two polygons' interiors overlap.
    PolygonsOverlap { polygons: [usize; 2] },
}

/// What is wrong with a ring on its own.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum RingProblem {
    /// Not closed, or fewer than 3 distinct vertices.
    NotClosed,
    /// A point repeated right after itself.
    RepeatedPoint,
    /// The ring passes twice through one vertex.
    VertexTwice,
    /// No area at its lowest-leftmost vertex (a spike, or a flat ring).
    ZeroArea,
}

impl std::fmt::Display for RingProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            RingProblem::NotClosed => "not closed or fewer than 3 vertices",
            RingProblem::RepeatedPoint => "repeated consecutive point",
            RingProblem::VertexTwice => "the ring passes twice through one vertex",
            RingProblem::ZeroArea => "zero area",
        })
    }
}

impl std::fmt::Display for ValidationError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ValidationError::Ring {
                polygon,
                ring,
                problem,
            } => write!(f, "polygon {polygon}, ring {ring}: {problem}"),
            ValidationError::WrongOrientation { polygon, ring } => {
                let kind = if *ring == 0 { "exterior" } else { "hole" };
                write!(f, "polygon {polygon}, ring {ring}: {kind} ring has the wrong orientation")
            }
            ValidationError::EdgesMeet {
                edges: [(a, b, pi, ri), (c, d, pj, rj)],
            } => write!(
                f,
                "edges cross or overlap: {a:?}-{b:?} (polygon {pi}, ring {ri}) and {c:?}-{d:?} (polygon {pj}, ring {rj})"
            ),
            ValidationError::HoleOutside { polygon, hole } => {
                write!(f, "polygon {polygon}: hole {hole} is not inside the exterior")
            }
            ValidationError::HolesOverlap {
                polygon,
                holes: [h, k],
            } => write!(f, "polygon {polygon}: hole {h} overlaps hole {k}"),
            ValidationError::PolygonsOverlap { polygons: [p, q] } => {
                write!(f, "polygon {p} overlaps polygon {q}")
            }
        }
    }
}

impl std::error::Error for ValidationError {}

/// Checks `result` against the output contract; the error says which rule broke where.
pub fn validate(result: &MultiPolygon) -> Result<(), ValidationError> {
    let mut edges: Vec<(Point, Point, usize, usize)> = Vec::new();
    for (pi, polygon) in result.0.iter().enumerate() {
        for (ri, ring) in polygon.rings().enumerate() {
            let turn = ring_turn(ring).map_err(|problem| ValidationError::Ring {
                polygon: pi,
                ring: ri,
                problem,
            })?;
            let want = if ri == 0 {
                Ordering::Greater
            } else {
                Ordering::Less
            };
            if turn != want {
                return Err(ValidationError::WrongOrientation {
                    polygon: pi,
                    ring: ri,
                });
            }
            edges.extend(ring.windows(2).map(|w| (w[0], w[1], pi, ri)));
        }
    }
    check_edges(&mut edges)?;
    check_nesting(result)
}

/// The turn of closed `ring` at its lowest-leftmost vertex (its orientation, `Greater` counter-clockwise), or what
/// is wrong with it on its own: too few vertices, a vertex twice, or no area there.
fn ring_turn(ring: &[Point]) -> Result<Ordering, RingProblem> {
    if ring.len() < 4 || ring.first() != ring.last() {
        return Err(RingProblem::NotClosed);
    }
    if ring.windows(2).any(|w| w[0] == w[1]) {
        return Err(RingProblem::RepeatedPoint);
    }
    let mut distinct: Vec<Point> = ring[..ring.len() - 1].to_vec();
    distinct.sort_by(lexicographic);
    if distinct.windows(2).any(|w| w[0] == w[1]) {
        return Err(RingProblem::VertexTwice);
    }
    let n = ring.len() - 1;
    let k = lowest_leftmost(&ring[..n]);
    match orient(ring[(k + n - 1) % n], ring[k], ring[k + 1]) {
        Ordering::Equal => Err(RingProblem::ZeroArea),
        turn => Ok(turn),
    }
}

/// The orientation of closed `ring` (`Greater` counter-clockwise) if it is simple: a ring [`validate`] would
/// accept, its edges meeting only where consecutive ones share a vertex. Every pair of edges is tested: for small
/// rings.
pub(crate) fn simple_ring_turn(ring: &[Point]) -> Option<Ordering> {
    if let Some(turn) = convex_turn(ring) {
        return Some(turn);
    }
    let turn = ring_turn(ring).ok()?;
    let edges = || ring.windows(2).map(|w| [w[0], w[1]]);
    let crossing =
        (edges().enumerate()).any(|(i, e)| edges().skip(i + 1).any(|f| edges_conflict(e, f)));
    (!crossing).then_some(turn)
}

/// No two edges may meet except at a common endpoint.
fn check_edges(edges: &mut [(Point, Point, usize, usize)]) -> Result<(), ValidationError> {
    edges.sort_by(|a, b| a.0.x.min(a.1.x).total_cmp(&b.0.x.min(b.1.x)));
    let mut active: Vec<usize> = Vec::new();
    for i in 0..edges.len() {
        let (a, b, pi, ri) = edges[i];
        let min_x = a.x.min(b.x);
        active.retain(|&j| edges[j].0.x.max(edges[j].1.x) >= min_x);
        for &j in &active {
            let (c, d, pj, rj) = edges[j];
            if edges_conflict([a, b], [c, d]) {
                return Err(ValidationError::EdgesMeet {
                    edges: [(a, b, pi, ri), (c, d, pj, rj)],
                });
            }
        }
        active.push(i);
    }
    Ok(())
}

/// The orientation of closed `ring` if it is strictly convex, in one pass: it turns the same way, strictly, at every
/// vertex, and goes around once. Turning one way, its direction goes around monotonically, k times in all, and the
/// sign of its x component (zeros aside) changes twice per turn around: twice in all for a convex ring, 2k times
/// for a star that winds k times.
pub(crate) fn convex_turn(ring: &[Point]) -> Option<Ordering> {
    let n = ring
        .len()
        .checked_sub(1)
        .filter(|&n| n >= 3 && ring[0] == ring[n])?;
    // (Every index below is at most n, and `ring[n]` is `ring[0]`: no `% n`, a division per vertex.)
    let turn = orient(ring[n - 1], ring[0], ring[1]);
    let x_direction = |i: usize| ring[i + 1].x.partial_cmp(&ring[i].x);
    let mut last_direction = (0..n)
        .rev()
        .map(x_direction)
        .find(|&d| d != Some(Ordering::Equal))?;
    let mut changes = 0;
    for i in 0..n {
        if i > 0 && orient(ring[i - 1], ring[i], ring[i + 1]) != turn {
            return None;
        }
        let direction = x_direction(i);
        if direction != Some(Ordering::Equal) {
            changes += usize::from(direction != last_direction);
            last_direction = direction;
        }
    }
    (turn != Ordering::Equal && changes == 2).then_some(turn)
}

/// Do edges `a b` and `c d` meet other than at one common endpoint?
fn edges_conflict([a, b]: [Point; 2], [c, d]: [Point; 2]) -> bool {
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    let shared = |p: Point| p == a || p == b;
    let touches =
        |p: Point, q: Point, r: Point, o: Ordering| o == Ordering::Equal && within(q, r, p);
    if o1 == Ordering::Equal && o2 == Ordering::Equal {
        // Collinear: they may share one endpoint, nothing more.
        [c, d].iter().any(|&p| within(a, b, p) && !shared(p))
            || [a, b].iter().any(|&p| within(c, d, p) && p != c && p != d)
            || (shared(c) && shared(d))
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
    }
}

/// Holes inside their shell and not inside each other; polygons' interiors disjoint.
fn check_nesting(result: &MultiPolygon) -> Result<(), ValidationError> {
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
                return Err(ValidationError::HoleOutside {
                    polygon: pi,
                    hole: hi + 1,
                });
            }
            for (hj, other) in polygon.holes.iter().enumerate().filter(|&(hj, _)| hj != hi) {
                if sides(hole, other, bbox(other)).any(|(_, side)| side == Side::Inside) {
                    return Err(ValidationError::HolesOverlap {
                        polygon: pi,
                        holes: [hi + 1, hj + 1],
                    });
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
                return Err(ValidationError::PolygonsOverlap { polygons: [pi, qi] });
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

    /// Simple rings, by the one-pass test for convex ones and the pairwise test for the others, and rings that are
    /// not simple, among them a five-pointed star, which turns the same way at every vertex.
    #[test]
    fn tells_simple_rings_and_their_orientation() {
        let closed = |points: &[[f64; 2]]| -> Vec<Point> {
            (points.iter().chain(points.first()))
                .map(|&[x, y]| Point::new(x, y))
                .collect()
        };
        let reversed =
            |points: &[[f64; 2]]| closed(&points.iter().rev().copied().collect::<Vec<_>>());
        let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let l_shape = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        let straight_on = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 2.0]];
        for simple in [&square[..], &l_shape, &straight_on] {
            assert_eq!(
                simple_ring_turn(&closed(simple)),
                Some(Ordering::Greater),
                "{simple:?}"
            );
            assert_eq!(
                simple_ring_turn(&reversed(simple)),
                Some(Ordering::Less),
                "{simple:?}"
            );
        }
        assert_eq!(convex_turn(&closed(&square)), Some(Ordering::Greater));
        assert_eq!(convex_turn(&closed(&l_shape)), None);
        let star: Vec<[f64; 2]> = (0..5)
            .map(|i| {
                let angle = f64::from(i) * 4.0 * std::f64::consts::PI / 5.0;
                [angle.cos(), angle.sin()]
            })
            .collect();
        let bow_tie = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0], [2.0, 2.0]];
        let spike = [[0.0, 0.0], [2.0, 0.0], [3.0, 0.0], [2.0, 0.0], [2.0, 2.0]];
        let through_a_vertex_twice = [
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 1.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [1.0, 1.0],
        ];
        let flat = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        let vertex_on_an_edge = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
        for not_simple in [
            &star[..],
            &bow_tie,
            &spike,
            &through_a_vertex_twice,
            &flat,
            &vertex_on_an_edge,
        ] {
            assert_eq!(
                simple_ring_turn(&closed(not_simple)),
                None,
                "{not_simple:?}"
            );
            assert_eq!(
                simple_ring_turn(&reversed(not_simple)),
                None,
                "{not_simple:?}"
            );
        }
    }

    #[test]
    fn accepts_a_square_with_a_hole_and_rejects_broken_rings() {
        let shell: &[[f64; 2]] = &[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [0.0, 0.0]];
        let hole: &[[f64; 2]] = &[[1.0, 1.0], [1.0, 2.0], [2.0, 2.0], [2.0, 1.0], [1.0, 1.0]];
        assert_eq!(validate(&mp(&[shell, hole])), Ok(()));
        let reversed: Vec<[f64; 2]> = shell.iter().rev().copied().collect();
        assert!(matches!(
            validate(&mp(&[&reversed])),
            Err(ValidationError::WrongOrientation { .. })
        ));
        let open = &shell[..4];
        assert!(validate(&mp(&[open])).is_err());
        let bow_tie: &[[f64; 2]] = &[[0.0, 0.0], [2.0, 0.0], [0.0, 2.0], [2.0, 2.0], [0.0, 0.0]];
        assert!(validate(&mp(&[bow_tie])).is_err());
        let outside_hole: &[[f64; 2]] =
            &[[5.0, 5.0], [5.0, 6.0], [6.0, 6.0], [6.0, 5.0], [5.0, 5.0]];
        assert!(matches!(
            validate(&mp(&[shell, outside_hole])),
            Err(ValidationError::HoleOutside { .. })
        ));
        // A hole touching the shell at two vertices and bulging out between them.
        let triangle: &[[f64; 2]] = &[[0.0, 1.0], [7.0, 4.0], [7.0, 7.0], [0.0, 1.0]];
        let bulge: &[[f64; 2]] = &[[5.0, 4.0], [7.0, 7.0], [8.0, 4.0], [7.0, 4.0], [5.0, 4.0]];
        assert!(matches!(
            validate(&mp(&[triangle, bulge])),
            Err(ValidationError::HoleOutside { .. })
        ));
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
        assert!(matches!(
            validate(&nested),
            Err(ValidationError::PolygonsOverlap { .. })
        ));
    }
}
