//! The sweep's shortcuts (not in the paper, for speed), each switched by [`Shortcuts`](crate::Shortcuts). Each leaves S,
//! the flags of Fig. 9 and the result as the paper's steps would, so the results are the same with it off.

use super::Sweep;
use crate::edges::{EventId, NONE};
use crate::events::event_order;
use crate::trace::Observer;
use std::cmp::Ordering;

impl<O: Observer> Sweep<'_, O> {
    /// Where the edge of left event `e` goes in S, if it goes just above the edge settled last (not in the paper).
    /// Edges that start at one point come in Q from the lowest up (§4), and each belongs just above the one before,
    /// as a rule: an edge of S between them would pass through the point and have been split there. Up a grid's
    /// column, too, a square's bottom edge mostly belongs just above the top edge of the square below. So the node
    /// of the edge settled last, if still in S, is where to insert when the order confirms it against both
    /// neighbours, as a search from the root would: two comparisons instead of a search, at a grid's corners and
    /// crossings, where two edges start at one point, and up its columns. (Walking on by neighbours when the
    /// first place fails measured worse: on the land it fails, and the steps cost more than they save.)
    pub(super) fn place_after_last_left(&self, e: EventId) -> Option<u32> {
        if !self.shortcuts.insert_after_last {
            return None;
        }
        let last = self.last_left;
        if last == NONE || self.event(last).node() == NONE {
            return None;
        }
        let node = self.event(last).node();
        let fits_below = |n: u32| n == NONE || self.is_below(e, self.status.key(n));
        (!self.is_below(e, self.status.key(node)) && fits_below(self.status.next(node)))
            .then_some(node)
    }

    /// The four events of a crossing, which wait in Q as one entry (not in the paper, for speed; see
    /// `split_crossing`): right events `first` and `second`, where two edges end at the crossing point, each with
    /// the left event made after it, where its edge goes on. Where nothing else is still to happen at the point
    /// (no other event waits there, and the two edges are still neighbours in S), they are handled at once: both
    /// edges end, and the parts past the point take their two nodes of S the other way round, leaving S as the
    /// four events one by one would (the flags of Fig. 9, the result edges and the close calls come out the same;
    /// possibleInter runs for each new pair of neighbours but the two parts themselves, which meet only at the
    /// point, and not for the pairs that the one-by-one way makes only for a moment, whose meetings are found when
    /// they are neighbours for good). Otherwise the four go into Q, to be taken one by one. Where crossings are
    /// alone (a coastline against a grid), this saves three heap entries, a removal and an insertion in S, and the
    /// in-place step's checks per crossing. Not inlined: in the main loop it made every event dearer.
    #[inline(never)]
    pub(super) fn process_crossing(&mut self, first: EventId, second: EventId) {
        let p = self.current;
        let node_of = |r: EventId| self.event(self.event(r).other).node();
        let (n1, n2) = (node_of(first), node_of(second));
        let neighbours = if n1 == NONE || n2 == NONE {
            None
        } else if self.status.next(n1) == n2 {
            Some((n1, n2))
        } else if self.status.next(n2) == n1 {
            Some((n2, n1))
        } else {
            None
        };
        // No other event waits at the point. (Then no other edge of S passes through it either: every edge of S
        // between such an edge and the two lies in the wedge that they close at the point, so passes through it or
        // ends there, and the one next to the two would have met one of them there and been split, which leaves a
        // left event waiting at the point.)
        let nothing_else = || {
            self.peek().is_none_or(|head| {
                self.exact.cmp_points(&self.point(head.event), &p) != Ordering::Equal
            })
        };
        let alone = neighbours.filter(|_| nothing_else());
        let Some((lower, upper)) = alone else {
            // (`first` too, now on its own: taken again in its turn, at this point and its vertex.)
            for e in [first, second, first + 1, second + 1] {
                self.push(e);
            }
            return;
        };
        // Close calls: each of the two is the other's neighbour, but ends at `p`, which is no close call; only the
        // edges below and above the pair are asked.
        self.note_close_calls_of(&p, [self.status.prev(lower), self.status.next(upper)]);
        // Both edges end, in the order of their right events.
        for (r, node) in [(first, n1), (second, n2)] {
            self.end_edge(self.event(r).other, node);
        }
        // Past the point, the edge that was above goes on below.
        let (lower_right, upper_right) = if lower == n1 {
            (first, second)
        } else {
            (second, first)
        };
        let (below_next, above_next) = (upper_right + 1, lower_right + 1);
        self.status
            .replace(lower, below_next, self.in_status(below_next));
        self.status
            .replace(upper, above_next, self.in_status(above_next));
        // (Each in its node before either is settled, so that S and the events agree throughout.)
        self.events[above_next as usize].enter_status(upper);
        // The two parts past the point start there on two lines that cross there: they meet nowhere else, and
        // possibleInter is not asked about them (it would find their common left endpoint, twice).
        self.settle(below_next, lower, true, upper);
        self.settle(above_next, upper, true, lower);
    }

    /// Do the new edge at `node` of S and its neighbour at `other` both start at the current point, on two lines?
    /// Then they meet there only, and possibleInter, which could find nothing else, is not asked (not in the paper):
    /// at a square's lower-left corner, a coastline's leftmost vertices, wherever a ring starts. Told by the output
    /// vertex of their left ends, an integer, and one orientation (the neighbour's right end off the new edge's line;
    /// on it, the two may overlap, §7.2, and possibleInter is asked).
    #[inline(always)]
    pub(super) fn start_here_apart(&self, node: u32, other: u32) -> bool {
        if !self.shortcuts.shared_start {
            return false;
        }
        let (new, neighbour) = (self.status.key(node), self.status.key(other));
        neighbour.vertex == new.vertex
            && self.exact.orient(&new.line, &neighbour.right) != Ordering::Equal
    }

    /// A chain going on (not in the paper): when the next event is a left endpoint at this point whose edge belongs
    /// exactly where the ending edge at `node` is in S, it is taken from Q to replace that edge in place: no
    /// removal, no search from the root, and no possibleInter between neighbours that would not stay neighbours.
    /// The result is the same as removing and inserting; at most vertices of a coastline, this is what happens.
    pub(super) fn successor_in_place(&mut self, node: u32) -> Option<EventId> {
        if !self.shortcuts.successor_in_place {
            return None;
        }
        let head = self.peek()?;
        let next = head.event;
        let event = self.event(next);
        if !event.left() || self.exact.cmp_points(&event.point, &self.current) != Ordering::Equal {
            return None;
        }
        if !(self.fits_beside(next, self.status.prev(node), false)
            && self.fits_beside(next, self.status.next(node), true))
        {
            return None;
        }
        // At the current point, so at the current output vertex.
        self.queue.take(head, |a, b| {
            event_order(&self.events, self.edges, &self.exact, a, b)
        });
        Some(next)
    }

    /// Does left event `next`, at the current point, belong on its side (above or not) of the edge at node `n` of
    /// S (`NONE`: no edge)? A neighbour whose line misses the point is on the side the orientation says
    /// (`is_below` at the new edge's left endpoint, asked once). One whose line holds the point ends or starts
    /// there, or passes through it: that one is split first (see `settle`), which the ordinary path handles.
    #[inline(always)]
    pub(super) fn fits_beside(&self, next: EventId, n: u32, above: bool) -> bool {
        if n == NONE {
            return true;
        }
        let key = self.status.key(n);
        match self.exact.orient(&key.line, &self.current) {
            Ordering::Equal => {
                !self.strictly_inside(n, &self.current) && self.is_below(next, key) == above
            }
            side => (side == Ordering::Less) == above,
        }
    }
}
