//! Checking the input and turning its rings into sweep events (step 1 of Fig. 5).

use crate::edges::{InputEdge, Operand};
use crate::error::{Error, Location};
use crate::events::{ordered_bits, sort_by_key, Buckets};
use crate::exact::Line;
use crate::geometry::{
    larger, next_around, open_len, smaller, MultiPolygon, Point, Polygon, MAX_COORDINATE,
    MIN_COORDINATE,
};

/// Checks every coordinate of `operand` (its index among the operation's operands is `index`), and returns the box
/// of each of its polygons (of all its rings: a hole may reach outside its shell), made on the same pass. The pass
/// only notes whether a polygon has a bad coordinate, without a branch per coordinate; such a polygon is read again
/// to name the first one.
///
/// (One pass for both, as every operation makes it over all its input: [`boxes`] alone is for polygons the
/// pipeline made itself.)
pub(crate) fn check(index: usize, operand: &MultiPolygon) -> Result<Vec<Bounds>, Error> {
    let mut boxes = Vec::with_capacity(operand.0.len());
    for (polygon, p) in operand.0.iter().enumerate() {
        let mut bounds = Bounds::EMPTY;
        let mut accepted = true;
        for ring in p.rings() {
            for point in ring {
                accepted &= is_accepted(point.x) & is_accepted(point.y);
                bounds = bounds.around(&Bounds::at(point));
            }
        }
        if let Some(error) = (!accepted)
            .then(|| first_rejected(index, polygon, p))
            .flatten()
        {
            return Err(error);
        }
        boxes.push(bounds);
    }
    Ok(boxes)
}

/// The box of each polygon of `operand`.
pub(crate) fn boxes(operand: &MultiPolygon) -> Vec<Bounds> {
    (operand.0.iter())
        .map(|p| {
            p.rings()
                .flatten()
                .fold(Bounds::EMPTY, |b, q| b.around(&Bounds::at(q)))
        })
        .collect()
}

/// Is `value` a coordinate the exact predicates' proofs cover: finite, and 0 or of a magnitude within
/// [`MIN_COORDINATE`]..=[`MAX_COORDINATE`]?
fn is_accepted(value: f64) -> bool {
    // On the bits of the magnitude, which order non-negative floats as their values (NaNs above infinity): 0, or
    // within the range by one unsigned comparison.
    let magnitude = value.to_bits() & !(1 << 63);
    let (min, max) = (MIN_COORDINATE.to_bits(), MAX_COORDINATE.to_bits());
    magnitude == 0 || magnitude.wrapping_sub(min) <= max - min
}

/// The error for the first coordinate of polygon `p` (number `polygon` of operand `index`) that [`is_accepted`]
/// rejects, if any.
fn first_rejected(index: usize, polygon: usize, p: &Polygon) -> Option<Error> {
    let (ring, vertex, value) = (p.rings().enumerate())
        .flat_map(|(ring, r)| {
            r.iter()
                .enumerate()
                .map(move |(vertex, point)| (ring, vertex, point))
        })
        .flat_map(|(ring, vertex, point)| [point.x, point.y].map(|value| (ring, vertex, value)))
        .find(|&(_, _, value)| !is_accepted(value))?;
    let at = Location {
        operand: index,
        polygon,
        ring,
        vertex,
    };
    Some(if value.is_finite() {
        Error::CoordinateOutOfRange { at, value }
    } else {
        Error::NonFiniteCoordinate { at, value }
    })
}

/// An axis-aligned box, closed; the empty box has min > max.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Bounds {
    pub min: [f64; 2],
    pub max: [f64; 2],
}

impl Bounds {
    pub const EMPTY: Bounds = Bounds {
        min: [f64::INFINITY; 2],
        max: [f64::NEG_INFINITY; 2],
    };

    /// The box of one point.
    pub fn at(p: &Point) -> Bounds {
        Bounds {
            min: [p.x, p.y],
            max: [p.x, p.y],
        }
    }

    /// The box around this one and `other`.
    pub fn around(&self, other: &Bounds) -> Bounds {
        Bounds {
            min: [
                smaller(self.min[0], other.min[0]),
                smaller(self.min[1], other.min[1]),
            ],
            max: [
                larger(self.max[0], other.max[0]),
                larger(self.max[1], other.max[1]),
            ],
        }
    }

    /// The box around `boxes`.
    pub fn around_all(boxes: &[Bounds]) -> Bounds {
        boxes.iter().fold(Bounds::EMPTY, |b, c| b.around(c))
    }

    pub fn max_x(&self) -> f64 {
        self.max[0]
    }

    /// The smallest coordinate on axis `k` (0: x, 1: y).
    pub fn min(&self, k: usize) -> f64 {
        self.min[k]
    }

    /// The four corners (of a box that is not empty).
    pub fn corners(&self) -> [Point; 4] {
        let ([x0, y0], [x1, y1]) = (self.min, self.max);
        [
            Point::new(x0, y0),
            Point::new(x1, y0),
            Point::new(x1, y1),
            Point::new(x0, y1),
        ]
    }

    /// The largest magnitude of a coordinate in the box (0 for an empty box): every point the sweep makes from
    /// edges within the box lies within it, crossings included.
    pub fn magnitude(&self) -> f64 {
        if self.min[0] > self.max[0] {
            return 0.0;
        }
        (self.min.iter().chain(&self.max)).fold(0.0, |m, v| larger(m, v.abs()))
    }

    /// This box grown by `margin` on every side.
    pub fn grown(&self, margin: f64) -> Bounds {
        Bounds {
            min: self.min.map(|v| v - margin),
            max: self.max.map(|v| v + margin),
        }
    }

    pub fn meets(&self, other: &Bounds) -> bool {
        (0..2).all(|k| self.min[k] <= other.max[k] && other.min[k] <= self.max[k])
    }

    /// Does this box lie within `other`?
    pub fn within(&self, other: &Bounds) -> bool {
        (0..2).all(|k| other.min[k] <= self.min[k] && self.max[k] <= other.max[k])
    }
}

/// The polygons that `keep` keeps (given a polygon's index), from left to right by the left sides of their boxes
/// `boxes`: the order in which an operation lists their edges. Not in the paper, and a matter of speed only. The
/// sweep reads the edges in its own order, left to right; listed so, the edges it reads next lie in memory near
/// those it has just read. (Listed row by row instead, the cells of a board's column lie a row apart, and the sweep
/// of 200 × 200 cells took a third longer.)
pub(crate) fn left_to_right(boxes: &[Bounds], keep: impl Fn(usize) -> bool) -> Vec<usize> {
    let mut order: Vec<(u64, u32)> = (0..boxes.len())
        .filter(|&p| keep(p))
        .map(|p| (ordered_bits(boxes[p].min[0]), p as u32))
        .collect();
    sort_by_key(&mut order, &mut Buckets::default());
    order.into_iter().map(|(_, p)| p as usize).collect()
}

/// Appends the edges of every ring of the polygons of `polygons` that `which` names (by index), in that order.
/// Edges of zero length are skipped; a ring with fewer than three vertices still gives its edges, which cancel each
/// other (§7.2).
pub(crate) fn add_edges(
    edges: &mut Vec<InputEdge>,
    polygons: &MultiPolygon,
    operand: Operand,
    which: impl IntoIterator<Item = usize>,
) {
    crate::workspace::reserve(edges, polygons.vertex_count()); // at most one edge per vertex
    for p in which {
        for ring in polygons.0[p].rings() {
            add_ring_edges(edges, ring, operand);
        }
    }
}

/// Appends the edges of one ring (open or closed) for `operand`.
pub(crate) fn add_ring_edges(edges: &mut Vec<InputEdge>, ring: &[Point], operand: Operand) {
    let n = open_len(ring);
    for i in 0..n {
        let (from, to) = (ring[i], ring[next_around(i, n)]);
        push_edge(edges, [from.x, from.y], [to.x, to.y], operand);
    }
}

/// The edge of a ring from `from` to `to` (none if they are equal), with the winding that ring gives it.
#[inline(always)]
pub(crate) fn push_edge(
    edges: &mut Vec<InputEdge>,
    from: [f64; 2],
    to: [f64; 2],
    operand: Operand,
) {
    if from == to {
        return;
    }
    // Sweep order: by x, then y (§7.1: a vertical edge's lower end is its left end).
    let forward = (from[0], from[1]) < (to[0], to[1]);
    let (a, b) = if forward { (from, to) } else { (to, from) };
    edges.push(InputEdge {
        line: Line { a, b },
        operand,
        // Crossing an edge upwards enters a counter-clockwise ring when the edge runs left to right.
        winding: if forward { 1 } else { -1 },
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    fn operand(rings: &[&[[f64; 2]]]) -> MultiPolygon {
        let polygon: Vec<Vec<[f64; 2]>> = rings.iter().map(|r| r.to_vec()).collect();
        let square = vec![vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]];
        MultiPolygon::from_coordinates(&[square, polygon])
    }

    #[test]
    fn coordinates_are_accepted_exactly_within_the_range_and_at_its_ends() {
        let (above, below) = (MAX_COORDINATE.next_up(), MIN_COORDINATE.next_down());
        for (value, accepted) in [
            (0.0, true),
            (-0.0, true),
            (1.0, true),
            (-1.5, true),
            (MIN_COORDINATE, true),
            (-MIN_COORDINATE, true),
            (MAX_COORDINATE, true),
            (-MAX_COORDINATE, true),
            (above, false),
            (-above, false),
            (below, false),
            (-below, false),
            (f64::MIN_POSITIVE / 4.0, false), // subnormal
            (f64::MAX, false),
            (f64::INFINITY, false),
            (f64::NEG_INFINITY, false),
            (f64::NAN, false),
            (-f64::NAN, false),
        ] {
            assert_eq!(is_accepted(value), accepted, "{value:e}");
        }
    }

    #[test]
    fn the_first_rejected_coordinate_is_named_and_boxes_cover_every_ring() {
        let shell: &[[f64; 2]] = &[[-0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]];
        let hole: &[[f64; 2]] = &[[1.0, 1.0], [9.0, -2.0], [1.0, 2.0]];
        let boxes = check(3, &operand(&[shell, hole])).unwrap();
        assert_eq!(
            boxes[1],
            Bounds {
                min: [-0.0, -2.0],
                max: [9.0, 3.0]
            }
        );
        let tiny = MIN_COORDINATE / 2.0;
        for (bad_hole, vertex, value, finite) in [
            (
                &[[1.0, 1.0], [2.0, 1.0], [f64::NAN, 2.0]][..],
                2,
                f64::NAN,
                false,
            ),
            (
                &[[1.0, 1.0], [2.0, f64::INFINITY], [1e300, 2.0]][..],
                1,
                f64::INFINITY,
                false,
            ),
            (
                &[[1.0, 1.0], [2.0, tiny], [1.0, f64::NAN]][..],
                1,
                tiny,
                true,
            ),
            (
                &[[-1e300, 1.0], [2.0, 1.0], [1.0, 2.0]][..],
                0,
                -1e300,
                true,
            ),
        ] {
            let error = check(3, &operand(&[shell, bad_hole])).unwrap_err();
            let at = Location {
                operand: 3,
                polygon: 1,
                ring: 1,
                vertex,
            };
            match error {
                Error::NonFiniteCoordinate {
                    at: found,
                    value: v,
                } if !finite => {
                    assert_eq!((found, v.is_nan()), (at, value.is_nan()));
                    assert!(v.is_nan() || v == value);
                }
                Error::CoordinateOutOfRange {
                    at: found,
                    value: v,
                } if finite => {
                    assert_eq!((found, v), (at, value));
                }
                other => panic!("{bad_hole:?}: {other:?}"),
            }
        }
    }
}
