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

thread_local! {
    /// The operations [`Counted`] has performed on this thread.
    static OPS: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// An f64 that counts its arithmetic: the substep kernel run once in it
/// counts the kernel's own operations (additions, subtractions,
/// multiplications, divisions), exactly as written, on the scene's
/// structure. Zero tests and constants are free.
#[derive(Clone, Debug)]
pub(crate) struct Counted(f64);

impl Counted {
    fn op(v: f64) -> Counted {
        OPS.with(|c| c.set(c.get() + 1));
        Counted(v)
    }
}

impl Field for Counted {
    fn zero() -> Counted {
        Counted(0.0)
    }
    fn int(n: u64) -> Counted {
        Counted(n as f64)
    }
    fn add(&self, o: &Counted) -> Counted {
        Counted::op(self.0 + o.0)
    }
    fn sub(&self, o: &Counted) -> Counted {
        Counted::op(self.0 - o.0)
    }
    fn mul(&self, o: &Counted) -> Counted {
        Counted::op(self.0 * o.0)
    }
    fn div(&self, o: &Counted) -> Counted {
        Counted::op(self.0 / o.0)
    }
    fn is_zero(&self) -> bool {
        self.0 == 0.0
    }
}

/// The arithmetic operations of one substep of `config` on `model`: the
/// kernel's own count (the coefficients computed once per configuration
/// are not counted). It depends on the scene's structure and the
/// configuration only, so it is the same on every machine.
pub(crate) fn ops_per_substep(model: &Model, config: &Config, tick_hz: f64) -> u64 {
    let conv = Convert { physical: &Counted, geometric: &Counted };
    let sub = Substep::<Counted>::new(model, config, tick_hz, &conv);
    let mut state = vec![Counted(1.0); sub.state_len()];
    OPS.with(|c| c.set(0));
    sub.apply(&mut state);
    OPS.with(|c| c.replace(0))
}

/// Measured ns per tick (`substeps` substeps of `sub`) on this machine: the
/// best of repeated runs within about `budget`, the state renormalised
/// between runs so it neither overflows nor underflows.
pub(crate) fn ns_per_tick(sub: &Substep<f64>, substeps: u64, budget: std::time::Duration) -> f64 {
    use std::hint::black_box;
    use std::time::Instant;
    let mut state = vec![1.0; sub.state_len()];
    let start = Instant::now();
    let mut best = f64::INFINITY;
    let mut ticks = 1u64;
    loop {
        let t = Instant::now();
        simulate(sub, substeps, ticks, black_box(&mut state));
        let ns = t.elapsed().as_nanos() as f64 / ticks as f64;
        best = best.min(ns);
        let scale = state.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if scale.is_finite() && scale > 0.0 {
            state.iter_mut().for_each(|x| *x /= scale);
        } else {
            state.iter_mut().for_each(|x| *x = 1.0);
        }
        if start.elapsed() >= budget {
            return best;
        }
        if ns * (ticks as f64) < 2e5 {
            ticks *= 2;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::file::SceneFile;
    use poly::Poly;

    /// A rational function of Φ, unreduced: enough for a few operations.
    #[derive(Clone, Debug)]
    struct R {
        n: Poly,
        d: Poly,
    }

    impl R {
        fn c(x: f64) -> R {
            R { n: Poly::constant(Q::from_float(x).unwrap()), d: Poly::one() }
        }
    }

    impl Field for R {
        fn zero() -> R {
            R { n: Poly::zero(), d: Poly::one() }
        }
        fn int(k: u64) -> R {
            R { n: Poly::int(k as i64), d: Poly::one() }
        }
        fn add(&self, o: &R) -> R {
            R { n: &(&self.n * &o.d) + &(&o.n * &self.d), d: &self.d * &o.d }
        }
        fn sub(&self, o: &R) -> R {
            R { n: &(&self.n * &o.d) - &(&o.n * &self.d), d: &self.d * &o.d }
        }
        fn mul(&self, o: &R) -> R {
            R { n: &self.n * &o.n, d: &self.d * &o.d }
        }
        fn div(&self, o: &R) -> R {
            R { n: &self.n * &o.d, d: &self.d * &o.n }
        }
        fn is_zero(&self) -> bool {
            self.n.is_zero()
        }
    }

    fn one_spring(solver: Solver) -> (Model, Config) {
        // The stiffness 7 stands for Φ² below (m = 1, h = 1).
        let s = SceneFile::parse(
            "s.toml",
            "tick_hz = 1\n[[mass]]\nname = \"a\"\nkg = 1\n[[spring]]\nbetween = [\"a\", \"ground\"]\nstiffness = 7\n",
        )
        .unwrap();
        (Model::of_scene(&s), Config::new(solver, 1, 1).unwrap())
    }

    /// A single spring with N = 1: xpbd is backward Euler on the
    /// oscillator, χ(z) = z² − 2z/(1 + Φ²) + 1/(1 + Φ²), i.e.
    /// (1 + Φ²)z² − 2z + 1, exactly in the symbol Φ; its roots are
    /// 1/(1 ± iΦ). Jacobi with one constraint is the same map.
    #[test]
    fn one_spring_xpbd_is_backward_euler_exactly() {
        let phi = Poly::parse("Phi").unwrap();
        let phi2 = &phi * &phi;
        let physical =
            |x: f64| if x == 7.0 { R { n: phi2.clone(), d: Poly::one() } } else { R::c(x) };
        let geometric = |x: f64| R::c(x);
        let one_plus = &Poly::one() + &phi2;
        for solver in [Solver::Xpbd, Solver::XpbdJacobi] {
            let (model, config) = one_spring(solver);
            let sub = Substep::new(
                &model,
                &config,
                1.0,
                &Convert { physical: &physical, geometric: &geometric },
            );
            let p = sub.matrix();
            let tr = p[0][0].add(&p[1][1]);
            let det = p[0][0].mul(&p[1][1]).sub(&p[0][1].mul(&p[1][0]));
            // tr·(1 + Φ²) = 2 and det·(1 + Φ²) = 1, as rational functions.
            assert_eq!(&tr.n * &one_plus, &tr.d * &Poly::int(2), "{solver:?} trace");
            assert_eq!(&det.n * &one_plus, det.d.clone(), "{solver:?} determinant");
        }
    }

    /// b2MakeSoft, transcribed from Box2D v3 (`src/solver.h`).
    fn make_soft(hertz: f64, zeta: f64, h: f64) -> (f64, f64, f64) {
        if hertz == 0.0 {
            return (0.0, 0.0, 0.0);
        }
        let omega = 2.0 * std::f64::consts::PI * hertz;
        let a1 = 2.0 * zeta + h * omega;
        let a2 = h * omega * a1;
        let a3 = 1.0 / (1.0 + a2);
        (omega / a1, a2 * a3, a3)
    }

    /// A distance joint with a spring, as Box2D v3 holds it (points at the
    /// body centres: no rotation terms).
    struct Joint {
        a: Option<usize>,
        b: Option<usize>,
        rest: [f64; 2],
        length: f64,
        axial_mass: f64,
        soft: (f64, f64, f64),
        impulse: f64,
    }

    /// One Box2D step of `substeps` on 2D bodies (positions are the
    /// deltaPositions from the rest shape): b2PrepareDistanceJoint, then per
    /// substep integrate velocities (no force), b2WarmStartDistanceJoint,
    /// b2SolveDistanceJoint(useBias = true), integrate positions,
    /// b2SolveDistanceJoint(useBias = false). `linear` takes the rest axis
    /// and C = axis·ds, the linearisation; otherwise the axis and length of
    /// the current separation, as Box2D does.
    fn box2d_step(
        joints: &mut [Joint],
        inv_mass: &[f64],
        x: &mut [[f64; 2]],
        v: &mut [[f64; 2]],
        dt: f64,
        substeps: u64,
        linear: bool,
    ) {
        let h = dt / substeps as f64;
        let at = |p: &[[f64; 2]], i: Option<usize>| i.map_or([0.0, 0.0], |i| p[i]);
        let geometry = |j: &Joint, x: &[[f64; 2]]| {
            let (da, db) = (at(x, j.a), at(x, j.b));
            let ds = [db[0] - da[0], db[1] - da[1]];
            if linear {
                let len = (j.rest[0] * j.rest[0] + j.rest[1] * j.rest[1]).sqrt();
                let axis = [j.rest[0] / len, j.rest[1] / len];
                (axis, axis[0] * ds[0] + axis[1] * ds[1])
            } else {
                let sep = [j.rest[0] + ds[0], j.rest[1] + ds[1]];
                let len = (sep[0] * sep[0] + sep[1] * sep[1]).sqrt();
                ([sep[0] / len, sep[1] / len], len - j.length)
            }
        };
        for _ in 0..substeps {
            for j in joints.iter() {
                let (axis, _) = geometry(j, x);
                let p = [j.impulse * axis[0], j.impulse * axis[1]];
                if let Some(a) = j.a {
                    v[a] = [v[a][0] - inv_mass[a] * p[0], v[a][1] - inv_mass[a] * p[1]];
                }
                if let Some(b) = j.b {
                    v[b] = [v[b][0] + inv_mass[b] * p[0], v[b][1] + inv_mass[b] * p[1]];
                }
            }
            for pass in 0..2 {
                if pass == 1 {
                    for (xi, vi) in x.iter_mut().zip(v.iter()) {
                        *xi = [xi[0] + h * vi[0], xi[1] + h * vi[1]];
                    }
                }
                for j in joints.iter_mut() {
                    let (axis, c) = geometry(j, x);
                    let (va, vb) = (at(v, j.a), at(v, j.b));
                    let cdot = axis[0] * (vb[0] - va[0]) + axis[1] * (vb[1] - va[1]);
                    let (bias_rate, mass_scale, impulse_scale) = j.soft;
                    let m = mass_scale * j.axial_mass;
                    let impulse = -m * (cdot + bias_rate * c) - impulse_scale * j.impulse;
                    j.impulse += impulse;
                    let p = [impulse * axis[0], impulse * axis[1]];
                    if let Some(a) = j.a {
                        v[a] = [v[a][0] - inv_mass[a] * p[0], v[a][1] - inv_mass[a] * p[1]];
                    }
                    if let Some(b) = j.b {
                        v[b] = [v[b][0] + inv_mass[b] * p[0], v[b][1] + inv_mass[b] * p[1]];
                    }
                }
            }
        }
    }

    /// soft_step against the transcription of Box2D's functions, stepped in
    /// f64: equal to 1e-12 (relative) over 200 ticks of 4 substeps, on a
    /// 2D triangle with one static corner and dampers; and the nonlinear
    /// transcription at an amplitude of 10⁻⁶ within 10⁻⁵ of it (the
    /// linearisation).
    #[test]
    fn soft_step_is_box2d() {
        let text = "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 1\npos = [0, 0]\nfixed = true\n[[mass]]\nname = \"b\"\nkg = 1.5\npos = [1, 0]\n[[mass]]\nname = \"c\"\nkg = 2\npos = [0.5, 0.8]\n[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 100\ndamping = 0.3\n[[spring]]\nbetween = [\"b\", \"c\"]\nstiffness = 50\n[[spring]]\nbetween = [\"c\", \"a\"]\nstiffness = 80\ndamping = 0.1\n";
        let scene = SceneFile::parse("s.toml", text).unwrap();
        let model = Model::of_scene(&scene);
        let config = Config::new(Solver::SoftStep, 4, 1).unwrap();
        let sub = substep_f64(&model, &config, 60.0);
        // Bodies b, c are free (indices 0, 1); a is static.
        let pos: [[f64; 2]; 3] = [[0.0, 0.0], [1.0, 0.0], [0.5, 0.8]];
        let body = [None, Some(0), Some(1)];
        let inv_mass = [1.0 / 1.5, 0.5];
        let h = 1.0 / (60.0 * 4.0);
        let springs: [(usize, usize, f64, f64); 3] =
            [(0, 1, 100.0, 0.3), (1, 2, 50.0, 0.0), (2, 0, 80.0, 0.1)];
        let make = || -> Vec<Joint> {
            springs
                .iter()
                .map(|&(a, b, k, c)| {
                    let (ba, bb) = (body[a], body[b]);
                    let wsum = ba.map_or(0.0, |i| inv_mass[i]) + bb.map_or(0.0, |i| inv_mass[i]);
                    let rest: [f64; 2] = [pos[b][0] - pos[a][0], pos[b][1] - pos[a][1]];
                    let hertz = (k * wsum).sqrt() / (2.0 * std::f64::consts::PI);
                    let zeta = c / (2.0 * (k / wsum).sqrt());
                    Joint {
                        a: ba,
                        b: bb,
                        rest,
                        length: (rest[0] * rest[0] + rest[1] * rest[1]).sqrt(),
                        axial_mass: 1.0 / wsum,
                        soft: make_soft(hertz, zeta, h),
                        impulse: 0.0,
                    }
                })
                .collect()
        };
        for (amplitude, linear, tol) in [(0.01, true, 1e-12), (1e-6, false, 1e-5)] {
            let x0 = [[0.3 * amplitude, -0.2 * amplitude], [0.1 * amplitude, 0.4 * amplitude]];
            let v0 = [[-0.5 * amplitude, 0.0], [0.2 * amplitude, 0.7 * amplitude]];
            let mut joints = make();
            let (mut x, mut v) = (x0, v0);
            let mut state = vec![0.0; sub.state_len()];
            for i in 0..2 {
                for p in 0..2 {
                    state[2 * i + p] = x0[i][p];
                    state[4 + 2 * i + p] = v0[i][p];
                }
            }
            for tick in 0..200 {
                box2d_step(&mut joints, &inv_mass, &mut x, &mut v, 1.0 / 60.0, 4, linear);
                simulate(&sub, 4, 1, &mut state);
                let ours: Vec<f64> = state[..8].to_vec();
                let theirs: Vec<f64> =
                    x.iter().chain(v.iter()).flat_map(|p| p.iter().copied()).collect();
                let norm = theirs.iter().map(|a| a * a).sum::<f64>().sqrt();
                let diff =
                    ours.iter().zip(&theirs).map(|(a, b)| (a - b) * (a - b)).sum::<f64>().sqrt();
                assert!(diff <= tol * norm, "tick {tick} (linear {linear}): {diff} vs {norm}");
                // The accumulated impulses: Box2D's axis runs a → b, ours
                // C = d·(x_a − x_b): opposite signs.
                if linear {
                    for (j, joint) in joints.iter().enumerate() {
                        let ours = -state[8 + j];
                        assert!((ours - joint.impulse).abs() <= 1e-9 * amplitude, "impulse {j}");
                    }
                }
            }
        }
    }
}
