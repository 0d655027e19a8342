//! The points of the sweep and the lines of the input segments.

/// The supporting line of an input segment, from its first endpoint in sweep order (`a`) to its last (`b`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Line {
    pub a: [f64; 2],
    pub b: [f64; 2],
}

impl Line {
    /// §7.1: a vertical edge's lower endpoint is its left endpoint, so its line points up.
    pub fn is_vertical(&self) -> bool {
        self.a[0] == self.b[0]
    }

    /// The line's direction `b - a`, and the cross product `(p - a) × (b - a)`: `p`'s offset from the line times
    /// the direction's length. In floats, for the tests of how near rounding brings a point to a line, which decide
    /// no predicate (the exact side of a line is [`super::Exact::orient`]).
    #[inline(always)]
    pub fn float_offset(&self, p: [f64; 2]) -> ([f64; 2], f64) {
        let (dx, dy) = (self.b[0] - self.a[0], self.b[1] - self.a[1]);
        ([dx, dy], (p[0] - self.a[0]) * dy - (p[1] - self.a[1]) * dx)
    }

    /// Is `p` within `distance` of the line, in floats (see [`Self::float_offset`]): |cross| / |d| ≤ `distance`,
    /// compared squared to avoid the square root.
    #[inline(always)]
    pub fn float_within(&self, p: [f64; 2], distance: f64) -> bool {
        let ([dx, dy], cross) = self.float_offset(p);
        cross * cross <= distance * distance * (dx * dx + dy * dy)
    }
}

/// A point of the sweep: an input vertex, or the exact crossing of two input segments' lines. A crossing whose
/// coordinates are both floats is made like an input vertex (see [`super::Exact::crossing`]): below, "input vertex"
/// means any point at a pair of floats.
///
/// Packed to 20 bytes (alignment 4), half of an event (see [`crate::events::SweepEvent`], the sweep's largest
/// array), where a 24-byte point would make it 48. Its fields are read by value, never by reference.
#[derive(Clone, Copy, Debug)]
#[repr(C, packed(4))]
pub(crate) struct SweepPoint {
    /// The coordinates, exact for input vertices, correctly rounded for crossings.
    pub approx: [f64; 2],
    /// The index of the exact coordinates in [`super::Exact`]'s crossings (`INPUT` for an input vertex) in the low bits,
    /// and a bit per axis (`EXACT_X`, `EXACT_Y`) telling whether that coordinate is exactly its approximation
    /// (always for an input vertex; for a crossing, e.g. x on a vertical input edge), so that comparisons of it
    /// need no exact arithmetic.
    tag: u32,
}

const EXACT_X: u32 = 1 << 30;
const EXACT_Y: u32 = 1 << 31;
/// The index bits of [`SweepPoint::tag`], and the index of every input vertex. Crossings are fewer: each one makes
/// four events at least, and events are numbered by `u32`.
pub(super) const INPUT: u32 = EXACT_X - 1;

impl SweepPoint {
    pub fn input(p: [f64; 2]) -> Self {
        SweepPoint {
            approx: p,
            tag: INPUT | EXACT_X | EXACT_Y,
        }
    }

    pub fn is_input(&self) -> bool {
        self.crossing() == INPUT
    }

    /// Was this point rounded: a crossing with a coordinate that is not exactly its approximation?
    pub fn is_rounded(&self) -> bool {
        self.tag & (EXACT_X | EXACT_Y) != EXACT_X | EXACT_Y
    }

    /// Is the coordinate on `axis` exactly `approx[axis]`?
    pub fn is_exact(&self, axis: usize) -> bool {
        self.tag & (EXACT_X << axis) != 0
    }

    /// Crossing number `index` (see [`super::Exact::crossing`]), at `approx`, its coordinates rounded, of which those
    /// marked in `exact` are exact.
    pub(super) fn crossing_at(approx: [f64; 2], index: u32, exact: [bool; 2]) -> Self {
        assert!(index < INPUT, "more crossings than events can name");
        let exact_bits = (u32::from(exact[0]) * EXACT_X) | (u32::from(exact[1]) * EXACT_Y);
        SweepPoint {
            approx,
            tag: index | exact_bits,
        }
    }

    /// The index of this point's exact coordinates among the crossings, or [`INPUT`].
    pub(super) fn crossing(&self) -> u32 {
        self.tag & INPUT
    }
}
