//! Section 5 (Standard Euler): the update v = v − Φy, y = y + Φv with old
//! values, its z-domain rows, χ = z² − 2z + (1 + Φ²), the eigenvalues
//! 1 ± jΦ, r² = 1 + Φ², and "always an unstable oscillation".

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec05.ode", Confirmed),
    ("sec05.update", Confirmed),
    ("sec05.z_rows", Confirmed),
    ("sec05.charpoly", Confirmed),
    ("sec05.eigenvalues", Confirmed),
    ("sec05.r_squared", Confirmed),
    ("sec05.always_unstable", Confirmed),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// The printed rows and χ are what Appendix B's program computes.
#[test]
fn rows_and_charpoly() {
    assert_eq!(z_rows_match("standard_euler", [["1", "-Phi"], ["Phi", "1"]]), [[true; 2]; 2]);
    check_charpoly("standard_euler", "z^2 - 2*z + (1 + Phi^2)");
}

#[test]
fn eigenvalues_and_modulus() {
    check_eigenvalues("standard_euler", "1", "Phi^2");
    check_r_squared("standard_euler", "1 + Phi^2");
}

/// Unstable oscillation at every Φ: complex roots with |z| > 1; numerically
/// the amplitude grows and y changes sign.
#[test]
fn always_an_unstable_oscillation() {
    for phi in [1e-3, 0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3] {
        let [z, _] = roots_at("standard_euler", phi);
        assert!(z.im.abs() > 0.0 && z.norm() > 1.0, "Φ={phi}: {z}");
    }
    assert!(late_amplitude("standard_euler", 0.3, 400) > 10.0);
    let c = claim("sec05.always_unstable");
    assert!(
        c.derived.contains("unstable oscillation") && !c.derived.contains(';'),
        "{}",
        c.derived
    );
}
