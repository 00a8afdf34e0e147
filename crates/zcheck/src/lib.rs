//! The zcheck application: everything only the command-line tool needs.
//!
//! - [`paper`]: the proof of Hoffmann's paper as data (claims, verdicts,
//!   evidence) and its Markdown/JSON report;
//! - [`overview`]: every method side by side (exact limit, series, cost);
//! - [`tradeoff`]: the speed/accuracy trade and the spring advisor;
//! - [`scene`]: the appendix scenes (three bodies, aircraft);
//! - [`plot`]: SVG figures;
//! - [`map`]: the exact (Φ, D) stability map of a damped method.
//!
//! The exact algebra lives in `poly`, the numeric witnesses in `check`; this
//! crate depends on both and neither depends on it.

pub mod cli;
mod drift_figure;
pub mod emit;
mod error;
pub mod load;
mod map;
pub mod overview;
pub mod paper;
pub mod plot;
pub mod scene;
pub mod tableau;
pub mod tradeoff;

pub use error::{Error, ErrorKind, Location};
