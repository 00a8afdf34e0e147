//! Section 7, False Euler: the update that reads the new v, its z-domain
//! rows, χ, the eigenvalues on the unit circle, "always a harmonic
//! oscillation", the frequency, and the stability limit T/T0 = 1/π.

use std::f64::consts::PI;

use poly::RootClass;

use super::common::*;
use super::exact::{at_phi, p_q, paper};
use super::{frequency, ranges};
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::{Finding, Scope};

pub(crate) fn claims() -> Vec<Claim> {
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
    // Section 7 states its own limit a few lines on: Φ² = 4.
    let (finding, map, failing) =
        ranges::always("false_euler", |c| c == RootClass::Harmonic, Some("Phi^2 - 4"));
    s.push(
        "always_harmonic",
        "Surprisingly, the solution is always a harmonic oscillation.",
        map,
        finding,
        format!(
            "exact class map over Φ > 0: the claim holds below the section's own limit Φ² = 4 and fails for \
             {failing}; at Φ = 2 the double root −1 is defective (see sec04.approach_minus_one), beyond it one \
             real root is below −1"
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
    let (p, q) = p_q(&builtin_derivation("false_euler"));
    let disc = &q - &(&p * &p);
    s.push(
        "cos_sin",
        "z1/2 = cos Ψ ± j sin Ψ",
        format!("|z|² = q = {q}; cos Ψ = p = {p}, sin² Ψ = q − p² = {disc}"),
        // cos²Ψ + sin²Ψ = 1: the printed form needs |z|² = q = 1.
        Finding::same(poly::Poly::one(), &q),
        format!(
            "q = {q} exactly, so a conjugate pair lies on the unit circle: z = cos Ψ ± j sin Ψ with cos Ψ = p; \
             p² + (q − p²) = {}",
            &(&p * &p) + &disc
        ),
    );
}

fn stability_limit(s: &mut Section) {
    let r = ranges::report("false_euler");
    let phi_max = ranges::limit_of(&r);
    let (p, q) = p_q(&builtin_derivation("false_euler"));
    let im_sq = &q - &(&p * &p);
    let im_zero = ranges::positive_roots(&im_sq);
    // What the paper prints, as numbers: Φ² = 4; T/T0 = 1/π, i.e.
    // Φ = 2π·T/T0 = 2; more than π steps per period, i.e. Φ < 2π/π = 2.
    let printed = ranges::positive_roots(&paper("Phi^2 - 4"));
    let show_all =
        |v: &[poly::Algebraic]| v.iter().map(ranges::show).collect::<Vec<_>>().join(", ");
    let limit = phi_max.as_ref().map(ranges::show).unwrap_or_else(|| "none".to_owned());
    let boundary = r.boundary().map(|b| b.to_string()).unwrap_or_else(|| "none".to_owned());
    // T/T0 = 1/π as a step: Φ = 2π·T/T0 = 2π/π.
    let period_ratio = poly::q(2, 1);
    s.push(
        "stability_limit",
        "The stability limit results from zero imaginary part of the eigenvalues: Φ² = 4, ω0T = 2, 2π(T/T0) = 2",
        format!(
            "Φ_max = {limit} (boundary: {}); the imaginary part Φ(1 − Φ²/4)^0.5 vanishes for Φ > 0 at Φ = {}",
            boundary.replace('_', " "),
            show_all(&im_zero)
        ),
        Finding::all([
            (format!("Φ_max = {limit} equals the printed Φ = {}", show_all(&printed)), show_all(&printed) == limit),
            (
                format!("the imaginary part vanishes at Φ = {} only", show_all(&im_zero)),
                im_zero == printed,
            ),
        ]),
        "Derivation::stability(false_euler): Sturm sequences over Q on the stability conditions; the \
         limit is where the pair meets at −1; Φ = ω0·T and Φ = 2π·T/T0",
    );
    s.push(
        "period_ratio",
        "T/T0 = 1/π",
        format!("T/T0 = Φ_max/(2π) with Φ_max = {limit}; the printed 1/π means Φ = 2π·(1/π) = {period_ratio}"),
        Finding::same(ranges::show(&poly::Algebraic::from_rational(period_ratio.clone())), &limit),
        "Φ = ω0·T = 2π·T/T0, so T/T0 = 1/π is Φ = 2 exactly; compared with the exact Φ_max",
    );
    s.push(
        "pi_steps",
        "This means: the integration is stable, if we have more than π steps per period.",
        format!(
            "T0/T = 2π/Φ > π ⟺ Φ < 2; Φ_max = {limit}; at exactly π steps (Φ = 2) it is unstable (defective \
             double root)"
        ),
        Finding::same(ranges::show(&poly::Algebraic::from_rational(period_ratio)), &limit),
        "more than π steps per period is Φ < 2π/π = 2 exactly; compared with the exact Φ_max from \
         Derivation::stability",
    );
    nyquist(s, phi_max.as_ref());
}

/// "The theoretical limit is given by the Nyquist criterion: T/T0 = 1/2."
/// Nyquist bounds what a sample sequence can represent (Ψ ≤ π), not which
/// steps are stable: the trapezoidal rule on the same oscillator,
/// χ = (4 + Φ²)z² − 2(4 − Φ²)z + (4 + Φ²), is harmonic at every Φ.
fn nyquist(s: &mut Section, phi_max: Option<&poly::Algebraic>) {
    let a = paper("4 + Phi^2");
    let b_half = paper("-(4 - Phi^2)");
    let c = paper("4 + Phi^2");
    // Roots on the unit circle for every Φ > 0: product c/a = 1 and a
    // negative discriminant (b/2)² − ac.
    let disc = &(&b_half * &b_half) - &(&a * &c);
    let disc_negative =
        ranges::positive_roots(&disc).is_empty() && at_phi(&disc, &poly::q(1, 1)) < poly::q(0, 1);
    let trapezoid_harmonic = a == c && disc_negative;
    // Samples per period of the exact oscillation at T/T0 = 1/2: Ψ = Φ = π.
    let nyquist_samples = poly::q(360, 180);
    let fe_limit = phi_max.map(ranges::show).unwrap_or_else(|| "none".to_owned());
    s.push(
        "nyquist",
        "This is a very good result, because the theoretical limit is given by the Nyquist criterion: T/T0 = 1/2.",
        format!(
            "as a limit of representation it is right: at T/T0 = 1/2 the exact oscillation has Ψ = π, {} samples \
             per period, the fewest that show it; as a limit of stability it is not: the trapezoidal rule on the \
             same oscillator has χ = ({a})z² + 2({b_half})z + ({c}), discriminant/4 = {disc} < 0 and |z|² = 1 \
             at every Φ, stable far beyond T/T0 = 1/2. False Euler's Φ_max = {fe_limit} is {}% of the Nyquist \
             step Φ = π",
            nyquist_samples,
            fixed(100.0 * phi_max.map_or(f64::NAN, |x| x.to_decimal(12).parse::<f64>().unwrap_or(f64::NAN)) / PI, 1)
        ),
        Finding::scoped([
            (
                "read as the resolution limit: Ψ ≤ π, at least 2 samples per period".to_owned(),
                nyquist_samples == poly::q(2, 1),
                Scope::Stated,
            ),
            (
                "read as a stability limit: no method is stable beyond T/T0 = 1/2".to_owned(),
                !trapezoid_harmonic,
                Scope::wording(
                    "Nyquist's criterion bounds what samples can represent; the paper compares False Euler's \
                     limit with it, and only that comparison's wording makes it a bound on stability",
                ),
            ),
        ]),
        format!(
            "exact: 360°/180° = {nyquist_samples} samples; the trapezoidal χ has equal leading and constant \
             coefficients ({}) and discriminant {disc}, so its roots are a conjugate pair on the unit circle for \
             every Φ > 0 (Poly, Sturm)",
            if a == c { "product of the roots 1" } else { "product of the roots not 1" }
        ),
    );
}
