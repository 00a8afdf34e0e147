//! The fuzz targets' bodies live in the workspace's `testkit` crate
//! (`testkit::fuzz`), where `cargo test --workspace` also replays the
//! committed corpora through them; the targets here call them.

pub use testkit::fuzz::*;
