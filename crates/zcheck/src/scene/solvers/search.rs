//! The advice: one configuration analysed, or the search over S in 1..=64
//! and N in 1..=16 (N = 1 for the soft step) for the cheapest configuration
//! that is stable and meets the targets, and the entry the CLI calls,
//! [`solver_advice`].
//!
//! The search screens in exact cost order and solves only what can win.
//! Cost is S·N·(constraints), so for each N (increasing) only S with
//! S·N below the best cost found so far can win (equal cost loses to the
//! fewer iterations already found): S_hi = min(64, ⌊(best − 1)/N⌋). Taking
//! "passes" (stable and accurate) as monotone in S at fixed N, as the
//! force-based advisor takes stability monotone in its substeps, S_hi is
//! screened first (failing, no smaller S passes) and otherwise the smallest
//! passing S is found by bisection. Each screen is one eigenvalue problem of
//! the deflated substep map; the recommendation alone is analysed in full
//! (certificate and simulation check). Ties go to fewer iterations, then
//! fewer substeps.

use std::collections::BTreeMap;

use serde::Serialize;

use super::super::file::SceneFile;
use super::analysis::{self, ConfigAdvice, Depth, Prepared};
use super::model::{Config, Solver, MAX_SUBSTEPS};
use crate::error::Error;

/// A configuration the search screened.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Candidate {
    /// The solver.
    pub solver: Solver,
    /// Substeps per tick.
    pub substeps: u64,
    /// Iterations per substep.
    pub iterations: u64,
    /// Stable on the non-rigid modes.
    pub stable: bool,
    /// Meets the phase and amplitude targets.
    pub meets_accuracy: bool,
    /// Constraint projections per tick.
    pub cost: u64,
    /// Exact arithmetic operations per tick (the kernel's count × S).
    pub ops_per_tick: u64,
    /// Largest phase error over the duration, rad.
    pub phase_error_rad: f64,
    /// Largest relative amplitude error over the duration.
    pub amplitude_error: f64,
}

/// The recommended configuration.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Recommended {
    /// The solver.
    pub solver: Solver,
    /// Substeps per tick.
    pub substeps: u64,
    /// Iterations per substep.
    pub iterations: u64,
}

/// The search's answer.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct SearchAdvice {
    /// The solver searched.
    pub solver: Solver,
    /// What was searched.
    pub searched: String,
    /// Every configuration screened, by cost (ties: fewer iterations, then
    /// fewer substeps).
    pub candidates: Vec<Candidate>,
    /// The cheapest stable configuration meeting the targets.
    pub recommended: Option<Recommended>,
    /// Why there is none.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// The recommended configuration analysed in full.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub analysis: Option<ConfigAdvice>,
    /// The pairing rule of eigenvalues with modes.
    pub pairing: &'static str,
}

/// One configuration or the search.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub(crate) enum Answer {
    /// `--substeps S --iterations N`.
    One(ConfigAdvice),
    /// No configuration given.
    Search(SearchAdvice),
}

/// The document `zcheck advise --scene FILE --solver ...` prints.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct SolverAdvice {
    /// Tick rate, Hz.
    pub tick_hz: f64,
    /// Duration, s.
    pub duration_s: f64,
    /// Phase target, rad.
    pub phase_rad: f64,
    /// Amplitude target.
    pub amplitude: f64,
    /// The targets apply at or below this frequency, Hz.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_hz: Option<f64>,
    /// Free degrees of freedom.
    pub dof: usize,
    /// Constraints (a ground spring of a 2D or 3D scene counts once per axis).
    pub constraints: usize,
    /// The answer.
    #[serde(flatten)]
    pub answer: Answer,
}

/// Advice for `solver` on a scene: the configuration `(substeps,
/// iterations)` analysed, or without one the search. Bad configurations
/// are usage errors naming the flag.
pub(crate) fn solver_advice(
    scene: &SceneFile,
    solver: Solver,
    config: Option<(u64, u64)>,
) -> Result<SolverAdvice, Error> {
    solver_advice_relaxed(scene, solver, config, 1.0)
}

/// [`solver_advice`] with Jacobi's relaxation factor (`xpbd_jacobi`).
pub(crate) fn solver_advice_relaxed(
    scene: &SceneFile,
    solver: Solver,
    config: Option<(u64, u64)>,
    relaxation: f64,
) -> Result<SolverAdvice, Error> {
    // Check the configuration before any work.
    let one = config.map(|(s, n)| Config::with_relaxation(solver, s, n, relaxation)).transpose()?;
    Config::with_relaxation(solver, 1, 1, relaxation)?;
    let prep = Prepared::new(scene)?;
    let answer = match one {
        Some(c) => Answer::One(analysis::analyse(&prep, &c, Depth::Full)?),
        None => Answer::Search(search(&prep, solver, relaxation)?),
    };
    Ok(SolverAdvice {
        tick_hz: prep.tick_hz,
        duration_s: prep.duration_s,
        phase_rad: prep.phase_rad,
        amplitude: prep.amplitude,
        max_hz: prep.max_hz,
        dof: prep.model.n(),
        constraints: prep.model.m(),
        answer,
    })
}

/// The search (see the module notes).
pub(crate) fn search(
    prep: &Prepared,
    solver: Solver,
    relaxation: f64,
) -> Result<SearchAdvice, Error> {
    let mut seen: BTreeMap<(u64, u64), Candidate> = BTreeMap::new();
    let eval =
        |s: u64, n: u64, seen: &mut BTreeMap<(u64, u64), Candidate>| -> Result<bool, Error> {
            if let Some(c) = seen.get(&(n, s)) {
                return Ok(c.stable && c.meets_accuracy);
            }
            if crate::interrupt::requested() {
                return Err(Error::interrupted("the solver search was stopped before it ended"));
            }
            let config = Config::with_relaxation(solver, s, n, relaxation)?;
            let a = analysis::analyse(prep, &config, Depth::Screen)?;
            let pass = a.stable && a.meets_accuracy;
            seen.insert(
                (n, s),
                Candidate {
                    solver,
                    substeps: s,
                    iterations: n,
                    stable: a.stable,
                    meets_accuracy: a.meets_accuracy,
                    cost: a.cost,
                    ops_per_tick: a.ops_per_tick,
                    phase_error_rad: a.phase_error_rad,
                    amplitude_error: a.amplitude_error,
                },
            );
            Ok(pass)
        };
    // Best so far: S·N, N, S.
    let mut best: Option<(u64, u64, u64)> = None;
    for n in solver.iteration_range() {
        let s_hi = match best {
            Some((units, _, _)) => MAX_SUBSTEPS.min((units - 1) / n),
            None => MAX_SUBSTEPS,
        };
        if s_hi == 0 || !eval(s_hi, n, &mut seen)? {
            continue;
        }
        let (mut lo, mut hi) = (0u64, s_hi);
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if eval(mid, n, &mut seen)? {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        best = Some((hi * n, n, hi));
    }
    let mut candidates: Vec<Candidate> = seen.into_values().collect();
    candidates.sort_by_key(|c| (c.cost, c.iterations, c.substeps));
    let searched = format!(
        "substeps 1..={MAX_SUBSTEPS}, iterations {}..={}",
        solver.iteration_range().start(),
        solver.iteration_range().end()
    );
    let (recommended, reason, analysis) = match best {
        Some((_, n, s)) => {
            let config = Config::with_relaxation(solver, s, n, relaxation)?;
            let full = analysis::analyse(prep, &config, Depth::Full)?;
            (Some(Recommended { solver, substeps: s, iterations: n }), None, Some(full))
        }
        None => {
            let reason = if candidates.iter().any(|c| c.stable) {
                let best_phase =
                    candidates.iter().map(|c| c.phase_error_rad).fold(f64::INFINITY, f64::min);
                let best_amp =
                    candidates.iter().map(|c| c.amplitude_error).fold(f64::INFINITY, f64::min);
                format!(
                    "no configuration with {searched} meets the targets (phase {} rad, amplitude {}): \
                     the smallest errors screened are {best_phase:.3e} rad and {best_amp:.3e}",
                    prep.phase_rad, prep.amplitude
                )
            } else {
                format!("no configuration with {searched} is stable")
            };
            (None, Some(reason), None)
        }
    };
    Ok(SearchAdvice {
        solver,
        searched,
        candidates,
        recommended,
        reason,
        analysis,
        pairing: analysis::PAIRING,
    })
}
