//! Section 7 False Euler.
