//! Layer 3, polynomials in several symbols: [`Sym`](sym::Sym), canonical
//! sparse [`Poly`](poly::Poly) over Q, polynomial matrices with their
//! determinants (sparse Berkowitz and the modular route), and the field F of
//! exact constants (√n, ∛n) that a method's coefficients may hold.
//!
//! Imports only from `arith` and `univariate`.

pub mod constants;
pub(crate) mod matrix;
pub(crate) mod poly;
pub(crate) mod resultant;
pub(crate) mod sym;
