//! Conserved quadratic forms of a linear step, exactly.
//!
//! A step x ↦ P x conserves the quadratic form xᵀQx when
//!
//! $$P^\mathsf{T} Q P = Q, \qquad Q = Q^\mathsf{T}.$$
//!
//! For a rational P these are n(n+1)/2 homogeneous linear equations in the
//! entries q_ij (i ≤ j), solved here by Gauss–Jordan elimination over Q.
//! A method whose roots are a distinct pair on the unit circle has exactly
//! one such form up to scale: for False Euler at Φ it is v² + y² − Φ·v·y.
//! The form is positive definite exactly when the state stays on an
//! ellipse; real roots λ, 1/λ conserve an indefinite form instead.
//! [`conserved_form`] returns it scaled so that its first nonzero diagonal
//! entry is 1.

use num_traits::{One, Signed, Zero};

use crate::{Method, Q};

/// Why a step has no single conserved form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NoForm {
    /// Only Q = 0 solves PᵀQP = Q (some root is off the unit circle).
    None,
    /// The solutions form a space of this dimension (> 1): the form is not
    /// unique (repeated roots or several pairs on the unit circle).
    NotUnique(usize),
    /// P has no rational value there: a parameter without a value, an
    /// exact irrational constant, or an implicit step singular there.
    Undefined,
}

/// The index of q_ij (i ≤ j) among the unknowns.
fn unknown(n: usize, i: usize, j: usize) -> usize {
    let (i, j) = if i <= j { (i, j) } else { (j, i) };
    i * n - i * (i + 1) / 2 + j
}

/// A basis of the symmetric Q with PᵀQP = Q (each an n×n matrix, rows).
///
/// Panics when `p` is not square (a programmer error).
#[track_caller]
pub fn conserved_forms(p: &[Vec<Q>]) -> Vec<Vec<Vec<Q>>> {
    let n = p.len();
    assert!(p.iter().all(|r| r.len() == n), "square matrix");
    let m = n * (n + 1) / 2;
    // Row (a, b), a ≤ b: Σ_ij P_ia P_jb q_ij − q_ab = 0.
    let mut rows: Vec<Vec<Q>> = Vec::with_capacity(m);
    for a in 0..n {
        for b in a..n {
            let mut row = vec![Q::zero(); m];
            for i in 0..n {
                for j in 0..n {
                    let c = &p[i][a] * &p[j][b];
                    if !c.is_zero() {
                        row[unknown(n, i, j)] += c;
                    }
                }
            }
            row[unknown(n, a, b)] -= Q::one();
            rows.push(row);
        }
    }
    // Gauss–Jordan to reduced row echelon form.
    let mut pivots = Vec::new();
    let mut r = 0;
    for col in 0..m {
        let Some(k) = (r..rows.len()).find(|&k| !rows[k][col].is_zero()) else { continue };
        rows.swap(r, k);
        let inv = rows[r][col].recip();
        for x in rows[r].iter_mut() {
            *x *= &inv;
        }
        for k in 0..rows.len() {
            if k != r && !rows[k][col].is_zero() {
                let f = rows[k][col].clone();
                let pivot = rows[r].clone();
                for (x, p) in rows[k].iter_mut().zip(&pivot) {
                    *x -= &f * p;
                }
            }
        }
        pivots.push(col);
        r += 1;
    }
    // One basis vector per free column.
    let mut basis = Vec::new();
    for free in (0..m).filter(|c| !pivots.contains(c)) {
        let mut q = vec![Q::zero(); m];
        q[free] = Q::one();
        for (row, &pc) in pivots.iter().enumerate() {
            q[pc] = -rows[row][free].clone();
        }
        let mut mat = vec![vec![Q::zero(); n]; n];
        for i in 0..n {
            for j in 0..n {
                mat[i][j] = q[unknown(n, i, j)].clone();
            }
        }
        basis.push(mat);
    }
    basis
}

/// The one conserved form of `p`, scaled so that its first nonzero
/// diagonal entry is 1 (positive), or why there is none.
pub fn conserved_form(p: &[Vec<Q>]) -> Result<Vec<Vec<Q>>, NoForm> {
    let mut basis = conserved_forms(p);
    match basis.len() {
        0 => Err(NoForm::None),
        1 => {
            let mut q = basis.pop().expect("one form");
            let n = q.len();
            let scale = (0..n).map(|i| q[i][i].clone()).find(|d| !d.is_zero());
            if let Some(s) = scale {
                let inv = s.recip();
                q.iter_mut().flatten().for_each(|x| *x *= &inv);
            }
            Ok(q)
        }
        k => Err(NoForm::NotUnique(k)),
    }
}

/// Whether the symmetric `q` is positive definite (every pivot of its
/// symmetric elimination is positive), decided exactly.
pub fn is_positive_definite(q: &[Vec<Q>]) -> bool {
    let n = q.len();
    let mut a: Vec<Vec<Q>> = q.to_vec();
    for k in 0..n {
        if !a[k][k].is_positive() {
            return false;
        }
        for i in k + 1..n {
            let f = &a[i][k] / &a[k][k];
            let pivot = a[k].clone();
            for (x, p) in a[i].iter_mut().zip(&pivot).skip(k) {
                *x -= &f * p;
            }
        }
    }
    true
}

/// xᵀQx, exactly.
pub fn form_value(q: &[Vec<Q>], x: &[Q]) -> Q {
    let mut sum = Q::zero();
    for (i, row) in q.iter().enumerate() {
        for (j, qij) in row.iter().enumerate() {
            if !qij.is_zero() {
                sum += qij * &x[i] * &x[j];
            }
        }
    }
    sum
}

/// The exact transition matrix of `method` with its parameters set to
/// `values` (every parameter must have a value; `None` otherwise, and for
/// an exact irrational constant or an implicit step singular there).
pub fn transition_matrix_at(method: &Method, params: &crate::Params) -> Option<Vec<Vec<Q>>> {
    let values = params.for_method(method).ok()?;
    let values = &values;
    // An implicit step's P is (d·P)/d with d = det A.
    let (p, d) = if method.is_implicit() {
        crate::derive::implicit::transition_fraction(method, &crate::lang::system::system(method))
    } else {
        (crate::derive::routes::transition_matrix(method), crate::Poly::one())
    };
    let d = d.eval(values)?;
    if d.is_zero() {
        return None;
    }
    (0..p.rows())
        .map(|i| p.row(i).iter().map(|e| e.eval(values).map(|x| x / &d)).collect())
        .collect()
}

/// The form as text over the slot names, e.g. `v^2 + y^2 - 1/10*v*y`.
pub fn form_text(q: &[Vec<Q>], names: &[String]) -> String {
    let mut out = String::new();
    let n = q.len();
    for i in 0..n {
        for j in i..n {
            let c = if i == j { q[i][i].clone() } else { &q[i][j] + &q[j][i] };
            if c.is_zero() {
                continue;
            }
            let mono = if i == j {
                format!("{}^2", names[i])
            } else {
                format!("{}*{}", names[i], names[j])
            };
            let (neg, abs) = (c.is_negative(), c.abs());
            let sign = match (out.is_empty(), neg) {
                (true, false) => "",
                (true, true) => "-",
                (false, false) => " + ",
                (false, true) => " - ",
            };
            if abs.is_one() {
                out += &format!("{sign}{mono}");
            } else {
                out += &format!("{sign}{abs}*{mono}");
            }
        }
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}

impl crate::Derivation {
    /// The conserved quadratic form Q (PᵀQP = Q) at the parameter values
    /// `params` (Φ among them), when the step has exactly one.
    pub fn conserved_form(&self, params: &crate::Params) -> Result<Vec<Vec<Q>>, NoForm> {
        match transition_matrix_at(self.method(), params) {
            Some(p) => conserved_form(&p),
            None => Err(NoForm::Undefined),
        }
    }
}
