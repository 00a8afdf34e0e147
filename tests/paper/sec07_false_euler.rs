//! Section 7 (False Euler): the update that reads the new v, its z-domain
//! rows, χ = z² − 2(1 − Φ²/2)z + 1, eigenvalues on the unit circle, "always
//! a harmonic oscillation" (only for 0 < Φ < 2), tan Ψ, Ψ ≅ Φ(1 + Φ²/24),
//! the frequency, and the stability limit Φ = 2, T/T0 = 1/π.

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec07.ode", Confirmed),
    ("sec07.update", Confirmed),
    ("sec07.z_rows", Confirmed),
    ("sec07.charpoly", Confirmed),
    ("sec07.eigenvalues", Confirmed),
    ("sec07.eigenvalues_factored", Confirmed),
    ("sec07.cos_sin", Confirmed),
    ("sec07.r_squared", Confirmed),
    ("sec07.always_harmonic", Refined),
    ("sec07.tan_psi", Confirmed),
    ("sec07.psi_approx", Confirmed),
    ("sec07.frequency_too_high", Confirmed),
    ("sec07.stability_limit", Confirmed),
    ("sec07.period_ratio", Confirmed),
    ("sec07.pi_steps", Confirmed),
    ("sec07.nyquist", Refined),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

#[test]
fn rows_charpoly_eigenvalues() {
    assert_eq!(z_rows_match("false_euler", [["1", "-Phi"], ["Phi", "1 - Phi^2"]]), [[true; 2]; 2]);
    check_charpoly("false_euler", "z^2 - 2*(1 - Phi^2/2)*z + 1");
    check_eigenvalues("false_euler", "1 - Phi^2/2", "1 - (1 - Phi^2/2)^2");
    check_eigenvalues("false_euler", "1 - Phi^2/2", "Phi^2*(1 - Phi^2/4)");
    check_r_squared("false_euler", "1");
}

/// Harmonic (bounded, |z| = 1) exactly for 0 < Φ < 2: at Φ = 2 the double
/// root −1 is defective (linear growth), beyond it a real root is below −1.
#[test]
fn harmonic_only_below_two() {
    for phi in [0.01, 0.5, 1.0, 1.5, 1.99] {
        let [z, w] = roots_at("false_euler", phi);
        assert!(
            z.im != 0.0
                && (z.norm() - 1.0).abs() <= 8.0 * f64::EPSILON
                && (w.norm() - 1.0).abs() <= 8.0 * f64::EPSILON
        );
        assert!(growth_ratio("false_euler", phi, 4000) < 1.01, "Φ={phi}");
    }
    assert!(growth_ratio("false_euler", 2.0, 4000) > 2.5);
    for phi in [2.01, 2.5, 4.0] {
        assert!(spectral_radius("false_euler", phi) > 1.0, "Φ={phi}");
    }
    let c = claim("sec07.always_harmonic");
    assert!(c.evidence.contains("Φ > 2"), "{}", c.evidence);
}

/// tan Ψ as printed (modulo π), Ψ = 2 arcsin(Φ/2) > Φ, and the Φ⁵ error of
/// the approximation.
#[test]
fn frequency() {
    for phi in [0.2, 1.0, 1.3, 1.5, 1.9] {
        let psi = psi("false_euler", phi).unwrap();
        assert!((psi - 2.0 * (phi / 2.0).asin()).abs() <= 64.0 * f64::EPSILON, "Φ={phi}");
        assert!(psi > phi);
        let tan = phi * (1.0 - phi * phi / 4.0).sqrt() / (1.0 - phi * phi / 2.0);
        assert!((psi.tan() - tan).abs() <= 1e3 * f64::EPSILON * (1.0 + tan.abs()).powi(2));
    }
    let order = error_order(|p| psi("false_euler", p).unwrap(), |p| p * (1.0 + p * p / 24.0), 0.2);
    assert!((order - 5.0).abs() < 0.1, "{order}");
}

/// Φ_max = 2 exactly: the imaginary part Φ(1 − Φ²/4)^0.5 vanishes there;
/// T/T0 = Φ/(2π) = 1/π; more than π steps per period; Nyquist at 1/2.
#[test]
fn stability_limit() {
    let (p, q) = p_q("false_euler");
    let two = poly::q(2, 1);
    let im_sq = &q - &(&p * &p);
    assert_eq!(at(&im_sq, &two), poly::q(0, 1));
    assert!(
        at(&im_sq, &poly::q(199, 100)) > poly::q(0, 1)
            && at(&im_sq, &poly::q(201, 100)) < poly::q(0, 1)
    );
    // T/T0 = Φ_max/(2π) with Φ_max from the exact analysis, not from the paper.
    let report = derive("false_euler").stability(&poly::Params::new()).unwrap();
    let phi_max = report.phi_max().expect("False Euler has a limit");
    let phi_max: f64 = phi_max.to_decimal(17).parse().unwrap();
    let t_over_t0 = phi_max / (2.0 * std::f64::consts::PI);
    assert!((t_over_t0 - 1.0 / std::f64::consts::PI).abs() <= f64::EPSILON);
    assert!(1.0 / t_over_t0 > 3.0 && t_over_t0 < 0.5);
    assert!(claim("sec07.stability_limit").derived.contains("double root at minus one"));
}
