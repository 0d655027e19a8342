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
//! to [`workspace::KEEP_BYTES`]: memory fresh from the system costs a page fault per page on first use, which made
//! up a fifth of the time of an operation on Table 1's data (see [`workspace`]). [`free_working_memory`] gives it
//! back.
//!
//! ## The algorithm, stage by stage
//! [`events`] (§3, Fig. 8, the order of §4) → [`status`] (§3, §7.1) → [`subdivide`] (Fig. 6, §7.2, §7.3) →
//! [`select`] (§4, Fig. 9, Fig. 10) → [`connect`] (§5), driven by [`sweep`] (Fig. 5) with the predicates of
//! [`exact`]. How this is made robust is on the [`robustness`] page.

pub mod connect;
pub(crate) mod edges;
pub mod error;
pub mod events;
pub mod exact;
#[cfg(feature = "geojson")]
pub mod geojson;
pub mod geometry;
pub mod input;
pub mod prune;
pub(crate) mod rounding;
pub mod select;
pub mod status;
pub mod subdivide;
pub mod sweep;
pub mod validate;
pub mod workspace;

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
pub use input::{MAX_COORDINATE, MIN_COORDINATE};
pub use select::{FillRule, Operation};
pub use validate::validate;
pub use workspace::free_working_memory;

use edges::InputEdge;
use events::MAX_EVENTS;
use input::Bounds;
use select::Selection;
use workspace::Workspace;

/// Options of an operation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Options {
    pub fill_rule: FillRule,
}

/// What an operation did, for display and benchmarks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Edges swept: those of all operands, less zero-length ones and those of the polygons left out: for an
    /// intersection or a difference, polygons whose box meets no polygon's box of the other operand, and clipping
    /// polygons wholly outside the subject away from its edges; for an intersection also those copied to the
    /// result, wholly inside the subject and apart from the others; for a union, clipping polygons wholly inside it;
    /// for a union or a difference, subject polygons inside one convex clipping polygon (see [`prune`]).
    pub input_edges: usize,
    /// Points where two edges properly cross (constructed intersection points).
    pub crossings: usize,
    /// Events created, including those made by subdivision.
    pub events: usize,
    /// Extra sweeps over the rounded result because rounding put vertices within a few ulps of each other (see
    /// the robustness page). Almost always 0.
    pub repair_passes: usize,
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
    workspace::with(|workspace| overlay_pair(operation, subject, clipping, options, workspace))
}

fn overlay_pair(
    operation: Operation,
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    options: &Options,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, Stats), Error> {
    let (subject_boxes, clipping_boxes) = (input::check(0, subject)?, input::check(1, clipping)?);
    // An intersection lies where polygons of both operands are, and a difference where the subject's are: a polygon
    // whose box meets no polygon's box of the other operand cannot change the result and is not swept. (Not in the
    // paper; it is what makes clipping a small area out of a large data set, or a grid of tiles against a
    // coastline, cost little more than the sort of the polygons kept.) Leaving them out is exact, not a heuristic:
    // a ring's winding number is 0 outside its box, so wherever the result can lie the operand's interior, under
    // either fill rule, is that of the polygons kept.
    let keep_all = |_: usize| true;
    let (mut edges, polygons) = (
        workspace::take(&mut workspace.edges),
        subject.0.len() + clipping.0.len(),
    );
    // About as many cells as polygons.
    let cells = input::Grid::side_for(polygons);
    let coverage = |boxes: &[Bounds]| input::Coverage::new(boxes, cells);
    let (subject_box, clipping_box) = (
        Bounds::around_all(&subject_boxes),
        Bounds::around_all(&clipping_boxes),
    );
    let magnitude = subject_box.around(&clipping_box).magnitude();
    // Farther apart than rounding moves anything, twice over. Not a tolerance that decides the result: it only
    // chooses which polygons are left out or copied rather than swept, and always errs towards sweeping. A box is
    // grown by it before it is judged (inside or outside the other operand, apart from the other boxes), so a
    // polygon is left out or copied on a stricter test than exactness needs; the judgments themselves are exact
    // (see `prune`), and a copy is written exactly as the sweep would write it.
    let margin = 2.0 * rounding::clearance(magnitude);
    // A clipping polygon wholly outside the subject, away from its edges, cannot change an intersection or a
    // difference, nor one wholly inside it a union; an intersection copies one wholly inside it and apart from the
    // others to its result (see `prune`; judged by the whole subject, before any of it is left out, and `margin`
    // around each box). The subject's polygons are then judged by the boxes of the clipping polygons swept. Here:
    // each clipping polygon inside the subject (`Some(true)`) or outside it (`Some(false)`) throughout its box, where
    // known.
    let inside_subject = |share: usize| -> Vec<Option<bool>> {
        // The grid costs about a pass over the subject's vertices: it can pay only when the clipping operand is not
        // much smaller, in many polygons, at least 1/`share` of the subject's vertices. An intersection or a
        // difference gains from it from a quarter (land × 3,895 squares, a quarter: 3.4% and 1.3% fewer
        // instructions; × 2,048, an eighth: 0.6% more for the intersection); a union, which leaves out only the
        // polygons inside, from half (at a quarter: 1.4% more). It has about four cells per clipping polygon, as
        // pruning needs cells smaller than the polygons it leaves out, and no more cells than the subject has
        // vertices.
        let subject_vertices = subject.vertex_count();
        if clipping.0.len() < MIN_POLYGONS_TO_PRUNE
            || share * clipping.vertex_count() < subject_vertices
        {
            return vec![None; clipping.0.len()];
        }
        let cells = input::Grid::side_for((4 * clipping.0.len()).min(subject_vertices));
        let known = prune::KnownWinding::new(subject, subject_box, cells);
        (clipping_boxes.iter())
            .map(|b| (known.throughout(&b.grown(margin))).map(|w| options.fill_rule.is_inside(w)))
            .collect()
    };
    // A subject polygon inside one convex clipping polygon, away from the others, cannot change a union or a
    // difference either (see `prune`; exact together with leaving out clipping polygons as above).
    let subject_inside_clipping =
        || prune::inside_one_convex(clipping, &clipping_boxes, &subject_boxes, margin);
    // The clipping polygons that an intersection copies to its result instead of sweeping them (see `prune`).
    let mut copies = Vec::new();
    match operation {
        Operation::Intersection => {
            let inside = inside_subject(4);
            let copied;
            (copied, copies) = prune::copied_whole(clipping, &clipping_boxes, &inside, margin);
            let swept = |p: usize| inside[p] != Some(false) && !copied[p];
            let clipping_kept: Vec<Bounds> = (0..clipping.0.len())
                .filter(|&p| swept(p))
                .map(|p| clipping_boxes[p])
                .collect();
            let near_clipping = coverage(&clipping_kept);
            input::add_edges(&mut edges, subject, 0, |p| {
                near_clipping.may_meet(&subject_boxes[p])
            });
            let near_subject = coverage(&subject_boxes);
            input::add_edges(&mut edges, clipping, 1, |p| {
                swept(p) && near_subject.may_meet(&clipping_boxes[p])
            });
        }
        Operation::Difference => {
            let left_out = subject_inside_clipping();
            input::add_edges(&mut edges, subject, 0, |p| !left_out[p]);
            let inside = inside_subject(4);
            let near_subject = coverage(&subject_boxes);
            input::add_edges(&mut edges, clipping, 1, |p| {
                inside[p] != Some(false) && near_subject.may_meet(&clipping_boxes[p])
            });
        }
        Operation::Union => {
            let left_out = subject_inside_clipping();
            input::add_edges(&mut edges, subject, 0, |p| !left_out[p]);
            let inside = inside_subject(2);
            input::add_edges(&mut edges, clipping, 1, |p| inside[p] != Some(true));
        }
        Operation::Xor => {
            input::add_edges(&mut edges, subject, 0, keep_all);
            input::add_edges(&mut edges, clipping, 1, keep_all);
        }
    }
    let (mut result, stats) = sweep(
        edges,
        Selection::Pair {
            operation,
            fill_rule: options.fill_rule,
        },
        stop_x(operation, &[subject_box, clipping_box]),
        magnitude,
        workspace,
    )?;
    result.0.append(&mut copies);
    Ok((result, stats))
}

/// Fewer clipping polygons than this are not judged by the subject's winding number (see `prune`): each would have
/// to lie within a cell of a grid of a few cells, away from all of the subject's edges, to be left out.
const MIN_POLYGONS_TO_PRUNE: usize = 16;

/// Past this x the result can have no edge, so the sweep stops there (the end of the subject for a difference,
/// of the operand that ends first for an intersection), given the box of every operand.
fn stop_x(operation: Operation, boxes: &[Bounds]) -> f64 {
    match operation {
        Operation::Intersection => boxes
            .iter()
            .map(Bounds::max_x)
            .fold(f64::INFINITY, f64::min),
        Operation::Difference => boxes[0].max_x(),
        Operation::Union | Operation::Xor => f64::INFINITY,
    }
}

/// Repair passes allowed after one operation. Each pass sweeps the rounded result, whose vertices are then exact
/// inputs: a pass that constructs no crossing point rounds nothing and ends the repair. On Table 1's data no pass is
/// needed; on random decimal grids, one in 99.4% of the cases and three at most (see the robustness page); the
/// bound only guarantees that the function returns.
const MAX_REPAIR_PASSES: usize = 4;

/// The sweep of Fig. 5 over `edges`, whose coordinates are of magnitude `magnitude` at most, then the result
/// rounded to f64 and, where rounding may have broken it, repaired by sweeping it again (see the robustness page;
/// the result lies within the edges' box, so within the same magnitude). `edges` is given to `workspace` once done.
fn sweep(
    mut edges: Vec<InputEdge>,
    selection: Selection,
    stop_x: f64,
    magnitude: f64,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, Stats), Error> {
    let (mut result, mut stats, mut suspect) = sweep_once(
        &edges,
        selection,
        stop_x,
        magnitude,
        MAX_REPAIR_PASSES > 0,
        workspace,
    )?;
    stats.input_edges = edges.len();
    while suspect && stats.repair_passes < MAX_REPAIR_PASSES {
        edges.clear();
        input::add_edges(&mut edges, &result, 0, |_| true);
        let repair = Selection::Count {
            operation: Operation::Union,
            operands: 1,
        };
        stats.repair_passes += 1;
        let may_snap = stats.repair_passes < MAX_REPAIR_PASSES;
        (result, _, suspect) = sweep_once(
            &edges,
            repair,
            f64::INFINITY,
            magnitude,
            may_snap,
            workspace,
        )?;
    }
    workspace.edges = edges;
    Ok((result, stats))
}

/// One sweep and its rounded result, and whether that result needs a repair pass. `may_snap`: a repair pass may
/// follow. Edges bent through vertices (see `connect`) meet there only once the result is swept again, so the last
/// pass allowed bends none and writes the result as rounded.
fn sweep_once(
    edges: &[InputEdge],
    selection: Selection,
    stop_x: f64,
    magnitude: f64,
    may_snap: bool,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, Stats, bool), Error> {
    // (Checked before the events are made: their construction counts endpoints in 32 bits.)
    if 2 * edges.len() > MAX_EVENTS {
        return Err(Error::TooLarge { limit: MAX_EVENTS });
    }
    let mut sweep = sweep::Sweep::new(edges, selection, stop_x, magnitude, workspace);
    sweep.run()?;
    let stats = Stats {
        crossings: sweep.exact.crossing_count(),
        events: sweep.events.len(),
        ..Stats::default()
    };
    // Without constructed points nothing is rounded: the output is the exact arrangement.
    let rounded = stats.crossings > 0;
    let suspect = rounded && (sweep.close_call || rounding::rounding_may_matter(&sweep.vertices));
    let events = &sweep.events;
    // Close calls to snap, as (vertex, result edge): only where rounding can move something.
    let close_pairs: Vec<(u32, u32)> = if rounded && may_snap {
        (sweep.close_pairs.iter())
            .map(|&(v, l)| (v, events[l as usize].result_edge()))
            .filter(|&(_, r)| r != edges::NONE)
            .collect()
    } else {
        Vec::new()
    };
    let (result, snapped) = connect::connect(
        &sweep.exact,
        edges,
        &sweep.vertices,
        &mut sweep.result,
        |e| events[e as usize].result_edge(),
        &close_pairs,
    );
    sweep.give_back(workspace);
    Ok((result, stats, suspect || snapped))
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
    overlay_refs(operation, &operands, options)
}

fn overlay_refs(
    operation: Operation,
    operands: &[&MultiPolygon],
    options: &Options,
) -> Result<MultiPolygon, Error> {
    workspace::with(|workspace| overlay_many(operation, operands, options, workspace))
}

fn overlay_many(
    operation: Operation,
    operands: &[&MultiPolygon],
    options: &Options,
    workspace: &mut Workspace,
) -> Result<MultiPolygon, Error> {
    let mut boxes = Vec::with_capacity(operands.len());
    for (index, operand) in operands.iter().enumerate() {
        boxes.push(Bounds::around_all(&input::check(index, operand)?));
    }
    if operands.is_empty() {
        return Ok(MultiPolygon::default());
    }
    let normalise = Selection::Pair {
        operation: Operation::Union,
        fill_rule: options.fill_rule,
    };
    let mut edges = Vec::new();
    for (index, operand) in operands.iter().enumerate() {
        let mut own = workspace::take(&mut workspace.edges);
        input::add_edges(&mut own, operand, 0, |_| true);
        let magnitude = boxes[index].magnitude();
        let (valid, _) = sweep(own, normalise, f64::INFINITY, magnitude, workspace)?;
        let slot = u8::from(operation == Operation::Difference && index > 0);
        input::add_edges(&mut edges, &valid, slot, |_| true);
    }
    let in_slot_0 = if operation == Operation::Difference {
        1
    } else {
        operands.len() as i32
    };
    let selection = Selection::Count {
        operation,
        operands: in_slot_0,
    };
    let magnitude = Bounds::around_all(&boxes).magnitude();
    Ok(sweep(
        edges,
        selection,
        stop_x(operation, &boxes),
        magnitude,
        workspace,
    )?
    .0)
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
    overlay_refs(Operation::Difference, &operands, &Options::default())
}
