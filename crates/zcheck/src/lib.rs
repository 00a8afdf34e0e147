//! The zcheck application: everything only the command-line tool needs.
//! The binary only calls [`cli::main`]; this library is public for the
//! tests, benchmarks and fuzz targets, and shows them only what they use.
//!
//! - [`api`]: the door of other front ends (the Python package): each
//!   question answered by the JSON document its command prints;
//! - [`cli`]: one module per subcommand, the one output `Format`, and the
//!   reporting of an [`Error`] (exit code 2);
//! - [`load`]: a method argument (built-in, `.zm` file, Butcher tableau)
//!   resolved once, with its one derivation;
//! - [`tableau`]: Butcher tableaux read from TOML, and `multistep`: linear
//!   multistep methods (`alpha`, `beta`) read from TOML; `partitioned`:
//!   partitioned pairs (`[q]`, `[p]`) and splittings (`drift`, `kick`);
//!   `readings`: a method's nonlinear reading (what `zcheck order` reads);
//! - `region`: the w-plane report (JSON, text, SVG) of `zcheck region`;
//! - [`paper`]: the proof of Hoffmann's paper as data (claims, verdicts,
//!   evidence) and its Markdown/JSON report;
//! - [`overview`]: every method side by side (exact limit, series, cost);
//! - [`tradeoff`]: the speed/accuracy trade, and the single-spring advisor;
//! - [`scene`]: the appendix scenes (three bodies, aircraft), and a user's
//!   scene of masses and springs with the whole-scene advisor;
//! - [`emit`]: a method's step as Rust or C source;
//! - [`plot`], `map`, `param_map`, `drift_figure`: SVG figures, the exact
//!   (Φ, p) stability map of a method's one parameter, and the map over
//!   two parameters coloured by the exact Φ_max; `spectral`: the spectral
//!   radius, period elongation and algorithmic damping (Hughes, ch. 9).
//!
//! The exact algebra lives in `poly`, the numeric witnesses in `check`; this
//! crate depends on both and neither depends on it.

#![warn(unreachable_pub)]

mod answers;
pub mod api;
pub mod cli;
mod drift_figure;
pub mod emit;
mod error;
mod interrupt;
pub mod load;
mod multistep;
pub mod native;
pub mod overview;
pub mod paper;
mod partitioned;
pub mod plot;
pub mod readings;
pub mod scene;
mod spectral;
pub mod tableau;
pub mod tradeoff;
pub(crate) mod values;
mod warn;

pub use error::{Error, ErrorKind, Location};
