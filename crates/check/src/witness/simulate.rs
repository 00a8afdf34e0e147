//! Witness 4: the long-run simulation, measured in the dominant mode.

use std::f64::consts::LN_2;

use super::eigen::C64;
use crate::numeric::Step;

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
    /// The caller's `progress` stopped the run before `n_steps`.
    pub stopped: bool,
}

/// Runs `step` for `n_steps` steps from a start with a large component in
/// the mode of `mode`, measuring with the left eigenvector `left` (see the
/// module docs). `progress` receives the number of steps done, now and then,
/// and returns `false` to stop the run there (a Ctrl-C): the simulation then
/// covers the steps done and says it was stopped.
pub fn simulate(
    step: &Step,
    mode: C64,
    left: &[C64],
    n_steps: u64,
    progress: &mut dyn FnMut(u64) -> bool,
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
    let mut stopped = false;
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
        if k % 65536 == 0 && !progress(k) {
            stopped = true;
            break;
        }
    }
    if !stopped {
        progress(done);
    }
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
        stopped,
    }
}
