//! The command line: the [`Cli`] clap parses, and one module per subcommand
//! with its clap `Args` and its `run`.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

use crate::error::Error;

pub mod advise;
pub mod derive;
pub mod drift;
pub mod emit;
pub mod equiv;
pub mod from_tableau;
pub mod map;
pub mod methods;
pub mod output;
pub mod overview;
pub mod paper;
pub mod plot;
pub mod scene;
pub mod stability;
pub mod tradeoff;
pub mod values;
pub mod verify;

/// Characteristic-polynomial verifier for simple time integrators
/// (Hoffmann, "Simple Integration Algorithms").
#[derive(Parser)]
#[command(name = "zcheck", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// List the built-in methods.
    Methods(methods::Args),
    /// Derive a method's transition matrix and characteristic polynomial.
    Derive(derive::Args),
    /// Check derived polynomials against eigenvalues and long-run simulation.
    Verify(verify::Args),
    /// Draw figures (SVG).
    Plot(plot::Args),
    /// Every paper method side by side: exact limit, Psi and |z|^2 series, cost.
    Overview(overview::Args),
    /// Exact stability limit and class changes of a method.
    Stability(stability::Args),
    /// Print the executable proof of the paper (the main job).
    Paper(paper::Args),
    /// Cost, accuracy and admissible step of every method, side by side.
    Tradeoff(tradeoff::Args),
    /// Advise a method and substeps for a spring in a game scene.
    Advise(advise::Args),
    /// Run an appendix scene (three bodies, aircraft).
    Scene(scene::Args),
    /// The strongest identity between two methods (equal, permuted, scaled, same chi).
    Equiv(equiv::Args),
    /// Exact stability region in (Phi, D), drawn over a grid of root classes.
    Map(map::Args),
    /// Round-off drift of a method's exact conserved form over long runs.
    Drift(drift::Args),
    /// Print a method's step as a Rust or C function.
    Emit(emit::Args),
    /// Write the .zm program of a Runge-Kutta method from its Butcher tableau (TOML).
    FromTableau(from_tableau::Args),
}

impl Cli {
    /// Runs the subcommand: its exit code (a verification that disagrees
    /// is a failure, not an error), or why it could not run.
    pub fn run(self) -> Result<ExitCode, Error> {
        match self.command {
            Command::Methods(a) => methods::run(a),
            Command::Derive(a) => derive::run(a),
            Command::Verify(a) => verify::run(a),
            Command::Plot(a) => plot::run(a),
            Command::Overview(a) => overview::run(a),
            Command::Stability(a) => stability::run(a),
            Command::Paper(a) => paper::run(a),
            Command::Tradeoff(a) => tradeoff::run(a),
            Command::Advise(a) => advise::run(a),
            Command::Scene(a) => scene::run(a),
            Command::Equiv(a) => equiv::run(a),
            Command::Map(a) => map::run(a),
            Command::Drift(a) => drift::run(a),
            Command::Emit(a) => emit::run(a),
            Command::FromTableau(a) => from_tableau::run(a),
        }
    }
}
