//! Section 10 (False Heun): the stages, the misprinted y update
//! (−Φ²y for −2Φ²y) and second z-domain row ((1 − Φ²/2) for
//! (1 − Φ² + Φ⁴/2)), the correct χ, r² = 1 − Φ²/2, and the class claim
//! "either monotonic unstable or a damped oscillation", which misses a
//! monotonic stable band and the constant point Φ = √2.

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec10.ode", Confirmed),
    ("sec10.stages", Confirmed),
    ("sec10.update_v", Confirmed),
    ("sec10.update_y", Errata),
    ("sec10.update_expanded", Confirmed),
    ("sec10.z_rows", Errata),
    ("sec10.charpoly", Confirmed),
    ("sec10.r_squared", Confirmed),
    ("sec10.either_or", Errata),
    ("sec10.not_recommended", Confirmed),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// The printed half-step y update differs from the program by −Φ²y/2; the
/// expanded line that follows is right.
#[test]
fn y_update_misprint() {
    for phi in PHIS {
        let (v, y) = (0.37, -1.1);
        let (_, y_new) = pascal_step("false_heun", v, y, phi);
        let (p2, p3, p4) = (phi * phi, phi.powi(3), phi.powi(4));
        let printed = y + 0.5 * (2.0 * phi * v - p3 * v - p2 * y + p4 * y);
        let corrected = y + 0.5 * (2.0 * phi * v - p3 * v - 2.0 * p2 * y + p4 * y);
        let expanded = y + phi * v - p2 * y - 0.5 * p3 * v + 0.5 * p4 * y;
        let tol = 64.0 * f64::EPSILON * (1.0 + p4);
        assert!((corrected - y_new).abs() <= tol && (expanded - y_new).abs() <= tol, "Φ={phi}");
        assert!(
            (printed - y_new - 0.5 * p2 * y).abs() <= tol,
            "Φ={phi}: the misprint is exactly +Φ²y/2"
        );
    }
}

/// Row 1 is right; row 2's y coefficient is (1 − Φ² + Φ⁴/2), not the
/// printed (1 − Φ²/2). χ as printed is the one of the correct rows.
#[test]
fn second_row_misprint_but_charpoly_right() {
    let printed = z_rows_match(
        "false_heun",
        [["1 - Phi^2/2", "-Phi*(1 - Phi^2/2)"], ["Phi*(1 - Phi^2/2)", "1 - Phi^2/2"]],
    );
    assert_eq!(printed, [[true, true], [true, false]]);
    assert_eq!(
        z_rows_match(
            "false_heun",
            [["1 - Phi^2/2", "-Phi*(1 - Phi^2/2)"], ["Phi*(1 - Phi^2/2)", "1 - Phi^2 + Phi^4/2"]]
        ),
        [[true; 2]; 2]
    );
    check_charpoly("false_heun", "z^2 - 2*(1 - 3/4*Phi^2 + Phi^4/4)*z + (1 - Phi^2/2)");
    check_r_squared("false_heun", "1 - Phi^2/2");
}

/// The classes over Φ > 0: damped oscillation for small Φ, then two real
/// roots in (0, 1) (monotonic stable) below √2, a root at exactly 1 at
/// Φ = √2, then a root above 1. "Either monotonic unstable or a damped
/// oscillation" misses the band.
#[test]
fn classes_over_phi() {
    #[track_caller]
    fn check(phi: f64, want: &str) {
        let r = roots_at("false_heun", phi);
        let got = if r[0].im != 0.0 {
            if r[0].norm() < 1.0 {
                "damped"
            } else {
                "unstable oscillation"
            }
        } else {
            let top = r.iter().map(|z| z.re).fold(f64::MIN, f64::max);
            let bottom = r.iter().map(|z| z.re).fold(f64::MAX, f64::min);
            if top > 1.0 {
                "monotonic unstable"
            } else if bottom > 0.0 {
                "monotonic stable"
            } else {
                "other"
            }
        };
        assert_eq!(got, want, "Φ={phi}: {r:?}");
    }
    check(0.5, "damped");
    check(1.2, "damped");
    check(1.35, "monotonic stable");
    check(1.41, "monotonic stable");
    check(1.42, "monotonic unstable");
    check(3.0, "monotonic unstable");
    // At Φ = √2 exactly, χ(1) = Φ²(1 − Φ²/2) = 0.
    let chi = derive("false_heun").charpoly().clone();
    let at_one = chi.subs(poly::Sym::z(), &poly::Poly::int(1));
    assert_eq!(at_one, parse("Phi^2*(1 - Phi^2/2)"));
    assert!(claim("sec10.either_or").evidence.contains("monotonic stable"));
}

/// Strong numerical damping: the amplitude after one true period at 20
/// steps per period is far below 1.
#[test]
fn strongly_damped() {
    let phi = 2.0 * std::f64::consts::PI / 20.0;
    let (mut v, mut y) = (0.0f64, 1.0f64);
    for _ in 0..20 {
        (v, y) = pascal_step("false_heun", v, y, phi);
    }
    assert!((v * v + y * y).sqrt() < 0.8);
}
