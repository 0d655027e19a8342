//! Checking the input and turning its rings into sweep events (step 1 of Fig. 5).

use crate::error::{Error, Location};
use crate::events::{Operand, SweepEvent};
use crate::exact::{Line, SweepPoint};
use crate::geometry::{open_len, MultiPolygon};

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

/// Appends two events per edge of every ring of `polygons`. Edges of zero length are skipped; a ring with fewer
/// than three vertices still gives its edges, which cancel each other (§7.2).
pub(crate) fn add_events(events: &mut Vec<SweepEvent>, polygons: &MultiPolygon, operand: Operand) {
    for ring in polygons.0.iter().flat_map(|p| p.rings()) {
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
            let line = Line { a, b };
            let segment = (events.len() / 2) as u32;
            let id = events.len() as u32;
            // Crossing an edge upwards enters a counter-clockwise ring when the edge runs left to right.
            let winding = if forward { 1 } else { -1 };
            let mut left =
                SweepEvent::new(SweepPoint::input(a), true, line, operand, segment, winding);
            let mut right =
                SweepEvent::new(SweepPoint::input(b), false, line, operand, segment, winding);
            left.other = id + 1;
            right.other = id;
            events.push(left);
            events.push(right);
        }
    }
}

/// The largest x of an operand's vertices, or -∞ when it has none.
pub(crate) fn max_x(polygons: &MultiPolygon) -> f64 {
    polygons
        .0
        .iter()
        .flat_map(|p| p.rings())
        .flatten()
        .map(|p| p.x)
        .fold(f64::NEG_INFINITY, f64::max)
}
