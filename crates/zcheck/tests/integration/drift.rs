//! `zcheck drift` and its library half (`check::drift`): the round-off model
//! on short runs, in f64 and f32, and the command's JSON and errors.

use crate::run::zcheck;
use check::drift::Study;
use check::kernel::{Kernel, Real};
use check::numeric::{Params, ParamsF64, Step};
use serde_json::Value;

fn study<T: Real>(name: &str, phi: f64, lanes: usize) -> Study<T> {
    let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(phi)).unwrap();
    Study::new(Kernel::<T>::new(&step), lanes).unwrap()
}

/// A short run is a random walk: the RMS drift over 64 starts follows
/// √N·s with s measured on single steps, within a factor 2 at every
/// checkpoint from N = 100 (64 starts give the RMS to about ±10 %), and the
/// slope of log RMS against log N is near ½.
#[track_caller]
fn check_random_walk<T: Real>(name: &str, phi: f64, n: u64) {
    let s = study::<T>(name, phi, 64);
    let one = s.one_step();
    assert!(one.std_eps > 0.01 && one.std_eps < 10.0, "{name} {}: s = {}", T::NAME, one.std_eps);
    let mut run = s.run(n, 2, |_| true);
    run.fit_model(&one);
    assert!(!run.interrupted && run.steps_done == n);
    assert!(!run.linear(), "{name} {}: bias {} dominates already at {n}", T::NAME, run.bias_eps);
    let worst = run.worst_ratio(100).unwrap();
    assert!(
        worst <= 2.0,
        "{name} {}: measured/model off by {worst}: {:?}",
        T::NAME,
        run.checkpoints
    );
    let slope = run.slope(100).unwrap();
    assert!((0.35..=0.7).contains(&slope), "{name} {}: slope {slope}", T::NAME);
}

#[test]
fn short_runs_follow_the_random_walk_model() {
    check_random_walk::<f64>("false_euler", 0.1, 20_000);
    check_random_walk::<f32>("false_euler", 0.1, 20_000);
    check_random_walk::<f64>("verlet", 0.1, 20_000);
}

/// The form the study measures is conserved exactly by the rounded program:
/// its rational run (no rounding at all) keeps Q(x) fixed, so any drift
/// measured is the arithmetic's rounding.
#[test]
fn the_form_is_exactly_conserved_by_the_rounded_coefficients() {
    let step = Step::compile(&poly::builtin("false_euler").unwrap(), &Params::phi(0.1)).unwrap();
    let kernel = Kernel::<f64>::new(&step);
    let s = Study::new(kernel.clone(), 1).unwrap();
    let p = kernel.exact_transition();
    let mut x: Vec<poly::Q> = vec![poly::q(3, 10), poly::q(1, 1)];
    let q0 = poly::advanced::invariant::form_value(s.form(), &x);
    for _ in 0..50 {
        x = (0..2).map(|i| &p[i][0] * &x[0] + &p[i][1] * &x[1]).collect();
        assert_eq!(poly::advanced::invariant::form_value(s.form(), &x), q0);
    }
}

/// Stopping early returns the partial result with a checkpoint where it
/// stopped.
#[test]
fn an_interrupted_run_is_partial() {
    let s = study::<f64>("false_euler", 0.1, 8);
    let mut calls = 0;
    let run = s.run(3 * check::drift::CHUNK, 1, |_| {
        calls += 1;
        calls < 2
    });
    assert!(run.interrupted);
    assert!(run.steps_done < 3 * check::drift::CHUNK);
    assert_eq!(run.checkpoints.last().unwrap().steps, run.steps_done);
}

/// The command's JSON: the exact form, the model and the verdict.
#[test]
fn drift_json() {
    let (code, out, err) =
        zcheck(&["drift", "false_euler", "--phi", "0.1", "--steps", "5000", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let r = &v["runs"][0];
    assert_eq!(r["form"], "v^2 - 1/10*v*y + y^2");
    assert_eq!(r["phi"], "1/10");
    assert_eq!(r["steps_done"], 5000);
    assert_eq!(r["within_model"], true, "{r}");
    assert!(r["checkpoints"].as_array().unwrap().len() >= 10);
}

/// A method whose roots leave the unit circle has no drift to study.
#[test]
fn drift_needs_unit_modulus() {
    let (code, _, err) = zcheck(&["drift", "standard_euler", "--phi", "0.1", "--steps", "10"]);
    assert_eq!(code, 2);
    assert!(err.contains("|z| = 1"), "{err}");
    let (code, _, err) = zcheck(&["drift", "false_euler", "--phi", "5/2", "--steps", "10"]);
    assert_eq!(code, 2);
    assert!(err.contains("indefinite"), "{err}");
}

/// Damped Euler's rounded coefficients conserve no form (det P = 1 − Φ² + Φ²
/// is 1 only exactly), so the form at the exact Φ is measured, and says so.
#[test]
fn drift_falls_back_to_the_exact_form() {
    let (code, out, err) =
        zcheck(&["drift", "damped_euler", "--phi", "0.1", "--steps", "2000", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let r = &v["runs"][0];
    assert!(r["form_measured"].as_str().unwrap().contains("exact Phi"), "{r}");
    assert_eq!(r["steps_done"], 2000);
}
