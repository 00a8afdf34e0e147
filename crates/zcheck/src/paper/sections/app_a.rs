//! Appendix A, Taylor approximations: every step of the two derivations
//! Ψ ≅ Φ(1 + Φ²/24) and Ψ ≅ Φ(1 + Φ²/6), checked as equalities of power
//! series through Φ³ with Ψ replaced by its exact series.

use poly::{Poly, Sym};

use super::common::*;
use super::exact::paper;
use super::frequency;
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::Finding;

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("A", "appA");
    tan_claim(
        &mut s,
        "tan_psi_euler",
        "damped_euler",
        "tan Ψ = Φ(1 − D²)^0.5 / (1 − DΦ) = Φ(1 − Φ²/4)^0.5 / (1 − Φ²/2)   (Damped Euler and False Euler)",
        "Phi^2*(1 - Phi^2/4)",
        "1 - Phi^2/2",
    );
    let same = builtin_derivation("damped_euler").charpoly()
        == builtin_derivation("false_euler").charpoly();
    s.append_evidence(&format!(
        "; Damped Euler (D = Φ/2) and False Euler have {} χ",
        if same { "the same" } else { "different" }
    ));
    let euler = [
        (
            "euler_step1",
            "Ψ + Ψ³/3 ≅ Φ(1 − Φ²/8)·(1 + Φ²/2) = Φ(1 + 3/8Φ² + ...)",
            "Psi + Psi^3/3",
            &["Phi*(1 - Phi^2/8)*(1 + Phi^2/2)", "Phi*(1 + 3/8*Phi^2)"][..],
        ),
        (
            "euler_step2",
            "Ψ(1 + Ψ²/3) ≅ Φ(1 + 3/8Φ²)",
            "Psi*(1 + Psi^2/3)",
            &["Phi*(1 + 3/8*Phi^2)"][..],
        ),
        (
            "euler_step3",
            "Ψ ≅ Φ(1 + 3/8Φ²)/(1 + Ψ²/3) ≅ Φ(1 + 3/8Φ²)·(1 − Ψ²/3)",
            "Psi",
            &["Phi*(1 + 3/8*Phi^2)*(1 - Psi^2/3)"][..],
        ),
        (
            "euler_step4",
            "Now we replace on the right side Ψ²/3 by Φ²/3",
            "Psi",
            &["Phi*(1 + 3/8*Phi^2)*(1 - Phi^2/3)"][..],
        ),
        ("euler_result", "Approximation: Ψ ≅ Φ(1 + Φ²/24)", "Psi", &["Phi*(1 + Phi^2/24)"][..]),
    ];
    for (key, statement, lhs, rhs) in euler {
        step(&mut s, key, "damped_euler", statement, lhs, rhs);
    }
    tan_claim(
        &mut s,
        "tan_psi_heun",
        "standard_heun",
        "Accurate solution for Standard Heun: tan Ψ = Φ / (1 − Φ²/2)",
        "Phi^2",
        "1 - Phi^2/2",
    );
    let heun = [
        (
            "heun_step1",
            "Ψ(1 + Ψ²/3) ≅ Φ(1 + Φ²/2)",
            "Psi*(1 + Psi^2/3)",
            &["Phi*(1 + Phi^2/2)"][..],
        ),
        (
            "heun_step2",
            "Ψ ≅ Φ(1 + Φ²/2)·(1 − Φ²/3)",
            "Psi",
            &["Phi*(1 + Phi^2/2)*(1 - Phi^2/3)"][..],
        ),
        ("heun_result", "Approximation: Ψ ≅ Φ(1 + Φ²/6)", "Psi", &["Phi*(1 + Phi^2/6)"][..]),
    ];
    for (key, statement, lhs, rhs) in heun {
        step(&mut s, key, "standard_heun", statement, lhs, rhs);
    }
    s.finish()
}

/// Ψ's exact series through Φ⁵ as a polynomial in Φ.
fn psi_poly(method: &str) -> Poly {
    frequency::series_poly(&frequency::psi_coeffs(method, 5))
}

/// `lhs ≅ rhs_1 = rhs_2 ...` through Φ³, with Ψ replaced by its series.
fn step(s: &mut Section, key: &str, method: &str, statement: &str, lhs: &str, rhs: &[&str]) {
    let psi = psi_poly(method);
    let sub = |text: &str| truncate(&paper(text).subs(Sym::new("Psi"), &psi), 4);
    let left = sub(lhs);
    let rights: Vec<Poly> = rhs.iter().map(|r| sub(r)).collect();
    let ok = rights.iter().all(|r| *r == left);
    let shown: Vec<String> = rights.iter().map(ToString::to_string).collect();
    let finding = Finding::all(
        rights.iter().zip(rhs).map(|(r, text)| (format!("{lhs} ≅ {text} through Φ³"), *r == left)),
    );
    s.push(
        key,
        statement,
        format!(
            "through Φ³: left side = {left}; {}",
            match shown.as_slice() {
                [one] => format!("right side = {one}"),
                [first, ..] if shown.iter().all(|x| x == first) => {
                    format!("each of the {} right sides = {first}", shown.len())
                }
                _ => format!("right sides = {}", shown.join(", ")),
            }
        ),
        finding,
        format!(
            "Ψ replaced by its exact series Ψ = {psi} + O(Φ⁷) ({method}, Derivation::psi_series), products truncated \
             after Φ³: the two sides {}",
            if ok { "agree exactly" } else { "differ" }
        ),
    );
}
