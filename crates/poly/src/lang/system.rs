//! The linear system of an implicit step: symbolic execution over the
//! start slots s and the unknowns u writes the equations `u = r(s, u)` as
//! A u = E s (A = I − ∂r/∂u, E = ∂r/∂s) and the end-of-step slots as
//! s' = H_s s + H_u u. Part of the language because a method whose system
//! is singular for every Φ is refused when it is read; `derive` solves it.

use crate::lang::method::{EndValue, Method, Operand};
use crate::multivariate::constants as field;
use crate::{Poly, PolyMatrix};

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

pub(crate) fn fix(m: &Method, p: Poly) -> Poly {
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

/// det `a`, reduced in the field of `m`'s constants (1 when `a` is empty):
/// for `a` = A, the determinant of the step's linear system.
pub(crate) fn determinant(m: &Method, a: &PolyMatrix) -> Poly {
    if a.rows() == 0 {
        return Poly::one();
    }
    fix(m, a.det())
}

/// The first of `rows` that is a linear combination of the rows before it
/// (over the rational functions in the parameters, with `m`'s constants);
/// `None` when the rows are linearly independent.
///
/// k rows R are dependent exactly when their Gram determinant det(R Rᵀ) is
/// 0: by Cauchy–Binet it is the sum of the squares of R's k×k minors, and
/// everything here is real (rational coefficients, positive real radicals,
/// real parameters), so the sum is the zero polynomial only when every
/// minor is. A prefix that is dependent stays dependent when rows are
/// added, so a binary search over the prefixes finds the first dependent
/// row in O(log n) determinants.
pub(crate) fn first_dependent_row(m: &Method, rows: &[Vec<Poly>]) -> Option<usize> {
    let dependent = |k: usize| {
        let gram = PolyMatrix::from_rows(
            (0..k)
                .map(|i| {
                    (0..k)
                        .map(|j| {
                            let mut acc = Poly::zero();
                            for (x, y) in rows[i].iter().zip(&rows[j]) {
                                if !x.is_zero() && !y.is_zero() {
                                    acc += &(x * y);
                                }
                            }
                            fix(m, acc)
                        })
                        .collect()
                })
                .collect(),
        );
        determinant(m, &gram).is_zero()
    };
    if !dependent(rows.len()) {
        return None;
    }
    // dependent(lo) is false (no rows are independent), dependent(hi) true.
    let (mut lo, mut hi) = (0, rows.len());
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if dependent(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi - 1)
}
