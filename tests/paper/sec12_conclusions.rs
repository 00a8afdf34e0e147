//! Section 12 Conclusions.
