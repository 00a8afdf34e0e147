//! The paper's seven direct methods applied to a whole mass–spring system,
//! as an engine would write them: the scalar test-equation programs with
//! the acceleration a(y, v) = −M⁻¹(K y + C v) in place of −ω₀(y + 2Dv).
//!
//! Two orders of update:
//!
//! - **vector** (all bodies at once, each stage a whole vector): a linear
//!   combination of M⁻¹K and M⁻¹C, so with proportional damping it splits
//!   into the modes exactly and each mode runs the scalar program at
//!   Φ = ωT, D = ζ (tested against the exact transition matrix);
//! - **Gauss–Seidel** (body by body, each seeing the bodies already
//!   updated this step): not modal; its full-step matrix is assembled by
//!   stepping the unit vectors and analysed as a whole.
//!
//! Damped Euler's artificial damping D = Φ/2 becomes, in a system, the
//! damping matrix T·K added to C (2·(Φ/2)·ω = ω²T per mode). Verlet keeps
//! (y, y_prev) and takes the velocity as (y − y_prev)/T.

// Stage updates index several parallel vectors by body; an index loop
// reads like the paper's equations.
#![allow(clippy::needless_range_loop)]

use nalgebra::DMatrix;

use super::modal::System;

/// A direct method of sections 5–11, on a system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kernel {
    /// Section 5 (damped: `damped_euler_d`).
    StandardEuler,
    /// Section 6, artificial damping Φ/2 on top of the physical.
    DampedEuler,
    /// Section 7.
    FalseEuler,
    /// Section 8.
    Verlet,
    /// Section 9.
    StandardHeun,
    /// Section 10.
    FalseHeun,
    /// Section 11.
    SemiFalseHeun,
}

impl Kernel {
    /// The kernel of a damped built-in (or of its undamped name).
    pub(crate) fn for_method(name: &str) -> Option<Kernel> {
        Some(match name {
            "damped_euler_d" | "standard_euler" => Kernel::StandardEuler,
            "damped_euler_damped" | "damped_euler" => Kernel::DampedEuler,
            "false_euler_damped" | "false_euler" => Kernel::FalseEuler,
            "verlet_damped" | "verlet" => Kernel::Verlet,
            "standard_heun_damped" | "standard_heun" => Kernel::StandardHeun,
            "false_heun_damped" | "false_heun" => Kernel::FalseHeun,
            "semi_false_heun_damped" | "semi_false_heun" => Kernel::SemiFalseHeun,
            _ => return None,
        })
    }

    /// Whether the second state vector is y_prev (Verlet) rather than v.
    pub(crate) fn keeps_previous(self) -> bool {
        self == Kernel::Verlet
    }
}

/// The state of a system: positions and velocities (Verlet: positions and
/// the previous positions).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct VState {
    /// Positions.
    pub y: Vec<f64>,
    /// Velocities, or previous positions for Verlet.
    pub w: Vec<f64>,
}

/// The system's accelerations with an optional extra damping e·K.
struct Forces<'a> {
    sys: &'a System,
    extra: f64,
}

impl Forces<'_> {
    /// out = −M⁻¹(K y + (C + eK) v).
    fn acc(&self, y: &[f64], v: &[f64], out: &mut [f64]) {
        for (i, o) in out.iter_mut().enumerate() {
            *o = -self.row(i, |j| y[j], |j| v[j]) / self.sys.mass[i];
        }
    }

    /// (K y + (C + eK) v)_i with y_j, v_j given by functions.
    fn row(&self, i: usize, y: impl Fn(usize) -> f64, v: impl Fn(usize) -> f64) -> f64 {
        let mut f = 0.0;
        for (j, k) in self.sys.k.row(i) {
            f += k * (y(j) + self.extra * v(j));
        }
        for (j, c) in self.sys.c.row(i) {
            f += c * v(j);
        }
        f
    }
}

fn forces(kernel: Kernel, sys: &System, t: f64) -> Forces<'_> {
    Forces { sys, extra: if kernel == Kernel::DampedEuler { t } else { 0.0 } }
}

/// One step of length `t`, all bodies at once.
pub(crate) fn step_vector(kernel: Kernel, sys: &System, t: f64, s: &mut VState) {
    let n = sys.n();
    let f = forces(kernel, sys, t);
    let mut a1 = vec![0.0; n];
    match kernel {
        Kernel::StandardEuler | Kernel::DampedEuler => {
            f.acc(&s.y, &s.w, &mut a1);
            for i in 0..n {
                s.y[i] += t * s.w[i];
                s.w[i] += t * a1[i];
            }
        }
        Kernel::FalseEuler => {
            f.acc(&s.y, &s.w, &mut a1);
            for i in 0..n {
                s.w[i] += t * a1[i];
                s.y[i] += t * s.w[i];
            }
        }
        Kernel::Verlet => {
            let v: Vec<f64> = (0..n).map(|i| (s.y[i] - s.w[i]) / t).collect();
            f.acc(&s.y, &v, &mut a1);
            for i in 0..n {
                let y1 = 2.0 * s.y[i] - s.w[i] + t * t * a1[i];
                s.w[i] = s.y[i];
                s.y[i] = y1;
            }
        }
        Kernel::StandardHeun | Kernel::FalseHeun | Kernel::SemiFalseHeun => {
            f.acc(&s.y, &s.w, &mut a1);
            let v11: Vec<f64> = (0..n).map(|i| s.w[i] + t * a1[i]).collect();
            let y11: Vec<f64> = match kernel {
                Kernel::FalseHeun => (0..n).map(|i| s.y[i] + t * v11[i]).collect(),
                _ => (0..n).map(|i| s.y[i] + t * s.w[i]).collect(),
            };
            let mut a2 = vec![0.0; n];
            f.acc(&y11, &v11, &mut a2);
            for i in 0..n {
                let v12 = s.w[i] + t * a2[i];
                let dy = match kernel {
                    Kernel::StandardHeun => s.w[i] + v11[i],
                    Kernel::FalseHeun => v11[i] + v12,
                    _ => s.w[i] + v12,
                };
                s.y[i] += 0.5 * t * dy;
                s.w[i] += 0.5 * t * (a1[i] + a2[i]);
            }
        }
    }
}

/// One step of length `t`, body by body in index order; each body's
/// stages see the other bodies' current values.
pub(crate) fn step_gauss_seidel(kernel: Kernel, sys: &System, t: f64, s: &mut VState) {
    let f = forces(kernel, sys, t);
    for i in 0..sys.n() {
        let m = sys.mass[i];
        // Body i's acceleration with its own (y, v) replaced by stage values.
        let (y_all, w_all) = (&s.y, &s.w);
        let acc = |yi: f64, vi: f64| -> f64 {
            let vel = |j: usize| {
                if kernel.keeps_previous() {
                    (y_all[j] - w_all[j]) / t
                } else {
                    w_all[j]
                }
            };
            -f.row(i, |j| if j == i { yi } else { y_all[j] }, |j| if j == i { vi } else { vel(j) })
                / m
        };
        let (y, w) = (s.y[i], s.w[i]);
        let (y1, w1) = match kernel {
            Kernel::StandardEuler | Kernel::DampedEuler => (y + t * w, w + t * acc(y, w)),
            Kernel::FalseEuler => {
                let v = w + t * acc(y, w);
                (y + t * v, v)
            }
            Kernel::Verlet => (2.0 * y - w + t * t * acc(y, (y - w) / t), y),
            Kernel::StandardHeun | Kernel::FalseHeun | Kernel::SemiFalseHeun => {
                let a1 = acc(y, w);
                let v11 = w + t * a1;
                let y11 = if kernel == Kernel::FalseHeun { y + t * v11 } else { y + t * w };
                let a2 = acc(y11, v11);
                let v12 = w + t * a2;
                let dy = match kernel {
                    Kernel::StandardHeun => w + v11,
                    Kernel::FalseHeun => v11 + v12,
                    _ => w + v12,
                };
                (y + 0.5 * t * dy, w + 0.5 * t * (a1 + a2))
            }
        };
        s.y[i] = y1;
        s.w[i] = w1;
    }
}

/// How the bodies are updated within a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Sweep {
    /// All at once (modal).
    Vector,
    /// In sequence.
    GaussSeidel,
}

/// One step in the given order.
pub(crate) fn step(kernel: Kernel, sweep: Sweep, sys: &System, t: f64, s: &mut VState) {
    match sweep {
        Sweep::Vector => step_vector(kernel, sys, t, s),
        Sweep::GaussSeidel => step_gauss_seidel(kernel, sys, t, s),
    }
}

/// The full-step matrix on (y, w): column k is one step from unit vector k.
pub(crate) fn step_matrix(kernel: Kernel, sweep: Sweep, sys: &System, t: f64) -> DMatrix<f64> {
    let n = sys.n();
    let mut p = DMatrix::zeros(2 * n, 2 * n);
    for k in 0..2 * n {
        let mut s = VState { y: vec![0.0; n], w: vec![0.0; n] };
        if k < n {
            s.y[k] = 1.0;
        } else {
            s.w[k - n] = 1.0;
        }
        step(kernel, sweep, sys, t, &mut s);
        for i in 0..n {
            p[(i, k)] = s.y[i];
            p[(n + i, k)] = s.w[i];
        }
    }
    p
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::modal::Sparse;
    use check::numeric::f64_to_q;
    use std::collections::HashMap;

    /// For one mass the vector kernel is the damped built-in exactly: its
    /// step matrix in (y, v/ω) equals the exact P(Φ, D) of the `.zm`
    /// program, to a few ulps (the oracle is the exact derivation).
    #[test]
    fn one_mass_is_the_builtin() {
        let (m, k, zeta, t): (f64, f64, f64, f64) = (2.0, 50.0, 0.1, 0.03);
        let omega = (k / m).sqrt();
        let c = 2.0 * zeta * omega * m;
        for name in poly::advanced::builtins::DAMPED_METHODS {
            let kernel = Kernel::for_method(name).unwrap();
            let sys = System { mass: vec![m], k: sparse1(k), c: sparse1(c) };
            for sweep in [Sweep::Vector, Sweep::GaussSeidel] {
                let p = step_matrix(kernel, sweep, &sys, t);
                let method = poly::builtin(name).unwrap();
                let d = poly::derive(&method).unwrap();
                let values: HashMap<poly::Sym, poly::Q> = [
                    (poly::Sym::phi(), f64_to_q(omega * t).unwrap()),
                    (poly::Sym::new("D"), f64_to_q(zeta).unwrap()),
                ]
                .into_iter()
                .collect();
                let exact = |i: usize, j: usize| {
                    check::numeric::q_to_f64(&d.transition_matrix()[(i, j)].eval(&values).unwrap())
                };
                // Slots: (v, y) for the two-variable methods, (y, y@1) for Verlet.
                let ours = if kernel.keeps_previous() {
                    [[p[(0, 0)], p[(0, 1)]], [p[(1, 0)], p[(1, 1)]]]
                } else {
                    // Order (v/ω, y): P_vv, P_vy·ω... in scaled velocity.
                    [[p[(1, 1)], p[(1, 0)] / omega], [p[(0, 1)] * omega, p[(0, 0)]]]
                };
                for i in 0..2 {
                    for j in 0..2 {
                        let e = exact(i, j);
                        assert!(
                            (ours[i][j] - e).abs() < 1e-13,
                            "{name} {sweep:?} [{i}][{j}]: {} vs {e}",
                            ours[i][j]
                        );
                    }
                }
            }
        }
    }

    fn sparse1(x: f64) -> Sparse {
        Sparse::diagonal(&[x])
    }
}
