//! The edges every stage passes on: the input edges the sweep reads (step 1 of Fig. 5) and the result edges it
//! writes for §5 to connect, and the ids that name events and nodes.

use crate::exact::Line;

/// An event, by its index in the sweep's events.
pub(crate) type EventId = u32;
/// "No event" / "no node".
pub(crate) const NONE: u32 = u32::MAX;

/// Subject or clipping operand (the paper's `pl`).
pub(crate) type Operand = u8;

/// An input edge (step 1 of Fig. 5), before it becomes its two events.
#[derive(Clone, Copy, Debug)]
pub(crate) struct InputEdge {
    /// Oriented in sweep order: `a` is the left endpoint.
    pub line: Line,
    pub operand: Operand,
    /// +1 when the ring runs from `a` to `b`, else -1 (see [`crate::events::SweepEvent::winding`]).
    pub winding: i32,
}

/// An edge of the result, oriented with the result on its left.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ResultEdge {
    pub from: u32,
    pub to: u32,
    /// The input segment it lies on, whose line (left to right) gives its direction.
    pub segment: u32,
    /// Travelled along the line (left to right), or against it.
    pub forward: bool,
    /// The closest non-vertical result edge below this one, as a left event (later: a result edge index).
    pub below: u32,
}
