//! Section 4 z-Transformation.
