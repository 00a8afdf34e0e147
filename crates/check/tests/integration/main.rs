//! Integration tests of the `check` crate, built as one test binary.
//!
//! - `jit` (feature `jit`): the native step bit for bit against the interpreter;
//! - `numeric`: the compiled step against exact arithmetic;
//! - `witness`: the four witnesses agree at defaults and at class boundaries;
//! - `extremes`: tiny and huge Φ, Jordan blocks;
//! - `snapshots`: rounded summaries of sweeps and verification.

mod extremes;
#[cfg(feature = "jit")]
mod jit;
mod kernel;
mod numeric;
use testkit::snapshot;
mod snapshots;
mod stability_scan;
mod witness;
