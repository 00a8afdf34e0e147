//! Section 10, False Heun: the stages, the two misprinted lines (the y
//! update and the second z-domain row), the correct χ, r², the class claim
//! "either monotonic unstable or a damped oscillation" and the advice.

use poly::{PolyMatrix, RootClass};

use super::common::*;
use super::exact::{p_q, paper};
use super::{advice, ranges};
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::Finding;

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("10", "sec10");
    ode_claim(&mut s, "false_heun", "v̇ = −ω0 y, ẏ = ω0 v", OSCILLATOR, Scheme::Consistent);
    stages_claim(
        &mut s,
        "stages",
        "false_heun",
        "dv(1) = −Φy; v(1) = v − Φy; dy(1) = Φv(1) = Φv − Φ²y; y(1) = y + Φv − Φ²y; dv(2) = −Φ(y + Φv − Φ²y); \
         v(2) = v − Φy − Φ²v + Φ³y; dy(2) = Φ(v − Φ²v − Φy + Φ³y)",
        &[
            ("dv1", Printed { printed: "dv(1) = −Φy", parse: "-Phi*y" }),
            ("v11", Printed { printed: "v(1) = v − Φy", parse: "v - Phi*y" }),
            ("dy1", Printed { printed: "dy(1) = Φv − Φ²y", parse: "Phi*v - Phi^2*y" }),
            ("y11", Printed { printed: "y(1) = y + Φv − Φ²y", parse: "y + Phi*v - Phi^2*y" }),
            ("dv2", Printed { printed: "dv(2) = −Φ(y + Φv − Φ²y)", parse: "-Phi*(y + Phi*v - Phi^2*y)" }),
            ("v12", Printed { printed: "v(2) = v − Φy − Φ²v + Φ³y", parse: "v - Phi*y - Phi^2*v + Phi^3*y" }),
            ("dy2", Printed {
                printed: "dy(2) = Φ(v − Φ²v − Φy + Φ³y)",
                parse: "Phi*(v - Phi^2*v - Phi*y + Phi^3*y)",
            }),
        ],
    );
    stages_claim(
        &mut s,
        "update_v",
        "false_heun",
        "v = v + 0.5(−2Φy + Φ³y − Φ²v)",
        &[(
            "v",
            Printed {
                printed: "v = v + 0.5(−2Φy + Φ³y − Φ²v)",
                parse: "v + 1/2*(-2*Phi*y + Phi^3*y - Phi^2*v)",
            },
        )],
    );
    stages_claim(
        &mut s,
        "update_y",
        "false_heun",
        "y = y + 0.5(2Φv − Φ³v − Φ²y + Φ⁴y)",
        &[(
            "y",
            Printed {
                printed: "y = y + 0.5(2Φv − Φ³v − Φ²y + Φ⁴y)",
                parse: "y + 1/2*(2*Phi*v - Phi^3*v - Phi^2*y + Phi^4*y)",
            },
        )],
    );
    stages_claim(
        &mut s,
        "update_expanded",
        "false_heun",
        "v = v − Φy − 0.5Φ²v + 0.5Φ³y;  y = y + Φv − Φ²y − 0.5Φ³v + 0.5Φ⁴y",
        &[
            (
                "v",
                Printed {
                    printed: "v = v − Φy − 0.5Φ²v + 0.5Φ³y",
                    parse: "v - Phi*y - 1/2*Phi^2*v + 1/2*Phi^3*y",
                },
            ),
            (
                "y",
                Printed {
                    printed: "y = y + Φv − Φ²y − 0.5Φ³v + 0.5Φ⁴y",
                    parse: "y + Phi*v - Phi^2*y - 1/2*Phi^3*v + 1/2*Phi^4*y",
                },
            ),
        ],
    );
    z_rows(&mut s);
    charpoly(&mut s);
    r_squared_claim(&mut s, "false_heun", "r1² = 1 − Φ²/2", "1 - Phi^2/2");
    // No range is stated: the section gives no limit for False Heun.
    let (finding, map, failing) = ranges::always(
        "false_heun",
        |c| matches!(c, RootClass::MonotonicUnstable | RootClass::DampedOscillation),
        None,
    );
    s.push(
        "either_or",
        "The solution is either monotonic unstable or a damped oscillation.",
        map,
        finding,
        format!(
            "exact class map over Φ > 0 (discriminant q − p² and χ(±1) by Sturm sequences): the two named \
             classes leave out {failing}"
        ),
    );
    s.correct(format!("The solution is {}.", s.last_derived()));
    not_recommended(&mut s);
    s.finish()
}

const ROWS: [ZRow; 2] = [
    ZRow {
        printed: "v = (1 − Φ²/2)v z⁻¹ − Φ(1 − Φ²/2)y z⁻¹",
        v: "1 - Phi^2/2",
        y: "-Phi*(1 - Phi^2/2)",
    },
    ZRow {
        printed: "y = Φ(1 − Φ²/2)v z⁻¹ + (1 − Φ²/2)y z⁻¹",
        v: "Phi*(1 - Phi^2/2)",
        y: "1 - Phi^2/2",
    },
];

fn z_rows(s: &mut Section) {
    z_rows_claim(
        s,
        "false_heun",
        "v = (1 − Φ²/2)v z⁻¹ − Φ(1 − Φ²/2)y z⁻¹;  y = Φ(1 − Φ²/2)v z⁻¹ + (1 − Φ²/2)y z⁻¹",
        &ROWS,
    );
    // The printed χ is right although the printed rows are not.
    let from_rows = printed_rows_charpoly();
    let d = builtin_derivation("false_heun");
    s.append_evidence(&format!(
        "; the printed rows would give χ = {from_rows}, not the printed (and derived) χ = {}, so the \
         section's χ was derived from the correct rows",
        d.charpoly()
    ));
}

/// χ of the matrix the printed rows describe.
pub(crate) fn printed_rows_charpoly() -> poly::Poly {
    let m = PolyMatrix::from_rows(ROWS.iter().map(|r| vec![paper(r.v), paper(r.y)]).collect());
    poly::advanced::charpoly_state_route(&m)
}

fn charpoly(s: &mut Section) {
    charpoly_claim(
        s,
        "charpoly",
        "false_heun",
        "z² − 2(1 − 3/4Φ² + Φ⁴/4)z + (1 − Φ²/2) = 0",
        "z^2 - 2*(1 - 3/4*Phi^2 + Phi^4/4)*z + (1 - Phi^2/2)",
    );
}

fn not_recommended(s: &mut Section) {
    let (_, q) = p_q(&builtin_derivation("false_heun"));
    let rows: Vec<String> = [10.0, 20.0, 50.0]
        .iter()
        .map(|&n: &f64| {
            let phi = 2.0 * std::f64::consts::PI / n;
            format!(
                "{n} steps/period: ×{}",
                fixed(super::sec09::growth_per_period(eval_f64(&q, phi), phi), 4)
            )
        })
        .collect();
    let own = advice::criteria("false_heun");
    let dominating = advice::dominated_by(&own, &poly::advanced::builtins::PAPER_METHODS);
    let by: Vec<String> = dominating
        .iter()
        .map(|(c, better)| format!("{} (better on {})", advice::text(c), better.join(", ")))
        .collect();
    s.push(
        "not_recommended",
        "False Heun is not recommended.",
        format!(
            "{}; amplitude per true period {}; dominated on the paper's criteria by: {}",
            advice::text(&own),
            rows.join(", "),
            if by.is_empty() { "none".to_owned() } else { by.join("; ") }
        ),
        Finding::all([(
            "another method of the paper is at least as good on every criterion of section 1 and better on one",
            !dominating.is_empty(),
        )]),
        "exact Φ_max (Derivation::stability), leading terms of Ψ − Φ and |z|² − 1 (poly's exact series), operations per \
         step (Derivation::cost), for every method of sections 5–11",
    );
}
