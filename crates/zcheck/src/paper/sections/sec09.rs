//! Section 9, Standard Heun: the predictor–corrector for linear systems,
//! the test ODE as printed (a misprint), the stages, χ, eigenvalues, r²,
//! "always an unstable oscillation", tan Ψ and the frequency.

use poly::RootClass;

use super::common::*;
use super::{frequency, ranges};
use crate::paper::{Claim, Verdict};

pub fn claims() -> Vec<Claim> {
    let mut s = Section::new("9", "sec09");
    scheme(&mut s);
    ode_claim(
        &mut s,
        "standard_heun",
        "v̇ = −ω0 v, ẏ = ω0 y",
        [["-1", "0"], ["0", "1"]],
        Scheme::Heun,
    );
    stages_claim(
        &mut s,
        "stages",
        "standard_heun",
        "dv(1) = −Φy; dy(1) = Φv; v(1) = v − Φy; y(1) = y + Φv; dv(2) = −Φ(y + Φv); dy(2) = Φ(v − Φy)",
        &[
            ("dv1", Printed { printed: "dv(1) = −Φy", parse: "-Phi*y" }),
            ("dy1", Printed { printed: "dy(1) = Φv", parse: "Phi*v" }),
            ("v11", Printed { printed: "v(1) = v − Φy", parse: "v - Phi*y" }),
            ("y11", Printed { printed: "y(1) = y + Φv", parse: "y + Phi*v" }),
            ("dv2", Printed { printed: "dv(2) = −Φ(y + Φv)", parse: "-Phi*(y + Phi*v)" }),
            ("dy2", Printed { printed: "dy(2) = Φ(v − Φy)", parse: "Phi*(v - Phi*y)" }),
        ],
    );
    z_rows_claim(
        &mut s,
        "standard_heun",
        "v = (1 − Φ²/2)v z⁻¹ − Φ y z⁻¹;  y = Φ v z⁻¹ + (1 − Φ²/2)y z⁻¹",
        &[
            ZRow {
                printed: "v = (1 − Φ²/2)v z⁻¹ − Φ y z⁻¹", v: "1 - Phi^2/2", y: "-Phi"
            },
            ZRow {
                printed: "y = Φ v z⁻¹ + (1 − Φ²/2)y z⁻¹", v: "Phi", y: "1 - Phi^2/2"
            },
        ],
    );
    charpoly_claim(
        &mut s,
        "charpoly",
        "standard_heun",
        "z² − 2(1 − Φ²/2)z + (1 + Φ⁴/4) = 0",
        "z^2 - 2*(1 - Phi^2/2)*z + (1 + Phi^4/4)",
    );
    eigen_claim(
        &mut s,
        "eigenvalues",
        "standard_heun",
        "z1/2 = (1 − Φ²/2) ± jΦ",
        "1 - Phi^2/2",
        "Phi^2",
    );
    r_squared_claim(&mut s, "standard_heun", "r1² = 1 + Φ⁴/4", "1 + Phi^4/4");
    let (verdict, map, failing) =
        ranges::always("standard_heun", |c| c == RootClass::UnstableOscillation);
    s.push(
        "always_unstable",
        "The solution is always an unstable oscillation.",
        map,
        verdict,
        if failing.is_empty() {
            "exact class map over all Φ > 0: q − p² = Φ² > 0 and q = 1 + Φ⁴/4 > 1".to_owned()
        } else {
            format!("exact class map: fails for {failing}")
        },
    );
    weak_instability(&mut s);
    tan_claim(&mut s, "tan_psi", "standard_heun", "tan Ψ = Φ / (1 − Φ²/2)", "Phi^2", "1 - Phi^2/2");
    frequency::approximation(&mut s, "standard_heun", "Ψ ≅ Φ·(1 + Φ²/6)", "Phi*(1 + Phi^2/6)");
    frequency::too_high(&mut s, "standard_heun", "The frequency is always too high.");
    s.finish()
}

fn scheme(s: &mut Section) {
    let defect = scheme_defect(&derivation("standard_heun"), &ode_matrix(OSCILLATOR), Scheme::Heun);
    s.push(
        "scheme",
        "dy(1) = τ(Ay + Bx); y(1) = y + dy(1); dy(2) = τ(Ay(1) + Bx); dy = 0.5(dy(1) + dy(2)); y = y + dy",
        format!("standard_heun: P = {}", matrix_text(&derivation("standard_heun").transition_matrix)),
        exact_verdict(is_zero_matrix(&defect)),
        "for x = 0 the scheme is y ← (I + τA + (τA)²/2) y; the built-in program (Appendix B case 5) gives \
         exactly that P with A = [[0, −1], [1, 0]] and τ·ω0 = Φ",
    );
}

/// The growth of the amplitude over one true period, r^(2π/Φ).
pub fn growth_per_period(r_squared: f64, phi: f64) -> f64 {
    r_squared.powf(std::f64::consts::PI / phi)
}

fn weak_instability(s: &mut Section) {
    let (_, q) = p_q(&derivation("standard_heun"));
    let rows: Vec<String> = [10.0, 20.0, 50.0, 100.0]
        .iter()
        .map(|&n: &f64| {
            let phi = 2.0 * std::f64::consts::PI / n;
            format!("{n} steps/period: ×{}", fixed(growth_per_period(eval_f64(&q, phi), phi), 5))
        })
        .collect();
    s.push(
        "weak_instability",
        "For sufficiently small timesteps τ the instability is weak.",
        format!("r² − 1 = {}; amplitude growth per true period (1 + Φ⁴/4)^(π/Φ) ≈ 1 + πΦ³/4: {}", &q - &poly::Poly::one(), rows.join(", ")),
        Verdict::Confirmed,
        "r² = q exactly; the growth per period tends to 1 as Φ → 0, but never reaches it: unstable for every Φ > 0",
    );
}
