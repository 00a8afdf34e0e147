//! The Gauss–Seidel analysis (`--sweep gauss-seidel`, [`SweepReport`]): a
//! built-in's fewest stable substeps body by body against all bodies at
//! once and the modal answer, the two eigenvalue witnesses of its full
//! step, and the ratio of the largest stable steps.

use serde::Serialize;

use super::full::{full_ok, full_stable, radii, MAX_FULL_DOF};
use crate::error::Error;
use crate::scene::modal::System;
use crate::scene::vector::{self, Kernel, Sweep};

/// Gauss–Seidel analysis of one candidate.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct SweepReport {
    /// The method.
    pub method: String,
    /// Fewest substeps stable with all bodies at once (modal).
    pub substeps_modal: Option<u64>,
    /// Fewest substeps with ρ ≤ 1 + 1e-12, all bodies at once (the same
    /// numeric test as the Gauss–Seidel column, for a like comparison).
    pub substeps_vector: Option<u64>,
    /// Fewest substeps with ρ ≤ 1 + 1e-12 body by body.
    pub substeps_gauss_seidel: Option<u64>,
    /// ρ of the Gauss–Seidel full step at `substeps_modal`: nalgebra.
    pub rho_nalgebra: Option<f64>,
    /// The same by faer.
    pub rho_faer: Option<f64>,
    /// Whether the two eigenvalue witnesses agree (1e-9 relative).
    pub witnesses_agree: bool,
    /// Largest stable step T body by body over the modal one.
    pub limit_ratio: Option<f64>,
}

/// The Gauss–Seidel report of one built-in.
pub(super) fn sweep_report(
    kernel: Kernel,
    name: &str,
    sys: &System,
    tick: f64,
    modal: Option<u64>,
) -> Result<SweepReport, Error> {
    if sys.n() > MAX_FULL_DOF {
        return Err(Error::usage(format!(
            "--sweep gauss-seidel: the scene has {} degrees of freedom: the full-step analysis takes at most {MAX_FULL_DOF}",
            sys.n()
        )));
    }
    let gs = full_stable(kernel, Sweep::GaussSeidel, sys, tick, modal.unwrap_or(1));
    let vec_n = full_stable(kernel, Sweep::Vector, sys, tick, modal.unwrap_or(1));
    let at = modal.or(gs).unwrap_or(1);
    let r = radii(&vector::step_matrix(kernel, Sweep::GaussSeidel, sys, 1.0 / (tick * at as f64)));
    // Largest stable T for each order, by bisection on T.
    let largest = |sweep: Sweep| -> Option<f64> {
        let mut lo = 0.0;
        let mut hi = 1.0 / tick;
        if full_ok(kernel, sweep, sys, hi) {
            return None;
        }
        let mut found = false;
        for k in 1..40 {
            let t = hi / 2f64.powi(k);
            if full_ok(kernel, sweep, sys, t) {
                lo = t;
                hi = t * 2.0;
                found = true;
                break;
            }
        }
        if !found {
            return None;
        }
        for _ in 0..50 {
            let mid = 0.5 * (lo + hi);
            if full_ok(kernel, sweep, sys, mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(lo)
    };
    let ratio = match (largest(Sweep::GaussSeidel), largest(Sweep::Vector)) {
        (Some(g), Some(v)) => Some(g / v),
        _ => None,
    };
    Ok(SweepReport {
        method: name.to_owned(),
        substeps_modal: modal,
        substeps_vector: vec_n,
        substeps_gauss_seidel: gs,
        rho_nalgebra: r.map(|x| x.0),
        rho_faer: r.map(|x| x.1),
        witnesses_agree: r.is_some_and(|(x, y)| (x - y).abs() <= 1e-9 * x.max(1.0)),
        limit_ratio: ratio,
    })
}
