//! A scene as game-engine constraints: every spring a distance constraint
//! linearised about the rest shape, C = d·(x_a − x_b) with d the unit rest
//! direction (a scalar scene: C = x_a − x_b; a spring to ground holds every
//! axis, one constraint per axis), compliance α = 1/stiffness, damping
//! β (N·s/m, 0 when none) and inverse masses w (0 for a fixed mass, whose
//! degrees of freedom are left out). A scene given as modes is one unit mass
//! per mode on a ground spring k = ω², β = 2ζω. The solver configuration
//! ([`Solver`], [`Config`]) and its cost, constraint projections per tick
//! S·N·(number of constraints), live here too.

use serde::Serialize;

use super::super::file::{Body, SceneFile};
use crate::error::Error;

/// The solvers analysed (`zcheck advise --solver`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub(crate) enum Solver {
    /// XPBD, Gauss–Seidel over the constraints in file order (Macklin,
    /// Müller, Chentanez 2016, Algorithm 1).
    Xpbd,
    /// XPBD with every Δλ of an iteration computed from the same positions,
    /// then all applied (plain Jacobi; an optional relaxation factor).
    XpbdJacobi,
    /// Box2D v3's soft step: distance joints with a spring, warm-started,
    /// solve and relax per substep.
    SoftStep,
}

impl Solver {
    /// Every solver, in a fixed order.
    pub(crate) const ALL: [Solver; 3] = [Solver::Xpbd, Solver::XpbdJacobi, Solver::SoftStep];

    /// Its name on the command line and in JSON.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Solver::Xpbd => "xpbd",
            Solver::XpbdJacobi => "xpbd_jacobi",
            Solver::SoftStep => "soft_step",
        }
    }

    /// The solver called `name`, or a usage error naming the flag.
    pub(crate) fn parse(name: &str) -> Result<Solver, Error> {
        Solver::ALL.into_iter().find(|s| s.name() == name).ok_or_else(|| {
            Error::usage(format!(
                "--solver {name}: unknown solver, expected one of: xpbd, xpbd_jacobi, soft_step"
            ))
        })
    }

    /// The iteration counts the search tries: 1..=16, or only 1 for the
    /// soft step (it has no iteration count).
    pub(crate) fn iteration_range(self) -> std::ops::RangeInclusive<u64> {
        match self {
            Solver::SoftStep => 1..=1,
            _ => 1..=MAX_ITERATIONS,
        }
    }
}

/// Largest substep count searched.
pub(crate) const MAX_SUBSTEPS: u64 = 64;
/// Largest iteration count searched.
pub(crate) const MAX_ITERATIONS: u64 = 16;

/// One solver configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Config {
    /// The solver.
    pub solver: Solver,
    /// Substeps per tick, S ≥ 1.
    pub substeps: u64,
    /// Iterations per substep, N ≥ 1 (exactly 1 for the soft step).
    pub iterations: u64,
    /// Jacobi's relaxation factor ω (Δλ and Δp scaled by ω); 1 is plain
    /// Jacobi, and the other solvers ignore it.
    pub relaxation: f64,
}

impl Config {
    /// A configuration, checked: S ≥ 1, N ≥ 1, N = 1 for the soft step, a
    /// relaxation factor in (0, 2). Errors name the flag.
    pub(crate) fn new(solver: Solver, substeps: u64, iterations: u64) -> Result<Config, Error> {
        Config::with_relaxation(solver, substeps, iterations, 1.0)
    }

    /// [`Config::new`] with a Jacobi relaxation factor.
    pub(crate) fn with_relaxation(
        solver: Solver,
        substeps: u64,
        iterations: u64,
        relaxation: f64,
    ) -> Result<Config, Error> {
        if substeps == 0 {
            return Err(Error::usage("--substeps 0: expected a whole number of substeps >= 1"));
        }
        if substeps > 1 << 20 {
            return Err(Error::usage(format!(
                "--substeps {substeps}: expected at most {} substeps per tick",
                1u64 << 20
            )));
        }
        if iterations == 0 {
            return Err(Error::usage("--iterations 0: expected a whole number of iterations >= 1"));
        }
        if iterations > 1 << 12 {
            return Err(Error::usage(format!(
                "--iterations {iterations}: expected at most {} iterations per substep",
                1u64 << 12
            )));
        }
        if solver == Solver::SoftStep && iterations != 1 {
            return Err(Error::usage(format!(
                "--iterations {iterations}: the soft step (Box2D v3) has no iteration count; expected 1 \
                 (its relax pass is part of every substep)"
            )));
        }
        if !(relaxation > 0.0 && relaxation < 2.0) {
            return Err(Error::usage(format!(
                "--relaxation {relaxation}: expected a factor in (0, 2), 1 for plain Jacobi"
            )));
        }
        Ok(Config { solver, substeps, iterations, relaxation })
    }
}

/// One linearised constraint.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Constraint {
    /// ∇C over the free degrees of freedom: (index, component).
    pub grad: Vec<(usize, f64)>,
    /// Stiffness k, N/m (α = 1/k).
    pub stiffness: f64,
    /// Damping β, N·s/m.
    pub damping: f64,
    /// Σ_i w_i |∇_i C|².
    pub wsum: f64,
}

/// A scene as constraints on its free degrees of freedom.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Model {
    /// Inverse mass per free degree of freedom.
    pub w: Vec<f64>,
    /// Mass per free degree of freedom, kg (for the exact route, read as
    /// the decimal it prints as).
    pub kg: Vec<f64>,
    /// The constraints, in file order (a ground spring of a 2D or 3D scene
    /// gives one per axis, in axis order).
    pub constraints: Vec<Constraint>,
    /// Whether the scene was given as modes.
    pub from_modes: bool,
}

impl Model {
    /// The constraints of a scene.
    pub(crate) fn of_scene(scene: &SceneFile) -> Model {
        match &scene.body {
            Body::Modes(list) => {
                let mut constraints = Vec::new();
                for (i, m) in list.iter().enumerate() {
                    let omega = 2.0 * std::f64::consts::PI * m.hz;
                    constraints.push(Constraint {
                        grad: vec![(i, 1.0)],
                        stiffness: omega * omega,
                        damping: 2.0 * m.ratio * omega,
                        wsum: 1.0,
                    });
                }
                Model {
                    w: vec![1.0; list.len()],
                    kg: vec![1.0; list.len()],
                    constraints,
                    from_modes: true,
                }
            }
            Body::Springs { masses, springs, dim } => {
                let dim = *dim;
                let mut base = vec![None; masses.len()];
                let (mut w, mut kg) = (Vec::new(), Vec::new());
                for (i, m) in masses.iter().enumerate() {
                    if !m.fixed {
                        base[i] = Some(w.len());
                        w.extend(std::iter::repeat_n(1.0 / m.kg, dim));
                        kg.extend(std::iter::repeat_n(m.kg, dim));
                    }
                }
                let mut constraints = Vec::new();
                let mut push = |grad: Vec<(usize, f64)>, k: f64, c: f64| {
                    if grad.is_empty() {
                        return;
                    }
                    let wsum = grad.iter().map(|&(i, g)| w[i] * g * g).sum();
                    constraints.push(Constraint { grad, stiffness: k, damping: c, wsum });
                };
                for s in springs {
                    let (a, b) = (base[s.a], s.b.and_then(|b| base[b]));
                    let dir = s.b.and_then(|b| {
                        let (pa, pb) = (masses[s.a].pos.as_ref()?, masses[b].pos.as_ref()?);
                        let diff: Vec<f64> = pa.iter().zip(pb).map(|(x, y)| y - x).collect();
                        let len = diff.iter().map(|x| x * x).sum::<f64>().sqrt();
                        Some(diff.iter().map(|x| x / len).collect::<Vec<f64>>())
                    });
                    match dir {
                        // A spring to ground (or between scalar masses):
                        // one constraint per axis.
                        None => {
                            for p in 0..dim {
                                let mut g = Vec::new();
                                if let Some(a) = a {
                                    g.push((a + p, 1.0));
                                }
                                if let Some(b) = b {
                                    g.push((b + p, -1.0));
                                }
                                push(g, s.stiffness, s.damping);
                            }
                        }
                        Some(d) => {
                            let mut g = Vec::new();
                            for (p, &dp) in d.iter().enumerate() {
                                if dp == 0.0 {
                                    continue;
                                }
                                if let Some(a) = a {
                                    g.push((a + p, dp));
                                }
                                if let Some(b) = b {
                                    g.push((b + p, -dp));
                                }
                            }
                            g.sort_by_key(|e| e.0);
                            push(g, s.stiffness, s.damping);
                        }
                    }
                }
                Model { w, kg, constraints, from_modes: false }
            }
        }
    }

    /// Free degrees of freedom.
    pub(crate) fn n(&self) -> usize {
        self.w.len()
    }

    /// Constraints.
    pub(crate) fn m(&self) -> usize {
        self.constraints.len()
    }

    /// The state the solver's map acts on: (x, v), and for the soft step
    /// the accumulated impulse of every joint too.
    pub(crate) fn state_len(&self, solver: Solver) -> usize {
        match solver {
            Solver::SoftStep => 2 * self.n() + self.m(),
            _ => 2 * self.n(),
        }
    }

    /// Constraint projections per tick: S·N·(constraints).
    pub(crate) fn cost(&self, config: &Config) -> u64 {
        config.substeps.saturating_mul(config.iterations).saturating_mul(self.m() as u64)
    }

    /// Dense K = Σ k_j ∇C_j ∇C_jᵀ and C = Σ β_j ∇C_j ∇C_jᵀ (row-major).
    pub(crate) fn stiffness_damping(&self) -> (Vec<f64>, Vec<f64>) {
        let n = self.n();
        let (mut k, mut c) = (vec![0.0; n * n], vec![0.0; n * n]);
        for con in &self.constraints {
            for &(i, gi) in &con.grad {
                for &(j, gj) in &con.grad {
                    k[i * n + j] += con.stiffness * gi * gj;
                    c[i * n + j] += con.damping * gi * gj;
                }
            }
        }
        (k, c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// K assembled from the constraints is the scene's K (modal.rs), on a
    /// 2D scene with a ground spring, a fixed end and a diagonal spring.
    #[test]
    fn constraints_give_the_scenes_stiffness() {
        let text = "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 2.0\npos = [0, 0]\n[[mass]]\nname = \"b\"\nkg = 1.0\npos = [1, 1]\n[[mass]]\nname = \"c\"\nkg = 1.0\npos = [2, 0]\nfixed = true\n[[spring]]\nbetween = [\"a\", \"ground\"]\nstiffness = 10\n[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 30\ndamping = 0.5\n[[spring]]\nbetween = [\"b\", \"c\"]\nstiffness = 7\n";
        let scene = SceneFile::parse("s.toml", text).unwrap();
        let model = Model::of_scene(&scene);
        assert_eq!(model.n(), 4);
        // Ground: two axes; a-b: one; b-c: one.
        assert_eq!(model.m(), 4);
        assert_eq!(model.cost(&Config::new(Solver::Xpbd, 3, 2).unwrap()), 24);
        let Body::Springs { masses, springs, dim } = &scene.body else { panic!() };
        let sys = super::super::super::modal::System::of_scene(masses, springs, *dim);
        let (k, c) = model.stiffness_damping();
        for i in 0..4 {
            for j in 0..4 {
                assert!((k[i * 4 + j] - sys.k.get(i, j)).abs() < 1e-12, "K[{i},{j}]");
                assert!((c[i * 4 + j] - sys.c.get(i, j)).abs() < 1e-12, "C[{i},{j}]");
            }
        }
        assert_eq!(model.w, vec![0.5, 0.5, 1.0, 1.0]);
    }

    /// Bad configurations are refused with the flag named.
    #[test]
    fn bad_configurations_are_refused() {
        let e = Config::new(Solver::Xpbd, 4, 0).unwrap_err().to_string();
        assert!(e.contains("--iterations 0"), "{e}");
        let e = Config::new(Solver::Xpbd, 0, 1).unwrap_err().to_string();
        assert!(e.contains("--substeps 0"), "{e}");
        let e = Config::new(Solver::SoftStep, 4, 2).unwrap_err().to_string();
        assert!(e.contains("--iterations 2") && e.contains("soft step"), "{e}");
        let e = Solver::parse("pbd").unwrap_err().to_string();
        assert!(e.contains("--solver pbd"), "{e}");
        assert!(Config::with_relaxation(Solver::XpbdJacobi, 1, 1, 2.5).is_err());
        assert_eq!(Solver::parse("soft_step").unwrap(), Solver::SoftStep);
    }
}
