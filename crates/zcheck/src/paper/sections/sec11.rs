//! Section 11, Semi-False Heun: stages, rows, χ, eigenvalues, r², "always
//! stable" (false beyond Φ = √(2√5 − 2)) and "as accurate as Standard Heun".

use poly::RootClass;

use super::common::*;
use super::{frequency, ranges};
use crate::paper::{Claim, Verdict};

pub fn claims() -> Vec<Claim> {
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
    s.finish()
}

fn always_stable(s: &mut Section) {
    let (verdict, map, failing) = ranges::always("semi_false_heun", RootClass::is_bounded);
    let r = ranges::report("semi_false_heun");
    let limit = r.phi_max.as_ref().map(ranges::show).unwrap_or_else(|| "none".to_owned());
    let boundary = r.boundary.as_ref().map(|b| b.to_string()).unwrap_or_else(|| "none".to_owned());
    s.push(
        "always_stable",
        "The solution is always stable ...",
        format!("stable only for 0 < Φ < {limit} (boundary: {boundary}); classes: {map}"),
        verdict,
        format!(
            "poly::stability::analyze: χ(−1) = 4 − Φ² − Φ⁴/4 vanishes at Φ² = 2√5 − 2, where a real root \
             leaves the unit disc through −1; unbounded for {failing}"
        ),
    );
}

fn damped_small(s: &mut Section) {
    let map = ranges::class_map("semi_false_heun");
    let first = map.first().and_then(|(_, c)| *c);
    s.push(
        "damped_small_steps",
        "... and for sufficiently small timesteps T a damped oscillation",
        ranges::class_map_text(&map[..1]),
        exact_verdict(first == Some(RootClass::DampedOscillation)),
        "exact class map: the first piece of Φ > 0 is a damped oscillation (q − p² = Φ²(1 − Φ²/2) > 0, \
         q = 1 − Φ⁴/4 < 1)",
    );
}

fn as_accurate(s: &mut Section) {
    let d_sf = derivation("semi_false_heun");
    let d_sh = derivation("standard_heun");
    let psi_sf = frequency::psi_coeffs("semi_false_heun", 5);
    let psi_sh = frequency::psi_coeffs("standard_heun", 5);
    let m_sf = poly::series::modulus_sq_series(&d_sf.charpoly, 6).expect("series");
    let m_sh = poly::series::modulus_sq_series(&d_sh.charpoly, 6).expect("series");
    let disp = |d: &poly::Derivation| {
        poly::series::dispersion_order(&d.charpoly).expect("series").map(|t| t.order)
    };
    let diss = |d: &poly::Derivation| {
        poly::series::dissipation_order(&d.charpoly).expect("series").map(|t| t.order)
    };
    let same = disp(&d_sf) == disp(&d_sh) && diss(&d_sf) == diss(&d_sh);
    s.push(
        "as_accurate",
        "... as accurate as Standard Heun (which is unstable).",
        format!(
            "Semi-False Heun: Ψ = {}, |z|² = {}; Standard Heun: Ψ = {}, |z|² = {}; dispersion orders {} vs \
             {}, dissipation orders {} vs {}",
            frequency::series_poly(&psi_sf),
            frequency::series_poly(&m_sf),
            frequency::series_poly(&psi_sh),
            frequency::series_poly(&m_sh),
            show_order(disp(&d_sf)),
            show_order(disp(&d_sh)),
            show_order(diss(&d_sf)),
            show_order(diss(&d_sh))
        ),
        if same { Verdict::Confirmed } else { Verdict::Refined },
        "poly::series on both χ: the phase error Ψ − Φ and the amplitude error |z|² − 1 have the same \
         orders; the phase error of Semi-False Heun is half as large (−Φ³/12 against +Φ³/6), the amplitude \
         error equal and opposite (−Φ⁴/4 against +Φ⁴/4)",
    );
}

fn show_order(k: Option<usize>) -> String {
    k.map_or_else(|| "none".to_owned(), |k| format!("Φ^{k}"))
}
