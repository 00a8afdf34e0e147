//! Frequency claims shared by sections 6, 7, 9 and 11: "the frequency is
//! always too high", the Taylor approximations of Ψ(Φ) and the table of
//! section 6.
//!
//! The series come from `poly::advanced::series` (exact arithmetic on the roots of χ);
//! the comparisons Ψ > Φ over a range are numeric (Ψ is transcendental in Φ),
//! with the exact argument quoted where one exists.

use std::f64::consts::PI;

use poly::{Poly, Sym, Q};

use super::common::*;
use super::exact::{p_q, paper};
use crate::load::builtin_derivation;
use crate::paper::finding::{Finding, Scope};

/// Ψ(Φ)'s Taylor coefficients of Φ^0..=Φ^order.
#[track_caller]
pub(crate) fn psi_coeffs(method: &str, order: usize) -> Vec<Q> {
    let d = builtin_derivation(method);
    poly::advanced::series::psi_series(d.charpoly(), order)
        .unwrap_or_else(|e| panic!("Ψ series of {method}: {e}"))
}

/// A coefficient list as a polynomial in Φ.
pub(crate) fn series_poly(c: &[Q]) -> Poly {
    let terms: Vec<Poly> = c.iter().map(|x| Poly::constant(x.clone())).collect();
    Poly::from_coeffs_in(Sym::phi(), &terms)
}

/// The largest Φ (at most `cap`) up to which a method's roots stay a
/// complex pair, in floating point; `cap` when they never stop.
fn oscillating_until(method: &str, cap: f64) -> f64 {
    let psi = PsiF64::new(&builtin_derivation(method));
    let n = 4000;
    let mut last = 0.0;
    for k in 1..=n {
        let phi = cap * k as f64 / n as f64;
        if psi.at(phi).is_none() {
            return last;
        }
        last = phi;
    }
    cap
}

/// The first Φ in (0, hi] where Ψ(Φ) − Φ changes sign, by a grid and
/// bisection; `None` when Ψ > Φ on the whole grid.
pub(crate) fn first_crossing(method: &str, hi: f64) -> Option<f64> {
    let psi = PsiF64::new(&builtin_derivation(method));
    let f = |phi: f64| psi.at(phi).map(|psi| psi - phi);
    let n = 4000;
    let mut prev = hi / n as f64;
    for k in 2..=n {
        let phi = hi * k as f64 / n as f64;
        match f(phi) {
            Some(v) if v > 0.0 => prev = phi,
            Some(_) => {
                let (mut a, mut b) = (prev, phi);
                for _ in 0..60 {
                    let m = 0.5 * (a + b);
                    if f(m).is_some_and(|v| v > 0.0) {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                return Some(0.5 * (a + b));
            }
            None => return None,
        }
    }
    None
}

/// "The frequency is always too high": Ψ > Φ wherever the samples oscillate.
pub(crate) fn too_high(s: &mut Section, method: &str, statement: &str) {
    let c = psi_coeffs(method, 3);
    let hi = oscillating_until(method, 2.0 * PI);
    let crossing = first_crossing(method, hi);
    let q_is_one = p_q(&builtin_derivation(method)).1.is_one();
    let near_zero = format!("near Φ = 0, Ψ − Φ = {}·Φ³ + O(Φ⁵) > 0", c[3]);
    // Section 6 states the range of the frequency approximations, Φ < 1;
    // "always too high" is read off those approximations.
    let finding = Finding::scoped([
        (
            "0 < Φ < 1, the range section 6 gives the approximations".to_owned(),
            crossing.is_none_or(|x| x >= 1.0),
            Scope::Stated,
        ),
        (
            format!("1 ≤ Φ < {}, the rest of the oscillating range", fixed(hi, 3)),
            crossing.is_none(),
            Scope::wording(
                "the paper derives \"too high\" from its approximations, which section 6 gives for \
                 Φ < 1; beyond, only \"always\" reaches",
            ),
        ),
    ]);
    let (derived, evidence) = match crossing {
        None => (
            format!("Ψ > Φ for every Φ at which the samples oscillate (0 < Φ < {})", fixed(hi, 3)),
            if q_is_one {
                format!(
                    "q = 1, so cos Ψ = p = 1 − Φ²/2, i.e. sin(Ψ/2) = Φ/2 and Ψ = 2·arcsin(Φ/2) > Φ \
                     because sin x < x for x > 0; {near_zero}; checked on 4000 grid points"
                )
            } else {
                format!("{near_zero}; Ψ − Φ > 0 on 4000 grid points of the oscillating range")
            },
        ),
        Some(x) => (
            format!(
                "Ψ > Φ only for 0 < Φ < {}; beyond, Ψ < Φ (Ψ < π while Φ grows without bound)",
                fixed(x, 4)
            ),
            format!(
                "{near_zero}; Ψ(Φ) = atan2(sqrt(q − p²), p) − Φ changes sign at Φ ≈ {} (grid of 4000 \
                 points on (0, {}] and bisection; the crossing is transcendental). At Φ = π, Ψ < π = Φ",
                fixed(x, 6),
                fixed(hi, 3)
            ),
        ),
    };
    s.push("frequency_too_high", statement, derived, finding, evidence);
}

/// A printed Taylor approximation of Ψ against the exact series.
pub(crate) fn approximation(s: &mut Section, method: &str, statement: &str, parse: &str) {
    let exact = psi_coeffs(method, 5);
    let printed = paper(parse);
    let through_3 = series_poly(&exact[..4]);
    let ok = printed == through_3;
    s.push(
        "psi_approx",
        statement,
        format!("Ψ = {} + O(Φ⁷)", series_poly(&exact)),
        Finding::same(&printed, &through_3),
        format!(
            "Derivation::psi_series({method}) by exact series arithmetic on cos Ψ = p/√q; the printed \
             approximation {} the series through Φ³",
            if ok { "equals" } else { "differs from" }
        ),
    );
}

/// "The approximation is valid for Φ < 1 or more than 2π samples per period."
pub(crate) fn validity(s: &mut Section, method: &str, approx: &str) {
    let d = builtin_derivation(method);
    let a = paper(approx);
    let at = |phi: f64| {
        let psi = psi_f64(&d, phi).expect("oscillating at Φ ≤ 1");
        ((eval_f64(&a, phi) - psi) / psi).abs()
    };
    let samples_at_one = 2.0 * PI / 1.0;
    // The largest relative error on (0, 1): the error grows like Φ⁴.
    let worst = (1..=100).map(|k| at(k as f64 / 100.0)).fold(0.0, f64::max);
    s.push(
        "approx_validity",
        "The approximation is valid for Φ < 1 or more than 2π samples per period.",
        format!(
            "Φ < 1 ⟺ T0/T = 2π/Φ > 2π ({} samples at Φ = 1); relative error of the approximation {}% at \
             Φ = 1, {}% at Φ = 0.5",
            fixed(samples_at_one, 3),
            fixed(100.0 * at(1.0), 2),
            fixed(100.0 * at(0.5), 3)
        ),
        Finding::all([
            (
                format!("Φ < 1 means more than 2π samples per period ({} at Φ = 1)", fixed(samples_at_one, 3)),
                (samples_at_one - 2.0 * PI).abs() <= 4.0 * f64::EPSILON,
            ),
            (
                format!("the relative error stays below 1% on 0 < Φ ≤ 1 (at most {}%)", fixed(100.0 * worst, 2)),
                worst < 0.01,
            ),
        ]),
        "T0/T = 2π/(ω0·T) = 2π/Φ exactly; the error is the neglected Φ⁵ term of the exact series, \
         evaluated against Ψ = atan2(sqrt(q − p²), p) on 100 points of (0, 1]; zcheck reads \"valid\" as \
         a relative error of Ψ below 1%",
    );
}

/// The table of section 6: true and approximate Ψ at given Φ, to 3 decimals.
pub(crate) fn table(
    s: &mut Section,
    method: &str,
    approx: &str,
    rows: &[(&str, &str, f64, &str, &str)],
) {
    let d = builtin_derivation(method);
    let a = paper(approx);
    for &(key, statement, phi, true_printed, approx_printed) in rows {
        let psi = psi_f64(&d, phi).expect("oscillating");
        let (t, ap) = (fixed(psi, 3), fixed(eval_f64(&a, phi), 3));
        s.push(
            key,
            statement,
            format!("Φ = {phi}: true Ψ = {t}, approximation Ψ = {ap}"),
            Finding::same(format!("{true_printed}, {approx_printed}"), format!("{t}, {ap}")),
            format!(
                "true Ψ = atan2(sqrt(q − p²), p) of {method} at Φ = {phi}, approximation evaluated at the \
                 same Φ, both rounded to 3 decimals{}",
                if (phi - 2f64.sqrt()).abs() < 1e-3 {
                    format!(
                        "; at Φ = √2 exactly Ψ = π/2 = {} (cos Ψ = 1 − Φ²/2 = 0), so the printed 1.570 belongs \
                         to the rounded Φ = 1.414",
                        fixed(PI / 2.0, 3)
                    )
                } else {
                    String::new()
                }
            ),
        );
    }
}
