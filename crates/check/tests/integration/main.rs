//! Integration tests of the `check` crate, built as one test binary.
//!
//! - `numeric`: the compiled step against exact arithmetic;
//! - `witness`: the four witnesses agree at defaults and at class boundaries;
//! - `extremes`: tiny and huge Φ, Jordan blocks;
//! - `snapshots`: rounded summaries of sweeps and verification.

mod extremes;
mod kernel;
mod numeric;
#[path = "../../../../tests/support/snapshot.rs"]
mod snapshot;
mod snapshots;
mod stability_scan;
mod witness;
