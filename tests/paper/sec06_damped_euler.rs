//! Section 6 (Damped Euler): the damped oscillator by Standard Euler, χ with
//! the damping ratio D, the eigenvalues (a conjugate pair only for D < 1),
//! r², the stabilising D = Φ/2, tan Ψ, the Taylor approximation
//! Ψ ≅ Φ(1 + Φ²/24) and its table at Φ = 1 and Φ = 1.414.

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec06.ode", Confirmed),
    ("sec06.update", Confirmed),
    ("sec06.z_rows", Confirmed),
    ("sec06.charpoly", Confirmed),
    ("sec06.eigenvalues", Confirmed),
    ("sec06.r_squared", Confirmed),
    ("sec06.damping_choice", Confirmed),
    ("sec06.y_first_symplectic", Confirmed),
    ("sec06.now_harmonic", Refined),
    ("sec06.tan_psi_d", Confirmed),
    ("sec06.tan_psi", Confirmed),
    ("sec06.frequency_too_high", Confirmed),
    ("sec06.psi_approx", Confirmed),
    ("sec06.approx_validity", Confirmed),
    ("sec06.table_phi_1", Confirmed),
    ("sec06.table_phi_1414", Confirmed),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// χ with D, checked numerically for several (Φ, D) through the trace and
/// determinant of the Pascal-style step, and exactly against the derivation.
#[test]
fn charpoly_with_damping_ratio() {
    let chi = parse("z^2 - 2*(1 - D*Phi)*z + (1 - 2*D*Phi + Phi^2)");
    assert_eq!(&chi, derive("damped_euler_d").charpoly());
    for (phi, d) in [(0.3, 0.1), (1.2, 0.7), (0.5, 1.5)] {
        let step = |v: f64, y: f64| (v - phi * (2.0 * d * v + y), y + phi * v);
        let (a, b) = step(1.0, 0.0);
        let (c, e) = step(0.0, 1.0);
        let (tr, det) = (a + e, a * e - b * c);
        let vals = [("Phi", phi), ("D", d)];
        let coeffs = chi.coeffs_in(poly::Sym::z());
        assert!((eval(&coeffs[1], &vals) + tr).abs() <= 8.0 * f64::EPSILON * (1.0 + tr.abs()));
        assert!((eval(&coeffs[0], &vals) - det).abs() <= 8.0 * f64::EPSILON * (1.0 + det.abs()));
    }
    assert_eq!(z_rows_match("damped_euler", [["1 - Phi^2", "-Phi"], ["Phi", "1"]]), [[true; 2]; 2]);
}

/// (1 − DΦ) ± jΦ(1 − D²)^0.5 is a conjugate pair only for D < 1: for D > 1
/// the roots of χ are real.
#[test]
fn eigenvalues_need_d_below_one() {
    let (p, q) = p_q("damped_euler_d");
    #[track_caller]
    fn check(p: &poly::Poly, q: &poly::Poly, phi: f64, d: f64, complex: bool) {
        let vals = [("Phi", phi), ("D", d)];
        let [z, _] = roots(eval(p, &vals), eval(q, &vals));
        assert_eq!(z.im != 0.0, complex, "Φ={phi} D={d}");
        if complex {
            assert!((z.re - (1.0 - d * phi)).abs() <= 8.0 * f64::EPSILON);
            assert!((z.im.abs() - phi * (1.0 - d * d).sqrt()).abs() <= 64.0 * f64::EPSILON);
            assert!(
                (z.norm_sqr() - (1.0 - 2.0 * d * phi + phi * phi)).abs() <= 64.0 * f64::EPSILON
            );
        }
    }
    check(&p, &q, 0.5, 0.3, true);
    check(&p, &q, 1.5, 0.9, true);
    check(&p, &q, 0.5, 1.2, false);
    assert!(claim("sec06.eigenvalues").derived.contains("D² < 1"));
}

/// D = Φ/2 puts the pair on the unit circle (harmonic) while Φ < 2; from
/// Φ = 2 on the damping ratio D = Φ/2 ≥ 1 and the samples grow.
#[test]
fn half_phi_damping_is_harmonic_below_two() {
    for phi in [0.1, 0.7, 1.4, 1.9] {
        let [z, _] = roots_at("damped_euler", phi);
        assert!(z.im != 0.0 && (z.norm() - 1.0).abs() <= 8.0 * f64::EPSILON, "Φ={phi}");
        assert!(growth_ratio("damped_euler", phi, 2000) < 1.01, "Φ={phi} bounded");
    }
    assert!(growth_ratio("damped_euler", 2.0, 2000) > 2.5, "Φ = 2 grows linearly");
    assert!(spectral_radius("damped_euler", 2.3) > 1.0);
    assert!(claim("sec06.now_harmonic").evidence.contains("Φ > 2"));
}

/// tan Ψ = Φ(1 − Φ²/4)^0.5/(1 − Φ²/2) reproduces the measured angle of the
/// roots (as tan, i.e. modulo π).
#[test]
fn tan_psi() {
    for phi in [0.2, 0.9, 1.3, 1.6, 1.95] {
        let psi = psi("damped_euler", phi).unwrap();
        let printed = phi * (1.0 - phi * phi / 4.0).sqrt() / (1.0 - phi * phi / 2.0);
        assert!(
            (psi.tan() - printed).abs() <= 1e3 * f64::EPSILON * (1.0 + printed.abs()).powi(2),
            "Φ={phi}"
        );
    }
}

/// Ψ = 2 arcsin(Φ/2) > Φ; Φ(1 + Φ²/24) has an error of order Φ⁵.
#[test]
fn frequency_and_approximation() {
    for k in 1..200 {
        let phi = 2.0 * k as f64 / 200.0;
        assert!(psi("damped_euler", phi).unwrap() > phi, "Φ={phi}");
    }
    let order = error_order(|p| psi("damped_euler", p).unwrap(), |p| p * (1.0 + p * p / 24.0), 0.2);
    assert!((order - 5.0).abs() < 0.1, "error order {order}");
}

/// The table: true Ψ and approximation at Φ = 1 and Φ = 1.414, 3 decimals.
#[test]
fn table() {
    #[track_caller]
    fn check(phi: f64, true_psi: &str, approx: &str) {
        assert_eq!(format!("{:.3}", psi("damped_euler", phi).unwrap()), true_psi);
        assert_eq!(format!("{:.3}", phi * (1.0 + phi * phi / 24.0)), approx);
    }
    check(1.0, "1.047", "1.042");
    check(1.414, "1.570", "1.532");
    // At exactly √2 the true value is π/2, which rounds to 1.571.
    assert_eq!(format!("{:.3}", psi("damped_euler", 2f64.sqrt()).unwrap()), "1.571");
}

/// Φ < 1 is more than 2π samples per period; the relative error at Φ = 1 is
/// half a percent.
#[test]
fn approximation_validity() {
    let phi = 1.0;
    let err = (phi * (1.0 + phi * phi / 24.0) - psi("damped_euler", phi).unwrap()).abs() / phi;
    assert!(err < 0.01 && 2.0 * std::f64::consts::PI / phi > 2.0 * std::f64::consts::PI - 1e-12);
}
