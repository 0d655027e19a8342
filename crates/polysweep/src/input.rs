//! Checking the input and turning its rings into sweep events (step 1 of Fig. 5).

use crate::error::{Error, Location};
use crate::events::{InputEdge, Operand};
use crate::exact::Line;
use crate::geometry::{open_len, MultiPolygon, Point, Polygon};

/// Largest coordinate magnitude accepted: 2^200. Within it (and above [`MIN_COORDINATE`]) the products formed by
/// the exact predicates neither overflow nor underflow, which their proofs assume.
pub const MAX_COORDINATE: f64 = (1u128 << 100) as f64 * (1u128 << 100) as f64;
/// Smallest non-zero coordinate magnitude accepted: 2^-200.
pub const MIN_COORDINATE: f64 = 1.0 / MAX_COORDINATE;

/// Checks every coordinate of `operand` (its index among the operation's operands is `index`).
pub(crate) fn check(index: usize, operand: &MultiPolygon) -> Result<(), Error> {
    for (polygon, p) in operand.0.iter().enumerate() {
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
            }
        }
    }
    Ok(())
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

    pub fn of<'a>(points: impl IntoIterator<Item = &'a Point>) -> Bounds {
        let empty = Bounds {
            min: [f64::INFINITY; 2],
            max: [f64::NEG_INFINITY; 2],
        };
        points.into_iter().fold(empty, |b, p| Bounds {
            min: [b.min[0].min(p.x), b.min[1].min(p.y)],
            max: [b.max[0].max(p.x), b.max[1].max(p.y)],
        })
    }

    pub fn of_polygons(polygons: &MultiPolygon) -> Bounds {
        Bounds::of(polygons.0.iter().flat_map(|p| p.rings()).flatten())
    }

    pub fn max_x(&self) -> f64 {
        self.max[0]
    }

    fn meets(&self, other: &Bounds) -> bool {
        (0..2).all(|k| self.min[k] <= other.max[k] && other.min[k] <= self.max[k])
    }
}

/// Appends the edges of every ring of `polygons` whose polygon's box (of all its rings) meets `region`. Edges of
/// zero length are skipped; a ring with fewer than three vertices still gives its edges, which cancel each other
/// (§7.2).
///
/// Leaving out polygons outside `region` is exact, not a heuristic: a ring's winding number is 0 outside its box, so
/// within `region` the operand's interior, under either fill rule, is that of the polygons kept.
pub(crate) fn add_edges(
    edges: &mut Vec<InputEdge>,
    polygons: &MultiPolygon,
    operand: Operand,
    region: &Bounds,
) {
    // The box of all the polygon's rings, not only its exterior: a hole may reach outside its shell.
    let near = |p: &&Polygon| {
        *region == Bounds::EVERYWHERE || Bounds::of(p.rings().flatten()).meets(region)
    };
    edges.reserve(polygons.vertex_count()); // at most one edge per vertex
    for ring in polygons.0.iter().filter(near).flat_map(|p| p.rings()) {
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
