//! A crossing point correctly rounded to f64 by float arithmetic alone, where that can be proven, so that most
//! crossings need no big integers (their exact coordinates are made later only if a predicate asks for them).
//!
//! The lines `a1 + d1·λ` and `a2 + d2·μ` cross at λ = t / den, with den = d1 × d2 and t = (a2 − a1) × d2. All of it
//! is evaluated in double-double arithmetic (pairs of floats whose sum carries about 106 bits: Knuth's exact sum
//! and Dekker's exact product; no fused multiply-add, which wasm lacks), with a bound on the error of every step,
//! proven by the usual analysis (each float operation is off by at most 2^-53 of its result) and then taken with a
//! wide margin. The exact coordinate therefore lies within a known distance of the estimate, and when no rounding
//! boundary (the midpoint between two floats) lies within that distance, the nearest float to the estimate is the
//! nearest float to the exact coordinate. Otherwise the caller rounds the exact value instead: for nearly parallel
//! lines, a coordinate within about 2^-90 of its size from a midpoint, and an estimate that is exactly a float (the
//! exact value may then be that float, which only the exact path can tell; knowing it lets later comparisons of
//! the coordinate skip exact arithmetic, as on grids of integers).
//!
//! Each coordinate is taken along whichever line bounds its error more tightly, and straight from an
//! axis-parallel line, where it is exact.
//!
//! The constants below are the terms of proven error bounds, not tolerances: they cannot change a result, only
//! whether the float estimate is used or the exact path decides (which always gives the same rounding).

use super::{Line, UNIT_ROUNDOFF as EPSILON};

/// The bounds below are computed in floats too; inflating them by this factor covers that rounding many times over.
const BOUND_MARGIN: f64 = 1.0 + 1.0 / (1u64 << 20) as f64;

/// An absolute floor on every error bound, far above what an underflow in any step could add (inputs are at least
/// 2^-200 in magnitude, so this only matters for crossings within about 2^-960 of an axis, which are left to the
/// exact path).
const UNDERFLOW_FLOOR: f64 = 1e-290;

/// A double-double: the unevaluated sum of two floats.
type Double = (f64, f64);

/// The correctly rounded coordinates of the crossing of the lines of `l` and `m` (not parallel), and which of them
/// are known to be exact; `None` when float arithmetic cannot prove the rounding.
pub(super) fn rounded_crossing(l: &Line, m: &Line) -> Option<([f64; 2], [bool; 2])> {
    // A coordinate is exact where one of the lines is parallel to the other axis: it is that line's. (Made as
    // whole values, not stored into arrays by halves, which stalls reading the arrays back whole.)
    let fixed = [0, 1].map(|axis| {
        let parallel = [l, m].into_iter().find(|line| line.a[axis] == line.b[axis]);
        parallel.map(|line| line.a[axis] + 0.0) // -0 as 0, as the exact path gives
    });
    if let [Some(x), Some(y)] = fixed {
        // A vertical line crossing a horizontal one, as on grids: no parameter to estimate.
        return Some(([x, y], [true, true]));
    }
    let along = parameters(l, m)?;
    let coordinate = |axis: usize| {
        if let Some(v) = fixed[axis] {
            return Some(v);
        }
        // λ's error shows in the coordinate multiplied by the line's extent along the axis.
        let spread = |i: usize| {
            let line = [l, m][i];
            (line.b[axis] - line.a[axis]).abs() * along[i].1
        };
        let base = if spread(0) <= spread(1) { 0 } else { 1 };
        let line = [l, m][base];
        rounded(line.a[axis], line.b[axis], along[base])
    };
    Some(([coordinate(0)?, coordinate(1)?], fixed.map(|v| v.is_some())))
}

/// The parameters of the crossing along `l` (`l.a + (l.b − l.a)·λ`) and along `m`, each with a bound on its
/// error; `None` when the lines are too close to parallel for a float determinant to be trusted.
fn parameters(l: &Line, m: &Line) -> Option<[(Double, f64); 2]> {
    // Differences of floats, exactly.
    let vector = |from: [f64; 2], to: [f64; 2]| [0, 1].map(|axis| two_sum(to[axis], -from[axis]));
    let (dl, dm) = (vector(l.a, l.b), vector(m.a, m.b));
    let (den, den_error) = determinant(dl, dm);
    // λ = (m.a − l.a) × dm / (dl × dm); μ = (l.a − m.a) × dl / (dm × dl), whose denominator is −den.
    let (t_l, t_l_error) = determinant(vector(l.a, m.a), dm);
    let (t_m, t_m_error) = determinant(vector(m.a, l.a), dl);
    // (Written so that a NaN also gives `None`.)
    let trusted = den_error < den.0.abs() / 4.0;
    let parameter = |t: Double, t_error: f64, den: Double| {
        let lambda = quotient(t, den);
        // |t/den − t'/den'| ≤ (|den'|·Δt + |t'|·Δden) / (|den'|·(|den'| − Δden)) ≤ 2 (Δt + |λ|·Δden) / |den'| here,
        // plus the quotient's own error.
        let error = 2.0 * (t_error + lambda.0.abs() * den_error) / den.0.abs()
            + 64.0 * EPSILON * EPSILON * lambda.0.abs();
        (lambda, error * BOUND_MARGIN)
    };
    trusted.then(|| {
        [
            parameter(t_l, t_l_error, den),
            parameter(t_m, t_m_error, (-den.0, -den.1)),
        ]
    })
}

/// The cross product `u × v` of two vectors whose coordinates are exact double-doubles, and a bound on its error.
fn determinant(u: [Double; 2], v: [Double; 2]) -> (Double, f64) {
    let (p, p_low) = two_product(u[0].0, v[1].0);
    let (q, q_low) = two_product(u[1].0, v[0].0);
    let (s, s_low) = two_sum(p, -q);
    // The products of a high part by a low part, each at most 2^-53 of p or q (those of two low parts, smaller by
    // another 2^-53, are left out).
    let cross = [
        u[0].0 * v[1].1,
        u[0].1 * v[1].0,
        -(u[1].0 * v[0].1),
        -(u[1].1 * v[0].0),
    ];
    let low = s_low + (p_low - q_low) + (cross[0] + cross[1]) + (cross[2] + cross[3]);
    // Six additions into `low`, each off by at most ε of a partial sum (all within the sum of the terms' sizes),
    // every term at most ε of the products' size: about 40 ε² of it in all, here 128 ε².
    let error = 128.0 * EPSILON * EPSILON * (p.abs() + q.abs()) + UNDERFLOW_FLOOR;
    (two_sum(s, low), error)
}

/// `t / n` as a double-double, within 64 ε² of its size (one Newton step on the float quotient).
fn quotient(t: Double, n: Double) -> Double {
    let q = t.0 / n.0;
    let (p, p_low) = two_product(q, n.0);
    // t − q·n: `t.0 − p` is exact (p is within two ulps of t.0), the rest is of order ε·t.
    let residual = ((t.0 - p) - p_low + t.1) - q * n.1;
    two_sum(q, residual / n.0)
}

/// The nearest float to `a + (b − a)·λ` for the exact λ, known to lie within `error` of the double-double
/// `lambda`; `None` when that cannot be proven.
fn rounded(a: f64, b: f64, (lambda, error): (Double, f64)) -> Option<f64> {
    let (d, d_low) = two_sum(b, -a); // b − a exactly
    let (p, p_low) = two_product(d, lambda.0);
    let cross = [d * lambda.1, d_low * lambda.0]; // and d_low · lambda.1, smaller by ε², left out
    let (s, s_low) = two_sum(a, p);
    let low = ((s_low + p_low) + cross[0]) + cross[1];
    // The estimate is s + low; r is its nearest float, and e = s + low − r exactly.
    let (r, e) = two_sum(s, low);
    // λ's error carried by |b − a|; the product left out (at most ε²|p|, doubled); the rounding of the two cross
    // products and of the three additions into `low` (3ε of the terms at most, taken as 4ε).
    let error = (d.abs() + d_low.abs()) * error
        + 2.0 * EPSILON * EPSILON * p.abs()
        + 4.0 * EPSILON * (s_low.abs() + p_low.abs() + cross[0].abs() + cross[1].abs())
        + UNDERFLOW_FLOOR;
    let magnitude = r.abs();
    if !(magnitude.is_normal() && magnitude > UNDERFLOW_FLOOR) {
        return None;
    }
    // The midpoints to the floats on either side; the closer one bounds how far the exact value may be.
    let bits = magnitude.to_bits();
    let half_gap =
        (f64::from_bits(bits + 1) - magnitude).min(magnitude - f64::from_bits(bits - 1)) / 2.0;
    // An estimate that is exactly a float is left to the exact path, which tells whether the coordinate is that float.
    (e != 0.0 && e.abs() + error * BOUND_MARGIN < half_gap).then_some(r)
}

/// `s + e = a + b` exactly (Knuth).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let b_virtual = s - a;
    let a_virtual = s - b_virtual;
    (s, (a - a_virtual) + (b - b_virtual))
}

/// `p + e = a · b` exactly, barring underflow (Dekker, with Veltkamp's split; no fused multiply-add, which wasm
/// lacks).
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let split = |v: f64| {
        let c = 134_217_729.0 * v; // 2^27 + 1
        let high = c - (c - v);
        (high, v - high)
    };
    let p = a * b;
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_sum_and_product() {
        let (s, e) = two_sum(1.0, 1e-20);
        assert_eq!((s, e), (1.0, 1e-20));
        let a = 1.0 + f64::EPSILON;
        let (p, e) = two_product(a, a); // (1 + 2^-52)^2 = 1 + 2^-51 + 2^-104
        assert_eq!(
            (p, e),
            (1.0 + 2.0 * f64::EPSILON, f64::EPSILON * f64::EPSILON)
        );
    }

    #[test]
    fn a_coordinate_on_a_midpoint_or_on_a_float_is_left_to_the_exact_path() {
        // 1 + 2^-53 is halfway between 1 and the next float: no estimate may round it.
        assert_eq!(rounded(1.0, 1.0 + f64::EPSILON, ((0.5, 0.0), 0.0)), None);
        // An eighth of the way is clear of every midpoint: it rounds to 1.
        assert_eq!(
            rounded(1.0, 1.0 + f64::EPSILON, ((0.125, 0.0), 0.0)),
            Some(1.0)
        );
        // Exactly a float: only the exact path can say the coordinate is exact, so it is left to it.
        assert_eq!(rounded(1.0, 3.0, ((0.5, 0.0), 0.0)), None);
    }
}
