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
//! ## Lines and layers
//! The same sweep also clips polylines by a polygon set ([`clip`]), cuts polygons along polylines ([`split`]),
//! overlays two layers of features keeping, for every face, the features that cover it ([`overlay_layers`]), and
//! merges features by key ([`dissolve`]). They read the arrangement of all the edges, which the sweep keeps whole
//! for them, with the input segments on every edge (see docs/architecture.md).
//!
//! ## Input
//! Each operand is a polygon set ([`MultiPolygon`]). Its interior is defined by a [`FillRule`] over all its rings
//! together: even-odd by default (§7.3 of the paper: ring orientation does not matter, rings may cross themselves
//! and each other, a ring inside another is a hole), or by the winding number: non-zero, positive or negative (as
//! Clipper2 and i_overlay offer). Rings may be open or closed; zero-length edges
//! are ignored. Coordinates must be finite with magnitude 0 or within [`MIN_COORDINATE`]..=[`MAX_COORDINATE`];
//! anything else is an [`Error`] naming the operand, polygon, ring and vertex.
//!
//! ## Output contract
//! The result is a [`MultiPolygon`], checked by [`validate`](fn@validate) in every test:
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
//! ## Memory
//! Each thread keeps the working memory of its last operation (its largest vectors, emptied) for the next one, up
//! to [`KEEP_BYTES`]: memory fresh from the system costs a page fault per page on first use, which made up a fifth
//! of the time of an operation on Table 1's data. [`free_working_memory`] gives it back. On Linux, vectors of 4 MiB
//! and more are advised transparent huge pages (`madvise`), a fault per 2 MiB: where the system allows it (its
//! setting `always` or `madvise`), the largest operations spend far less time on faults (docs/benchmarks.md).
//!
//! ## The algorithm, stage by stage
//! The input is checked and made edges (step 1 of Fig. 5); the events are sorted (§3, Fig. 8, the order of §4);
//! the sweep of Fig. 5 keeps the status (§3, §7.1), subdivides edges (Fig. 6, §7.2, §7.3) and selects the result
//! edges (§4, Fig. 9, Fig. 10), which are connected into polygons (§5). docs/architecture.md maps each section of
//! the paper to its module, with every departure from the paper; how this is made robust is on the
//! [`robustness`] page.

// The stages, in the order an operation goes through them (see docs/architecture.md).
mod arrangement;
mod connect;
mod edges;
mod events;
mod input;
mod layers;
mod lines;
mod overlay;
mod prune;
mod rounding;
mod select;
mod snap_round;
mod status;
mod structure;
mod subdivide;
mod sweep;
mod trace;
// What every stage uses.
mod error;
mod exact;
mod geometry;
mod options;
mod validate;
mod workspace;

#[cfg(feature = "geojson")]
pub mod geojson;

/// Seeded random numbers for the unit tests (xorshift): reproducible, and no dependency.
#[cfg(test)]
mod test_random {
    /// Random 64-bit words.
    pub fn bits(seed: u64) -> impl FnMut() -> u64 {
        let mut state = seed;
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        }
    }

    /// Random floats in [0, 1).
    pub fn unit(seed: u64) -> impl FnMut() -> f64 {
        let mut bits = bits(seed);
        move || (bits() >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[doc = include_str!("../../../docs/robustness.md")]
pub mod robustness {}

pub use error::{Error, Location};
pub use geometry::{ring_area, MultiPolygon, Point, Polygon, Ring};
pub use geometry::{MAX_COORDINATE, MIN_COORDINATE};
pub use layers::{dissolve, overlay_layers, LayerFace, LayerMode};
pub use lines::{clip, split, Boundary, ClipOptions, Keep, LineString};
pub use options::Options;
#[doc(hidden)]
pub use options::Shortcuts;
pub use overlay::Stats;
pub use select::{FillRule, Operation};
pub use trace::{trace, trace_with_status_for, Meeting, Reason, Step, TraceEdge};
pub use validate::{validate, RingProblem, ValidationError};
pub use workspace::{free_working_memory, KEEP_BYTES};

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
    overlay::overlay_pair(operation, subject, clipping, options)
}

/// `subject ∩ clipping` under the even-odd rule.
pub fn intersection(
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
) -> Result<MultiPolygon, Error> {
    overlay(
        Operation::Intersection,
        subject,
        clipping,
        &Options::default(),
    )
}

/// `subject ∪ clipping` under the even-odd rule.
pub fn union(subject: &MultiPolygon, clipping: &MultiPolygon) -> Result<MultiPolygon, Error> {
    overlay(Operation::Union, subject, clipping, &Options::default())
}

/// `subject − clipping` under the even-odd rule.
pub fn difference(subject: &MultiPolygon, clipping: &MultiPolygon) -> Result<MultiPolygon, Error> {
    overlay(
        Operation::Difference,
        subject,
        clipping,
        &Options::default(),
    )
}

/// `subject ⊕ clipping` (symmetric difference) under the even-odd rule.
pub fn xor(subject: &MultiPolygon, clipping: &MultiPolygon) -> Result<MultiPolygon, Error> {
    overlay(Operation::Xor, subject, clipping, &Options::default())
}

/// `operation` over many operands: the union, intersection or xor of all, or for [`Operation::Difference`] the
/// first minus all the others. Errors name the operand by its index in `operands`.
///
/// The paper's flags describe two operands; here each operand is first made a valid polygon set by its own
/// sweep (applying its fill rule), and then all go through one sweep that counts, for every region, how many
/// operands contain it.
///
/// ```
/// use polysweep::{overlay_all, MultiPolygon, Operation, Options};
/// let square = |x: f64| MultiPolygon::from_coordinates(&[vec![vec![[x, 0.0], [x + 1.0, 0.0], [x + 1.0, 1.0], [x, 1.0]]]]);
/// let row = overlay_all(Operation::Union, &[square(0.0), square(1.0), square(2.0)], &Options::default())?;
/// assert_eq!(row.0.len(), 1);
/// assert_eq!(row.area(), 3.0);
/// # Ok::<(), polysweep::Error>(())
/// ```
pub fn overlay_all(
    operation: Operation,
    operands: &[MultiPolygon],
    options: &Options,
) -> Result<MultiPolygon, Error> {
    let operands: Vec<&MultiPolygon> = operands.iter().collect();
    overlay::overlay_many(operation, &operands, options)
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
///
/// ```
/// use polysweep::{difference_all, MultiPolygon};
/// let square = |x: f64, side: f64| {
///     MultiPolygon::from_coordinates(&[vec![vec![[x, 0.0], [x + side, 0.0], [x + side, side], [x, side]]]])
/// };
/// let rest = difference_all(&square(0.0, 4.0), &[square(0.0, 1.0), square(3.0, 1.0)])?;
/// assert_eq!(rest.area(), 14.0);
/// # Ok::<(), polysweep::Error>(())
/// ```
pub fn difference_all(
    subject: &MultiPolygon,
    clips: &[MultiPolygon],
) -> Result<MultiPolygon, Error> {
    let operands: Vec<&MultiPolygon> = std::iter::once(subject).chain(clips).collect();
    overlay::overlay_many(Operation::Difference, &operands, &Options::default())
}
