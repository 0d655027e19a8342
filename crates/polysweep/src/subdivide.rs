//! possibleInter and the subdivision of edges (§3, Fig. 6, Fig. 7; overlapping edges §7.2; self-intersections
//! §7.3).
//!
//! Two neighbours in S are tested with four exact orientation tests. When they meet at one point, each edge that
//! has the point strictly inside is split there (Fig. 6): its left event keeps the part before the point, a new
//! right and a new left event go into Q. When they are collinear and overlap, each is split at the other's
//! endpoints inside it; the fragments that then coincide are merged into one edge carrying both windings.
//!
//! Departures from the paper:
//! - §7.3: intersections are found between all edges, of one operand or of both, always. Self-intersecting input
//!   needs it, and an exact sweep needs the status to be a true order of non-crossing edges.
//! - §7.2: the paper keeps both coinciding edges and marks one NON_CONTRIBUTING and the other SAME_TRANSITION or
//!   DIFFERENT_TRANSITION. Merging them instead keeps one edge whose winding is the sum of both; the selection
//!   rule of [`crate::select`] then yields Fig. 10 exactly, also for more than two coinciding edges and for edges
//!   of the same operand (which cancel under even-odd).
//! - At a proper crossing the four new events go into Q as one entry, which the sweep takes as one step where
//!   nothing else happens at the point (see `Sweep::process_crossing`).
//! - Every split point lies exactly on both edges' input lines (an endpoint on a line by an exact test, or an
//!   exact crossing), so fragments never move: nothing is rounded until the output.

use crate::edges::{EventId, NONE};
use crate::exact::SweepPoint;
use crate::geometry::{larger, smaller};
use crate::sweep::Sweep;
use crate::trace::{Meeting, Observer};
use std::cmp::Ordering::{Equal, Less};

impl<O: Observer> Sweep<'_, O> {
    /// possibleInter (Fig. 5) of two edges, given by their nodes in S, `lower` below `upper`. It reads the nodes,
    /// not the events.
    #[inline(always)]
    pub(crate) fn possible_inter(&mut self, lower: u32, upper: u32) {
        let ((a1, b1), (a2, b2)) = (self.ends(lower), self.ends(upper));
        // Edges whose ranges of y lie apart cannot meet (not in the paper: a cheaper test that tells most neighbours
        // apart). It is exact: correct rounding is monotone, so approximations strictly apart are exact values
        // strictly apart.
        let y_range = |a: &SweepPoint, b: &SweepPoint| {
            let (u, v) = (a.approx[1], b.approx[1]);
            (smaller(u, v), larger(u, v))
        };
        let ((low1, high1), (low2, high2)) = (y_range(&a1, &b1), y_range(&a2, &b2));
        if high1 < low2 || high2 < low1 {
            return;
        }
        // Read as needed: most other pairs are told apart by the first two tests, without `lower`'s line.
        let l2 = self.status.key(upper).line;
        let (s1, s2) = (self.exact.orient(&l2, &a1), self.exact.orient(&l2, &b1));
        if s1 == s2 && s1 != Equal {
            return; // `lower` lies on one side of `upper`'s line
        }
        let l1 = self.status.key(lower).line;
        let (s3, s4) = (self.exact.orient(&l1, &a2), self.exact.orient(&l1, &b2));
        if s3 == s4 && s3 != Equal {
            return;
        }
        if s1 == Equal && s2 == Equal {
            return self.overlap(lower, upper);
        }
        // One common point. Fig. 6: an endpoint of one edge on the other, or a proper crossing.
        let meeting = match (s1, s2, s3, s4) {
            (Equal, ..) => a1,
            (_, Equal, ..) => b1,
            (_, _, Equal, _) => a2,
            (_, _, _, Equal) => b2,
            _ => {
                self.watch_contact(lower, upper);
                let x = self.exact.crossing(&l1, &l2);
                if O::ON {
                    self.trace_meeting(lower, upper, Meeting::Crossing, &x);
                }
                self.split_crossing(lower, upper, x);
                return;
            }
        };
        for node in [lower, upper] {
            if self.strictly_inside(node, &meeting) {
                self.watch_contact(lower, upper);
                if O::ON {
                    self.trace_meeting(lower, upper, Meeting::VertexOnEdge, &meeting);
                }
                self.split(self.status.event(node), meeting);
            }
        }
    }

    /// §7.2: two collinear edges, given by their nodes in S. Splits each at the other's endpoints that lie inside
    /// it, then merges the fragments that coincide.
    fn overlap(&mut self, lower: u32, upper: u32) {
        let ((a1, b1), (a2, b2)) = (self.ends(lower), self.ends(upper));
        if self.exact.cmp_points(&b1, &a2) != std::cmp::Ordering::Greater
            || self.exact.cmp_points(&b2, &a1) != std::cmp::Ordering::Greater
        {
            return; // they touch at an endpoint at most
        }
        self.watch_contact(lower, upper);
        if O::ON {
            // The common part starts at the later left end.
            let start = if self.exact.cmp_points(&a1, &a2) == Less {
                a2
            } else {
                a1
            };
            self.trace_meeting(lower, upper, Meeting::Overlap, &start);
        }
        for (node, [first, last]) in [(lower, [a2, b2]), (upper, [a1, b1])] {
            // The far point first, so that the edge keeps its left part and the second split cuts that part.
            for p in [last, first] {
                if self.strictly_inside(node, &p) {
                    self.split(self.status.event(node), p);
                }
            }
        }
        if self.exact.cmp_points(&a1, &a2) == Equal {
            let (lower, upper) = (self.status.event(lower), self.status.event(upper));
            // Both now run from the common left point to the nearer right point: one edge from now on.
            // The edge being inserted is the one that leaves: edges above the other may already refer to it.
            let (keep, merged) = if lower == self.inserting {
                (upper, lower)
            } else {
                (lower, upper)
            };
            self.merge(keep, merged);
        }
    }

    /// The left and right endpoints of the edge at `node` in S.
    fn ends(&self, node: u32) -> (SweepPoint, SweepPoint) {
        let edge = self.status.key(node);
        (edge.left, edge.right)
    }

    /// Fig. 6: splits the edge of left event `edge`, which is in S, at `p`, which lies on it strictly between its
    /// endpoints.
    pub(crate) fn split(&mut self, edge: EventId, p: SweepPoint) {
        if !self.room_for_events(2) {
            return;
        }
        let new_right = self.cut(edge, p);
        self.push(new_right);
        self.push(new_right + 1);
    }

    /// Fig. 6 at a proper crossing `x` of the edges at nodes `lower` and `upper` of S: both are split there, and
    /// their four new events wait in Q as one entry, the first of them in the event order, a right event (see
    /// `Sweep::process_crossing`; not in the paper, for speed).
    fn split_crossing(&mut self, lower: u32, upper: u32, x: SweepPoint) {
        if !self.room_for_events(4) {
            return;
        }
        let (a, b) = (
            self.cut(self.status.event(lower), x),
            self.cut(self.status.event(upper), x),
        );
        if !self.shortcuts.crossing_step {
            for e in [a, b, a + 1, b + 1] {
                self.push(e);
            }
            return;
        }
        // Of the two right events at `x`, the lower edge's comes first (§4), and that is `lower`'s without asking:
        // `upper` lies above it left of `x`, where both edges come from, and so does its left end, which is off
        // `lower`'s line (two common points would make the lines one).
        debug_assert_eq!(self.event_order(a, b), Less);
        self.push_crossing(a, b);
    }

    /// The split of Fig. 6 without Q: the edge of left event `edge`, in S, ends at `p` (strictly between its
    /// endpoints), and a new edge goes on from there. Returns the new right event, at `p`; the new left event is the
    /// one after it.
    fn cut(&mut self, edge: EventId, p: SweepPoint) -> EventId {
        if O::ON {
            self.trace_subdivision(edge, &p);
        }
        let base = self.event(edge).clone();
        let right = base.other;
        let (new_right, new_left) = (
            self.events.len() as EventId,
            self.events.len() as EventId + 1,
        );
        self.events.push(base.fragment(p, false, edge));
        self.events.push(base.fragment(p, true, right));
        self.events[edge as usize].set_other(new_right);
        self.events[right as usize].set_other(new_left);
        if let Some(sources) = &mut self.sources {
            sources.split(edge);
        }
        debug_assert_ne!(base.node(), NONE, "split of an edge not in S");
        self.status.key_mut(base.node()).right = p;
        new_right
    }

    /// §7.2: `merged` coincides with `keep`; `keep` takes its winding and `merged` leaves S. The flags of `keep`
    /// are set again from the edge below it.
    fn merge(&mut self, keep: EventId, merged: EventId) {
        let winding = self.event(merged).winding;
        for (w, m) in self.events[keep as usize].winding.iter_mut().zip(winding) {
            *w += m;
        }
        if let Some(sources) = &mut self.sources {
            let segments = [keep, merged].map(|e| self.events[e as usize].segment());
            sources.merge(keep, merged, segments);
        }
        self.status.remove(self.event(merged).node());
        self.events[merged as usize].leave_status();
        self.set_flags(self.event(keep).node());
    }
}
