//! Numeric witnesses for zcheck's exact derivations.
//!
//! `check` is the numeric half of zcheck. It reads the same lowered `.zm`
//! methods as `poly` and checks the exact characteristic polynomials against
//! independent numeric evidence: eigenvalues of the numeric transition matrix
//! (nalgebra and faer), roots of the exact polynomial, and long-run
//! simulation. It also hosts the proof report, the appendix scenes and the
//! speed/accuracy trade-off. It depends on `poly`; `poly` never depends on it.

pub mod classify;
pub mod load;
pub mod numeric;
pub mod overview;
pub mod paper;
pub mod plot;
pub mod scene;
pub mod sweep;
pub mod tradeoff;
pub mod witness;
