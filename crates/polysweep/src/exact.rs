//! Exact geometric predicates on the points of the sweep (see the [robustness page](crate::robustness)).
//!
//! A point of the sweep is either an input vertex (two f64, exact) or the crossing of the supporting lines of two
//! input segments, defined exactly by those two lines, with its correctly rounded f64 coordinates (proven by float
//! arithmetic where possible, see [`estimate`]) and, made on first need, its exact coordinates `(x, y) / d` in
//! dyadic big integers. Every predicate the sweep asks — the order of two points (§4's event order) and the side of
//! a point with respect to an input segment's line (the status order of §3, §7.1 and the intersection tests of
//! Fig. 6) — is answered exactly: first by a floating-point filter with a proven
//! error bound, and only when the filter cannot decide, by big-integer arithmetic. Computed points are never rounded
//! for a decision; they are rounded to f64 only when the result rings are written out.
//!
//! Departure from the paper: the paper assumes real arithmetic (and Schneider and Eberly's float intersection
//! routine). Rounded intersection points are what make float implementations of this sweep fail, so they are
//! replaced by exact ones.

use std::cell::OnceCell;
use std::cmp::Ordering;

mod dyadic;
mod estimate;
mod point;

use dyadic::{Dyadic, Fraction};
pub(crate) use point::{Line, SweepPoint};

/// A crossing point: the two lines it was made from, and its exact coordinates, made when first needed. Boxed, as
/// they seldom are (never on Table 1's data): a crossing is then 72 bytes instead of 192, and the lines, which
/// the predicates read, lie closer together.
#[derive(Clone, Debug)]
struct Crossing {
    lines: [Line; 2],
    exact: OnceCell<Box<Fraction>>,
}

/// Relative error bound of the float filters. The filtered expressions have at most four rounded operations in a
/// chain, each off by at most 2^-53 relative; 2^-50 covers them with room to spare. It cannot change a decision:
/// when the float value is within the bound of zero, the exact path decides.
const FILTER_RELATIVE: f64 = 1.0 / (1u64 << 50) as f64;
/// Absolute floor of every error bound: the smallest subnormal, so that an underflowed product never passes the
/// filter with a bound of zero.
const FILTER_ABSOLUTE: f64 = f64::from_bits(1);

/// Error bound of a correctly rounded coordinate: half an ulp, over-estimated as a full relative ulp.
fn rounding_error(v: f64) -> f64 {
    v.abs() * FILTER_RELATIVE / 4.0 + FILTER_ABSOLUTE
}

/// Shewchuk's error bound of the first stage of orient2d, (3 + 16ε)ε with ε = 2^-53, relative to the sum of the
/// magnitudes of the two products. It is a proven bound on the rounding error of the float determinant, not a
/// tolerance: a determinant beyond it has the sign of the exact one, and anything within it goes to the adaptive
/// exact predicate, so it cannot change a decision, only how fast it is made.
const ORIENT_FILTER: f64 = (3.0 + 16.0 * UNIT_ROUNDOFF) * UNIT_ROUNDOFF;

/// ε = 2^-53: a float operation's result is off by at most this much of itself (round to nearest). The unit of
/// every proven error bound here, not a tolerance.
const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

/// The sign of `value`, if it is farther from zero than `bound`.
fn filtered_sign(value: f64, bound: f64) -> Option<Ordering> {
    if value > bound {
        Some(Ordering::Greater)
    } else if value < -bound {
        Some(Ordering::Less)
    } else {
        None // also when a NaN or an overflow made the filter meaningless
    }
}

/// The exact coordinates of every crossing point made so far.
#[derive(Default)]
pub(crate) struct Exact {
    /// The crossings with a coordinate that is not a float, whose exact coordinates may be needed.
    crossings: Vec<Crossing>,
    /// Every crossing constructed, those at float points included.
    made: usize,
}

impl Exact {
    /// One coordinate of `p` as a fraction with a positive denominator.
    fn fraction(&self, p: &SweepPoint, axis: usize) -> (Dyadic, Dyadic) {
        if p.is_exact(axis) {
            (Dyadic::from_f64(p.approx[axis]), Dyadic::one())
        } else {
            let c = self.exact_crossing(p);
            (
                if axis == 0 { c.x.clone() } else { c.y.clone() },
                c.den.clone(),
            )
        }
    }

    /// The exact coordinates of crossing `p`, made on first use.
    fn exact_crossing(&self, p: &SweepPoint) -> &Fraction {
        let c = &self.crossings[p.crossing() as usize];
        c.exact
            .get_or_init(|| Box::new(Fraction::crossing(&c.lines[0], &c.lines[1])))
    }

    fn error(p: &SweepPoint, axis: usize) -> f64 {
        if p.is_exact(axis) {
            0.0
        } else {
            rounding_error(p.approx[axis])
        }
    }

    /// Compares one coordinate of two points exactly.
    ///
    /// Every constructed coordinate is its exact value rounded to nearest (see [`estimate`] and
    /// `Dyadic::divide_to_f64`; the cold path beyond the input range may round a subnormal twice, which is still
    /// monotone). Rounding that is monotone and leaves floats as they are orders the exact values as it orders the
    /// floats, wherever the floats differ; equal floats stand for equal values when both are exact. Only equal
    /// floats of which one at least is rounded need the exact coordinates.
    #[inline]
    pub fn cmp_coordinate(&self, p: &SweepPoint, q: &SweepPoint, axis: usize) -> Ordering {
        let (u, v) = (p.approx[axis], q.approx[axis]);
        if u != v || (p.is_exact(axis) && q.is_exact(axis)) {
            // Worked out as a value rather than by branches, which the callers' own tests of it would follow and
            // no predictor can guess. -0 equals 0.
            return match i8::from(u > v) - i8::from(u < v) {
                -1 => Ordering::Less,
                0 => Ordering::Equal,
                _ => Ordering::Greater,
            };
        }
        self.cmp_coordinate_of_crossing(p, q, axis)
    }

    /// [`Self::cmp_coordinate`] of two points whose coordinate rounds to one float, one of them at least a
    /// crossing's rounded coordinate.
    #[inline(never)]
    fn cmp_coordinate_of_crossing(&self, p: &SweepPoint, q: &SweepPoint, axis: usize) -> Ordering {
        if p.crossing() == q.crossing() {
            return Ordering::Equal; // the events of one crossing (`INPUT` points are representable)
        }
        let ((pn, pd), (qn, qd)) = (self.fraction(p, axis), self.fraction(q, axis));
        (&(&pn * &qd) - &(&qn * &pd)).sign()
    }

    /// The sweep order of points: left to right, and bottom to top at equal x (§4, §7.1).
    pub fn cmp_points(&self, p: &SweepPoint, q: &SweepPoint) -> Ordering {
        self.cmp_coordinate(p, q, 0)
            .then_with(|| self.cmp_coordinate(p, q, 1))
    }

    /// The side of `p` with respect to `line`: `Greater` if `p` is to the left of `a → b` (above a non-vertical
    /// line), `Less` if to the right (below), `Equal` if on the line.
    #[inline]
    pub fn orient(&self, line: &Line, p: &SweepPoint) -> Ordering {
        if !p.is_input() {
            return self.orient_crossing(line, p);
        }
        // Shewchuk's first filter, inline because it almost always decides; his adaptive predicate when it cannot.
        let [ax, ay, bx, by, px, py] = [
            line.a[0],
            line.a[1],
            line.b[0],
            line.b[1],
            p.approx[0],
            p.approx[1],
        ];
        let (left, right) = ((ax - px) * (by - py), (ay - py) * (bx - px));
        let bound = ORIENT_FILTER * (left.abs() + right.abs());
        let det = left - right;
        // One test whether the filter decides (it almost always does), and the sign as a value rather than a second
        // branch: which side a point lies is what a search of S asks at every level, and no predictor can guess it.
        if det.abs() > bound {
            if det > 0.0 {
                Ordering::Greater
            } else {
                Ordering::Less
            }
        } else if (ax == px || by == py) && (ay == py || bx == px) {
            // Both products have a factor that is exactly 0: `p` is exactly on the line (a grid's lines, edges
            // meeting at a vertex), the filter's commonest failure, decided without the adaptive predicate.
            Ordering::Equal
        } else {
            Self::orient_adaptive(line, p.approx)
        }
    }

    #[inline(never)]
    fn orient_adaptive(line: &Line, p: [f64; 2]) -> Ordering {
        let c = |v: [f64; 2]| robust::Coord { x: v[0], y: v[1] };
        let det = robust::orient2d(c(line.a), c(line.b), c(p));
        det.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    }

    #[inline(never)]
    fn orient_crossing(&self, line: &Line, p: &SweepPoint) -> Ordering {
        let c = &self.crossings[p.crossing() as usize];
        if c.lines.contains(line) {
            // The commonest question about a crossing, and one no filter can answer: it is exactly zero.
            return Ordering::Equal;
        }
        // Against an axis-parallel line (grids, boxes, other crossings' lines) the side is one coordinate compared.
        let a = SweepPoint::input(line.a);
        if line.a[1] == line.b[1] {
            let above = self.cmp_coordinate(p, &a, 1);
            return if line.a[0] < line.b[0] {
                above
            } else {
                above.reverse()
            };
        }
        if line.a[0] == line.b[0] {
            let left = self.cmp_coordinate(&a, p, 0);
            return if line.a[1] < line.b[1] {
                left
            } else {
                left.reverse()
            };
        }
        let (dx, dy) = (line.b[0] - line.a[0], line.b[1] - line.a[1]);
        let (px, py) = (p.approx[0] - line.a[0], p.approx[1] - line.a[1]);
        let (left, right) = (dx * py, dy * px);
        let bound = 2.0 * (dx.abs() * Self::error(p, 1) + dy.abs() * Self::error(p, 0))
            + (left.abs() + right.abs()) * FILTER_RELATIVE
            + FILTER_ABSOLUTE;
        filtered_sign(left - right, bound).unwrap_or_else(|| {
            // (b - a) × (p - a), multiplied through by p's positive denominator.
            let [ax, ay, bx, by] =
                [line.a[0], line.a[1], line.b[0], line.b[1]].map(Dyadic::from_f64);
            let (dx, dy) = (&bx - &ax, &by - &ay);
            let c = self.exact_crossing(p);
            let (px, py) = (&c.x - &(&ax * &c.den), &c.y - &(&ay * &c.den));
            (&(&dx * &py) - &(&dy * &px)).sign()
        })
    }

    /// The sign of the cross product of the two lines' directions: `Greater` if `m` turns left from `l`.
    pub fn cross_directions(&self, l: &Line, m: &Line) -> Ordering {
        let (lx, ly) = (l.b[0] - l.a[0], l.b[1] - l.a[1]);
        let (mx, my) = (m.b[0] - m.a[0], m.b[1] - m.a[1]);
        let (left, right) = (lx * my, ly * mx);
        let bound = (left.abs() + right.abs()) * FILTER_RELATIVE + FILTER_ABSOLUTE;
        filtered_sign(left - right, bound).unwrap_or_else(|| {
            let d = |line: &Line, axis: usize| {
                &Dyadic::from_f64(line.b[axis]) - &Dyadic::from_f64(line.a[axis])
            };
            (&(&d(l, 0) * &d(m, 1)) - &(&d(l, 1) * &d(m, 0))).sign()
        })
    }

    /// The side of the point ((x0 + x1) / 2, (y0 + y1) / 2) with respect to `line`, as [`Self::orient`] gives it:
    /// for the corners of a float's rounding cell, which lie halfway between floats (see [`crate::snap_round`]).
    /// Exact, without a filter: it is asked only where a result is snap-rounded.
    pub fn orient_midpoint(&self, line: &Line, x: [f64; 2], y: [f64; 2]) -> Ordering {
        let d = |v: f64| Dyadic::from_f64(v);
        let [ax, ay] = line.a.map(d);
        let (dx, dy) = (&d(line.b[0]) - &ax, &d(line.b[1]) - &ay);
        // Twice the point's offset from `a`, so that the midpoint needs no division.
        let twice = |[u, v]: [f64; 2], a: &Dyadic| &(&d(u) + &d(v)) - &(a + a);
        (&(&dx * &twice(y, &ay)) - &(&dy * &twice(x, &ax))).sign()
    }

    /// The point where the lines of `l` and `m` cross. The caller has established that they are not parallel.
    /// Its coordinates are rounded by float arithmetic where that is proven right (see [`estimate`]), else from
    /// the exact ones, which are then kept.
    pub fn crossing(&mut self, l: &Line, m: &Line) -> SweepPoint {
        self.made += 1;
        let exact = OnceCell::new();
        let (approx, representable) = estimate::rounded_crossing(l, m).unwrap_or_else(|| {
            let fraction = exact.get_or_init(|| Box::new(Fraction::crossing(l, m)));
            fraction.rounded()
        });
        if representable == [true; 2] {
            // Exactly a pair of floats (grids, axis-parallel edges): a point like an input vertex, which no
            // predicate needs the lines for, so no record is kept (72 bytes a crossing on dense grids).
            return SweepPoint::input(approx);
        }
        self.crossings.push(Crossing {
            lines: [*l, *m],
            exact,
        });
        let index = (self.crossings.len() - 1) as u32;
        SweepPoint::crossing_at(approx, index, representable)
    }

    /// Room for `more` crossings without allocating (see [`crate::workspace::room`]).
    pub fn room(&mut self, more: usize) -> bool {
        crate::workspace::room(&mut self.crossings, more)
    }

    /// How many crossing points were constructed.
    pub fn crossing_count(&self) -> usize {
        self.made
    }
}

#[cfg(test)]
mod tests;
