//! Selecting the result edges (§4, Fig. 9, Fig. 10; the even-odd rule of §7.3, and non-zero, not in the paper).
//!
//! The paper reads three flags of the edge below (`pl`, `inOut`, `inside`, Fig. 9) to know whether an edge lies
//! inside the other polygon. Here every edge carries the winding numbers of both operands for the region just
//! above it (`coverage_above`), computed the same way from the edge below: its counts plus this edge's winding.
//! Under the even-odd rule (the paper's, §7.3) the parity of those counts is exactly the paper's pair of flags:
//! `inOut` of an edge is "its own operand's count below is odd" and `inside` is "the other operand's count is
//! odd". Counts rather than bits give the non-zero fill rule with the same code.
//!
//! An edge is in the result when the result holds on one side of it and not on the other. That one comparison
//! is the whole of Fig. 10 too: overlapping edges are merged into one edge carrying both windings (§7.2, see
//! [`crate::subdivide`]), and for that edge "the result differs across it" is exactly the table of Fig. 10:
//! SAME_TRANSITION fragments are kept by intersection and union, DIFFERENT_TRANSITION fragments by difference,
//! and xor keeps neither (see the tests below).
//!
//! Departure: vertical edges (§7.1) do not cross the upward ray at `x + dx`, so the coverage above a vertical
//! edge is the coverage below it; what the vertical edge separates is its right side (that coverage) from its
//! left side (that coverage plus its winding).

use crate::edges::{EventId, NONE};
use std::hint::select_unpredictable;

/// A Boolean operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operation {
    Intersection,
    Union,
    /// Subject minus clipping.
    Difference,
    Xor,
}

/// How the rings of one operand define its interior.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FillRule {
    /// A point is inside when a ray from it crosses the operand's rings an odd number of times (§7.3). Ring
    /// orientation does not matter.
    #[default]
    EvenOdd,
    /// A point is inside when the winding number of the operand's rings around it is not zero (as in Clipper2
    /// and i_overlay): rings are taken with their orientation as given.
    NonZero,
    /// A point is inside when the winding number is positive: counter-clockwise rings add, clockwise ones take
    /// away (as in Clipper2 and i_overlay).
    Positive,
    /// A point is inside when the winding number is negative: the mirror of [`FillRule::Positive`].
    Negative,
    /// Each polygon read by its structure, as polygon-clipping and GEOS's `make_valid(…, method='structure')`
    /// read GeoJSON: a ring's region is where that ring alone winds around (so orientation does not matter, and a
    /// ring that crosses itself is read by the non-zero rule), a polygon is its exterior's region less its holes',
    /// and an operand is the union of its polygons (so overlapping parts do not cancel). Where the input is a
    /// valid polygon set, this is what every rule reads, at the same cost: the sweep sees that it is valid. An
    /// operand it finds otherwise is first read by its structure, about three times the work (see
    /// [`Stats::structure_sweeps`](crate::Stats::structure_sweeps)).
    Structure,
}

impl FillRule {
    pub(crate) fn is_inside(self, winding: i32) -> bool {
        match self {
            FillRule::EvenOdd => winding % 2 != 0,
            FillRule::NonZero => winding != 0,
            FillRule::Positive => winding > 0,
            FillRule::Negative => winding < 0,
            // (An operand read by its structure is first made a valid polygon set, which even-odd reads as it is:
            // see `overlay`.)
            FillRule::Structure => winding % 2 != 0,
        }
    }
}

impl Operation {
    /// The selection table: is a region with this membership in the result?
    pub(crate) fn keeps(self, in_subject: bool, in_clipping: bool) -> bool {
        match self {
            Operation::Intersection => in_subject && in_clipping,
            Operation::Union => in_subject || in_clipping,
            Operation::Difference => in_subject && !in_clipping,
            Operation::Xor => in_subject != in_clipping,
        }
    }
}

/// Which regions one sweep keeps.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Selection {
    /// The paper's case: two operands, each under its fill rule.
    Pair {
        operation: Operation,
        fill_rule: FillRule,
    },
    /// Many operands, each a valid polygon set (winding 1 inside, 0 outside), counted together: slot 0 counts the
    /// operands containing a region (for a difference: the subject), slot 1 the clipping operands of a
    /// difference. `operands` is how many there are in slot 0.
    Count { operation: Operation, operands: i32 },
    /// Every edge, whatever lies on either side: the arrangement of all the edges, whose faces
    /// [`crate::arrangement`] reads (lines and layers).
    Arrangement,
}

impl Selection {
    /// The fill rule the operands are read by (a polygon set counted together is read by its winding's parity).
    pub fn fill_rule(&self) -> FillRule {
        match *self {
            Selection::Pair { fill_rule, .. } => fill_rule,
            Selection::Count { .. } | Selection::Arrangement => FillRule::EvenOdd,
        }
    }

    // (Inlined into `flags`, on the path of every edge; as a call it cost 2% of Table 1.)
    #[inline(always)]
    pub fn in_result(&self, coverage: [i32; 2]) -> bool {
        match *self {
            Selection::Pair {
                operation,
                fill_rule,
            } => operation.keeps(
                fill_rule.is_inside(coverage[0]),
                fill_rule.is_inside(coverage[1]),
            ),
            Selection::Count {
                operation,
                operands,
            } => match operation {
                Operation::Union => coverage[0] > 0,
                Operation::Intersection => coverage[0] >= operands,
                Operation::Xor => coverage[0] % 2 != 0,
                Operation::Difference => coverage[0] > 0 && coverage[1] <= 0,
            },
            Selection::Arrangement => false,
        }
    }

    /// Fig. 9 generalised: the flags of an edge with `winding`, vertical or not, given the edge below it in S (its
    /// left event, flags and whether it is vertical), if any.
    #[inline]
    pub fn flags(
        &self,
        winding: [i32; 2],
        vertical: bool,
        below: Option<(EventId, &Flags, bool)>,
    ) -> Flags {
        let (coverage_below, result_below) = match below {
            None => ([0; 2], NONE),
            // The closest non-vertical result edge below: the edge below, or the one it names. (A selection, not a
            // branch: whether the edge below is in the result is a coin toss.)
            Some((b, flags, b_vertical)) => (
                flags.coverage_above,
                select_unpredictable(flags.in_result & !b_vertical, b, flags.result_below),
            ),
        };
        let crossed = [
            coverage_below[0] + winding[0],
            coverage_below[1] + winding[1],
        ];
        let result_above = self.in_result(crossed);
        Flags {
            coverage_above: if vertical { coverage_below } else { crossed },
            result_above,
            in_result: matches!(self, Selection::Arrangement)
                || self.in_result(coverage_below) != result_above,
            result_below,
        }
    }
}

/// What the selection knows of an edge in S (Fig. 9, generalised).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Flags {
    /// Winding numbers of the region just above the edge (§4, Fig. 9).
    pub coverage_above: [i32; 2],
    /// The edge is part of the result's boundary (§4, Fig. 10).
    pub in_result: bool,
    /// The result lies above the edge (left of it when vertical).
    pub result_above: bool,
    /// The closest non-vertical result edge below this one when it was inserted, as a left event, used to nest
    /// holes (§5).
    pub result_below: EventId,
}

#[cfg(test)]
mod tests {
    use super::*;
    use Operation::*;

    /// Fig. 10: which of two overlapping edges' fragments each operation keeps. An overlapping pair is one merged
    /// edge; `below` is the coverage under it.
    fn keeps_overlap(operation: Operation, below: [i32; 2], winding: [i32; 2]) -> bool {
        let s = Selection::Pair {
            operation,
            fill_rule: FillRule::EvenOdd,
        };
        s.in_result(below) != s.in_result([below[0] + winding[0], below[1] + winding[1]])
    }

    #[test]
    fn figure_10_same_and_different_transition() {
        // SAME_TRANSITION: both polygons on the same side (both above).
        let same = ([0, 0], [1, 1]);
        // DIFFERENT_TRANSITION: subject above, clipping below.
        let different = ([0, 1], [1, -1]);
        for (operation, keep_same, keep_different) in [
            (Intersection, true, false),
            (Union, true, false),
            (Difference, false, true),
            (Xor, false, false),
        ] {
            assert_eq!(
                keeps_overlap(operation, same.0, same.1),
                keep_same,
                "{operation:?} same transition"
            );
            assert_eq!(
                keeps_overlap(operation, different.0, different.1),
                keep_different,
                "{operation:?} different"
            );
        }
    }

    #[test]
    fn figure_9_flags_are_the_parities_of_the_counts() {
        // An edge of the clipping polygon above a subject edge, both bounding regions from below.
        let s = Selection::Pair {
            operation: Intersection,
            fill_rule: FillRule::EvenOdd,
        };
        let subject = s.flags([1, 0], false, None);
        let clipping = s.flags([0, 1], false, Some((0, &subject, false)));
        // Paper: ple null => inside = inOut = false; so the subject edge is not inside the clipping polygon.
        assert!(!subject.in_result);
        // Second edge: inside the subject (its `inside` flag is !ple.inOut = true), so it bounds the intersection.
        assert!(clipping.in_result && clipping.result_above);
        assert_eq!(
            clipping.result_below, NONE,
            "the edge below is not in the result"
        );
        // A third edge above, of the subject again: it closes the subject's region, and the clipping edge below it
        // is the result edge below it.
        let third = s.flags([-1, 0], false, Some((1, &clipping, false)));
        assert!(third.in_result && !third.result_above);
        assert_eq!(third.result_below, 1);
        // A vertical edge leaves the coverage above as it was below.
        let vertical = s.flags([1, 0], true, Some((1, &clipping, false)));
        assert_eq!(vertical.coverage_above, clipping.coverage_above);
    }

    #[test]
    fn counted_operands() {
        let three = |operation| Selection::Count {
            operation,
            operands: 3,
        };
        assert!(three(Union).in_result([1, 0]) && !three(Union).in_result([0, 0]));
        assert!(three(Intersection).in_result([3, 0]) && !three(Intersection).in_result([2, 0]));
        assert!(three(Xor).in_result([3, 0]) && !three(Xor).in_result([2, 0]));
        assert!(three(Difference).in_result([1, 0]) && !three(Difference).in_result([1, 2]));
    }

    #[test]
    fn non_zero_fills_doubly_wound_regions() {
        let s = Selection::Pair {
            operation: Union,
            fill_rule: FillRule::NonZero,
        };
        assert!(s.in_result([2, 0]));
        let e = Selection::Pair {
            operation: Union,
            fill_rule: FillRule::EvenOdd,
        };
        assert!(!e.in_result([2, 0]));
    }
}
