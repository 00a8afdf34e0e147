//! Dense f64 linear algebra for the numeric route (faer): the orthonormal
//! complement of the rigid subspace (Householder), the deflated maps, their
//! eigenvalues, matrix powers, the ∞-norm bound, and the assignment that
//! pairs eigenvalues with modes (the Hungarian algorithm, O(n²m)).

use faer::Mat;
use num_complex::Complex64 as C64;

use crate::error::Error;

/// A row-major nested matrix as faer's.
#[cfg(test)]
pub(crate) fn mat(rows: &[Vec<f64>]) -> Mat<f64> {
    let n = rows.len();
    let m = rows.first().map_or(0, Vec::len);
    Mat::from_fn(n, m, |i, j| rows[i][j])
}

/// An orthonormal basis (n × (n − r)) of the orthogonal complement of the
/// span of `basis` (r independent vectors of length n), from a Householder
/// QR of the basis: the last n − r columns of Q.
pub(crate) fn complement(basis: &[Vec<f64>], n: usize) -> Mat<f64> {
    let r = basis.len();
    // Householder vectors of the n × r matrix, column by column.
    let mut a: Vec<Vec<f64>> = basis.to_vec();
    let mut vs: Vec<Vec<f64>> = Vec::with_capacity(r);
    for k in 0..r {
        // Apply the previous reflections to column k.
        let mut col = a[k].clone();
        for (j, v) in vs.iter().enumerate() {
            reflect(v, j, &mut col);
        }
        let norm = col[k..].iter().map(|x| x * x).sum::<f64>().sqrt();
        let mut v = vec![0.0; n];
        let alpha = if col[k] >= 0.0 { -norm } else { norm };
        v[k] = col[k] - alpha;
        v[k + 1..n].copy_from_slice(&col[k + 1..n]);
        let vn = v[k..].iter().map(|x| x * x).sum::<f64>().sqrt();
        if vn > 0.0 {
            v.iter_mut().for_each(|x| *x /= vn);
        }
        vs.push(v);
        a[k] = col;
    }
    // Q e_c for c = r..n: apply the reflections in reverse order.
    let mut out = Mat::<f64>::zeros(n, n - r);
    for c in r..n {
        let mut e = vec![0.0; n];
        e[c] = 1.0;
        for (j, v) in vs.iter().enumerate().rev() {
            reflect(v, j, &mut e);
        }
        for i in 0..n {
            out[(i, c - r)] = e[i];
        }
    }
    out
}

/// x ← (I − 2vvᵀ) x, v supported from index `from`.
fn reflect(v: &[f64], from: usize, x: &mut [f64]) {
    let d: f64 = v[from..].iter().zip(&x[from..]).map(|(a, b)| a * b).sum();
    for (xi, vi) in x[from..].iter_mut().zip(&v[from..]) {
        *xi -= 2.0 * d * vi;
    }
}

/// Q_⊥ = blockdiag(R_⊥, R_⊥, I_extra): the coordinates of the non-rigid
/// part of a state (x, v, extra).
pub(crate) fn block_complement(rperp: &Mat<f64>, extra: usize) -> Mat<f64> {
    let (n, k) = (rperp.nrows(), rperp.ncols());
    let mut q = Mat::<f64>::zeros(2 * n + extra, 2 * k + extra);
    for i in 0..n {
        for j in 0..k {
            q[(i, j)] = rperp[(i, j)];
            q[(n + i, k + j)] = rperp[(i, j)];
        }
    }
    for e in 0..extra {
        q[(2 * n + e, 2 * k + e)] = 1.0;
    }
    q
}

/// Q_⊥ᵀ A Q_⊥.
pub(crate) fn project(a: &Mat<f64>, q: &Mat<f64>) -> Mat<f64> {
    q.transpose() * (a * q)
}

/// The eigenvalues of a square matrix (faer).
pub(crate) fn eigenvalues(a: &Mat<f64>) -> Result<Vec<C64>, Error> {
    if a.nrows() == 0 {
        return Ok(Vec::new());
    }
    a.eigenvalues().map_err(|e| {
        Error::numeric(format!("the eigenvalues of the solver's map did not converge: {e:?}"))
    })
}

/// A^k by repeated squaring.
pub(crate) fn power(a: &Mat<f64>, mut k: u64) -> Mat<f64> {
    let n = a.nrows();
    let mut result = Mat::<f64>::identity(n, n);
    let mut base = a.clone();
    let mut first = true;
    while k > 0 {
        if k & 1 == 1 {
            result = if first { base.clone() } else { &result * &base };
            first = false;
        }
        k >>= 1;
        if k > 0 {
            base = &base * &base;
        }
    }
    result
}

/// The ∞-norm (largest absolute row sum).
pub(crate) fn norm_inf(a: &Mat<f64>) -> f64 {
    // Column by column: faer stores columns contiguously.
    let mut rows = vec![0.0f64; a.nrows()];
    for j in 0..a.ncols() {
        for (r, x) in rows.iter_mut().zip(a.col(j).iter()) {
            *r += x.abs();
        }
    }
    rows.into_iter().fold(0.0, f64::max)
}

/// y = A x (faer's matrix-vector product).
pub(crate) fn mat_vec(a: &Mat<f64>, x: &[f64]) -> Vec<f64> {
    let x = faer::Col::<f64>::from_fn(x.len(), |j| x[j]);
    let y = a * &x;
    y.iter().copied().collect()
}

/// The minimum-cost assignment of every row to a distinct column (rows ≤
/// columns), by the Hungarian algorithm with potentials: `out[i]` is row
/// i's column. Costs must be finite.
pub(crate) fn assignment(cost: &[Vec<f64>]) -> Vec<usize> {
    let n = cost.len();
    if n == 0 {
        return Vec::new();
    }
    let m = cost[0].len();
    assert!(n <= m, "more rows than columns");
    // 1-based potentials u (rows), v (columns); p[j] = row matched to column j.
    let mut u = vec![0.0; n + 1];
    let mut v = vec![0.0; m + 1];
    let mut p = vec![0usize; m + 1];
    let mut way = vec![0usize; m + 1];
    for i in 1..=n {
        p[0] = i;
        let mut j0 = 0;
        let mut minv = vec![f64::INFINITY; m + 1];
        let mut used = vec![false; m + 1];
        loop {
            used[j0] = true;
            let i0 = p[j0];
            let mut delta = f64::INFINITY;
            let mut j1 = 0;
            for j in 1..=m {
                if !used[j] {
                    let cur = cost[i0 - 1][j - 1] - u[i0] - v[j];
                    if cur < minv[j] {
                        minv[j] = cur;
                        way[j] = j0;
                    }
                    if minv[j] < delta {
                        delta = minv[j];
                        j1 = j;
                    }
                }
            }
            for j in 0..=m {
                if used[j] {
                    u[p[j]] += delta;
                    v[j] -= delta;
                } else {
                    minv[j] -= delta;
                }
            }
            j0 = j1;
            if p[j0] == 0 {
                break;
            }
        }
        loop {
            let j1 = way[j0];
            p[j0] = p[j1];
            j0 = j1;
            if j0 == 0 {
                break;
            }
        }
    }
    let mut out = vec![0; n];
    for j in 1..=m {
        if p[j] > 0 {
            out[p[j] - 1] = j - 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The assignment is the exhaustive optimum on small random matrices.
    #[test]
    fn assignment_is_optimal() {
        let mut seed = 7u64;
        let mut rnd = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for (n, m) in [(1, 1), (2, 3), (3, 3), (4, 6), (5, 5)] {
            let c: Vec<Vec<f64>> = (0..n).map(|_| (0..m).map(|_| rnd()).collect()).collect();
            let a = assignment(&c);
            let total: f64 = a.iter().enumerate().map(|(i, &j)| c[i][j]).sum();
            let mut cols: Vec<usize> = a.clone();
            cols.sort_unstable();
            cols.dedup();
            assert_eq!(cols.len(), n);
            // Exhaustive: every injective map rows → columns.
            fn best(c: &[Vec<f64>], i: usize, used: &mut Vec<bool>) -> f64 {
                if i == c.len() {
                    return 0.0;
                }
                let mut b = f64::INFINITY;
                for j in 0..used.len() {
                    if !used[j] {
                        used[j] = true;
                        b = b.min(c[i][j] + best(c, i + 1, used));
                        used[j] = false;
                    }
                }
                b
            }
            let opt = best(&c, 0, &mut vec![false; m]);
            assert!((total - opt).abs() < 1e-12, "{n}x{m}: {total} vs {opt}");
        }
    }

    /// The complement is orthonormal and orthogonal to the basis.
    #[test]
    fn complement_is_orthonormal() {
        let basis = vec![vec![1.0, 1.0, 1.0, 1.0], vec![0.0, 1.0, 2.0, 3.0]];
        let q = complement(&basis, 4);
        assert_eq!(q.ncols(), 2);
        for a in 0..2 {
            for b in 0..2 {
                let d: f64 = (0..4).map(|i| q[(i, a)] * q[(i, b)]).sum();
                assert!((d - if a == b { 1.0 } else { 0.0 }).abs() < 1e-14);
            }
            for v in &basis {
                let d: f64 = (0..4).map(|i| q[(i, a)] * v[i]).sum();
                assert!(d.abs() < 1e-14);
            }
        }
    }
}
