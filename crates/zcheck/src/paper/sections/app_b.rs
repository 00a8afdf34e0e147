//! Appendix B, the Pascal source: each method's "Direct Integration" and
//! "Transition matrix" branches give the same recursion; Verlet's start
//! y2:=1 is False Euler with v0 = 0; Damped Euler's D:=0.5*woT is section
//! 6's choice; and the slips in the listing.

use poly::advanced::Operand;
use poly::Sym;

use super::common::*;
use super::exact::paper;
use super::pascal;
use super::sec08;
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::Finding;

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("B", "appB");
    for matrix in poly::advanced::builtins::builtin_names()
        .filter(|n| poly::advanced::builtins::direct_twin(n).is_some())
    {
        twins(&mut s, matrix);
    }
    verlet_start(&mut s);
    damping(&mut s);
    slips(&mut s);
    s.finish()
}

fn twins(s: &mut Section, matrix: &str) {
    let direct = poly::advanced::builtins::direct_twin(matrix).expect("filtered");
    let a = builtin_derivation(direct);
    let b = builtin_derivation(matrix);
    let same = a.transition_matrix() == b.transition_matrix();
    let mut evidence = format!(
        "symbolic execution of both branches (built-ins {direct} and {matrix}) gives the same P exactly"
    );
    if !same {
        evidence = format!(
            "{direct}: P = {}; {matrix}: P = {}",
            matrix_text(a.transition_matrix()),
            matrix_text(b.transition_matrix())
        );
    }
    let dead = dead_assignments(a.method());
    if !dead.is_empty() {
        evidence.push_str(&format!(
            "; the direct branch computes {} and never reads it",
            dead.join(", ")
        ));
    }
    s.push(
        &format!("{direct}_branches"),
        format!(
            "{}: {{ Direct Integration }} and {{ Transition matrix }} compute the same step",
            title(direct)
        ),
        format!("P = {}", matrix_text(a.transition_matrix())),
        Finding::same(matrix_text(b.transition_matrix()), matrix_text(a.transition_matrix())),
        evidence,
    );
}

use super::ranges::title;

/// Temporaries written and never read.
fn dead_assignments(m: &poly::Method) -> Vec<String> {
    let n = m.assigns().len();
    (0..n)
        .filter(|&k| matches!(m.assigns()[k].target, poly::advanced::Target::Temp(_)))
        .filter(|&k| {
            !m.assigns().iter().any(|a| a.terms.iter().any(|(op, _)| *op == Operand::Stmt(k)))
        })
        .map(|k| m.target_name(&m.assigns()[k]).to_owned())
        .collect()
}

fn verlet_start(s: &mut Section) {
    let phis =
        [poly::q(1, 10), poly::q(1, 2), poly::q(1, 1), poly::q(3, 2), poly::q(2, 1), poly::q(9, 4)];
    let fe = builtin_derivation("false_euler");
    let n = 24;
    let ok = phis.iter().all(|phi| {
        let p = matrix_at(fe.transition_matrix(), phi);
        let euler = iterate_exact(&p, &[poly::q(0, 1), poly::q(1, 1)], n);
        let verlet = sec08::verlet_samples(phi, &poly::q(1, 1), &poly::q(1, 1), n);
        euler.iter().map(|x| &x[1]).eq(verlet.iter())
    });
    s.push(
        "verlet_start",
        "Verlet: t0:=0; y0:=1; y2:=1; { v0=0 }",
        "Verlet from y0 = y2 = 1 produces exactly False Euler's y samples from v0 = 0, y0 = 1",
        Finding::all([("the y samples coincide at every Φ tried", ok)]),
        format!(
            "exact rational runs of {n} steps at Φ = 1/10, 1/2, 1, 3/2, 2, 9/4; False Euler's y obeys \
             y_i = (2 − Φ²) y_(i−1) − y_(i−2) with y_(−1) = y_0 − Φ·v_0 = y_0 when v0 = 0"
        ),
    );
}

fn damping(s: &mut Section) {
    let d = builtin_derivation("damped_euler_d");
    let half = paper("Phi/2");
    let p = d.transition_matrix().map(|e| e.subs(Sym::new("D"), &half));
    let builtin = builtin_derivation("damped_euler").transition_matrix().clone();
    s.push(
        "damped_euler_d",
        "Damped Euler: D:=0.5*woT;  v1:= v0-woT*(y0+2*D*v0)",
        format!("P = {}", matrix_text(&p)),
        Finding::same(matrix_text(&p), matrix_text(&builtin)),
        "section 6's damped scheme with D a parameter, after D := Φ/2, has exactly the transition matrix of \
         the Appendix B program (and of its (1-woT2)*v0 matrix branch)",
    );
}

fn slips(s: &mut Section) {
    // The "Transition matrix" comments: the one that differs from the others
    // is the slip; it matters only if removing it changes the tokens.
    let comments: Vec<String> = pascal::comments(pascal::APPENDIX_B)
        .into_iter()
        .filter(|c| c.starts_with("Transition"))
        .collect();
    let intended = comments
        .iter()
        .max_by_key(|c| comments.iter().filter(|d| d == c).count())
        .cloned()
        .unwrap_or_default();
    let odd: Vec<&String> = comments.iter().filter(|c| **c != intended).collect();
    let printed = odd.first().map_or_else(|| intended.clone(), |c| (*c).clone());
    let mended = pascal::APPENDIX_B.replace(&printed, &intended);
    let changes_math = pascal::tokens(pascal::APPENDIX_B) != pascal::tokens(&mended);
    let statement = "Standard Heun: { Transition matrixix }";
    let corrected = statement.replace(&printed, &intended);
    s.push(
        "typo_matrixix",
        statement,
        format!(
            "{} of the {} \"Transition\" comments read {{ {printed} }} where the others read {{ {intended} }}; \
             the listing's tokens without comments are {} after mending it",
            odd.len(),
            comments.len(),
            if changes_math { "different" } else { "the same" }
        ),
        Finding::Slip { printed, intended, changes_math },
        "the Appendix B listing, transcribed verbatim, scanned (paper/sections/pascal.rs): comments compared \
         with each other, tokens compared with and without the slip",
    );
    s.correct(corrected);
    undeclared(s);
}

/// Names the listing assigns but never declares.
fn undeclared(s: &mut Section) {
    let names = pascal::undeclared(pascal::APPENDIX_B);
    let early = pascal::read_before_written(pascal::APPENDIX_B);
    let undefined: Vec<&String> = names.iter().filter(|n| early.contains(n)).collect();
    let list = if names.is_empty() { "none".to_owned() } else { names.join(", ") };
    s.push(
        "undeclared_names",
        "Var t0,y0,v0,t1,y1,v1,y2: Double; dv1,dy1,dv2,dy2,y11,v11,v12: Double; woT,woT2,woT4: Double; i,k: \
         Integer;  ...  D:=0.5*woT; ...  x0:=0; ... x1 := x0+dT;",
        format!(
            "assigned but not declared in Func: {list}; {} of them is read before it is written",
            if undefined.is_empty() { "none".to_owned() } else { format!("{undefined:?}") }
        ),
        Finding::Slip {
            printed: format!("undeclared: {list}"),
            intended: "undeclared: none".to_owned(),
            changes_math: !undefined.is_empty(),
        },
        "the listing scanned: the Var list and parameters against every name on the left of :=. d is case 2's \
         damping (section 6's D); x0, x1 are case 7's time, where the other cases write t0, t1; p0, q0, p1, q1 \
         are the screen coordinates MapP returns, which every listing of the paper uses without declaring. Each \
         is written before it is read, so declaring it changes nothing the program computes",
    );
    if !names.is_empty() {
        s.correct(format!("the Var list, with {list} declared too"));
    }
}
