//! Section 11 Semi-False Heun.
