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

use crate::numeric::ParamsF64;
use nalgebra::DMatrix;
use poly::Method;

use crate::error::Error;
use crate::numeric::{Params, Step};

mod eigen;
mod exact;
mod simulate;
mod tolerance;

pub use eigen::*;
pub use exact::*;
pub use simulate::*;
pub use tolerance::*;

/// The simulation length when none is given.
pub const DEFAULT_STEPS: u64 = 1_000_000;

/// The largest norm of P, and magnitude of an eigenvalue, the witnesses take:
/// their squares stay far inside the `f64` range.
pub const MAX_WITNESS_MAGNITUDE: f64 = 1e100;

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
    pub fn new(method: &Method) -> Result<Witnesses, Error> {
        Ok(Witnesses::from_derivation(&poly::derive(method)?))
    }

    /// The witnesses of an existing derivation, without deriving again.
    pub fn from_derivation(derivation: &poly::Derivation) -> Witnesses {
        Witnesses {
            method: derivation.method().clone(),
            charpoly: ExactCharpoly::from_derivation(derivation),
        }
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
    pub fn at(&self, params: &Params, steps: u64) -> Result<PointReport, Error> {
        self.at_with_progress(params, steps, &mut |_| true)
    }

    /// [`Witnesses::at`], reporting simulation progress. `progress` returns
    /// `false` to stop the simulation (a Ctrl-C): the answer is then an
    /// error of kind [`ErrorKind::Interrupted`](crate::ErrorKind::Interrupted).
    pub fn at_with_progress(
        &self,
        params: &Params,
        steps: u64,
        progress: &mut dyn FnMut(u64) -> bool,
    ) -> Result<PointReport, Error> {
        let step = Step::compile(&self.method, params)?;
        let p = step.transition_matrix();
        // The witnesses square magnitudes (norms, SVD): beyond 1e100 that
        // overflows, and nalgebra's SVD panics on the NaN that follows.
        if p.iter().any(|x| !x.is_finite()) {
            return Err(Error::out_of_range("the transition matrix overflows f64"));
        }
        if p.amax() * p.nrows() as f64 > MAX_WITNESS_MAGNITUDE {
            return Err(Error::out_of_range(&format!(
                "the transition matrix has an entry of magnitude {:.1e}",
                p.amax()
            )));
        }
        let exact = self.charpoly.at(params)?;
        if let Some(big) =
            exact.roots.iter().find(|z| z.norm().is_nan() || z.norm() > MAX_WITNESS_MAGNITUDE)
        {
            return Err(Error::out_of_range(&format!(
                "an eigenvalue has magnitude {:.1e}",
                big.norm()
            )));
        }
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
            if sim.stopped {
                return Err(Error::interrupted(sim.steps, steps));
            }
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
