//! The Sylvester resultant of two polynomials in one symbol whose
//! coefficients are polynomials in the others: the projection that
//! eliminates a symbol (region boundaries, the w-plane's boundary locus,
//! moduli of roots).

use crate::multivariate::matrix::PolyMatrix;
use crate::multivariate::poly::Poly;

/// The Sylvester resultant of two polynomials given by their coefficients
/// (lowest power first), each coefficient a polynomial in the remaining
/// symbols; zero when either is zero.
pub fn resultant(f: &[Poly], g: &[Poly]) -> Poly {
    let trim = |c: &[Poly]| -> Vec<Poly> {
        let mut v = c.to_vec();
        while v.last().is_some_and(Poly::is_zero) {
            v.pop();
        }
        v
    };
    let (f, g) = (trim(f), trim(g));
    if f.is_empty() || g.is_empty() {
        return Poly::zero();
    }
    let (m, n) = (f.len() - 1, g.len() - 1);
    if m + n == 0 {
        return Poly::one();
    }
    let size = m + n;
    let mut rows = vec![vec![Poly::zero(); size]; size];
    for i in 0..n {
        for (k, c) in f.iter().rev().enumerate() {
            rows[i][i + k] = c.clone();
        }
    }
    for i in 0..m {
        for (k, c) in g.iter().rev().enumerate() {
            rows[n + i][i + k] = c.clone();
        }
    }
    PolyMatrix::from_rows(rows).det()
}
