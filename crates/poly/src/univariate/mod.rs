//! Layer 2, polynomials in one variable: dense [`UPoly`](upoly::UPoly) over
//! Q and their integer forms, determinants and resultants over Z\[Φ\] by
//! modular evaluation, Sturm sequences, Descartes isolation, rational
//! roots, real algebraic numbers and arithmetic in Q(α).
//!
//! Imports only from `arith`.

pub(crate) mod algebraic;
pub(crate) mod isolate;
pub(crate) mod modular;
pub(crate) mod number_field;
pub(crate) mod rational_roots;
pub(crate) mod roots;
pub mod sturm;
pub(crate) mod upoly;
