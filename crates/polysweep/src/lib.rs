//! # polysweep
//!
//! Boolean operations on polygons — intersection, union, difference and xor — by the plane sweep of Martínez,
//! Rueda and Feito, *A new algorithm for computing Boolean operations on polygons* (Computers & Geosciences,
//! 2009), with exact predicates so that it never fails on rounding.
//!
//! ```
//! use polysweep::{intersection, union, MultiPolygon};
//!
//! let square = |x: f64, y: f64| MultiPolygon::from_coordinates(&[vec![vec![
//!     [x, y], [x + 2.0, y], [x + 2.0, y + 2.0], [x, y + 2.0], [x, y],
//! ]]]);
//! let (a, b) = (square(0.0, 0.0), square(1.0, 1.0));
//! assert_eq!(intersection(&a, &b)?.area(), 1.0);
//! assert_eq!(union(&a, &b)?.area(), 7.0);
//! # Ok::<(), polysweep::Error>(())
//! ```
//!
//! ## Input
//! Each operand is a polygon set ([`MultiPolygon`]). Its interior is defined by a [`FillRule`] over all its rings
//! together: even-odd by default (§7.3 of the paper: ring orientation does not matter, rings may cross themselves
//! and each other, a ring inside another is a hole), or non-zero. Rings may be open or closed; zero-length edges
//! are ignored. Coordinates must be finite with magnitude 0 or within [`MIN_COORDINATE`]..=[`MAX_COORDINATE`];
//! anything else is an [`Error`] naming the operand, polygon, ring and vertex.
//!
//! ## Output contract
//! The result is a [`MultiPolygon`], checked by [`validate`] in every test:
//! - every ring is closed (first point repeated last) and has at least 3 distinct vertices, with no repeated
//!   consecutive points and no zero-area spikes;
//! - exterior rings are counter-clockwise and holes clockwise (RFC 7946);
//! - rings do not cross or touch themselves; two rings meet at most at common vertices; every hole lies inside
//!   its polygon's exterior; an island inside a hole is a polygon of its own;
//! - an empty result is an empty `MultiPolygon`;
//! - input vertices that no intersection touches come out bit-for-bit identical; intersection points are exact
//!   until the output, where they are rounded to the nearest `f64`.
//!
//! Vertices where the boundary goes straight on (from the input, or where an edge of the other operand ended)
//! are kept.
//!
//! ## The algorithm, stage by stage
//! [`events`] (§3, Fig. 8, the order of §4) → [`status`] (§3, §7.1) → [`subdivide`] (Fig. 6, §7.2, §7.3) →
//! [`select`] (§4, Fig. 9, Fig. 10) → [`connect`] (§5), driven by [`sweep`] (Fig. 5) with the predicates of
//! [`exact`]. How this is made robust is on the [`robustness`] page.

pub mod connect;
pub mod error;
pub mod events;
pub mod exact;
pub mod geometry;
pub mod input;
pub mod select;
pub mod status;
pub mod subdivide;
pub mod sweep;
pub mod validate;

#[doc = include_str!("../../../docs/robustness.md")]
pub mod robustness {}

pub use error::{Error, Location};
pub use geometry::{ring_area, MultiPolygon, Point, Polygon, Ring};
pub use input::{MAX_COORDINATE, MIN_COORDINATE};
pub use select::{FillRule, Operation};
pub use validate::validate;

use select::Selection;

/// Options of an operation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Options {
    pub fill_rule: FillRule,
}

/// What one sweep did, for display and benchmarks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Edges of both operands (after dropping zero-length ones).
    pub input_edges: usize,
    /// Points where two edges properly cross (constructed intersection points).
    pub crossings: usize,
    /// Events processed, including those made by subdivision.
    pub events: usize,
}

/// Computes `operation` on `subject` and `clipping` (for [`Operation::Difference`], subject minus clipping).
pub fn overlay(
    operation: Operation,
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    options: &Options,
) -> Result<MultiPolygon, Error> {
    overlay_with_stats(operation, subject, clipping, options).map(|(result, _)| result)
}

/// [`overlay`], also returning what the sweep did.
pub fn overlay_with_stats(
    operation: Operation,
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    options: &Options,
) -> Result<(MultiPolygon, Stats), Error> {
    input::check(0, subject)?;
    input::check(1, clipping)?;
    Ok(checked_overlay(operation, subject, clipping, options))
}

fn checked_overlay(operation: Operation, subject: &MultiPolygon, clipping: &MultiPolygon, options: &Options) -> (MultiPolygon, Stats) {
    let mut events = Vec::new();
    input::add_events(&mut events, subject, 0);
    input::add_events(&mut events, clipping, 1);
    let input_edges = events.len() / 2;
    // Past the last x where the result can have an edge, the sweep can stop (the end of the subject for a
    // difference, of either operand for an intersection).
    let stop_x = match operation {
        Operation::Intersection => input::max_x(subject).min(input::max_x(clipping)),
        Operation::Difference => input::max_x(subject),
        Operation::Union | Operation::Xor => f64::INFINITY,
    };
    let mut sweep = sweep::Sweep::new(events, Selection { operation, fill_rule: options.fill_rule }, stop_x);
    sweep.run();
    let stats = Stats { input_edges, crossings: sweep.exact.crossing_count(), events: sweep.events.len() };
    let events = &sweep.events;
    let result = connect::connect(&sweep.exact, &sweep.vertices, &mut sweep.result, |e| events[e as usize].result_edge);
    (result, stats)
}

/// `subject ∩ clipping` under the even-odd rule.
pub fn intersection(subject: &MultiPolygon, clipping: &MultiPolygon) -> Result<MultiPolygon, Error> {
    overlay(Operation::Intersection, subject, clipping, &Options::default())
}

/// `subject ∪ clipping` under the even-odd rule.
pub fn union(subject: &MultiPolygon, clipping: &MultiPolygon) -> Result<MultiPolygon, Error> {
    overlay(Operation::Union, subject, clipping, &Options::default())
}

/// `subject − clipping` under the even-odd rule.
pub fn difference(subject: &MultiPolygon, clipping: &MultiPolygon) -> Result<MultiPolygon, Error> {
    overlay(Operation::Difference, subject, clipping, &Options::default())
}

/// `subject ⊕ clipping` (symmetric difference) under the even-odd rule.
pub fn xor(subject: &MultiPolygon, clipping: &MultiPolygon) -> Result<MultiPolygon, Error> {
    overlay(Operation::Xor, subject, clipping, &Options::default())
}

/// `operation` over many operands: the union, intersection or xor of all, or for [`Operation::Difference`] the
/// first minus all the others. Errors name the operand by its index in `operands`.
///
/// The paper's flags describe two operands, so one sweep takes two: the operands are combined pairwise in a
/// balanced tree (log₂ m rounds of sweeps), each intermediate result already a valid polygon set. Under the
/// non-zero rule only the first round uses it: intermediate results are valid and mean the same under both.
///
/// ```
/// use polysweep::{overlay_all, MultiPolygon, Operation, Options};
/// let square = |x: f64| MultiPolygon::from_coordinates(&[vec![vec![[x, 0.0], [x + 1.0, 0.0], [x + 1.0, 1.0], [x, 1.0]]]]);
/// let row = overlay_all(Operation::Union, &[square(0.0), square(1.0), square(2.0)], &Options::default())?;
/// assert_eq!(row.0.len(), 1);
/// assert_eq!(row.area(), 3.0);
/// # Ok::<(), polysweep::Error>(())
/// ```
pub fn overlay_all(operation: Operation, operands: &[MultiPolygon], options: &Options) -> Result<MultiPolygon, Error> {
    for (index, operand) in operands.iter().enumerate() {
        input::check(index, operand)?;
    }
    let Some((first, rest)) = operands.split_first() else { return Ok(MultiPolygon::default()) };
    if operation == Operation::Difference {
        let clipping = reduce(Operation::Union, rest, options);
        return Ok(checked_overlay(Operation::Difference, first, &clipping, options).0);
    }
    Ok(reduce(operation, operands, options))
}

/// Combines checked operands pairwise, halving their number each round. Even a single operand goes through one
/// sweep, so that the result always meets the output contract.
fn reduce(operation: Operation, operands: &[MultiPolygon], options: &Options) -> MultiPolygon {
    let empty = MultiPolygon::default();
    let mut layer: Vec<MultiPolygon> = operands
        .chunks(2)
        .map(|pair| match pair {
            [a, b] => checked_overlay(operation, a, b, options).0,
            // A lone operand is normalised by a union with nothing (intersecting it with nothing would empty it).
            [a] => checked_overlay(Operation::Union, a, &empty, options).0,
            _ => unreachable!("chunks of two"),
        })
        .collect();
    let normalised = Options { fill_rule: FillRule::EvenOdd };
    while layer.len() > 1 {
        let mut pairs = std::mem::take(&mut layer).into_iter();
        while let Some(a) = pairs.next() {
            layer.push(match pairs.next() {
                Some(b) => checked_overlay(operation, &a, &b, &normalised).0,
                None => a,
            });
        }
    }
    layer.pop().unwrap_or_default()
}

/// The union of all operands.
pub fn union_all(operands: &[MultiPolygon]) -> Result<MultiPolygon, Error> {
    overlay_all(Operation::Union, operands, &Options::default())
}

/// The intersection of all operands.
pub fn intersection_all(operands: &[MultiPolygon]) -> Result<MultiPolygon, Error> {
    overlay_all(Operation::Intersection, operands, &Options::default())
}

/// The symmetric difference of all operands: the points inside an odd number of them.
pub fn xor_all(operands: &[MultiPolygon]) -> Result<MultiPolygon, Error> {
    overlay_all(Operation::Xor, operands, &Options::default())
}

/// `subject` minus every one of `clips`. Errors name `subject` as operand 0 and `clips[i]` as operand `i + 1`.
pub fn difference_all(subject: &MultiPolygon, clips: &[MultiPolygon]) -> Result<MultiPolygon, Error> {
    let operands: Vec<MultiPolygon> = std::iter::once(subject.clone()).chain(clips.iter().cloned()).collect();
    overlay_all(Operation::Difference, &operands, &Options::default())
}
