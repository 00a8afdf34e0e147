//! Section 8 Verlet Integration.
