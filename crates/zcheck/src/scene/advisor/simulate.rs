//! The checking simulation ([`Simulated`]): the whole scene run with the
//! method's system kernel (or, for a `.zm` file, its compiled scalar step
//! per mode) at the accurate substeps, projected on the mode shapes, each
//! modal sequence's per-step root fitted by least squares and its drifts
//! compared with the prediction; under non-proportional damping, projected
//! on the full step's left eigenvectors instead.

use check::numeric::{Params, ParamsF64, Step};
use num_complex::Complex64 as C64;
use serde::Serialize;

use super::accuracy::{in_band, predicted_errors, Errors};
use super::analysed::Analysed;
use super::full::{band_eigenvalues, drifts, full_kernel, matched};
use crate::scene::file::SceneFile;
use crate::scene::modal::{Modal, Mode, System};
use crate::scene::vector::{self, Kernel, Sweep, VState};
use crate::tradeoff::accuracy::{Spring, Target};

/// Agreement of predicted and simulated drifts: within this fraction of the
/// target (phase in radians, amplitude relative), plus 1e-9 absolute.
pub(crate) const AGREE_FRACTION: f64 = 1e-3;

/// The simulation's verdict.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Simulated {
    /// Errors measured from the simulation (modes simulated only).
    pub(crate) phase_rad: f64,
    /// Relative amplitude error measured.
    pub(crate) amplitude: f64,
    /// Whether they agree with the prediction for the same modes.
    pub(crate) agree: bool,
    /// How it was simulated.
    pub(crate) how: String,
    /// Modes projected and fitted.
    pub(crate) modes_checked: usize,
    /// Steps simulated.
    pub(crate) steps: u64,
}

/// The checking simulation of one candidate at its accurate substeps `n`:
/// the full step's (coupled modes) or the modal one's.
pub(super) fn simulate_candidate(
    a: &Analysed,
    scene: &SceneFile,
    modal: &Modal,
    system: &System,
    shapes: &[Vec<f64>],
    target: &Target,
    n: u64,
) -> Option<Simulated> {
    let full_sys = modal.full.as_ref().unwrap_or(system);
    match full_kernel(a, modal, full_sys) {
        Some(kernel) => {
            let lambdas = band_eigenvalues(full_sys, scene.max_hz);
            simulate_full(kernel, full_sys, &lambdas, scene.tick_hz, n, scene.duration_s, target)
        }
        None => simulate_check(a, scene, modal, system, shapes, n, target),
    }
}

/// The modes the check projects on (oscillating, in the band): all when
/// few, else the 12 whose predicted drifts are largest and the 4 lowest.
fn checked_modes(
    a: &Analysed,
    modes: &[Mode],
    tick: f64,
    n: u64,
    target: &Target,
    band: Option<f64>,
) -> Vec<usize> {
    let osc: Vec<usize> = (0..modes.len())
        .filter(|&i| modes[i].ratio < 1.0 && !modes[i].sampled && in_band(band, modes[i].omega))
        .collect();
    if osc.len() <= 16 {
        return osc;
    }
    let err = |i: usize| predicted_errors(a, modes, tick, n, target, band, Some(&[i]));
    let mut by_phase = osc.clone();
    by_phase.sort_by(|&x, &y| err(y).phase_rad.total_cmp(&err(x).phase_rad));
    let mut by_amp = osc.clone();
    by_amp.sort_by(|&x, &y| err(y).amplitude.total_cmp(&err(x).amplitude));
    let mut out: Vec<usize> =
        by_phase[..6].iter().chain(&by_amp[..6]).chain(&osc[..4]).copied().collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// Samples per mode for the fit.
const FIT_SAMPLES: usize = 200;

/// Largest simulated work, steps × degrees of freedom.
const SIM_WORK: f64 = 3e7;

/// Simulates the whole scene at `n` substeps and fits each checked mode's
/// per-step root from its projected sequence. Each mode is sampled every
/// m-th step with m·Φ ≈ 1/2, so that the fitted recurrence is well
/// conditioned however small the substep (the root of the sampled sequence
/// is z^m).
fn simulate_check(
    a: &Analysed,
    scene: &SceneFile,
    modal: &Modal,
    system: &System,
    shapes: &[Vec<f64>],
    n: u64,
    target: &Target,
) -> Option<Simulated> {
    let modes = &modal.modes;
    let tick = scene.tick_hz;
    let checked = checked_modes(a, modes, tick, n, target, scene.max_hz);
    if checked.is_empty() {
        return None;
    }
    let t = 1.0 / (tick * n as f64);
    let total_steps = (scene.duration_s * tick).round().max(1.0) as u64 * n;
    let dim = system.n();
    let stride: Vec<u64> =
        checked.iter().map(|&i| ((0.5 / (modes[i].omega * t)).round() as u64).max(1)).collect();
    let wanted = stride.iter().map(|m| m * FIT_SAMPLES as u64).max().unwrap_or(1);
    // The duration, but at least enough steps for a fit of 32 samples of
    // every checked mode (past a short duration: the fitted per-step root
    // is extrapolated to the duration either way).
    let enough = stride.iter().max().copied().unwrap_or(1).saturating_mul(32);
    let steps = wanted.min(total_steps.max(enough)).min((SIM_WORK / dim as f64) as u64).max(1);
    let mut seqs: Vec<Vec<f64>> = vec![Vec::with_capacity(FIT_SAMPLES); checked.len()];
    let how;
    match a.spec.system_kernel() {
        Some(kernel) => {
            how = "whole scene, system kernel".to_owned();
            // Start: each checked mode with unit modal amplitude, at rest.
            let mut y = vec![0.0; dim];
            for &i in &checked {
                for (yk, s) in y.iter_mut().zip(&shapes[i]) {
                    *yk += s;
                }
            }
            let w = if kernel.keeps_previous() { y.clone() } else { vec![0.0; dim] };
            let mut state = VState { y, w };
            for k in 0..=steps {
                if k % 4096 == 0 && crate::interrupt::requested() {
                    return None;
                }
                if k > 0 {
                    vector::step(kernel, Sweep::Vector, system, t, &mut state);
                }
                for (j, &i) in checked.iter().enumerate() {
                    if k % stride[j] == 0 && seqs[j].len() < FIT_SAMPLES {
                        let q = shapes[i]
                            .iter()
                            .zip(&state.y)
                            .zip(&system.mass)
                            .map(|((p, y), m)| p * m * y)
                            .sum();
                        seqs[j].push(q);
                    }
                }
            }
        }
        None => {
            // A .zm file has no system form: each checked mode runs the
            // compiled scalar step at its own (Phi, D).
            how = "per mode, compiled .zm step".to_owned();
            let m = a.spec.method();
            let y_slot = m
                .slots()
                .iter()
                .position(|&(var, lag)| m.state()[var] == "y" && lag == 0)
                .unwrap_or(0);
            let start = check::numeric::initial_slots(m, |v| if v == "y" { 1.0 } else { 0.0 });
            for (j, &i) in checked.iter().enumerate() {
                let params = Params::phi(modes[i].omega * t).with("D", modes[i].ratio);
                let step = Step::compile(m, &params).ok()?;
                let mut st = step.state(&start);
                seqs[j].push(st.slots()[y_slot]);
                while seqs[j].len() < FIT_SAMPLES && (seqs[j].len() as u64) * stride[j] <= steps {
                    if crate::interrupt::requested() {
                        return None;
                    }
                    step.advance(&mut st, stride[j]);
                    seqs[j].push(st.slots()[y_slot]);
                }
            }
        }
    }
    let mut sim = Errors { phase_rad: 0.0, amplitude: 0.0 };
    let mut agree = true;
    let mut fitted = 0;
    for ((s, &i), &m_stride) in seqs.iter().zip(&checked).zip(&stride) {
        let m = &modes[i];
        let phi = m.omega * t;
        let pred = predicted_errors(a, modes, tick, n, target, scene.max_hz, Some(&[i]));
        // Fit where the mode is still well above rounding noise.
        let psi_eff = phi * m_stride as f64;
        let window = if m.ratio > 0.0 {
            ((18.0 / (m.ratio * psi_eff)).ceil() as usize).max(16)
        } else {
            s.len()
        };
        let s = &s[..s.len().min(window)];
        if s.len() < 16 {
            continue;
        }
        let Some((psi_fit, ln_r_fit)) = fit_root(s) else {
            // Real roots: no oscillation to fit; only a prediction of no
            // oscillation agrees.
            agree &= pred.phase_rad.is_infinite();
            continue;
        };
        fitted += 1;
        let (psi, ln_r) = (psi_fit / m_stride as f64, ln_r_fit / m_stride as f64);
        let spring = Spring { damping: m.ratio };
        let phase = total_steps as f64 * (psi - spring.psi_exact(phi)).abs();
        let amp = (total_steps as f64 * (ln_r - spring.ln_r_exact(phi))).exp_m1().abs();
        agree &= close(phase, pred.phase_rad, target.phase_tol)
            && close(amp, pred.amplitude, target.amp_tol);
        sim.phase_rad = sim.phase_rad.max(phase);
        sim.amplitude = sim.amplitude.max(amp);
    }
    Some(Simulated {
        phase_rad: sim.phase_rad,
        amplitude: sim.amplitude,
        agree: agree && fitted > 0,
        how,
        modes_checked: fitted,
        steps,
    })
}

/// Whether a simulated error agrees with its prediction.
fn close(sim: f64, pred: f64, tol: f64) -> bool {
    (sim - pred).abs() <= AGREE_FRACTION * tol + 1e-9 || (sim.is_infinite() && pred.is_infinite())
}

/// (Ψ, ln r) of the sequence's two-term recurrence q_{k+1} = a q_k + b q_{k−1},
/// fitted by least squares; `None` when the sequence is too short or its
/// roots are real.
pub(crate) fn fit_root(q: &[f64]) -> Option<(f64, f64)> {
    if q.len() < 4 {
        return None;
    }
    let scale = q.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let (mut s11, mut s12, mut s22, mut r1, mut r2) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for k in 1..q.len() - 1 {
        let (x1, x2, y) = (q[k] / scale, q[k - 1] / scale, q[k + 1] / scale);
        s11 += x1 * x1;
        s12 += x1 * x2;
        s22 += x2 * x2;
        r1 += x1 * y;
        r2 += x2 * y;
    }
    let det = s11 * s22 - s12 * s12;
    if det == 0.0 {
        return None;
    }
    let a = (r1 * s22 - r2 * s12) / det;
    let b = (s11 * r2 - s12 * r1) / det;
    if b >= 0.0 || a * a + 4.0 * b >= 0.0 {
        return None;
    }
    let r = (-b).sqrt();
    Some(((a / (2.0 * r)).clamp(-1.0, 1.0).acos(), r.ln()))
}

/// The full-step check: simulate the whole scene with the kernel, project
/// the state on the full step's left eigenvectors (faer, of Pᵀ), and fit
/// each projected sequence's ratio w_{k+m}/w_k.
fn simulate_full(
    kernel: Kernel,
    sys: &System,
    lambdas: &[C64],
    tick: f64,
    n: u64,
    duration: f64,
    target: &Target,
) -> Option<Simulated> {
    let t = 1.0 / (tick * n as f64);
    let dim = sys.n();
    let p = vector::step_matrix(kernel, Sweep::Vector, sys, t);
    let pt = faer::Mat::<f64>::from_fn(2 * dim, 2 * dim, |i, j| p[(j, i)]);
    let evd = pt.eigen().ok()?;
    let (u, s) = (evd.U(), evd.S());
    let total_steps = (duration * tick).round().max(1.0) * n as f64;
    let mut mu_sim = Vec::new();
    let mut state = VState {
        y: vec![1.0; dim],
        w: if kernel.keeps_previous() { vec![1.0; dim] } else { vec![0.0; dim] },
    };
    // Per λ: the left eigenvector's column and the sampling stride.
    let mut plan = Vec::new();
    for l in lambdas {
        let e = (l * t).exp();
        let col = (0..2 * dim).min_by(|&x, &y| (s[x] - e).norm().total_cmp(&(s[y] - e).norm()))?;
        plan.push((col, ((0.5 / (l.norm() * t)).round() as u64).max(1)));
    }
    let max_stride = plan.iter().map(|p| p.1).max().unwrap_or(1);
    let steps = (total_steps as u64)
        .min(max_stride * FIT_SAMPLES as u64)
        .min((SIM_WORK / dim as f64) as u64);
    let mut seqs: Vec<Vec<C64>> = vec![Vec::with_capacity(FIT_SAMPLES); lambdas.len()];
    for k in 0..=steps {
        if k % 4096 == 0 && crate::interrupt::requested() {
            return None;
        }
        if k > 0 {
            vector::step(kernel, Sweep::Vector, sys, t, &mut state);
        }
        for (seq, &(col, stride)) in seqs.iter_mut().zip(&plan) {
            if k % stride == 0 && seq.len() < FIT_SAMPLES {
                let w: C64 = (0..dim)
                    .map(|i| u[(i, col)] * state.y[i] + u[(dim + i, col)] * state.w[i])
                    .sum();
                seq.push(w);
            }
        }
    }
    for ((l, w), &(_, stride)) in lambdas.iter().zip(&seqs).zip(&plan) {
        let (mut num, mut den) = (C64::new(0.0, 0.0), 0.0);
        let window = if l.re < 0.0 {
            ((18.0 / (-l.re * t * stride as f64)).ceil() as usize).max(16)
        } else {
            w.len()
        };
        for k in 0..w.len().min(window).saturating_sub(1) {
            num += w[k + 1] * w[k].conj();
            den += w[k].norm_sqr();
        }
        if den == 0.0 || w.len() < 16 {
            return None;
        }
        let ratio = num / den;
        mu_sim.push(C64::from_polar(
            ratio.norm().powf(1.0 / stride as f64),
            ratio.arg() / stride as f64,
        ));
    }
    let predicted = drifts(lambdas, &matched(&p, lambdas, t)?, t, total_steps);
    let sim = drifts(lambdas, &mu_sim, t, total_steps);
    Some(Simulated {
        phase_rad: sim.phase_rad,
        amplitude: sim.amplitude,
        agree: close(sim.phase_rad, predicted.phase_rad, target.phase_tol)
            && close(sim.amplitude, predicted.amplitude, target.amp_tol),
        how: "whole scene, system kernel, projected on the full step's left eigenvectors"
            .to_owned(),
        modes_checked: lambdas.len(),
        steps,
    })
}
