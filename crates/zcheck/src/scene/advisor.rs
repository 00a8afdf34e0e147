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

use std::collections::HashMap;
use std::time::Duration;

use check::numeric::{f64_to_decimal_q, f64_to_q, Params, ParamsF64, Step};
use nalgebra::DMatrix;
use num_complex::Complex64 as C64;
use poly::advanced::region::{PhiLimit, Region};
use poly::{Poly, Sym};
use serde::Serialize;

use super::file::SceneFile;
use super::modal::{continuous_eigenvalues, DampingKind, Modal, Mode, Sparse, System};
use super::vector::{self, Kernel, Sweep, VState};
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::tradeoff::accuracy::{Accuracy, Spring, Target};
use crate::tradeoff::kernels;
use crate::tradeoff::Rank;

/// Agreement of predicted and simulated drifts: within this fraction of the
/// target (phase in radians, amplitude relative), plus 1e-9 absolute.
pub(crate) const AGREE_FRACTION: f64 = 1e-3;

/// Largest number of substeps searched.
const MAX_SUBSTEPS: u64 = 1 << 24;

/// Largest system for the dense full-step analysis (2n × 2n eigenvalues).
pub(crate) const MAX_FULL_DOF: usize = 400;

/// Predicted or simulated errors over the duration (largest over modes).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub(crate) struct Errors {
    /// Phase error, radians.
    pub phase_rad: f64,
    /// Relative amplitude error.
    pub amplitude: f64,
}

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

/// A polynomial in (Φ, D) with f64 coefficients.
#[derive(Clone, Debug)]
struct BiPoly(Vec<(f64, i32, i32)>);

impl BiPoly {
    fn new(p: &Poly, d: Sym) -> BiPoly {
        BiPoly(
            p.terms()
                .map(|(m, c)| {
                    (
                        check::numeric::q_to_f64(c),
                        m.exponent(Sym::phi()) as i32,
                        m.exponent(d) as i32,
                    )
                })
                .collect(),
        )
    }

    fn eval(&self, phi: f64, d: f64) -> f64 {
        self.0.iter().map(|&(c, i, j)| c * phi.powi(i) * d.powi(j)).sum()
    }
}

/// Everything per candidate that does not depend on the mode.
struct Analysed {
    spec: LoadedMethod,
    region: Region,
    /// χ's coefficients in z (lowest first), in (Φ, D).
    coeffs: Vec<BiPoly>,
    /// p, q − 1 and q − p² when χ is monic of degree 2.
    second: Option<[BiPoly; 3]>,
    exact_limits: HashMap<u64, PhiLimit>,
    /// χ with D substituted and its exact stable intervals (None when the
    /// analysis failed), by the bits of D.
    at_param: std::cell::RefCell<HashMap<u64, AtParam>>,
}

/// χ(·, D) at one D, and its exact stable Φ-intervals when analysed.
type AtParam = (Poly, Option<Vec<poly::advanced::stability::StableInterval>>);

/// How far the f64 spectral radius must clear 1 for the float to decide
/// membership of the stable region (see [`Analysed::inside`]).
const FLOAT_MARGIN: f64 = 1e-6;

impl Analysed {
    fn new(spec: LoadedMethod) -> Result<Analysed, Error> {
        let d = Sym::new("D");
        if let Some(extra) =
            spec.method().params().iter().find(|s| s.name() != "Phi" && s.name() != "D")
        {
            return Err(Error::unsupported(format!(
                "method {}: parameter {extra} has no value in a scene: expected only Phi and D",
                spec.display()
            )));
        }
        let chi = &spec.derivation()?.charpoly();
        let region = spec
            .derivation()?
            .region(d)
            .map_err(|e| Error::from(e).context(format!("method {}", spec.display())))?;
        let zc = chi.coeffs_in(Sym::z());
        let coeffs = zc.iter().map(|c| BiPoly::new(c, d)).collect();
        let second = (zc.len() == 3 && zc[2].is_one()).then(|| {
            let p = &zc[1] * &Poly::constant(poly::q(-1, 2));
            let q = zc[0].clone();
            let disc = &q - &(&p * &p);
            [BiPoly::new(&p, d), BiPoly::new(&(&q - &Poly::one()), d), BiPoly::new(&disc, d)]
        });
        Ok(Analysed {
            spec,
            region,
            coeffs,
            second,
            exact_limits: HashMap::new(),
            at_param: Default::default(),
        })
    }

    /// Spectral radius of χ at (Φ, D) in f64.
    fn rho(&self, phi: f64, d: f64) -> f64 {
        let c: Vec<f64> = self.coeffs.iter().map(|p| p.eval(phi, d)).collect();
        if c.len() == 3 {
            let (a, b, cc) = (c[2], c[1], c[0]);
            let disc = b * b - 4.0 * a * cc;
            if disc < 0.0 {
                return (cc / a).abs().sqrt();
            }
            let s = disc.sqrt();
            let r1 = (-b - b.signum() * s) / (2.0 * a);
            let r2 = if r1 != 0.0 { cc / (a * r1) } else { 0.0 };
            return r1.abs().max(r2.abs());
        }
        match check::witness::polynomial_roots(&c) {
            Ok(r) => r.iter().map(|z| z.norm()).fold(0.0, f64::max),
            Err(_) => f64::INFINITY,
        }
    }

    /// Is (Φ, D) inside the stable region? Decided by the f64 spectral
    /// radius only where it clears 1 by [`FLOAT_MARGIN`] (10⁹ times the
    /// rounding error of a simple root, 10² times that of a double one);
    /// otherwise exactly, against the stable intervals of χ(·, D), computed
    /// once per D (a scene's undamped modes share one analysis), or by the
    /// exact class at Φ when that analysis fails.
    fn inside(&self, phi: f64, d: f64) -> bool {
        let rho = self.rho(phi, d);
        if rho < 1.0 - FLOAT_MARGIN {
            return true;
        }
        if rho > 1.0 + FLOAT_MARGIN && rho.is_finite() {
            return false;
        }
        self.inside_exact(phi, d)
    }

    /// Exact membership of (Φ, D), with no float deciding. D is read as
    /// the decimal it prints as (a typed `--damping 0.1` or `ratio = 0.1`
    /// is 1/10, as everywhere else); Φ, a computed ωT/n, as its exact
    /// binary value.
    fn inside_exact(&self, phi: f64, d: f64) -> bool {
        let (Some(p), Some(dq)) = (f64_to_q(phi), f64_to_decimal_q(d)) else { return false };
        let mut cache = self.at_param.borrow_mut();
        let (_, intervals) = cache.entry(d.to_bits()).or_insert_with(|| {
            let chi = self.region.at_param(&dq);
            let intervals = self.region.stability_at(&dq).ok().map(|r| r.stable_intervals);
            (chi, intervals)
        });
        match intervals {
            Some(intervals) => intervals.iter().any(|iv| {
                let above_lo = match iv.lo.cmp_rational(&p) {
                    std::cmp::Ordering::Less => true,
                    std::cmp::Ordering::Equal => iv.lo_closed,
                    std::cmp::Ordering::Greater => false,
                };
                let below_hi = match &iv.hi {
                    None => true,
                    Some(hi) => match hi.cmp_rational(&p) {
                        std::cmp::Ordering::Greater => true,
                        std::cmp::Ordering::Equal => iv.hi_closed,
                        std::cmp::Ordering::Less => false,
                    },
                };
                above_lo && below_hi
            }),
            None => self.region.contains(&p, &dq).unwrap_or(false),
        }
    }

    /// The exact Φ_max at ζ (cached by the bits of ζ).
    fn limit(&mut self, d: f64) -> Option<PhiLimit> {
        if let Some(l) = self.exact_limits.get(&d.to_bits()) {
            return Some(l.clone());
        }
        let l = self.region.phi_max(&f64_to_decimal_q(d)?).ok()?;
        self.exact_limits.insert(d.to_bits(), l.clone());
        Some(l)
    }

    /// A float estimate of the smallest stable n for a mode with per-tick
    /// step `phi1` (None: runs away).
    fn estimate_stable(&self, phi1: f64, d: f64) -> Option<u64> {
        let ok = |phi: f64| self.rho(phi, d) <= 1.0 + 1e-12;
        if ok(phi1) {
            return Some(1);
        }
        let mut lo = phi1 / MAX_SUBSTEPS as f64;
        if !ok(lo) {
            return None;
        }
        let mut hi = phi1;
        for _ in 0..60 {
            let mid = (lo * hi).sqrt();
            if ok(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(((phi1 / lo).ceil() as u64).max(1))
    }

    /// The exact smallest n (given the interval assumption) starting from a
    /// guess: up while outside, down while n − 1 is inside.
    fn exact_stable(&self, phi1: f64, d: f64, guess: u64) -> Option<u64> {
        let mut n = guess.max(1);
        let mut tries = 0;
        while !self.inside(phi1 / n as f64, d) {
            n = if tries < 16 { n + 1 } else { n * 2 };
            tries += 1;
            if n > MAX_SUBSTEPS {
                return None;
            }
        }
        while n > 1 && self.inside(phi1 / (n - 1) as f64, d) {
            n -= 1;
        }
        Some(n)
    }

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

    fn meets(&self, mode: &Mode, tick: f64, n: u64, target: &Target) -> bool {
        if mode.ratio >= 1.0 {
            return true;
        }
        let t = Target { periods: mode.hz() * target.periods, ..*target };
        self.accuracy(mode.omega / (tick * n as f64), mode.ratio).is_some_and(|a| a.meets(&t))
    }
}

/// The scene's step per tick and duration, and the target (periods is the
/// duration in seconds here; each mode multiplies by its own frequency).
fn target_of(scene: &SceneFile) -> Target {
    Target { phase_tol: scene.phase_rad, amp_tol: scene.amplitude, periods: scene.duration_s }
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
    /// within [`SIM_COST_FACTOR`] of the recommended's cost.
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

fn advise_one(
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

/// The eigenvalues λ of the continuous system whose |λ| lies in the band:
/// those the targets apply to.
fn band_eigenvalues(full_sys: &System, band: Option<f64>) -> Vec<C64> {
    continuous_eigenvalues(full_sys).into_iter().filter(|l| in_band(band, l.norm())).collect()
}

/// The full-step kernel a candidate is judged by: its system kernel, under
/// non-proportional damping, for a scene small enough.
fn full_kernel(a: &Analysed, modal: &Modal, full_sys: &System) -> Option<Kernel> {
    match a.spec.system_kernel() {
        Some(k)
            if modal.damping == DampingKind::NonProportional && full_sys.n() <= MAX_FULL_DOF =>
        {
            Some(k)
        }
        _ => None,
    }
}

/// The checking simulation of one candidate at its accurate substeps `n`:
/// the full step's (coupled modes) or the modal one's.
fn simulate_candidate(
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

/// A candidate the checking simulation left out, and its cost against the
/// recommended's (`None` when either cost is unknown).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct LeftOut {
    /// The method.
    pub method: String,
    /// Its ns per tick over the recommended's.
    pub cost_ratio: Option<f64>,
}

/// The checking simulation runs the recommended method and those within
/// this factor of its cost per tick: they are the ones a user would pick
/// instead. A method that needs 10⁵ substeps per tick is not simulated.
pub const SIM_COST_FACTOR: f64 = 4.0;

/// The smallest n ≥ `from` with `ok(n)`, by doubling then bisection
/// (assumes `ok` monotone), `None` past [`MAX_SUBSTEPS`].
fn smallest_meeting(ok: impl Fn(u64) -> bool, from: u64) -> Option<u64> {
    if ok(from) {
        return Some(from);
    }
    let mut lo = from;
    let mut hi = from.max(1) * 2;
    while !ok(hi) {
        lo = hi;
        hi *= 2;
        if hi > MAX_SUBSTEPS {
            return None;
        }
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if ok(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}

/// Whether a mode of angular frequency `omega` is held to the accuracy
/// targets: at or below `max_hz` (every mode when `None`).
fn in_band(max_hz: Option<f64>, omega: f64) -> bool {
    max_hz.is_none_or(|f| omega / (2.0 * std::f64::consts::PI) <= f)
}

/// The largest predicted drifts over the `modes` in the band (or the
/// listed ones).
fn predicted_errors(
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
fn fit_root(q: &[f64]) -> Option<(f64, f64)> {
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

/// For each λ, the eigenvalue μ of the full step nearest e^{λT}.
fn matched(p: &DMatrix<f64>, lambdas: &[C64], t: f64) -> Option<Vec<C64>> {
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
fn full_errors(
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

fn drifts(lambdas: &[C64], mu: &[C64], t: f64, steps: f64) -> Errors {
    let mut e = Errors { phase_rad: 0.0, amplitude: 0.0 };
    for (l, m) in lambdas.iter().zip(mu) {
        if l.im > 0.0 {
            e.phase_rad = e.phase_rad.max(steps * (m.arg() - l.im * t).abs());
        }
        e.amplitude = e.amplitude.max((steps * (m.norm().ln() - l.re * t)).exp_m1().abs());
    }
    e
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

/// ρ of a full-step matrix by nalgebra and by faer.
fn radii(p: &DMatrix<f64>) -> Option<(f64, f64)> {
    let rad = |v: Vec<num_complex::Complex<f64>>| v.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let a = check::witness::eigenvalues_nalgebra(p).ok()?;
    let b = check::witness::eigenvalues_faer(p).ok()?;
    Some((rad(a), rad(b)))
}

/// Numeric tolerance on ρ of a full step: eigenvalues on the unit circle
/// come out within a few hundred ulps of it for these small, well
/// conditioned matrices.
pub(crate) const FULL_RHO_TOL: f64 = 1e-12;

/// The largest substep count a full-step search reports: beyond it a
/// growth of ρ − 1 below [`FULL_RHO_TOL`] cannot be told from none (the
/// exact analysis says "never" for Standard Euler; the numeric one would
/// find a step with ρ − 1 < 1e-12).
pub(crate) const MAX_FULL_SUBSTEPS: u64 = 1 << 16;

/// Numeric stability of a full step: ρ ≤ 1 + [`FULL_RHO_TOL`] by both witnesses.
fn full_ok(kernel: Kernel, sweep: Sweep, sys: &System, t: f64) -> bool {
    radii(&vector::step_matrix(kernel, sweep, sys, t))
        .is_some_and(|(a, b)| a <= 1.0 + FULL_RHO_TOL && b <= 1.0 + FULL_RHO_TOL)
}

/// The smallest n with a stable full step at T = 1/(tick·n), searched from
/// a guess (assumes stability monotone in n).
fn full_stable(kernel: Kernel, sweep: Sweep, sys: &System, tick: f64, guess: u64) -> Option<u64> {
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

/// The Gauss–Seidel report of one built-in.
fn sweep_report(
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The float filter of `inside` never contradicts the exact decision:
    /// every damped built-in on a grid of (Φ, D) across its boundary,
    /// including points within 10⁻⁹ of the exact limit.
    #[test]
    fn the_float_filter_agrees_with_the_exact_membership() {
        for spec in LoadedMethod::damped_builtins().unwrap() {
            let a = Analysed::new(spec).unwrap();
            for d in [0.0, 0.05, 0.3, 0.9] {
                let mut phis: Vec<f64> = (1..=40).map(|k| k as f64 * 0.1).collect();
                if let Ok(PhiLimit::Below(m)) = a.region.phi_max(&f64_to_decimal_q(d).unwrap()) {
                    let m: f64 = m.to_decimal(17).parse().unwrap();
                    phis.extend([m * (1.0 - 1e-9), m * (1.0 + 1e-9), m * 0.999, m * 1.001]);
                }
                for phi in phis {
                    assert_eq!(
                        a.inside(phi, d),
                        a.inside_exact(phi, d),
                        "{} at Phi = {phi}, D = {d}",
                        a.spec.display()
                    );
                }
            }
        }
    }
}
