//! Section 7, False Euler: the update that reads the new v, its z-domain
//! rows, χ, the eigenvalues on the unit circle, "always a harmonic
//! oscillation", the frequency, and the stability limit T/T0 = 1/π.

use std::f64::consts::PI;

use poly::RootClass;

use super::common::*;
use super::{frequency, ranges};
use crate::paper::{Claim, Verdict};

pub fn claims() -> Vec<Claim> {
    let mut s = Section::new("7", "sec07");
    ode_claim(&mut s, "false_euler", "v̇ = −ω0 y, ẏ = ω0 v", OSCILLATOR, Scheme::Consistent);
    stages_claim(
        &mut s,
        "update",
        "false_euler",
        "v = v − Φy;  y = y + Φv   (the second equation uses the new value v)",
        &[
            ("v", Printed { printed: "v = v − Φy", parse: "v - Phi*y" }),
            ("y", Printed { printed: "y = y + Φv (new v)", parse: "y + Phi*(v - Phi*y)" }),
        ],
    );
    z_rows_claim(
        &mut s,
        "false_euler",
        "v = v z⁻¹ − Φ y z⁻¹;  y = Φ v z⁰ + y z⁻¹ = Φ v z⁻¹ + (1 − Φ²) y z⁻¹",
        &[
            ZRow { printed: "v = v z⁻¹ − Φ y z⁻¹", v: "1", y: "-Phi" },
            ZRow { printed: "y = Φ v z⁻¹ + (1 − Φ²) y z⁻¹", v: "Phi", y: "1 - Phi^2" },
        ],
    );
    charpoly_claim(
        &mut s,
        "charpoly",
        "false_euler",
        "z² − 2(1 − Φ²/2)z + 1 = 0",
        "z^2 - 2*(1 - Phi^2/2)*z + 1",
    );
    eigen_claim(
        &mut s,
        "eigenvalues",
        "false_euler",
        "z1/2 = 1 − Φ²/2 ± j(1 − (1 − Φ²/2)²)^0.5",
        "1 - Phi^2/2",
        "1 - (1 - Phi^2/2)^2",
    );
    eigen_claim(
        &mut s,
        "eigenvalues_factored",
        "false_euler",
        "z1/2 = 1 − Φ²/2 ± jΦ(1 − Φ²/4)^0.5",
        "1 - Phi^2/2",
        "Phi^2*(1 - Phi^2/4)",
    );
    unit_circle(&mut s);
    r_squared_claim(&mut s, "false_euler", "r1² = 1", "1");
    let (verdict, map, failing) = ranges::always("false_euler", |c| c == RootClass::Harmonic);
    s.push(
        "always_harmonic",
        "Surprisingly, the solution is always a harmonic oscillation.",
        map,
        verdict,
        format!(
            "exact class map over Φ > 0: the claim fails for {failing}; at Φ = 2 the double root −1 is \
             defective (see sec04.approach_minus_one), beyond it one real root is below −1"
        ),
    );
    tan_claim(
        &mut s,
        "tan_psi",
        "false_euler",
        "tan Ψ = Φ(1 − Φ²/4)^0.5 / (1 − Φ²/2)",
        "Phi^2*(1 - Phi^2/4)",
        "1 - Phi^2/2",
    );
    frequency::approximation(&mut s, "false_euler", "Ψ ≅ Φ(1 + Φ²/24)", "Phi*(1 + Phi^2/24)");
    frequency::too_high(&mut s, "false_euler", "The frequency is always too high.");
    stability_limit(&mut s);
    s.finish()
}

fn unit_circle(s: &mut Section) {
    let (p, q) = p_q(&derivation("false_euler"));
    let disc = &q - &(&p * &p);
    let ok = q.is_one();
    s.push(
        "cos_sin",
        "z1/2 = cos Ψ ± j sin Ψ",
        format!("|z|² = q = {q}; cos Ψ = p = {p}, sin² Ψ = q − p² = {disc}"),
        exact_verdict(ok),
        "q = 1 exactly, so a conjugate pair lies on the unit circle: z = cos Ψ ± j sin Ψ with cos Ψ = p; \
         p² + (q − p²) = 1",
    );
}

fn stability_limit(s: &mut Section) {
    let r = ranges::report("false_euler");
    let phi_max = r.phi_max.clone();
    let (p, q) = p_q(&derivation("false_euler"));
    let im_sq = &q - &(&p * &p);
    let im_zero = ranges::positive_roots(&im_sq);
    let two = poly::Algebraic::from_rational(poly::q(2, 1));
    let limit_is_two = phi_max.as_ref() == Some(&two);
    let boundary = r.boundary.as_ref().map(|b| b.to_string()).unwrap_or_else(|| "none".to_owned());
    let im_text: Vec<String> = im_zero.iter().map(ranges::show).collect();
    s.push(
        "stability_limit",
        "The stability limit results from zero imaginary part of the eigenvalues: Φ² = 4, ω0T = 2, 2π(T/T0) = 2",
        format!(
            "Φ_max = {} (boundary: {boundary}); the imaginary part Φ(1 − Φ²/4)^0.5 vanishes for Φ > 0 at Φ = {}",
            phi_max.as_ref().map(ranges::show).unwrap_or_else(|| "none".to_owned()),
            im_text.join(", ")
        ),
        exact_verdict(limit_is_two && im_zero == vec![two.clone()]),
        "poly::stability::analyze(false_euler): Schur–Cohn conditions and Sturm sequences over Q; the limit \
         is exactly 2, where the pair meets at −1; Φ = ω0·T and Φ = 2π·T/T0",
    );
    s.push(
        "period_ratio",
        "T/T0 = 1/π",
        format!("T/T0 = Φ_max/(2π) = 2/(2π) = 1/π ≈ {}", fixed(1.0 / PI, 4)),
        exact_verdict(limit_is_two),
        "Φ = ω0·T = 2π·T/T0, so T/T0 = Φ/(2π) = 2/(2π) at Φ_max = 2",
    );
    s.push(
        "pi_steps",
        "This means: the integration is stable, if we have more than π steps per period.",
        "T0/T = 2π/Φ > π ⟺ Φ < 2 = Φ_max; at exactly π steps (Φ = 2) it is unstable (defective double root)",
        exact_verdict(limit_is_two),
        "exact limit Φ_max = 2 from poly::stability; the class map shows harmonic on 0 < Φ < 2 only",
    );
    s.push(
        "nyquist",
        "This is a very good result, because the theoretical limit is given by the Nyquist criterion: T/T0 = 1/2.",
        format!(
            "Nyquist: at least 2 samples per period, T/T0 < 1/2 (Φ < π ≈ {}); False Euler is \
             stable up to T/T0 = 1/π ≈ {}, i.e. {}% of the Nyquist step",
            fixed(PI, 4),
            fixed(1.0 / PI, 4),
            fixed(100.0 * (1.0 / PI) / 0.5, 1)
        ),
        Verdict::Confirmed,
        "T/T0 = 1/2 is Ψ = π for the true oscillation (Φ = π); the numeric pair reaches Ψ = π already at \
         Φ = 2, where 2·arcsin(Φ/2) = π",
    );
}
