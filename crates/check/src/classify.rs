//! Numeric classification of a point Φ into the section-4 taxonomy
//! ([`poly::RootClass`]).
//!
//! Two classifiers, for two kinds of evidence:
//!
//! * [`classify_pq`] decides a second-order method, χ(z) = z² − 2p·z + q,
//!   from the **signs** of a few polynomials in the parameters, each shifted
//!   so that the decision is a comparison with zero:
//!
//!   | value              | decides                                    |
//!   |--------------------|--------------------------------------------|
//!   | p² − q             | complex pair (< 0), double root (= 0), two real roots (> 0) |
//!   | q − 1              | \|z\| against 1 for a complex pair (\|z\|² = q) |
//!   | p, p − 1, p + 1    | where a double root z = p lies             |
//!   | χ(1) = 1 − 2p + q, χ(−1) = 1 + 2p + q | a real root against ±1  |
//!   | q + 1              | \|z\| against 1 when p = 0 (z = ±√−q)      |
//!
//!   The shifted polynomials are formed exactly (in `poly`'s rationals) and
//!   evaluated either exactly at the rational value of the `f64` Φ and then
//!   rounded (rounding keeps the sign, so the class is exact for that Φ), or
//!   by `f64` Horner with an error bound, falling back to the exact value when
//!   the bound does not settle the sign (see [`crate::sweep`]). No tolerance
//!   is needed: "on the unit circle" means `q − 1` is exactly zero at that Φ.
//!
//! * [`classify_roots`] decides any order from numeric roots and per-root
//!   tolerances (the agreement radii of [`crate::witness`]): a root is on the
//!   unit circle when ||z| − 1| ≤ tol, real when |Im z| ≤ tol, repeated when
//!   two roots lie within the sum of their tolerances, zero when |z| ≤ tol.
//!   The dominant roots are those within tolerance of the largest modulus;
//!   among them a complex pair decides before a negative real root, and a
//!   negative real root before a positive one (z² = q with q > 0 alternates
//!   with Ψ = π).

use std::cmp::Ordering;

use num_complex::Complex;
use poly::RootClass;

/// The sign table of second-order methods lives in `poly` (one table for the
/// exact analysis and the numeric classifiers).
pub use poly::advanced::stability::{classify_pq, PqSigns};

/// The class decided by numeric roots with per-root tolerances (see the
/// module docs). `tolerance[i]` belongs to `roots[i]`.
#[track_caller]
pub fn classify_roots(roots: &[Complex<f64>], tolerance: &[f64]) -> RootClass {
    use RootClass::*;
    assert_eq!(roots.len(), tolerance.len(), "one tolerance per root");
    if roots.is_empty() {
        return Deadbeat;
    }
    let tol_max = tolerance.iter().cloned().fold(0.0, f64::max);
    let rho = roots.iter().map(|z| z.norm()).fold(0.0, f64::max);
    if roots.iter().zip(tolerance).all(|(z, &t)| z.norm() <= t) {
        return Deadbeat;
    }
    let dominant: Vec<usize> =
        (0..roots.len()).filter(|&i| roots[i].norm() >= rho - (tolerance[i] + tol_max)).collect();
    let is_real = |i: usize| roots[i].im.abs() <= tolerance[i];
    // Preference among dominant roots: complex, then negative, then positive.
    let rank = |i: usize| {
        if !is_real(i) {
            0
        } else if roots[i].re < 0.0 {
            1
        } else {
            2
        }
    };
    let rep =
        *dominant.iter().min_by_key(|&&i| (rank(i), roots[i].im < 0.0)).expect("a dominant root");
    let z = roots[rep];
    let tol = tolerance[rep];
    let repeated =
        dominant.iter().any(|&j| j != rep && (roots[j] - z).norm() <= tolerance[j] + tol);
    let radius = z.norm();
    let on_circle = (radius - 1.0).abs() <= tol;
    if repeated && on_circle {
        return DoubleRootOnCircle;
    }
    let side = if on_circle {
        Ordering::Equal
    } else {
        radius.partial_cmp(&1.0).unwrap_or(Ordering::Greater)
    };
    let (below, at, above) = match rank(rep) {
        0 => (DampedOscillation, Harmonic, UnstableOscillation),
        1 => (AlternatingStable, Alternating, AlternatingUnstable),
        _ => (MonotonicStable, Constant, MonotonicUnstable),
    };
    match side {
        Ordering::Less => below,
        Ordering::Equal => at,
        Ordering::Greater => above,
    }
}

/// The angle of a root in [0, π]: Ψ of section 4 (`atan2(|Im z|, Re z)`).
pub fn psi_of(z: Complex<f64>) -> f64 {
    z.im.abs().atan2(z.re)
}

/// The dominant root: largest modulus, preferring Im ≥ 0, then the class
/// order of [`classify_roots`] (complex, negative, positive) among ties
/// within `tie` of each other.
pub fn dominant_root(roots: &[Complex<f64>], tie: f64) -> Option<Complex<f64>> {
    let rho = roots.iter().map(|z| z.norm()).fold(f64::NEG_INFINITY, f64::max);
    roots
        .iter()
        .filter(|z| z.norm() >= rho - tie)
        .min_by(|a, b| {
            let rank = |z: &Complex<f64>| {
                if z.im.abs() > tie {
                    0
                } else if z.re < 0.0 {
                    1
                } else {
                    2
                }
            };
            (rank(a), a.im < 0.0).cmp(&(rank(b), b.im < 0.0))
        })
        .copied()
}
