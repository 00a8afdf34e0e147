//! The single-spring advisor: one spring in game units (Hz) on a fixed
//! tick, answered from the trade-off's model of each method (`zcheck advise
//! --freq --tick`). A whole scene of masses and springs, or of modes, is
//! the whole-scene advisor's ([`crate::scene::advisor`]), which `zcheck
//! advise` also runs on this spring as a one-mode scene.
//!
//! A spring of frequency f simulated at a tick rate of `tick` Hz advances by
//! Φ = 2π·f/tick per tick. With k substeps per tick each substep is Φ/k. For
//! each method the advisor reports:
//!
//! - whether it is stable at Φ itself (Φ < Φ_max, decided exactly);
//! - the fewest substeps k that make it stable (Φ/k < Φ_max);
//! - the fewest substeps that meet the tolerance over the spring's duration
//!   (Φ/k at most the largest admissible Φ, so never at or past Φ_max);
//! - the cost per tick at that k, in operations and in measured ns;
//!
//! and names the cheapest method meeting the tolerance (by ns per tick).
//!
//! It models only what the spring requires: an undamped spring, unless a
//! damping ratio is given; then every method runs on the damped spring and is
//! judged against the exact damped oscillator's per-step decay e^{−DΦ} and
//! phase advance Φ√(1 − D²).

use std::f64::consts::PI;

use serde::Serialize;

use super::accuracy::{Spring, Target};
use super::family::{Candidate, MAX_SUBSTEPS};
use super::rank::{limit_text, Ops, Rank};
use crate::error::Error;

/// A spring in a game: its frequency, the tick rate, and the target.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub(crate) struct SpringScene {
    /// The spring's natural frequency, Hz.
    pub freq_hz: f64,
    /// The simulation tick rate, Hz.
    pub tick_hz: f64,
    /// How long the spring must stay within tolerance, seconds.
    pub duration_s: f64,
    /// Largest accumulated phase error over the duration, radians.
    pub phase_tol: f64,
    /// Largest relative amplitude error over the duration.
    pub amp_tol: f64,
    /// The physical damping ratio D, when the spring is damped.
    pub damping: Option<f64>,
}

impl SpringScene {
    /// Default duration: one second.
    pub(crate) const DEFAULT_DURATION_S: f64 = 1.0;
    /// Default phase tolerance: 0.1 rad accumulated over the duration.
    pub(crate) const DEFAULT_PHASE_TOL: f64 = 0.1;
    /// Default amplitude tolerance: 1 % over the duration.
    pub(crate) const DEFAULT_AMP_TOL: f64 = 0.01;

    /// Checks the spring's numbers; the error names the bad value and what
    /// was expected.
    pub(crate) fn validate(&self) -> Result<(), Error> {
        let positive = [
            ("--freq", self.freq_hz),
            ("--tick", self.tick_hz),
            ("--duration", self.duration_s),
            ("--phase-tol", self.phase_tol),
            ("--amp-tol", self.amp_tol),
        ];
        for (name, x) in positive {
            if !(x.is_finite() && x > 0.0) {
                return Err(Error::usage(format!("{name} {x}: expected a finite number > 0")));
            }
        }
        if let Some(d) = self.damping {
            if !(0.0..1.0).contains(&d) {
                return Err(Error::usage(format!(
                    "--damping {d}: expected a damping ratio with 0 <= D < 1 (an oscillating spring)"
                )));
            }
        }
        Ok(())
    }

    /// Φ = 2π·f/tick, radians per tick.
    pub(crate) fn phi(&self) -> f64 {
        2.0 * PI * self.freq_hz / self.tick_hz
    }

    /// The duration in periods of the spring, f·duration.
    pub(crate) fn periods(&self) -> f64 {
        self.freq_hz * self.duration_s
    }

    /// The accuracy target.
    pub(crate) fn target(&self) -> Target {
        Target { phase_tol: self.phase_tol, amp_tol: self.amp_tol, periods: self.periods() }
    }

    /// The exact spring judged against.
    pub(crate) fn spring(&self) -> Spring {
        Spring { damping: self.damping.unwrap_or(0.0) }
    }
}

/// One method's answer for the spring.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct MethodAdvice {
    /// The method (damped variants by their base name).
    pub method: String,
    /// Exact Φ_max as text ("none": unbounded at every Φ > 0).
    pub phi_max: String,
    /// Stable at the spring's Φ with one step per tick (Φ < Φ_max).
    pub stable_at_phi: bool,
    /// The fewest substeps k with Φ/k < Φ_max (`None`: never stable).
    pub substeps_stable: Option<u64>,
    /// The fewest substeps meeting the tolerance (`None`: no stable step
    /// meets it).
    pub substeps_tol: Option<u64>,
    /// Operations per step.
    pub ops_per_step: Ops,
    /// Measured ns per step (the compiled step).
    pub ns_per_step: f64,
    /// Measured ns per step of the hand-written kernel, where there is one.
    pub ns_per_step_hand: Option<f64>,
    /// Operations per tick at `substeps_tol`.
    pub ops_per_tick: Option<Ops>,
    /// ns per tick at `substeps_tol`.
    pub ns_per_tick: Option<f64>,
    /// Phase drift over the duration at `substeps_tol`, radians.
    pub phase_drift: Option<f64>,
    /// Relative amplitude drift over the duration at `substeps_tol`.
    pub amplitude_drift: Option<f64>,
}

/// The single-spring advisor's answer.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct SpringAdvice {
    /// The spring as given.
    pub scene: SpringScene,
    /// Φ per tick.
    pub phi: f64,
    /// The duration in periods.
    pub periods: f64,
    /// One entry per method.
    pub methods: Vec<MethodAdvice>,
    /// The cheapest method meeting the tolerance, by `rank`.
    pub cheapest: Option<String>,
    /// What `cheapest` is ranked by.
    pub rank: Rank,
}

/// Advises on `scene` among `candidates`, with each candidate's measured
/// ns per step from `ns_per_step`; the cheapest is chosen `by` exact
/// operations per tick or by the ns measured.
pub(crate) fn advise_spring(
    scene: &SpringScene,
    candidates: &[Candidate],
    by: Rank,
    mut ns_per_step: impl FnMut(&Candidate) -> f64,
) -> Result<SpringAdvice, Error> {
    scene.validate()?;
    let phi = scene.phi();
    let (spring, target) = (scene.spring(), scene.target());
    let mut methods = Vec::with_capacity(candidates.len());
    for c in candidates {
        let ns = ns_per_step(c);
        let admissible = c
            .limit
            .search_cap()
            .and_then(|cap| c.model.largest_admissible_phi(spring, &target, cap));
        let substeps_tol = admissible.and_then(|a| {
            let guess = (phi / a).ceil();
            if guess.is_nan() || guess >= MAX_SUBSTEPS as f64 {
                return None;
            }
            let mut k = (guess as u64).max(1);
            // Float rounding in Φ/k: step up until the substep is admissible.
            while !(phi / k as f64 <= a && c.limit.is_below(phi / k as f64)) {
                k += 1;
                if k > MAX_SUBSTEPS {
                    return None;
                }
            }
            Some(k)
        });
        let at = substeps_tol.map(|k| c.model.accuracy(phi / k as f64, spring));
        let per_step = c.cost.program;
        methods.push(MethodAdvice {
            method: c.display.clone(),
            phi_max: limit_text(c),
            stable_at_phi: c.limit.is_below(phi),
            substeps_stable: c.limit.substeps_for(phi),
            substeps_tol,
            ops_per_step: per_step.into(),
            ns_per_step: ns,
            ns_per_step_hand: None,
            ops_per_tick: substeps_tol.map(|k| Ops {
                mul: k * u64::from(per_step.mul),
                add: k * u64::from(per_step.add),
                copy: k * u64::from(per_step.copy),
            }),
            ns_per_tick: substeps_tol.map(|k| k as f64 * ns),
            phase_drift: at.map(|a| a.phase_drift(target.periods)),
            amplitude_drift: at.map(|a| a.amplitude_drift(target.periods)),
        });
    }
    let cheapest = methods
        .iter()
        .filter_map(|m| {
            let ns = m.ns_per_tick?;
            Some(((m.ops_per_tick.map_or(0, |o| o.mul + o.add), ns, m.method.as_str()), m))
        })
        .min_by(|a, b| by.cmp(a.0, b.0))
        .map(|(_, m)| m.method.clone());
    Ok(SpringAdvice { scene: *scene, phi, periods: scene.periods(), methods, cheapest, rank: by })
}
