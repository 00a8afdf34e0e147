//! Reference integrators that judge the scenes' accuracy: classic RK4 with a
//! small fixed step, and adaptive Dormand–Prince 5(4) at a tight tolerance;
//! and any embedded explicit pair with step control (RK-Merson in the
//! report's section 12), given its coefficients.
//!
//! Both work on a fixed-size state `[f64; N]` of an autonomous system
//! `y' = f(y)`, which is all the appendix scenes need. They are written here
//! rather than taken from `ode_solvers` because that crate wants nalgebra
//! `SVector` states and a new dependency in the shared manifests, and the
//! scenes need to stop exactly on their own sample grid (every `dT`) with the
//! step size carried from one sample interval to the next.

use crate::error::Error;

fn axpy<const N: usize>(y: &[f64; N], terms: &[(f64, &[f64; N])]) -> [f64; N] {
    let mut out = *y;
    for (i, o) in out.iter_mut().enumerate() {
        for (c, k) in terms {
            *o += c * k[i];
        }
    }
    out
}

/// One step of the classic fourth-order Runge–Kutta method.
pub(crate) fn rk4_step<const N: usize>(
    f: &impl Fn(&[f64; N]) -> [f64; N],
    y: &[f64; N],
    h: f64,
) -> [f64; N] {
    let k1 = f(y);
    let k2 = f(&axpy(y, &[(h / 2.0, &k1)]));
    let k3 = f(&axpy(y, &[(h / 2.0, &k2)]));
    let k4 = f(&axpy(y, &[(h, &k3)]));
    axpy(y, &[(h / 6.0, &k1), (h / 3.0, &k2), (h / 3.0, &k3), (h / 6.0, &k4)])
}

/// Mixed error tolerance of the adaptive integrator: a component's local
/// error may be `absolute + relative * |y|`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tolerance {
    pub relative: f64,
    pub absolute: f64,
}

impl Tolerance {
    /// The tolerance the scenes use for their references: far below every
    /// error the paper's methods make at the paper's steps.
    pub(crate) const TIGHT: Tolerance = Tolerance { relative: 1e-12, absolute: 1e-12 };
}

/// Adaptive Dormand–Prince 5(4) (local extrapolation, PI-free classic step
/// control), advancing an autonomous system by exactly `duration`.
///
/// `step` carries the step size between calls, so a run over a sample grid
/// does not restart its step selection at every sample; start it at a
/// modest guess such as `1e-3`.
pub(crate) fn dopri5<const N: usize>(
    f: &impl Fn(&[f64; N]) -> [f64; N],
    y: &[f64; N],
    duration: f64,
    tolerance: Tolerance,
    step: &mut f64,
) -> Result<[f64; N], Error> {
    // Dormand & Prince (1980), Butcher tableau; E = b5 - b4.
    const A21: f64 = 1.0 / 5.0;
    const A31: f64 = 3.0 / 40.0;
    const A32: f64 = 9.0 / 40.0;
    const A41: f64 = 44.0 / 45.0;
    const A42: f64 = -56.0 / 15.0;
    const A43: f64 = 32.0 / 9.0;
    const A51: f64 = 19372.0 / 6561.0;
    const A52: f64 = -25360.0 / 2187.0;
    const A53: f64 = 64448.0 / 6561.0;
    const A54: f64 = -212.0 / 729.0;
    const A61: f64 = 9017.0 / 3168.0;
    const A62: f64 = -355.0 / 33.0;
    const A63: f64 = 46732.0 / 5247.0;
    const A64: f64 = 49.0 / 176.0;
    const A65: f64 = -5103.0 / 18656.0;
    const B1: f64 = 35.0 / 384.0;
    const B3: f64 = 500.0 / 1113.0;
    const B4: f64 = 125.0 / 192.0;
    const B5: f64 = -2187.0 / 6784.0;
    const B6: f64 = 11.0 / 84.0;
    const E1: f64 = 71.0 / 57600.0;
    const E3: f64 = -71.0 / 16695.0;
    const E4: f64 = 71.0 / 1920.0;
    const E5: f64 = -17253.0 / 339200.0;
    const E6: f64 = 22.0 / 525.0;
    const E7: f64 = -1.0 / 40.0;

    let mut y = *y;
    let mut done = 0.0;
    let mut h = step.abs().max(f64::MIN_POSITIVE);
    while done < duration {
        let last = h >= duration - done;
        let h_try = if last { duration - done } else { h };
        let k1 = f(&y);
        let k2 = f(&axpy(&y, &[(h_try * A21, &k1)]));
        let k3 = f(&axpy(&y, &[(h_try * A31, &k1), (h_try * A32, &k2)]));
        let k4 = f(&axpy(&y, &[(h_try * A41, &k1), (h_try * A42, &k2), (h_try * A43, &k3)]));
        let k5 = f(&axpy(
            &y,
            &[(h_try * A51, &k1), (h_try * A52, &k2), (h_try * A53, &k3), (h_try * A54, &k4)],
        ));
        let k6 = f(&axpy(
            &y,
            &[
                (h_try * A61, &k1),
                (h_try * A62, &k2),
                (h_try * A63, &k3),
                (h_try * A64, &k4),
                (h_try * A65, &k5),
            ],
        ));
        let y_new = axpy(
            &y,
            &[
                (h_try * B1, &k1),
                (h_try * B3, &k3),
                (h_try * B4, &k4),
                (h_try * B5, &k5),
                (h_try * B6, &k6),
            ],
        );
        let k7 = f(&y_new);
        let mut sum = 0.0;
        for i in 0..N {
            let e = h_try
                * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
            let scale = tolerance.absolute + tolerance.relative * y[i].abs().max(y_new[i].abs());
            sum += (e / scale) * (e / scale);
        }
        let err = (sum / N as f64).sqrt();
        if !err.is_finite() || y_new.iter().any(|v| !v.is_finite()) {
            // A non-finite trial may just be a step too large near a close
            // encounter: shrink it, and give up only when it cannot shrink.
            h = h_try * 0.1;
            if h <= f64::EPSILON * (1.0 + done.abs()) {
                return Err(Error::numeric(format!(
                    "reference state became non-finite at t = {done}"
                )));
            }
            continue;
        }
        let factor = if err == 0.0 { 5.0 } else { (0.9 * err.powf(-0.2)).clamp(0.2, 5.0) };
        if err <= 1.0 {
            y = y_new;
            done += h_try;
            if last {
                // Keep the step the controller wanted, not the clipped one.
                *step = h.max(h_try * factor);
                return Ok(y);
            }
            h = h_try * factor;
        } else {
            h = h_try * factor.min(1.0);
        }
        if h <= 4.0 * f64::EPSILON * (1.0 + done.abs()) {
            return Err(Error::numeric(format!("reference step size underflowed at t = {done}")));
        }
    }
    *step = h;
    Ok(y)
}

/// An explicit Runge–Kutta pair with an error estimate: the stages `a`
/// (strictly lower triangular), the weights `b` of the solution kept, and
/// the weights `e` of the local error estimate `h·Σ e_i k_i`, whose size
/// goes as `h^order`.
pub(crate) struct EmbeddedPair {
    pub a: Vec<Vec<f64>>,
    pub b: Vec<f64>,
    pub e: Vec<f64>,
    pub order: i32,
}

/// Adaptive integration by an embedded pair (no local extrapolation beyond
/// what `b` holds, the classic step control), advancing an autonomous
/// system by exactly `duration`; `step` carries the step size as in
/// [`dopri5`].
pub(crate) fn embedded<const N: usize>(
    f: &impl Fn(&[f64; N]) -> [f64; N],
    y: &[f64; N],
    duration: f64,
    tolerance: Tolerance,
    step: &mut f64,
    pair: &EmbeddedPair,
) -> Result<[f64; N], Error> {
    let mut y = *y;
    let mut done = 0.0;
    let mut h = step.abs().max(f64::MIN_POSITIVE);
    let exponent = -1.0 / f64::from(pair.order);
    while done < duration {
        let last = h >= duration - done;
        let h_try = if last { duration - done } else { h };
        let mut k: Vec<[f64; N]> = Vec::with_capacity(pair.b.len());
        for row in &pair.a {
            let terms: Vec<(f64, &[f64; N])> = row
                .iter()
                .zip(&k)
                .filter(|(c, _)| **c != 0.0)
                .map(|(c, ki)| (h_try * c, ki))
                .collect();
            k.push(f(&axpy(&y, &terms)));
        }
        let weighted = |w: &[f64]| -> Vec<(f64, &[f64; N])> {
            w.iter().zip(&k).filter(|(c, _)| **c != 0.0).map(|(c, ki)| (h_try * c, ki)).collect()
        };
        let y_new = axpy(&y, &weighted(&pair.b));
        let error = axpy(&[0.0; N], &weighted(&pair.e));
        let mut sum = 0.0;
        for i in 0..N {
            let scale = tolerance.absolute + tolerance.relative * y[i].abs().max(y_new[i].abs());
            sum += (error[i] / scale) * (error[i] / scale);
        }
        let err = (sum / N as f64).sqrt();
        if !err.is_finite() || y_new.iter().any(|v| !v.is_finite()) {
            h = h_try * 0.1;
            if h <= f64::EPSILON * (1.0 + done.abs()) {
                return Err(Error::numeric(format!("state became non-finite at t = {done}")));
            }
            continue;
        }
        let factor = if err == 0.0 { 5.0 } else { (0.9 * err.powf(exponent)).clamp(0.2, 5.0) };
        if err <= 1.0 {
            y = y_new;
            done += h_try;
            if last {
                *step = h.max(h_try * factor);
                return Ok(y);
            }
            h = h_try * factor;
        } else {
            h = h_try * factor.min(1.0);
        }
        if h <= 4.0 * f64::EPSILON * (1.0 + done.abs()) {
            return Err(Error::numeric(format!("step size underflowed at t = {done}")));
        }
    }
    *step = h;
    Ok(y)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The harmonic oscillator y'' = -y has the exact solution (cos t, -sin t).
    fn oscillator(y: &[f64; 2]) -> [f64; 2] {
        [y[1], -y[0]]
    }

    #[track_caller]
    fn check_against_exact(end: f64, got: [f64; 2], tolerance: f64) {
        let exact = [end.cos(), -end.sin()];
        for i in 0..2 {
            assert!(
                (got[i] - exact[i]).abs() <= tolerance,
                "component {i}: {} vs {}",
                got[i],
                exact[i]
            );
        }
    }

    #[test]
    fn rk4_has_fourth_order_on_the_oscillator() {
        // Halving the step divides the global error by ~16.
        let error = |h: f64| {
            let n = (10.0 / h).round() as usize;
            let mut y = [1.0, 0.0];
            for _ in 0..n {
                y = rk4_step(&oscillator, &y, h);
            }
            (y[0] - 10f64.cos()).hypot(y[1] + 10f64.sin())
        };
        let ratio = error(0.02) / error(0.01);
        assert!((ratio - 16.0).abs() < 0.5, "ratio {ratio}");
    }

    #[test]
    fn embedded_pair_converges_with_its_tolerance() {
        // Heun–Euler 2(1): the second-order solution, the first-order one
        // for the error estimate (e = b − b̂).
        let pair = EmbeddedPair {
            a: vec![vec![], vec![1.0]],
            b: vec![0.5, 0.5],
            e: vec![-0.5, 0.5],
            order: 2,
        };
        let error_at = |tolerance: f64| {
            let mut step = 1e-3;
            let mut y = [1.0, 0.0];
            for _ in 0..100 {
                let t = Tolerance { relative: tolerance, absolute: tolerance };
                y = embedded(&oscillator, &y, 0.3, t, &mut step, &pair).unwrap();
            }
            (y[0] - 30f64.cos()).hypot(y[1] + 30f64.sin())
        };
        let (loose, tight) = (error_at(1e-5), error_at(1e-8));
        assert!(loose < 1e-2, "{loose}");
        assert!(tight < loose / 100.0, "{tight} against {loose}");
    }

    #[test]
    fn dopri5_meets_a_tight_tolerance_over_many_periods() {
        let mut step = 1e-3;
        let mut y = [1.0, 0.0];
        // Sample every 0.3 like Appendix C, 1000 samples (about 48 periods).
        for _ in 0..1000 {
            y = dopri5(&oscillator, &y, 0.3, Tolerance::TIGHT, &mut step).unwrap();
        }
        // Global error grows with the number of steps; 1e-9 is ~5e6 ulp.
        check_against_exact(300.0, y, 1e-9);
    }

    #[test]
    fn dopri5_reports_a_singularity() {
        // y' = y^2 from y = 1 blows up at t = 1.
        let err = dopri5(&|y: &[f64; 1]| [y[0] * y[0]], &[1.0], 2.0, Tolerance::TIGHT, &mut 1e-3)
            .unwrap_err();
        let shown = err.to_string();
        let time: f64 = shown.rsplit("t = ").next().and_then(|t| t.parse().ok()).expect("a time");
        assert!((time - 1.0).abs() < 1e-3, "{err}");
    }
}
