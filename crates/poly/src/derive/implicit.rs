//! The state route for implicit steps: the linear system, P as rational
//! functions, and χ as the determinant of a pencil.
//!
//! Symbolic execution of the step over the start slots s (N of them) and the
//! unknowns u (n of them) writes every value as a linear form in (s, u). The
//! equations `u_j = r_j(s, u)` give the system
//!
//! $$ A u = E s, \qquad A = I - \partial r / \partial u, \quad E = \partial r / \partial s, $$
//!
//! and the slots at the end of the step are s' = H_s s + H_u u. So
//! P = H_s + H_u A⁻¹ E, whose entries are rational functions of Φ with the
//! common denominator d = det A; [`transition_fraction`] returns d·P (by
//! cofactors, exactly) and d. The characteristic polynomial with the
//! denominators cleared is
//!
//! $$ \chi(z) = \det A \cdot \det(zI - P) = \det \begin{pmatrix} A & -E \\ -H_u & zI - H_s \end{pmatrix}, $$
//!
//! the determinant of the pencil zA' − B' with A' = diag(0, I) and
//! B' = [[−A, E], [H_u, H_s]] (Schur complement). Its leading coefficient in
//! z is det A, which may depend on Φ; its zeros are the Φ at which the step's
//! system is singular. The z route (`derive.rs`) reaches the same polynomial
//! from the equations as written, with no solving.

use crate::lang::method::{EndValue, Method, Operand};
use crate::multivariate::constants as field;
use crate::{Poly, PolyMatrix, Sym};

/// The linear system of an implicit step and its output map.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct System {
    /// A = I − ∂r/∂u, one row per equation (n × n).
    pub a: PolyMatrix,
    /// E = ∂r/∂s (n × N).
    pub e: PolyMatrix,
    /// H_s: the end-of-step slots' dependence on the start slots (N × N).
    pub h_s: PolyMatrix,
    /// H_u: their dependence on the unknowns (N × n).
    pub h_u: PolyMatrix,
}

fn fix(m: &Method, p: Poly) -> Poly {
    if m.constants().is_empty() {
        p
    } else {
        field::reduce(&p)
    }
}

/// The system of `m` by symbolic execution over (slots, unknowns).
pub fn system(m: &Method) -> System {
    let slots = m.slots();
    let (n_s, n_u) = (slots.len(), m.unknowns().len());
    let width = n_s + n_u;
    let slot_of = |var: usize, lag: u32| {
        slots.iter().position(|&s| s == (var, lag)).expect("lag within the method's history")
    };
    let unit = |k: usize| {
        let mut v = vec![Poly::zero(); width];
        v[k] = Poly::one();
        v
    };
    let form = |terms: &[(Operand, Poly)], values: &[Vec<Poly>]| {
        let mut acc = vec![Poly::zero(); width];
        for (op, c) in terms {
            let src = match *op {
                Operand::Stmt(t) => values[t].clone(),
                Operand::Start { var, lag } => unit(slot_of(var, lag)),
                Operand::Unknown(u) => unit(n_s + u),
            };
            for (x, s) in acc.iter_mut().zip(&src) {
                if !s.is_zero() {
                    *x += &(c * s);
                }
            }
        }
        acc.into_iter().map(|p| fix(m, p)).collect::<Vec<_>>()
    };
    let mut values: Vec<Vec<Poly>> = Vec::with_capacity(m.assigns().len());
    for a in m.assigns() {
        let v = form(&a.terms, &values);
        values.push(v);
    }
    let mut a = PolyMatrix::identity(n_u);
    let mut e = PolyMatrix::zeros(n_u, n_s);
    for eq in m.equations() {
        let r = form(&eq.terms, &values);
        let j = eq.unknown;
        for (i, x) in r.into_iter().enumerate() {
            if i < n_s {
                e[(j, i)] = x;
            } else {
                a[(j, i - n_s)] -= &x;
            }
        }
    }
    let mut h_s = PolyMatrix::zeros(n_s, n_s);
    let mut h_u = PolyMatrix::zeros(n_s, n_u);
    for (row, &(var, lag)) in slots.iter().enumerate() {
        let new = if lag == 0 {
            match m.end_value(var) {
                EndValue::Assign(k) => values[k].clone(),
                EndValue::Unknown(u) => unit(n_s + u),
                EndValue::Kept => unit(slot_of(var, 0)),
            }
        } else {
            unit(slot_of(var, lag - 1))
        };
        for (col, x) in new.into_iter().enumerate() {
            if col < n_s {
                h_s[(row, col)] = x;
            } else {
                h_u[(row, col - n_s)] = x;
            }
        }
    }
    System { a, e, h_s, h_u }
}

/// det A, the determinant of the step's linear system (1 when explicit).
pub fn system_determinant(m: &Method) -> Poly {
    let s = system(m);
    if s.a.rows() == 0 {
        return Poly::one();
    }
    fix(m, s.a.det())
}

/// χ = det [[A, −E], [−H_u, zI − H_s]] = det A · det(zI − P).
pub fn charpoly_pencil(m: &Method, s: &System) -> Poly {
    let (n_u, n_s) = (s.a.rows(), s.h_s.rows());
    let n = n_u + n_s;
    let zp = Poly::sym(Sym::z());
    let mut big = PolyMatrix::zeros(n, n);
    for i in 0..n_u {
        for j in 0..n_u {
            big[(i, j)] = s.a[(i, j)].clone();
        }
        for j in 0..n_s {
            big[(i, n_u + j)] = -&s.e[(i, j)];
        }
    }
    for i in 0..n_s {
        for j in 0..n_u {
            big[(n_u + i, j)] = -&s.h_u[(i, j)];
        }
        for j in 0..n_s {
            big[(n_u + i, n_u + j)] = -&s.h_s[(i, j)];
        }
        big[(n_u + i, n_u + i)] += &zp;
    }
    fix(m, big.det())
}

/// (d·P, d) with d = det A: the transition matrix as rational functions
/// over one common denominator, P = H_s + H_u adj(A) E / d.
pub fn transition_fraction(m: &Method, s: &System) -> (PolyMatrix, Poly) {
    let n_u = s.a.rows();
    let n_s = s.h_s.rows();
    let d = fix(m, s.a.det());
    // adj(A)[i][j] = (−1)^(i+j) · minor(j, i).
    let mut adj = PolyMatrix::zeros(n_u, n_u);
    for i in 0..n_u {
        for j in 0..n_u {
            let minor = if n_u == 1 {
                Poly::one()
            } else {
                let rows: Vec<Vec<Poly>> = (0..n_u)
                    .filter(|&r| r != j)
                    .map(|r| (0..n_u).filter(|&c| c != i).map(|c| s.a[(r, c)].clone()).collect())
                    .collect();
                PolyMatrix::from_rows(rows).det()
            };
            adj[(i, j)] = fix(m, if (i + j) % 2 == 0 { minor } else { -&minor });
        }
    }
    let mut p = PolyMatrix::zeros(n_s, n_s);
    for r in 0..n_s {
        for c in 0..n_s {
            let mut acc = &d * &s.h_s[(r, c)];
            for k in 0..n_u {
                if s.h_u[(r, k)].is_zero() {
                    continue;
                }
                for j in 0..n_u {
                    if adj[(k, j)].is_zero() || s.e[(j, c)].is_zero() {
                        continue;
                    }
                    acc += &(&(&s.h_u[(r, k)] * &adj[(k, j)]) * &s.e[(j, c)]);
                }
            }
            p[(r, c)] = fix(m, acc);
        }
    }
    (p, d)
}

/// The Φ > 0 at which an implicit step's system is singular: the positive
/// real zeros of d = det A (as a polynomial in Φ alone). For a d holding
/// constants, the zeros of its norm over Q at which d itself changes sign.
/// Empty for an explicit method or when d holds other parameters.
pub fn singular_points(d: &crate::Derivation) -> Vec<crate::Algebraic> {
    let den = &d.p_denominator;
    let n = field::norm(den);
    let Some(u) = n.to_upoly(Sym::phi()) else { return Vec::new() };
    if u.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    let roots = crate::Algebraic::positive_roots(&u.squarefree());
    if !field::has_generators(den) {
        return roots;
    }
    let at = |x: &crate::Q| {
        field::sign(&field::reduce(&den.subs(Sym::phi(), &Poly::constant(x.clone()))))
    };
    roots
        .into_iter()
        .filter(|r| {
            let r = r.refine(&crate::Q::new(1.into(), 1_000_000.into()));
            let (lo, hi) = r.interval();
            at(&lo) != at(&hi)
        })
        .collect()
}
