//! The speed/accuracy trade (`crate::tradeoff`): the accuracy model against
//! the paper's closed forms and B's numeric witnesses, the hand kernels
//! against the exact transition matrix, the admissible-Φ search against the
//! exact stability limit, the ranking against its own definition, and the
//! advisor against `poly::advanced::stability` and the numeric classification.

use check::numeric::ParamsF64;
use std::collections::HashMap;
use std::f64::consts::PI;

use super::accuracy::{SecondOrder, Spring, Target};
use super::measure::measure_ns_per_step_within;
use super::rank::{self, TradeRow};
use super::spring_advisor::{advise_spring, SpringScene};
use super::{family, kernels, Rank};
use crate::load::LoadedMethod;
use crate::tradeoff::family::Candidate;
use check::numeric::{f64_to_q, q_to_f64, Params, Step};
use check::witness;
use poly::{Sym, Q};

const EPS: f64 = f64::EPSILON;

/// The seven direct methods applied to a spring with damping ratio `d`.
fn damped_family(d: &Q) -> Result<Vec<Candidate>, crate::Error> {
    family::damped_candidates(&LoadedMethod::damped_builtins()?, d)
}

/// χ of a candidate with its parameters substituted (a polynomial in z and
/// Φ), derived again from its method.
fn charpoly(c: &Candidate) -> poly::Poly {
    let values: HashMap<Sym, Q> = c.params.iter().cloned().collect();
    poly::advanced::charpoly(&c.method).unwrap().eval_partial(&values)
}

/// The measurement budget of the tests' timings.
const BUDGET: std::time::Duration = std::time::Duration::from_millis(3);

fn undamped() -> Vec<Candidate> {
    family::undamped_family().expect("built-ins derive")
}

fn candidate(name: &str) -> Candidate {
    undamped().into_iter().find(|c| c.name == name).expect("known method")
}

fn direct_undamped() -> Vec<Candidate> {
    undamped()
        .into_iter()
        .filter(|c| poly::advanced::builtins::PAPER_METHODS.contains(&c.name.as_str()))
        .collect()
}

#[track_caller]
fn check_psi_and_growth(name: &str, phi: f64, psi: f64, ln_r: f64, tol: f64) {
    let acc = candidate(name).model.accuracy(phi, Spring::UNDAMPED);
    assert!(acc.oscillating, "{name} at {phi}: expected a complex pair");
    assert!((acc.psi - psi).abs() <= tol * psi.abs(), "{name} at {phi}: psi {} vs {psi}", acc.psi);
    assert!((acc.phase_error_per_step - (psi - phi)).abs() <= tol * psi.abs(), "{name} at {phi}");
    let ln_tol = tol * ln_r.abs().max(f64::MIN_POSITIVE);
    assert!(
        (acc.ln_growth_per_step - ln_r).abs() <= ln_tol,
        "{name} at {phi}: ln r {} vs {ln_r}",
        acc.ln_growth_per_step
    );
}

/// The accuracy model reproduces the paper's closed forms: tan Ψ (sections
/// 6, 7, 9) and r² (sections 5, 7, 9, 11), to a few ulps.
#[test]
fn accuracy_matches_the_papers_closed_forms() {
    for phi in [1e-3f64, 0.01, 0.1, 0.5, 1.0, 1.4, 1.9] {
        // False Euler, Verlet, Damped Euler: tan Ψ = Φ(1 − Φ²/4)^½ / (1 − Φ²/2), r = 1.
        let psi = (phi * (1.0 - phi * phi / 4.0).sqrt()).atan2(1.0 - phi * phi / 2.0);
        for m in ["false_euler", "verlet", "damped_euler", "false_euler_matrix"] {
            check_psi_and_growth(m, phi, psi, 0.0, 8.0 * EPS);
        }
        // Standard Heun: tan Ψ = Φ / (1 − Φ²/2), r² = 1 + Φ⁴/4.
        let psi = phi.atan2(1.0 - phi * phi / 2.0);
        check_psi_and_growth(
            "standard_heun",
            phi,
            psi,
            0.5 * (phi.powi(4) / 4.0).ln_1p(),
            8.0 * EPS,
        );
        // Standard Euler: z = 1 ± jΦ.
        check_psi_and_growth(
            "standard_euler",
            phi,
            phi.atan(),
            0.5 * (phi * phi).ln_1p(),
            8.0 * EPS,
        );
    }
    for phi in [1e-3f64, 0.1, 0.5, 1.0, 1.4] {
        // Semi-False Heun: z = (1 − Φ²/2) ± jΦ(1 − Φ²/2)^½, r² = 1 − Φ⁴/4.
        let a = 1.0 - phi * phi / 2.0;
        let psi = (phi * a.sqrt()).atan2(a);
        check_psi_and_growth(
            "semi_false_heun",
            phi,
            psi,
            0.5 * (-phi.powi(4) / 4.0).ln_1p(),
            8.0 * EPS,
        );
    }
}

/// The amplitude factor per period is |z|^(2π/Φ): exactly 1 for the harmonic
/// methods, e^{π Φ³/4}-ish for Standard Heun (ln r ≈ Φ⁴/8 per step).
#[test]
fn amplitude_factor_per_period() {
    let fe = candidate("false_euler").model.accuracy(0.3, Spring::UNDAMPED);
    assert_eq!(fe.amplitude_factor_per_period(), 1.0);
    let phi: f64 = 0.01;
    let sh = candidate("standard_heun").model.accuracy(phi, Spring::UNDAMPED);
    let expected = (0.5 * (phi.powi(4) / 4.0).ln_1p() * 2.0 * PI / phi).exp();
    assert!((sh.amplitude_factor_per_period() - expected).abs() <= 8.0 * EPS * expected);
}

/// Small Φ: False Euler's phase error per step follows Appendix A's
/// Ψ ≈ Φ(1 + Φ²/24), i.e. Ψ − Φ ≈ Φ³/24, and C1's exact Ψ series agrees with
/// the model to the next order's relative size.
#[test]
fn small_phi_phase_error_leading_term() {
    for phi in [1e-3f64, 3e-3, 1e-2] {
        let fe = candidate("false_euler").model.accuracy(phi, Spring::UNDAMPED);
        let lead = phi.powi(3) / 24.0;
        // Next term is O(Φ⁵); the cancellation in Ψ − Φ costs about ε·Φ/lead.
        let tol = lead * (phi * phi + 64.0 * EPS * phi / lead);
        assert!((fe.phase_error_per_step - lead).abs() <= tol, "false_euler at {phi}");
    }
    // C1's exact series of Ψ to Φ⁷, summed at small Φ, against the model's Ψ.
    let mut checked = 0;
    for c in undamped() {
        let Ok(series) = poly::advanced::series::psi_series(&charpoly(&c), 7) else { continue };
        checked += 1;
        for phi in [1e-3f64, 1e-2, 5e-2] {
            let sum: f64 =
                series.iter().enumerate().map(|(k, a)| q_to_f64(a) * phi.powi(k as i32)).sum();
            let acc = c.model.accuracy(phi, Spring::UNDAMPED);
            // Truncation O(Φ⁹) plus a few ulps of Ψ.
            let tol = phi.powi(9) + 16.0 * EPS * phi;
            assert!((acc.psi - sum).abs() <= tol, "{} at {phi}: {} vs {sum}", c.name, acc.psi);
        }
    }
    assert!(checked >= 9, "only {checked} methods have a rational Psi series");
}

/// B's numeric witnesses (eigenvalues of the compiled step's transition
/// matrix, by nalgebra) agree with the accuracy model's principal root, up
/// to the eigenvalue problem's backward error (a few hundred ulps of ‖P‖).
#[test]
fn accuracy_matches_numeric_eigenvalues() {
    for c in undamped() {
        for phi in [0.05, 0.3, 0.9, 1.3] {
            let acc = c.model.accuracy(phi, Spring::UNDAMPED);
            if !acc.oscillating {
                continue;
            }
            let step = Step::compile(&c.method, &Params::phi(phi)).unwrap();
            let eig = witness::eigenvalues_nalgebra(&step.transition_matrix()).unwrap();
            let top = eig.iter().copied().max_by(|a, b| a.im.total_cmp(&b.im)).unwrap();
            let tol = 256.0 * EPS * (1.0 + phi * phi);
            assert!((top.arg() - acc.psi).abs() <= tol, "{} at {phi}: psi", c.name);
            let ln_r = acc.ln_growth_per_step;
            assert!((top.norm().ln() - ln_r).abs() <= tol, "{} at {phi}: ln r", c.name);
        }
    }
}

/// Implicit and algebraic second-order built-ins: the model of χ = a z² +
/// b z + c (a = det A, constants such as sqrt(2) evaluated once) agrees with
/// the eigenvalues of the compiled step (an LU solve per Φ), and with the
/// closed forms: trapezoidal Ψ = 2·atan(Φ/2), |z| = 1; backward Euler
/// Ψ = atan Φ, |z|² = 1/(1 + Φ²).
#[test]
fn accuracy_of_implicit_methods_matches_eigenvalues_and_closed_forms() {
    for name in poly::advanced::builtins::IMPLICIT_METHODS {
        let m = LoadedMethod::builtin(name).unwrap();
        if m.method().state_size() != 2 {
            continue;
        }
        let c = Candidate::new(&m, Vec::new()).expect("second order");
        for phi in [0.05, 0.3, 0.9, 1.3, 2.5] {
            let acc = c.model.accuracy(phi, Spring::UNDAMPED);
            let step = Step::compile(&c.method, &Params::phi(phi)).unwrap();
            let eig = witness::eigenvalues_nalgebra(&step.transition_matrix()).unwrap();
            let top = eig.iter().copied().max_by(|a, b| a.norm().total_cmp(&b.norm())).unwrap();
            let tol = 1024.0 * EPS * (1.0 + phi * phi);
            if acc.oscillating {
                let top = eig.iter().copied().max_by(|a, b| a.im.total_cmp(&b.im)).unwrap();
                assert!((top.arg() - acc.psi).abs() <= tol, "{name} at {phi}: psi");
            }
            assert!(
                (top.norm().ln() - acc.ln_growth_per_step).abs() <= tol,
                "{name} at {phi}: ln r {} vs {}",
                top.norm().ln(),
                acc.ln_growth_per_step
            );
        }
    }
    let trap = Candidate::new(&LoadedMethod::builtin("trapezoidal").unwrap(), Vec::new()).unwrap();
    let be = Candidate::new(&LoadedMethod::builtin("backward_euler").unwrap(), Vec::new()).unwrap();
    for phi in [1e-3, 0.1, 1.0, 3.0, 10.0] {
        let t = trap.model.accuracy(phi, Spring::UNDAMPED);
        assert!((t.psi - 2.0 * (phi / 2.0).atan()).abs() <= 4.0 * EPS * t.psi, "{phi}");
        assert!(t.ln_growth_per_step.abs() <= 4.0 * EPS, "{phi}: {}", t.ln_growth_per_step);
        let b = be.model.accuracy(phi, Spring::UNDAMPED);
        assert!((b.psi - phi.atan()).abs() <= 4.0 * EPS * b.psi, "{phi}");
        let ln_r = -0.5 * (phi * phi).ln_1p();
        assert!((b.ln_growth_per_step - ln_r).abs() <= 8.0 * EPS * ln_r.abs(), "{phi}");
    }
}

/// Every hand-written kernel does one step of its method's exact transition
/// matrix (evaluated exactly at Φ and D, then rounded), to a few ulps.
#[test]
fn hand_kernels_follow_their_definitions() {
    let d_value = 0.125; // exact in binary
    let mut cands = undamped();
    cands.extend(damped_family(&f64_to_q(d_value).unwrap()).unwrap());
    for c in &cands {
        let name = c.hand_kernel.expect("every built-in has a hand kernel");
        for phi in [0.125, 0.75, 1.5] {
            let mut values: HashMap<Sym, Q> = c.params.iter().cloned().collect();
            values.insert(Sym::phi(), f64_to_q(phi).unwrap());
            let p = poly::advanced::transition_matrix(&c.method);
            for start in [[1.0, 0.0], [0.0, 1.0], [0.6, -0.8]] {
                let (mut a, mut b) = (start[0], start[1]);
                assert!(kernels::run_hand_kernel(name, &mut a, &mut b, phi, d_value, 1), "{name}");
                for (row, got) in [(0, a), (1, b)] {
                    let want: f64 = (0..2)
                        .map(|j| q_to_f64(&p[(row, j)].eval(&values).unwrap()) * start[j])
                        .sum();
                    assert!(
                        (got - want).abs() <= 16.0 * EPS * (1.0 + want.abs()),
                        "{name} at {phi} from {start:?}: slot {row}: {got} vs {want}"
                    );
                }
            }
        }
    }
}

/// At D = 0 each damped variant is its undamped method (same χ).
#[test]
fn damped_family_reduces_to_the_undamped_methods() {
    let zero = f64_to_q(0.0).unwrap();
    for c in damped_family(&zero).unwrap() {
        let base = poly::builtin(&c.display).unwrap();
        assert_eq!(charpoly(&c), poly::advanced::charpoly(&base).unwrap(), "{}", c.name);
    }
}

/// The largest admissible Φ meets the target, a slightly larger one fails
/// (or is past the stability limit), and it is always strictly below the
/// exact Φ_max.
#[test]
fn admissible_phi_is_a_sharp_bound_below_phi_max() {
    for target in [Target::DEFAULT, Target { phase_tol: 1.0, amp_tol: 0.5, periods: 1.0 }] {
        for c in undamped() {
            let Some(cap) = c.limit.search_cap() else {
                assert!(c.limit.phi_max.is_none(), "{}", c.name);
                continue;
            };
            let Some(phi) = c.model.largest_admissible_phi(Spring::UNDAMPED, &target, cap) else {
                continue;
            };
            assert!(c.limit.is_below(phi), "{}: {phi} not below phi_max", c.name);
            assert!(c.model.accuracy(phi, Spring::UNDAMPED).meets(&target), "{}", c.name);
            let above = phi * (1.0 + 1e-9);
            assert!(
                above >= cap || !c.model.accuracy(above, Spring::UNDAMPED).meets(&target),
                "{}: {above} still meets the target",
                c.name
            );
        }
    }
}

fn rows(target: &Target) -> Vec<TradeRow> {
    let cands = undamped();
    // Invented but distinct timings: the ranking must follow whatever is measured.
    rank::trade(&cands, Spring::UNDAMPED, target, Rank::Measured, |c| {
        1.0 + c.cost.program.arithmetic() as f64
    })
}

/// The default ranking is by exact operations per period, ties by name,
/// whatever the timings: invented timings that run against the counts
/// (the cheapest in operations measured slowest) do not move it.
#[test]
fn exact_ranking_ignores_the_timings() {
    let target = Target::DEFAULT;
    let rows = rank::trade(&undamped(), Spring::UNDAMPED, &target, Rank::Exact, |c| {
        1e6 - c.cost.program.arithmetic() as f64
    });
    let ranked: Vec<&TradeRow> = rows.iter().filter(|r| r.rank.is_some()).collect();
    assert!(ranked.len() >= 3, "{} ranked", ranked.len());
    for pair in ranked.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let (ca, cb) = (a.cost_per_period.unwrap(), b.cost_per_period.unwrap());
        assert!(
            (ca.arithmetic, &a.method) < (cb.arithmetic, &b.method),
            "{} before {}",
            a.method,
            b.method
        );
        assert_eq!(ca.arithmetic, ca.ops.mul + ca.ops.add);
    }
}

/// The ranking follows ns_per_step × steps_per_period, ascending; methods
/// with no admissible Φ come last and unranked.
#[test]
fn ranking_follows_measured_cost_per_period() {
    for target in [Target::DEFAULT, Target { phase_tol: 0.01, amp_tol: 1e-3, periods: 100.0 }] {
        let rows = rows(&target);
        let mut last = 0.0;
        let mut seen_unranked = false;
        for (k, r) in rows.iter().enumerate() {
            match (r.cost_per_period, r.steps_per_period, r.admissible_phi) {
                (Some(c), Some(n), Some(phi)) => {
                    assert!(!seen_unranked, "{}: ranked after an unranked row", r.method);
                    assert_eq!(r.rank, Some(k + 1));
                    assert_eq!(n, (2.0 * PI / phi).ceil() as u64, "{}", r.method);
                    assert_eq!(c.ns, r.ns_per_step * n as f64, "{}", r.method);
                    assert_eq!(c.ops.mul, n * r.ops_per_step.mul, "{}", r.method);
                    assert!(c.ns >= last, "{}: not in ascending ns per period", r.method);
                    last = c.ns;
                }
                (None, None, None) => {
                    seen_unranked = true;
                    assert_eq!(r.rank, None);
                }
                other => panic!("{}: inconsistent row {other:?}", r.method),
            }
        }
        // The methods unbounded at every Φ > 0 are never ranked.
        for m in ["standard_euler", "standard_heun"] {
            assert_eq!(rows.iter().find(|r| r.method == m).unwrap().rank, None, "{m}");
        }
    }
}

/// A rounded summary of the trade at the default target (no timings: those
/// vary by machine), snapshotted.
#[test]
fn trade_summary_snapshot() {
    let rows = rows(&Target::DEFAULT);
    let mut lines: Vec<String> = rows
        .iter()
        .map(|r| {
            format!(
                "{:<24} {}m+{}a+{}c  matrix {}m+{}a  phi_max {:<16} adm {:<8} steps/T {:<6} ops/T {}",
                r.method,
                r.ops_per_step.mul,
                r.ops_per_step.add,
                r.ops_per_step.copy,
                r.ops_per_step_matrix_form.mul,
                r.ops_per_step_matrix_form.add,
                r.phi_max_exact,
                r.admissible_phi.map_or("-".into(), |p| format!("{p:.4}")),
                r.steps_per_period.map_or("-".into(), |n| n.to_string()),
                r.cost_per_period.map_or("-".into(), |c| c.arithmetic.to_string()),
            )
        })
        .collect();
    lines.sort();
    testkit::snapshot::in_dir("zcheck")
        .bind(|| insta::assert_snapshot!("tradeoff_default_target", lines.join("\n")));
}

fn scene(freq: f64, tick: f64, damping: Option<f64>) -> SpringScene {
    SpringScene {
        freq_hz: freq,
        tick_hz: tick,
        duration_s: SpringScene::DEFAULT_DURATION_S,
        phase_tol: SpringScene::DEFAULT_PHASE_TOL,
        amp_tol: SpringScene::DEFAULT_AMP_TOL,
        damping,
    }
}

fn candidates_for(s: &SpringScene) -> Vec<Candidate> {
    match s.damping {
        Some(d) => damped_family(&f64_to_q(d).unwrap()).unwrap(),
        None => direct_undamped(),
    }
}

/// The advisor's stable set at Φ equals the methods with Φ < Φ_max by
/// `poly::advanced::stability::analyze`, equals the methods whose exact class at Φ
/// (`poly::advanced::stability::class_at`) and numeric class (B's classification of
/// the numeric roots) is bounded; and its stabilising substeps k are the
/// fewest with that property.
#[test]
fn advisor_agrees_with_stability_and_classification() {
    let scenes = [
        scene(120.0, 60.0, None),
        scene(5.0, 60.0, None),
        scene(19.0, 60.0, None),
        scene(10.0, 30.0, None),
        scene(9.0, 60.0, Some(0.25)),
        scene(30.0, 60.0, Some(0.5)),
    ];
    for s in scenes {
        let cands = candidates_for(&s);
        let advice = advise_spring(&s, &cands, Rank::Exact, |_| 1.0).unwrap();
        for (c, m) in cands.iter().zip(&advice.methods) {
            let report = poly::advanced::stability::analyze(&charpoly(c)).unwrap();
            // χ alone: bounded below Φ_max, or below the point P would decide.
            let below_max = report.phi_max().or(report.undecided_at()).is_some_and(|max| {
                max.cmp_rational(&f64_to_q(advice.phi).unwrap()) == std::cmp::Ordering::Greater
            });
            assert_eq!(m.stable_at_phi, below_max, "{} at {}", c.name, advice.phi);
            let bounded = |phi: f64| {
                let exact =
                    poly::advanced::stability::class_at(&charpoly(c), &f64_to_q(phi).unwrap())
                        .unwrap();
                let numeric = numeric_class(c, phi);
                assert_eq!(exact.bounded(), numeric.bounded(), "{} at {phi}", c.name);
                exact.bounded() == Some(true)
            };
            assert_eq!(m.stable_at_phi, bounded(advice.phi), "{} at {}", c.name, advice.phi);
            match m.substeps_stable {
                Some(k) => {
                    assert!(bounded(advice.phi / k as f64), "{}: {k} substeps", c.name);
                    if k > 1 {
                        assert!(!bounded(advice.phi / (k - 1) as f64), "{}: {k} - 1", c.name);
                    }
                }
                None => {
                    assert!(report.phi_max().is_none() && !report.bounded_for_all(), "{}", c.name)
                }
            }
            if let Some(k) = m.substeps_tol {
                assert!(k >= m.substeps_stable.unwrap(), "{}", c.name);
            }
        }
    }
}

fn numeric_class(c: &Candidate, phi: f64) -> poly::RootClass {
    let mut params = Params::phi(phi);
    for (s, q) in &c.params {
        params.set(s.name(), q_to_f64(q));
    }
    let exact = witness::ExactCharpoly::new(&c.method).unwrap();
    exact.at(&params).unwrap().class
}

/// The README's example: a 120 Hz spring on a 60 Hz tick, Φ = 4π. Nothing
/// is stable without substeps; the stabilising substeps are ⌈4π/Φ_max⌉ with
/// the paper's limits: 2 (False Euler, Verlet, Damped Euler: 4π/2 = 6.28 →
/// 7), √(2√5 − 2) ≈ 1.572 (Semi-False Heun: 7.99 → 8), √2 (False Heun:
/// 8.89 → 9); Standard Euler and Standard Heun never.
#[test]
fn advisor_120_hz_on_60_hz_tick() {
    let s = scene(120.0, 60.0, None);
    let advice = advise_spring(&s, &direct_undamped(), Rank::Measured, |c| {
        1.0 + c.cost.program.arithmetic() as f64
    })
    .unwrap();
    assert!((advice.phi - 4.0 * PI).abs() <= 4.0 * EPS * advice.phi);
    let by: HashMap<&str, _> = advice.methods.iter().map(|m| (m.method.as_str(), m)).collect();
    for (m, k) in [
        ("false_euler", Some(7)),
        ("verlet", Some(7)),
        ("damped_euler", Some(7)),
        ("semi_false_heun", Some(8)),
        ("false_heun", Some(9)),
        ("standard_euler", None),
        ("standard_heun", None),
    ] {
        assert!(!by[m].stable_at_phi, "{m}");
        assert_eq!(by[m].substeps_stable, k, "{m}");
    }
    // The cheapest meets the tolerance at its substeps and costs least per tick.
    let best = by[advice.cheapest.as_deref().expect("some method meets the default tolerance")];
    let best_ns = best.ns_per_tick.unwrap();
    assert!(best.phase_drift.unwrap() <= s.phase_tol && best.amplitude_drift.unwrap() <= s.amp_tol);
    assert!(advice.methods.iter().filter_map(|m| m.ns_per_tick).all(|ns| ns >= best_ns));
}

/// With damping the target is the exact damped oscillator: a method that
/// matches it exactly has zero drift, and the advisor's drift for False
/// Euler shrinks with more substeps.
#[test]
fn damped_scene_is_judged_against_the_damped_oscillator() {
    let s = scene(2.0, 60.0, Some(0.1));
    let spring = s.spring();
    let fe = damped_family(&f64_to_q(0.1).unwrap())
        .unwrap()
        .into_iter()
        .find(|c| c.display == "false_euler")
        .unwrap();
    let phi = s.phi();
    let err = |k: f64| fe.model.accuracy(phi / k, spring).error(s.periods());
    assert!(err(1.0) > err(2.0) && err(2.0) > err(4.0), "error must fall with substeps");
    // The exact spring's own per-step root is judged error-free.
    assert_eq!(spring.psi_exact(phi), phi * (1.0f64 - 0.01).sqrt());
    assert_eq!(spring.ln_r_exact(phi), -0.1 * phi);
}

/// Bad scene numbers are errors naming the flag and what was expected.
#[test]
fn scene_validation() {
    #[track_caller]
    fn check(s: SpringScene, expected: &str) {
        let err = advise_spring(&s, &[], Rank::Exact, |_| 1.0).unwrap_err().to_string();
        assert!(err.contains(expected), "{err}");
    }
    check(scene(0.0, 60.0, None), "--freq 0: expected a finite number > 0");
    check(scene(10.0, f64::NAN, None), "--tick NaN: expected a finite number > 0");
    check(scene(10.0, 60.0, Some(1.0)), "--damping 1: expected a damping ratio with 0 <= D < 1");
    check(SpringScene { amp_tol: -1.0, ..scene(10.0, 60.0, None) }, "--amp-tol -1");
}

/// The second-order model refuses what it cannot model.
#[test]
fn model_errors() {
    let cubic = poly::Poly::parse("z^3 - Phi*z + 1").unwrap();
    let err = SecondOrder::new(&cubic, &[]).unwrap_err().to_string();
    assert!(err.contains("expected a second-order method"), "{err}");
    let free_d = poly::Poly::parse("z^2 - 2*z + D*Phi + 1").unwrap();
    let err = SecondOrder::new(&free_d, &[]).unwrap_err().to_string();
    assert!(err.contains("expected every other parameter to have a value"), "{err}");
}

/// `zcheck overview --implicit` rows carry the literature's facts: the
/// A-stable methods are bounded for every Φ (Gauss–Legendre included,
/// through its double root at −1 where P = −I), Newmark's linear-
/// acceleration method stops at 2√3, Forest–Ruth near 1.5734, and each
/// implicit row says what its cost includes.
#[test]
fn overview_of_the_implicit_builtins() {
    for name in poly::advanced::builtins::IMPLICIT_METHODS {
        let row = crate::overview::summarize(&poly::builtin(name).unwrap(), 5).unwrap();
        match name {
            "newmark_linear" => assert_eq!(row.phi_max_exact, "2*sqrt(3)"),
            "forest_ruth" => {
                assert!((row.phi_max.unwrap() - 1.5734).abs() < 1e-4, "{:?}", row.phi_max)
            }
            _ => assert_eq!(row.phi_max_exact, "none: bounded for every Phi > 0", "{name}"),
        }
        let m = poly::builtin(name).unwrap();
        assert_eq!(row.unknowns, m.unknowns().len(), "{name}");
        if m.is_implicit() {
            assert!(row.solve.0 > 0 && row.solve.0 <= row.mul, "{name}: {:?}", row.solve);
        }
    }
    let text = crate::overview::to_markdown(&[crate::overview::summarize(
        &poly::builtin("gauss_legendre_2").unwrap(),
        5,
    )
    .unwrap()]);
    assert!(text.contains("(4 unknowns; LU once per Φ)"), "{text}");
}

/// The library call the advisor uses measures any method.
#[test]
fn measure_any_method() {
    let m = poly::Method::parse("x.zm", "method x\nstate y\ny = 2*y - y@1 - Phi^2*y\n").unwrap();
    let ns = measure_ns_per_step_within(
        &m,
        &<check::numeric::Params as check::numeric::ParamsF64>::phi(0.1),
        BUDGET,
    )
    .unwrap();
    assert!(ns.is_finite() && ns > 0.0);
    let err = measure_ns_per_step_within(
        &poly::builtin("damped_euler_d").unwrap(),
        &<check::numeric::Params as check::numeric::ParamsF64>::phi(0.1),
        BUDGET,
    );
    assert!(err.is_err(), "D has no value");
}
