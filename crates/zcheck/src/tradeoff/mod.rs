//! Speed versus accuracy: the paper's four criteria side by side.
//!
//! Section 1 judges a method by (1) stability, (2) frequency deviation,
//! (3) calculations per step and (4) the largest allowed step. This module
//! puts the four together for a programmer with a target:
//!
//! - cost per step, exact, from the method definition ([`poly::cost`]), and
//!   measured on the compiled step of any method ([`measure`]), with the
//!   hand-written kernels ([`kernels`]) as a baseline;
//! - accuracy per step from the exact characteristic polynomial
//!   ([`accuracy`]): phase error Ψ − Φ and amplitude factor per period;
//! - the exact stability limit Φ_max (`poly::stability`), which no answer
//!   ever reaches ([`family`]);
//! - the trade: the largest admissible Φ for a target, steps per period, cost
//!   per simulated period, a ranking and a work-precision figure
//!   ([`rank`], [`figure`]);
//! - a scene advisor in game units: spring frequency and tick rate in Hz
//!   ([`advise`]).

pub mod accuracy;
pub mod advise;
pub mod family;
pub mod figure;
pub mod kernels;
pub mod measure;
pub mod rank;

pub use accuracy::{Accuracy, SecondOrder, Spring, Target};
pub use advise::{advise, Advice, MethodAdvice, Scene};
pub use family::{damped_family, undamped_family, Candidate, Limit};
pub use measure::{measure_ns_per_step, measure_ns_per_step_within};
pub use rank::{trade, TradeRow};
