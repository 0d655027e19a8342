//! A trace of the sweep, step by step, for people to follow the algorithm on any case (the playground's explorer,
//! `trace` in the npm package) and to watch a hard case event by event: each event taken from Q and S after it
//! (§3, Fig. 5), what possibleInter found (Fig. 6, §7.2), each subdivision (Fig. 7), the flags of Fig. 9 an edge got
//! on entering S, the selection of Fig. 10 as each edge left S, and the rings the connection step closed (§5).
//!
//! The sweep reports to an [`Observer`], a type parameter: operations use [`Silent`], whose `ON` is false, so every
//! report is compiled away and the operations run the same instructions as without this module. [`trace`] runs the
//! paper's algorithm (every shortcut of [`crate::Shortcuts`] off) with an observer that records the steps.

use crate::edges::{EventId, NONE};
use crate::error::Error;
use crate::exact::SweepPoint;
use crate::geometry::MultiPolygon;
use crate::input;
use crate::options::{Options, Shortcuts};
use crate::select::{FillRule, Operation, Selection};
use crate::sweep::{InStatus, Sweep};
use crate::workspace::Workspace;
use std::ops::Range;

/// What the sweep reports to. `ON` false compiles the reports away.
pub(crate) trait Observer {
    const ON: bool;
    /// Whether S is wanted after the event at hand (making it costs a walk of S).
    fn wants_status(&self) -> bool;
    fn step(&mut self, step: Step);
}

/// The observer of operations: reports nothing, costs nothing.
#[derive(Default)]
pub(crate) struct Silent;

impl Observer for Silent {
    const ON: bool = false;
    #[inline(always)]
    fn wants_status(&self) -> bool {
        false
    }
    #[inline(always)]
    fn step(&mut self, _: Step) {}
}

/// The observer of [`trace`]: keeps every step, and S after the events numbered in `status_for`.
struct Recorder {
    steps: Vec<Step>,
    events: usize,
    status_for: Range<usize>,
}

impl Observer for Recorder {
    const ON: bool = true;
    fn wants_status(&self) -> bool {
        self.status_for.contains(&(self.events.wrapping_sub(1)))
    }
    fn step(&mut self, step: Step) {
        self.events += usize::from(matches!(step, Step::Event { .. }));
        self.steps.push(step);
    }
}

/// An edge as the trace shows it: its endpoints in sweep order (left, then right; crossings rounded to the
/// nearest floats), the operand of its input edge (0 the subject, 1 the clipping polygon), and its winding per
/// operand, which for edges of both operands merged into one (§7.2) is non-zero for both.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TraceEdge {
    pub left: [f64; 2],
    pub right: [f64; 2],
    pub operand: usize,
    pub winding: [i32; 2],
}

/// What possibleInter found between two neighbours in S.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Meeting {
    /// They cross at a point inside both (Fig. 6, Fig. 7).
    Crossing,
    /// An endpoint of one lies inside the other (Fig. 6).
    VertexOnEdge,
    /// They are collinear and overlap (§7.2, Fig. 6): split at each other's endpoints, the common part merged.
    Overlap,
}

/// Why an edge leaving S is in the result or not: the row of Fig. 10 that decided it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Reason {
    /// An edge of one operand inside the other.
    InsideOther,
    /// An edge of one operand outside the other.
    OutsideOther,
    /// Overlapping edges (§7.2) with both operands on the same side: SAME_TRANSITION.
    SameTransition,
    /// Overlapping edges with the operands on opposite sides: DIFFERENT_TRANSITION.
    DifferentTransition,
    /// Edges whose windings cancel: the same region on both sides (§7.3).
    NoTransition,
}

/// One step of the sweep. (More kinds of step may come: match with a wildcard.)
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Step {
    /// An event taken from Q: its point, whether it is the left endpoint of its edge, and the edge.
    Event {
        point: [f64; 2],
        left: bool,
        edge: TraceEdge,
    },
    /// possibleInter found `lower` and `upper`, neighbours in S, meet: at `at` (for an overlap, the start of the
    /// common part).
    Meeting {
        lower: TraceEdge,
        upper: TraceEdge,
        meeting: Meeting,
        at: [f64; 2],
    },
    /// An edge, in S, split at a point inside it (Fig. 6): it ends there, and a new edge from there goes into Q.
    Subdivision { edge: TraceEdge, at: [f64; 2] },
    /// The flags of Fig. 9 an edge got on entering S, from the edge below it: whether it is an inside-outside
    /// transition of its own operand going up (`in_out`), whether it lies inside the other operand
    /// (`inside_other`), and whether it bounds the result (`in_result`), the winding numbers below it per operand
    /// (`coverage_below`) they are read from.
    Flags {
        edge: TraceEdge,
        coverage_below: [i32; 2],
        in_out: bool,
        inside_other: bool,
        in_result: bool,
    },
    /// An edge left S at its right endpoint: in the result or not, and why.
    Selection {
        edge: TraceEdge,
        in_result: bool,
        reason: Reason,
    },
    /// S after an event, bottom to top.
    Status(Vec<TraceEdge>),
    /// The connection step closed a ring of the result (§5): ring 0 of its polygon is the exterior, the others
    /// its holes, which nest in it.
    Ring {
        polygon: usize,
        ring: usize,
        points: Vec<[f64; 2]>,
    },
}

impl Reason {
    /// The row of Fig. 10 for an edge of `winding` between the coverages below and above it, under `fill_rule`.
    pub(crate) fn of(fill_rule: FillRule, winding: [i32; 2], below: [i32; 2]) -> Reason {
        let inside = |c: i32| fill_rule.is_inside(c);
        let flips = [0, 1].map(|i| inside(below[i]) != inside(below[i] + winding[i]));
        match flips {
            [true, true] => {
                if inside(below[0] + winding[0]) == inside(below[1] + winding[1]) {
                    Reason::SameTransition
                } else {
                    Reason::DifferentTransition
                }
            }
            [false, false] => Reason::NoTransition,
            _ => {
                let other = if flips[0] { 1 } else { 0 };
                if inside(below[other]) {
                    Reason::InsideOther
                } else {
                    Reason::OutsideOther
                }
            }
        }
    }
}

/// The steps of the sweep of `operation` on `subject` and `clipping`, as the paper runs it (none of the
/// shortcuts), then the rings of the result. Errors are those of [`crate::overlay`]. Made for teaching and
/// debugging: S is kept after every event, so memory grows with events × the size of S (see
/// [`trace_with_status_for`] for long traces).
pub fn trace(
    operation: Operation,
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    options: &Options,
) -> Result<Vec<Step>, Error> {
    trace_with_status_for(operation, subject, clipping, options, 0..usize::MAX)
}

/// [`trace`] with S kept only after the events numbered in `status_for` (counted from 0): a viewer of a long
/// trace (the land's 120,000 events) asks for S around the event it shows.
pub fn trace_with_status_for(
    operation: Operation,
    subject: &MultiPolygon,
    clipping: &MultiPolygon,
    options: &Options,
    status_for: Range<usize>,
) -> Result<Vec<Step>, Error> {
    let boxes = [input::check(0, subject)?, input::check(1, clipping)?];
    let bounds = boxes.each_ref().map(|b| input::Bounds::around_all(b));
    let magnitude = bounds[0].around(&bounds[1]).magnitude();
    let mut edges = Vec::new();
    input::add_edges(&mut edges, subject, 0, 0..subject.0.len());
    input::add_edges(&mut edges, clipping, 1, 0..clipping.0.len());
    let fill_rule = match options.fill_rule {
        // The structural reading sweeps more than once; its first sweep reads operands as even-odd does.
        FillRule::Structure => FillRule::EvenOdd,
        rule => rule,
    };
    let selection = Selection::Pair {
        operation,
        fill_rule,
    };
    let mut workspace = Workspace::default();
    let mut sweep = Sweep::new(
        &edges,
        selection,
        f64::INFINITY,
        magnitude,
        Shortcuts::NONE,
        &mut workspace,
        Recorder {
            steps: Vec::new(),
            events: 0,
            status_for,
        },
    );
    sweep.run()?;
    let mut steps = std::mem::take(&mut sweep.observer.steps);
    let events = &sweep.events;
    let (result, _) = crate::connect::connect(
        &sweep.exact,
        &edges,
        &sweep.vertices,
        &mut sweep.result,
        |e| events[e as usize].result_edge(),
        &mut Default::default(),
    );
    for (p, polygon) in result.0.iter().enumerate() {
        for (r, ring) in polygon.rings().enumerate() {
            steps.push(Step::Ring {
                polygon: p,
                ring: r,
                points: ring.iter().map(|q| [q.x, q.y]).collect(),
            });
        }
    }
    Ok(steps)
}

/// The sweep's reports, each called behind `if O::ON` and `#[cold]`, so that a [`Silent`] sweep has none of them.
impl<O: Observer> Sweep<'_, O> {
    /// The event `e`, taken from Q.
    #[cold]
    pub(crate) fn trace_event(&mut self, e: EventId) {
        let (point, left, edge) = (
            self.point(e).approx,
            self.event(e).left(),
            self.trace_edge(e),
        );
        self.observer.step(Step::Event { point, left, edge });
    }

    /// S after the event, bottom to top.
    #[cold]
    pub(crate) fn trace_status(&mut self) {
        let mut edges = Vec::new();
        let mut node = self.status.lowest();
        while node != NONE {
            edges.push(self.trace_edge(self.status.event(node)));
            node = self.status.next(node);
        }
        self.observer.step(Step::Status(edges));
    }

    /// What possibleInter found between the edges at nodes `lower` and `upper` of S.
    #[cold]
    pub(crate) fn trace_meeting(
        &mut self,
        lower: u32,
        upper: u32,
        meeting: Meeting,
        at: &SweepPoint,
    ) {
        let [lower, upper] = [lower, upper].map(|n| self.trace_edge(self.status.event(n)));
        let at = at.approx;
        self.observer.step(Step::Meeting {
            lower,
            upper,
            meeting,
            at,
        });
    }

    /// The edge of left event `edge`, in S, split at `p`.
    #[cold]
    pub(crate) fn trace_subdivision(&mut self, edge: EventId, p: &SweepPoint) {
        let edge = self.trace_edge(edge);
        self.observer.step(Step::Subdivision { edge, at: p.approx });
    }

    /// The flags of Fig. 9 the edge at `node` got on entering S.
    #[cold]
    pub(crate) fn trace_flags(&mut self, node: u32) {
        let below = self.status.prev(node);
        let coverage_below = match below {
            NONE => [0; 2],
            b => self.status.key(b).flags.coverage_above,
        };
        let edge = self.status.key(node);
        let fill_rule = self.selection.fill_rule();
        let own = edge.operand as usize;
        let step = Step::Flags {
            edge: self.trace_edge(edge.event),
            coverage_below,
            in_out: fill_rule.is_inside(coverage_below[own]),
            inside_other: fill_rule.is_inside(coverage_below[1 - own]),
            in_result: edge.flags.in_result,
        };
        self.observer.step(step);
    }

    /// The selection of Fig. 10 for the edge of left event `l`, leaving S.
    #[cold]
    pub(crate) fn trace_selection(&mut self, l: EventId, edge: &InStatus) {
        let winding = self.event(l).winding;
        let above = edge.flags.coverage_above;
        let below = if edge.line.is_vertical() {
            above
        } else {
            [above[0] - winding[0], above[1] - winding[1]]
        };
        let step = Step::Selection {
            edge: self.trace_edge(l),
            in_result: edge.flags.in_result,
            reason: Reason::of(self.selection.fill_rule(), winding, below),
        };
        self.observer.step(step);
    }

    /// The edge of event `e` (left or right) as the trace shows it.
    fn trace_edge(&self, e: EventId) -> TraceEdge {
        let l = if self.event(e).left() {
            e
        } else {
            self.event(e).other
        };
        TraceEdge {
            left: self.point(l).approx,
            right: self.far_point(l).approx,
            operand: self.input_edge(l).operand as usize,
            winding: self.event(l).winding,
        }
    }
}
