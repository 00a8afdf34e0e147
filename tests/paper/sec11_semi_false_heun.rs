//! Section 11 (Semi-False Heun): stages, updates, rows, χ, eigenvalues,
//! r² = 1 − Φ⁴/4, "always stable" (false beyond Φ = √(2√5 − 2) ≈ 1.5723,
//! where a real root passes −1), damped for small Φ, and "as accurate as
//! Standard Heun" (same orders of phase and amplitude error).

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec11.ode", Confirmed),
    ("sec11.stages", Confirmed),
    ("sec11.update", Confirmed),
    ("sec11.z_rows", Confirmed),
    ("sec11.charpoly", Confirmed),
    ("sec11.eigenvalues", Confirmed),
    ("sec11.r_squared", Confirmed),
    ("sec11.always_stable", Errata),
    ("sec11.damped_small_steps", Confirmed),
    ("sec11.as_accurate", Confirmed),
    ("sec11.academic_example", Confirmed),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

#[test]
fn rows_charpoly_eigenvalues() {
    assert_eq!(
        z_rows_match(
            "semi_false_heun",
            [["1 - Phi^2/2", "-Phi"], ["Phi*(1 - Phi^2/2)", "1 - Phi^2/2"]]
        ),
        [[true; 2]; 2]
    );
    check_charpoly("semi_false_heun", "z^2 - 2*(1 - Phi^2/2)*z + (1 - Phi^4/4)");
    check_eigenvalues("semi_false_heun", "1 - Phi^2/2", "Phi^2*(1 - Phi^2/2)");
    check_r_squared("semi_false_heun", "1 - Phi^4/4");
}

/// Stable up to Φ² = 2√5 − 2, where χ(−1) = 4 − Φ² − Φ⁴/4 vanishes; just
/// beyond, a real root is below −1 and the Pascal program blows up.
#[test]
fn not_always_stable() {
    let limit = (2.0 * 5f64.sqrt() - 2.0).sqrt();
    let chi_minus_one = |phi: f64| 4.0 - phi * phi - phi.powi(4) / 4.0;
    assert!(chi_minus_one(limit).abs() <= 16.0 * f64::EPSILON);
    for phi in [0.5, 1.2, 1.45, limit - 1e-3] {
        assert!(spectral_radius("semi_false_heun", phi) < 1.0, "Φ={phi}");
    }
    for phi in [limit + 1e-3, 1.7, 2.5] {
        let r = roots_at("semi_false_heun", phi);
        assert!(r.iter().any(|z| z.im == 0.0 && z.re < -1.0), "Φ={phi}: {r:?}");
    }
    for phi in [1.7, 2.5] {
        assert!(late_amplitude("semi_false_heun", phi, 400) > 1e3, "Φ={phi}");
    }
    let c = claim("sec11.always_stable");
    assert!(
        c.derived.contains("sqrt(2*sqrt(5) - 2)") && c.derived.contains("1.5723"),
        "{}",
        c.derived
    );
}

/// Same orders of error as Standard Heun: Ψ − Φ ~ Φ³ (constants −1/12 and
/// +1/6) and |z|² − 1 ~ Φ⁴ (constants −1/4 and +1/4), measured numerically.
#[test]
fn as_accurate_as_standard_heun() {
    #[track_caller]
    fn check(name: &str, phase: f64, amplitude: f64) {
        let phi: f64 = 0.01;
        let psi = psi(name, phi).unwrap();
        assert!(((psi - phi) / phi.powi(3) - phase).abs() < 1e-3, "{name} phase");
        let r2 = roots_at(name, phi)[0].norm_sqr();
        assert!(((r2 - 1.0) / phi.powi(4) - amplitude).abs() < 1e-3, "{name} amplitude");
    }
    check("semi_false_heun", -1.0 / 12.0, -0.25);
    check("standard_heun", 1.0 / 6.0, 0.25);
}
