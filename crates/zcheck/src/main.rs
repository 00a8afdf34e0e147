//! `zcheck`: the command-line face of zcheck.
//!
//! Each subcommand lives in its own module under `cli/` with its clap
//! arguments and a `run` function; this file only dispatches.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod cli;

/// Characteristic-polynomial verifier for simple time integrators
/// (Hoffmann, "Simple Integration Algorithms").
#[derive(Parser)]
#[command(name = "zcheck", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// List the built-in methods.
    Methods(cli::methods::Args),
    /// Derive a method's transition matrix and characteristic polynomial.
    Derive(cli::derive::Args),
    /// Check derived polynomials against eigenvalues and long-run simulation.
    Verify(cli::verify::Args),
    /// Draw figures (SVG).
    Plot(cli::plot::Args),
    /// Every paper method side by side: exact limit, Psi and |z|^2 series, cost.
    Overview(cli::overview::Args),
    /// Exact stability limit and class changes of a method.
    Stability(cli::stability::Args),
    /// Print the executable proof of the paper (the main job).
    Paper(cli::paper::Args),
    /// Cost, accuracy and admissible step of every method, side by side.
    Tradeoff(cli::tradeoff::Args),
    /// Advise a method and substeps for a spring in a game scene.
    Advise(cli::advise::Args),
    /// Run an appendix scene (three bodies, aircraft).
    Scene(cli::scene::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Methods(a) => cli::methods::run(a),
        Command::Derive(a) => cli::derive::run(a),
        Command::Verify(a) => cli::verify::run(a),
        Command::Plot(a) => cli::plot::run(a),
        Command::Overview(a) => cli::overview::run(a),
        Command::Stability(a) => cli::stability::run(a),
        Command::Paper(a) => cli::paper::run(a),
        Command::Tradeoff(a) => cli::tradeoff::run(a),
        Command::Advise(a) => cli::advise::run(a),
        Command::Scene(a) => cli::scene::run(a),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
