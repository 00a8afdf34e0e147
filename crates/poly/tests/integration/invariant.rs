//! Conserved quadratic forms (`poly::advanced::invariant`): the brief's closed form for
//! False Euler, and PᵀQP = Q checked by plain multiplication on every
//! built-in that has a form.

use poly::advanced::invariant::{
    conserved_form, form_text, is_positive_definite, transition_matrix_at, NoForm,
};
use poly::{q, Q};

fn at(name: &str, phi: Q) -> Vec<Vec<Q>> {
    let m = poly::builtin(name).unwrap();
    let values = poly::Params::new().bind("Phi", phi).bind("D", q(1, 5));
    transition_matrix_at(&m, &values).expect("every parameter set")
}

/// PᵀQP − Q, entry by entry (the slow, obvious oracle).
fn residual(p: &[Vec<Q>], qm: &[Vec<Q>]) -> Vec<Vec<Q>> {
    let n = p.len();
    let mut out = vec![vec![q(0, 1); n]; n];
    for a in 0..n {
        for b in 0..n {
            let mut s = q(0, 1);
            for i in 0..n {
                for j in 0..n {
                    s += &p[i][a] * &qm[i][j] * &p[j][b];
                }
            }
            out[a][b] = s - &qm[a][b];
        }
    }
    out
}

/// False Euler conserves v² + y² − Φ·v·y (the paper's energy-like form).
#[test]
fn false_euler_form_is_the_closed_form() {
    let form = conserved_form(&at("false_euler", q(1, 10))).unwrap();
    assert_eq!(form_text(&form, &["v".into(), "y".into()]), "v^2 - 1/10*v*y + y^2");
    assert!(is_positive_definite(&form));
}

/// Every built-in at several Φ: a form, when found, solves PᵀQP = Q; a
/// method whose roots leave the unit circle has none (Standard Euler,
/// |z|² = 1 + Φ²), and Verlet and False Euler have one below Φ_max = 2.
#[test]
fn forms_solve_the_defining_equation() {
    let mut found = 0;
    for name in poly::advanced::builtins::builtin_names() {
        let m = poly::builtin(name).unwrap();
        for phi in [q(1, 10), q(1, 2), q(3, 2)] {
            let values = poly::Params::new().bind("Phi", phi.clone()).bind("D", q(1, 5));
            // An exact irrational constant (sqrt(3)) has no rational P.
            let Some(p) = transition_matrix_at(&m, &values) else {
                assert!(!m.constants().is_empty(), "{name} at {phi}");
                continue;
            };
            match conserved_form(&p) {
                Ok(form) => {
                    found += 1;
                    assert!(residual(&p, &form).iter().flatten().all(|x| *x == q(0, 1)), "{name}");
                    assert!(form.iter().flatten().any(|x| *x != q(0, 1)), "{name}: zero form");
                }
                Err(e) => {
                    assert!(!["false_euler", "verlet"].contains(&name), "{name} at {phi}: {e:?}")
                }
            }
        }
    }
    assert!(found >= 6, "{found} forms found");
    assert_eq!(conserved_form(&at("standard_euler", q(1, 10))), Err(NoForm::None));
}

/// Beyond Φ_max the roots are real, λ and 1/λ (det P = 1): a form is still
/// conserved, but it is indefinite (a hyperbola, not an ellipse).
#[test]
fn form_past_the_limit_is_indefinite() {
    let form = conserved_form(&at("false_euler", q(5, 2))).unwrap();
    assert!(!is_positive_definite(&form));
    assert!(is_positive_definite(&conserved_form(&at("false_euler", q(19, 10))).unwrap()));
}
