//! Positive semidefiniteness, decided exactly by symmetric elimination.
//!
//! A symmetric M is PSD exactly when: it is empty; or some diagonal entry
//! is negative (then it is not); or every diagonal entry is zero (then it is
//! PSD exactly when M = 0, since a nonzero m_ij beside m_ii = m_jj = 0 gives
//! the 2×2 principal minor −m_ij² < 0); or, pivoting on a positive diagonal
//! entry m_kk, the Schur complement M' = M − m_·k m_k· / m_kk (row and
//! column k removed) is PSD (congruence: M ≅ diag(m_kk, M')). No float is
//! involved; the tests hold it against all principal minors.

use std::cmp::Ordering;

use super::value::Value;

/// Whether the symmetric matrix `m` (row by row) is positive semidefinite,
/// decided exactly; entries may hold radicals. Only the upper triangle is
/// read; `None` when `m` is not square.
///
/// ```
/// use poly::advanced::order::{positive_semidefinite, Value};
/// let m = |rows: &[[i64; 2]; 2]| -> Vec<Vec<Value>> {
///     rows.iter().map(|r| r.iter().map(|&x| Value::from(poly::q(x, 1))).collect()).collect()
/// };
/// assert_eq!(positive_semidefinite(&m(&[[1, 1], [1, 1]])), Some(true));
/// assert_eq!(positive_semidefinite(&m(&[[0, 1], [1, 0]])), Some(false));
/// ```
pub fn positive_semidefinite(m: &[Vec<Value>]) -> Option<bool> {
    let n = m.len();
    if m.iter().any(|r| r.len() != n) {
        return None;
    }
    // The upper triangle, symmetric.
    let mut a: Vec<Vec<Value>> =
        (0..n).map(|i| (0..n).map(|j| m[i.min(j)][i.max(j)].clone()).collect()).collect();
    loop {
        let n = a.len();
        if n == 0 {
            return Some(true);
        }
        let mut pivot = None;
        for (k, row) in a.iter().enumerate() {
            match row[k].sign() {
                Ordering::Less => return Some(false),
                Ordering::Greater if pivot.is_none() => pivot = Some(k),
                _ => {}
            }
        }
        let Some(k) = pivot else {
            return Some(a.iter().flatten().all(Value::is_zero));
        };
        let inv = a[k][k].inverse().expect("a positive pivot");
        let col: Vec<Value> = (0..n).map(|i| a[i][k].clone()).collect();
        let keep: Vec<usize> = (0..n).filter(|&i| i != k).collect();
        a =
            keep.iter()
                .map(|&i| {
                    let f = col[i].mul(&inv);
                    keep.iter()
                        .map(|&j| {
                            if f.is_zero() {
                                a[i][j].clone()
                            } else {
                                a[i][j].sub(&f.mul(&col[j]))
                            }
                        })
                        .collect()
                })
                .collect();
    }
}
