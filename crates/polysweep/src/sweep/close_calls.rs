//! Close calls: event points that pass within a few ulps of a neighbouring edge (not in the paper, which does not
//! round). The sweep decides every predicate exactly, but the output is rounded; these are the places where
//! rounding could move a point across an edge, noted for the output rounding (see [`crate::rounding`]).

use super::{InStatus, Sweep};
use crate::edges::NONE;
use crate::exact::SweepPoint;
use crate::geometry::larger;
use crate::trace::Observer;
use std::cmp::Ordering;

impl<O: Observer> Sweep<'_, O> {
    /// Rounding moves a constructed point by at most half an ulp, and an edge with such an end (even one made by a
    /// later split) by as much. So an event point can end up on the other side of a neighbouring edge only if it
    /// lies within a few ulps of it; `close_call` notes it, and the rounded result is then validated. `p`, the
    /// current vertex, is checked against the neighbours of the edge at `node` in S.
    #[inline(always)]
    pub(super) fn note_close_calls(&mut self, p: &SweepPoint, node: u32) {
        self.note_close_calls_of(p, [self.status.prev(node), self.status.next(node)]);
    }

    /// [`Self::note_close_calls`] for the edges at `nodes` of S (`NONE`: no edge).
    #[inline(always)]
    pub(super) fn note_close_calls_of(&mut self, p: &SweepPoint, nodes: [u32; 2]) {
        for neighbour in nodes {
            if self.is_close_call(p, neighbour) {
                self.close_call = true;
            }
        }
    }

    /// Is `p` within a few ulps of the edge at `node` in S (`NONE`: no edge) without being one of its ends?
    #[inline(always)]
    pub(super) fn is_close_call(&self, p: &SweepPoint, node: u32) -> bool {
        if node == NONE {
            return false;
        }
        let InStatus {
            line,
            left: a,
            right: b,
            ..
        } = *self.status.key(node);
        if !line.float_within(p.approx, self.widest_clearance) {
            return false;
        }
        let magnitude = [a.approx, b.approx, p.approx]
            .iter()
            .flatten()
            .fold(0.0f64, |m, v| larger(m, v.abs()));
        // A vertex of the edge moves with it.
        line.float_within(p.approx, crate::rounding::clearance(magnitude))
            && ![a, b]
                .iter()
                .any(|q| self.exact.cmp_points(q, p) == Ordering::Equal)
    }
}
