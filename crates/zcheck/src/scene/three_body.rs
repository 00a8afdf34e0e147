//! Appendices C and D: three unit masses in the plane, integrated by False
//! Euler (C) or Standard Euler with and without energy control (D), as the
//! paper's Pascal code does it, with its defects made explicit options.
//!
//! The paper's force on body 1 is `(x2-x1)/r12 + (x3-x1)/r13` with `r12` the
//! SQUARED distance: a force of magnitude 1/r (gravity in two dimensions,
//! potential `ln r`). Appendix D's "total energy" uses `-Sqrt(1/r12)`, the
//! potential of a 1/r² force. [`ForceLaw`] and [`EnergyDefinition`] offer
//! both, so the invariant that really holds can be measured.

use serde::Serialize;

use super::reference::{dopri5, Tolerance};
use super::track::Track;
use crate::error::Error;

/// Positions or velocities of the three bodies.
pub type Bodies = [[f64; 2]; 3];

/// The pairs in the order the paper writes r12, r13, r23.
const PAIRS: [(usize, usize); 3] = [(0, 1), (0, 2), (1, 2)];

/// The force between two bodies at distance r.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ForceLaw {
    /// |F| = 1/r, potential `ln r`: the paper's code, `(x2-x1)/r12` with `r12`
    /// the squared distance (two-dimensional gravity).
    InverseDistance,
    /// |F| = 1/r², potential `-1/r`: Newton's law, the one Appendix D's
    /// energy formula belongs to.
    InverseSquare,
}

/// Which "total energy" the energy control and the reports use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EnergyDefinition {
    /// Appendix D as printed: kinetic energy minus the sum of 1/r.
    Paper,
    /// The energy that the chosen force law conserves: kinetic plus `sum ln r`
    /// for [`ForceLaw::InverseDistance`], minus `sum 1/r` for
    /// [`ForceLaw::InverseSquare`].
    Consistent,
}

/// The integration rule of the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Integrator {
    /// Appendix C: new velocity from the old positions, new position from the
    /// NEW velocity (symplectic Euler).
    FalseEuler,
    /// Appendix D: new velocity and new position both from old values.
    StandardEuler,
}

/// What the first step's force reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FirstStep {
    /// The intended model: the force from the old positions `x1o, ...`.
    OldPositions,
    /// The code as printed: the velocity update reads `x1, x2, ...`, the NEW
    /// positions. From step 2 on they equal the old ones (`x1o:=x1` closes
    /// the loop), but on step 1 they are uninitialised; this models them as
    /// zeroed memory, so the first step has no force.
    ZeroedNewPositions,
}

/// The initial velocities (the positions are the paper's equilateral
/// triangle on the unit circle in both appendices).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum InitialVelocities {
    /// Appendix C: unit speed tangential to the unit circle (clockwise);
    /// `eps` is added to body 3's y velocity.
    Tangential,
    /// Appendix D as printed: unit speed radially outward
    /// (`v1o:=-co; w1o:=-si` at `(-co,-si)`); `eps` is body 3's x velocity.
    Radial,
}

/// The energy control term of Appendix D, `-Cf*dEn*v` in every velocity
/// derivative.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct EnergyControl {
    /// `Cf`, the "experimental control factor" (0.3 in the paper).
    pub factor: f64,
    /// Which energy `dEn` measures.
    pub energy: EnergyDefinition,
}

/// Everything a three-body scene needs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ThreeBodyConfig {
    pub integrator: Integrator,
    /// `dT`.
    pub dt: f64,
    pub force_law: ForceLaw,
    pub control: Option<EnergyControl>,
    pub first_step: FirstStep,
    pub velocities: InitialVelocities,
    /// The asymmetry `eps` of the initial velocities (Appendix D: 0.01).
    pub eps: f64,
}

impl ThreeBodyConfig {
    /// Appendix C as intended: False Euler, dT = 0.3, the coded 1/r force,
    /// tangential unit velocities, force from the old positions.
    pub fn appendix_c() -> Self {
        ThreeBodyConfig {
            integrator: Integrator::FalseEuler,
            dt: 0.3,
            force_law: ForceLaw::InverseDistance,
            control: None,
            first_step: FirstStep::OldPositions,
            velocities: InitialVelocities::Tangential,
            eps: 0.0,
        }
    }

    /// Appendix D, upper image: Standard Euler, dT = 0.01, eps = 0.01, the
    /// printed (radial) initial velocities.
    pub fn appendix_d() -> Self {
        ThreeBodyConfig {
            integrator: Integrator::StandardEuler,
            dt: 0.01,
            force_law: ForceLaw::InverseDistance,
            control: None,
            first_step: FirstStep::OldPositions,
            velocities: InitialVelocities::Radial,
            eps: 0.01,
        }
    }

    /// Appendix D, lower image: the same with energy control, Cf = 0.3, on
    /// the energy the force law conserves (the paper's intent; the printed
    /// formula is [`EnergyDefinition::Paper`]).
    pub fn appendix_d_energy() -> Self {
        ThreeBodyConfig {
            control: Some(EnergyControl { factor: 0.3, energy: EnergyDefinition::Consistent }),
            ..Self::appendix_d()
        }
    }

    /// The initial state: the equilateral triangle on the unit circle.
    pub fn initial_state(&self) -> State {
        // SicCoc(30*wrad, si, co); the paper holds si, co in Single, which
        // would make the triangle equilateral only to ~2e-8: we use f64.
        let (si, co) = (0.5, 3f64.sqrt() / 2.0);
        let position = [[-co, -si], [co, -si], [0.0, 1.0]];
        let velocity = match self.velocities {
            InitialVelocities::Tangential => [[-si, co], [-si, -co], [1.0, self.eps]],
            InitialVelocities::Radial => [[-co, -si], [co, -si], [self.eps, 1.0]],
        };
        State { position, velocity }
    }
}

/// Positions and velocities of the three unit masses.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct State {
    pub position: Bodies,
    pub velocity: Bodies,
}

impl State {
    /// The accelerations under `law` at the current positions.
    pub fn acceleration(&self, law: ForceLaw) -> Bodies {
        acceleration(&self.position, law)
    }

    /// Kinetic energy (unit masses), summed in the paper's order
    /// `(sqr(v1o)+sqr(w1o)+...+sqr(w3o))/2`.
    pub(crate) fn kinetic_energy(&self) -> f64 {
        let mut sum = 0.0;
        for v in &self.velocity {
            sum += v[0] * v[0];
            sum += v[1] * v[1];
        }
        sum / 2.0
    }

    /// The squared distances r12, r13, r23, as the paper's `r12` holds them.
    pub(crate) fn squared_distances(&self) -> [f64; 3] {
        let p = &self.position;
        PAIRS.map(|(i, j)| {
            let (dx, dy) = (p[j][0] - p[i][0], p[j][1] - p[i][1]);
            dx * dx + dy * dy
        })
    }

    /// The three pair distances r12, r13, r23 (not squared).
    pub(crate) fn distances(&self) -> [f64; 3] {
        PAIRS.map(|(i, j)| distance(&self.position[i], &self.position[j]))
    }

    /// Appendix D's total energy, operation for operation:
    /// `(sqr(v1o)+...)/2 - Sqrt(1/r12) - Sqrt(1/r23) - Sqrt(1/r13)`.
    pub fn energy_paper(&self) -> f64 {
        energy_paper(self.kinetic_energy(), &self.squared_distances())
    }

    /// The energy conserved by the equations of motion under `law`.
    pub fn energy_consistent(&self, law: ForceLaw) -> f64 {
        let d = self.distances();
        match law {
            ForceLaw::InverseDistance => {
                self.kinetic_energy() + d.iter().map(|r| r.ln()).sum::<f64>()
            }
            ForceLaw::InverseSquare => self.energy_paper(),
        }
    }

    /// The energy `definition` under `law`.
    pub fn energy(&self, definition: EnergyDefinition, law: ForceLaw) -> f64 {
        match definition {
            EnergyDefinition::Paper => self.energy_paper(),
            EnergyDefinition::Consistent => self.energy_consistent(law),
        }
    }

    /// Angular momentum about the origin, sum of `x*w - y*v`.
    pub fn angular_momentum(&self) -> f64 {
        self.position.iter().zip(&self.velocity).map(|(p, v)| p[0] * v[1] - p[1] * v[0]).sum()
    }

    /// Total momentum.
    pub(crate) fn momentum(&self) -> [f64; 2] {
        let mut m = [0.0; 2];
        for v in &self.velocity {
            m[0] += v[0];
            m[1] += v[1];
        }
        m
    }

    /// Centre of mass.
    pub(crate) fn centre_of_mass(&self) -> [f64; 2] {
        let mut c = [0.0; 2];
        for p in &self.position {
            c[0] += p[0] / 3.0;
            c[1] += p[1] / 3.0;
        }
        c
    }

    /// Distance of each body from the centre of mass.
    pub fn radii(&self) -> [f64; 3] {
        let c = self.centre_of_mass();
        self.position.map(|p| distance(&p, &c))
    }

    fn is_finite(&self) -> bool {
        self.position.iter().chain(&self.velocity).flatten().all(|x| x.is_finite())
    }

    fn to_array(self) -> [f64; 12] {
        let mut y = [0.0; 12];
        for b in 0..3 {
            y[2 * b..2 * b + 2].copy_from_slice(&self.position[b]);
            y[6 + 2 * b..6 + 2 * b + 2].copy_from_slice(&self.velocity[b]);
        }
        y
    }

    fn from_array(y: &[f64; 12]) -> Self {
        let mut s = State { position: [[0.0; 2]; 3], velocity: [[0.0; 2]; 3] };
        for b in 0..3 {
            s.position[b] = [y[2 * b], y[2 * b + 1]];
            s.velocity[b] = [y[6 + 2 * b], y[6 + 2 * b + 1]];
        }
        s
    }
}

/// Everything the run follows, from one pass over the pairs: the energies
/// need the distances anyway, and `ln r12 + ln r13 + ln r23` is one `ln`.
struct Measures {
    energy_paper: f64,
    energy_consistent: f64,
    centre_of_mass: [f64; 2],
    radii: [f64; 3],
    distance_min: f64,
}

fn measure(state: &State, law: ForceLaw) -> Measures {
    let p = &state.position;
    let squared = state.squared_distances();
    let kinetic = state.kinetic_energy();
    let energy_paper = energy_paper(kinetic, &squared);
    let energy_consistent = energy_consistent(kinetic, &squared, energy_paper, law);
    let c = state.centre_of_mass();
    let radii = p.map(|q| ((q[0] - c[0]).powi(2) + (q[1] - c[1]).powi(2)).sqrt());
    let distance_min = squared.iter().fold(f64::INFINITY, |m, &r2| m.min(r2)).sqrt();
    Measures { energy_paper, energy_consistent, centre_of_mass: c, radii, distance_min }
}

/// `squared` in the order r12, r13, r23; the paper subtracts r12, r23, r13.
fn energy_paper(kinetic: f64, squared: &[f64; 3]) -> f64 {
    kinetic - (1.0 / squared[0]).sqrt() - (1.0 / squared[2]).sqrt() - (1.0 / squared[1]).sqrt()
}

fn energy_consistent(kinetic: f64, squared: &[f64; 3], energy_paper: f64, law: ForceLaw) -> f64 {
    match law {
        // ln r12 + ln r13 + ln r23 = ln(r12^2 r13^2 r23^2) / 2: one logarithm.
        ForceLaw::InverseDistance => kinetic + 0.5 * (squared[0] * squared[1] * squared[2]).ln(),
        ForceLaw::InverseSquare => energy_paper,
    }
}

fn distance(a: &[f64; 2], b: &[f64; 2]) -> f64 {
    ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt()
}

fn acceleration(position: &Bodies, law: ForceLaw) -> Bodies {
    let mut a = [[0.0; 2]; 3];
    for (i, j) in PAIRS {
        let dx = position[j][0] - position[i][0];
        let dy = position[j][1] - position[i][1];
        // r12 in the paper is the squared distance.
        let r2 = dx * dx + dy * dy;
        // Divide as the paper does, (x2-x1)/r12, so that the scene repeats
        // the Pascal code bit for bit.
        let denominator = match law {
            ForceLaw::InverseDistance => r2,
            ForceLaw::InverseSquare => r2 * r2.sqrt(),
        };
        let (fx, fy) = (dx / denominator, dy / denominator);
        a[i][0] += fx;
        a[i][1] += fy;
        a[j][0] -= fx;
        a[j][1] -= fy;
    }
    a
}

/// One step of the scene. `reference_energy` is Appendix D's `Eno`; `first`
/// says whether this is step 1 (see [`FirstStep`]).
pub fn step(config: &ThreeBodyConfig, state: &mut State, reference_energy: f64, first: bool) {
    let h = config.dt;
    let acc = if first && config.first_step == FirstStep::ZeroedNewPositions {
        // (0 - 0)/r12 + (0 - 0)/r13: the literal first step has no force.
        [[0.0; 2]; 3]
    } else {
        state.acceleration(config.force_law)
    };
    let damping = match config.control {
        // -Cf*dEn*v: dEn from the old state, v the old velocity.
        Some(c) => c.factor * (state.energy(c.energy, config.force_law) - reference_energy),
        None => 0.0,
    };
    let bodies = state.position.iter_mut().zip(state.velocity.iter_mut()).zip(&acc);
    for ((position, velocity), acc) in bodies {
        for ((x, v), a) in position.iter_mut().zip(velocity.iter_mut()).zip(acc) {
            let v_old = *v;
            let v_new = v_old + h * (a - damping * v_old);
            *v = v_new;
            *x += h * match config.integrator {
                Integrator::FalseEuler => v_new,
                Integrator::StandardEuler => v_old,
            };
        }
    }
}

/// The equations of motion without any control: the physics the scene
/// approximates, for the reference integrator.
pub fn derivative(y: &[f64; 12], law: ForceLaw) -> [f64; 12] {
    let s = State::from_array(y);
    let a = s.acceleration(law);
    let mut d = [0.0; 12];
    d[..6].copy_from_slice(&y[6..]);
    for b in 0..3 {
        d[6 + 2 * b..6 + 2 * b + 2].copy_from_slice(&a[b]);
    }
    d
}

/// One sample of a run, kept for figures.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub(crate) struct Sample {
    pub step: u64,
    pub time: f64,
    pub position: Bodies,
    pub energy_paper: f64,
    pub energy_consistent: f64,
}

/// A finished run of a three-body scene.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ThreeBodyRun {
    pub config: ThreeBodyConfig,
    /// Steps asked for.
    pub n_steps: u64,
    /// Steps done before the state became non-finite (or `n_steps`).
    pub completed_steps: u64,
    /// The first step whose result was NaN or infinite (a collision).
    pub first_nonfinite_step: Option<u64>,
    pub energy_paper: Track,
    pub energy_consistent: Track,
    pub angular_momentum: Track,
    pub momentum_x: Track,
    pub momentum_y: Track,
    /// Distance of the centre of mass from its uniform motion
    /// `c0 + P0 t / 3` (0 for an exact integrator).
    pub centre_of_mass_drift: Track,
    /// Smallest and largest distance of any body from the centre of mass.
    pub radius_min: f64,
    pub radius_max: f64,
    /// Distance from the centre of mass averaged over bodies and steps.
    pub radius_mean: f64,
    /// Closest approach of any pair.
    pub distance_min: f64,
    /// The first 100 steps in full (the paper's Appendix C image).
    pub first_steps: Vec<Bodies>,
    /// At most ~4000 samples over the whole run, for figures.
    pub(crate) samples: Vec<Sample>,
    pub final_state: State,
}

impl ThreeBodyRun {
    /// Bounded: every step finite and no body farther than 10 (ten times
    /// the initial radius) from the centre of mass.
    pub fn bounded(&self) -> bool {
        self.first_nonfinite_step.is_none() && self.radius_max <= 10.0
    }
}

/// Run `n_steps` of the scene; `progress` is called with the number of steps
/// done now and then (for a progress bar).
pub fn simulate(
    config: &ThreeBodyConfig,
    n_steps: u64,
    progress: &mut dyn FnMut(u64),
) -> ThreeBodyRun {
    let mut state = config.initial_state();
    let law = config.force_law;
    let reference_energy = config.control.map_or(0.0, |c| state.energy(c.energy, law));
    let centre0 = state.centre_of_mass();
    let momentum0 = state.momentum();
    let mut energy_paper = Track::new(state.energy_paper());
    let mut energy_consistent = Track::new(state.energy_consistent(law));
    let mut angular_momentum = Track::new(state.angular_momentum());
    let mut momentum_x = Track::new(momentum0[0]);
    let mut momentum_y = Track::new(momentum0[1]);
    let mut centre_of_mass_drift = Track::new(0.0);
    let (mut radius_min, mut radius_max, mut radius_sum) = (f64::INFINITY, 0.0f64, 0.0);
    let mut distance_min = f64::INFINITY;
    let every = (n_steps / 4000).max(1);
    let sample = |step: u64, s: &State| Sample {
        step,
        time: step as f64 * config.dt,
        position: s.position,
        energy_paper: s.energy_paper(),
        energy_consistent: s.energy_consistent(law),
    };
    let mut samples = vec![sample(0, &state)];
    let mut first_steps = vec![state.position];
    let mut completed = 0;
    let mut first_nonfinite_step = None;
    for k in 1..=n_steps {
        step(config, &mut state, reference_energy, k == 1);
        if !state.is_finite() {
            first_nonfinite_step = Some(k);
            break;
        }
        completed = k;
        let t = k as f64 * config.dt;
        let m = measure(&state, law);
        energy_paper.push(m.energy_paper);
        energy_consistent.push(m.energy_consistent);
        angular_momentum.push(state.angular_momentum());
        let p = state.momentum();
        momentum_x.push(p[0]);
        momentum_y.push(p[1]);
        let c = m.centre_of_mass;
        let drift_x = c[0] - (centre0[0] + momentum0[0] * t / 3.0);
        let drift_y = c[1] - (centre0[1] + momentum0[1] * t / 3.0);
        centre_of_mass_drift.push((drift_x * drift_x + drift_y * drift_y).sqrt());
        for r in m.radii {
            radius_min = radius_min.min(r);
            radius_max = radius_max.max(r);
            radius_sum += r;
        }
        distance_min = distance_min.min(m.distance_min);
        if k <= 100 {
            first_steps.push(state.position);
        }
        if k % every == 0 || k == n_steps {
            samples.push(sample(k, &state));
        }
        if k % 65536 == 0 {
            progress(k);
        }
    }
    progress(completed);
    ThreeBodyRun {
        config: *config,
        n_steps,
        completed_steps: completed,
        first_nonfinite_step,
        energy_paper,
        energy_consistent,
        angular_momentum,
        momentum_x,
        momentum_y,
        centre_of_mass_drift,
        radius_min,
        radius_max,
        radius_mean: radius_sum / (3 * completed.max(1)) as f64,
        distance_min,
        first_steps,
        samples,
        final_state: state,
    }
}

/// The reference solution of the scene's physics (no control, no first-step
/// defect) at every step `0..=n_steps`, by Dormand–Prince at a tight
/// tolerance.
pub fn reference(config: &ThreeBodyConfig, n_steps: u64) -> Result<Vec<State>, Error> {
    let law = config.force_law;
    let f = move |y: &[f64; 12]| derivative(y, law);
    let mut y = config.initial_state().to_array();
    let mut out = vec![State::from_array(&y)];
    let mut h = 1e-3;
    for _ in 0..n_steps {
        y = dopri5(&f, &y, config.dt, Tolerance::TIGHT, &mut h)?;
        out.push(State::from_array(&y));
    }
    Ok(out)
}

/// How closely a run follows the reference.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Accuracy {
    /// Steps compared.
    pub steps: u64,
    /// Largest distance of any body from its reference position.
    pub max_position_error: f64,
    /// The first step at which that distance exceeds 0.1 (none: never).
    pub faithful_until: Option<u64>,
    /// Largest drift of the consistent energy along the reference: how well
    /// the reference itself keeps the invariant.
    pub reference_energy_drift: f64,
    /// Range of the paper's energy along the reference, `[min, max]`.
    pub reference_energy_paper_range: [f64; 2],
}

/// Compare the first `n_steps` of the scene with the reference.
pub fn accuracy(config: &ThreeBodyConfig, n_steps: u64) -> Result<Accuracy, Error> {
    let reference = reference(config, n_steps)?;
    let mut state = config.initial_state();
    let law = config.force_law;
    let reference_energy = config.control.map_or(0.0, |c| state.energy(c.energy, law));
    let e0 = state.energy_consistent(law);
    let mut acc = Accuracy {
        steps: n_steps,
        max_position_error: 0.0,
        faithful_until: None,
        reference_energy_drift: 0.0,
        reference_energy_paper_range: [f64::INFINITY, f64::NEG_INFINITY],
    };
    for (k, r) in reference.iter().enumerate() {
        if k > 0 {
            step(config, &mut state, reference_energy, k == 1);
        }
        let error =
            (0..3).map(|b| distance(&state.position[b], &r.position[b])).fold(0.0, f64::max);
        // NaN compares false: a non-finite scene state counts as lost.
        let lost = error.is_nan() || error > 0.1;
        if lost && acc.faithful_until.is_none() {
            acc.faithful_until = Some(k as u64);
        }
        acc.max_position_error =
            acc.max_position_error.max(if error.is_nan() { f64::INFINITY } else { error });
        acc.reference_energy_drift =
            acc.reference_energy_drift.max((r.energy_consistent(law) - e0).abs());
        let ep = r.energy_paper();
        acc.reference_energy_paper_range[0] = acc.reference_energy_paper_range[0].min(ep);
        acc.reference_energy_paper_range[1] = acc.reference_energy_paper_range[1].max(ep);
    }
    Ok(acc)
}
