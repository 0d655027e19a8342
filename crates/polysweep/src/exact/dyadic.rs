//! Exact dyadic arithmetic: the numbers `m · 2^e` that every f64 is, closed under sums, differences and products,
//! and the exact coordinates of a crossing as fractions of them. Used only where the float filters of
//! [`super::Exact`] cannot decide.

use super::point::Line;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// An exact dyadic number `m · 2^e`: every f64 is one, and sums, differences and products of them are too. No
/// division and so no gcd: this is what makes the exact path cheap.
#[derive(Clone, Debug)]
pub(super) struct Dyadic {
    pub(super) m: BigInt,
    pub(super) e: i64,
}

impl Dyadic {
    pub(super) fn from_f64(v: f64) -> Self {
        if v == 0.0 {
            return Dyadic {
                m: BigInt::zero(),
                e: 0,
            };
        }
        let bits = v.to_bits();
        let exponent = ((bits >> 52) & 0x7ff) as i64;
        let fraction = bits & ((1u64 << 52) - 1);
        // Normal numbers have the implicit leading bit; subnormals have exponent 1 - 1075.
        let (mantissa, e) = if exponent == 0 {
            (fraction, -1074)
        } else {
            (fraction | (1u64 << 52), exponent - 1075)
        };
        let m = BigInt::from(mantissa);
        Dyadic {
            m: if v < 0.0 { -m } else { m },
            e,
        }
    }

    pub(super) fn one() -> Self {
        Dyadic {
            m: BigInt::from(1),
            e: 0,
        }
    }

    pub(super) fn sign(&self) -> Ordering {
        self.m.sign().cmp(&num_bigint::Sign::NoSign)
    }

    /// The nearest f64 to `self / den` (`den` positive), and whether it is exactly `self / den`.
    pub(super) fn divide_to_f64(&self, den: &Dyadic) -> (f64, bool) {
        let (n, d) = (self.m.magnitude(), den.m.magnitude());
        if n.is_zero() {
            return (0.0, true);
        }
        // q = ⌊n · 2^s / d⌋ has 55 or 56 bits: the 53 of an f64 and two or three more to round by; r is the rest.
        let s = 55 + d.bits() as i64 - n.bits() as i64;
        let (q, r) = if s >= 0 {
            (n << s as usize).div_rem(d)
        } else {
            n.div_rem(&(d << (-s) as usize))
        };
        let q = q.to_u64().expect("a quotient of at most 56 bits");
        let extra = 64 - q.leading_zeros() - 53;
        let (mut mantissa, dropped, half) = (q >> extra, q & ((1 << extra) - 1), 1 << (extra - 1));
        let exact = dropped == 0 && r.is_zero();
        // Round to nearest, ties to even; a tie only if nothing is left in r.
        if dropped > half || (dropped == half && (!r.is_zero() || mantissa & 1 == 1)) {
            mantissa += 1;
        }
        // The value is mantissa · 2^exponent, with mantissa ≤ 2^53.
        let exponent = self.e - den.e - s + extra as i64;
        if !(-1022..=900).contains(&exponent) {
            return self.divide_to_f64_far_from_one(den);
        }
        let magnitude = mantissa as f64 * f64::from_bits(((exponent + 1023) as u64) << 52);
        (
            if self.m.is_negative() {
                -magnitude
            } else {
                magnitude
            },
            exact,
        )
    }

    /// [`Self::divide_to_f64`] where the scale is too large or small for its shortcut (no input within the accepted
    /// range of coordinates comes here).
    #[cold]
    pub(super) fn divide_to_f64_far_from_one(&self, den: &Dyadic) -> (f64, bool) {
        let ratio = BigRational::new_raw(self.m.clone(), den.m.clone())
            .to_f64()
            .unwrap_or(f64::NAN);
        let value = ratio * 2f64.powi((self.e - den.e) as i32);
        let exact = (&(&Dyadic::from_f64(value) * den) - self).sign() == Ordering::Equal;
        (value, exact)
    }
}

impl Add for &Dyadic {
    type Output = Dyadic;
    fn add(self, other: &Dyadic) -> Dyadic {
        let (hi, lo) = if self.e >= other.e {
            (self, other)
        } else {
            (other, self)
        };
        Dyadic {
            m: (&hi.m << (hi.e - lo.e) as usize) + &lo.m,
            e: lo.e,
        }
    }
}

impl Neg for &Dyadic {
    type Output = Dyadic;
    fn neg(self) -> Dyadic {
        Dyadic {
            m: -&self.m,
            e: self.e,
        }
    }
}

impl Sub for &Dyadic {
    type Output = Dyadic;
    fn sub(self, other: &Dyadic) -> Dyadic {
        self + &-other
    }
}

impl Mul for &Dyadic {
    type Output = Dyadic;
    fn mul(self, other: &Dyadic) -> Dyadic {
        Dyadic {
            m: &self.m * &other.m,
            e: self.e + other.e,
        }
    }
}

/// The exact coordinates of a crossing: `(x / den, y / den)` with `den > 0`.
#[derive(Clone, Debug)]
pub(super) struct Fraction {
    pub(super) x: Dyadic,
    pub(super) y: Dyadic,
    pub(super) den: Dyadic,
}

impl Fraction {
    /// The point where the lines of `l` and `m` cross (they are not parallel).
    pub(super) fn crossing(l: &Line, m: &Line) -> Self {
        let r = |v: [f64; 2]| [Dyadic::from_f64(v[0]), Dyadic::from_f64(v[1])];
        let ([a1x, a1y], [b1x, b1y], [a2x, a2y], [b2x, b2y]) = (r(l.a), r(l.b), r(m.a), r(m.b));
        let (d1x, d1y) = (&b1x - &a1x, &b1y - &a1y);
        let (d2x, d2y) = (&b2x - &a2x, &b2y - &a2y);
        // The crossing is a1 + d1 · t / den with t = (a2 - a1) × d2 and den = d1 × d2.
        let mut den = &(&d1x * &d2y) - &(&d1y * &d2x);
        let mut t = &(&(&a2x - &a1x) * &d2y) - &(&(&a2y - &a1y) * &d2x);
        debug_assert!(!den.m.is_zero(), "crossing of parallel lines");
        if den.m.is_negative() {
            (den, t) = (-&den, -&t);
        }
        Fraction {
            x: &(&a1x * &den) + &(&d1x * &t),
            y: &(&a1y * &den) + &(&d1y * &t),
            den,
        }
    }

    /// The nearest floats to the coordinates, and which of them are exact.
    pub(super) fn rounded(&self) -> ([f64; 2], [bool; 2]) {
        let ((x, x_exact), (y, y_exact)) = (
            self.x.divide_to_f64(&self.den),
            self.y.divide_to_f64(&self.den),
        );
        ([x, y], [x_exact, y_exact])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn division_rounds_to_nearest_like_the_rational_path() {
        // Quotients of products of floats, of every size the crossings make, against BigRational's rounding (a
        // different algorithm), including exact quotients and ties.
        let mut random = crate::test_random::bits(0x2545_f491_4f6c_dd1d);
        let float = |bits: u64, scale: i32| {
            let mantissa = (bits >> 11) as f64 / (1u64 << 53) as f64 + 0.5;
            let sign = if bits & 1 == 1 { -1.0 } else { 1.0 };
            sign * mantissa * 2f64.powi(scale)
        };
        for i in 0..20_000 {
            let (a, b) = (
                float(random(), (random() % 60) as i32 - 30),
                float(random(), (random() % 60) as i32 - 30).abs(),
            );
            // One float by another: IEEE division is correctly rounded too.
            let (quotient, exact) = Dyadic::from_f64(a).divide_to_f64(&Dyadic::from_f64(b));
            assert_eq!(quotient, a / b, "{a} / {b}");
            // q · b − a rounded once (fused) is zero exactly when q · b = a.
            assert_eq!(exact, quotient.mul_add(b, -a) == 0.0, "{a} / {b}");
            let mut num = Dyadic::from_f64(a);
            let mut den = Dyadic::from_f64(b);
            for _ in 0..i % 3 {
                num = &num * &Dyadic::from_f64(float(random(), (random() % 60) as i32 - 30));
                den = &den * &Dyadic::from_f64(float(random(), (random() % 60) as i32 - 30).abs());
            }
            if i % 7 == 0 {
                num = &den * &Dyadic::from_f64(a); // an exact quotient
                assert_eq!(num.divide_to_f64(&den), (a, true));
            }
            if i % 11 == 0 {
                // A tie: exactly halfway between `a` and the next float up.
                let mut half_ulp =
                    Dyadic::from_f64(f64::from_bits(a.abs().to_bits() + 1) - a.abs());
                half_ulp.e -= 1;
                let halfway = &Dyadic::from_f64(a.abs()) + &half_ulp;
                num = &halfway * &den;
                assert!(!num.divide_to_f64(&den).1);
            }
            assert_eq!(
                num.divide_to_f64(&den),
                num.divide_to_f64_far_from_one(&den),
                "case {i}"
            );
        }
    }
}
