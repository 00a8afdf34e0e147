//! The whole-scene advisor: which method, how many substeps per tick, for a
//! whole scene of masses and springs, or of modes (`zcheck advise --scene`).
//! A single spring in game units is the single-spring advisor's
//! (`tradeoff::spring_advisor`); `zcheck advise --freq --tick`
//! runs both, this one on the spring as a one-mode scene.
//!
//! For every candidate method and every mode (ω, ζ) the substep is
//! Φ = ω/(tick·n). Per candidate:
//!
//! - `substeps_stable`: the smallest n putting every mode inside the exact
//!   (Φ, D) region of the method. A float estimate of each mode's n picks
//!   the limiting modes; the answer is then decided exactly: every mode is
//!   checked inside the region at n, and the limiting mode outside at
//!   n − 1. A mode whose f64 spectral radius clears 1 by 10⁻⁶ is decided by
//!   it (that margin is 10⁹ times the rounding error of a simple root);
//!   every other is decided exactly against the stable intervals of
//!   χ(·, ζ) from `poly::advanced::region` and `poly::advanced::stability`, analysed once per ζ. A mode whose
//!   float estimate runs away is settled by the exact Φ_max(ζ) (`Never`:
//!   unbounded at every small Φ). The stable set at fixed ζ is taken to be
//!   the interval (0, Φ_max) below the first boundary.
//! - `substeps_accurate`: the smallest n ≥ `substeps_stable` at which every
//!   mode meets the target over the duration, from the exact χ's principal
//!   root r·e^{jΨ} against the exact e^{(−ζ ± j√(1−ζ²))Φ} (the model of
//!   `tradeoff::accuracy`, with p, q − 1 and q − p² exact polynomials in
//!   (Φ, D) evaluated in f64). Overdamped modes (ζ ≥ 1) have no phase and
//!   are judged for stability only.
//! - the cost per tick: measured ns per step × substeps × degrees of freedom.
//!
//! With `[accuracy] max_hz = F` the targets (and the check by simulation)
//! apply only to the modes at or below F Hz; every mode is still judged
//! for stability. Zero-frequency (rigid) modes are left out of both: Φ = 0
//! needs no substeps, and a scene with no other mode is stable and accurate
//! at one substep.
//!
//! With non-proportional damping, `substeps_stable` of a built-in comes
//! from the assembled full-step matrix (`vector`), not from the modes.
//!
//! The prediction is checked by simulating the whole scene with the
//! method's system kernel (`vector`) at `substeps_accurate`, projecting the
//! positions on the mode shapes, and fitting each modal sequence's
//! per-step root from the recurrence q_{k+1} = a q_k + b q_{k−1} (least
//! squares): the simulated drifts are the fitted root's, over the duration.
//!
//! The files, one concern each: this one holds the entry ([`advise`],
//! [`Options`]), the report ([`SceneAdvice`], `ModeReport`, `Recommended`,
//! `LeftOut`), the ranking by exact cost and the choice of what to
//! simulate. `analysed.rs` builds a candidate's analysis once
//! (χ as f64 polynomials in (Φ, D), its exact region); `estimate.rs` holds
//! the float estimates, `exact.rs` the exact region checks, `accuracy.rs`
//! the accuracy model of a mode, `full.rs` the full step under
//! non-proportional damping, `candidate.rs` one candidate's answer,
//! `simulate.rs` the checking simulation and `sweep.rs` the Gauss–Seidel
//! analysis.

mod accuracy;
mod analysed;
mod candidate;
mod estimate;
mod exact;
mod full;
mod simulate;
mod sweep;

use check::numeric::{Params, ParamsF64};
use serde::Serialize;

use self::analysed::Analysed;
use self::candidate::advise_one;
pub(crate) use self::candidate::CandidateAdvice;
#[cfg(test)]
pub(crate) use self::simulate::fit_root;
use self::simulate::simulate_candidate;
pub(crate) use self::simulate::AGREE_FRACTION;
use self::sweep::{sweep_report, SweepReport};
use super::file::SceneFile;
use super::modal::{DampingKind, Modal, Sparse, System};
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::tradeoff::accuracy::Target;
use crate::tradeoff::kernels;
use crate::tradeoff::Rank;

/// One mode in the report.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct ModeReport {
    /// Undamped frequency, Hz.
    pub hz: f64,
    /// Damping ratio.
    pub ratio: f64,
    /// A sample of the unresolved spectrum of a large scene, not a mode
    /// found (see `spectrum` in the advice).
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub sampled: bool,
    /// Whether it sets the recommended method's `substeps_stable`.
    pub limits_stability: bool,
    /// Whether it sets the recommended method's `substeps_accurate`.
    pub limits_accuracy: bool,
}

/// The recommendation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Recommended {
    /// The method.
    pub method: String,
    /// Substeps per tick.
    pub substeps: u64,
}

/// The advisor's answer.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SceneAdvice {
    /// Tick rate, Hz.
    pub(crate) tick_hz: f64,
    /// Duration, s.
    pub(crate) duration_s: f64,
    /// Phase target, rad.
    pub(crate) phase_rad: f64,
    /// Amplitude target.
    pub(crate) amplitude: f64,
    /// The targets apply to modes at or below this frequency, Hz (`None`:
    /// every mode).
    pub(crate) max_hz: Option<f64>,
    /// Degrees of freedom.
    pub(crate) dof: usize,
    /// Zero-frequency (rigid-body) modes left out: they need no substeps.
    pub(crate) rigid_modes: usize,
    /// The damping's structure.
    pub(crate) damping: DampingKind,
    /// The modes, increasing frequency.
    pub(crate) modes: Vec<ModeReport>,
    /// Every candidate.
    pub(crate) candidates: Vec<CandidateAdvice>,
    /// The cheapest candidate meeting the target, by `rank`.
    pub(crate) recommended: Option<Recommended>,
    /// What `recommended` is ranked by: exact operations per tick (the
    /// default, the same on every machine) or the ns measured here.
    pub(crate) rank: Rank,
    /// The highest mode's frequency, Hz, as the eigensolver gives it.
    pub(crate) highest_hz: Option<f64>,
    /// A certified upper bound on the highest undamped frequency, Hz
    /// (Gershgorin, or a Cholesky certificate on the sparse route; `None`
    /// for a scene of modes).
    pub(crate) highest_hz_bound: Option<f64>,
    /// How the spectrum was found: dense (every mode) or sparse.
    pub(crate) spectrum: super::modal::RouteReport,
    /// The candidates meeting the target that the checking simulation left
    /// out: more than [`SIM_COST_FACTOR`] times the recommended's cost.
    pub(crate) simulation_left_out: Vec<LeftOut>,
    /// The Gauss–Seidel analysis, when asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) sweep: Option<Vec<SweepReport>>,
}

/// The scene's step per tick and duration, and the target (periods is the
/// duration in seconds here; each mode multiplies by its own frequency).
fn target_of(scene: &SceneFile) -> Target {
    Target { phase_tol: scene.phase_rad, amp_tol: scene.amplitude, periods: scene.duration_s }
}

/// The system a scene simulates: its own, or (a scene of modes) one unit
/// mass per mode with k = ω², c = 2ζω.
fn system_of(modal: &Modal) -> (System, Vec<Vec<f64>>) {
    if let Some(sys) = &modal.system {
        let shapes = modal.modes.iter().map(|m| m.shape.clone().unwrap_or_default()).collect();
        return (sys.clone(), shapes);
    }
    let n = modal.modes.len();
    let k: Vec<f64> = modal.modes.iter().map(|m| m.omega * m.omega).collect();
    let c: Vec<f64> = modal.modes.iter().map(|m| 2.0 * m.ratio * m.omega).collect();
    let (k, c) = (Sparse::diagonal(&k), Sparse::diagonal(&c));
    let shapes = (0..n).map(|i| (0..n).map(|j| if i == j { 1.0 } else { 0.0 }).collect()).collect();
    (System { mass: vec![1.0; n], k, c }, shapes)
}

/// Options of [`advise`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Options {
    /// Simulate to check the prediction.
    pub simulate: bool,
    /// Simulate every candidate that meets the target, not only those
    /// within `SIM_COST_FACTOR` of the recommended's cost.
    pub simulate_all: bool,
    /// Analyse the Gauss–Seidel sweep too.
    pub gauss_seidel: bool,
    /// The eigensolver that reduces the scene.
    pub route: super::modal::Route,
    /// What the recommendation is ranked by.
    pub rank: Rank,
}

/// Advises on a scene.
pub fn advise(
    scene: &SceneFile,
    modal: &Modal,
    specs: Vec<LoadedMethod>,
    options: Options,
) -> Result<SceneAdvice, Error> {
    let tick = scene.tick_hz;
    let target = target_of(scene);
    let dof = scene.dof();
    let (system, shapes) = system_of(modal);
    let mut candidates = Vec::new();
    let mut analysed_all = Vec::new();
    // Every candidate's native step in one rustc call (or from the cache).
    let d_timing = modal.modes.iter().map(|m| m.ratio).fold(0.0, f64::max).min(1.0);
    let timing = Params::phi(kernels::TIMING_PHI).with("D", d_timing);
    let _ =
        crate::native::prepare(&specs.iter().map(|s| (s.method(), &timing)).collect::<Vec<_>>());
    for spec in specs {
        if !spec.method().params().iter().any(|s| s.name() == "D")
            && modal.modes.iter().any(|m| m.ratio != 0.0)
        {
            return Err(Error::unsupported(format!(
                "method {}: the scene is damped but the method has no parameter D: expected `param D` \
                 (the test equation v' = -2*D*v - y, y' = v)",
                spec.display()
            )));
        }
        let mut a = Analysed::new(spec)?;
        let adv = advise_one(&mut a, scene, modal, &system, &target)?;
        candidates.push(adv);
        analysed_all.push(a);
    }
    // The cheapest meeting the target, by exact operations per tick (ties
    // by name) or by the ns measured (ties by operations, then name).
    let by = options.rank;
    let recommended = candidates
        .iter()
        .filter_map(|c| {
            let ns = c.ns_per_tick.filter(|ns| ns.is_finite() || by == Rank::Exact)?;
            Some(((c.ops_per_tick?, ns, c.method.as_str()), c.substeps_accurate?, c))
        })
        .min_by(|a, b| by.cmp(a.0, b.0))
        .map(|(_, n, c)| Recommended { method: c.method.clone(), substeps: n });
    // The checking simulation: the recommended method and those within
    // SIM_COST_FACTOR of its cost (in the ranking's measure), in parallel;
    // the others are named.
    let cost = |c: &CandidateAdvice| match by {
        Rank::Exact => c.ops_per_tick.map(|o| o as f64),
        Rank::Measured => c.ns_per_tick,
    };
    let rec_cost = recommended
        .as_ref()
        .and_then(|r| candidates.iter().find(|c| c.method == r.method).and_then(cost));
    let mut simulation_left_out = Vec::new();
    if options.simulate {
        let close_in_cost = |c: &CandidateAdvice| match (cost(c), rec_cost) {
            _ if options.simulate_all => true,
            (Some(x), Some(rec)) => x <= SIM_COST_FACTOR * rec,
            _ => false,
        };
        for c in candidates.iter().filter(|c| c.substeps_accurate.is_some() && !close_in_cost(c)) {
            simulation_left_out.push(LeftOut {
                method: c.method.clone(),
                cost_ratio: match (cost(c), rec_cost) {
                    (Some(x), Some(rec)) if rec > 0.0 => Some(x / rec),
                    _ => None,
                },
            });
        }
        use rayon::prelude::*;
        analysed_all
            .par_iter_mut()
            .zip(candidates.par_iter_mut())
            .filter(|(_, c)| c.substeps_accurate.is_some() && close_in_cost(c))
            .for_each(|(a, c)| {
                let n = c.substeps_accurate.expect("filtered");
                c.simulated = simulate_candidate(a, scene, modal, &system, &shapes, &target, n);
            });
        crate::interrupt::check(|| {
            "the checking simulation was stopped before it ended (--no-simulate skips it)".into()
        })?;
    }
    let reference = recommended
        .as_ref()
        .and_then(|r| candidates.iter().find(|c| c.method == r.method))
        .or_else(|| candidates.iter().find(|c| c.substeps_stable.is_some()));
    let modes = modal
        .modes
        .iter()
        .enumerate()
        .map(|(i, m)| ModeReport {
            hz: m.hz(),
            ratio: m.ratio,
            sampled: m.sampled,
            limits_stability: reference.is_some_and(|c| {
                c.substeps_stable.is_some() && c.mode_stable[i] == c.substeps_stable
            }),
            limits_accuracy: reference.is_some_and(|c| {
                c.substeps_accurate.is_some() && c.mode_accurate[i] == c.substeps_accurate
            }),
        })
        .collect();
    let sweep = if options.gauss_seidel {
        Some(
            analysed_all
                .iter()
                .zip(&candidates)
                .filter_map(|(a, c)| {
                    Some(sweep_report(
                        a.spec.system_kernel()?,
                        a.spec.display(),
                        &system,
                        tick,
                        c.substeps_stable,
                    ))
                })
                .collect::<Result<Vec<_>, Error>>()?,
        )
    } else {
        None
    };
    Ok(SceneAdvice {
        tick_hz: tick,
        duration_s: scene.duration_s,
        phase_rad: scene.phase_rad,
        amplitude: scene.amplitude,
        max_hz: scene.max_hz,
        dof,
        rigid_modes: modal.rigid,
        damping: modal.damping,
        modes,
        candidates,
        recommended,
        rank: options.rank,
        highest_hz: modal.route.highest_ritz_hz.or_else(|| {
            modal
                .modes
                .iter()
                .filter(|m| !m.sampled)
                .map(|m| m.hz())
                .fold(None, |a: Option<f64>, h| Some(a.map_or(h, |a| a.max(h))))
        }),
        spectrum: modal.route.clone(),
        highest_hz_bound: modal.omega_bound.map(|w| w / (2.0 * std::f64::consts::PI)),
        simulation_left_out,
        sweep,
    })
}

/// A candidate the checking simulation left out, and its cost against the
/// recommended's (`None` when either cost is unknown).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub(crate) struct LeftOut {
    /// The method.
    pub method: String,
    /// Its ns per tick over the recommended's.
    pub cost_ratio: Option<f64>,
}

/// The checking simulation runs the recommended method and those within
/// this factor of its cost per tick: they are the ones a user would pick
/// instead. A method that needs 10⁵ substeps per tick is not simulated.
pub(crate) const SIM_COST_FACTOR: f64 = 4.0;
