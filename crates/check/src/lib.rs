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

pub mod classify;
mod error;
pub mod load;
pub mod numeric;
pub mod sweep;
pub mod witness;

pub use crate::error::{Error, ErrorKind};

/// The README's examples, run as doctests so the front page never lies.
#[cfg(doctest)]
#[doc = include_str!("../../../README.md")]
pub struct ReadmeDoctests;
