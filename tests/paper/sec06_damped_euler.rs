//! Section 6 Damped Euler.
