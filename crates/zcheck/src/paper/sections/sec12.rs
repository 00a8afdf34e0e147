//! Section 12, Conclusions: the two recommendations, checked against the
//! exact stability limits and the frequency/amplitude series.

use std::f64::consts::PI;

use super::common::*;
use super::{frequency, ranges};
use crate::paper::{Claim, Verdict};

pub fn claims() -> Vec<Claim> {
    let mut s = Section::new("12", "sec12");
    false_euler(&mut s);
    standard_heun(&mut s);
    s.finish()
}

fn false_euler(s: &mut Section) {
    let r = ranges::report("false_euler");
    let limit = r.phi_max.as_ref().map(ranges::show).unwrap_or_else(|| "none".to_owned());
    let fe = frequency::psi_coeffs("false_euler", 3);
    let sh = frequency::psi_coeffs("standard_heun", 3);
    s.push(
        "use_false_euler",
        "Use False Euler for fast calculations for the specified simple systems, like particle motion, mass and \
         spring systems or celestial motions with low accuracy but guaranteed stability.",
        format!(
            "stable (harmonic, |z| = 1) only for 0 < Φ < {limit}, i.e. more than π steps per period; phase error \
             Ψ − Φ = {}·Φ³ against Standard Heun's {}·Φ³, no amplitude error",
            fe[3], sh[3]
        ),
        Verdict::Refined,
        "poly::stability::analyze(false_euler) gives Φ_max = 2 exactly (double root at −1): stability is \
         guaranteed only under T < T0/π; poly::series gives the phase errors, |z|² = q = 1 exactly",
    );
}

fn standard_heun(s: &mut Section) {
    let r = ranges::report("standard_heun");
    let (_, q) = p_q(&derivation("standard_heun"));
    let rows: Vec<String> = [10.0, 20.0, 50.0, 100.0]
        .iter()
        .map(|&n: &f64| {
            let phi = 2.0 * PI / n;
            let per_period = super::sec09::growth_per_period(eval_f64(&q, phi), phi);
            let doubling = (2f64).ln() / per_period.ln();
            format!(
                "{n} steps/period: ×{} per period, doubles in {} periods",
                fixed(per_period, 5),
                fixed(doubling, 0)
            )
        })
        .collect();
    s.push(
        "use_standard_heun",
        "Use Standard Heun for general systems with medium accuracy and medium speed, if a sufficiently small \
         timestep can be guaranteed.",
        format!(
            "no timestep makes it stable (Φ_max: {}); the amplitude grows by (1 + Φ⁴/4)^(π/Φ) per period: {}",
            r.phi_max.as_ref().map(ranges::show).unwrap_or_else(|| "none, unstable for every Φ > 0".to_owned()),
            rows.join("; ")
        ),
        Verdict::Refined,
        "poly::stability::analyze(standard_heun): no stable Φ > 0; a small step only slows the growth, so \
         'sufficiently small' means small against the simulated duration, not a stability bound",
    );
}
