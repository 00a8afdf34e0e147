//! Section 9 Standard Heun.
