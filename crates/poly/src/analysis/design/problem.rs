//! The design problem as given (a method, an objective, one or two free
//! parameters with exact ranges, the others bound, an optional least
//! order), checked, and turned into the engine that evaluates the objective
//! exactly: a sign system (the axes of y' = λy for a one-step method, the
//! SSP coefficient) or the oscillator's Φ_max, with the order conditions
//! that restrict the allowed set as polynomials in the free parameters.

use std::collections::HashMap;

use num_traits::One;

use super::oscillator::{tableau_chi, Oscillator, Source};
use super::report::{input_error, FreeParam, Objective};
use super::system::{SignCondition, SignSystem};
use super::tableau::ParamTableau;
use crate::analysis::order::trees;
use crate::error::Error;
use crate::{Derivation, Params, Poly, PolyMatrix, Sym, Q};

/// The method whose parameters are designed.
#[derive(Clone, Copy, Debug)]
pub enum Subject<'a> {
    /// A derived `.zm` program: an oscillator program in Φ, or a scalar
    /// program in `w`.
    Program(&'a Derivation),
    /// A Butcher tableau whose entries name the parameters.
    Tableau(&'a ParamTableau),
}

/// What to maximise, over what.
#[derive(Clone, Debug)]
pub struct Problem<'a> {
    /// The method.
    pub subject: Subject<'a>,
    /// The objective.
    pub objective: Objective,
    /// One or two free parameters with their ranges.
    pub free: Vec<FreeParam>,
    /// Values of the method's other parameters.
    pub bound: Params,
    /// Keep only the points where the classical order (a tableau) or the
    /// linear order (a program) is at least this.
    pub min_order: Option<usize>,
}

/// The engine behind an objective.
#[derive(Clone, Debug)]
pub(crate) enum Engine<'a> {
    Signs(SignSystem),
    Oscillator(Oscillator<'a>),
}

/// A checked problem.
#[derive(Clone, Debug)]
pub(crate) struct Setup<'a> {
    pub engine: Engine<'a>,
    /// The free parameters' symbols, in the problem's order.
    pub syms: Vec<Sym>,
    /// Polynomials in the free parameters that must vanish (the order
    /// conditions); empty when every point is allowed.
    pub order_conditions: Vec<Poly>,
}

fn declared(subject: &Subject) -> Vec<Sym> {
    match subject {
        Subject::Program(d) => {
            d.method().params().iter().copied().filter(|&s| s != Sym::phi()).collect()
        }
        Subject::Tableau(t) => t.params().to_vec(),
    }
}

fn method_name(subject: &Subject) -> String {
    match subject {
        Subject::Program(d) => d.method().name().to_owned(),
        Subject::Tableau(t) => t.name().to_owned(),
    }
}

/// Checks the problem and builds its engine.
pub(crate) fn setup<'a>(problem: &Problem<'a>) -> Result<Setup<'a>, Error> {
    let name = method_name(&problem.subject);
    if problem.free.is_empty() || problem.free.len() > 2 {
        return Err(input_error(format!(
            "{} free parameters: expected one or two",
            problem.free.len()
        )));
    }
    let params = declared(&problem.subject);
    let list = params.iter().map(|s| s.name()).collect::<Vec<_>>().join(", ");
    let mut syms = Vec::new();
    for f in &problem.free {
        if f.lo > f.hi {
            return Err(input_error(format!(
                "the range of {} is empty ({}..{}): expected lo <= hi",
                f.name, f.lo, f.hi
            )));
        }
        let s = Sym::new(&f.name);
        if !params.contains(&s) {
            return Err(input_error(format!(
                "method `{name}` has no parameter {}; expected one of: {list}",
                f.name
            )));
        }
        if syms.contains(&s) || problem.bound.value(&f.name).is_some() {
            return Err(input_error(format!("{} is given twice", f.name)));
        }
        syms.push(s);
    }
    for (b, _) in problem.bound.iter() {
        if !params.contains(&Sym::new(b)) {
            return Err(input_error(format!(
                "method `{name}` has no parameter {b}; expected one of: {list}"
            )));
        }
    }
    if let Some(s) =
        params.iter().find(|s| !syms.contains(s) && problem.bound.value(s.name()).is_none())
    {
        return Err(input_error(format!(
            "parameter {} is neither free nor bound: give it a range or a value",
            s.name()
        )));
    }
    let bound: HashMap<Sym, Q> =
        problem.bound.iter().map(|(n, v)| (Sym::new(n), v.clone())).collect();
    let objective = problem.objective;
    // χ(z, w) of a one-step method on y' = λy, when the objective asks it.
    let scalar_chi = |chi: Poly| -> Result<(Poly, Poly), Error> {
        let z = Sym::z();
        if chi.degree_in(z) != 1 {
            return Err(input_error(format!(
                "{objective} is optimised exactly for one-step methods (chi linear in z); \
                 `{name}` has chi of degree {} in z",
                chi.degree_in(z)
            )));
        }
        let c = chi.coeffs_in(z);
        Ok((c[1].clone(), c[0].clone()))
    };
    let (engine, one_step) = match (objective, &problem.subject) {
        (Objective::SspCoefficient, Subject::Program(_)) => {
            return Err(input_error(format!(
                "ssp_coefficient applies to a Butcher tableau; `{name}` is a program"
            )))
        }
        (Objective::SspCoefficient, Subject::Tableau(t)) => (Engine::Signs(ssp_system(t)), None),
        (Objective::PhiMax, Subject::Program(d)) => {
            if d.method().is_scalar() {
                return Err(input_error(format!(
                    "`{name}` is written for y' = λy (it reads w): phi_max is the oscillator's; \
                     maximise real_limit or imag_limit"
                )));
            }
            let chi = d.charpoly().eval_partial(&bound);
            let source = Source::Program(d, problem.bound.clone());
            (Engine::Oscillator(Oscillator::new(source, &chi)), None)
        }
        (Objective::PhiMax, Subject::Tableau(t)) => {
            let chi = tableau_chi(t);
            (Engine::Oscillator(Oscillator::new(Source::Tableau(t), &chi)), None)
        }
        (_, Subject::Program(d)) => {
            let chi = if d.method().is_scalar() {
                d.charpoly().eval_partial(&bound)
            } else {
                d.symbolic_scalar_charpoly(&bound)?
            };
            let chi = super::algebra::content_in(&chi, Sym::z()).1;
            let (c1, c0) = scalar_chi(chi)?;
            (Engine::Signs(axis_system(objective, &c1, &c0)), Some((c1, c0)))
        }
        (_, Subject::Tableau(t)) => {
            let (p, q) = t.p_q();
            (Engine::Signs(axis_system(objective, &q, &-&p)), None)
        }
    };
    let order_conditions = match problem.min_order {
        None | Some(0) => Vec::new(),
        Some(order) => match (&problem.subject, &one_step, objective) {
            (Subject::Tableau(t), _, _) => classical_conditions(t, order)?,
            (Subject::Program(_), Some((c1, c0)), _) => linear_conditions(c1, c0, order),
            (Subject::Program(d), None, _) => {
                let chi = d.charpoly().eval_partial(&bound);
                match (d.method().is_scalar(), chi.degree_in(Sym::z())) {
                    (true, 1) => {
                        let c = chi.coeffs_in(Sym::z());
                        linear_conditions(&c[1], &c[0], order)
                    }
                    _ => {
                        return Err(input_error(format!(
                            "min_order on `{name}`: the linear order is read as conditions on \
                             the parameters for one-step methods (a scalar program linear in \
                             z, or a tableau) only"
                        )))
                    }
                }
            }
        },
    };
    let order_conditions = order_conditions
        .into_iter()
        .map(|p| p.eval_partial(&bound))
        .filter(|p| !p.is_zero())
        .collect();
    Ok(Setup { engine, syms, order_conditions })
}

/// The margin of an axis of y' = λy for χ = c₁(w)z + c₀(w) (R = −c₀/c₁):
/// on the negative real axis w = −x, (c₁ + c₀)(c₁ − c₀) ≥ 0, that is
/// |R| ≤ 1 with the factors R = 1 and R = −1; on the imaginary axis
/// w = iy, |c₁|² − |c₀|² ≥ 0.
fn axis_system(objective: Objective, c1: &Poly, c0: &Poly) -> SignSystem {
    let w = Sym::w();
    if objective == Objective::RealLimit {
        let x = Sym::new("x_design");
        let at = |p: &Poly| p.subs(w, &-&Poly::sym(x));
        let mut s = SignSystem { x, factors: Vec::new(), conditions: Vec::new() };
        let plus = s.factor(at(&(c1 + c0)), "Q(w) - P(w) (R = 1)");
        let minus = s.factor(at(&(c1 - c0)), "Q(w) + P(w) (R = -1)");
        s.conditions.push(SignCondition {
            factors: vec![plus, minus],
            label: "|R(w)| <= 1 on the negative real axis".to_owned(),
        });
        return s;
    }
    let y = Sym::new("y_design");
    let split = |f: &Poly| crate::analysis::plane::at_imaginary(f, w, y);
    let ((ar, ai), (br, bi)) = (split(c1), split(c0));
    let margin = &(&(&ar * &ar) + &(&ai * &ai)) - &(&(&br * &br) + &(&bi * &bi));
    let mut s = SignSystem { x: y, factors: Vec::new(), conditions: Vec::new() };
    let k = s.factor(margin, "|Q(iy)|^2 - |P(iy)|^2 (|R(iy)| = 1)");
    s.conditions.push(SignCondition {
        factors: vec![k],
        label: "|R(iy)| <= 1 on the imaginary axis".to_owned(),
    });
    s
}

/// Kraaijevanger's conditions for A = Ã/δ, b = b̃/δ (see
/// `order::ssp`): with M = δI + rÃ, D̃ = det M and adj M, each of D̃,
/// Ã·adj, b̃ᵀadj, adj·e and D̃ − r b̃ᵀadj e is ≥ 0 once multiplied by the
/// power of δ that makes it the true quantity's sign.
fn ssp_system(t: &ParamTableau) -> SignSystem {
    let (a, b, delta) = t.common();
    let s = t.stages();
    let r = Sym::new("r_design");
    let rp = Poly::sym(r);
    let m: Vec<Vec<Poly>> = (0..s)
        .map(|i| {
            (0..s)
                .map(|j| {
                    let e = &rp * &a[i][j];
                    if i == j {
                        &e + &delta
                    } else {
                        e
                    }
                })
                .collect()
        })
        .collect();
    let det = PolyMatrix::from_rows(m.clone()).det();
    // adj(M)_{ij} = (−1)^{i+j} det(M without row j and column i).
    let adj: Vec<Vec<Poly>> = (0..s)
        .map(|i| {
            (0..s)
                .map(|j| {
                    if s == 1 {
                        return Poly::one();
                    }
                    let minor: Vec<Vec<Poly>> = (0..s)
                        .filter(|&k| k != j)
                        .map(|k| (0..s).filter(|&l| l != i).map(|l| m[k][l].clone()).collect())
                        .collect();
                    let d = PolyMatrix::from_rows(minor).det();
                    if (i + j) % 2 == 0 {
                        d
                    } else {
                        -&d
                    }
                })
                .collect()
        })
        .collect();
    let mut sys = SignSystem { x: r, factors: Vec::new(), conditions: Vec::new() };
    let delta_k = (delta.as_constant().is_none())
        .then(|| sys.factor(delta.clone(), "the common denominator of the entries"));
    let add = |sys: &mut SignSystem, p: Poly, power: usize, label: String| {
        if p.is_zero() {
            return;
        }
        let k = sys.factor(p, &label);
        let mut factors = vec![k];
        if power % 2 == 1 {
            factors.extend(delta_k);
        }
        sys.conditions.push(SignCondition { factors, label });
    };
    add(&mut sys, det.clone(), s, "det(I + rA) (I + rK invertible)".to_owned());
    let dot =
        |u: &[Poly], v: &[Poly]| u.iter().zip(v).fold(Poly::zero(), |acc, (x, y)| &acc + &(x * y));
    let col = |j: usize| -> Vec<Poly> { (0..s).map(|k| adj[k][j].clone()).collect() };
    for (i, row) in a.iter().enumerate() {
        for j in 0..s {
            add(
                &mut sys,
                dot(row, &col(j)),
                s,
                format!("entry ({}, {}) of A(I + rA)^-1", i + 1, j + 1),
            );
        }
    }
    for j in 0..s {
        add(&mut sys, dot(&b, &col(j)), s, format!("entry {} of b^T(I + rA)^-1", j + 1));
    }
    let adj_e: Vec<Poly> =
        adj.iter().map(|row| row.iter().fold(Poly::zero(), |acc, x| &acc + x)).collect();
    for (i, e) in adj_e.iter().enumerate() {
        add(&mut sys, e.clone(), s - 1, format!("entry {} of (I + rA)^-1 e", i + 1));
    }
    add(
        &mut sys,
        &det - &(&rp * &dot(&b, &adj_e)),
        s,
        "the last entry of (I + rK)^-1 e".to_owned(),
    );
    sys
}

/// The linear order conditions for χ = c₁z + c₀: c₁(w)e^w + c₀(w) =
/// O(w^(p+1)), one polynomial per power of w up to p.
fn linear_conditions(c1: &Poly, c0: &Poly, order: usize) -> Vec<Poly> {
    let w = Sym::w();
    let (a, b) = (c1.coeffs_in(w), c0.coeffs_in(w));
    let mut fact = vec![Q::one()];
    for k in 1..=order {
        fact.push(&fact[k - 1] * Q::from_integer((k as i64).into()));
    }
    (0..=order)
        .map(|k| {
            let mut s = b.get(k).cloned().unwrap_or_default();
            for j in 0..=k {
                if let Some(aj) = a.get(j) {
                    s += &aj.scale(&fact[k - j].recip());
                }
            }
            s
        })
        .collect()
}

/// A tree from its notation: the list of its children's notations.
fn children(notation: &str) -> Vec<&str> {
    let inner = &notation[1..notation.len() - 1];
    let mut out = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (i, ch) in inner.char_indices() {
        match ch {
            '[' => {
                if depth == 0 {
                    start = i;
                }
                depth += 1;
            }
            ']' => {
                depth -= 1;
                if depth == 0 {
                    out.push(&inner[start..=i]);
                }
            }
            _ => {}
        }
    }
    out
}

/// The stage vector g̃_t (Ã's powers applied along the tree).
fn stage_vector(notation: &str, a: &[Vec<Poly>]) -> Vec<Poly> {
    let s = a.len();
    let mut g = vec![Poly::one(); s];
    for child in children(notation) {
        let u = stage_vector(child, a);
        for i in 0..s {
            let au = a[i].iter().zip(&u).fold(Poly::zero(), |acc, (x, y)| &acc + &(x * y));
            g[i] = &g[i] * &au;
        }
    }
    g
}

/// The classical order conditions up to `order`: γ(t)·b̃·g̃_t − δ^|t| for
/// every rooted tree t with |t| ≤ order.
fn classical_conditions(t: &ParamTableau, order: usize) -> Result<Vec<Poly>, Error> {
    let (a, b, delta) = t.common();
    let mut out = Vec::new();
    for n in 1..=order {
        for tree in trees(n)? {
            let g = stage_vector(tree.notation(), &a);
            let phi = b.iter().zip(&g).fold(Poly::zero(), |acc, (x, y)| &acc + &(x * y));
            let gamma = Q::from_integer((tree.density() as i64).into());
            out.push(&phi.scale(&gamma) - &delta.pow(n as u32));
        }
    }
    Ok(out)
}
