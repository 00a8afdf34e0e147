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
    /// Print the executable proof of the paper (the main job).
    Paper(cli::paper::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Methods(a) => cli::methods::run(a),
        Command::Derive(a) => cli::derive::run(a),
        Command::Paper(a) => cli::paper::run(a),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
