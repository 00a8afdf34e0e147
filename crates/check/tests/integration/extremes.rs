//! The extremes: Φ = 1e-8, where |z| − 1 lies far below machine epsilon,
//! and a stability limit (False Euler at Φ = 2: a double root at −1, a Jordan
//! block, linear growth).

use check::numeric::ParamsF64;
use std::collections::HashMap;

use check::classify::classify_roots;
use check::numeric::{f64_to_q, q_to_f64, Params};
use check::witness::Witnesses;
use poly::{RootClass, Sym, Q};

/// ln ρ at Φ = 1e-8 from the cancellation-free form equals the exact value
/// (x = q − 1 in rationals, ½·ln(1 + x) by its series x − x²/2 + x³/3, whose
/// next term is below 1e-60 relative) to within 2 ulps.
#[track_caller]
fn check_growth_at_tiny_phi(name: &str) {
    let phi = 1e-8;
    let m = poly::builtin(name).unwrap();
    let d = poly::derive(&m).unwrap();
    let (_, q) = d.p_q().unwrap();
    let mut at: HashMap<Sym, Q> = HashMap::new();
    at.insert(Sym::phi(), f64_to_q(phi).unwrap());
    at.insert(Sym::new("D"), f64_to_q(0.3).unwrap());
    let x = q.eval(&at).unwrap() - Q::from_integer(1.into());
    let series =
        &x - &(&x * &x) / Q::from_integer(2.into()) + &(&x * &x * &x) / Q::from_integer(3.into());
    let exact = q_to_f64(&(series / Q::from_integer(2.into())));
    let w = Witnesses::new(&m).unwrap();
    let got = w.charpoly().at(&Params::phi(phi).with("D", 0.3)).unwrap();
    assert!(
        (got.growth_per_step - exact).abs() <= 2.0 * f64::EPSILON * exact.abs(),
        "{name}: ln rho = {:e}, exact {exact:e}",
        got.growth_per_step
    );
    // The naive form rounds q to f64 first and loses everything below eps.
    let naive = 0.5 * q_to_f64(&q.eval(&at).unwrap()).ln();
    if exact.abs() < f64::EPSILON / 4.0 {
        assert_eq!(naive, 0.0, "{name}: the naive form should cancel");
    }
}

#[test]
fn growth_per_step_at_phi_1e_minus_8_is_exact() {
    // ln rho: 5e-17 (Standard Euler), -2.5e-17 (False Heun), 2.5e-33
    // (Standard Heun), -1.25e-33 (Semi-False Heun), -3e-9 (Damped Euler, D = 0.3).
    for name in
        ["standard_euler", "false_heun", "standard_heun", "semi_false_heun", "damped_euler_d"]
    {
        check_growth_at_tiny_phi(name);
    }
}

/// Ψ at Φ = 1e-8 keeps full relative accuracy: for False Euler
/// cos Ψ = 1 − Φ²/2, so Ψ = 2·asin(Φ/2) exactly (a naive atan2 of the
/// rounded p gives 0).
#[test]
fn psi_at_phi_1e_minus_8_is_accurate() {
    let phi = 1e-8;
    let w = Witnesses::new(&poly::builtin("false_euler").unwrap()).unwrap();
    let got = w.charpoly().at(&Params::phi(phi)).unwrap();
    let exact = 2.0 * (phi / 2.0).asin();
    assert!((got.psi - exact).abs() <= 2.0 * f64::EPSILON * exact, "{} vs {exact}", got.psi);
    let p_rounded: f64 = 1.0 - phi * phi / 2.0;
    assert_eq!(p_rounded, 1.0, "the rounded p has lost Phi^2/2");
}

/// At Φ = 1e-8 Standard Euler is exactly an unstable oscillation
/// (q − 1 = Φ² > 0), but no numeric eigenvalue can resolve |z| − 1 = 5e-17:
/// classified with their tolerances they read harmonic. The class therefore
/// comes from the exact form, and the witnesses are judged by distance.
#[test]
fn tiny_phi_class_comes_from_the_exact_form() {
    let w = Witnesses::new(&poly::builtin("standard_euler").unwrap()).unwrap();
    let r = w.at(&Params::phi(1e-8), 10_000).unwrap();
    assert_eq!(r.exact.class, RootClass::UnstableOscillation);
    assert_eq!(classify_roots(&r.nalgebra, &r.tolerance), RootClass::Harmonic);
    assert!(r.agree(), "{:?}", r.checks);
}

/// False Euler at the limit Φ = 2 and its two neighbouring floats: every
/// witness agrees at 10^6 steps; the numeric eigenvalues of all three read a
/// double root on the circle within the √ε-scale radius, while the exact
/// class tells harmonic | double root | alternating unstable apart.
#[test]
fn false_euler_at_its_stability_limit() {
    let w = Witnesses::new(&poly::builtin("false_euler").unwrap()).unwrap();
    let expected = [
        (2f64.next_down(), RootClass::Harmonic),
        (2.0, RootClass::DoubleRootOnCircle),
        (2f64.next_up(), RootClass::AlternatingUnstable),
    ];
    for (phi, class) in expected {
        let steps = if phi == 2.0 { 1_000_000 } else { 100_000 };
        let r = w.at(&Params::phi(phi), steps).unwrap();
        assert_eq!(r.exact.class, class, "exact class at {phi}");
        assert!(r.agree(), "at {phi}: {:?}", r.checks);
        assert_eq!(r.cluster, [2, 2], "a cluster of two roots at {phi}");
        for found in [&r.nalgebra, &r.faer] {
            assert_eq!(
                classify_roots(found, &r.tolerance),
                RootClass::DoubleRootOnCircle,
                "numeric class at {phi}"
            );
        }
        // The radius is the sqrt(eps) scale, not the eps scale.
        assert!(
            r.tolerance[0] > 1e3 * f64::EPSILON.sqrt() * f64::EPSILON.sqrt(),
            "{:?}",
            r.tolerance
        );
        assert!(r.tolerance[0] < 1e3 * f64::EPSILON.sqrt(), "{:?}", r.tolerance);
    }
    // The Jordan block grows linearly: P^n = (-1)^n (I - n (P + I)), so the
    // norm grows like n while the mode itself (measured by its left
    // eigenvector) neither grows nor decays.
    let r = w.at(&Params::phi(2.0), 1_000_000).unwrap();
    let sim = r.sim.unwrap();
    let n = sim.steps as f64;
    let log_growth = sim.norm_growth_per_step * n;
    assert!(
        (n.ln() - 5.0..=n.ln() + 2.0).contains(&log_growth),
        "ln(|x_n|/|x_0|) = {log_growth}, ln n = {}",
        n.ln()
    );
    assert!(
        sim.growth_per_step.abs() <= 64.0 * f64::EPSILON,
        "mode growth {}",
        sim.growth_per_step
    );
    assert!(
        (sim.psi_per_step - std::f64::consts::PI).abs() <= 64.0 * f64::EPSILON,
        "psi {}",
        sim.psi_per_step
    );
}
