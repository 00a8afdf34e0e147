//! Speed versus accuracy: the paper's four criteria side by side.
//!
//! Section 1 judges a method by (1) stability, (2) frequency deviation,
//! (3) calculations per step and (4) the largest allowed step. This module
//! puts the four together for a programmer with a target:
//!
//! - cost per step, exact, from the method definition ([`poly::advanced::cost`]), and
//!   measured on the compiled step of any method (`measure`), with the
//!   hand-written kernels ([`kernels`]) as a baseline;
//! - accuracy per step from the exact characteristic polynomial
//!   (`accuracy`): phase error Ψ − Φ and amplitude factor per period;
//! - the exact stability limit Φ_max (`poly::advanced::stability`), which no answer
//!   ever reaches (`family`);
//! - the trade: the largest admissible Φ for a target, steps per period, cost
//!   per simulated period, a ranking and a work-precision figure
//!   (`rank`, `figure`);
//! - the single-spring advisor, in game units: spring frequency and tick
//!   rate in Hz (`spring_advisor`; a whole scene is
//!   [`crate::scene::advisor`]'s).
//!
//! The submodules import one another directly, never through this file,
//! which only names `Rank`, the one type the advisors share.

pub(crate) mod accuracy;
pub(crate) mod family;
pub(crate) mod figure;
pub mod kernels;
pub(crate) mod measure;
pub(crate) mod rank;
pub(crate) mod spring_advisor;

pub(crate) use rank::Rank;

#[cfg(test)]
mod tests;
