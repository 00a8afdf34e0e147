//! Section 12 (Conclusions): "use False Euler ... with guaranteed
//! stability" holds only for T < T0/π; "use Standard Heun ... if a
//! sufficiently small timestep can be guaranteed" — no timestep makes it
//! stable, the amplitude grows by (1 + Φ⁴/4)^(π/Φ) per period, which is the
//! weak instability section 9 states, so the recommendation is confirmed; the
//! satellite's drift is asserted for high-quality integration (RK4) only.

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec12.use_false_euler", Refined),
    ("sec12.use_standard_heun", Confirmed),
    ("sec12.professional_methods", Confirmed),
    ("sec12.satellite_drift", Confirmed),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// False Euler: bounded below Φ = 2, unbounded at and above it; its phase
/// error is smaller than Standard Heun's (Φ³/24 against Φ³/6).
#[test]
fn false_euler_stability_is_conditional() {
    assert!(growth_ratio("false_euler", 1.99, 4000) < 1.01);
    assert!(growth_ratio("false_euler", 2.0, 4000) > 2.5);
    assert!(late_amplitude("false_euler", 2.2, 400) > 1e6);
    let phi: f64 = 0.05;
    let fe = psi("false_euler", phi).unwrap() - phi;
    let sh = psi("standard_heun", phi).unwrap() - phi;
    assert!(fe > 0.0 && sh > 0.0 && fe < sh / 3.0, "{fe} vs {sh}");
}

/// Standard Heun grows at every step size; halving the step reduces the
/// growth per period about eightfold (∝ Φ³) but never to zero.
#[test]
fn standard_heun_is_never_stable() {
    let growth = |steps: f64| {
        let phi = 2.0 * std::f64::consts::PI / steps;
        (1.0 + phi.powi(4) / 4.0).powf(std::f64::consts::PI / phi) - 1.0
    };
    for steps in [10.0, 20.0, 50.0, 100.0, 1000.0] {
        assert!(growth(steps) > 0.0);
        let ratio = growth(steps) / growth(2.0 * steps);
        assert!(ratio > 7.0 && ratio < 9.0, "{steps}: {ratio}");
    }
    assert!(late_amplitude("standard_heun", 2.0 * std::f64::consts::PI / 20.0, 20 * 200) > 100.0);
}
