//! Truncated power series over Q (placeholder, filled in next).
