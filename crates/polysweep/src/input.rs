//! Checking the input and turning its rings into sweep events (step 1 of Fig. 5).

use crate::error::{Error, Location};
use crate::events::{InputEdge, Operand};
use crate::exact::Line;
use crate::geometry::{larger, open_len, smaller, MultiPolygon, Point};

/// Largest coordinate magnitude accepted: 2^200. Within it (and above [`MIN_COORDINATE`]) the products formed by
/// the exact predicates neither overflow nor underflow, which their proofs assume.
pub const MAX_COORDINATE: f64 = (1u128 << 100) as f64 * (1u128 << 100) as f64;
/// Smallest non-zero coordinate magnitude accepted: 2^-200.
pub const MIN_COORDINATE: f64 = 1.0 / MAX_COORDINATE;

/// Checks every coordinate of `operand` (its index among the operation's operands is `index`), and returns the box
/// of each of its polygons (of all its rings: a hole may reach outside its shell), made on the same pass.
pub(crate) fn check(index: usize, operand: &MultiPolygon) -> Result<Vec<Bounds>, Error> {
    let mut boxes = Vec::with_capacity(operand.0.len());
    for (polygon, p) in operand.0.iter().enumerate() {
        let mut bounds = Bounds::EMPTY;
        for (ring, r) in p.rings().enumerate() {
            for (vertex, point) in r.iter().enumerate() {
                let at = Location {
                    operand: index,
                    polygon,
                    ring,
                    vertex,
                };
                for value in [point.x, point.y] {
                    if !value.is_finite() {
                        return Err(Error::NonFiniteCoordinate { at, value });
                    }
                    let magnitude = value.abs();
                    if magnitude != 0.0 && !(MIN_COORDINATE..=MAX_COORDINATE).contains(&magnitude) {
                        return Err(Error::CoordinateOutOfRange { at, value });
                    }
                }
                bounds = bounds.around(&Bounds::at(point));
            }
        }
        boxes.push(bounds);
    }
    Ok(boxes)
}

/// An axis-aligned box, closed; the empty box has min > max.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Bounds {
    min: [f64; 2],
    max: [f64; 2],
}

impl Bounds {
    pub const EVERYWHERE: Bounds = Bounds {
        min: [f64::NEG_INFINITY; 2],
        max: [f64::INFINITY; 2],
    };

    pub const EMPTY: Bounds = Bounds {
        min: [f64::INFINITY; 2],
        max: [f64::NEG_INFINITY; 2],
    };

    /// The box of one point.
    fn at(p: &Point) -> Bounds {
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

    /// The largest magnitude of a coordinate in the box (0 for an empty box): every point the sweep makes from
    /// edges within the box lies within it, crossings included.
    pub fn magnitude(&self) -> f64 {
        if self.min[0] > self.max[0] {
            return 0.0;
        }
        (self.min.iter().chain(&self.max)).fold(0.0, |m, v| larger(m, v.abs()))
    }

    pub fn meets(&self, other: &Bounds) -> bool {
        (0..2).all(|k| self.min[k] <= other.max[k] && other.min[k] <= self.max[k])
    }
}

/// Appends the edges of every ring of the polygons of `polygons` that `keep` (given a polygon's index) keeps.
/// Edges of zero length are skipped; a ring with fewer than three vertices still gives its edges, which cancel each
/// other (§7.2).
pub(crate) fn add_edges(
    edges: &mut Vec<InputEdge>,
    polygons: &MultiPolygon,
    operand: Operand,
    keep: impl Fn(usize) -> bool,
) {
    edges.reserve(polygons.vertex_count()); // at most one edge per vertex
    let kept = polygons.0.iter().enumerate().filter(|&(p, _)| keep(p));
    for ring in kept.flat_map(|(_, p)| p.rings()) {
        let n = open_len(ring);
        for i in 0..n {
            let (from, to) = (ring[i], ring[(i + 1) % n]);
            if from == to {
                continue;
            }
            let (from, to) = ([from.x, from.y], [to.x, to.y]);
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
    }
}
