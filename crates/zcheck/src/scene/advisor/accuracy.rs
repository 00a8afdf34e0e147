//! The accuracy model of a mode: predicted phase and amplitude errors from
//! the exact χ's principal root against the exact e^{(−ζ ± j√(1−ζ²))Φ}
//! (`tradeoff::accuracy`), whether a mode meets the target at n substeps,
//! which modes the targets apply to (`max_hz`), and the largest predicted
//! drifts over the modes ([`Errors`]).

use serde::Serialize;

use super::analysed::Analysed;
use crate::scene::modal::Mode;
use crate::tradeoff::accuracy::{Accuracy, Spring, Target};

/// Predicted or simulated errors over the duration (largest over modes).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub(crate) struct Errors {
    /// Phase error, radians.
    pub phase_rad: f64,
    /// Relative amplitude error.
    pub amplitude: f64,
}

impl Analysed {
    /// The accuracy of one mode at substep Φ.
    fn accuracy(&self, phi: f64, d: f64) -> Option<Accuracy> {
        let [p, qm1, disc] = self.second.as_ref()?;
        let (pv, dv) = (p.eval(phi, d), disc.eval(phi, d));
        let (psi, ln_r, oscillating) = if dv > 0.0 {
            (dv.sqrt().atan2(pv), 0.5 * qm1.eval(phi, d).ln_1p(), true)
        } else {
            let s = (-dv).sqrt();
            let big = if pv >= 0.0 { pv + s } else { pv - s };
            (if big >= 0.0 { 0.0 } else { std::f64::consts::PI }, big.abs().ln(), false)
        };
        let spring = Spring { damping: d };
        Some(Accuracy {
            phi,
            oscillating,
            psi,
            phase_error_per_step: psi - spring.psi_exact(phi),
            ln_growth_per_step: ln_r - spring.ln_r_exact(phi),
        })
    }

    pub(super) fn meets(&self, mode: &Mode, tick: f64, n: u64, target: &Target) -> bool {
        if mode.ratio >= 1.0 {
            return true;
        }
        let t = Target { periods: mode.hz() * target.periods, ..*target };
        self.accuracy(mode.omega / (tick * n as f64), mode.ratio).is_some_and(|a| a.meets(&t))
    }
}

/// Whether a mode of angular frequency `omega` is held to the accuracy
/// targets: at or below `max_hz` (every mode when `None`).
pub(super) fn in_band(max_hz: Option<f64>, omega: f64) -> bool {
    max_hz.is_none_or(|f| omega / (2.0 * std::f64::consts::PI) <= f)
}

/// The largest predicted drifts over the `modes` in the band (or the
/// listed ones).
pub(super) fn predicted_errors(
    a: &Analysed,
    modes: &[Mode],
    tick: f64,
    n: u64,
    target: &Target,
    band: Option<f64>,
    only: Option<&[usize]>,
) -> Errors {
    let mut e = Errors { phase_rad: 0.0, amplitude: 0.0 };
    for (i, m) in modes.iter().enumerate() {
        if only.is_some_and(|o| !o.contains(&i)) || m.ratio >= 1.0 || !in_band(band, m.omega) {
            continue;
        }
        if let Some(acc) = a.accuracy(m.omega / (tick * n as f64), m.ratio) {
            let periods = m.hz() * target.periods;
            e.phase_rad = e.phase_rad.max(acc.phase_drift(periods));
            e.amplitude = e.amplitude.max(acc.amplitude_drift(periods));
        }
    }
    e
}
