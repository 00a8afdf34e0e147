//! Test helpers shared across the workspace: a dev-dependency of every
//! crate's tests, benches and of the fuzz targets, never of a library.
//!
//! - [`snapshot`]: insta's snapshot path, `snapshots/<dir>/` at the top;
//! - [`random_program`]: random linear `.zm` programs for property tests;
//! - [`programs`]: generated large programs (spring chains, long chains of
//!   temporaries) for the benches and the tests of large derivations;
//! - [`oracle`]: slow, obvious answers for the fast paths to be held to;
//! - [`scratch`]: files for the CLI's tests, removed when dropped;
//! - [`fuzz`]: the bodies of the fuzz targets, and [`replay`], which runs a
//!   target's committed corpus through its body as an ordinary test.

pub mod oracle;
pub mod programs;
pub mod random_program;
pub mod replay;
pub mod scratch;
pub mod snapshot;

/// The bodies of the fuzz targets, one function per target.
pub mod fuzz {
    #[cfg(feature = "app")]
    pub use crate::fuzz_app::{order_toml, scene_toml, tableau};
    pub use crate::fuzz_poly::{parse, parse_derive, stability};
}

#[cfg(feature = "app")]
mod fuzz_app;
mod fuzz_poly;
