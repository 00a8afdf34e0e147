//! Layer 6, the questions asked of a derivation: stability over Φ (one
//! engine, for rational χ and χ with exact constants alike), the root
//! classes, series of Ψ and |z|², the (Φ, parameter) region, equivalence of
//! two methods, the conserved form, the cost per step, and the exact
//! optimiser of free parameters (design).
//!
//! Imports from every layer below; nothing imports it but the crate root.

pub(crate) mod class;
pub mod cost;
pub mod design;
pub mod equiv;
pub mod invariant;
pub mod order;
pub mod plane;
pub mod region;
pub mod series;
pub(crate) mod singular;
pub mod stability;
