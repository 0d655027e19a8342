//! The plane sweep of Fig. 5: events in order, the sweep-line status, and the result edges.
//!
//! ```text
//! while Q is not empty:
//!     event = Q.pop()
//!     left endpoint:  insert its edge into S, set its flags from the edge below (Fig. 9),
//!                     possibleInter with both neighbours (Fig. 6)
//!     right endpoint: if its edge is in the result, record it; remove it from S;
//!                     possibleInter of the two edges that become neighbours
//! ```
//!
//! The status order (§3, §7.1) compares a new edge with an edge of S at the new edge's left endpoint `p`: the
//! side of `p` from the other edge's line, or, when `p` is on that line, the side of the new edge's right
//! endpoint. A vertical edge is placed by its lower endpoint and so goes above a non-vertical edge starting
//! there (§7.1). Collinear edges are ordered by operand and input segment; they are merged as soon as they become
//! identical (§7.2).
//!
//! Departure from the paper: when a new edge starts at a point `p` inside an edge of S (a vertex on an edge, Fig.
//! 6), that edge is split at `p` and the new edge is put back in Q. The split makes a right endpoint at `p`, which
//! §4 orders before every left endpoint at `p`; processing it first keeps the flags of Fig. 9 right.
//!
//! Second departure, for speed: where a chain of edges goes on through a vertex (one edge ends there and the next
//! starts in its place in S, most vertices of real data), the new edge takes the old one's node in S instead of a
//! removal and an insertion (see `successor_in_place`); the status and the flags come out the same.
//!
//! Third departure, for speed: the four events of a proper crossing of two edges wait in Q as one entry, and where
//! nothing else is still to happen at the crossing point the two edges simply trade places in S there (as in
//! Bentley and Ottmann's sweep), their parts before the point ending as the paper's split would end them (see
//! `process_crossing`).
//!
//! Fourth departure, for speed: a new edge and a neighbour that start at the same point on two lines meet nowhere
//! else, and possibleInter is not asked about them (see `start_here_apart`).
//!
//! The steps taken for every event (possibleInter, `settle`, the close-call checks, the in-place step's fit test,
//! popping Q) are `#[inline(always)]`: as calls, their arguments and results went through memory (see
//! docs/benchmarks.md).

use crate::arrangement::Sources;
use crate::edges::{EventId, InputEdge, Operand, ResultEdge, NONE};
use crate::events::{
    event_order, far_point, initial_events, EventQueue, Head, SweepEvent, MAX_EVENTS,
};
use crate::exact::{Exact, Line, SweepPoint};
use crate::options::Shortcuts;
use crate::select::{Flags, Selection};
use crate::structure::Watch;
use crate::trace::{Observer, Silent};
use crate::workspace::{reserve, room, take, Workspace};

mod close_calls;
mod shortcuts;
use crate::error::Error;
use std::cmp::Ordering;

/// What S keeps of an edge while the edge is in it: what the status order reads (see [`Sweep::is_below`]), which
/// never changes while the edge is there; its endpoints, which possibleInter reads (a split moves the right one);
/// and what the sweep reads when the edge above it is inserted or when it ends, its flags of Fig. 9 and the output
/// vertex at its left end. Kept in the node, not in the events, because S is small and read all the time, and the
/// events are many: a neighbour's events are far behind and ahead in memory.
#[derive(Clone, Copy)]
pub(crate) struct InStatus {
    pub line: Line,
    pub operand: Operand,
    pub segment: u32,
    pub event: EventId,
    /// The endpoints of the edge (not of its input segment), left and right.
    pub left: SweepPoint,
    pub right: SweepPoint,
    pub flags: Flags,
    vertex: u32,
}

/// Events' worth of memory that [`Sweep::room_for_events`] reserves beyond what a split asks for, so that it looks at
/// its vectors once every few hundred events rather than at every split (a look is a comparison per vector: at every
/// crossing of a dense arrangement it was a noticeable share of the crossing's cost).
const ROOM_AHEAD: usize = 256;

pub(crate) struct Sweep<'a, O: Observer = Silent> {
    /// The input edges: what every fragment of one keeps of it (its line and operand) is read here.
    pub edges: &'a [InputEdge],
    pub events: Vec<SweepEvent>,
    pub exact: Exact,
    pub queue: EventQueue,
    pub status: crate::status::Status<InStatus>,
    pub selection: Selection,
    /// The point being processed.
    pub current: SweepPoint,
    /// Distinct event points in sweep order: the vertices of the result.
    pub vertices: Vec<SweepPoint>,
    pub result: Vec<ResultEdge>,
    /// Events beyond this x cannot add result edges (not in the paper: past the end of the subject, or of either
    /// operand for an intersection; infinite when the shortcut is off).
    pub stop_x: f64,
    /// The left event being inserted, or `NONE`.
    pub inserting: EventId,
    /// The left event settled last, or `NONE` (see `place_after_last_left`).
    last_left: EventId,
    /// Some event point passed within a few ulps of a neighbouring edge: rounding the output could move one across
    /// the other (see `note_close_calls`).
    pub close_call: bool,
    /// The clearance of the largest magnitude of the input's coordinates, which bounds every point's (crossings
    /// lie between input vertices): edges farther than this from a point need no closer look.
    widest_clearance: f64,
    /// The most events this sweep may make: [`MAX_EVENTS`], within which every index fits its 32 bits (smaller in
    /// tests). A split that would pass it stops the sweep with [`Error::TooLarge`] (see `room_for_events`).
    pub max_events: usize,
    /// Why a split found no room (under `max_events`, or in memory): Q has been emptied and stays empty.
    stopped: Option<Error>,
    /// Events that `room_for_events` has reserved memory for beyond those it was asked for, in every vector, so
    /// that most splits need not look at them all.
    room_reserved: usize,
    /// Which of the shortcuts of [`shortcuts`] are on.
    pub shortcuts: Shortcuts,
    /// What the structural reading's check watches, when it is on (see [`crate::structure`]).
    pub watch: Option<&'a mut Watch>,
    /// For an arrangement sweep only (see [`crate::arrangement`]): which input segments lie on each edge, and every
    /// edge recorded as a fragment when it leaves S, instead of the result edges.
    pub sources: Option<Sources>,
    /// What the steps are reported to (see [`crate::trace`]): nothing, for the operations.
    pub observer: O,
}

impl<'a, O: Observer> Sweep<'a, O> {
    /// A sweep of `edges`, all within coordinates of magnitude `magnitude`, reporting its steps to `observer`
    /// ([`Silent`] for the operations, see [`crate::trace`]). Its vectors are `workspace`'s (see
    /// [`Self::give_back`]).
    pub fn new(
        edges: &'a [InputEdge],
        selection: Selection,
        stop_x: f64,
        magnitude: f64,
        shortcuts: Shortcuts,
        workspace: &mut Workspace,
        observer: O,
    ) -> Self {
        let exact = Exact::default();
        let events = initial_events(
            edges,
            &exact,
            &mut workspace.sort,
            take(&mut workspace.events),
            shortcuts.merge_identical_edges,
        );
        let queue = EventQueue::new(events.len());
        // Every vertex has two events at least (a ring vertex two, a crossing four): room for as many vertices as
        // the events have room for, and for a result edge per input edge (a union of polygons apart keeps them
        // all), so that these vectors seldom move.
        let mut vertices = take(&mut workspace.vertices);
        reserve(&mut vertices, events.len() / 2 + events.len() / 8);
        let mut result = take(&mut workspace.result);
        reserve(&mut result, events.len() / 2);
        Sweep {
            edges,
            events,
            exact,
            queue,
            status: Default::default(),
            selection,
            current: SweepPoint::input([f64::NEG_INFINITY; 2]),
            vertices,
            result,
            stop_x,
            inserting: NONE,
            last_left: NONE,
            close_call: false,
            widest_clearance: crate::rounding::clearance(magnitude),
            max_events: MAX_EVENTS,
            stopped: None,
            room_reserved: 0,
            shortcuts,
            watch: None,
            sources: None,
            observer,
        }
    }

    /// Gives this sweep's vectors back to `workspace`, for the next sweep.
    pub fn give_back(self, workspace: &mut Workspace) {
        (workspace.events, workspace.vertices, workspace.result) =
            (self.events, self.vertices, self.result);
    }

    pub fn event(&self, e: EventId) -> &SweepEvent {
        &self.events[e as usize]
    }

    pub fn point(&self, e: EventId) -> SweepPoint {
        self.events[e as usize].point
    }

    /// The point at the other end of event `e`'s edge.
    pub fn far_point(&self, e: EventId) -> SweepPoint {
        far_point(&self.events, self.edges, e)
    }

    /// The input edge that event `e`'s edge lies on.
    pub fn input_edge(&self, e: EventId) -> &'a InputEdge {
        &self.edges[self.event(e).segment() as usize]
    }

    /// Puts event `e` in Q, unless the sweep has been stopped (see [`Self::max_events`]).
    pub fn push(&mut self, e: EventId) {
        self.push_with(e, NONE);
    }

    /// Puts the four events of a crossing in Q as one entry: `first`, the first of them in the event order, with
    /// `second`, the other right event (see [`Self::process_crossing`]).
    pub fn push_crossing(&mut self, first: EventId, second: EventId) {
        self.push_with(first, second);
    }

    fn push_with(&mut self, e: EventId, partner: EventId) {
        if self.stopped.is_some() {
            return;
        }
        self.queue
            .push(e, partner, self.point(e).approx[0], |a, b| {
                event_order(&self.events, self.edges, &self.exact, a, b)
            });
    }

    /// The event order of `a` and `b`. (Q's own pushes and pops, which borrow Q mutably, call [`event_order`] on the
    /// fields instead.)
    pub fn event_order(&self, a: EventId, b: EventId) -> Ordering {
        event_order(&self.events, self.edges, &self.exact, a, b)
    }

    /// The next event of Q, without taking it.
    fn peek(&self) -> Option<Head> {
        self.queue.peek(
            |e| self.events[e as usize].point.approx[0],
            |a, b| self.event_order(a, b),
        )
    }

    /// Fig. 5's main loop.
    pub fn run(&mut self) -> Result<(), Error> {
        while let Some(head) = self.queue.pop(
            |e| self.events[e as usize].point.approx[0],
            |a, b| event_order(&self.events, self.edges, &self.exact, a, b),
        ) {
            let e = head.event;
            let point = self.point(e);
            if self
                .exact
                .cmp_coordinate(&point, &SweepPoint::input([self.stop_x, 0.0]), 0)
                == Ordering::Greater
            {
                break;
            }
            self.current = point;

            self.assign_vertex(e);
            if O::ON {
                self.trace_event(e);
            }
            if head.partner != NONE {
                self.process_crossing(e, head.partner);
            } else if self.event(e).left() {
                self.process_left(e);
            } else {
                self.process_right(e);
            }
            if O::ON && self.observer.wants_status() {
                self.trace_status();
            }
        }
        match self.stopped.take() {
            Some(error) => Err(error),
            None => Ok(()),
        }
    }

    /// Can a split add `count` more events? If not, the sweep stops: Q is emptied and nothing more is put in it, so
    /// the loop ends once the event at hand is done (the status left as it is, and no result made).
    ///
    /// Memory is reserved here for everything a split adds (events, their entries in Q and nodes in S, the
    /// crossing, its vertex, result edges), so that running out of it ends the sweep with [`Error::OutOfMemory`]
    /// where the allocator says so (wasm32's 4 GiB), rather than aborting in a push.
    pub fn room_for_events(&mut self, count: usize) -> bool {
        if self.stopped.is_none() {
            let more = count + ROOM_AHEAD;
            if self.events.len() + count > self.max_events {
                self.stopped = Some(Error::TooLarge {
                    limit: self.max_events,
                });
            } else if self.room_reserved >= count {
                self.room_reserved -= count;
            } else if room(&mut self.events, more)
                && self.queue.room(more)
                && self.status.room(more)
                && self.exact.room(more)
                && room(&mut self.vertices, more)
                && room(&mut self.result, more)
                && (self.sources.as_mut()).is_none_or(|s| s.room(more))
            {
                self.room_reserved = ROOM_AHEAD;
            } else {
                self.stopped = Some(Error::OutOfMemory {
                    edges: self.edges.len(),
                    crossings: self.exact.crossing_count(),
                });
            }
            if self.stopped.is_some() {
                self.queue.clear();
            }
        }
        self.stopped.is_none()
    }

    /// Events come in point order, so equal points are consecutive and share one output vertex.
    fn assign_vertex(&mut self, e: EventId) {
        let point = self.point(e);
        let same = self
            .vertices
            .last()
            .is_some_and(|last| self.exact.cmp_points(last, &point) == Ordering::Equal);
        if !same {
            self.vertices.push(point);
        }
    }

    /// The output vertex of the event being processed.
    fn current_vertex(&self) -> u32 {
        (self.vertices.len() - 1) as u32
    }

    /// The status order: is the new edge `e` below the edge `old` of S?
    #[inline]
    fn is_below(&self, e: EventId, old: &InStatus) -> bool {
        let new = self.event(e);
        let side = self.exact.orient(&old.line, &new.point);
        // The side as a value, not a branch: a search of S asks this at every level, and no predictor can guess it.
        if side != Ordering::Equal {
            return side == Ordering::Less;
        }
        match self.exact.orient(&old.line, &self.far_point(e)) {
            Ordering::Less => true,
            Ordering::Greater => false,
            Ordering::Equal => {
                let operand = self.input_edge(e).operand;
                (operand, new.segment(), e) < (old.operand, old.segment, old.event)
            }
        }
    }

    /// Does the edge at `node` in S pass through `p` strictly between its endpoints?
    pub fn passes_through(&self, node: u32, p: &SweepPoint) -> bool {
        self.exact.orient(&self.status.key(node).line, p) == Ordering::Equal
            && self.strictly_inside(node, p)
    }

    /// Is `p` strictly between the endpoints of the edge at `node` in S, in sweep order? (For a point on the
    /// edge's line: is it inside the edge?)
    pub fn strictly_inside(&self, node: u32, p: &SweepPoint) -> bool {
        let edge = self.status.key(node);
        self.exact.cmp_points(&edge.left, p) == Ordering::Less
            && self.exact.cmp_points(p, &edge.right) == Ordering::Less
    }

    /// What S keeps of the edge of left event `e`, being inserted at this event's point; its flags are set once it
    /// is in S (see [`Self::set_flags`]).
    fn in_status(&self, e: EventId) -> InStatus {
        let input = self.input_edge(e);
        InStatus {
            line: input.line,
            operand: input.operand,
            segment: self.event(e).segment(),
            event: e,
            left: self.point(e),
            right: self.far_point(e),
            flags: Flags {
                coverage_above: [0; 2],
                in_result: false,
                result_above: false,
                result_below: NONE,
            },
            vertex: self.current_vertex(),
        }
    }

    /// Fig. 9: the flags of the edge at `node` in S, from the edge below it.
    #[inline(always)]
    pub fn set_flags(&mut self, node: u32) {
        set_flags(&mut self.status, &self.selection, &self.events, node);
    }

    fn process_left(&mut self, e: EventId) {
        let node = match self.place_after_last_left(e) {
            Some(below) => self.status.insert_above(below, e, self.in_status(e)),
            None => {
                // The order reads the events, not S, so S is taken out while it inserts.
                let mut status = std::mem::take(&mut self.status);
                let node = status.insert(e, self.in_status(e), |old| self.is_below(e, old));
                self.status = status;
                node
            }
        };
        self.settle(e, node, false, NONE);
    }

    /// The rest of Fig. 5 for left event `e`, once its edge is at `node` in S: a neighbour through its left
    /// endpoint is split first; then the flags of Fig. 9 and possibleInter with both neighbours.
    /// `neighbours_checked`: the caller has made sure that neither neighbour passes through the point and has
    /// noted close calls with them (the in-place step, whose neighbours are those of the edge that ended).
    /// `meets_only_here`: the node of an edge that meets this one at the point and nowhere else (`NONE`: none),
    /// which possibleInter is not asked about.
    #[inline(always)]
    fn settle(&mut self, e: EventId, node: u32, neighbours_checked: bool, meets_only_here: u32) {
        self.inserting = e;
        self.events[e as usize].enter_status(node);
        let (below, above) = (self.status.prev(node), self.status.next(node));
        let p = self.current;
        if !neighbours_checked {
            for neighbour in [below, above] {
                if neighbour != NONE && self.passes_through(neighbour, &p) {
                    self.watch_contact(neighbour, node);
                    self.split(self.status.event(neighbour), p);
                    self.status.remove(node);
                    self.events[e as usize].leave_status();
                    self.push(e);
                    self.inserting = NONE;
                    return;
                }
            }
            self.note_close_calls(&p, node);
        }
        self.set_flags(node);
        if O::ON {
            self.trace_flags(node);
        }
        if let Some(watch) = self.watch.as_deref() {
            if !watch.reached(self.event(e).segment()) {
                self.watch_ring_start(e, node);
            }
        }

        // (Nothing since the caller chose `meets_only_here` has inserted into S, so its index still names that edge,
        // or none.)
        debug_assert!(
            meets_only_here == NONE
                || self
                    .exact
                    .cmp_points(&self.status.key(meets_only_here).left, &p)
                    == Ordering::Equal
        );
        if below != NONE && below != meets_only_here && !self.start_here_apart(node, below) {
            self.possible_inter(below, node);
        }
        // (Unless `e` was merged into the edge below and left S.)
        if above != NONE
            && above != meets_only_here
            && self.event(e).node() != NONE
            && !self.start_here_apart(node, above)
        {
            self.possible_inter(node, above);
        }
        self.inserting = NONE;
        self.last_left = e;
    }

    fn process_right(&mut self, r: EventId) {
        let l = self.event(r).other;
        let node = self.event(l).node();
        if node == NONE {
            return; // merged into an overlapping edge (§7.2)
        }
        let (below, above) = (self.status.prev(node), self.status.next(node));
        self.note_close_calls(&self.current.clone(), node);
        self.end_edge(l, node);
        if let Some(next) = self.successor_in_place(node) {
            self.status.replace(node, next, self.in_status(next));
            self.settle(next, node, true, NONE);
            // Should `next` have left S again (merged into a neighbour, or put back in Q), the neighbours it
            // separated are neighbours now, as on the ordinary path.
            if self.event(next).node() == NONE && below != NONE && above != NONE {
                self.possible_inter(below, above);
            }
            return;
        }
        self.status.remove(node);
        if below != NONE && above != NONE {
            self.possible_inter(below, above);
        }
    }

    /// The edge of left event `l`, at `node` in S, ends at the current point: it leaves S, as a result edge if it
    /// is one (the node stays, for the caller to remove or reuse).
    #[inline(always)]
    fn end_edge(&mut self, l: EventId, node: u32) {
        let edge = *self.status.key(node);
        if O::ON {
            self.trace_selection(l, &edge);
        }
        if edge.flags.in_result {
            let (from, to) = (edge.vertex, self.current_vertex());
            if let Some(sources) = &mut self.sources {
                let winding = self.events[l as usize].winding;
                let index = sources.record(l, [from, to], edge.segment, winding, &edge.flags);
                self.events[l as usize].record(index);
                return;
            }
            let forward = edge.flags.result_above;
            let result_edge = ResultEdge {
                from: if forward { from } else { to },
                to: if forward { to } else { from },
                segment: edge.segment,
                forward,
                below: edge.flags.result_below,
            };
            self.events[l as usize].record(self.result.len() as u32);
            self.result.push(result_edge);
        } else {
            self.events[l as usize].leave_status();
        }
    }
}

/// [`Sweep::set_flags`], outside the sweep's impl: as a method of the sweep, generic over its observer, LLVM laid it
/// out with 7% more instructions (Table 1's callgrind counts).
#[inline(never)]
fn set_flags(
    status: &mut crate::status::Status<InStatus>,
    selection: &Selection,
    events: &[SweepEvent],
    node: u32,
) {
    let below = match status.prev(node) {
        NONE => None,
        b => Some(status.key(b)),
    };
    let edge = status.key(node);
    let flags = selection.flags(
        events[edge.event as usize].winding,
        edge.line.is_vertical(),
        below.map(|b| (b.event, &b.flags, b.line.is_vertical())),
    );
    status.key_mut(node).flags = flags;
}

#[cfg(test)]
mod tests;
