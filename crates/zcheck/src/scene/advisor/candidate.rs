//! One candidate's answer ([`CandidateAdvice`]): the fewest stable
//! substeps over every mode (float estimates, then exact checks of the
//! limiting ones, or the full step under non-proportional damping), the
//! certified substeps, Φ_max at the limiting mode, the fewest accurate
//! substeps, the predicted errors and the cost (exact operations and
//! measured ns per tick).

use std::time::Duration;

use check::numeric::{Params, ParamsF64};
use poly::advanced::region::PhiLimit;
use serde::Serialize;

use super::accuracy::{in_band, predicted_errors, Errors};
use super::analysed::{smallest_meeting, Analysed};
use super::full::{band_eigenvalues, full_errors, full_kernel, full_stable, MAX_FULL_DOF};
use super::simulate::Simulated;
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::scene::file::SceneFile;
use crate::scene::modal::{DampingKind, Modal, System};
use crate::scene::vector::Sweep;
use crate::tradeoff::accuracy::Target;
use crate::tradeoff::kernels;

/// One candidate's answer.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct CandidateAdvice {
    /// The method.
    pub(crate) method: String,
    /// Fewest substeps per tick with every mode inside the region (`None`:
    /// none found).
    pub(crate) substeps_stable: Option<u64>,
    /// On an undamped scene, the fewest substeps that keep the certified
    /// bound on the highest frequency stable: never fewer than the exact
    /// answer (`None` elsewhere).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) substeps_stable_certified: Option<u64>,
    /// Fewest substeps meeting the target (`None`: none found).
    pub(crate) substeps_accurate: Option<u64>,
    /// Exact arithmetic operations (multiplications plus additions) per
    /// step of one degree of freedom: the method's program.
    pub(crate) ops_per_step: u64,
    /// Exact operations per tick at `substeps_accurate`: operations per
    /// step × substeps × degrees of freedom. The default ranking's cost.
    pub(crate) ops_per_tick: Option<u64>,
    /// Measured ns per step of one degree of freedom.
    pub(crate) ns_per_step: f64,
    /// ns per tick at `substeps_accurate`: ns per step × substeps × DOF.
    pub(crate) ns_per_tick: Option<f64>,
    /// Predicted errors at `substeps_accurate`.
    pub(crate) predicted: Option<Errors>,
    /// Simulated errors at `substeps_accurate`.
    pub(crate) simulated: Option<Simulated>,
    /// Exact Φ_max at the stability-limiting mode's ζ.
    pub(crate) phi_max: Option<String>,
    /// How `substeps_stable` was decided.
    pub(crate) stability_from: String,
    /// Per mode: own fewest stable substeps.
    #[serde(skip)]
    pub(crate) mode_stable: Vec<Option<u64>>,
    /// Per mode: own fewest accurate substeps.
    #[serde(skip)]
    pub(crate) mode_accurate: Vec<Option<u64>>,
}

/// ns per step of one degree of freedom.
fn ns_per_step(spec: &LoadedMethod, d: f64) -> f64 {
    // The method's own compiled step (native by default), as `tradeoff`
    // ranks: the hand kernels are a baseline, never the ranking.
    let budget = Duration::from_millis(3);
    let params = Params::phi(kernels::TIMING_PHI).with("D", d);
    crate::tradeoff::measure::measure_ns_per_step_within(spec.method(), &params, budget)
        .unwrap_or(f64::NAN)
}

pub(super) fn advise_one(
    a: &mut Analysed,
    scene: &SceneFile,
    modal: &Modal,
    system: &System,
    target: &Target,
) -> Result<CandidateAdvice, Error> {
    let tick = scene.tick_hz;
    let modes = &modal.modes;
    let band = scene.max_hz;
    // The full-step analysis (non-proportional damping) runs without the
    // rigid modes.
    let full_sys = modal.full.as_ref().unwrap_or(system);
    // Float estimates for every mode, then exact answers for the limiting
    // ones (within a factor 0.9 of the largest estimate, or runaways).
    let estimates: Vec<Option<u64>> =
        modes.iter().map(|m| a.estimate_stable(m.omega / tick, m.ratio)).collect();
    let top = estimates.iter().map(|e| e.unwrap_or(u64::MAX)).max().unwrap_or(1);
    let mut mode_stable = vec![None; modes.len()];
    let mut never = false;
    let mut limiting: Option<usize> = None;
    for (i, m) in modes.iter().enumerate() {
        let e = estimates[i].unwrap_or(u64::MAX);
        if (e as f64) < 0.9 * top as f64 && e != u64::MAX {
            mode_stable[i] = Some(e);
            continue;
        }
        // A float estimate is confirmed exactly from there; only a runaway
        // estimate needs the exact Φ_max(ζ) (an analysis per ζ, costly when
        // every mode has its own ratio, as under Rayleigh damping).
        let exact = match estimates[i] {
            Some(guess) => a.exact_stable(m.omega / tick, m.ratio, guess),
            None => match a.limit(m.ratio) {
                Some(PhiLimit::Never) => None,
                Some(PhiLimit::Every) => Some(1),
                _ => a.exact_stable(m.omega / tick, m.ratio, 1),
            },
        };
        if exact.is_none() {
            never = true;
        }
        mode_stable[i] = exact;
    }
    let mut stability_from = "exact (Phi, D) region per mode".to_owned();
    // No mode at all (every one rigid): one substep, max over nothing.
    let mut substeps_stable = if never {
        None
    } else {
        let mut n = mode_stable.iter().map(|s| s.unwrap_or(1)).max().unwrap_or(1);
        // Every mode exactly inside at n (the float estimates of the
        // non-limiting ones included).
        let mut guard = 0;
        while !modes.iter().all(|m| a.inside(m.omega / (tick * n as f64), m.ratio)) && guard < 64 {
            n += 1;
            guard += 1;
        }
        (guard < 64).then_some(n)
    };
    if let Some(n) = substeps_stable {
        limiting = mode_stable.iter().position(|s| *s == Some(n));
    }
    if modal.damping == DampingKind::NonProportional {
        match a.spec.system_kernel() {
            Some(k) if full_sys.n() <= MAX_FULL_DOF => {
                substeps_stable = full_stable(k, Sweep::Vector, full_sys, tick, substeps_stable.unwrap_or(1));
                stability_from = "full-step matrix (non-proportional damping)".to_owned();
            }
            _ => {
                stability_from =
                    "modal estimate only: non-proportional damping, no full-step analysis for this method or size"
                        .to_owned()
            }
        }
    }
    // On an undamped scene the highest frequency limits stability, so the
    // substeps that keep its certified bound stable are never too few,
    // whatever the eigensolver's error.
    let substeps_stable_certified = match (modal.damping, modal.omega_bound, substeps_stable) {
        (DampingKind::Undamped, Some(w), Some(n)) => a.exact_stable(w / tick, 0.0, n),
        _ => None,
    };
    let phi_max = limiting.and_then(|i| match a.limit(modes[i].ratio)? {
        PhiLimit::Below(m) => Some(m.to_decimal(12)),
        PhiLimit::Every => Some("every Phi".to_owned()),
        PhiLimit::Never => Some("none".to_owned()),
    });
    // Accuracy: per mode, the fewest n ≥ substeps_stable meeting the target.
    let mut mode_accurate = vec![None; modes.len()];
    let mut substeps_accurate = None;
    if let (Some(ns), true) = (substeps_stable, a.second.is_some()) {
        for (i, m) in modes.iter().enumerate() {
            if in_band(band, m.omega) {
                mode_accurate[i] = smallest_meeting(|n| a.meets(m, tick, n, target), ns);
            }
        }
        if modes.iter().zip(&mode_accurate).all(|(m, n)| n.is_some() || !in_band(band, m.omega)) {
            let mut n = mode_accurate.iter().flatten().copied().max().unwrap_or(ns);
            let mut guard = 0;
            while !modes
                .iter()
                .filter(|m| in_band(band, m.omega))
                .all(|m| a.meets(m, tick, n, target))
                && guard < 64
            {
                n += 1;
                guard += 1;
            }
            substeps_accurate = (guard < 64).then_some(n);
        }
    }
    let d_timing = modes.iter().map(|m| m.ratio).fold(0.0, f64::max).min(1.0);
    let ns = ns_per_step(&a.spec, d_timing);
    let ops = u64::from(a.spec.derivation()?.cost().program.arithmetic());
    let dof = scene.dof() as f64;
    let full = full_kernel(a, modal, full_sys);
    let predicted = if let Some(kernel) = full {
        // The modes are coupled: judge the full step's eigenvalues against
        // the continuous system's e^{λT}.
        let lambdas = band_eigenvalues(full_sys, band);
        let duration = scene.duration_s;
        let meets = |n: u64| {
            full_errors(kernel, full_sys, &lambdas, tick, n, duration)
                .is_some_and(|e| e.phase_rad <= target.phase_tol && e.amplitude <= target.amp_tol)
        };
        substeps_accurate = substeps_stable.and_then(|ns| smallest_meeting(meets, ns));
        substeps_accurate.and_then(|n| full_errors(kernel, full_sys, &lambdas, tick, n, duration))
    } else {
        substeps_accurate.map(|n| predicted_errors(a, modes, tick, n, target, band, None))
    };
    Ok(CandidateAdvice {
        method: a.spec.display().to_owned(),
        substeps_stable,
        substeps_stable_certified,
        substeps_accurate,
        ops_per_step: ops,
        ops_per_tick: substeps_accurate
            .map(|n| ops.saturating_mul(n).saturating_mul(scene.dof() as u64)),
        ns_per_step: ns,
        ns_per_tick: substeps_accurate.map(|n| ns * n as f64 * dof),
        predicted,
        simulated: None,
        phi_max,
        stability_from,
        mode_stable,
        mode_accurate,
    })
}
