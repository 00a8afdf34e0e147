//! Section 9 (Standard Heun): the predictor–corrector on a linear system,
//! the misprinted test ODE (v̇ = −ω0 v, ẏ = ω0 y), the stages, rows, χ,
//! eigenvalues, r² = 1 + Φ⁴/4, "always an unstable oscillation", the weak
//! growth for small Φ, tan Ψ, Ψ ≅ Φ(1 + Φ²/6) and "the frequency is always
//! too high" (only up to Φ ≈ 2.0816).

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec09.scheme", Confirmed),
    ("sec09.scheme_with_input", Refined),
    ("sec09.ode", Errata),
    ("sec09.stages", Confirmed),
    ("sec09.z_rows", Confirmed),
    ("sec09.charpoly", Confirmed),
    ("sec09.eigenvalues", Confirmed),
    ("sec09.r_squared", Confirmed),
    ("sec09.always_unstable", Confirmed),
    ("sec09.weak_instability", Confirmed),
    ("sec09.tan_psi", Confirmed),
    ("sec09.psi_approx", Confirmed),
    ("sec09.frequency_too_high", Refined),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// The printed ODE v̇ = −ω0 v, ẏ = ω0 y would make Heun's first stage
/// dv(1) = −Φv; the Pascal program (and the next printed line dv(1) = −Φy)
/// integrates v̇ = −ω0 y, ẏ = ω0 v: P = I + ΦA + (ΦA)²/2 with that A.
#[test]
fn the_printed_ode_is_a_misprint() {
    let heun = |a: [[f64; 2]; 2], phi: f64| {
        let mut p = [[0.0; 2]; 2];
        for i in 0..2 {
            for j in 0..2 {
                let a2: f64 = (0..2).map(|k| a[i][k] * a[k][j]).sum();
                p[i][j] = (i == j) as u8 as f64 + phi * a[i][j] + phi * phi * a2 / 2.0;
            }
        }
        p
    };
    for phi in PHIS {
        let program = pascal_matrix("standard_heun", phi);
        let close = |p: [[f64; 2]; 2]| {
            (0..4).all(|k| {
                (p[k / 2][k % 2] - program[k / 2][k % 2]).abs()
                    <= 16.0 * f64::EPSILON * (1.0 + phi * phi)
            })
        };
        assert!(close(heun([[0.0, -1.0], [1.0, 0.0]], phi)), "Φ={phi}");
        assert!(!close(heun([[-1.0, 0.0], [0.0, 1.0]], phi)), "Φ={phi}");
    }
}

#[test]
fn rows_charpoly_eigenvalues() {
    assert_eq!(
        z_rows_match("standard_heun", [["1 - Phi^2/2", "-Phi"], ["Phi", "1 - Phi^2/2"]]),
        [[true; 2]; 2]
    );
    check_charpoly("standard_heun", "z^2 - 2*(1 - Phi^2/2)*z + (1 + Phi^4/4)");
    check_eigenvalues("standard_heun", "1 - Phi^2/2", "Phi^2");
    check_r_squared("standard_heun", "1 + Phi^4/4");
}

/// Unstable for every Φ > 0, weakly for small Φ: the amplitude after one
/// true period (2π/Φ steps) of the Pascal program is (1 + Φ⁴/4)^(π/Φ).
#[test]
fn always_unstable_but_weakly() {
    for phi in [1e-2, 0.1, 1.0, 1.5, 3.0, 100.0] {
        let [z, _] = roots_at("standard_heun", phi);
        assert!(z.im != 0.0 && z.norm() > 1.0, "Φ={phi}");
    }
    for steps in [20usize, 50, 100] {
        let phi = 2.0 * std::f64::consts::PI / steps as f64;
        let (mut v, mut y) = (0.0f64, 1.0f64);
        for _ in 0..steps {
            (v, y) = pascal_step("standard_heun", v, y, phi);
        }
        let grown = (v * v + y * y).sqrt();
        let want = (1.0 + phi.powi(4) / 4.0).powf(std::f64::consts::PI / phi);
        assert!(
            grown > 1.0 && (grown - want).abs() <= 1e3 * f64::EPSILON,
            "{steps} steps: {grown} vs {want}"
        );
    }
}

/// tan Ψ = Φ/(1 − Φ²/2) (modulo π), the Φ⁵ error of Φ(1 + Φ²/6), and the
/// frequency too high only below the crossing Φ ≈ 2.0816 (Ψ = Φ there): at
/// Φ = 2.08 the numeric angle is still above Φ, at 2.083 already below.
#[test]
fn frequency() {
    for phi in [0.3, 1.0, 1.6, 2.5] {
        let psi = psi("standard_heun", phi).unwrap();
        let tan = phi / (1.0 - phi * phi / 2.0);
        assert!(
            (psi.tan() - tan).abs() <= 1e3 * f64::EPSILON * (1.0 + tan.abs()).powi(2),
            "Φ={phi}"
        );
    }
    let order = error_order(|p| psi("standard_heun", p).unwrap(), |p| p * (1.0 + p * p / 6.0), 0.2);
    assert!((order - 5.0).abs() < 0.1, "{order}");
    assert!(psi("standard_heun", 2.08).unwrap() > 2.08);
    assert!(psi("standard_heun", 2.083).unwrap() < 2.083);
    assert!(psi("standard_heun", 3.0).unwrap() < 3.0);
    assert!(claim("sec09.frequency_too_high").derived.contains("0 < Φ < 2.0"));
}
