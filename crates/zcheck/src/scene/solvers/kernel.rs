//! The substep of each solver, written once over any field (`f64` for the
//! simulation and the numeric map, `poly::Q` for the exact map, rational
//! functions of Φ in the tests), as the issue defines them; the state is
//! (x, v) over the free degrees of freedom, and for the soft step the
//! accumulated impulse of every joint too. Each map is linear in that
//! state, so applying it to basis vectors gives its matrix.
//!
//! `xpbd` (Macklin, Müller, Chentanez 2016, Algorithm 1), h = 1/(tick·S):
//! x_prev = x, p = x + h v, λ = 0; N times, for every constraint j in file
//! order: α̃ = α_j/h², β̃ = h²β_j, γ = α̃β̃/h,
//! Δλ = (−C_j(p) − α̃λ_j − γ∇C_j·(p − x_prev)) / ((1 + γ)Σ w_i|∇_i C_j|² + α̃),
//! λ_j += Δλ, p_i += w_i∇_i C_j Δλ; then v = (p − x_prev)/h, x = p.
//! `xpbd_jacobi` computes every Δλ of an iteration from the same p, then
//! applies them all (times the relaxation factor ω, 1 for plain Jacobi).
//!
//! `soft_step` follows Box2D v3 (`src/solver.c`, `b2SolverStage_*`;
//! `src/distance_joint.c`, `b2PrepareDistanceJoint`, `b2WarmStartDistanceJoint`,
//! `b2SolveDistanceJoint`; `src/solver.h`, `b2MakeSoft`), per substep:
//! integrate velocities (no force: nothing), warm start (every joint applies
//! its accumulated impulse), solve with bias, integrate positions
//! (x += h v), relax (Box2D's spring branch ignores `useBias`, so relax is
//! the same spring solve again). The spring solve is
//! impulse = −massScale·axialMass·(Ċ + biasRate·C) − impulseScale·acc,
//! acc += impulse, v_i += w_i∇_i C·impulse. With the joint's hertz
//! √(k·Σw)/(2π) and damping ratio ζ = β/(2√(k/Σw)), b2MakeSoft's
//! coefficients are rational in (k, β, Σw, h): biasRate = k/(β + hk),
//! a₂ = hΣw(β + hk), massScale = a₂/(1 + a₂), impulseScale = 1/(1 + a₂),
//! which is how they are computed here (exact over Q); the tests hold them
//! against a transcription of b2MakeSoft.

use poly::Q;

use super::model::{Config, Model, Solver};

/// The arithmetic the substep needs.
pub(crate) trait Field: Clone {
    /// 0.
    fn zero() -> Self;
    /// An integer.
    fn int(n: u64) -> Self;
    /// self + o.
    fn add(&self, o: &Self) -> Self;
    /// self − o.
    fn sub(&self, o: &Self) -> Self;
    /// self · o.
    fn mul(&self, o: &Self) -> Self;
    /// self / o.
    fn div(&self, o: &Self) -> Self;
    /// Whether it is zero (skipped in sums).
    fn is_zero(&self) -> bool;
}

impl Field for f64 {
    fn zero() -> f64 {
        0.0
    }
    fn int(n: u64) -> f64 {
        n as f64
    }
    fn add(&self, o: &f64) -> f64 {
        self + o
    }
    fn sub(&self, o: &f64) -> f64 {
        self - o
    }
    fn mul(&self, o: &f64) -> f64 {
        self * o
    }
    fn div(&self, o: &f64) -> f64 {
        self / o
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
}

impl Field for Q {
    fn zero() -> Q {
        <Q as num_traits::Zero>::zero()
    }
    fn int(n: u64) -> Q {
        Q::from_integer(n.into())
    }
    fn add(&self, o: &Q) -> Q {
        self + o
    }
    fn sub(&self, o: &Q) -> Q {
        self - o
    }
    fn mul(&self, o: &Q) -> Q {
        self * o
    }
    fn div(&self, o: &Q) -> Q {
        self / o
    }
    fn is_zero(&self) -> bool {
        num_traits::Zero::is_zero(self)
    }
}

/// A constraint's data in the field: ∇C and the per-substep coefficients.
#[derive(Clone, Debug)]
pub(crate) struct Coeff<T> {
    /// ∇C over the free degrees of freedom.
    pub grad: Vec<(usize, T)>,
    /// w_i ∇_i C, for the position or velocity update.
    pub wgrad: Vec<(usize, T)>,
    /// XPBD: α̃ = α/h².
    pub alpha_tilde: T,
    /// XPBD: γ = α̃β̃/h.
    pub gamma: T,
    /// XPBD: 1/((1 + γ)Σw|∇C|² + α̃).
    pub inv_denom: T,
    /// Soft step: massScale·axialMass.
    pub mass: T,
    /// Soft step: biasRate.
    pub bias_rate: T,
    /// Soft step: impulseScale.
    pub impulse_scale: T,
}

/// Everything one substep needs, in the field.
#[derive(Clone, Debug)]
pub(crate) struct Substep<T> {
    /// The solver.
    pub solver: Solver,
    /// Iterations (XPBD).
    pub iterations: u64,
    /// Jacobi's relaxation factor.
    pub relaxation: T,
    /// h.
    pub h: T,
    /// 1/h.
    pub inv_h: T,
    /// Free degrees of freedom.
    pub n: usize,
    /// The constraints.
    pub cons: Vec<Coeff<T>>,
}

/// How the model's numbers enter the field: `physical` for the typed
/// inputs (masses, stiffness, damping, tick rate), `geometric` for the
/// computed unit directions.
pub(crate) struct Convert<'a, T> {
    /// A typed number.
    pub physical: &'a dyn Fn(f64) -> T,
    /// A computed number.
    pub geometric: &'a dyn Fn(f64) -> T,
}

impl<T: Field> Substep<T> {
    /// The substep of `config` on `model` at a tick rate of `tick_hz`.
    pub(crate) fn new(model: &Model, config: &Config, tick_hz: f64, conv: &Convert<T>) -> Self {
        let one = T::int(1);
        let h = one.div(&(conv.physical)(tick_hz).mul(&T::int(config.substeps)));
        let inv_h = one.div(&h);
        let h2 = h.mul(&h);
        let w: Vec<T> = model.kg.iter().map(|&m| one.div(&(conv.physical)(m))).collect();
        let cons = model
            .constraints
            .iter()
            .map(|c| {
                let grad: Vec<(usize, T)> =
                    c.grad.iter().map(|&(i, g)| (i, (conv.geometric)(g))).collect();
                let wgrad: Vec<(usize, T)> = grad.iter().map(|(i, g)| (*i, w[*i].mul(g))).collect();
                let wsum = grad
                    .iter()
                    .zip(&wgrad)
                    .fold(T::zero(), |s, ((_, g), (_, wg))| s.add(&g.mul(wg)));
                let k = (conv.physical)(c.stiffness);
                let beta = (conv.physical)(c.damping);
                let alpha = one.div(&k);
                let alpha_tilde = alpha.div(&h2);
                let beta_tilde = h2.mul(&beta);
                let gamma = alpha_tilde.mul(&beta_tilde).div(&h);
                let inv_denom = one.div(&one.add(&gamma).mul(&wsum).add(&alpha_tilde));
                // b2MakeSoft in closed form (see the module notes).
                let bhk = beta.add(&h.mul(&k));
                let a2 = h.mul(&wsum).mul(&bhk);
                let a3 = one.div(&one.add(&a2));
                let mass = a2.mul(&a3).div(&wsum);
                Coeff {
                    grad,
                    wgrad,
                    alpha_tilde,
                    gamma,
                    inv_denom,
                    mass,
                    bias_rate: k.div(&bhk),
                    impulse_scale: a3,
                }
            })
            .collect();
        Substep {
            solver: config.solver,
            iterations: config.iterations,
            relaxation: (conv.geometric)(config.relaxation),
            h,
            inv_h,
            n: model.n(),
            cons,
        }
    }

    /// The state's length.
    pub(crate) fn state_len(&self) -> usize {
        match self.solver {
            Solver::SoftStep => 2 * self.n + self.cons.len(),
            _ => 2 * self.n,
        }
    }

    /// One substep on `state` = (x, v[, impulse]).
    pub(crate) fn apply(&self, state: &mut [T]) {
        match self.solver {
            Solver::SoftStep => self.soft(state),
            Solver::Xpbd => self.xpbd(state, false),
            Solver::XpbdJacobi => self.xpbd(state, true),
        }
    }

    fn xpbd(&self, state: &mut [T], jacobi: bool) {
        let n = self.n;
        let (x, v) = state.split_at_mut(n);
        let x_prev: Vec<T> = x.to_vec();
        // p = x + h v, in place of x.
        for (xi, vi) in x.iter_mut().zip(v.iter()) {
            *xi = xi.add(&self.h.mul(vi));
        }
        let p = x;
        let m = self.cons.len();
        let mut lambda = vec![T::zero(); m];
        let mut delta = vec![T::zero(); if jacobi { m } else { 0 }];
        let dot = |g: &[(usize, T)], y: &[T]| {
            g.iter().fold(T::zero(), |s, (i, gi)| s.add(&gi.mul(&y[*i])))
        };
        let dot_diff = |g: &[(usize, T)], y: &[T], z: &[T]| {
            g.iter().fold(T::zero(), |s, (i, gi)| s.add(&gi.mul(&y[*i].sub(&z[*i]))))
        };
        for _ in 0..self.iterations {
            for (j, c) in self.cons.iter().enumerate() {
                let cp = dot(&c.grad, p);
                let mut num = cp.add(&c.alpha_tilde.mul(&lambda[j]));
                if !c.gamma.is_zero() {
                    num = num.add(&c.gamma.mul(&dot_diff(&c.grad, p, &x_prev)));
                }
                let dl = T::zero().sub(&num.mul(&c.inv_denom));
                if jacobi {
                    delta[j] = dl;
                } else {
                    lambda[j] = lambda[j].add(&dl);
                    for (i, wg) in &c.wgrad {
                        p[*i] = p[*i].add(&wg.mul(&dl));
                    }
                }
            }
            if jacobi {
                for (j, c) in self.cons.iter().enumerate() {
                    let dl = delta[j].mul(&self.relaxation);
                    lambda[j] = lambda[j].add(&dl);
                    for (i, wg) in &c.wgrad {
                        p[*i] = p[*i].add(&wg.mul(&dl));
                    }
                }
            }
        }
        for ((vi, pi), xi) in v.iter_mut().zip(p.iter()).zip(&x_prev) {
            *vi = pi.sub(xi).mul(&self.inv_h);
        }
    }

    fn soft(&self, state: &mut [T]) {
        let n = self.n;
        let (x, rest) = state.split_at_mut(n);
        let (v, acc) = rest.split_at_mut(n);
        // Warm start.
        for (c, a) in self.cons.iter().zip(acc.iter()) {
            for (i, wg) in &c.wgrad {
                v[*i] = v[*i].add(&wg.mul(a));
            }
        }
        self.spring_pass(x, v, acc);
        for (xi, vi) in x.iter_mut().zip(v.iter()) {
            *xi = xi.add(&self.h.mul(vi));
        }
        // Relax: the spring branch ignores useBias.
        self.spring_pass(x, v, acc);
    }

    fn spring_pass(&self, x: &[T], v: &mut [T], acc: &mut [T]) {
        for (c, a) in self.cons.iter().zip(acc.iter_mut()) {
            let (mut cdot, mut cx) = (T::zero(), T::zero());
            for (i, g) in &c.grad {
                cdot = cdot.add(&g.mul(&v[*i]));
                cx = cx.add(&g.mul(&x[*i]));
            }
            let imp = T::zero()
                .sub(&c.mass.mul(&cdot.add(&c.bias_rate.mul(&cx))))
                .sub(&c.impulse_scale.mul(a));
            *a = a.add(&imp);
            for (i, wg) in &c.wgrad {
                v[*i] = v[*i].add(&wg.mul(&imp));
            }
        }
    }

    /// The substep's matrix (row-major, state_len²): the map applied to
    /// every basis vector.
    pub(crate) fn matrix(&self) -> Vec<Vec<T>> {
        let d = self.state_len();
        let mut cols = Vec::with_capacity(d);
        for k in 0..d {
            let mut e = vec![T::zero(); d];
            e[k] = T::int(1);
            self.apply(&mut e);
            cols.push(e);
        }
        (0..d).map(|i| (0..d).map(|k| cols[k][i].clone()).collect()).collect()
    }
}

/// The f64 conversion: the numbers as they are.
pub(crate) fn f64_convert() -> Convert<'static, f64> {
    Convert { physical: &|x| x, geometric: &|x| x }
}

/// The substep in f64.
pub(crate) fn substep_f64(model: &Model, config: &Config, tick_hz: f64) -> Substep<f64> {
    Substep::new(model, config, tick_hz, &f64_convert())
}

/// Steps `state` by `ticks` ticks of `config` (S substeps each): the
/// simulation the tick map is checked against.
pub(crate) fn simulate(sub: &Substep<f64>, substeps: u64, ticks: u64, state: &mut [f64]) {
    for _ in 0..ticks * substeps {
        sub.apply(state);
    }
}
