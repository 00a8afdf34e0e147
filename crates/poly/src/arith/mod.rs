//! Layer 1, arithmetic: the exact scalar [`Q`], integer gcds, and all of
//! Z/p (primes, Montgomery arithmetic, CRT, interpolation, determinants and
//! polynomial remainders modulo p).
//!
//! Imports nothing from the crate above it.

pub(crate) mod fixed;
pub(crate) mod int;
pub(crate) mod intgcd;
pub(crate) mod rational;
pub(crate) mod zp;
