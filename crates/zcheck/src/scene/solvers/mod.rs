//! The solvers game engines run, analysed exactly where the scene is small
//! and numerically where it must be (issue 36): XPBD with substeps and
//! iterations (Gauss–Seidel, `xpbd`, or Jacobi, `xpbd_jacobi`; "small
//! steps" is `xpbd` with one iteration) and Box2D v3's soft step
//! (`soft_step`). A scene of linear(ised) springs makes each solver's
//! substep a linear map of its state, so stability, effective frequencies
//! and damping, and the phase and amplitude errors over the scene's
//! duration follow from that map's eigenvalues; the search finds the
//! cheapest (substeps, iterations) meeting the targets.
//!
//! Files by concern: `model` (the constraints of a scene, the solver
//! configuration and its cost), `kernel` (each solver's substep over any
//! field: the simulation, the numeric and the exact maps), `exact` (the map
//! over Q, its characteristic polynomial and stability by `poly`'s root
//! classes; the exact null space of the constraint Jacobian), `dense`
//! (faer linear algebra and the pairing assignment), `analysis` (one
//! configuration), `search` (the search and the entry
//! [`solver_advice`]), `figure` (`zcheck plot solvers`: error against cost
//! over (S, N), and the small-steps comparison).

mod analysis;
mod dense;
mod exact;
pub(crate) mod figure;
mod kernel;
mod model;
mod search;
#[cfg(test)]
mod tests;

pub(crate) use analysis::ConfigAdvice;
pub(crate) use model::Solver;
pub(crate) use search::{solver_advice, solver_advice_relaxed, Answer, SolverAdvice};
