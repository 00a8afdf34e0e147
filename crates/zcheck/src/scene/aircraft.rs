//! Appendix E: the rotation of an aircraft, a principal-axis rigid body with
//! roll, pitch and yaw dampers, roll and pitch angle controllers and a yaw
//! torque driven by the roll angle, integrated by False Euler at dT = 0.1
//! exactly as the paper's `Integ` procedure does.
//!
//! The state is the body rates `wx, wy, wz` (rad/s) and the Euler angles
//! `Phi, The, Psi` in DEGREES (roll, pitch, yaw; z-y-x convention), because
//! the paper's controller gains are per degree (`contPhi = 0.06`).

use nalgebra::{SMatrix, SVector};
use serde::Serialize;

use super::reference::rk4_step;
use super::track::Track;
use crate::error::Error;

/// Principal moments of inertia.
pub(crate) const JX: f64 = 0.6;
pub(crate) const JY: f64 = 1.0;
pub(crate) const JZ: f64 = 1.5;
/// Dampers (torque per rad/s).
pub(crate) const DAMP_P: f64 = 2.0;
pub(crate) const DAMP_Q: f64 = 3.0;
pub(crate) const DAMP_R: f64 = 1.0;
/// Controllers (torque per degree) and the yaw torque per sine of roll.
pub(crate) const CONT_PHI: f64 = 0.06;
pub(crate) const CONT_THE: f64 = 0.10;
pub(crate) const CONT_PSI: f64 = 1.0;
/// The gimbal-lock guard: `|cos The|` is kept at or above this.
pub(crate) const GIMBAL_EPS: f64 = 1e-5;
const WRAD: f64 = std::f64::consts::PI / 180.0;

/// Commands and step of the aircraft scene.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AircraftConfig {
    /// `Phic`, the commanded roll angle in degrees.
    pub phi_command: f64,
    /// `Thec`, the commanded pitch angle in degrees.
    pub theta_command: f64,
    /// `Txc, Tyc, Tzc`, the commanded torques.
    pub torque_command: [f64; 3],
    /// `CO = 1`: the attitude controllers are on.
    pub controller: bool,
    /// `dT`.
    pub dt: f64,
}

impl Default for AircraftConfig {
    /// The command this scene checks: a 30° bank with 10° pitch from level
    /// flight at rest, controllers on, no torque command, dT = 0.1.
    fn default() -> Self {
        AircraftConfig {
            phi_command: 30.0,
            theta_command: 10.0,
            torque_command: [0.0; 3],
            controller: true,
            dt: 0.1,
        }
    }
}

/// Body rates (rad/s) and Euler angles (degrees).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct AircraftState {
    /// `wx, wy, wz`.
    pub rates: [f64; 3],
    /// `Phi, The, Psi`.
    pub angles: [f64; 3],
}

/// The paper's `While Phi > 180 Do Phi := Phi-360; ...`, into [-180, 180].
/// The paper's loop never ends on an infinite angle; this one returns it.
fn wrap(angle: f64) -> f64 {
    if !angle.is_finite() || (-180.0..=180.0).contains(&angle) {
        angle
    } else {
        let a = (angle + 180.0).rem_euclid(360.0) - 180.0;
        if a == -180.0 && angle > 0.0 {
            180.0
        } else {
            a
        }
    }
}

/// Torques `Tx, Ty, Tz` from the rates and the (wrapped) angles.
fn torques(config: &AircraftConfig, rates: &[f64; 3], angles: &[f64; 3]) -> [f64; 3] {
    let (s_phi, _) = (WRAD * angles[0]).sin_cos();
    let c_the = (WRAD * angles[1]).cos();
    let mut t = [
        -DAMP_P * rates[0] + config.torque_command[0],
        -DAMP_Q * rates[1] + config.torque_command[1],
        -DAMP_R * rates[2] - CONT_PSI * s_phi * c_the + config.torque_command[2],
    ];
    if config.controller {
        t[0] -= CONT_PHI * (angles[0] - config.phi_command);
        t[1] -= CONT_THE * (angles[1] - config.theta_command);
    }
    t
}

/// Euler's equations for a principal-axis body.
fn rate_derivative(rates: &[f64; 3], t: &[f64; 3]) -> [f64; 3] {
    let [wx, wy, wz] = *rates;
    [
        (wy * wz * (JY - JZ) + t[0]) / JX,
        (wz * wx * (JZ - JX) + t[1]) / JY,
        (wx * wy * (JX - JY) + t[2]) / JZ,
    ]
}

/// The Euler-angle rates in degrees per second, with the gimbal-lock guard.
fn angle_derivative(rates: &[f64; 3], angles: &[f64; 3]) -> [f64; 3] {
    let (s_phi, c_phi) = (WRAD * angles[0]).sin_cos();
    let (s_the, mut c_the) = (WRAD * angles[1]).sin_cos();
    if c_the.abs() < GIMBAL_EPS {
        c_the = if c_the > 0.0 { GIMBAL_EPS } else { -GIMBAL_EPS };
    }
    let ic_the = 1.0 / c_the;
    let [wx, wy, wz] = *rates;
    [
        (wx + wy * s_phi * s_the * ic_the + wz * c_phi * s_the * ic_the) / WRAD,
        (wy * c_phi - wz * s_phi) / WRAD,
        (wy * s_phi * ic_the + wz * c_phi * ic_the) / WRAD,
    ]
}

fn wrapped(config: &AircraftConfig, angles: &[f64; 3]) -> [f64; 3] {
    if config.controller {
        [wrap(angles[0]), wrap(angles[1]), angles[2]]
    } else {
        *angles
    }
}

/// One False Euler step of `Integ`: the rates from the old state, then the
/// angles from the NEW rates and the old angles' sines and cosines.
pub fn step(config: &AircraftConfig, state: &mut AircraftState) {
    // The paper wraps Phi and The (only with the controller on) before the
    // controller reads them; the sines were taken before, which is the same.
    state.angles = wrapped(config, &state.angles);
    let t = torques(config, &state.rates, &state.angles);
    let d = rate_derivative(&state.rates, &t);
    for (w, dw) in state.rates.iter_mut().zip(d) {
        *w += config.dt * dw;
    }
    let d = angle_derivative(&state.rates, &state.angles);
    for (a, da) in state.angles.iter_mut().zip(d) {
        *a += config.dt * da;
    }
}

/// The continuous equations, `[wx, wy, wz, Phi, The, Psi]`.
pub fn derivative(config: &AircraftConfig, y: &[f64; 6]) -> [f64; 6] {
    let rates = [y[0], y[1], y[2]];
    let angles = wrapped(config, &[y[3], y[4], y[5]]);
    let dr = rate_derivative(&rates, &torques(config, &rates, &angles));
    let da = angle_derivative(&rates, &angles);
    [dr[0], dr[1], dr[2], da[0], da[1], da[2]]
}

/// The paper's rotation matrix `o11 .. o33` (body to earth, z-y-x).
pub(crate) fn rotation_matrix(angles: &[f64; 3]) -> [[f64; 3]; 3] {
    let (sphi, cphi) = (WRAD * angles[0]).sin_cos();
    let (sthe, cthe) = (WRAD * angles[1]).sin_cos();
    let (spsi, cpsi) = (WRAD * angles[2]).sin_cos();
    [
        [cpsi * cthe, -spsi * cphi + cpsi * sthe * sphi, spsi * sphi + cpsi * sthe * cphi],
        [spsi * cthe, cpsi * cphi + spsi * sthe * sphi, -cpsi * sphi + spsi * sthe * cphi],
        [-sthe, cthe * sphi, cthe * cphi],
    ]
}

/// Largest entry of `|O^T O - I|`.
pub(crate) fn orthonormality_error(m: &[[f64; 3]; 3]) -> f64 {
    let mut worst = 0.0f64;
    for i in 0..3 {
        for j in 0..3 {
            let dot: f64 = (0..3).map(|k| m[k][i] * m[k][j]).sum();
            worst = worst.max((dot - if i == j { 1.0 } else { 0.0 }).abs());
        }
    }
    worst
}

/// The steady turn the closed loop settles into: rates and angles at which
/// the rate and the roll and pitch derivatives vanish (yaw keeps turning).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SteadyTurn {
    pub rates: [f64; 3],
    /// Roll and pitch in degrees.
    pub phi: f64,
    pub theta: f64,
    /// `dPsi/dt` in degrees per second.
    pub yaw_rate: f64,
}

/// Solve for the steady turn of the continuous equations by Newton's method
/// from the command (an independent route to the simulated end state).
pub fn steady_turn(config: &AircraftConfig) -> Result<SteadyTurn, Error> {
    let residual = |x: &SVector<f64, 5>| {
        let d = derivative(config, &[x[0], x[1], x[2], x[3], x[4], 0.0]);
        SVector::<f64, 5>::from([d[0], d[1], d[2], d[3], d[4]])
    };
    let mut x = SVector::<f64, 5>::from([0.0, 0.0, 0.0, config.phi_command, config.theta_command]);
    for _ in 0..50 {
        let r = residual(&x);
        if r.norm() < 1e-13 {
            let d = derivative(config, &[x[0], x[1], x[2], x[3], x[4], 0.0]);
            return Ok(SteadyTurn {
                rates: [x[0], x[1], x[2]],
                phi: x[3],
                theta: x[4],
                yaw_rate: d[5],
            });
        }
        let mut jacobian = SMatrix::<f64, 5, 5>::zeros();
        for j in 0..5 {
            let h = 1e-7 * (1.0 + x[j].abs());
            let mut xp = x;
            xp[j] += h;
            let mut xm = x;
            xm[j] -= h;
            jacobian.set_column(j, &((residual(&xp) - residual(&xm)) / (2.0 * h)));
        }
        let dx = jacobian.lu().solve(&r).ok_or_else(no_steady_turn)?;
        x -= dx;
    }
    Err(no_steady_turn())
}

fn no_steady_turn() -> Error {
    Error::numeric("no steady turn found for the aircraft's command")
}

/// One sample of a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub(crate) struct AircraftSample {
    pub time: f64,
    pub angles: [f64; 3],
    pub reference_angles: [f64; 3],
}

/// A finished aircraft run, with its reference.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AircraftRun {
    pub config: AircraftConfig,
    pub n_steps: u64,
    pub final_state: AircraftState,
    pub reference_final_state: AircraftState,
    /// The equilibrium of the continuous equations (Newton), if found.
    pub steady_turn: Option<SteadyTurn>,
    /// First time after which roll and pitch stay within 0.1° of the steady
    /// turn (none: not settled within the run).
    pub settling_time: Option<f64>,
    /// Largest roll and pitch difference from the reference, degrees.
    pub max_angle_error: [f64; 2],
    /// Orthonormality of the paper's rotation matrix built from the angles.
    pub orthonormality: Track,
    /// Largest entry of the difference between the rotation matrix built
    /// from the reference angles and one integrated directly,
    /// `dO/dt = O [w]x`, by the same RK4: checks the angle kinematics.
    pub kinematics_error: f64,
    /// Rotational kinetic energy (not an invariant: dampers and controllers).
    pub kinetic_energy: Track,
    pub(crate) samples: Vec<AircraftSample>,
}

/// The reference: RK4 with 20 substeps per `dT` (h = 0.005 s, far inside
/// RK4's accuracy for these ~2.4 rad/s dynamics), on the angles and rates
/// together with the rotation matrix `O` integrated directly.
const SUBSTEPS: u32 = 20;

/// Run `n_steps` of False Euler beside the reference.
pub fn simulate(
    config: &AircraftConfig,
    n_steps: u64,
    progress: &mut dyn FnMut(u64),
) -> AircraftRun {
    let mut state = AircraftState::default();
    let mut reference = [0.0f64; 15];
    let o0 = rotation_matrix(&state.angles);
    for i in 0..3 {
        reference[6 + 3 * i..9 + 3 * i].copy_from_slice(&o0[i]);
    }
    let f = |y: &[f64; 15]| {
        let mut out = [0.0; 15];
        let d = derivative(config, &[y[0], y[1], y[2], y[3], y[4], y[5]]);
        out[..6].copy_from_slice(&d);
        // dO/dt = O [w]x with [w]x the cross-product matrix of the body rates.
        let w = [y[0], y[1], y[2]];
        let cross = [[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]];
        for i in 0..3 {
            for j in 0..3 {
                out[6 + 3 * i + j] = (0..3).map(|k| y[6 + 3 * i + k] * cross[k][j]).sum();
            }
        }
        out
    };
    let steady = steady_turn(config).ok();
    let kinetic = |s: &AircraftState| {
        0.5 * (JX * s.rates[0].powi(2) + JY * s.rates[1].powi(2) + JZ * s.rates[2].powi(2))
    };
    let mut orthonormality = Track::new(orthonormality_error(&o0));
    let mut kinetic_energy = Track::new(kinetic(&state));
    let mut max_angle_error = [0.0f64; 2];
    let mut kinematics_error = 0.0f64;
    let mut settling_time = Some(0.0);
    let h = config.dt / f64::from(SUBSTEPS);
    let mut samples =
        vec![AircraftSample { time: 0.0, angles: state.angles, reference_angles: [0.0; 3] }];
    for k in 1..=n_steps {
        step(config, &mut state);
        for _ in 0..SUBSTEPS {
            reference = rk4_step(&f, &reference, h);
        }
        let time = k as f64 * config.dt;
        let ref_angles = [reference[3], reference[4], reference[5]];
        for i in 0..2 {
            max_angle_error[i] =
                max_angle_error[i].max(angle_difference(state.angles[i], ref_angles[i]));
        }
        let o = rotation_matrix(&ref_angles);
        for i in 0..3 {
            for j in 0..3 {
                kinematics_error = kinematics_error.max((o[i][j] - reference[6 + 3 * i + j]).abs());
            }
        }
        orthonormality.push(orthonormality_error(&rotation_matrix(&state.angles)));
        kinetic_energy.push(kinetic(&state));
        let settled = steady.is_some_and(|s| {
            angle_difference(state.angles[0], s.phi) <= 0.1
                && angle_difference(state.angles[1], s.theta) <= 0.1
        });
        if !settled {
            settling_time = None;
        } else if settling_time.is_none() {
            settling_time = Some(time);
        }
        samples.push(AircraftSample { time, angles: state.angles, reference_angles: ref_angles });
        if k % 4096 == 0 {
            progress(k);
        }
    }
    progress(n_steps);
    let reference_final_state = AircraftState {
        rates: [reference[0], reference[1], reference[2]],
        angles: [reference[3], reference[4], reference[5]],
    };
    AircraftRun {
        config: *config,
        n_steps,
        final_state: state,
        reference_final_state,
        steady_turn: steady,
        settling_time: if steady.is_some() { settling_time } else { None },
        max_angle_error,
        orthonormality,
        kinematics_error,
        kinetic_energy,
        samples,
    }
}

/// |a - b| in degrees, modulo 360 (roll and pitch are wrapped).
fn angle_difference(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[track_caller]
    fn check_wrap(angle: f64, expected: f64) {
        assert_eq!(wrap(angle), expected, "wrap({angle})");
    }

    #[test]
    fn wrap_matches_the_paper_loops() {
        check_wrap(190.0, -170.0);
        check_wrap(-190.0, 170.0);
        check_wrap(180.0, 180.0);
        check_wrap(540.0, 180.0);
        check_wrap(-180.0, -180.0);
        check_wrap(725.0, 5.0);
        assert!(wrap(f64::INFINITY).is_infinite());
    }

    #[test]
    fn rotation_matrix_is_orthonormal() {
        for angles in [[0.0, 0.0, 0.0], [30.0, 10.0, -45.0], [170.0, -89.0, 400.0]] {
            let e = orthonormality_error(&rotation_matrix(&angles));
            assert!(e <= 8.0 * f64::EPSILON, "{angles:?}: {e}");
        }
    }
}
