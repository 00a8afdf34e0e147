//! Section 6, Damped Euler: the damped oscillator, its characteristic
//! equation, the stabilising choice D = Φ/2, tan Ψ, the Taylor
//! approximation and the table at Φ = 1 and Φ = 1.414.

use poly::{Poly, RootClass, Sym};

use super::common::*;
use super::exact::{p_q, paper};
use super::{frequency, ranges};
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::Finding;

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("6", "sec06");
    ode_claim(
        &mut s,
        "damped_euler_d",
        "v̇ = −ω0 (2Dv + y), ẏ = ω0 v;  dv = −Φ(2Dv + y), dy = Φv",
        [["-2*D", "-1"], ["1", "0"]],
        Scheme::Euler,
    );
    stages_claim(
        &mut s,
        "update",
        "damped_euler_d",
        "v = v + dv = v − Φ(2Dv + y);  y = y + dy = y + Φv",
        &[
            ("v", Printed { printed: "v = v − Φ(2Dv + y)", parse: "v - Phi*(2*D*v + y)" }),
            ("y", Printed { printed: "y = y + Φv", parse: "y + Phi*v" }),
        ],
    );
    z_rows_claim(
        &mut s,
        "damped_euler_d",
        "v = (1 − Φ2D) v z⁻¹ − Φ y z⁻¹;  y = Φ v z⁻¹ + y z⁻¹",
        &[
            ZRow {
                printed: "v = (1 − Φ2D) v z⁻¹ − Φ y z⁻¹", v: "1 - Phi*2*D", y: "-Phi"
            },
            ZRow { printed: "y = Φ v z⁻¹ + y z⁻¹", v: "Phi", y: "1" },
        ],
    );
    charpoly_claim(
        &mut s,
        "charpoly",
        "damped_euler_d",
        "z² − 2(1 − DΦ)z + (1 − 2DΦ + Φ²) = 0",
        "z^2 - 2*(1 - D*Phi)*z + (1 - 2*D*Phi + Phi^2)",
    );
    eigenvalues(&mut s);
    r_squared(&mut s);
    damping_choice(&mut s);
    y_first_symplectic(&mut s);
    now_harmonic(&mut s);
    tan_claim(
        &mut s,
        "tan_psi_d",
        "damped_euler_d",
        "tan Ψ = Φ(1 − D²)^0.5 / (1 − DΦ)",
        "Phi^2*(1 - D^2)",
        "1 - D*Phi",
    );
    tan_claim(
        &mut s,
        "tan_psi",
        "damped_euler",
        "tan Ψ = Φ(1 − Φ²/4)^0.5 / (1 − Φ²/2)   (D = Φ/2)",
        "Phi^2*(1 - Phi^2/4)",
        "1 - Phi^2/2",
    );
    frequency::too_high(
        &mut s,
        "damped_euler",
        "The frequency of the sample sequence is always too high.",
    );
    frequency::approximation(&mut s, "damped_euler", "Ψ ≅ Φ(1 + Φ²/24)", "Phi*(1 + Phi^2/24)");
    frequency::validity(&mut s, "damped_euler", "Phi*(1 + Phi^2/24)");
    frequency::table(
        &mut s,
        "damped_euler",
        "Phi*(1 + Phi^2/24)",
        &[
            (
                "table_phi_1",
                "Φ = 1: True Ψ = 1.047, Approximation Ψ = 1.042",
                1.0,
                "1.047",
                "1.042",
            ),
            (
                "table_phi_1414",
                "Φ = 1.414: True Ψ = 1.570, Approximation Ψ = 1.532",
                1.414,
                "1.570",
                "1.532",
            ),
        ],
    );
    s.finish()
}

fn eigenvalues(s: &mut Section) {
    let d = builtin_derivation("damped_euler_d");
    let (p, q) = p_q(&d);
    let disc = &q - &(&p * &p);
    s.push(
        "eigenvalues",
        "z1/2 = (1 − DΦ) ± jΦ(1 − D²)^0.5",
        format!("p = {p}, q − p² = {disc}: a conjugate pair iff D² < 1 (Φ > 0); for D ≥ 1 the same formula gives real roots"),
        Finding::same(
            format!("p = {}, q − p² = {}", paper("1 - D*Phi"), paper("Phi^2*(1 - D^2)")),
            format!("p = {p}, q − p² = {disc}"),
        ),
        format!(
            "the printed real part is compared with p and the printed imaginary part squared with q − p² \
             (poly::derive(damped_euler_d)); q − p² = {disc} changes sign at D = 1"
        ),
    );
}

fn r_squared(s: &mut Section) {
    let d = builtin_derivation("damped_euler_d");
    let (_, q) = p_q(&d);
    s.push(
        "r_squared",
        "r1² = 1 − 2DΦ + Φ²",
        format!("r² = q = {q} while D² < 1"),
        Finding::same(paper("1 - 2*D*Phi + Phi^2"), &q),
        "for a conjugate pair r² = z1·z2 = q (section 4); q from poly::derive(damped_euler_d)",
    );
}

fn damping_choice(s: &mut Section) {
    let d = builtin_derivation("damped_euler_d");
    let (_, q) = p_q(&d);
    let factored = paper("Phi*(Phi - 2*D)");
    let at_half = q.subs(Sym::new("D"), &paper("Phi/2"));
    let builtin_q = p_q(&builtin_derivation("damped_euler")).1;
    s.push(
        "damping_choice",
        "... stabilizing the solution of an undamped oscillator numerically, by r1² = 1: D = 0.5Φ",
        format!("r1² − 1 = {} = Φ(Φ − 2D): zero for Φ > 0 iff D = Φ/2", &q - &Poly::one()),
        Finding::all([
            ("q − 1 = Φ(Φ − 2D)", &q - &Poly::one() == factored),
            ("q = 1 at D = Φ/2", at_half.is_one()),
            ("the built-in damped_euler (D:=0.5*woT) has q = 1", builtin_q.is_one()),
        ]),
        "exact: q − 1 factors as Φ(Φ − 2D); substituting D = Φ/2 gives q = 1, and the built-in \
         damped_euler (Appendix B: D:=0.5*woT) has q = 1",
    );
}

/// The symplectic Euler that updates y first, as written in
/// `crates/zcheck/methods/symplectic_euler_y_first.zm`.
const Y_FIRST: &str = include_str!("../../../methods/symplectic_euler_y_first.zm");

/// With D = Φ/2, Damped Euler is exactly the symplectic Euler that updates
/// y first (`poly::advanced::equiv`): the "artificial damping" cancels
/// Standard Euler's growth by reading the new y.
fn y_first_symplectic(s: &mut Section) {
    use poly::advanced::equiv::{self, Relation};
    let damped = builtin_derivation("damped_euler");
    let y_first = poly::Method::parse("symplectic_euler_y_first.zm", Y_FIRST)
        .ok()
        .and_then(|m| poly::derive(&m).ok());
    let relation = |b: &poly::Derivation| {
        y_first.as_ref().map(|a| equiv::relate(a, b)).unwrap_or(Relation::Different)
    };
    let equal = relation(&damped) == Relation::Equal;
    let to_false_euler = relation(&builtin_derivation("false_euler"));
    let signed = matches!(to_false_euler, Relation::PermutationAndScaling { .. });
    s.push(
        "y_first_symplectic",
        "The artificial damping D has only the purpose of stabilizing the solution of an undamped oscillator \
         numerically, by r1² = 1: D = 0.5Φ",
        format!(
            "with D = Φ/2 the step is exactly the symplectic Euler that updates y first (`y = y + Phi*v; \
             v = v - Phi*y`): the same transition matrix, P = {}; that is False Euler with v and y exchanged \
             and one sign flipped, so the artificial damping leaves no damping, which is why r1² = 1",
            matrix_text(damped.transition_matrix()),
        ),
        Finding::all([
            ("Damped Euler (D = Φ/2) and the y-first symplectic Euler have equal P", equal),
            ("the y-first symplectic Euler is False Euler up to a signed permutation", signed),
        ]),
        "Derivation::relate on the built-in damped_euler (Appendix B: D:=0.5*woT) and \
         crates/zcheck/methods/symplectic_euler_y_first.zm (zcheck equiv), exact",
    );
}

fn now_harmonic(s: &mut Section) {
    // The printed eigenvalues (1 − DΦ) ± jΦ(1 − D²)^0.5 are a conjugate pair
    // only while 1 − D² > 0: with D = Φ/2, the range the section implies.
    let (finding, map, failing) =
        ranges::always("damped_euler", |c| c == RootClass::Harmonic, Some("1 - Phi^2/4"));
    s.push(
        "now_harmonic",
        "Because the sample sequence is now harmonic we can calculate the true frequency Ω0 by using Ψ = Ω0 T.",
        map,
        finding,
        format!(
            "exact class map of damped_euler (D = Φ/2) over Φ > 0: harmonic only while D < 1, the range the \
             printed eigenvalues (1 − D²)^0.5 imply; it fails for {failing}"
        ),
    );
}
