//! Section 8, Verlet integration: the recursion derived from False Euler,
//! the same characteristic equation, the initial-velocity remark and the
//! operation count "two multiplications and two additions per step".

use poly::{Poly, Q};

use super::common::*;
use crate::paper::{Claim, Verdict};

pub fn claims() -> Vec<Claim> {
    let mut s = Section::new("8", "sec08");
    recursion(&mut s);
    oscillator(&mut s);
    charpoly_claim(
        &mut s,
        "charpoly",
        "verlet",
        "z² − 2(1 − Φ²/2)z + 1 = 0",
        "z^2 - 2*(1 - Phi^2/2)*z + 1",
    );
    same_as_false_euler(&mut s);
    initial_velocity(&mut s);
    operations(&mut s);
    s.finish()
}

/// y_i = y_{i−1} + T v_i with v_i = v_{i−1} + T a_{i−1} and the secant
/// T v_{i−1} = y_{i−1} − y_{i−2}.
fn recursion(s: &mut Section) {
    let (y1, y2, t, a, u) =
        (Poly::var("y1"), Poly::var("y2"), Poly::var("T"), Poly::var("a"), Poly::var("u"));
    // u stands for T·v_{i−1}; T·v_i = u + T²a.
    let y_i = &y1 + &(&u + &(&(&t * &t) * &a));
    let y_i = y_i.subs(poly::Sym::new("u"), &(&y1 - &y2));
    let printed = paper("2*y1 - y2 + T^2*a");
    s.push(
        "recursion",
        "v_i = v_{i−1} + T a_{i−1};  y_i = y_{i−1} + T v_i;  v_{i−1} = (y_{i−1} − y_{i−2})/T  ⇒  y_i = 2y_{i−1} − y_{i−2} + T² a_{i−1}",
        format!("y_i = {y_i} (y1 = y_(i−1), y2 = y_(i−2))"),
        exact_verdict(y_i == printed),
        "exact substitution with T·v_{i−1} = y_{i−1} − y_{i−2}",
    );
}

fn oscillator(s: &mut Section) {
    let m = derivation("verlet").method;
    let step = stage_value(&m, "y");
    let printed = paper("2*(1 - Phi^2/2)*y - y_lag1");
    s.push(
        "oscillator_recursion",
        "a_{i−1} = −ω0² y_{i−1};  y_i − 2(1 − Φ²/2) y_{i−1} + y_{i−2} = 0",
        format!("the verlet step (Appendix B case 4) gives y_i = {step} (y = y_(i−1), y_lag1 = y_(i−2))"),
        exact_verdict(step == printed),
        "symbolic execution of y1:=2*y0-y2+Sqr(dT)*(-wo*wo*y0) with T²ω0² = Φ²",
    );
}

fn same_as_false_euler(s: &mut Section) {
    let fe = derivation("false_euler");
    let ve = derivation("verlet");
    let samples = same_samples(&[poly::q(1, 10), poly::q(1, 1), poly::q(2, 1), poly::q(5, 2)], 24);
    s.push(
        "same_as_false_euler",
        "This is the characteristic equation of False Euler − Verlet is the same.",
        format!("χ(false_euler) = {}, χ(verlet) = {}", fe.charpoly, ve.charpoly),
        exact_verdict(fe.charpoly == ve.charpoly && samples),
        "equal polynomials exactly; and beyond χ, the y samples coincide exactly (rationals, 24 steps at \
         Φ = 1/10, 1, 2, 5/2) when Verlet starts from y_{−1} = y_0 − Φ·v_0",
    );
}

/// False Euler's y samples and Verlet's, started from y_{−1} = y_0 − Φ v_0,
/// agree exactly.
pub fn same_samples(phis: &[Q], n: usize) -> bool {
    let fe = derivation("false_euler");
    let starts = [
        (poly::q(0, 1), poly::q(1, 1)),
        (poly::q(1, 3), poly::q(-2, 1)),
        (poly::q(5, 7), poly::q(0, 1)),
    ];
    phis.iter().all(|phi| {
        let p = matrix_at(&fe.transition_matrix, phi);
        starts.iter().all(|(v0, y0)| {
            let euler = iterate_exact(&p, &[v0.clone(), y0.clone()], n);
            let verlet = verlet_samples(phi, y0, &(y0 - phi * v0), n);
            euler.iter().map(|x| &x[1]).eq(verlet.iter())
        })
    })
}

/// Verlet's samples y_0..y_n from y_0 and y_{−1}, Appendix B case 4.
pub fn verlet_samples(phi: &Q, y0: &Q, y_minus_one: &Q, n: usize) -> Vec<Q> {
    let mut out = vec![y0.clone()];
    let (mut prev, mut cur) = (y_minus_one.clone(), y0.clone());
    for _ in 0..n {
        // y1 := 2*y0 - y2 + Sqr(dT)*(-wo*wo*y0), with (wo*dT)² = Φ².
        let next = poly::q(2, 1) * &cur - &prev - phi * phi * &cur;
        prev = std::mem::replace(&mut cur, next);
        out.push(cur.clone());
    }
    out
}

fn initial_velocity(s: &mut Section) {
    let ok = same_samples(&[poly::q(1, 2), poly::q(3, 2)], 16);
    s.push(
        "initial_velocity",
        "Verlet Integration doesn't use the state variable v explicitly. This causes big problems for the \
         introduction of the initial condition v(0) = v0 and also for ... forces which depend on the velocity",
        "v0 enters Verlet exactly through y_{−1} = y_0 − Φ·v_0 (Appendix B's y2:=1 is the case v0 = 0); \
         velocity-dependent forces do need v, which Verlet does not carry",
        if ok { Verdict::Refined } else { Verdict::Errata },
        "exact rational runs: with y_{−1} = y_0 − Φ·v_0, Verlet's samples equal False Euler's for \
         (v0, y0) = (0, 1), (1/3, −2), (5/7, 0) at Φ = 1/2 and 3/2, 16 steps",
    );
}

fn operations(s: &mut Section) {
    let count = |name: &str| {
        let m = poly::builtin(name).expect("built-in");
        let c = poly::step_cost(&m).program;
        (c.mul, c.add)
    };
    let fe = count("false_euler");
    let ve = count("verlet");
    let verdict = if fe == (2, 2) && ve == (2, 2) {
        Verdict::Confirmed
    } else if fe == (2, 2) {
        Verdict::Refined
    } else {
        Verdict::Errata
    };
    s.push(
        "operations",
        "The speed depends on the programming. Essentially, both methods need two multiplications and two \
         additions per step.",
        format!(
            "False Euler: {} mul + {} add per step; Verlet: {} mul + {} add per step (plus one copy y@1 ← y)",
            fe.0, fe.1, ve.0, ve.1
        ),
        verdict,
        "poly::step_cost on the lowered programs (coefficients folded once per Φ, ±1 free): False Euler \
         v = v − Φ·y, y = y + Φ·v; Verlet y = (2 − Φ²)·y − y@1 — Appendix B's line \
         2*y0-y2+Sqr(dT)*(-wo*wo*y0) spends more only because it does not fold 2 − Φ²",
    );
}
