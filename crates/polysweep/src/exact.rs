//! Exact geometric predicates on the points of the sweep (see the [robustness page](crate::robustness)).
//!
//! A point of the sweep is either an input vertex (two f64, exact) or the crossing of the supporting lines of two
//! input segments, kept exactly as a pair of rationals. Every predicate the sweep asks — the order of two points
//! (§4's event order) and the side of a point with respect to an input segment's line (the status order of §3,
//! §7.1 and the intersection tests of Fig. 6) — is answered exactly: first by a floating-point filter with a proven
//! error bound, and only when the filter cannot decide, by rational arithmetic. Computed points are never rounded
//! for a decision; they are rounded to f64 only when the result rings are written out.
//!
//! Departure from the paper: the paper assumes real arithmetic (and Schneider and Eberly's float intersection
//! routine). Rounded intersection points are what make float implementations of this sweep fail, so they are
//! replaced by exact ones.

use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

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
}

const INPUT: u32 = u32::MAX;

/// A point of the sweep: an input vertex, or the exact crossing of two input segments' lines.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SweepPoint {
    /// The coordinates, exact for input vertices, correctly rounded for crossings.
    pub approx: [f64; 2],
    /// Index of the exact coordinates in [`Exact::crossings`], or `INPUT`.
    crossing: u32,
    /// Which coordinates of a crossing are exactly their approximation (e.g. x on a vertical input edge), so that
    /// comparisons of them need no exact arithmetic.
    representable: [bool; 2],
}

impl SweepPoint {
    pub fn input(p: [f64; 2]) -> Self {
        SweepPoint {
            approx: p,
            crossing: INPUT,
            representable: [true; 2],
        }
    }

    pub fn is_input(&self) -> bool {
        self.crossing == INPUT
    }
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

fn rational(v: f64) -> BigRational {
    BigRational::from_float(v).expect("coordinates are validated finite")
}

fn sign(v: &BigRational) -> Ordering {
    if v.is_zero() {
        Ordering::Equal
    } else if v.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

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
    crossings: Vec<[BigRational; 2]>,
}

impl Exact {
    fn exact(&self, p: &SweepPoint, axis: usize) -> BigRational {
        if p.representable[axis] {
            rational(p.approx[axis])
        } else {
            self.crossings[p.crossing as usize][axis].clone()
        }
    }

    fn error(p: &SweepPoint, axis: usize) -> f64 {
        if p.representable[axis] {
            0.0
        } else {
            rounding_error(p.approx[axis])
        }
    }

    /// Compares one coordinate of two points exactly.
    pub fn cmp_coordinate(&self, p: &SweepPoint, q: &SweepPoint, axis: usize) -> Ordering {
        let (u, v) = (p.approx[axis], q.approx[axis]);
        if p.representable[axis] && q.representable[axis] {
            return u.partial_cmp(&v).unwrap_or(Ordering::Equal); // -0 equals 0
        }
        let bound = 2.0 * (Self::error(p, axis) + Self::error(q, axis));
        filtered_sign(u - v, bound).unwrap_or_else(|| self.exact(p, axis).cmp(&self.exact(q, axis)))
    }

    /// The sweep order of points: left to right, and bottom to top at equal x (§4, §7.1).
    pub fn cmp_points(&self, p: &SweepPoint, q: &SweepPoint) -> Ordering {
        self.cmp_coordinate(p, q, 0)
            .then_with(|| self.cmp_coordinate(p, q, 1))
    }

    /// The side of `p` with respect to `line`: `Greater` if `p` is to the left of `a → b` (above a non-vertical
    /// line), `Less` if to the right (below), `Equal` if on the line.
    pub fn orient(&self, line: &Line, p: &SweepPoint) -> Ordering {
        if p.is_input() {
            let c = |v: [f64; 2]| robust::Coord { x: v[0], y: v[1] };
            let det = robust::orient2d(c(line.a), c(line.b), c(p.approx));
            return det.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
        }
        let (dx, dy) = (line.b[0] - line.a[0], line.b[1] - line.a[1]);
        let (px, py) = (p.approx[0] - line.a[0], p.approx[1] - line.a[1]);
        let (left, right) = (dx * py, dy * px);
        let bound = 2.0 * (dx.abs() * Self::error(p, 1) + dy.abs() * Self::error(p, 0))
            + (left.abs() + right.abs()) * FILTER_RELATIVE
            + FILTER_ABSOLUTE;
        filtered_sign(left - right, bound).unwrap_or_else(|| {
            let (ax, ay) = (rational(line.a[0]), rational(line.a[1]));
            let dx = rational(line.b[0]) - &ax;
            let dy = rational(line.b[1]) - &ay;
            sign(&(dx * (self.exact(p, 1) - ay) - dy * (self.exact(p, 0) - ax)))
        })
    }

    /// The sign of the cross product of the two lines' directions: `Greater` if `m` turns left from `l`.
    pub fn cross_directions(&self, l: &Line, m: &Line) -> Ordering {
        let (lx, ly) = (l.b[0] - l.a[0], l.b[1] - l.a[1]);
        let (mx, my) = (m.b[0] - m.a[0], m.b[1] - m.a[1]);
        let (left, right) = (lx * my, ly * mx);
        let bound = (left.abs() + right.abs()) * FILTER_RELATIVE + FILTER_ABSOLUTE;
        filtered_sign(left - right, bound).unwrap_or_else(|| {
            let d = |line: &Line, axis: usize| rational(line.b[axis]) - rational(line.a[axis]);
            sign(&(d(l, 0) * d(m, 1) - d(l, 1) * d(m, 0)))
        })
    }

    /// The point where the lines of `l` and `m` cross. The caller has established that they are not parallel.
    pub fn crossing(&mut self, l: &Line, m: &Line) -> SweepPoint {
        let r = |v: [f64; 2]| [rational(v[0]), rational(v[1])];
        let ([a1x, a1y], [b1x, b1y], [a2x, a2y], [b2x, b2y]) = (r(l.a), r(l.b), r(m.a), r(m.b));
        let (d1x, d1y) = (b1x - &a1x, b1y - &a1y);
        let (d2x, d2y) = (b2x - &a2x, b2y - &a2y);
        let denominator = &d1x * &d2y - &d1y * &d2x;
        debug_assert!(!denominator.is_zero(), "crossing of parallel lines");
        let t = ((&a2x - &a1x) * &d2y - (&a2y - &a1y) * &d2x) / denominator;
        let exact = [a1x + &t * d1x, a1y + t * d1y];
        let approx = [
            exact[0].to_f64().unwrap_or(f64::NAN),
            exact[1].to_f64().unwrap_or(f64::NAN),
        ];
        let representable = [0, 1].map(|axis| rational(approx[axis]) == exact[axis]);
        self.crossings.push(exact);
        SweepPoint {
            approx,
            crossing: (self.crossings.len() - 1) as u32,
            representable,
        }
    }

    /// How many crossing points were constructed.
    pub fn crossing_count(&self) -> usize {
        self.crossings.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_is_exact_and_predicates_see_it_on_both_lines() {
        let mut exact = Exact::default();
        // Lines whose crossing (1/3, 1/3) is not representable in binary floating point.
        let l = Line {
            a: [0.0, 0.0],
            b: [1.0, 1.0],
        };
        let m = Line {
            a: [0.0, 1.0],
            b: [0.5, 0.0],
        };
        let x = exact.crossing(&l, &m);
        assert_eq!(exact.orient(&l, &x), Ordering::Equal);
        assert_eq!(exact.orient(&m, &x), Ordering::Equal);
        let rounded = SweepPoint::input(x.approx);
        assert_ne!(
            exact.cmp_points(&x, &rounded),
            Ordering::Equal,
            "1/3 is not a float"
        );
        assert_eq!(x.approx, [1.0 / 3.0, 1.0 / 3.0]);
    }

    #[test]
    fn orientation_of_nearly_collinear_points_is_exact() {
        let exact = Exact::default();
        let line = Line {
            a: [0.5, 0.5],
            b: [12.0, 12.0],
        };
        // 0.5 + 2^-53 rounds to 0.5 but 0.5 + 2^-52 does not: just above the diagonal.
        let p = SweepPoint::input([24.0, 24.0 + 24.0 * f64::EPSILON]);
        assert_eq!(exact.orient(&line, &p), Ordering::Greater);
        assert_eq!(
            exact.orient(&line, &SweepPoint::input([24.0, 24.0])),
            Ordering::Equal
        );
    }

    #[test]
    fn direction_cross_product() {
        let exact = Exact::default();
        let east = Line {
            a: [0.0, 0.0],
            b: [1.0, 0.0],
        };
        let north = Line {
            a: [5.0, 5.0],
            b: [5.0, 9.0],
        };
        assert_eq!(exact.cross_directions(&east, &north), Ordering::Greater);
        assert_eq!(exact.cross_directions(&north, &east), Ordering::Less);
        assert_eq!(exact.cross_directions(&east, &east), Ordering::Equal);
    }
}
