//! One configuration (solver, S substeps, N iterations) analysed: the
//! substep map P (f64, by applying the solver to basis vectors), the rigid
//! modes deflated before any eigenvalue is taken, the non-rigid eigenvalues
//! μ paired with the true modes, and the answers of the issue: spectral
//! radius of the tick map P^S (exact where the scene is small), stability on
//! the non-rigid modes, each mode's effective frequency and damping ratio,
//! the phase and amplitude errors over the duration, and the cost.
//!
//! Rigid modes: every motion in null(J) (J the constraint Jacobian, computed
//! exactly over Q in `exact`) is rigid, and span{(u, 0), (0, u)} for u in
//! null(J) is invariant under every solver's map (C = 0, Ċ = 0, no impulse).
//! The non-rigid map is D = Q_⊥ᵀ P Q_⊥ with Q_⊥ = blockdiag(R_⊥, R_⊥, I),
//! R_⊥ an orthonormal basis of null(J)^⊥: no eigenvalue of the rigid
//! Jordan block at 1 is ever computed, so it cannot read as 1 + 10⁻⁸. The
//! true modes are the eigenvalues λ of the continuous system
//! ẋ = v, v̇ = −M⁻¹(Kx + Cv) deflated the same way.
//!
//! Pairing (the rule stated in the output): the non-rigid eigenvalues λ
//! with Im λ ≥ 0 are assigned to distinct eigenvalues μ of D minimising the
//! total distance in log space, Σ |ln μ − λh| (principal logarithm,
//! h = 1/(tick·S)), by the Hungarian algorithm: exact for a normal map,
//! and for the Gauss–Seidel map, whose eigenvectors are not the modes, the
//! nearest consistent matching to the exponential of the true spectrum.
//!
//! At scale a Gauss–Seidel map is far from normal, so a numeric ρ ≤ 1 is
//! not a proof: the radius is `certified` only when an exact verdict or a
//! norm bound ‖T^k‖_∞^{1/k} < 1 of the deflated tick map T proves it.

use std::cmp::Ordering;

use faer::Mat;
use num_complex::Complex64 as C64;
use serde::Serialize;

use super::super::file::SceneFile;
use super::dense;
use super::exact;
use super::kernel::{self, Substep};
use super::model::{Config, Model, Solver};
use crate::error::Error;

/// Largest state (of the substep map) decided exactly over Q.
pub(crate) const EXACT_MAX_STATE: usize = 12;

/// Largest N·(constraints) decided exactly (the rationals of the map grow
/// with every projection).
pub(crate) const EXACT_MAX_WORK: u64 = 64;

/// Largest state analysed with dense eigenvalues.
pub(crate) const DENSE_MAX_STATE: usize = 2400;

/// Numeric tolerance on the non-rigid radius when no exact verdict is at
/// hand (a few hundred ulps for these well-scaled maps).
pub(crate) const RHO_TOL: f64 = 1e-12;

/// The pairing rule, as the output states it.
pub(crate) const PAIRING: &str = "each true mode (continuous eigenvalue lambda, Im >= 0, rigid modes deflated) is \
     paired with a distinct eigenvalue mu of the substep map minimising the total |ln mu - lambda*h| \
     (Hungarian assignment, h = 1/(tick*S))";

/// A scene prepared for its configurations: the constraints, the exact
/// rigid subspace and the true modes.
pub(crate) struct Prepared {
    /// The constraints.
    pub model: Model,
    /// Tick rate, Hz.
    pub tick_hz: f64,
    /// Duration, s.
    pub duration_s: f64,
    /// Phase target, rad.
    pub phase_rad: f64,
    /// Amplitude target.
    pub amplitude: f64,
    /// Targets apply at or below this frequency.
    pub max_hz: Option<f64>,
    /// r = dim null(J): rigid modes.
    pub rigid: usize,
    /// R_⊥ (`None` when r = 0).
    pub rperp: Option<Mat<f64>>,
    /// The true non-rigid eigenvalues λ, Im λ ≥ 0, increasing |λ|.
    pub lambdas: Vec<C64>,
}

impl Prepared {
    /// Prepares a scene.
    pub(crate) fn new(scene: &SceneFile) -> Result<Prepared, Error> {
        let model = Model::of_scene(scene);
        if model.m() == 0 {
            return Err(Error::unsupported(
                "no spring of the scene moves a free mass: nothing for a solver to project",
            ));
        }
        if model.state_len(Solver::Xpbd) > DENSE_MAX_STATE {
            return Err(too_large(&model, 2 * model.n()));
        }
        let n = model.n();
        let basis = exact::null_basis(&model);
        let rigid = basis.len();
        let rperp = (rigid > 0).then(|| {
            let f: Vec<Vec<f64>> =
                basis.iter().map(|v| v.iter().map(check::numeric::q_to_f64).collect()).collect();
            dense::complement(&f, n)
        });
        let (k, c) = model.stiffness_damping();
        let lambdas = if c.iter().all(|&x| x == 0.0) {
            undamped_lambdas(&k, &model.w, rigid)?
        } else {
            general_lambdas(&k, &c, &model.w, rperp.as_ref())?
        };
        Ok(Prepared {
            model,
            tick_hz: scene.tick_hz,
            duration_s: scene.duration_s,
            phase_rad: scene.phase_rad,
            amplitude: scene.amplitude,
            max_hz: scene.max_hz,
            rigid,
            rperp,
            lambdas,
        })
    }

    /// Ticks in the duration.
    pub(crate) fn ticks(&self) -> f64 {
        (self.duration_s * self.tick_hz).round().max(1.0)
    }

    /// Whether a true eigenvalue is held to the targets.
    fn in_band(&self, l: C64) -> bool {
        self.max_hz.is_none_or(|f| l.norm() / (2.0 * std::f64::consts::PI) <= f)
    }
}

/// The error of a scene past the dense route's size.
fn too_large(model: &Model, state: usize) -> Error {
    Error::unsupported(format!(
        "the scene has {} free degrees of freedom and {} constraints: the solver's state has {state} \
         entries, and the dense analysis takes at most {DENSE_MAX_STATE} (2 x DOF, plus one impulse \
         per joint for soft_step)",
        model.n(),
        model.m()
    ))
}

/// The true non-rigid eigenvalues of an undamped scene: λ = i·√μ for the
/// eigenvalues μ of the symmetric W^½ K W^½ (W the inverse masses), the
/// `rigid` smallest (zero: null K = null J) left out. An n × n symmetric
/// problem in place of the 2n × 2n general one.
pub(crate) fn undamped_lambdas(k: &[f64], w: &[f64], rigid: usize) -> Result<Vec<C64>, Error> {
    let n = w.len();
    let sw: Vec<f64> = w.iter().map(|x| x.sqrt()).collect();
    let a = Mat::<f64>::from_fn(n, n, |i, j| sw[i] * k[i * n + j] * sw[j]);
    let mut mu = a.self_adjoint_eigenvalues(faer::Side::Lower).map_err(|e| {
        Error::numeric(format!("the eigenvalues of the scene's stiffness did not converge: {e:?}"))
    })?;
    mu.sort_by(f64::total_cmp);
    Ok(mu.into_iter().skip(rigid).map(|m| C64::new(0.0, m.max(0.0).sqrt())).collect())
}

/// The true non-rigid eigenvalues with Im λ ≥ 0 of ẋ = v,
/// v̇ = −W(Kx + Cv), from the 2n × 2n first-order system deflated by
/// `rperp`, increasing |λ|.
pub(crate) fn general_lambdas(
    k: &[f64],
    c: &[f64],
    w: &[f64],
    rperp: Option<&Mat<f64>>,
) -> Result<Vec<C64>, Error> {
    let n = w.len();
    let a = Mat::<f64>::from_fn(2 * n, 2 * n, |i, j| match (i < n, j < n) {
        (true, true) => 0.0,
        (true, false) => f64::from(u8::from(j - n == i)),
        (false, true) => -k[(i - n) * n + j] * w[i - n],
        (false, false) => -c[(i - n) * n + (j - n)] * w[i - n],
    });
    let a = match rperp {
        Some(r) => dense::project(&a, &dense::block_complement(r, 0)),
        None => a,
    };
    let all = dense::eigenvalues(&a)?;
    let scale = all.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let tol = 1e-10 * scale.max(f64::MIN_POSITIVE);
    let mut lambdas: Vec<C64> = all
        .into_iter()
        .filter(|z| z.im > -tol)
        .map(|z| if z.im.abs() <= tol { C64::new(z.re, 0.0) } else { z })
        .collect();
    lambdas.sort_by(|x, y| x.norm().total_cmp(&y.norm()));
    Ok(lambdas)
}

/// The spectral radius of the tick map.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct Radius {
    /// ρ of the tick map over every free degree of freedom (1 at least when
    /// there are rigid modes).
    pub value: f64,
    /// ρ against 1, decided exactly: "< 1", "= 1" or "> 1" (absent when the
    /// scene is too large for the exact route).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exact: Option<String>,
    /// ρ of the non-rigid modes alone.
    pub non_rigid: f64,
    /// Whether ρ ≤ 1 of the non-rigid modes is proved (exactly, or by a
    /// norm bound); a numeric eigenvalue of a non-normal map is no proof.
    pub certified: bool,
    /// The norm bound ‖T^k‖_∞^{1/k} that proves it, when one does.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub norm_bound: Option<f64>,
}

/// One true mode as the solver realises it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct ModeAdvice {
    /// The true undamped frequency |λ|/2π, Hz.
    pub hz: f64,
    /// The true damping ratio −Re λ/|λ|.
    pub ratio: f64,
    /// θ/(2π)·tick_hz with θ = S·|arg μ|, Hz.
    pub effective_hz: f64,
    /// −ln r/√(ln² r + θ²), r = |μ|^S.
    pub effective_ratio: f64,
    /// Whether the targets apply to it (at or below `max_hz`).
    pub in_band: bool,
}

/// The check by simulation: the tick map's powers against the solver
/// stepped in f64.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct SimulationCheck {
    /// Ticks compared.
    pub ticks: u64,
    /// Largest ‖T^k s − step^k s‖ / ‖step^k s‖.
    pub max_relative_difference: f64,
}

/// One configuration's answer (`zcheck advise --solver S --substeps S
/// --iterations N`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct ConfigAdvice {
    /// The solver.
    pub solver: Solver,
    /// Substeps per tick.
    pub substeps: u64,
    /// Iterations per substep.
    pub iterations: u64,
    /// Jacobi's relaxation factor (`xpbd_jacobi` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub relaxation: Option<f64>,
    /// Spectral radius of the tick map.
    pub spectral_radius: Radius,
    /// ρ ≤ 1 and no growing Jordan block, on the non-rigid modes.
    pub stable: bool,
    /// How `stable` was decided: "exact" or "numeric".
    pub stable_from: &'static str,
    /// Whether the modes in the band meet the phase and amplitude targets.
    pub meets_accuracy: bool,
    /// Largest phase error over the duration, rad (modes in the band).
    pub phase_error_rad: f64,
    /// Largest relative amplitude error over the duration.
    pub amplitude_error: f64,
    /// Constraint projections per tick, S·N·(constraints).
    pub cost: u64,
    /// Exact arithmetic operations per tick: the substep kernel's count on
    /// this scene (`kernel::ops_per_substep`) times S. The same on every
    /// machine; what `--solvers` ranks families by.
    pub ops_per_tick: u64,
    /// Measured ns per tick on this machine (a full analysis only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ns_per_tick: Option<f64>,
    /// Rigid modes deflated (dim null J).
    pub rigid_modes: usize,
    /// Every non-rigid mode, increasing frequency.
    pub modes: Vec<ModeAdvice>,
    /// How eigenvalues were paired with modes.
    pub pairing: &'static str,
    /// The check by simulation (a full analysis only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub simulation: Option<SimulationCheck>,
}

/// How much of a configuration to analyse.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Depth {
    /// Stability and accuracy only (the search's screen).
    Screen,
    /// Everything: the norm certificate and the simulation check too.
    Full,
}

/// Analyses one configuration.
pub(crate) fn analyse(
    prep: &Prepared,
    config: &Config,
    depth: Depth,
) -> Result<ConfigAdvice, Error> {
    let model = &prep.model;
    let s = config.substeps;
    if model.state_len(config.solver) > DENSE_MAX_STATE {
        return Err(too_large(model, model.state_len(config.solver)));
    }
    let sub = kernel::substep_f64(model, config, prep.tick_hz);
    // In the scaled state (x, h·v, h·Σw·impulse), where every entry of the
    // map is of order one: a similarity, so the same eigenvalues, and the
    // powers and norms are computed without the cancellation of entries
    // of order kh.
    let scale = scaling(&sub);
    let raw = sub.matrix();
    let p = Mat::<f64>::from_fn(raw.len(), raw.len(), |i, j| raw[i][j] * scale[j] / scale[i]);
    let extra = sub.state_len() - 2 * model.n();
    let q = prep.rperp.as_ref().map(|r| dense::block_complement(r, extra));
    let d = match &q {
        Some(q) => dense::project(&p, q),
        None => p.clone(),
    };
    let mu = dense::eigenvalues(&d)?;
    let rho_sub = mu.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let rho_nr = rho_sub.powf(s as f64);
    // The exact verdict, when the state is small.
    let exact_work = config.iterations.saturating_mul(model.m() as u64);
    let verdict = if sub.state_len() <= EXACT_MAX_STATE && exact_work <= EXACT_MAX_WORK {
        let pq = exact::substep_q(model, config, prep.tick_hz).matrix();
        Some(exact::verdict(&pq, 2 * prep.rigid).ok_or_else(|| {
            Error::numeric(
                "disagreement: (z - 1)^(2r) does not divide the exact characteristic polynomial of the \
                 substep map, r the rigid modes of the exact null space",
            )
        })?)
    } else {
        None
    };
    let (stable, stable_from) = match verdict.as_ref().and_then(|v| v.bounded) {
        Some(b) => (b, "exact"),
        None => (rho_nr <= 1.0 + RHO_TOL, "numeric"),
    };
    let exact_str = verdict.as_ref().map(|v| {
        let whole = if prep.rigid > 0 { v.rho.max(Ordering::Equal) } else { v.rho };
        match whole {
            Ordering::Less => "< 1",
            Ordering::Equal => "= 1",
            Ordering::Greater => "> 1",
        }
        .to_owned()
    });
    // Pairing.
    let h = 1.0 / (prep.tick_hz * s as f64);
    let log = |z: C64| if z.norm() > 0.0 { z.ln() } else { C64::new(-1e3, 0.0) };
    let cost: Vec<Vec<f64>> = prep
        .lambdas
        .iter()
        .map(|l| mu.iter().map(|&m| (log(m) - l * h).norm().min(1e12)).collect())
        .collect();
    let pairs = if prep.lambdas.len() <= mu.len() {
        dense::assignment(&cost)
    } else {
        return Err(Error::numeric("more true modes than eigenvalues of the solver's map"));
    };
    let ticks = prep.ticks();
    let tick = prep.tick_hz;
    let (mut phase, mut amp) = (0.0f64, 0.0f64);
    let mut modes = Vec::with_capacity(prep.lambdas.len());
    for (l, &j) in prep.lambdas.iter().zip(&pairs) {
        let m = mu[j];
        let theta = s as f64 * m.arg().abs();
        let ln_r = s as f64 * m.norm().ln();
        let in_band = prep.in_band(*l);
        if in_band {
            if l.im > 0.0 {
                phase = phase.max(ticks * (theta - l.im / tick).abs());
            }
            amp = amp.max((ticks * (ln_r - l.re / tick)).exp_m1().abs());
        }
        let eff_ratio = if theta == 0.0 && ln_r == 0.0 {
            0.0
        } else {
            -ln_r / (ln_r * ln_r + theta * theta).sqrt()
        };
        modes.push(ModeAdvice {
            hz: l.norm() / (2.0 * std::f64::consts::PI),
            ratio: if l.norm() > 0.0 { -l.re / l.norm() } else { 0.0 },
            effective_hz: theta / (2.0 * std::f64::consts::PI) * tick,
            effective_ratio: eff_ratio,
            in_band,
        });
    }
    let meets_accuracy =
        stable && phase.is_finite() && phase <= prep.phase_rad && amp <= prep.amplitude;
    let mut certified = verdict.as_ref().is_some_and(|v| v.bounded.is_some());
    let mut norm_bound = None;
    let mut simulation = None;
    let mut ns_per_tick = None;
    if depth == Depth::Full {
        ns_per_tick = Some(kernel::ns_per_tick(&sub, s, std::time::Duration::from_millis(3)));
        // ‖T^k‖^(1/k) ≥ ρ(T): no power can bring the bound below
        // 1 − 10⁻⁹ when ρ itself is not, so the products are not tried.
        // The tick map P^S of a small state, computed once: the simulation
        // check applies it, and without rigid modes (D = P) it is the
        // certificate's T too.
        let tick_map = (p.nrows() <= TICK_MAP_MAX_STATE).then(|| dense::power(&p, s));
        if !certified && rho_nr < 1.0 - CERTIFY_MARGIN {
            let t = match (&q, &tick_map) {
                (None, Some(t)) => t.clone(),
                _ => dense::power(&d, s),
            };
            norm_bound = certify(t);
            certified = norm_bound.is_some();
        }
        let len = p.nrows() as f64;
        let affordable = (CHECK_FLOPS / (2.0 * len * len * s as f64)) as u64;
        let ticks = (prep.ticks().min(120.0) as u64).min(affordable.max(MIN_CHECK_TICKS));
        simulation = Some(simulation_check(&sub, &p, tick_map.as_ref(), &scale, s, ticks));
    }
    Ok(ConfigAdvice {
        solver: config.solver,
        substeps: s,
        iterations: config.iterations,
        relaxation: (config.solver == Solver::XpbdJacobi).then_some(config.relaxation),
        spectral_radius: Radius {
            value: if prep.rigid > 0 { rho_nr.max(1.0) } else { rho_nr },
            exact: exact_str,
            non_rigid: rho_nr,
            certified,
            norm_bound,
        },
        stable,
        stable_from,
        meets_accuracy,
        phase_error_rad: phase,
        amplitude_error: amp,
        cost: model.cost(config),
        ops_per_tick: kernel::ops_per_substep(model, config, prep.tick_hz).saturating_mul(s),
        ns_per_tick,
        rigid_modes: prep.rigid,
        modes,
        pairing: PAIRING,
        simulation,
    })
}

/// A norm bound on the deflated tick map T = D^S: the smallest
/// ‖T^{2^j}‖_∞^{1/2^j} over j ≤ 8 when it is below 1 − 10⁻⁹ (far above the
/// rounding of the products), else `None`. The squarings are capped at
/// about [`CERTIFY_FLOPS`] of work, so a large map tries fewer powers and
/// stays uncertified sooner.
fn certify(mut t: Mat<f64>) -> Option<f64> {
    let n = t.nrows().max(1) as f64;
    let squarings = ((CERTIFY_FLOPS / (2.0 * n * n * n)) as u32).min(8);
    for j in 0..=squarings {
        let b = dense::norm_inf(&t).powf(1.0 / f64::from(1u32 << j));
        if b < 1.0 - CERTIFY_MARGIN {
            return Some(b);
        }
        if j < squarings {
            t = &t * &t;
        }
    }
    None
}

/// The largest state whose tick map P^S is formed (by squaring) for the
/// simulation check and the certificate; past it the check steps the map
/// S times per tick.
const TICK_MAP_MAX_STATE: usize = 600;

/// How far below 1 a norm bound must be to certify.
const CERTIFY_MARGIN: f64 = 1e-9;

/// The work [`certify`] may spend on squarings, flops.
const CERTIFY_FLOPS: f64 = 5e8;

/// The work the simulation check may spend on products of the substep map
/// with a state, flops: a large state is compared over fewer ticks (at
/// least [`MIN_CHECK_TICKS`]).
const CHECK_FLOPS: f64 = 2e9;

/// The fewest ticks the simulation check compares.
const MIN_CHECK_TICKS: u64 = 10;

/// D with state = D·scaled state: 1 for x, 1/h for v, 1/(h·Σw) for a
/// joint's impulse.
fn scaling(sub: &Substep<f64>) -> Vec<f64> {
    let n = sub.n;
    let mut d = vec![1.0; n];
    d.extend(std::iter::repeat_n(sub.inv_h, n));
    if sub.solver == Solver::SoftStep {
        for c in &sub.cons {
            let wsum: f64 = c.grad.iter().zip(&c.wgrad).map(|((_, g), (_, wg))| g * wg).sum();
            d.push(sub.inv_h / wsum);
        }
    }
    d
}

/// The tick map's powers against stepping the solver: T = P^S (by squaring
/// when the state is small, else S products with P per tick) applied to a
/// fixed pseudo-random state, `ticks` times.
fn simulation_check(
    sub: &Substep<f64>,
    p: &Mat<f64>,
    tick_map: Option<&Mat<f64>>,
    scale: &[f64],
    s: u64,
    ticks: u64,
) -> SimulationCheck {
    let len = sub.state_len();
    let mut seed = 0x9e3779b97f4a7c15u64;
    let mut state: Vec<f64> = (0..len)
        .map(|_| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        })
        .collect();
    let mut via_map: Vec<f64> = state.iter().zip(scale).map(|(x, d)| x / d).collect();
    let mut worst = 0.0f64;
    for _ in 0..ticks {
        kernel::simulate(sub, s, 1, &mut state);
        via_map = match tick_map {
            Some(t) => dense::mat_vec(t, &via_map),
            None => (0..s).fold(via_map, |x, _| dense::mat_vec(p, &x)),
        };
        // Compared in the scaled state.
        let scaled: Vec<f64> = state.iter().zip(scale).map(|(x, d)| x / d).collect();
        let norm = scaled.iter().map(|x| x * x).sum::<f64>().sqrt();
        let diff = scaled.iter().zip(&via_map).map(|(a, b)| (a - b) * (a - b)).sum::<f64>().sqrt();
        if norm > 0.0 {
            worst = worst.max(diff / norm);
        }
    }
    SimulationCheck { ticks, max_relative_difference: worst }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(text: &str) -> SceneFile {
        SceneFile::parse("s.toml", text).unwrap()
    }

    /// A free pair (no ground) has one rigid mode; it is deflated, the
    /// configuration is stable, and the radius over every DOF is exactly 1.
    #[test]
    fn a_free_pair_deflates_its_translation() {
        let s = scene("tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 1\n[[mass]]\nname = \"b\"\nkg = 3\n[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 100\n");
        let prep = Prepared::new(&s).unwrap();
        assert_eq!(prep.rigid, 1);
        assert_eq!(prep.lambdas.len(), 1);
        for solver in Solver::ALL {
            let a = analyse(&prep, &Config::new(solver, 2, 1).unwrap(), Depth::Full).unwrap();
            assert!(a.stable, "{solver:?}");
            assert_eq!(a.stable_from, "exact");
            assert_eq!(a.spectral_radius.exact.as_deref(), Some("= 1"));
            assert_eq!(a.spectral_radius.value, 1.0);
            assert!(a.spectral_radius.non_rigid < 1.0);
            let sim = a.simulation.unwrap();
            assert!(
                sim.max_relative_difference < 1e-12,
                "{solver:?}: {}",
                sim.max_relative_difference
            );
        }
    }

    /// The 1000:1 mass-ratio chain (ground, 1000 kg, 1 kg, 1000 kg, 1 kg;
    /// 1000 N/m springs): the stated spectral radius against the decay of
    /// a simulated state (‖s_2K‖/‖s_K‖)^(1/K), and every stated effective
    /// frequency and ratio (to 1e-7) against the substep root fitted to a simulation
    /// started on the real part of each complex eigenvector.
    #[test]
    fn mass_ratio_chain_against_simulation() {
        let s = scene("tick_hz = 60\nduration_s = 2\n[[mass]]\nname = \"a\"\nkg = 1000\n[[mass]]\nname = \"b\"\nkg = 1\n[[mass]]\nname = \"c\"\nkg = 1000\n[[mass]]\nname = \"d\"\nkg = 1\n[[spring]]\nbetween = [\"ground\", \"a\"]\nstiffness = 1000\n[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 1000\n[[spring]]\nbetween = [\"b\", \"c\"]\nstiffness = 1000\n[[spring]]\nbetween = [\"c\", \"d\"]\nstiffness = 1000\n");
        let prep = Prepared::new(&s).unwrap();
        for (solver, substeps, iterations) in
            [(Solver::Xpbd, 2, 4), (Solver::XpbdJacobi, 4, 2), (Solver::SoftStep, 4, 1)]
        {
            let config = Config::new(solver, substeps, iterations).unwrap();
            let a = analyse(&prep, &config, Depth::Full).unwrap();
            assert_eq!(a.modes.len(), 4);
            let sub = kernel::substep_f64(&prep.model, &config, 60.0);
            // Radius: a random state's decay over K ticks.
            let mut state: Vec<f64> =
                (0..sub.state_len()).map(|i| ((i * 7919) % 13) as f64 - 6.0).collect();
            let k = 3000;
            kernel::simulate(&sub, substeps, k, &mut state);
            let n1 = state.iter().map(|x| x * x).sum::<f64>().sqrt();
            kernel::simulate(&sub, substeps, k, &mut state);
            let n2 = state.iter().map(|x| x * x).sum::<f64>().sqrt();
            let rho_sim = (n2 / n1).powf(1.0 / k as f64);
            let rho = a.spectral_radius.value;
            assert!((rho_sim - rho).abs() < 2e-3 * rho, "{solver:?}: {rho_sim} vs {rho}");
            // Frequencies: per complex eigenvector of P, the fitted root.
            let p = dense::mat(&sub.matrix());
            let evd = p.eigen().unwrap();
            let (u, vals) = (evd.U(), evd.S());
            let mut fitted = Vec::new();
            for col in 0..sub.state_len() {
                if vals[col].im <= 1e-9 {
                    continue;
                }
                let mut st: Vec<f64> = (0..sub.state_len()).map(|i| u[(i, col)].re).collect();
                let i = (0..sub.state_len())
                    .max_by(|&x, &y| u[(x, col)].norm().total_cmp(&u[(y, col)].norm()))
                    .unwrap();
                // Sampled every `stride` substeps, about half a radian
                // apart, so the fit is well conditioned for slow modes.
                let stride = ((0.5 / vals[col].arg().abs()).round() as usize).max(1);
                let mut seq = vec![st[i]];
                for _ in 0..40 {
                    for _ in 0..stride {
                        sub.apply(&mut st);
                    }
                    seq.push(st[i]);
                }
                // The advisor's least-squares fit of the two-term recurrence.
                if let Some((psi, ln_r)) = crate::scene::advisor::fit_root(&seq) {
                    let theta = substeps as f64 * psi / stride as f64;
                    let ln_r = substeps as f64 * ln_r / stride as f64;
                    fitted.push((
                        theta / (2.0 * std::f64::consts::PI) * 60.0,
                        -ln_r / (ln_r * ln_r + theta * theta).sqrt(),
                    ));
                }
            }
            for m in &a.modes {
                assert!(
                    fitted
                        .iter()
                        .any(|&(hz, ratio)| (hz - m.effective_hz).abs() <= 1e-7 * m.effective_hz
                            && (ratio - m.effective_ratio).abs() <= 1e-7),
                    "{solver:?}: mode {} Hz: effective {} Hz, ratio {} not among {fitted:?}",
                    m.hz,
                    m.effective_hz,
                    m.effective_ratio
                );
            }
        }
    }
}
