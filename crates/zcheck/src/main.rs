//! `zcheck`: the command-line face of zcheck.
//!
//! Each subcommand lives in its own module under `cli/` with its clap
//! arguments and a `run` function; this file only dispatches.

use std::io::Write as _;
use std::process::ExitCode;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

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
    /// The strongest identity between two methods (equal, permuted, scaled, same chi).
    Equiv(cli::equiv::Args),
    /// Exact stability region in (Phi, D), drawn over a grid of root classes.
    Map(cli::map::Args),
    /// Round-off drift of a method's exact conserved form over long runs.
    Drift(cli::drift::Args),
    /// Print a method's step as a Rust or C function.
    Emit(cli::emit::Args),
    /// Write the .zm program of a Runge-Kutta method from its Butcher tableau (TOML).
    FromTableau(cli::from_tableau::Args),
}

/// The most bytes of an error message printed: enough for any real error,
/// and a bound on what a hostile input can put on the terminal.
const MAX_ERROR_BYTES: usize = 4000;

fn main() -> ExitCode {
    // `--phi -1`, `--eps -0.5`: a negative number is a value, never a flag.
    let command = Cli::command().mut_subcommands(|s| s.allow_negative_numbers(true));
    let cli = match command.try_get_matches().and_then(|m| Cli::from_arg_matches(&m)) {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
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
        Command::Equiv(a) => cli::equiv::run(a),
        Command::Map(a) => cli::map::run(a),
        Command::Drift(a) => cli::drift::run(a),
        Command::Emit(a) => cli::emit::run(a),
        Command::FromTableau(a) => cli::from_tableau::run(a),
    };
    match result {
        Ok(code) => code,
        // The reader closed stdout early: nothing is wrong.
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            print_error(&format!("error: {e:#}"));
            ExitCode::from(2)
        }
    }
}

/// Help and version go to stdout with exit 0; usage errors to stderr, made
/// safe to print (the user's argument is echoed), with exit 2.
fn clap_exit(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    let text = e.render().to_string();
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => match cli::output::emit(&text) {
            Ok(()) => ExitCode::SUCCESS,
            Err(_) => ExitCode::from(2),
        },
        _ => {
            print_error(&text);
            ExitCode::from(2)
        }
    }
}

fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<std::io::Error>()
            .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

/// Prints an error on stderr: control and invisible characters (other than
/// line feeds) as `U+XXXX`, and at most [`MAX_ERROR_BYTES`]. A failure to
/// write stderr is ignored: there is nowhere left to report it.
fn print_error(text: &str) {
    let lines: Vec<String> =
        text.trim_end().split('\n').map(|l| poly::show_invisible(l).into_owned()).collect();
    let mut shown = lines.join("\n");
    if shown.len() > MAX_ERROR_BYTES {
        let mut cut = MAX_ERROR_BYTES;
        while !shown.is_char_boundary(cut) {
            cut -= 1;
        }
        let more = shown.len() - cut;
        shown.truncate(cut);
        shown.push_str(&format!("… ({more} more bytes)"));
    }
    let _ = writeln!(std::io::stderr().lock(), "{shown}");
}
