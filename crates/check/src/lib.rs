//! Numeric witnesses for zcheck's exact derivations.
//!
//! `check` is the numeric half of zcheck. It reads the same lowered `.zm`
//! methods as `poly` and checks the exact characteristic polynomials against
//! independent numeric evidence. It depends on `poly`; `poly` never depends on
//! it.

pub mod load;
