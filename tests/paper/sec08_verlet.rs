//! Section 8 (Verlet): y_i = 2y_(i−1) − y_(i−2) + T² a_(i−1) from False
//! Euler's substitution, the harmonic recursion and χ (the same as False
//! Euler's), initial velocity through y_(−1), and the operation count.

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec08.recursion", Confirmed),
    ("sec08.oscillator_recursion", Confirmed),
    ("sec08.charpoly", Confirmed),
    ("sec08.same_as_false_euler", Confirmed),
    ("sec08.secant_change_of_variables", Confirmed),
    ("sec08.initial_velocity", Refined),
    ("sec08.operations", Refined),
    ("sec08.bad_formulation", Refined),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// Verlet's recursion with a = −ω0² y reproduces False Euler's y samples
/// for any v0 when y_(−1) = y_0 − Φ v_0, in floating point (the exact runs
/// are in the claim); and χ is False Euler's.
#[test]
fn same_samples_as_false_euler() {
    assert_eq!(*derive("verlet").charpoly(), parse("z^2 - 2*(1 - Phi^2/2)*z + 1"));
    assert_eq!(derive("verlet").charpoly(), derive("false_euler").charpoly());
    for phi in [0.1, 0.8, 1.9] {
        for (v0, y0) in [(0.0, 1.0), (0.7, -0.2)] {
            let (mut v, mut y) = (v0, y0);
            let (mut prev, mut cur) = (y0 - phi * v0, y0);
            for n in 0..100 {
                (v, y) = pascal_step("false_euler", v, y, phi);
                let next = 2.0 * cur - prev + phi * phi * (-cur);
                (prev, cur) = (cur, next);
                assert!((cur - y).abs() <= 64.0 * f64::EPSILON * (n as f64 + 1.0), "Φ={phi} n={n}");
            }
        }
    }
}

/// The recursion by substitution: y_i = y + T·v_i, v_i = v + T·a, T·v = y1 − y2.
#[test]
fn recursion_by_substitution() {
    let (t, a, y1, y2): (f64, f64, f64, f64) = (0.3, -1.7, 0.4, 0.9);
    let v_prev = (y1 - y2) / t;
    let v_i = v_prev + t * a;
    let y_i = y1 + t * v_i;
    assert!((y_i - (2.0 * y1 - y2 + t * t * a)).abs() <= 8.0 * f64::EPSILON);
}

/// Operation counts: False Euler's v = v − Φy, y = y + Φv is 2 mul + 2 add;
/// Verlet's y = (2 − Φ²)y − y@1 needs one of each once 2 − Φ² is folded.
#[test]
fn operations() {
    let count = |name: &str| {
        let m = poly::builtin(name).unwrap();
        let mut mul = 0;
        let mut add = 0;
        for a in m.assigns() {
            let nontrivial = a
                .terms
                .iter()
                .filter(|(_, c)| {
                    c.as_constant().is_none_or(|k| k != poly::q(1, 1) && k != poly::q(-1, 1))
                })
                .count();
            mul += nontrivial;
            add += a.terms.len().saturating_sub(1);
        }
        (mul, add)
    };
    assert_eq!(count("false_euler"), (2, 2));
    assert_eq!(count("verlet"), (1, 1));
    assert!(claim("sec08.operations").derived.contains("Verlet: 1 mul + 1 add"));
}
