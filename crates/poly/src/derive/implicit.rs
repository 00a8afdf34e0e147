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
//! system is singular. The z route (`routes.rs`) reaches the same polynomial
//! from the equations as written, with no solving.

use crate::lang::method::Method;
use crate::lang::system::{fix, System};
use crate::{Poly, PolyMatrix, Sym};

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
