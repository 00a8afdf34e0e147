//! Section 11, Semi-False Heun: stages, rows, χ, eigenvalues, r², "always
//! stable" (false beyond Φ = √(2√5 − 2)) and "as accurate as Standard Heun".

use poly::RootClass;

use super::common::*;
use super::exact::p_q;
use super::{advice, frequency, ranges};
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::Finding;

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("11", "sec11");
    ode_claim(&mut s, "semi_false_heun", "v̇ = −ω0 y, ẏ = ω0 v", OSCILLATOR, Scheme::Consistent);
    stages_claim(
        &mut s,
        "stages",
        "semi_false_heun",
        "dv(1) = −Φy; v(1) = v − Φy; dy(1) = Φv; y(1) = y + Φv; dv(2) = −Φ(y + Φv); v(2) = v − Φy − Φ²v; \
         dy(2) = Φv(2) = Φ(v − Φy − Φ²v)",
        &[
            ("dv1", Printed { printed: "dv(1) = −Φy", parse: "-Phi*y" }),
            ("v11", Printed { printed: "v(1) = v − Φy", parse: "v - Phi*y" }),
            ("dy1", Printed { printed: "dy(1) = Φv", parse: "Phi*v" }),
            ("y11", Printed { printed: "y(1) = y + Φv", parse: "y + Phi*v" }),
            ("dv2", Printed { printed: "dv(2) = −Φ(y + Φv)", parse: "-Phi*(y + Phi*v)" }),
            ("v12", Printed { printed: "v(2) = v − Φy − Φ²v", parse: "v - Phi*y - Phi^2*v" }),
            ("dy2", Printed { printed: "dy(2) = Φ(v − Φy − Φ²v)", parse: "Phi*(v - Phi*y - Phi^2*v)" }),
        ],
    );
    stages_claim(
        &mut s,
        "update",
        "semi_false_heun",
        "v = v + 0.5(−2Φy − Φ²v);  y = y + 0.5(2Φv − Φ²y − Φ³v);  v = v − Φy − 0.5Φ²v;  y = y + Φv − 0.5Φ²y − 0.5Φ³v",
        &[
            ("v", Printed { printed: "v = v + 0.5(−2Φy − Φ²v)", parse: "v + 1/2*(-2*Phi*y - Phi^2*v)" }),
            ("y", Printed { printed: "y = y + 0.5(2Φv − Φ²y − Φ³v)", parse: "y + 1/2*(2*Phi*v - Phi^2*y - Phi^3*v)" }),
            ("v", Printed { printed: "v = v − Φy − 0.5Φ²v", parse: "v - Phi*y - 1/2*Phi^2*v" }),
            ("y", Printed { printed: "y = y + Φv − 0.5Φ²y − 0.5Φ³v", parse: "y + Phi*v - 1/2*Phi^2*y - 1/2*Phi^3*v" }),
        ],
    );
    z_rows_claim(
        &mut s,
        "semi_false_heun",
        "v = (1 − Φ²/2) v z⁻¹ − Φ y z⁻¹;  y = Φ(1 − Φ²/2) v z⁻¹ + (1 − Φ²/2) y z⁻¹",
        &[
            ZRow {
                printed: "v = (1 − Φ²/2) v z⁻¹ − Φ y z⁻¹", v: "1 - Phi^2/2", y: "-Phi"
            },
            ZRow {
                printed: "y = Φ(1 − Φ²/2) v z⁻¹ + (1 − Φ²/2) y z⁻¹",
                v: "Phi*(1 - Phi^2/2)",
                y: "1 - Phi^2/2",
            },
        ],
    );
    charpoly_claim(
        &mut s,
        "charpoly",
        "semi_false_heun",
        "z² − 2(1 − Φ²/2)z + (1 − Φ⁴/4) = 0",
        "z^2 - 2*(1 - Phi^2/2)*z + (1 - Phi^4/4)",
    );
    eigen_claim(
        &mut s,
        "eigenvalues",
        "semi_false_heun",
        "z1/2 = (1 − Φ²/2) ± jΦ(1 − Φ²/2)^0.5",
        "1 - Phi^2/2",
        "Phi^2*(1 - Phi^2/2)",
    );
    r_squared_claim(&mut s, "semi_false_heun", "r1² = 1 − Φ⁴/4", "1 - Phi^4/4");
    always_stable(&mut s);
    damped_small(&mut s);
    as_accurate(&mut s);
    academic(&mut s);
    s.finish()
}

fn always_stable(s: &mut Section) {
    // The section states no limit: "always" is the assertion.
    let (finding, map, failing) =
        ranges::always("semi_false_heun", |c| c.bounded() == Some(true), None);
    let r = ranges::report("semi_false_heun");
    let limit = ranges::limit_text("semi_false_heun");
    let boundary =
        r.boundary().map(|b| b.to_string().replace('_', " ")).unwrap_or_else(|| "none".to_owned());
    let chi_minus_one =
        builtin_derivation("semi_false_heun").charpoly().subs(poly::Sym::z(), &poly::Poly::int(-1));
    let crossings: Vec<String> =
        ranges::positive_roots(&chi_minus_one).iter().map(ranges::show).collect();
    s.push(
        "always_stable",
        "The solution is always stable ...",
        format!("stable only for 0 < Φ < {limit} (boundary: {boundary}); classes: {map}"),
        finding,
        format!(
            "Derivation::stability: χ(−1) = {chi_minus_one} vanishes at Φ = {}, where a real root leaves the \
             unit disc through −1; the section gives no limit, and the method is unbounded for {failing}",
            crossings.join(", ")
        ),
    );
    s.correct(format!("The solution is stable for 0 < Φ < {limit} only."));
}

fn damped_small(s: &mut Section) {
    let map = ranges::class_map("semi_false_heun");
    let first = map.first().and_then(|(_, c)| *c);
    let (p, q) = p_q(&builtin_derivation("semi_false_heun"));
    let disc = &q - &(&p * &p);
    s.push(
        "damped_small_steps",
        "... and for sufficiently small timesteps T a damped oscillation",
        ranges::class_map_text(&map[..1]),
        Finding::all([(
            "the first piece of Φ > 0 is a damped oscillation",
            first == Some(RootClass::DampedOscillation),
        )]),
        format!(
            "exact class map: q − p² = {disc} ({}) and q = {q} ({})",
            ranges::sign_text(&disc, "a complex pair", "real roots"),
            ranges::sign_text(&(&q - &poly::Poly::one()), "r > 1", "r < 1"),
        ),
    );
}

fn as_accurate(s: &mut Section) {
    let d_sf = builtin_derivation("semi_false_heun");
    let d_sh = builtin_derivation("standard_heun");
    let psi_sf = frequency::psi_coeffs("semi_false_heun", 5);
    let psi_sh = frequency::psi_coeffs("standard_heun", 5);
    let m_sf = poly::advanced::series::modulus_sq_series(d_sf.charpoly(), 6).expect("series");
    let m_sh = poly::advanced::series::modulus_sq_series(d_sh.charpoly(), 6).expect("series");
    let disp = |d: &poly::Derivation| {
        poly::advanced::series::dispersion_order(d.charpoly()).expect("series").map(|t| t.order)
    };
    let diss = |d: &poly::Derivation| {
        poly::advanced::series::dissipation_order(d.charpoly()).expect("series").map(|t| t.order)
    };
    let (sf, sh) = (advice::criteria("semi_false_heun"), advice::criteria("standard_heun"));
    s.push(
        "as_accurate",
        "... as accurate as Standard Heun (which is unstable).",
        format!(
            "Semi-False Heun: Ψ = {}, |z|² = {}; Standard Heun: Ψ = {}, |z|² = {}; {}; {}",
            frequency::series_poly(&psi_sf),
            frequency::series_poly(&m_sf),
            frequency::series_poly(&psi_sh),
            frequency::series_poly(&m_sh),
            orders("dispersion", disp(&d_sf), disp(&d_sh)),
            orders("dissipation", diss(&d_sf), diss(&d_sh)),
        ),
        Finding::all([
            ("the same dispersion order", disp(&d_sf) == disp(&d_sh)),
            ("the same dissipation order", diss(&d_sf) == diss(&d_sh)),
        ]),
        format!(
            "poly's exact series on both χ: leading phase errors {} against {}, leading amplitude errors {} against {}",
            term(&sf.phase),
            term(&sh.phase),
            term(&sf.amplitude),
            term(&sh.amplitude)
        ),
    );
}

fn term(t: &Option<(usize, poly::Q)>) -> String {
    t.as_ref().map_or_else(|| "0".to_owned(), |(k, c)| format!("{c}·Φ^{k}"))
}

/// Two methods' orders of one error, said once when they agree.
fn orders(what: &str, semi_false: Option<usize>, standard: Option<usize>) -> String {
    if semi_false == standard {
        format!("both of {what} order {}", show_order(semi_false))
    } else {
        format!(
            "{what} orders {} (Semi-False Heun) and {} (Standard Heun)",
            show_order(semi_false),
            show_order(standard)
        )
    }
}

fn show_order(k: Option<usize>) -> String {
    k.map_or_else(|| "none".to_owned(), |k| format!("Φ^{k}"))
}

/// "Because of the odd programming structure and the limited scope of
/// applications, Semi-False Heun cannot be recommended. It's merely an
/// academic example."
fn academic(s: &mut Section) {
    let own = advice::criteria("semi_false_heun");
    let dominating = advice::dominated_by(&own, &poly::advanced::builtins::PAPER_METHODS);
    let by: Vec<String> = dominating
        .iter()
        .map(|(c, better)| format!("{} (better on {})", advice::text(c), better.join(", ")))
        .collect();
    s.push(
        "academic_example",
        "Because of the odd programming structure and the limited scope of applications, Semi-False Heun cannot \
         be recommended. It's merely an academic example.",
        format!(
            "{}; dominated on the paper's criteria by: {}",
            advice::text(&own),
            if by.is_empty() { "none".to_owned() } else { by.join("; ") }
        ),
        Finding::all([(
            "another method of the paper is at least as good on every criterion of section 1 and better on one",
            !dominating.is_empty(),
        )]),
        "exact Φ_max (Derivation::stability), leading terms of Ψ − Φ and |z|² − 1 (poly's exact series), operations per \
         step (Derivation::cost), for every method of sections 5–11; \"odd structure\" and \"limited scope\" \
         are judgements zcheck does not check",
    );
}
