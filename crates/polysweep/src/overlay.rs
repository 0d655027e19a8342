//! The pipeline of one operation (Fig. 5 and §5): the input checked and made edges, the sweep, the result edges
//! connected into rings and polygons, and the rounded result repaired where rounding may have broken it.
//!
//! ```text
//! input::check ─► prune::plan ─► input::add_edges ─► Sweep::run ─► connect ─► (repair sweeps) ─► MultiPolygon
//!                 (shortcuts)                        events, status,
//!                                                    subdivide, select
//! ```

use crate::edges::{InputEdge, NONE};
use crate::error::Error;
use crate::events::MAX_EVENTS;
use crate::geometry::MultiPolygon;
use crate::input::{self, Bounds};
use crate::options::Options;
use crate::select::{FillRule, Operation, Selection};
use crate::sweep::Sweep;
use crate::workspace::{self, Workspace};
use crate::{connect, prune, rounding};

/// `operation` on `subject` and `clipping`, in this thread's working memory.
pub(crate) fn overlay_pair(
    operation: Operation,
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    options: &Options,
) -> Result<(MultiPolygon, Stats), Error> {
    let boxes = [input::check(0, subject)?, input::check(1, clipping)?];
    if options.fill_rule == FillRule::Structure {
        let [subject_box, clipping_box] = boxes.each_ref().map(|b| Bounds::around_all(b));
        let magnitude = subject_box.around(&clipping_box).magnitude();
        // Each operand read by its structure is a valid polygon set, which the even-odd rule reads as it is. (Not
        // checked again: its vertices are the input's and crossings between them, which the sweep takes as they
        // come, as it does in `overlay_many`.)
        let [subject, clipping] =
            workspace::with(options.shortcuts.keep_working_memory, |workspace| {
                let mut read = |operand| read_by_structure(operand, magnitude, options, workspace);
                Ok::<_, Error>([read(subject)?, read(clipping)?])
            })?;
        let boxes = [input::boxes(&subject), input::boxes(&clipping)];
        let options = options.with_fill_rule(FillRule::EvenOdd);
        return overlay_checked(operation, [&subject, &clipping], boxes, &options);
    }
    overlay_checked(operation, [subject, clipping], boxes, options)
}

/// [`overlay_pair`] on operands already checked, whose polygons' boxes are `boxes`.
fn overlay_checked(
    operation: Operation,
    [subject, clipping]: [&MultiPolygon; 2],
    boxes: [Vec<Bounds>; 2],
    options: &Options,
) -> Result<(MultiPolygon, Stats), Error> {
    let bounds = boxes.each_ref().map(|b| Bounds::around_all(b));
    let magnitude = bounds[0].around(&bounds[1]).magnitude();
    let margin = 2.0 * rounding::clearance(magnitude);
    let shortcuts = &options.shortcuts;
    let [subject_boxes, clipping_boxes] = boxes.each_ref().map(Vec::as_slice);
    let plan = prune::plan(
        operation,
        [subject, clipping],
        [subject_boxes, clipping_boxes],
        options.fill_rule,
        shortcuts,
        margin,
    );
    workspace::with(shortcuts.keep_working_memory, |workspace| {
        let mut edges = workspace::take(&mut workspace.edges);
        input::add_edges(&mut edges, subject, 0, |p| plan.subject[p]);
        input::add_edges(&mut edges, clipping, 1, |p| plan.clipping[p]);
        let selection = Selection::Pair {
            operation,
            fill_rule: options.fill_rule,
        };
        let stop_x = stop_x(operation, &bounds, options);
        let (mut result, stats) = sweep(edges, selection, stop_x, magnitude, options, workspace)?;
        result.0.extend(plan.copies);
        Ok((result, stats))
    })
}

/// `operation` over many operands (see [`crate::overlay_all`]): each made a valid polygon set by its own sweep,
/// then one sweep that counts, for every region, how many of them contain it.
pub(crate) fn overlay_many(
    operation: Operation,
    operands: &[&MultiPolygon],
    options: &Options,
) -> Result<MultiPolygon, Error> {
    workspace::with(options.shortcuts.keep_working_memory, |workspace| {
        overlay_many_in(operation, operands, options, workspace)
    })
}

fn overlay_many_in(
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
        let magnitude = boxes[index].magnitude();
        let valid = if options.fill_rule == FillRule::Structure {
            read_by_structure(operand, magnitude, options, workspace)?
        } else {
            let mut own = workspace::take(&mut workspace.edges);
            input::add_edges(&mut own, operand, 0, |_| true);
            sweep(own, normalise, f64::INFINITY, magnitude, options, workspace)?.0
        };
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
    let stop_x = stop_x(operation, &boxes, options);
    Ok(sweep(edges, selection, stop_x, magnitude, options, workspace)?.0)
}

/// `operand` read by its structure ([`FillRule::Structure`]), as a valid polygon set: each ring's own region by the
/// non-zero rule of that ring alone, each polygon its exterior's region less the union of its holes' regions, the
/// operand the union of its polygons. Not in the paper: GEOS's `make_valid` by structure, and polygon-clipping's
/// reading of input. A sweep per ring and per polygon with holes, then one over all polygons, each exact up to the
/// rounding of its own output (as `overlay_many`'s normalisation is), and about three times the work of reading
/// the operand by another rule. `magnitude` bounds its coordinates.
fn read_by_structure(
    operand: &MultiPolygon,
    magnitude: f64,
    options: &Options,
    workspace: &mut Workspace,
) -> Result<MultiPolygon, Error> {
    let sweep_edges = |add: &dyn Fn(&mut Vec<InputEdge>), selection, workspace: &mut Workspace| {
        let mut edges = workspace::take(&mut workspace.edges);
        add(&mut edges);
        Ok::<_, Error>(
            sweep(
                edges,
                selection,
                f64::INFINITY,
                magnitude,
                options,
                workspace,
            )?
            .0,
        )
    };
    let alone = Selection::Pair {
        operation: Operation::Union,
        fill_rule: FillRule::NonZero,
    };
    let less_holes = Selection::Count {
        operation: Operation::Difference,
        operands: 1,
    };
    let mut regions = Vec::with_capacity(operand.0.len());
    for polygon in &operand.0 {
        let exterior = &polygon.exterior;
        let outer = sweep_edges(
            &|edges| input::add_ring_edges(edges, exterior, 0),
            alone,
            workspace,
        )?;
        if polygon.holes.is_empty() || outer.0.is_empty() {
            regions.push(outer);
            continue;
        }
        let mut holes = Vec::with_capacity(polygon.holes.len());
        for hole in &polygon.holes {
            holes.push(sweep_edges(
                &|edges| input::add_ring_edges(edges, hole, 0),
                alone,
                workspace,
            )?);
        }
        let add = |edges: &mut Vec<InputEdge>| {
            input::add_edges(edges, &outer, 0, |_| true);
            for hole in &holes {
                input::add_edges(edges, hole, 1, |_| true);
            }
        };
        regions.push(sweep_edges(&add, less_holes, workspace)?);
    }
    let union = Selection::Count {
        operation: Operation::Union,
        operands: regions.len() as i32,
    };
    sweep_edges(
        &|edges| {
            regions
                .iter()
                .for_each(|r| input::add_edges(edges, r, 0, |_| true))
        },
        union,
        workspace,
    )
}

/// Past this x the result can have no edge, so the sweep stops there (the end of the subject for a difference,
/// of the operand that ends first for an intersection), given the box of every operand. Not in the paper; exact,
/// as every operand's rings lie within its box.
fn stop_x(operation: Operation, boxes: &[Bounds], options: &Options) -> f64 {
    if !options.shortcuts.stop_early {
        return f64::INFINITY;
    }
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
    options: &Options,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, Stats), Error> {
    let first = Pass {
        stop_x,
        magnitude,
        may_snap: MAX_REPAIR_PASSES > 0,
    };
    let (mut result, mut stats, mut suspect) =
        sweep_once(&edges, selection, first, options, workspace)?;
    stats.input_edges = edges.len();
    while suspect && stats.repair_passes < MAX_REPAIR_PASSES {
        edges.clear();
        input::add_edges(&mut edges, &result, 0, |_| true);
        let repair = Selection::Count {
            operation: Operation::Union,
            operands: 1,
        };
        stats.repair_passes += 1;
        let pass = Pass {
            stop_x: f64::INFINITY,
            magnitude,
            may_snap: stats.repair_passes < MAX_REPAIR_PASSES,
        };
        (result, _, suspect) = sweep_once(&edges, repair, pass, options, workspace)?;
    }
    workspace.edges = edges;
    Ok((result, stats))
}

/// How one sweep goes: where it stops, the magnitude of its coordinates, and whether a repair pass may follow it.
/// Edges bent through vertices (see [`rounding`]) meet there only once the result is swept again, so the last pass
/// allowed bends none and writes the result as rounded.
#[derive(Clone, Copy)]
struct Pass {
    stop_x: f64,
    magnitude: f64,
    may_snap: bool,
}

/// One sweep and its rounded result, and whether that result needs a repair pass.
fn sweep_once(
    edges: &[InputEdge],
    selection: Selection,
    pass: Pass,
    options: &Options,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, Stats, bool), Error> {
    // (Checked before the events are made: their construction counts endpoints in 32 bits.)
    if 2 * edges.len() > MAX_EVENTS {
        return Err(Error::TooLarge { limit: MAX_EVENTS });
    }
    let shortcuts = options.shortcuts;
    let mut sweep = Sweep::new(
        edges,
        selection,
        pass.stop_x,
        pass.magnitude,
        shortcuts,
        workspace,
    );
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
    let close_pairs: Vec<(u32, u32)> = if rounded && pass.may_snap {
        (sweep.close_pairs.iter())
            .map(|&(v, l)| (v, events[l as usize].result_edge()))
            .filter(|&(_, r)| r != NONE)
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

/// What an operation did, for display and benchmarks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Stats {
    /// Edges swept: those of all operands, less zero-length ones and those of the polygons left out: for an
    /// intersection, polygons whose box meets no polygon's box of the other operand, for a difference clipping
    /// polygons whose box meets none of the subject's; for both, clipping polygons wholly outside the subject away
    /// from its edges; for an intersection also those copied to the result, wholly inside the subject and apart
    /// from the others; for a union, clipping polygons wholly inside it; for a union or a difference, subject
    /// polygons inside one convex clipping polygon (see docs/architecture.md).
    pub input_edges: usize,
    /// Points where two edges properly cross (constructed intersection points).
    pub crossings: usize,
    /// Events created, including those made by subdivision.
    pub events: usize,
    /// Extra sweeps over the rounded result because rounding put vertices within a few ulps of each other (see
    /// the robustness page). Almost always 0.
    pub repair_passes: usize,
}
