//! The spectrum of a scene too large for a dense eigendecomposition: only
//! what the advice needs, from the sparse K̃ = M^{-1/2} K M^{-1/2}.
//!
//! - **The highest eigenvalue**, which decides stability. Lanczos's
//!   three-term recurrence (no reorthogonalisation, so O(n) memory) gives
//!   Ritz values that never exceed λ_max and whose largest converges to it
//!   whatever the loss of orthogonality. It is then *certified*: a Cholesky
//!   factorisation of sI − K̃ exists only when every eigenvalue is below s
//!   (Sylvester's law of inertia), so s = θ(1 + 2·10⁻⁷) just above the
//!   Ritz value θ is an upper bound once faer factors it. Gershgorin's
//!   bound is the fallback, and is taken whenever it is the smaller.
//! - **The lowest modes, or every mode at or below `max_hz`**, with their
//!   shapes: Lanczos with full reorthogonalisation on (K̃ + σI)⁻¹, applied
//!   by faer's sparse Cholesky (shift and invert). Each returned pair is
//!   checked by its residual in K̃ itself.
//!
//! The modes between those computed are not resolved: every one lies in
//! the interval between the highest computed mode and the certified bound,
//! and the advisor checks stability (and, outside a `max_hz` band, the
//! targets) on samples spanning it (`Mode::sampled`).

use faer::linalg::solvers::SolveCore;
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::{Conj, Mat, Side};

use super::sparse::{Assembly, Sparse};
use crate::error::Error;

/// Relative margin above the Ritz value at which the highest eigenvalue is
/// certified: ω is then overstated by at most 10⁻⁷ of itself.
const CERTIFY_MARGIN: f64 = 2e-7;

/// Most Lanczos steps for the highest eigenvalue.
const MAX_LANCZOS_STEPS: usize = 4000;

/// Most modes computed by shift and invert.
pub(crate) const MAX_COMPUTED_MODES: usize = 512;

/// How the bound on the highest eigenvalue was certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub(crate) enum Certificate {
    /// Cholesky of sI − K̃ (Sylvester's law of inertia).
    Cholesky,
    /// Gershgorin's row sums of K̃.
    Gershgorin,
}

/// The highest eigenvalue of K̃.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Highest {
    /// The largest Ritz value: never above λ_max.
    pub ritz: f64,
    /// A certified upper bound.
    pub upper: f64,
    /// How `upper` is certified.
    pub certificate: Certificate,
    /// Lanczos steps taken.
    pub steps: usize,
}

/// A small deterministic generator for start vectors (xorshift64*), so a
/// start vector is never orthogonal to a mode by symmetry.
fn start_vector(n: usize, seed: u64) -> Vec<f64> {
    let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    let mut v: Vec<f64> = (0..n)
        .map(|_| {
            x ^= x >> 12;
            x ^= x << 25;
            x ^= x >> 27;
            let r = x.wrapping_mul(0x2545_F491_4F6C_DD1D);
            (r >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        })
        .collect();
    let norm = v.iter().map(|a| a * a).sum::<f64>().sqrt();
    v.iter_mut().for_each(|a| *a /= norm);
    v
}

/// The number of eigenvalues below `x` of the symmetric tridiagonal matrix
/// with diagonal `a` and off-diagonal `b` (Sturm: the negative pivots of
/// T − xI).
fn count_below(a: &[f64], b: &[f64], x: f64) -> usize {
    let mut count = 0;
    let mut d = 1.0;
    for i in 0..a.len() {
        let off = if i == 0 { 0.0 } else { b[i - 1] * b[i - 1] / d };
        d = a[i] - x - off;
        if d == 0.0 {
            d = -f64::EPSILON * (a[i].abs() + x.abs()).max(f64::MIN_POSITIVE);
        }
        if d < 0.0 {
            count += 1;
        }
    }
    count
}

/// The largest eigenvalue of that tridiagonal matrix, by bisection.
fn tridiagonal_max(a: &[f64], b: &[f64]) -> f64 {
    let k = a.len();
    let radius = |i: usize| {
        (if i > 0 { b[i - 1].abs() } else { 0.0 }) + (if i + 1 < k { b[i].abs() } else { 0.0 })
    };
    let mut hi = (0..k).map(|i| a[i] + radius(i)).fold(f64::MIN, f64::max);
    let mut lo = (0..k).map(|i| a[i] - radius(i)).fold(f64::MAX, f64::min);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if count_below(a, b, mid) == k {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    lo
}

/// Lanczos on `a` from a fixed random start: the largest Ritz value and
/// the steps taken. Stops when it has moved by at most `tol` of itself
/// over the last 20 steps, at an invariant subspace, or after
/// [`MAX_LANCZOS_STEPS`].
fn lanczos_max(a: &Sparse, tol: f64) -> (f64, usize) {
    let n = a.n();
    let mut v = start_vector(n, 1);
    let mut prev = vec![0.0; n];
    let mut w = vec![0.0; n];
    let (mut alpha, mut beta): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
    let mut theta = f64::MIN;
    let mut checked = f64::MIN;
    let scale = a.max_abs().max(f64::MIN_POSITIVE);
    for k in 0..MAX_LANCZOS_STEPS.min(n) {
        a.mul_vec(&v, &mut w);
        let al: f64 = w.iter().zip(&v).map(|(x, y)| x * y).sum();
        let b_prev = beta.last().copied().unwrap_or(0.0);
        let mut b2 = 0.0;
        for i in 0..n {
            w[i] -= al * v[i] + b_prev * prev[i];
            b2 += w[i] * w[i];
        }
        alpha.push(al);
        let b = b2.sqrt();
        let done = b <= 1e-13 * scale || k + 1 == MAX_LANCZOS_STEPS.min(n);
        if (k + 1) % 20 == 0 || done {
            theta = tridiagonal_max(&alpha, &beta);
            if done || (k >= 40 && theta - checked <= tol * theta.abs()) {
                return (theta, k + 1);
            }
            checked = theta;
        }
        beta.push(b);
        let inv = 1.0 / b;
        for i in 0..n {
            prev[i] = v[i];
            v[i] = w[i] * inv;
        }
    }
    (theta.max(0.0), alpha.len())
}

/// sI − A (`negate`) or A + sI, with every diagonal entry stored.
fn shifted(a: &Sparse, s: f64, negate: bool) -> Sparse {
    let n = a.n();
    let mut m = Assembly::new(n);
    for i in 0..n {
        m.add(i, i, s);
        for (j, x) in a.row(i) {
            m.add(i, j, if negate { -x } else { x });
        }
    }
    m.finish()
}

/// The Cholesky factor of a symmetric sparse matrix, `None` when it is not
/// positive definite; an error when the factor does not fit in memory.
fn cholesky(a: &Sparse) -> Result<Option<Llt<usize, f64>>, Error> {
    let csc = a.as_faer().transpose();
    let too_big = |what: &str| {
        Error::numeric(format!(
            "the sparse Cholesky factor of a {n}×{n} scene matrix does not fit in memory ({what}): \
             the scene is too large for this machine",
            n = a.n()
        ))
    };
    let symbolic = SymbolicLlt::try_new(csc.symbolic(), Side::Lower)
        .map_err(|e| too_big(&format!("{e:?}")))?;
    match Llt::try_new_with_symbolic(symbolic, csc, Side::Lower) {
        Ok(llt) => Ok(Some(llt)),
        Err(faer::sparse::linalg::LltError::Numeric(_)) => Ok(None),
        Err(e) => Err(too_big(&format!("{e:?}"))),
    }
}

/// The highest eigenvalue of the symmetric positive semi-definite `kt`,
/// with a certified upper bound; `gershgorin` is Gershgorin's bound.
pub(crate) fn highest(kt: &Sparse, gershgorin: f64) -> Result<Highest, Error> {
    // A Ritz value that has stopped moving by 10⁻⁹ is almost always within
    // the margin of λ_max; when the certificate then fails, Lanczos runs
    // again to 10⁻¹², and Gershgorin is the last resort.
    let mut steps = 0;
    let mut ritz = 0.0;
    for tol in [1e-9, 1e-12] {
        let (theta, k) = lanczos_max(kt, tol);
        steps += k;
        ritz = theta.max(ritz);
        let s = ritz * (1.0 + CERTIFY_MARGIN);
        if gershgorin <= s || ritz <= 0.0 {
            break;
        }
        // The factorisation succeeds only when sI − K̃ is positive
        // definite; a factor computed in f64 is that of sI − K̃ + E with |E|
        // of order ε·s times the row length, far inside the margin.
        if cholesky(&shifted(kt, s, true))?.is_some() {
            return Ok(Highest { ritz, upper: s, certificate: Certificate::Cholesky, steps });
        }
    }
    Ok(Highest { ritz, upper: gershgorin, certificate: Certificate::Gershgorin, steps })
}

/// Eigenpairs (λ, u) of K̃ from the bottom of the spectrum.
#[derive(Clone, Debug, Default)]
pub(crate) struct Lowest {
    /// Eigenvalues, increasing.
    pub values: Vec<f64>,
    /// Unit eigenvectors of K̃, one per value.
    pub vectors: Vec<Vec<f64>>,
    /// Whether every eigenvalue up to the requested one was found (a
    /// converged one lies past it), rather than the step limit stopping
    /// the search.
    pub complete: bool,
}

/// The eigenpairs of K̃ at the bottom of its spectrum: every one with
/// λ ≤ `up_to` (at most [`MAX_COMPUTED_MODES`]), or, with `up_to = None`,
/// the `count` lowest beyond the `zero_tol` zero modes. `top` is an upper
/// bound on λ_max (for the tolerances).
///
/// Lanczos with full reorthogonalisation on (K̃ + σI)⁻¹, applied by faer's
/// sparse Cholesky factor: the largest eigenvalues μ = 1/(λ + σ) of the
/// inverse are K̃'s lowest, and converge first. Ritz pairs are accepted
/// when their residual in the inverse is below 10⁻¹⁰ of the largest μ, and
/// then checked by their residual in K̃ itself (10⁻⁸ of `top`). Exactly
/// repeated eigenvalues are found once (a Krylov space holds one vector of
/// each eigenspace); the advice depends on the frequencies only.
pub(crate) fn lowest(
    kt: &Sparse,
    up_to: Option<f64>,
    count: usize,
    zero_tol: f64,
    top: f64,
) -> Result<Lowest, Error> {
    let n = kt.n();
    let sigma = match up_to {
        Some(t) => t.max(1e-9 * top),
        None => 1e-6 * top,
    }
    .max(f64::MIN_POSITIVE);
    let Some(llt) = cholesky(&shifted(kt, sigma, false))? else {
        return Err(Error::numeric(
            "K + sigma M is not positive definite: a spring with negative stiffness?".to_owned(),
        ));
    };
    let max_steps = n.min(2 * MAX_COMPUTED_MODES + 64);
    // The basis, column-major in one buffer grown by doubling, so the
    // reorthogonalisation is two matrix–vector products (faer, vectorised).
    let mut buf: Vec<f64> = Vec::new();
    let grow = |buf: &mut Vec<f64>, cols: usize| -> Result<(), Error> {
        let want = n * cols;
        if buf.capacity() < want {
            let cap = (2 * buf.capacity()).max(want).min(n * (max_steps + 1));
            buf.try_reserve_exact(cap - buf.len()).map_err(|_| too_large(n, cols))?;
        }
        Ok(())
    };
    grow(&mut buf, 32.min(max_steps + 1))?;
    buf.extend(start_vector(n, 7));
    let (mut alpha, mut beta): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
    let mut next_check = 24.min(max_steps);
    loop {
        let k = alpha.len();
        let vk = faer::ColRef::from_slice(&buf[k * n..(k + 1) * n]);
        let mut w = Mat::<f64>::from_fn(n, 1, |i, _| vk[i]);
        llt.solve_in_place_with_conj(Conj::No, w.as_mut());
        let mut w: faer::Col<f64> = w.col(0).to_owned();
        let a_k: f64 = vk.transpose() * &w;
        alpha.push(a_k);
        // The three-term recurrence first, then the full reorthogonalisation
        // removes only what rounding left.
        w -= faer::Scale(a_k) * vk;
        if k > 0 {
            let prev = faer::ColRef::from_slice(&buf[(k - 1) * n..k * n]);
            w -= faer::Scale(beta[k - 1]) * prev;
        }
        // Full reorthogonalisation, twice (Kahan: twice is enough).
        let basis = faer::MatRef::from_column_major_slice(&buf[..(k + 1) * n], n, k + 1);
        // Classical Gram–Schmidt, repeated only when it cancelled most of
        // the vector (Daniel, Gragg, Kaufman and Stewart's criterion).
        let mut b = w.norm_l2();
        for _ in 0..2 {
            let c: faer::Col<f64> = basis.transpose() * &w;
            w -= basis * &c;
            let after = w.norm_l2();
            let enough = after > std::f64::consts::FRAC_1_SQRT_2 * b;
            b = after;
            if enough {
                break;
            }
        }
        let steps = k + 1;
        let invariant = b <= 1e-14 / sigma;
        if steps == next_check || invariant || steps == max_steps {
            next_check = (steps + steps / 4).max(steps + 12).min(max_steps);
            let (mu, y) = tridiagonal_eigen(&alpha, &beta)?;
            let mu_max = mu.iter().copied().fold(0.0, f64::max);
            let converged = |i: usize| invariant || b * y[(steps - 1, i)].abs() <= 1e-10 * mu_max;
            // Largest μ first: λ increasing.
            let order: Vec<usize> = {
                let mut o: Vec<usize> = (0..steps).collect();
                o.sort_by(|&p, &q| mu[q].total_cmp(&mu[p]));
                o
            };
            let lambda = |i: usize| 1.0 / mu[i] - sigma;
            // Done when every Ritz value inside the wanted range converged
            // and a converged one lies past it.
            let mut found = 0;
            let mut past = false;
            let mut all_in_range_converged = true;
            for &i in &order {
                let inside = match up_to {
                    Some(t) => lambda(i) <= t,
                    None => found < count,
                };
                if inside {
                    if converged(i) {
                        if lambda(i) > zero_tol || up_to.is_some() {
                            found += 1;
                        }
                    } else {
                        all_in_range_converged = false;
                        break;
                    }
                } else {
                    past = converged(i);
                    break;
                }
            }
            let done = all_in_range_converged && (past || invariant);
            if done || steps == max_steps || invariant {
                let mut out = Lowest { complete: done, ..Lowest::default() };
                let mut ku = vec![0.0; n];
                let basis = faer::MatRef::from_column_major_slice(&buf[..steps * n], n, steps);
                for &i in &order {
                    let l = lambda(i);
                    if up_to.is_some_and(|t| l > t) || !converged(i) {
                        break;
                    }
                    if up_to.is_none()
                        && out.values.iter().filter(|&&x| x > zero_tol).count() >= count
                    {
                        break;
                    }
                    let ucol: faer::Col<f64> = basis * y.col(i);
                    let norm = ucol.norm_l2();
                    let u: Vec<f64> = (0..n).map(|r| ucol[r] / norm).collect();
                    kt.mul_vec(&u, &mut ku);
                    let r = ku.iter().zip(&u).map(|(a, b)| (a - l * b).powi(2)).sum::<f64>().sqrt();
                    if r > 1e-8 * top {
                        return Err(Error::numeric(format!(
                            "the sparse eigensolver's mode at {l:.6e} has residual {r:.3e}: not trusted"
                        )));
                    }
                    out.values.push(l.max(0.0));
                    out.vectors.push(u);
                }
                return Ok(out);
            }
        }
        beta.push(b);
        grow(&mut buf, steps + 1)?;
        buf.extend(w.iter().map(|x| x / b));
    }
}

/// An error for a Krylov basis that does not fit in memory.
fn too_large(n: usize, steps: usize) -> Error {
    Error::numeric(format!(
        "the sparse eigensolver's basis of {steps} vectors of {n} degrees of freedom does not fit \
         in memory: the scene is too large for this machine"
    ))
}

/// Every eigenpair of the symmetric tridiagonal matrix (diagonal `a`,
/// off-diagonal `b`), by faer's dense solver: values, and vectors as
/// columns.
fn tridiagonal_eigen(a: &[f64], b: &[f64]) -> Result<(Vec<f64>, Mat<f64>), Error> {
    let k = a.len();
    let t = Mat::<f64>::from_fn(k, k, |i, j| tridiagonal_entry(a, b, i, j));
    let e = t.self_adjoint_eigen(Side::Lower).map_err(|e| {
        Error::numeric(format!("the Lanczos tridiagonal eigenproblem did not converge: {e:?}"))
    })?;
    Ok(((0..k).map(|i| e.S()[i]).collect(), e.U().to_owned()))
}

/// Entry (i, j) of the symmetric tridiagonal matrix with diagonal `a` and
/// off-diagonal `b`.
fn tridiagonal_entry(a: &[f64], b: &[f64], i: usize, j: usize) -> f64 {
    if i == j {
        a[i]
    } else if i + 1 == j {
        b[i]
    } else if j + 1 == i {
        b[j]
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The path graph's Laplacian plus the identity: eigenvalues
    /// 1 + 2 − 2cos(kπ/(n+1)), k = 1..n.
    fn path(n: usize) -> (Sparse, Vec<f64>) {
        let mut a = Assembly::new(n);
        for i in 0..n {
            a.add(i, i, 3.0);
            if i + 1 < n {
                a.add(i, i + 1, -1.0);
                a.add(i + 1, i, -1.0);
            }
        }
        let exact = (1..=n)
            .map(|k| 3.0 - 2.0 * (k as f64 * std::f64::consts::PI / (n as f64 + 1.0)).cos())
            .collect();
        (a.finish(), exact)
    }

    #[test]
    fn sturm_count_and_bisection_agree_with_a_dense_solver() {
        let a = [2.0, -1.0, 0.5, 4.0, 3.0];
        let b = [1.0, 0.3, -2.0, 0.7];
        let t = nalgebra::DMatrix::from_fn(5, 5, |i, j| tridiagonal_entry(&a, &b, i, j));
        let mut e: Vec<f64> = t.symmetric_eigenvalues().iter().copied().collect();
        e.sort_by(f64::total_cmp);
        for (k, &x) in e.iter().enumerate() {
            assert_eq!(count_below(&a, &b, x - 1e-9), k);
            assert_eq!(count_below(&a, &b, x + 1e-9), k + 1);
        }
        assert!((tridiagonal_max(&a, &b) - e[4]).abs() < 1e-12);
    }

    /// The certified bound is above the exact λ_max and within the margin.
    #[test]
    fn highest_is_certified_and_tight() {
        for n in [5, 100, 3000] {
            let (a, exact) = path(n);
            let top = exact[n - 1];
            let h = highest(&a, a.gershgorin_upper()).unwrap();
            assert!(h.ritz <= top * (1.0 + 1e-14), "{n}: ritz {} > {top}", h.ritz);
            assert!(h.upper >= top, "{n}: bound {} < {top}", h.upper);
            if h.certificate == Certificate::Cholesky {
                assert!(h.upper <= top * (1.0 + 1e-6), "{n}: {} vs {top}", h.upper);
            }
        }
    }

    #[test]
    fn lowest_finds_the_bottom_of_the_spectrum() {
        let (a, exact) = path(400);
        let top = exact[399];
        let low = lowest(&a, None, 5, 0.0, top).unwrap();
        assert!(low.values.len() >= 5);
        for (got, want) in low.values.iter().zip(&exact) {
            assert!((got - want).abs() <= 1e-9 * want, "{got} vs {want}");
        }
        let band = 0.5 * (exact[37] + exact[38]);
        let low = lowest(&a, Some(band), 0, 0.0, top).unwrap();
        assert!(low.complete);
        assert_eq!(low.values.len(), 38);
        for (got, want) in low.values.iter().zip(&exact) {
            assert!((got - want).abs() <= 1e-9 * want, "{got} vs {want}");
        }
    }
}
