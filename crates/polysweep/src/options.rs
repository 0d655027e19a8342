//! The options of an operation, and the switches of the optimisations that are not in the paper.

use crate::select::FillRule;

/// Options of an operation. Built from the defaults, so that options added later do not break callers:
///
/// ```
/// use polysweep::{FillRule, Options};
/// let options = Options::default().with_fill_rule(FillRule::NonZero);
/// assert_eq!(options.fill_rule, FillRule::NonZero);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Options {
    /// How each operand's rings define its interior (even-odd by default).
    pub fill_rule: FillRule,
    /// The optimisations not in the paper, all on by default (see [`Shortcuts`]).
    #[doc(hidden)]
    pub shortcuts: Shortcuts,
}

impl Options {
    /// These options with `fill_rule`.
    pub fn with_fill_rule(self, fill_rule: FillRule) -> Self {
        Options { fill_rule, ..self }
    }

    /// These options with only the paper's algorithm: every shortcut off. For tests, which must see the same
    /// results either way; slower.
    #[doc(hidden)]
    pub fn without_shortcuts(self) -> Self {
        Options {
            shortcuts: Shortcuts::NONE,
            ..self
        }
    }
}

/// The optimisations not in the paper, each behind one switch. Each is exact: with any of them off, an operation
/// computes the same exact result (see docs/architecture.md for the argument of each). Only the last bits of a
/// result rounded near a close call can depend on which polygons and events were swept (see `prune`).
#[doc(hidden)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shortcuts {
    /// Leave out polygons whose box meets no polygon's box of the other operand, where they cannot change the
    /// result (of either operand for an intersection, of the clipping operand for a difference).
    pub prune_by_boxes: bool,
    /// Leave out clipping polygons that lie wholly inside or outside the subject, known from the subject's winding
    /// number on a grid.
    pub prune_by_winding: bool,
    /// An intersection copies clipping polygons wholly inside the subject and apart from the others to its result
    /// (only those that `prune_by_winding` has found inside: off with it).
    pub copy_inside: bool,
    /// A union, a xor or a difference copies polygons apart from all others to its result (of the subject only,
    /// for a difference).
    pub copy_apart: bool,
    /// A union or a difference leaves out subject polygons inside one convex clipping polygon.
    pub prune_inside_convex: bool,
    /// The sweep stops past the last x where the result can have an edge.
    pub stop_early: bool,
    /// A lone proper crossing is one step: the two edges trade places in S.
    pub crossing_step: bool,
    /// An edge that goes on through a vertex takes the ending edge's node in S.
    pub successor_in_place: bool,
    /// A new edge is tried just above the edge inserted last before S is searched.
    pub insert_after_last: bool,
    /// Two neighbours in S that start at one point, on two lines, are not tested for meeting elsewhere.
    pub shared_start: bool,
    /// Identical edges (one segment in several rings, as the shared borders of a parcel map) become one edge
    /// carrying all their windings when the events are made, rather than when they meet in S (§7.2). Not while the
    /// structural reading watches the sweep, which must see edges of one operand meet.
    pub merge_identical_edges: bool,
    /// Each thread keeps its working memory from one operation to the next.
    pub keep_working_memory: bool,
    /// Under the structural reading, an operation is first swept under even-odd, watched, and its operands read by
    /// their structure only where the sweep finds that the two rules read them differently.
    pub watch_structure: bool,
}

impl Shortcuts {
    /// Every shortcut on: the default.
    pub const ALL: Shortcuts = Shortcuts {
        prune_by_boxes: true,
        prune_by_winding: true,
        copy_inside: true,
        copy_apart: true,
        prune_inside_convex: true,
        stop_early: true,
        crossing_step: true,
        successor_in_place: true,
        insert_after_last: true,
        shared_start: true,
        merge_identical_edges: true,
        keep_working_memory: true,
        watch_structure: true,
    };

    /// Every shortcut off: the paper's algorithm (with exact predicates and output rounding).
    pub const NONE: Shortcuts = Shortcuts {
        prune_by_boxes: false,
        prune_by_winding: false,
        copy_inside: false,
        copy_apart: false,
        prune_inside_convex: false,
        stop_early: false,
        crossing_step: false,
        successor_in_place: false,
        insert_after_last: false,
        shared_start: false,
        merge_identical_edges: false,
        keep_working_memory: false,
        watch_structure: false,
    };
}

impl Default for Shortcuts {
    fn default() -> Self {
        Shortcuts::ALL
    }
}
