//! Appendix A (Taylor): every step of the derivations Ψ ≅ Φ(1 + Φ²/24)
//! (Damped and False Euler) and Ψ ≅ Φ(1 + Φ²/6) (Standard Heun), checked as
//! power series through Φ³ and by the order of the numeric error.

use zcheck::paper::Verdict::{self, *};

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

/// The paper's two approximations are the leading phase-error terms of the
/// extended table (`zcheck overview`): Ψ − Φ = Φ³/24 and Φ³/6, parsed from
/// the paper's own printed forms.
#[test]
fn extension_reproduces_the_papers_two_series() {
    #[track_caller]
    fn check(method: &str, paper_approximation: &str) {
        let row = zcheck::overview::summarize(&poly::builtin(method).unwrap(), 5).unwrap();
        let paper = poly::Poly::parse(paper_approximation).unwrap() - poly::Poly::var("Phi");
        let ours = poly::Poly::parse(&row.phase_error).unwrap();
        assert_eq!(ours, paper, "{method}: phase error {} vs paper {paper}", row.phase_error);
    }
    check("damped_euler", "Phi*(1 + Phi^2/24)");
    check("false_euler", "Phi*(1 + Phi^2/24)");
    check("standard_heun", "Phi*(1 + Phi^2/6)");
}

/// Every method's Ψ series in the extended table matches the true Ψ(Φ) (the
/// angle of the numeric eigenvalue) with an error of order Φ⁷, the first
/// omitted power: the series are right, not just their leading terms.
#[test]
fn extension_series_match_the_true_psi_for_every_method() {
    for row in zcheck::overview::paper_overview(5).unwrap() {
        let text = row.psi_series.split(" + O(").next().unwrap();
        let series = poly::Poly::parse(text).unwrap();
        let eval = |phi: f64| -> f64 {
            series
                .terms()
                .map(|(m, c)| {
                    let e = m.factors().iter().map(|&(_, e)| e).sum::<u32>();
                    let c = check::numeric::q_to_f64(c);
                    c * phi.powi(e as i32)
                })
                .sum()
        };
        let order = error_order(|p| psi(&row.method, p).unwrap(), eval, 0.2);
        assert!(order > 6.5, "{}: Psi series error order {order}", row.method);
    }
}

/// The extended table, for people to review (exact series, limits rounded
/// to 4 decimals).
#[test]
fn extension_table_snapshot() {
    let rows = zcheck::overview::paper_overview(5).unwrap();
    let table = zcheck::overview::to_markdown(&rows);
    crate::snapshot::in_dir("paper").bind(|| insta::assert_snapshot!("overview_table", table));
}
