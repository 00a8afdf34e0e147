//! The full step of a whole system (`vector`), used under non-proportional
//! damping where the modes are coupled: the kernel a candidate is judged
//! by, its eigenvalues matched to the continuous system's e^{λT} and their
//! phase and amplitude errors, and its numeric stability (ρ by nalgebra
//! and faer) with the fewest stable substeps.

use nalgebra::DMatrix;
use num_complex::Complex64 as C64;

use super::accuracy::{in_band, Errors};
use super::analysed::{smallest_meeting, Analysed};
use crate::scene::modal::{continuous_eigenvalues, DampingKind, Modal, System};
use crate::scene::vector::{self, Kernel, Sweep};

/// Largest system for the dense full-step analysis (2n × 2n eigenvalues).
pub(super) const MAX_FULL_DOF: usize = 400;

/// The eigenvalues λ of the continuous system whose |λ| lies in the band:
/// those the targets apply to.
pub(super) fn band_eigenvalues(full_sys: &System, band: Option<f64>) -> Vec<C64> {
    continuous_eigenvalues(full_sys).into_iter().filter(|l| in_band(band, l.norm())).collect()
}

/// The full-step kernel a candidate is judged by: its system kernel, under
/// non-proportional damping, for a scene small enough.
pub(super) fn full_kernel(a: &Analysed, modal: &Modal, full_sys: &System) -> Option<Kernel> {
    match a.spec.system_kernel() {
        Some(k)
            if modal.damping == DampingKind::NonProportional && full_sys.n() <= MAX_FULL_DOF =>
        {
            Some(k)
        }
        _ => None,
    }
}

/// For each λ, the eigenvalue μ of the full step nearest e^{λT}.
pub(super) fn matched(p: &DMatrix<f64>, lambdas: &[C64], t: f64) -> Option<Vec<C64>> {
    let mu = check::witness::eigenvalues_faer(p).ok()?;
    Some(
        lambdas
            .iter()
            .map(|l| {
                let e = (l * t).exp();
                *mu.iter()
                    .min_by(|x, y| (*x - e).norm().total_cmp(&(*y - e).norm()))
                    .expect("eigenvalues")
            })
            .collect(),
    )
}

/// Phase and amplitude errors over `duration` of the full step at `n`
/// substeps: per λ, N·|arg μ − Im λ·T| and |e^{N(ln|μ| − Re λ·T)} − 1|.
pub(super) fn full_errors(
    kernel: Kernel,
    sys: &System,
    lambdas: &[C64],
    tick: f64,
    n: u64,
    duration: f64,
) -> Option<Errors> {
    let t = 1.0 / (tick * n as f64);
    let steps = (duration * tick).round().max(1.0) * n as f64;
    let mu = matched(&vector::step_matrix(kernel, Sweep::Vector, sys, t), lambdas, t)?;
    Some(drifts(lambdas, &mu, t, steps))
}

pub(super) fn drifts(lambdas: &[C64], mu: &[C64], t: f64, steps: f64) -> Errors {
    let mut e = Errors { phase_rad: 0.0, amplitude: 0.0 };
    for (l, m) in lambdas.iter().zip(mu) {
        if l.im > 0.0 {
            e.phase_rad = e.phase_rad.max(steps * (m.arg() - l.im * t).abs());
        }
        e.amplitude = e.amplitude.max((steps * (m.norm().ln() - l.re * t)).exp_m1().abs());
    }
    e
}

/// ρ of a full-step matrix by nalgebra and by faer.
pub(super) fn radii(p: &DMatrix<f64>) -> Option<(f64, f64)> {
    let rad = |v: Vec<num_complex::Complex<f64>>| v.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let a = check::witness::eigenvalues_nalgebra(p).ok()?;
    let b = check::witness::eigenvalues_faer(p).ok()?;
    Some((rad(a), rad(b)))
}

/// Numeric tolerance on ρ of a full step: eigenvalues on the unit circle
/// come out within a few hundred ulps of it for these small, well
/// conditioned matrices.
const FULL_RHO_TOL: f64 = 1e-12;

/// The largest substep count a full-step search reports: beyond it a
/// growth of ρ − 1 below [`FULL_RHO_TOL`] cannot be told from none (the
/// exact analysis says "never" for Standard Euler; the numeric one would
/// find a step with ρ − 1 < 1e-12).
const MAX_FULL_SUBSTEPS: u64 = 1 << 16;

/// Numeric stability of a full step: ρ ≤ 1 + [`FULL_RHO_TOL`] by both witnesses.
pub(super) fn full_ok(kernel: Kernel, sweep: Sweep, sys: &System, t: f64) -> bool {
    radii(&vector::step_matrix(kernel, sweep, sys, t))
        .is_some_and(|(a, b)| a <= 1.0 + FULL_RHO_TOL && b <= 1.0 + FULL_RHO_TOL)
}

/// The smallest n with a stable full step at T = 1/(tick·n), searched from
/// a guess (assumes stability monotone in n).
pub(super) fn full_stable(
    kernel: Kernel,
    sweep: Sweep,
    sys: &System,
    tick: f64,
    guess: u64,
) -> Option<u64> {
    let ok = |n: u64| full_ok(kernel, sweep, sys, 1.0 / (tick * n as f64));
    if ok(guess) {
        let (mut lo, mut hi) = (0u64, guess);
        // Shrink: find the smallest ok n in [1, guess].
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if mid >= 1 && ok(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return Some(hi);
    }
    smallest_meeting(ok, guess).filter(|&n| n <= MAX_FULL_SUBSTEPS)
}
