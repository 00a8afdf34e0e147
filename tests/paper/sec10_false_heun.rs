//! Section 10 False Heun.
