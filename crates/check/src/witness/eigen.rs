//! Witnesses 1 and 2: the eigenvalues of the numeric P (nalgebra, faer),
//! paired with the reference roots; eigenvalue condition numbers.

use nalgebra::DMatrix;
use num_traits::Zero;

use crate::error::Error;

/// A complex `f64`.
pub type C64 = num_complex::Complex<f64>;

/// Witness 1: eigenvalues of P by nalgebra's real Schur decomposition,
/// stopped after 100·N iterations.
pub fn eigenvalues_nalgebra(p: &DMatrix<f64>) -> Result<Vec<C64>, Error> {
    let n = p.nrows();
    let schur = nalgebra::linalg::Schur::try_new(p.clone(), f64::EPSILON, 100 * n.max(1))
        .ok_or(Error::no_convergence("nalgebra"))?;
    Ok(schur.complex_eigenvalues().iter().copied().collect())
}

/// Witness 2: eigenvalues of P by faer.
pub fn eigenvalues_faer(p: &DMatrix<f64>) -> Result<Vec<C64>, Error> {
    let m = faer::Mat::<f64>::from_fn(p.nrows(), p.ncols(), |i, j| p[(i, j)]);
    m.eigenvalues().map_err(|_| NoConvergenceFaer.into())
}

struct NoConvergenceFaer;

impl From<NoConvergenceFaer> for Error {
    fn from(_: NoConvergenceFaer) -> Self {
        Error::no_convergence("faer")
    }
}

/// Reorders `candidates` to pair with `reference`, minimising the total
/// distance (exhaustively up to 7 roots, greedily beyond).
#[track_caller]
pub fn pair_up(reference: &[C64], candidates: &[C64]) -> Vec<C64> {
    assert_eq!(reference.len(), candidates.len(), "as many candidates as references");
    let n = reference.len();
    if n <= 7 {
        let mut perm: Vec<usize> = (0..n).collect();
        let mut best = perm.clone();
        let mut best_cost = f64::INFINITY;
        permute(&mut perm, 0, &mut |p| {
            let cost: f64 =
                p.iter().enumerate().map(|(i, &j)| (reference[i] - candidates[j]).norm()).sum();
            if cost < best_cost {
                best_cost = cost;
                best = p.to_vec();
            }
        });
        best.iter().map(|&j| candidates[j]).collect()
    } else {
        let mut out = vec![C64::zero(); n];
        let mut used_r = vec![false; n];
        let mut used_c = vec![false; n];
        for _ in 0..n {
            let mut best = (f64::INFINITY, 0, 0);
            for i in (0..n).filter(|&i| !used_r[i]) {
                for j in (0..n).filter(|&j| !used_c[j]) {
                    let d = (reference[i] - candidates[j]).norm();
                    if d < best.0 {
                        best = (d, i, j);
                    }
                }
            }
            used_r[best.1] = true;
            used_c[best.2] = true;
            out[best.1] = candidates[best.2];
        }
        out
    }
}

fn permute(p: &mut Vec<usize>, k: usize, visit: &mut dyn FnMut(&[usize])) {
    if k == p.len() {
        visit(p);
        return;
    }
    for i in k..p.len() {
        p.swap(k, i);
        permute(p, k + 1, visit);
        p.swap(k, i);
    }
}

/// The eigenvalue condition number of `z` for P, with the unit left
/// eigenvector w (w^H P ≈ z·w^H).
///
/// Both eigenvectors are right singular vectors of the smallest singular
/// value: of P − zI (right) and of its adjoint (left). nalgebra's complex
/// SVD returns an accurate V but a U that reconstructs the matrix only to
/// about 1e-4 relative (nalgebra 0.33, a 2×2 with singular values 2e-4 and
/// 6e-17), so U is never used.
pub fn eigen_condition(p: &DMatrix<f64>, z: C64) -> (f64, Vec<C64>) {
    let n = p.nrows();
    let m = DMatrix::<C64>::from_fn(n, n, |i, j| {
        C64::new(p[(i, j)], 0.0) - if i == j { z } else { C64::zero() }
    });
    let null_vector = |a: DMatrix<C64>| -> Vec<C64> {
        let svd = a.svd(false, true);
        let k = svd.singular_values.iamin();
        svd.v_t.as_ref().expect("v computed").row(k).iter().map(|x| x.conj()).collect()
    };
    let left = null_vector(m.adjoint());
    let right = null_vector(m);
    let dot: C64 = left.iter().zip(&right).map(|(a, b)| a.conj() * b).sum();
    let kappa = (1.0 / dot.norm()).min(1e300);
    (kappa, left)
}

/// The roots of a polynomial with complex coefficients (lowest power
/// first; [`polynomial_roots`](crate::witness::polynomial_roots) takes real
/// ones, highest first), as the eigenvalues of its companion matrix by
/// nalgebra's complex Schur decomposition; leading zeros are dropped first.
pub fn complex_polynomial_roots(coeffs: &[C64]) -> Result<Vec<C64>, Error> {
    let mut c = coeffs.to_vec();
    while c.last().is_some_and(|x| x.is_zero()) {
        c.pop();
    }
    let n = c.len().saturating_sub(1);
    if n == 0 {
        return Ok(Vec::new());
    }
    let lead = c[n];
    let mut m = DMatrix::<C64>::zeros(n, n);
    for i in 1..n {
        m[(i, i - 1)] = C64::new(1.0, 0.0);
    }
    for i in 0..n {
        m[(i, n - 1)] = -c[i] / lead;
    }
    let schur = nalgebra::linalg::Schur::try_new(m, f64::EPSILON, 100 * n.max(1))
        .ok_or(Error::no_convergence("nalgebra (complex)"))?;
    Ok(schur.eigenvalues().map(|v| v.iter().copied().collect()).unwrap_or_default())
}
