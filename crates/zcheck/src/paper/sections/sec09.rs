//! Section 9, Standard Heun: the predictor–corrector for linear systems,
//! the test ODE as printed (a misprint), the stages, χ, eigenvalues, r²,
//! "always an unstable oscillation", tan Ψ and the frequency.

use super::common::*;
use super::exact::p_q;
use super::frequency;
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::{Finding, Scope};

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("9", "sec09");
    scheme(&mut s);
    scheme_with_input(&mut s);
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
    always_unstable_claim(&mut s, "standard_heun");
    weak_instability(&mut s);
    tan_claim(&mut s, "tan_psi", "standard_heun", "tan Ψ = Φ / (1 − Φ²/2)", "Phi^2", "1 - Phi^2/2");
    frequency::approximation(&mut s, "standard_heun", "Ψ ≅ Φ·(1 + Φ²/6)", "Phi*(1 + Phi^2/6)");
    frequency::too_high(&mut s, "standard_heun", "The frequency is always too high.");
    s.finish()
}

fn scheme(s: &mut Section) {
    let defect =
        scheme_defect(&builtin_derivation("standard_heun"), &ode_matrix(OSCILLATOR), Scheme::Heun);
    s.push(
        "scheme",
        "dy(1) = τ(Ay + Bx); y(1) = y + dy(1); dy(2) = τ(Ay(1) + Bx); dy = 0.5(dy(1) + dy(2)); y = y + dy",
        format!(
            "standard_heun: P = {}",
            matrix_text(builtin_derivation("standard_heun").transition_matrix())
        ),
        Finding::same(matrix_text(&defect), matrix_text(&poly::PolyMatrix::zeros(2, 2))),
        "for x = 0 the scheme is y ← (I + τA + (τA)²/2) y; the built-in program (Appendix B case 5) gives \
         exactly that P with A = [[0, −1], [1, 0]] and τ·ω0 = Φ",
    );
}

/// The growth of the amplitude over one true period, r^(2π/Φ).
pub(crate) fn growth_per_period(r_squared: f64, phi: f64) -> f64 {
    r_squared.powf(std::f64::consts::PI / phi)
}

fn weak_instability(s: &mut Section) {
    let (_, q) = p_q(&builtin_derivation("standard_heun"));
    let steps = [10.0, 20.0, 50.0, 100.0];
    let growth: Vec<f64> = steps
        .iter()
        .map(|&n: &f64| {
            let phi = 2.0 * std::f64::consts::PI / n;
            growth_per_period(eval_f64(&q, phi), phi)
        })
        .collect();
    let rows: Vec<String> = steps
        .iter()
        .zip(&growth)
        .map(|(n, g)| format!("{n} steps/period: ×{}", fixed(*g, 5)))
        .collect();
    // ln(growth per period) = (π/Φ)·ln q ~ π·c·Φ^(k−1) for q − 1 = c·Φ^k + ...
    let excess = &q - &poly::Poly::one();
    let lowest = excess.coeffs_in(poly::Sym::phi()).iter().position(|c| !c.is_zero());
    s.push(
        "weak_instability",
        "For sufficiently small timesteps τ the instability is weak.",
        format!(
            "r² − 1 = {excess}; amplitude growth per true period (r²)^(π/Φ): {}",
            rows.join(", ")
        ),
        Finding::all([
            ("the growth per period shrinks as the step shrinks (10 → 100 steps per period)".to_owned(), growth.windows(2).all(|w| w[1] < w[0])),
            (
                format!("the growth per period tends to 1 as Φ → 0 (r² − 1 starts at Φ^{})", lowest.unwrap_or(0)),
                lowest.is_some_and(|k| k >= 2),
            ),
            ("the growth never reaches 1 (unstable at every step)".to_owned(), growth.iter().all(|g| *g > 1.0)),
        ]),
        format!(
            "r² = q exactly; ln(growth per period) = (π/Φ)·ln q ~ Φ^{} → 0, but never 0: unstable for every Φ > 0",
            lowest.map_or(0, |k| k.saturating_sub(1))
        ),
    );
}

/// Section 9's general formulation with an input x: the corrector
/// dy(2) = τ(Ay(1) + Bx) reuses x at the start of the step. For a scalar
/// ẏ = a·y + x(t), x(t) = x0 + x1·t, one step is compared exactly with the
/// Taylor expansion of the true solution through τ².
fn scheme_with_input(s: &mut Section) {
    use poly::{Poly, Sym};
    let tau_sym = Sym::new("tau");
    let (a, y, x0, x1, tau) =
        (Poly::var("a"), Poly::var("y"), Poly::var("x0"), Poly::var("x1"), Poly::sym(tau_sym));
    let half = poly::q(1, 2);
    let through = |p: &Poly, k: usize| {
        let mut c = p.coeffs_in(tau_sym);
        c.truncate(k + 1);
        Poly::from_coeffs_in(tau_sym, &c)
    };
    let f = |y: &Poly, x: &Poly| &(&a * y) + x;
    // The printed scheme, and Heun with x(t + τ) in the corrector.
    let dy1 = &tau * &f(&y, &x0);
    let y1 = &y + &dy1;
    let printed = &y + &(&dy1 + &(&tau * &f(&y1, &x0))).scale(&half);
    let x_end = &x0 + &(&x1 * &tau);
    let heun = &y + &(&dy1 + &(&tau * &f(&y1, &x_end))).scale(&half);
    // y(τ) = y + τ·ẏ + τ²/2·ÿ with ẏ = a y + x0, ÿ = a ẏ + x1.
    let yd = f(&y, &x0);
    let ydd = &(&a * &yd) + &x1;
    let exact = &(&y + &(&tau * &yd)) + &(&(&tau * &tau) * &ydd).scale(&half);
    let err_printed = through(&(&printed - &exact), 2);
    let err_heun = through(&(&heun - &exact), 2);
    let err_constant = err_printed.subs(Sym::new("x1"), &Poly::zero());
    s.push(
        "scheme_with_input",
        "dy(1) = τ(Ay + Bx); y(1) = y + dy(1); dy(2) = τ(Ay(1) + Bx); dy = 0.5(dy(1) + dy(2))   (general \
         formulation with an input x)",
        format!(
            "for ẏ = a·y + x(t), x = x0 + x1·t, the printed step (x at the start in both stages) differs from \
             the true solution by {err_printed} + O(τ³): first order in the input unless x is held over the \
             step; with x(t + τ) in the corrector the difference is {} + O(τ³)",
            if err_heun.is_zero() { "0".to_owned() } else { err_heun.to_string() }
        ),
        Finding::scoped([
            (
                "input held constant over the step (x1 = 0, the sampled x_(i−1) of section 4): second order"
                    .to_owned(),
                err_constant.is_zero(),
                Scope::Stated,
            ),
            (
                format!("time-varying input (x1 ≠ 0): second order, local error {err_printed}"),
                err_printed.is_zero(),
                Scope::wording(
                    "section 4 samples the input once per step (x_(i−1)), the case stated; an input that \
                     varies within the step is reached only by the words \"general formulation\"",
                ),
            ),
        ]),
        "exact symbolic step (poly) against the Taylor expansion of the true solution, truncated after τ²",
    );
}
