//! Section 5 Standard Euler.
