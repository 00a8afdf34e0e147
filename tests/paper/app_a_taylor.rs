//! Appendix A (Taylor): every step of the derivations Ψ ≅ Φ(1 + Φ²/24)
//! (Damped and False Euler) and Ψ ≅ Φ(1 + Φ²/6) (Standard Heun), checked as
//! power series through Φ³ and by the order of the numeric error.

use check::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("appA.tan_psi_euler", Confirmed),
    ("appA.euler_step1", Confirmed),
    ("appA.euler_step2", Confirmed),
    ("appA.euler_step3", Confirmed),
    ("appA.euler_step4", Confirmed),
    ("appA.euler_result", Confirmed),
    ("appA.tan_psi_heun", Confirmed),
    ("appA.heun_step1", Confirmed),
    ("appA.heun_step2", Confirmed),
    ("appA.heun_result", Confirmed),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// Each "≅" of Appendix A holds with an error of order Φ⁵: both sides are
/// evaluated numerically with the true Ψ(Φ) of the method.
#[test]
fn each_step_is_accurate_to_phi_cubed() {
    type Side = fn(f64, f64) -> f64;
    #[track_caller]
    fn check(method: &str, lhs: Side, rhs: Side) {
        let order = error_order(
            |p| lhs(psi(method, p).unwrap(), p),
            |p| rhs(psi(method, p).unwrap(), p),
            0.1,
        );
        assert!(order > 4.8, "{method}: error order {order}");
    }
    let tan_euler: Side = |_, p| p * (1.0 - p * p / 4.0).sqrt() / (1.0 - p * p / 2.0);
    check("false_euler", |s, _| s.tan(), tan_euler);
    check(
        "false_euler",
        |s, _| s + s.powi(3) / 3.0,
        |_, p| p * (1.0 - p * p / 8.0) * (1.0 + p * p / 2.0),
    );
    check("false_euler", |s, _| s * (1.0 + s * s / 3.0), |_, p| p * (1.0 + 3.0 / 8.0 * p * p));
    check("false_euler", |s, _| s, |s, p| p * (1.0 + 3.0 / 8.0 * p * p) * (1.0 - s * s / 3.0));
    check("false_euler", |s, _| s, |_, p| p * (1.0 + 3.0 / 8.0 * p * p) * (1.0 - p * p / 3.0));
    check("false_euler", |s, _| s, |_, p| p * (1.0 + p * p / 24.0));
    check("standard_heun", |s, _| s * (1.0 + s * s / 3.0), |_, p| p * (1.0 + p * p / 2.0));
    check("standard_heun", |s, _| s, |_, p| p * (1.0 + p * p / 2.0) * (1.0 - p * p / 3.0));
    check("standard_heun", |s, _| s, |_, p| p * (1.0 + p * p / 6.0));
}

/// tan Ψ exactly: tan²Ψ = (q − p²)/p² gives the printed squares for both
/// methods as polynomial identities.
#[test]
fn tan_psi_identities() {
    #[track_caller]
    fn check(method: &str, num_sq: &str, den: &str) {
        let (p, q) = p_q(method);
        assert_eq!(
            &(&q - &(&p * &p)) * &(&parse(den) * &parse(den)),
            &parse(num_sq) * &(&p * &p),
            "{method}"
        );
    }
    check("false_euler", "Phi^2*(1 - Phi^2/4)", "1 - Phi^2/2");
    check("damped_euler", "Phi^2*(1 - Phi^2/4)", "1 - Phi^2/2");
    check("standard_heun", "Phi^2", "1 - Phi^2/2");
}
