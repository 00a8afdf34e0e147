//! Four numeric witnesses for a method's exact characteristic polynomial,
//! and the tolerance model that decides whether they agree.
//!
//! At one point (Φ and any other parameters) a method is witnessed by:
//!
//! 1. **nalgebra**: the eigenvalues of the numeric transition matrix P
//!    ([`Step::transition_matrix`]), by a real Schur decomposition with an
//!    iteration bound ([`eigenvalues_nalgebra`]);
//! 2. **faer**: the eigenvalues of the same P by faer's real
//!    eigendecomposition ([`eigenvalues_faer`]);
//! 3. **exact roots**: the roots of the exact χ(z) from `poly`, with every
//!    coefficient evaluated exactly at the rational value of the `f64`
//!    parameters and rounded once ([`ExactCharpoly`]). For degree 2 the
//!    roots come from a closed form that never cancels: the shifted
//!    polynomials q − p², q − 1, χ(±1) are formed exactly, so
//!    z = p ± j√(q − p²) and ln|z| = ½·ln1p(q − 1) keep full relative
//!    accuracy even at Φ = 1e-8, where |z| − 1 ≈ 5e-17 lies far below
//!    machine epsilon. Beyond degree 2 the roots are the eigenvalues of the
//!    companion matrix. These roots are the **reference** the others are
//!    paired with, and their class is the point's class.
//! 4. **simulation**: the compiled recursion itself run for many steps
//!    ([`simulate`]), measured in the dominant mode: c_k = w^H x_k with w the
//!    left eigenvector of the dominant root λ (the smallest singular vector
//!    of P − λI). Exactly, c_{k+1} = λ·c_k for any P, normal or not, and even
//!    for a Jordan block (w is then orthogonal to the eigenvector, and c still
//!    scales by λ), so the growth per step ln|c_n/c_0|/n and the phase
//!    increment per step (mean |arg(c_{k+1}/c_k)|) carry no transient. The
//!    state is rescaled by exact powers of two, so unstable runs never
//!    overflow. The raw norm growth ln(‖x_n‖/‖x_0‖)/n is measured too: it is
//!    what a user sees, and it fails if a larger mode were hiding.
//!
//! # Tolerance model
//!
//! With ε = `f64::EPSILON`, N the order, s = max(1, ‖P‖_F):
//!
//! * an isolated root z_i has the agreement radius `tol_i = 16·N·ε·s·κ_i`,
//!   where κ_i = 1/|w^H v| is the eigenvalue condition number of P (unit
//!   left and right null vectors of P − z_i I). Beyond degree 2 the
//!   reference roots come from the companion matrix, so the radius also
//!   covers their sensitivity to the rounded coefficients,
//!   κ_poly_i = Σ|c_k||z_i|^k / |χ'(z_i)|: `16·N·ε·max(s·κ_i, κ_poly_i)`.
//!   The degree-2 closed form on exactly shifted coefficients has no such
//!   error: it is accurate to a few ulps of |z|;
//! * roots of a cluster of m roots closer than `2·8·N·√ε·s` (a double root,
//!   or nearly one) move like the m-th root of a perturbation, so their
//!   radius is `min(isolated, 8·N·ε^(1/m)·s)`: the √ε scale for a double
//!   root, where a Jordan block makes κ_i meaningless;
//! * a numeric eigenvalue agrees when its distance to the paired reference
//!   root is within tol_i (pairing minimises the total distance);
//! * the simulation agrees when |e^g − ρ| and ρ·|Ψ_sim − Ψ| are within
//!   tol_d of the dominant root (plus n·16·N·ε·s inside a cluster, where the
//!   rounding of a defective mode accumulates), and its norm growth is
//!   within `(ln(1 + κ_max) + m·ln(n + 1) + 4)/n` of ln ρ (the transient of a
//!   non-normal P and the polynomial growth k^(m−1) of a Jordan block).
//!
//! The constants are multiples of ε; the tests check that they are neither
//! loose (a perturbed reference fails) nor tight (every built-in at every
//! class boundary passes).

use std::collections::HashMap;
use std::f64::consts::LN_2;

use nalgebra::DMatrix;
use num_complex::Complex;
use num_traits::{Signed, Zero};
use poly::{Method, Poly, RootClass, Sym, Q};

use crate::classify::{classify_pq, classify_roots, psi_of, PqSigns};
use crate::numeric::{f64_to_q, q_to_f64, NumericError, Params, Step};

/// A complex `f64`.
pub type C64 = Complex<f64>;

/// The simulation length when none is given.
pub const DEFAULT_STEPS: u64 = 1_000_000;

/// Multiplier of N·ε for an isolated root.
pub const C_ISOLATED: f64 = 16.0;
/// Multiplier of N·ε^(1/m) for a cluster of m roots.
pub const C_CLUSTER: f64 = 8.0;

/// The shifted polynomials of a second-order χ = z² − 2p·z + q, exact in
/// the parameters (see [`crate::classify`]).
#[derive(Clone, Debug)]
pub struct PqPolys {
    /// p.
    pub p: Poly,
    /// q.
    pub q: Poly,
    /// p² − q.
    pub disc: Poly,
    /// p − 1.
    pub p_minus_1: Poly,
    /// p + 1.
    pub p_plus_1: Poly,
    /// q − 1.
    pub q_minus_1: Poly,
    /// q + 1.
    pub q_plus_1: Poly,
    /// χ(1) = 1 − 2p + q.
    pub chi_1: Poly,
    /// χ(−1) = 1 + 2p + q.
    pub chi_minus_1: Poly,
}

impl PqPolys {
    /// The shifted polynomials of z² − 2p·z + q.
    pub fn new(p: Poly, q: Poly) -> PqPolys {
        let one = Poly::one();
        let two_p = &p + &p;
        PqPolys {
            disc: &(&p * &p) - &q,
            p_minus_1: &p - &one,
            p_plus_1: &p + &one,
            q_minus_1: &q - &one,
            q_plus_1: &q + &one,
            chi_1: &(&one - &two_p) + &q,
            chi_minus_1: &(&one + &two_p) + &q,
            p,
            q,
        }
    }

    /// The polynomials in [`PqSigns`] order after `p` and `q`: disc, p, p − 1,
    /// p + 1, q − 1, q + 1, χ(1), χ(−1).
    pub fn sign_polys(&self) -> [&Poly; 8] {
        [
            &self.disc,
            &self.p,
            &self.p_minus_1,
            &self.p_plus_1,
            &self.q_minus_1,
            &self.q_plus_1,
            &self.chi_1,
            &self.chi_minus_1,
        ]
    }
}

/// Signs from eight values in [`PqPolys::sign_polys`] order.
pub fn pq_signs(v: [std::cmp::Ordering; 8]) -> PqSigns {
    PqSigns {
        disc: v[0],
        p: v[1],
        p_minus_1: v[2],
        p_plus_1: v[3],
        q_minus_1: v[4],
        q_plus_1: v[5],
        chi_1: v[6],
        chi_minus_1: v[7],
    }
}

/// The exact χ(z) of a method, ready to be evaluated at numeric parameters.
#[derive(Clone, Debug)]
pub struct ExactCharpoly {
    method: String,
    params: Vec<Sym>,
    charpoly: Poly,
    coeffs: Vec<Poly>,
    pq: Option<PqPolys>,
}

/// What the exact χ says at one point.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactForm {
    /// χ's coefficients, highest power first, each exact-then-rounded.
    pub coeffs: Vec<f64>,
    /// The roots, largest modulus first (Im ≥ 0 first among a pair).
    pub roots: Vec<C64>,
    /// ρ = max |z|.
    pub spectral_radius: f64,
    /// ln ρ, without cancellation for degree 2 (see the module docs).
    pub growth_per_step: f64,
    /// Ψ of the dominant root, in [0, π].
    pub psi: f64,
    /// The section-4 class (exact for degree 2, tolerance-based beyond).
    pub class: RootClass,
}

impl ExactCharpoly {
    /// Derives `method` (both exact routes) and prepares χ.
    pub fn new(method: &Method) -> Result<ExactCharpoly, NumericError> {
        let d = poly::derive(method)?;
        Ok(ExactCharpoly::from_derivation(&d))
    }

    /// Prepares χ from a derivation.
    pub fn from_derivation(d: &poly::Derivation) -> ExactCharpoly {
        ExactCharpoly {
            method: d.method.name().to_owned(),
            params: d.method.params().to_vec(),
            charpoly: d.charpoly.clone(),
            coeffs: d.coeffs(),
            pq: d.p_q().map(|(p, q)| PqPolys::new(p, q)),
        }
    }

    /// χ as a polynomial in z and the parameters.
    pub fn charpoly(&self) -> &Poly {
        &self.charpoly
    }

    /// The degree N.
    pub fn degree(&self) -> usize {
        self.coeffs.len() - 1
    }

    /// The shifted polynomials, for a second-order method.
    pub fn pq(&self) -> Option<&PqPolys> {
        self.pq.as_ref()
    }

    /// The parameters as exact rationals.
    pub fn exact_params(&self, params: &Params) -> Result<HashMap<Sym, Q>, NumericError> {
        let mut map = HashMap::new();
        for &s in &self.params {
            let x = params.get(s.name()).ok_or_else(|| NumericError::MissingParam {
                method: self.method.clone(),
                param: s.name().to_owned(),
            })?;
            let xq = f64_to_q(x).ok_or_else(|| NumericError::NotFinite {
                what: format!("parameter `{}`", s.name()),
            })?;
            map.insert(s, xq);
        }
        Ok(map)
    }

    /// The coefficients at `params`, highest power first, each evaluated
    /// exactly and rounded once.
    pub fn coeffs_at(&self, params: &Params) -> Result<Vec<f64>, NumericError> {
        let map = self.exact_params(params)?;
        Ok(self.coeffs.iter().map(|c| q_to_f64(&exact_eval(c, &map))).collect())
    }

    /// Roots, growth, Ψ and class at `params`.
    pub fn at(&self, params: &Params) -> Result<ExactForm, NumericError> {
        let map = self.exact_params(params)?;
        let coeffs: Vec<f64> = self.coeffs.iter().map(|c| q_to_f64(&exact_eval(c, &map))).collect();
        match &self.pq {
            Some(pq) => Ok(second_order_form(pq, &map, coeffs)),
            None => {
                let mut roots = polynomial_roots(&coeffs)?;
                sort_roots(&mut roots);
                let tol = poly_tolerances(&coeffs, &roots);
                let class = classify_roots(&roots, &tol);
                let rho = roots.iter().map(|z| z.norm()).fold(0.0, f64::max);
                let dom = roots.first().copied().unwrap_or_default();
                Ok(ExactForm {
                    coeffs,
                    psi: psi_of(dom),
                    spectral_radius: rho,
                    growth_per_step: rho.ln(),
                    class,
                    roots,
                })
            }
        }
    }
}

fn exact_eval(p: &Poly, map: &HashMap<Sym, Q>) -> Q {
    p.eval(map).expect("every parameter has a value")
}

fn sign(x: &Q) -> std::cmp::Ordering {
    if x.is_zero() {
        std::cmp::Ordering::Equal
    } else if x.is_positive() {
        std::cmp::Ordering::Greater
    } else {
        std::cmp::Ordering::Less
    }
}

/// The class of a second-order χ exactly at the rational values `map`.
pub fn exact_pq_class(pq: &PqPolys, map: &HashMap<Sym, Q>) -> RootClass {
    let s = pq.sign_polys().map(|p| sign(&exact_eval(p, map)));
    classify_pq(&pq_signs(s))
}

fn second_order_form(pq: &PqPolys, map: &HashMap<Sym, Q>, coeffs: Vec<f64>) -> ExactForm {
    let e = |p: &Poly| q_to_f64(&exact_eval(p, map));
    let (p, q, disc) = (e(&pq.p), e(&pq.q), e(&pq.disc));
    let class = exact_pq_class(pq, map);
    let (roots, radius, growth, psi);
    if disc < 0.0 {
        // Complex pair p ± j√(q − p²); |z|² = q.
        let s = (-disc).sqrt();
        roots = vec![C64::new(p, s), C64::new(p, -s)];
        radius = q.sqrt();
        growth = 0.5 * e(&pq.q_minus_1).ln_1p();
        psi = s.atan2(p);
    } else if disc == 0.0 {
        roots = vec![C64::new(p, 0.0); 2];
        radius = p.abs();
        growth = if p > 0.0 { e(&pq.p_minus_1).ln_1p() } else { (-e(&pq.p_plus_1)).ln_1p() };
        psi = if p < 0.0 { std::f64::consts::PI } else { 0.0 };
    } else {
        let s = disc.sqrt();
        // The root with the sign of p is the larger one; the other follows
        // from the product q, never from a cancelling difference.
        let big = if p >= 0.0 { p + s } else { p - s };
        let small = if big != 0.0 { q / big } else { -s };
        roots = vec![C64::new(big, 0.0), C64::new(small, 0.0)];
        radius = big.abs();
        growth = if p == 0.0 {
            s.ln()
        } else if p > 0.0 {
            // |z| − 1 = (p − 1) + s, or −χ(1)/(1 − z_other) when that cancels.
            let (pm1, direct) = (e(&pq.p_minus_1), e(&pq.p_minus_1) + s);
            let t = if direct.abs() >= 0.5 * pm1.abs().max(s) {
                direct
            } else {
                -e(&pq.chi_1) / (1.0 - small)
            };
            t.ln_1p()
        } else {
            let (pp1, direct) = (e(&pq.p_plus_1), s - e(&pq.p_plus_1));
            let t = if direct.abs() >= 0.5 * pp1.abs().max(s) {
                direct
            } else {
                -e(&pq.chi_minus_1) / (1.0 + small)
            };
            t.ln_1p()
        };
        psi = if big < 0.0 { std::f64::consts::PI } else { 0.0 };
    }
    let mut roots = roots;
    sort_roots(&mut roots);
    ExactForm { coeffs, roots, spectral_radius: radius, growth_per_step: growth, psi, class }
}

/// Sorts roots by decreasing modulus, Im ≥ 0 first within a pair, then by
/// decreasing real part.
pub fn sort_roots(roots: &mut [C64]) {
    roots.sort_by(|a, b| {
        b.norm()
            .partial_cmp(&a.norm())
            .unwrap_or(std::cmp::Ordering::Equal)
            .then((a.im < 0.0).cmp(&(b.im < 0.0)))
            .then(b.re.partial_cmp(&a.re).unwrap_or(std::cmp::Ordering::Equal))
    });
}

/// Roots of a monic polynomial (coefficients highest first, the first 1):
/// directly for degree 1, as companion-matrix eigenvalues beyond.
pub fn polynomial_roots(coeffs: &[f64]) -> Result<Vec<C64>, NumericError> {
    let n = coeffs.len().saturating_sub(1);
    match n {
        0 => Ok(Vec::new()),
        1 => Ok(vec![C64::new(-coeffs[1] / coeffs[0], 0.0)]),
        _ => {
            let mut c = DMatrix::<f64>::zeros(n, n);
            for j in 0..n {
                c[(0, j)] = -coeffs[j + 1] / coeffs[0];
            }
            for i in 1..n {
                c[(i, i - 1)] = 1.0;
            }
            eigenvalues_nalgebra(&c)
        }
    }
}

/// Witness 1: eigenvalues of P by nalgebra's real Schur decomposition,
/// stopped after 100·N iterations.
pub fn eigenvalues_nalgebra(p: &DMatrix<f64>) -> Result<Vec<C64>, NumericError> {
    let n = p.nrows();
    let schur = nalgebra::linalg::Schur::try_new(p.clone(), f64::EPSILON, 100 * n.max(1))
        .ok_or(NumericError::NoConvergence { solver: "nalgebra" })?;
    Ok(schur.complex_eigenvalues().iter().copied().collect())
}

/// Witness 2: eigenvalues of P by faer.
pub fn eigenvalues_faer(p: &DMatrix<f64>) -> Result<Vec<C64>, NumericError> {
    let m = faer::Mat::<f64>::from_fn(p.nrows(), p.ncols(), |i, j| p[(i, j)]);
    m.eigenvalues().map_err(|_| NoConvergenceFaer.into())
}

struct NoConvergenceFaer;

impl From<NoConvergenceFaer> for NumericError {
    fn from(_: NoConvergenceFaer) -> Self {
        NumericError::NoConvergence { solver: "faer" }
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

fn scale_of(p: &DMatrix<f64>) -> f64 {
    p.norm().max(1.0)
}

fn poly_condition(coeffs: &[f64], z: C64) -> f64 {
    let n = coeffs.len() - 1;
    let mut abs_sum = 0.0;
    let mut deriv = C64::zero();
    for (k, &c) in coeffs.iter().enumerate() {
        let power = (n - k) as i32;
        abs_sum += c.abs() * z.norm().powi(power);
        if power > 0 {
            deriv += C64::new(c * power as f64, 0.0) * z.powi(power - 1);
        }
    }
    let d = deriv.norm();
    if d == 0.0 {
        f64::INFINITY
    } else {
        abs_sum / d
    }
}

/// Cluster sizes: how many roots lie within the cluster radius of each.
fn cluster_sizes(roots: &[C64], scale: f64) -> Vec<usize> {
    let n = roots.len().max(1) as f64;
    let radius = 2.0 * C_CLUSTER * n * f64::EPSILON.sqrt() * scale;
    roots.iter().map(|a| roots.iter().filter(|b| (*a - **b).norm() <= radius).count()).collect()
}

fn combine(isolated: f64, m: usize, n: usize, scale: f64) -> f64 {
    if m >= 2 {
        let cluster = C_CLUSTER * n as f64 * f64::EPSILON.powf(1.0 / m as f64) * scale;
        isolated.min(cluster)
    } else {
        isolated
    }
}

/// Agreement radii from the polynomial alone (no P): used to classify roots
/// of orders beyond 2.
pub fn poly_tolerances(coeffs: &[f64], roots: &[C64]) -> Vec<f64> {
    let n = roots.len();
    let scale = coeffs.iter().fold(1.0f64, |a, c| a.max(c.abs()));
    let sizes = cluster_sizes(roots, scale);
    roots
        .iter()
        .zip(&sizes)
        .map(|(&z, &m)| {
            let iso = C_ISOLATED * n as f64 * f64::EPSILON * poly_condition(coeffs, z).max(scale);
            combine(iso, m, n, scale)
        })
        .collect()
}

/// Agreement radii of the reference roots for P (see the module docs), with
/// each root's condition number κ and cluster size.
pub fn tolerances(
    p: &DMatrix<f64>,
    coeffs: &[f64],
    roots: &[C64],
) -> (Vec<f64>, Vec<f64>, Vec<usize>) {
    let n = roots.len();
    let scale = scale_of(p);
    let sizes = cluster_sizes(roots, scale);
    let mut tol = Vec::with_capacity(n);
    let mut kappa = Vec::with_capacity(n);
    for (&z, &m) in roots.iter().zip(&sizes) {
        let (k, _) = eigen_condition(p, z);
        // The degree-2 closed form is exact up to rounding; companion roots
        // carry the coefficients' sensitivity.
        let kappa_poly = if n == 2 { 0.0 } else { poly_condition(coeffs, z) };
        let iso = C_ISOLATED * n as f64 * f64::EPSILON * (scale * k).max(kappa_poly);
        tol.push(combine(iso, m, n, scale));
        kappa.push(k);
    }
    (tol, kappa, sizes)
}

/// What the long-run simulation measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Simulation {
    /// Steps run.
    pub steps: u64,
    /// ln|c_n/c_0|/n in the dominant mode (−∞ when the state vanished).
    pub growth_per_step: f64,
    /// Mean |arg(c_{k+1}/c_k)| in the dominant mode, in [0, π].
    pub psi_per_step: f64,
    /// ln(‖x_n‖/‖x_0‖)/n of the whole state.
    pub norm_growth_per_step: f64,
    /// The root whose mode was measured.
    pub mode: C64,
}

/// Runs `step` for `n_steps` steps from a start with a large component in
/// the mode of `mode`, measuring with the left eigenvector `left` (see the
/// module docs). `progress` receives the number of steps done, now and then.
pub fn simulate(
    step: &Step,
    mode: C64,
    left: &[C64],
    n_steps: u64,
    progress: &mut dyn FnMut(u64),
) -> Simulation {
    let n = step.order();
    let project = |x: &[f64]| -> C64 { left.iter().zip(x).map(|(w, &xi)| w.conj() * xi).sum() };
    // A generic start, or a basis vector if that meets the mode better.
    let generic: Vec<f64> = (0..n).map(|i| (1.0 + 0.7 * i as f64).sin() + 0.25).collect();
    let mut start = generic.clone();
    let score = |x: &[f64]| project(x).norm() / x.iter().map(|v| v * v).sum::<f64>().sqrt();
    for j in 0..n {
        let mut e = vec![0.0; n];
        e[j] = 1.0;
        if score(&e) > 2.0 * score(&start) {
            start = e;
        }
    }
    let norm = |x: &[f64]| x.iter().map(|v| v * v).sum::<f64>().sqrt();
    let mut state = step.state(&start);
    let c0 = project(&start);
    let x0_norm = norm(&start);
    let mut c_prev = c0;
    let mut exponent: i64 = 0;
    let (mut phase_sum, mut phase_comp) = (0.0f64, 0.0f64);
    let mut vanished = false;
    let mut done = 0;
    for k in 1..=n_steps {
        step.advance(&mut state, 1);
        let x = state.slots_mut();
        let max = x.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        if max == 0.0 || !max.is_finite() {
            vanished = max == 0.0;
            done = k;
            break;
        }
        let mut c = project(x);
        let r = c * c_prev.conj();
        let inc = r.im.atan2(r.re).abs();
        // Neumaier summation keeps the phase sum at full precision.
        let t = phase_sum + inc;
        phase_comp +=
            if phase_sum.abs() >= inc { (phase_sum - t) + inc } else { (inc - t) + phase_sum };
        phase_sum = t;
        if !(2f64.powi(-256)..=2f64.powi(256)).contains(&max) {
            let e = max.log2().floor() as i32;
            let f = 2f64.powi(-e);
            x.iter_mut().for_each(|v| *v *= f);
            c *= f;
            exponent += e as i64;
        }
        c_prev = c;
        done = k;
        if k % 65536 == 0 {
            progress(k);
        }
    }
    progress(done);
    let steps = done.max(1) as f64;
    let log_scale = exponent as f64 * LN_2;
    let growth = if vanished {
        f64::NEG_INFINITY
    } else {
        (c_prev.norm().ln() - c0.norm().ln() + log_scale) / steps
    };
    let norm_growth = if vanished {
        f64::NEG_INFINITY
    } else {
        (norm(state.slots()).ln() - x0_norm.ln() + log_scale) / steps
    };
    Simulation {
        steps: done,
        growth_per_step: growth,
        psi_per_step: (phase_sum + phase_comp) / steps,
        norm_growth_per_step: norm_growth,
        mode,
    }
}

/// One comparison of a witness with the reference.
#[derive(Clone, Debug, PartialEq)]
pub struct WitnessCheck {
    /// `nalgebra`, `faer`, `simulation`, `simulation_norm`.
    pub witness: &'static str,
    /// Whether it agrees.
    pub agree: bool,
    /// The largest error divided by its tolerance (≤ 1 when agreeing).
    pub worst_ratio: f64,
}

/// Everything witnessed at one point.
#[derive(Clone, Debug)]
pub struct PointReport {
    /// The parameter values (Φ among them).
    pub params: Params,
    /// The numeric P.
    pub transition_matrix: DMatrix<f64>,
    /// The reference: the exact χ at this point.
    pub exact: ExactForm,
    /// Agreement radius of each reference root.
    pub tolerance: Vec<f64>,
    /// Eigenvalue condition number of each reference root for P.
    pub condition: Vec<f64>,
    /// Cluster size of each reference root.
    pub cluster: Vec<usize>,
    /// nalgebra's eigenvalues, paired with the reference roots.
    pub nalgebra: Vec<C64>,
    /// faer's eigenvalues, paired with the reference roots.
    pub faer: Vec<C64>,
    /// The simulation (None when zero steps were asked for).
    pub sim: Option<Simulation>,
    /// Each comparison.
    pub checks: Vec<WitnessCheck>,
}

impl PointReport {
    /// Φ.
    pub fn phi(&self) -> f64 {
        self.params.phi_value()
    }

    /// Whether every witness agrees with the reference.
    pub fn agree(&self) -> bool {
        self.checks.iter().all(|c| c.agree)
    }
}

/// The witnesses of one method.
#[derive(Clone, Debug)]
pub struct Witnesses {
    method: Method,
    charpoly: ExactCharpoly,
}

impl Witnesses {
    /// Derives `method` exactly and prepares its witnesses.
    pub fn new(method: &Method) -> Result<Witnesses, NumericError> {
        Ok(Witnesses { method: method.clone(), charpoly: ExactCharpoly::new(method)? })
    }

    /// The method.
    pub fn method(&self) -> &Method {
        &self.method
    }

    /// The exact χ.
    pub fn charpoly(&self) -> &ExactCharpoly {
        &self.charpoly
    }

    /// All four witnesses at `params`, with a simulation of `steps` steps
    /// (none when 0).
    pub fn at(&self, params: &Params, steps: u64) -> Result<PointReport, NumericError> {
        self.at_with_progress(params, steps, &mut |_| {})
    }

    /// [`Witnesses::at`], reporting simulation progress.
    pub fn at_with_progress(
        &self,
        params: &Params,
        steps: u64,
        progress: &mut dyn FnMut(u64),
    ) -> Result<PointReport, NumericError> {
        let step = Step::compile(&self.method, params)?;
        let p = step.transition_matrix();
        if p.iter().any(|x| !x.is_finite()) {
            return Err(NumericError::NotFinite { what: "the transition matrix".into() });
        }
        let exact = self.charpoly.at(params)?;
        let (tolerance, condition, cluster) = tolerances(&p, &exact.coeffs, &exact.roots);
        let nalgebra = pair_up(&exact.roots, &eigenvalues_nalgebra(&p)?);
        let faer = pair_up(&exact.roots, &eigenvalues_faer(&p)?);
        let mut checks = Vec::new();
        for (name, found) in [("nalgebra", &nalgebra), ("faer", &faer)] {
            let worst = exact
                .roots
                .iter()
                .zip(found.iter())
                .zip(&tolerance)
                .map(|((r, f), t)| (r - f).norm() / t)
                .fold(0.0, f64::max);
            checks.push(WitnessCheck { witness: name, agree: worst <= 1.0, worst_ratio: worst });
        }
        let sim = if steps > 0 && !exact.roots.is_empty() {
            let dom = exact.roots[0];
            let (_, left) = eigen_condition(&p, dom);
            let sim = simulate(&step, dom, &left, steps, progress);
            let n = exact.roots.len();
            let rho = exact.spectral_radius;
            let mut tol = tolerance[0];
            if cluster[0] >= 2 {
                tol += sim.steps as f64 * C_ISOLATED * n as f64 * f64::EPSILON * scale_of(&p);
            }
            let growth_err = if sim.growth_per_step == f64::NEG_INFINITY {
                rho
            } else {
                (sim.growth_per_step.exp() - rho).abs()
            };
            let psi_err = rho * (sim.psi_per_step - exact.psi).abs();
            let ratio = growth_err.max(psi_err) / tol;
            checks.push(WitnessCheck {
                witness: "simulation",
                agree: ratio <= 1.0,
                worst_ratio: ratio,
            });
            let kappa_max = condition.iter().cloned().fold(1.0, f64::max).min(1e300);
            let m = cluster.iter().copied().max().unwrap_or(1) as f64;
            let steps_f = sim.steps.max(1) as f64;
            let log_tol = ((1.0 + kappa_max).ln() + m * (steps_f + 1.0).ln() + 4.0) / steps_f;
            let norm_tol = tol + rho * log_tol.exp_m1();
            let norm_err = if sim.norm_growth_per_step == f64::NEG_INFINITY {
                rho
            } else {
                (sim.norm_growth_per_step.exp() - rho).abs()
            };
            checks.push(WitnessCheck {
                witness: "simulation_norm",
                agree: norm_err <= norm_tol,
                worst_ratio: norm_err / norm_tol,
            });
            Some(sim)
        } else {
            None
        };
        Ok(PointReport {
            params: step.params().clone(),
            transition_matrix: p,
            exact,
            tolerance,
            condition,
            cluster,
            nalgebra,
            faer,
            sim,
            checks,
        })
    }
}
