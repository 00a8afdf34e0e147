#![deny(missing_docs)]
//! Numeric witnesses for zcheck's exact derivations.
//!
//! `check` is the numeric half of zcheck. It reads the same lowered `.zm`
//! methods as `poly` and checks the exact characteristic polynomials against
//! independent numeric evidence: eigenvalues of the numeric transition matrix
//! (nalgebra and faer), roots of the exact polynomial, and long-run
//! simulation. It depends on `poly`; `poly` never depends on it. The
//! application (CLI, proof report, scenes, trade-off, plots) lives in the
//! `zcheck` crate, which depends on this one.
//!
//! ```
//! use check::ParamsF64;
//! let d = poly::derive_source("mine.zm", "method mine\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n")?;
//! let witnesses = check::witness::Witnesses::from_derivation(&d);
//! for phi in [0.1, 1.0, 1.9] {
//!     let point = witnesses.at(&check::Params::phi(phi), 20_000)?;
//!     assert!(point.agree(), "every witness agrees with the exact χ at Φ = {phi}");
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Parameters
//!
//! There is one parameter type, [`poly::Params`], exact. [`ParamsF64`] is its
//! `f64` view: an `f64` is stored as the rational it is, and read back as the
//! nearest double. A value a user typed as a decimal is parsed exactly by
//! `poly` and stays that decimal on the exact side.
//!
//! # Input safety
//!
//! Nothing here panics on user input: parse errors, missing parameters,
//! non-finite values and solvers that fail to converge are all [`Error`]s.
//! The eigenvalue solvers run under an iteration bound; a simulation is
//! bounded by the step count the caller gives and rescales its state by exact
//! powers of two, so unstable runs never overflow. The setters of
//! [`ParamsF64`] panic on a non-finite `f64` (a programming error, like a
//! zero denominator); validate user input with [`ParamsF64::try_with`].
//!
//! # Error reporting
//!
//! [`Error`] is the crate's one error type: [`Error::kind`] to branch on, a
//! lower-case `Display` that says what was expected, and a `source()` chain.
//! A parse or derivation error shows `poly`'s located message
//! (`file:line:column: ...`) unchanged; an I/O error carries its path.

pub mod classify;
pub mod drift;
mod error;
#[cfg(feature = "jit")]
pub mod jit;
pub mod kernel;
pub mod load;
pub mod numeric;
pub mod sweep;
pub mod witness;

pub use crate::error::{Error, ErrorKind};
pub use crate::numeric::{Params, ParamsF64};

/// Every numeric witness of an existing derivation at one point: the
/// eigenvalues of P (nalgebra, faer) and a `steps`-step simulation, each
/// held against the exact χ by the tolerance model ([`witness`]).
///
/// ```
/// use check::ParamsF64;
/// let d = poly::derive(&poly::builtin("false_euler")?)?;
/// let point = check::verify(&d, &check::Params::phi(0.5), 10_000)?;
/// assert!(point.agree());
/// assert!((point.exact.spectral_radius - 1.0).abs() < 1e-15);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn verify(
    derivation: &poly::Derivation,
    params: &Params,
    steps: u64,
) -> Result<witness::PointReport, Error> {
    witness::Witnesses::from_derivation(derivation).at(params, steps)
}

/// The README's examples, run as doctests so the front page never lies.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
