//! Round-off drift of a conserved quadratic form over long runs.
//!
//! A method with |z| = 1 at Φ conserves a positive definite quadratic form
//! xᵀQx exactly ([`poly::advanced::invariant`]); in floating point each step rounds,
//! and the form drifts. This module measures that drift and the model it is
//! judged against:
//!
//! * **The form.** Q is solved exactly from the step as it runs: the
//!   kernel's operations in rational arithmetic with its coefficients as
//!   rounded to `f64` or `f32` ([`Kernel::exact_transition`]). So the drift
//!   measured is the rounding of the arithmetic alone; the rounding of the
//!   coefficients changes which ellipse the state keeps to, not whether it
//!   keeps to one.
//! * **The drift.** For each of many independent starts, δ_N = Q(x_N)/Q(x_0) − 1,
//!   evaluated exactly (states are converted to rationals without error).
//!   The spread over starts gives the RMS drift.
//! * **The model.** One step of rounding changes Q by a relative amount with
//!   standard deviation s, measured exactly on [`ONE_STEP_SAMPLES`]
//!   consecutive steps of one orbit. Independent errors would make the
//!   drift a random walk, RMS √N·s. Rounding along an orbit is not always
//!   unbiased: the orbit revisits the same states, so a per-step bias b
//!   (far below what the one-step sample can resolve) adds up linearly,
//!   N·b. The model is RMS(N) = √(N·s² + N²·b²), with s predicted from one
//!   step and b the excess of the final RMS over the random walk (zero when
//!   there is none); every earlier checkpoint then tests the model's shape,
//!   and the slope of log RMS against log N (½ for a random walk, 1 for a
//!   linear drift) says which term dominates.

use num_traits::ToPrimitive;
use poly::Q;

use crate::kernel::{Kernel, Real};

/// Steps of one orbit measured for the one-step model.
pub const ONE_STEP_SAMPLES: usize = 20_000;

/// Steps per chunk between two progress reports.
pub const CHUNK: u64 = 1 << 22;

/// A relative quantity in units of the precision's machine epsilon.
fn in_eps<T: Real>(x: f64) -> f64 {
    x / T::EPSILON
}

/// The exact value of a finite float.
fn exact<T: Real>(x: T) -> Q {
    Q::from_float(x.to_f64()).expect("finite state")
}

fn form_of<T: Real>(form: &[Vec<Q>], x: &[T]) -> Q {
    let xq: Vec<Q> = x.iter().map(|&v| exact(v)).collect();
    poly::advanced::invariant::form_value(form, &xq)
}

/// Q(x)/Q(x0) − 1, exactly, rounded once to `f64`.
fn rel_change(q: &Q, q0: &Q) -> f64 {
    ((q - q0) / q0).to_f64().unwrap_or(f64::NAN)
}

/// The one-step round-off of Q: mean and standard deviation of the
/// relative change per step, in units of ε.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OneStep {
    /// Mean relative change per step, in ε.
    pub mean_eps: f64,
    /// Standard deviation of the relative change per step, in ε.
    pub std_eps: f64,
    /// Steps measured.
    pub samples: usize,
}

impl OneStep {
    /// The standard error of `mean_eps`.
    pub fn mean_se_eps(&self) -> f64 {
        self.std_eps / (self.samples as f64).sqrt()
    }
}

/// Drift statistics over the starts after `steps` steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checkpoint {
    /// Steps taken.
    pub steps: u64,
    /// RMS over the starts of δ = Q(x_N)/Q(x_0) − 1, in ε.
    pub rms_eps: f64,
    /// Mean of δ, in ε.
    pub mean_eps: f64,
    /// Largest |δ|, in ε.
    pub max_abs_eps: f64,
    /// The model's RMS at this N, in ε (set by [`Run::fit_model`]).
    pub predicted_rms_eps: f64,
}

/// A prepared drift study: the kernel, its exact form and the starts.
#[derive(Clone, Debug)]
pub struct Study<T> {
    kernel: Kernel<T>,
    /// The native step that runs the lanes instead (feature `jit`).
    #[cfg(feature = "jit")]
    native: Option<std::sync::Arc<crate::jit::Jit<T>>>,
    form: Vec<Vec<Q>>,
    starts: Vec<Vec<T>>,
    q0: Vec<Q>,
}

/// Why no drift study is possible.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NoStudy {
    /// The step conserves no quadratic form, or more than one.
    Form(poly::advanced::invariant::NoForm),
    /// The conserved form is indefinite: the roots are real (off |z| = 1).
    Indefinite,
}

impl<T: Real> Study<T> {
    /// Prepares a study of `kernel` from `lanes` independent starts.
    pub fn new(kernel: Kernel<T>, lanes: usize) -> Result<Study<T>, NoStudy> {
        let p = kernel.exact_transition();
        let form = poly::advanced::invariant::conserved_form(&p).map_err(NoStudy::Form)?;
        if !poly::advanced::invariant::is_positive_definite(&form) {
            return Err(NoStudy::Indefinite);
        }
        // Starts spread over the ellipse's directions and over binades, so
        // the starts' mantissas differ.
        Ok(Study::with_form(kernel, lanes, form))
    }

    /// A study measuring `form` instead: for a step whose rounded
    /// coefficients conserve no form (Damped Euler: its det P = 1 − Φ² + Φ²
    /// no longer cancels exactly), the form at the exact Φ, whose drift then
    /// includes the coefficients' rounding.
    #[track_caller]
    pub fn with_form(kernel: Kernel<T>, lanes: usize, form: Vec<Vec<Q>>) -> Study<T> {
        assert_eq!(form.len(), kernel.order(), "one row per slot");
        let mut s = Study::new_unchecked(kernel, lanes, form);
        s.q0 = s.starts.iter().map(|x| form_of(&s.form, x)).collect();
        s
    }

    fn new_unchecked(kernel: Kernel<T>, lanes: usize, form: Vec<Vec<Q>>) -> Study<T> {
        let n = kernel.order();
        let starts: Vec<Vec<T>> = (0..lanes)
            .map(|l| {
                (0..n)
                    .map(|s| {
                        let x = (1.0 + l as f64 * 0.618_033_988_749_895 + s as f64 * 2.1).sin();
                        T::from_f64(x * (1.0 + (l % 7) as f64 / 7.0))
                    })
                    .collect()
            })
            .collect();
        Study {
            kernel,
            form,
            starts,
            q0: Vec::new(),
            #[cfg(feature = "jit")]
            native: None,
        }
    }

    /// Runs the lanes with the native step compiled from `step`, the step
    /// the kernel was made from (feature `jit`): bit for bit the kernel's
    /// operations, so the results are the same, only sooner.
    #[cfg(feature = "jit")]
    #[track_caller]
    pub fn with_native(mut self, step: &crate::numeric::Step) -> Result<Study<T>, crate::Error> {
        assert_eq!(step.order(), self.kernel.order(), "the kernel's own step");
        self.native = Some(std::sync::Arc::new(crate::jit::Jit::compile(step)?));
        Ok(self)
    }

    /// The exact conserved form of the step as it runs.
    pub fn form(&self) -> &[Vec<Q>] {
        &self.form
    }

    /// The number of independent starts.
    pub fn lanes(&self) -> usize {
        self.starts.len()
    }

    /// The one-step model, measured exactly on [`ONE_STEP_SAMPLES`]
    /// consecutive steps of the first start's orbit.
    pub fn one_step(&self) -> OneStep {
        let mut state = self.kernel.state(&self.starts[0]);
        let mut prev = form_of(&self.form, state.slots());
        let (mut sum, mut sum2) = (0.0, 0.0);
        for _ in 0..ONE_STEP_SAMPLES {
            self.kernel.advance(&mut state, 1);
            let q = form_of(&self.form, state.slots());
            let d = in_eps::<T>(rel_change(&q, &prev));
            sum += d;
            sum2 += d * d;
            prev = q;
        }
        let m = ONE_STEP_SAMPLES as f64;
        let mean = sum / m;
        OneStep {
            mean_eps: mean,
            std_eps: (sum2 / m - mean * mean).max(0.0).sqrt(),
            samples: ONE_STEP_SAMPLES,
        }
    }

    /// The drift statistics of struct-of-arrays states `data` after `steps`.
    fn checkpoint(&self, data: &[T], steps: u64) -> Checkpoint {
        let lanes = self.lanes();
        let n = self.kernel.order();
        let mut rel = Vec::with_capacity(lanes);
        for l in 0..lanes {
            let x: Vec<T> = (0..n).map(|s| data[s * lanes + l]).collect();
            rel.push(in_eps::<T>(rel_change(&form_of(&self.form, &x), &self.q0[l])));
        }
        let m = lanes as f64;
        Checkpoint {
            steps,
            rms_eps: (rel.iter().map(|d| d * d).sum::<f64>() / m).sqrt(),
            mean_eps: rel.iter().sum::<f64>() / m,
            max_abs_eps: rel.iter().fold(0.0, |a: f64, d| a.max(d.abs())),
            predicted_rms_eps: f64::NAN,
        }
    }

    /// Runs `n_steps` steps of every start on `threads` threads, with a
    /// checkpoint at 1, 2, 5, 10, 20, ... steps and at `n_steps`.
    /// `progress(steps_done)` is called after every chunk; when it returns
    /// `false` the run stops there and the result is partial.
    pub fn run(&self, n_steps: u64, threads: usize, mut progress: impl FnMut(u64) -> bool) -> Run {
        let lanes = self.lanes();
        let n = self.kernel.order();
        let threads = threads.clamp(1, lanes.max(1));
        // One struct-of-arrays block of lanes per thread.
        let per = lanes.div_ceil(threads);
        let groups: Vec<std::ops::Range<usize>> = (0..threads)
            .map(|t| t * per..((t + 1) * per).min(lanes))
            .filter(|r| !r.is_empty())
            .collect();
        let mut blocks: Vec<Vec<T>> = groups
            .iter()
            .map(|r| {
                let w = r.len();
                let mut d = vec![T::default(); w * n];
                for (i, l) in r.clone().enumerate() {
                    for s in 0..n {
                        d[s * w + i] = self.starts[l][s];
                    }
                }
                d
            })
            .collect();
        let gather = |blocks: &[Vec<T>]| -> Vec<T> {
            let mut data = vec![T::default(); lanes * n];
            for (r, d) in groups.iter().zip(blocks) {
                let w = r.len();
                for (i, l) in r.clone().enumerate() {
                    for s in 0..n {
                        data[s * lanes + l] = d[s * w + i];
                    }
                }
            }
            data
        };
        let mut checkpoints = Vec::new();
        let mut done = 0u64;
        let start = std::time::Instant::now();
        let mut interrupted = false;
        'outer: for target in checkpoint_steps(n_steps) {
            while done < target {
                let k = (target - done).min(CHUNK);
                std::thread::scope(|scope| {
                    for (d, r) in blocks.iter_mut().zip(&groups) {
                        let kernel = &self.kernel;
                        #[cfg(feature = "jit")]
                        let native = self.native.as_deref();
                        let w = r.len();
                        scope.spawn(move || {
                            #[cfg(feature = "jit")]
                            if let Some(native) = native {
                                return native.advance_lanes(d, w, k);
                            }
                            kernel.advance_lanes(d, w, k)
                        });
                    }
                });
                done += k;
                if !progress(done) {
                    interrupted = true;
                    break 'outer;
                }
            }
            checkpoints.push(self.checkpoint(&gather(&blocks), done));
        }
        if interrupted && checkpoints.last().is_none_or(|c| c.steps != done) {
            checkpoints.push(self.checkpoint(&gather(&blocks), done));
        }
        Run {
            checkpoints,
            steps_done: done,
            interrupted,
            seconds: start.elapsed().as_secs_f64(),
            bias_eps: f64::NAN,
        }
    }
}

/// 1, 2, 5, 10, 20, 50, ... below `n`, then `n` itself.
pub fn checkpoint_steps(n: u64) -> Vec<u64> {
    let mut out = Vec::new();
    let mut decade = 1u64;
    'outer: loop {
        for m in [1, 2, 5] {
            let s = decade.saturating_mul(m);
            if s >= n {
                break 'outer;
            }
            out.push(s);
        }
        decade = decade.saturating_mul(10);
    }
    out.push(n);
    out
}

/// The result of [`Study::run`].
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// The statistics at every checkpoint reached.
    pub checkpoints: Vec<Checkpoint>,
    /// Steps actually taken per start.
    pub steps_done: u64,
    /// Whether the run stopped early.
    pub interrupted: bool,
    /// Wall time of the run.
    pub seconds: f64,
    /// The per-step bias b of the model, in ε (set by [`Run::fit_model`]).
    pub bias_eps: f64,
}

impl Run {
    /// Sets the model RMS(N) = √(N·s² + N²·b²) at every checkpoint, with s
    /// from `one_step` and b from the final checkpoint's excess over the
    /// random walk.
    pub fn fit_model(&mut self, one_step: &OneStep) {
        let s = one_step.std_eps;
        let b = self.checkpoints.last().map_or(0.0, |c| {
            let n = c.steps as f64;
            ((c.rms_eps * c.rms_eps - n * s * s).max(0.0)).sqrt() / n
        });
        self.bias_eps = b;
        for c in &mut self.checkpoints {
            let n = c.steps as f64;
            c.predicted_rms_eps = (n * s * s + n * n * b * b).sqrt();
        }
    }

    /// Whether the drift is dominated by the bias at the final checkpoint.
    pub fn linear(&self) -> bool {
        self.checkpoints.last().is_some_and(|c| {
            let n = c.steps as f64;
            n * self.bias_eps > c.predicted_rms_eps / 2.0_f64.sqrt()
        })
    }

    /// The largest factor between measured and modelled RMS over the
    /// checkpoints with at least `from` steps (1 is a perfect fit).
    pub fn worst_ratio(&self, from: u64) -> Option<f64> {
        self.checkpoints
            .iter()
            .filter(|c| c.steps >= from && c.predicted_rms_eps > 0.0)
            .map(|c| {
                let r = c.rms_eps / c.predicted_rms_eps;
                r.max(1.0 / r)
            })
            .fold(None, |a: Option<f64>, r| Some(a.map_or(r, |a| a.max(r))))
    }

    /// State-steps per second.
    pub fn throughput(&self, lanes: usize) -> f64 {
        self.steps_done as f64 * lanes as f64 / self.seconds
    }

    /// The least-squares slope of log RMS against log N over the
    /// checkpoints with N ≥ `from` and a nonzero RMS (`None` with fewer
    /// than three).
    pub fn slope(&self, from: u64) -> Option<f64> {
        let pts: Vec<(f64, f64)> = self
            .checkpoints
            .iter()
            .filter(|c| c.steps >= from && c.rms_eps > 0.0)
            .map(|c| ((c.steps as f64).ln(), c.rms_eps.ln()))
            .collect();
        if pts.len() < 3 {
            return None;
        }
        let m = pts.len() as f64;
        let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + x, b + y));
        let (mx, my) = (sx / m, sy / m);
        let (mut num, mut den) = (0.0, 0.0);
        for (x, y) in &pts {
            num += (x - mx) * (y - my);
            den += (x - mx) * (x - mx);
        }
        Some(num / den)
    }
}
