//! The pipeline of one operation (Fig. 5 and §5): the input checked and made edges, the sweep, the result edges
//! connected into rings and polygons, and the rounded result snap-rounded where rounding broke it.
//!
//! ```text
//! input::check ─► prune::plan ─► input::add_edges ─► Sweep::run ─► connect ─► (snap rounding) ─► MultiPolygon
//!                 (shortcuts)                        events, status,
//!                                                    subdivide, select
//! ```

use crate::edges::InputEdge;
use crate::error::Error;
use crate::events::MAX_EVENTS;
use crate::exact::SweepPoint;
use crate::geometry::MultiPolygon;
use crate::input::{self, Bounds};
use crate::options::Options;
use crate::select::{FillRule, Operation, Selection};
use crate::snap_round::Grid;
use crate::structure::{add_watched_edges, valid_by_structure, Watch};
use crate::sweep::Sweep;
use crate::trace::Silent;
use crate::validate::validate;
use crate::workspace::{self, Workspace};
use crate::{connect, prune, rounding, snap_round};

/// `operation` on `subject` and `clipping`, in this thread's working memory.
pub(crate) fn overlay_pair(
    operation: Operation,
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    options: &Options,
) -> Result<(MultiPolygon, Stats), Error> {
    let boxes = [input::check(0, subject)?, input::check(1, clipping)?];
    if options.fill_rule != FillRule::Structure {
        return overlay_checked(operation, [subject, clipping], &boxes, options, None);
    }
    // Under the structural reading: valid operands are read alike by the even-odd rule, which a watched sweep
    // tells (see `structure`); only otherwise is each made a valid polygon set first.
    let even_odd = options.with_fill_rule(FillRule::EvenOdd);
    let mut structure_sweeps = 0;
    if options.shortcuts.watch_structure {
        structure_sweeps += 1;
        let mut watch = Watch::new();
        let watched = overlay_checked(
            operation,
            [subject, clipping],
            &boxes,
            &even_odd,
            Some(&mut watch),
        )?;
        if watch.alike == [true; 2] {
            return Ok(watched);
        }
    }
    let [subject_box, clipping_box] = boxes.each_ref().map(|b| Bounds::around_all(b));
    let magnitude = subject_box.around(&clipping_box).magnitude();
    // (Not checked again: their vertices are the input's and crossings between them, which the sweep takes as they
    // come, as it does in `overlay_many`.)
    let [subject, clipping] =
        workspace::with(options.shortcuts.keep_working_memory, |workspace| {
            let mut read = |operand| {
                let (valid, sweeps) = valid_by_structure(operand, magnitude, options, workspace)?;
                structure_sweeps += sweeps;
                Ok::<_, Error>(valid)
            };
            Ok::<_, Error>([read(subject)?, read(clipping)?])
        })?;
    let boxes = [input::boxes(&subject), input::boxes(&clipping)];
    let (result, stats) =
        overlay_checked(operation, [&subject, &clipping], &boxes, &even_odd, None)?;
    let stats = Stats {
        structure_sweeps,
        ..stats
    };
    Ok((result, stats))
}

/// [`overlay_pair`] on operands already checked, whose polygons' boxes are `boxes`; with `watch`, watched for the
/// structural reading (see [`crate::structure`]).
pub(crate) fn overlay_checked(
    operation: Operation,
    [subject, clipping]: [&MultiPolygon; 2],
    boxes: &[Vec<Bounds>; 2],
    options: &Options,
    mut watch: Option<&mut Watch>,
) -> Result<(MultiPolygon, Stats), Error> {
    let bounds = boxes.each_ref().map(|b| Bounds::around_all(b));
    let magnitude = bounds[0].around(&bounds[1]).magnitude();
    let margin = 2.0 * rounding::clearance(magnitude);
    let shortcuts = &options.shortcuts;
    let [subject_boxes, clipping_boxes] = boxes.each_ref().map(Vec::as_slice);
    let mut plan = prune::plan(
        operation,
        [subject, clipping],
        [subject_boxes, clipping_boxes],
        options.fill_rule,
        shortcuts,
        margin,
    );
    // Clipping polygons judged by the subject's even-odd winding number are judged by its structural one only where
    // the two agree: the whole subject is then watched (see `structure`).
    if watch.is_some() && plan.judged_by_subject && operation == Operation::Intersection {
        plan.subject.fill(true);
    }
    workspace::with(shortcuts.keep_working_memory, |workspace| {
        let mut edges = workspace::take(&mut workspace.edges);
        let subject_order = input::left_to_right(subject_boxes, |p| plan.subject[p]);
        let clipping_order = input::left_to_right(clipping_boxes, |p| plan.clipping[p]);
        if let Some(watch) = watch.as_deref_mut() {
            add_watched_edges(&mut edges, subject, 0, subject_order, watch);
            add_watched_edges(&mut edges, clipping, 1, clipping_order, watch);
        } else {
            input::add_edges(&mut edges, subject, 0, subject_order);
            input::add_edges(&mut edges, clipping, 1, clipping_order);
        }
        let selection = Selection::Pair {
            operation,
            fill_rule: options.fill_rule,
        };
        let stop_x = stop_x(operation, &bounds, options);
        let (mut result, stats) = sweep(
            edges, selection, stop_x, magnitude, options, workspace, watch,
        )?;
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
            valid_by_structure(operand, magnitude, options, workspace)?.0
        } else {
            let mut own = workspace::take(&mut workspace.edges);
            input::add_edges(&mut own, operand, 0, 0..operand.0.len());
            sweep(
                own,
                normalise,
                f64::INFINITY,
                magnitude,
                options,
                workspace,
                None,
            )?
            .0
        };
        let slot = u8::from(operation == Operation::Difference && index > 0);
        input::add_edges(&mut edges, &valid, slot, 0..valid.0.len());
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
    Ok(sweep(
        edges, selection, stop_x, magnitude, options, workspace, None,
    )?
    .0)
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

/// The sweep of Fig. 5 over `edges`, whose coordinates are of magnitude `magnitude` at most, then the result
/// rounded to f64; where rounding may have broken it, it is validated, and if it is broken, snap-rounded instead
/// (see the robustness page, "Termination": at most four more sweeps, no loop). `edges` is given to `workspace`
/// once done. `watch`, if any, watches the first sweep (see [`crate::structure`]).
pub(crate) fn sweep(
    edges: Vec<InputEdge>,
    selection: Selection,
    stop_x: f64,
    magnitude: f64,
    options: &Options,
    workspace: &mut Workspace,
    watch: Option<&mut Watch>,
) -> Result<(MultiPolygon, Stats), Error> {
    let pass = Pass { stop_x, magnitude };
    let (mut result, mut stats, suspect) =
        sweep_once(&edges, selection, pass, options, workspace, watch)?;
    stats.input_edges = edges.len();
    if suspect && validate(&result).is_err() {
        (result, stats.snap_rounding_sweeps) =
            snap_rounded(&edges, selection, pass, options, workspace)?;
    }
    workspace.edges = edges;
    Ok((result, stats))
}

/// Where one sweep stops, and the magnitude of its coordinates.
#[derive(Clone, Copy)]
struct Pass {
    stop_x: f64,
    magnitude: f64,
}

/// One sweep and its rounded result, and whether rounding may have broken that result.
fn sweep_once(
    edges: &[InputEdge],
    selection: Selection,
    pass: Pass,
    options: &Options,
    workspace: &mut Workspace,
    watch: Option<&mut Watch>,
) -> Result<(MultiPolygon, Stats, bool), Error> {
    let mut options = *options;
    options.shortcuts.merge_identical_edges &= watch.is_none();
    let mut sweep = start_sweep(edges, selection, pass, &options, workspace)?;
    sweep.watch = watch;
    sweep.run()?;
    if let Some(watch) = sweep.watch.as_deref_mut() {
        // (Noted by the initial sort, see `events::initial_events`.)
        for (alike, shared) in watch.alike.iter_mut().zip(workspace.sort.shared_vertex) {
            *alike &= !shared;
        }
    }
    let stats = Stats {
        crossings: sweep.exact.crossing_count(),
        events: sweep.events.len(),
        ..Stats::default()
    };
    // Without rounded points (no crossings, or only crossings of vertical and horizontal lines, as on grids) the
    // output is the exact arrangement.
    let rounded = stats.crossings > 0 && sweep.vertices.iter().any(SweepPoint::is_rounded);
    let suspect = rounded && (sweep.close_call || rounding::rounding_may_matter(&sweep.vertices));
    let events = &sweep.events;
    let (result, made_vertical) = connect::connect(
        &sweep.exact,
        edges,
        &sweep.vertices,
        &mut sweep.result,
        |e| events[e as usize].result_edge(),
        &mut workspace.connect,
    );
    sweep.give_back(workspace);
    Ok((result, stats, suspect || made_vertical))
}

/// A sweep over `edges`, not yet run.
fn start_sweep<'a>(
    edges: &'a [InputEdge],
    selection: Selection,
    pass: Pass,
    options: &Options,
    workspace: &mut Workspace,
) -> Result<Sweep<'a>, Error> {
    // (Checked before the events are made: their construction counts endpoints in 32 bits.)
    if 2 * edges.len() > MAX_EVENTS {
        return Err(Error::TooLarge { limit: MAX_EVENTS });
    }
    let shortcuts = options.shortcuts;
    Ok(Sweep::new(
        edges,
        selection,
        pass.stop_x,
        pass.magnitude,
        shortcuts,
        workspace,
        Silent,
    ))
}

/// The result of the sweep over `edges`, snap-rounded ([`snap_round`]) and read back by one more sweep, whose
/// result is exact where the snapped edges meet only at their ends or along each other. On the floats' own cells
/// that holds but across powers of two; where it does not (the sweep back constructs a point), the same is done on
/// the uniform grid, where it always holds. Also says how many sweeps this made: 2, or 4.
fn snap_rounded(
    edges: &[InputEdge],
    selection: Selection,
    pass: Pass,
    options: &Options,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, usize), Error> {
    let (result, crossings) = snap_to(Grid::Floats, edges, selection, pass, options, workspace)?;
    if crossings == 0 {
        return Ok((result, 2));
    }
    let uniform = Grid::uniform(pass.magnitude);
    let (result, crossings) = snap_to(uniform, edges, selection, pass, options, workspace)?;
    debug_assert_eq!(crossings, 0, "edges snap-rounded on a uniform grid cross");
    Ok((result, 4))
}

/// The sweep over `edges`, its result snap-rounded to `grid` and swept back; and the crossings that sweep found.
fn snap_to(
    grid: Grid,
    edges: &[InputEdge],
    selection: Selection,
    pass: Pass,
    options: &Options,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, usize), Error> {
    let mut sweep = start_sweep(edges, selection, pass, options, workspace)?;
    sweep.run()?;
    let snapped =
        snap_round::snap_rounded_edges(&sweep.exact, edges, &sweep.vertices, &sweep.result, grid);
    sweep.give_back(workspace);
    // Read as every ring is: winding 1 inside, 0 outside.
    let union = Selection::Count {
        operation: Operation::Union,
        operands: 1,
    };
    let whole = Pass {
        stop_x: f64::INFINITY,
        // (A cell's centre is within a cell of the magnitude's float.)
        magnitude: pass.magnitude * 2.0,
    };
    let (result, stats, _) = sweep_once(&snapped, union, whole, options, workspace, None)?;
    Ok((result, stats.crossings))
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
    /// Extra sweeps because the rounded result failed validation, where rounding put vertices within a few ulps of
    /// edges: 2 (the result snap-rounded, then read back), 4 (again, on a uniform grid), else 0 (see the
    /// robustness page). Almost always 0.
    pub snap_rounding_sweeps: usize,
    /// Under [`FillRule::Structure`], the sweeps that reading the operands by their structure added to the
    /// operation's own: 0 where the operation's sweep found every operand a valid polygon set (simple rings apart
    /// from each other, holes in their own shells), which it then reads as it is. Otherwise one for that first
    /// sweep, then per operand one where a sweep of it alone finds it valid, or one per ring, one per polygon with
    /// holes and one more (see [`crate::structure`]).
    pub structure_sweeps: usize,
}
