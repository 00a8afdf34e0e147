//! Layer 5, derivation: a [`Method`](crate::Method) to its z-domain matrix
//! M(z), its transition matrix P, and its characteristic polynomial χ(z),
//! by two independent routes that must agree (the polynomial-matrix
//! determinant det M(z), and det(zI − P)), with implicit steps solved
//! exactly as a linear system.
//!
//! Imports only from the layers below.

pub(crate) mod implicit;
pub(crate) mod oscillator;
pub(crate) mod routes;
