//! The command line: the `Cli` clap parses, and one module per subcommand
//! with its clap `Args` and its `run`.

use std::process::ExitCode;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

use crate::error::Error;

pub(crate) mod advise;
pub(crate) mod derive;
pub(crate) mod design;
pub(crate) mod drift;
pub(crate) mod emit;
pub(crate) mod equiv;
pub(crate) mod format;
pub(crate) mod from_tableau;
pub(crate) mod map;
pub(crate) mod mesh;
pub(crate) mod methods;
pub(crate) mod order;
pub(crate) mod output;
pub(crate) mod overview;
pub(crate) mod paper;
pub(crate) mod plot;
pub(crate) mod region;
pub(crate) mod scene;
pub(crate) mod stability;
pub(crate) mod tradeoff;
pub(crate) mod verify;

/// Runs the command line: parses the arguments, runs the command, and exits
/// 0 on success (a verification that disagrees exits 1). Help and version
/// go to stdout; a usage error or a failed command is reported on stderr
/// with exit code 2. A reader that closes stdout early is no error.
pub fn main() -> ExitCode {
    // `--phi -1`, `--eps -0.5`: a negative number is a value, never a flag.
    let command = Cli::command().mut_subcommands(|s| s.allow_negative_numbers(true));
    let cli = match command.try_get_matches().and_then(|m| Cli::from_arg_matches(&m)) {
        Ok(cli) => cli,
        Err(e) => return output::clap_exit(&e),
    };
    match cli.run() {
        Ok(code) => code,
        // The reader closed stdout early: nothing is wrong.
        Err(e) if output::is_broken_pipe(&e) => ExitCode::SUCCESS,
        // Ctrl-C: a clean message (how far the run got), exit 130.
        Err(e) if e.kind() == crate::ErrorKind::Interrupted => {
            output::print_error(&format!("interrupted: {}", output::with_sources(&e)));
            ExitCode::from(crate::interrupt::EXIT_CODE)
        }
        Err(e) => {
            output::print_error(&format!("error: {}", output::with_sources(&e)));
            ExitCode::from(2)
        }
    }
}

/// Characteristic-polynomial verifier for simple time integrators
/// (Hoffmann, "Simple Integration Algorithms").
#[derive(Parser)]
#[command(name = "zcheck", version, about, long_about = None)]
pub(crate) struct Cli {
    /// Treat warnings (an unread value, a tableau whose weights do not sum
    /// to 1, a decimal that is probably 1/3) as errors: exit 2 before any
    /// output.
    #[arg(long, global = true)]
    deny_warnings: bool,
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
    Advise(Box<advise::Args>),
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
    /// The method on y' = λy in the complex w = hλ plane: classical and linear order, error constant, axis limits, A(α), ρ∞.
    Region(region::Args),
    /// Classical order by rooted trees, stage order, algebraic stability, symplecticity, SSP coefficient, embedded order, modified equation.
    Order(order::Args),
    /// Choose one or two free parameters for the best exact stability (Phi_max, real or imaginary limit, SSP coefficient), with a certificate.
    Design(design::Args),
    /// Write a scene (TOML) from a triangle mesh (OBJ): particles, edge and bending springs.
    SceneFromMesh(mesh::Args),
}

impl Cli {
    /// Runs the subcommand: its exit code (a verification that disagrees
    /// is a failure, not an error), or why it could not run.
    pub(crate) fn run(self) -> Result<ExitCode, Error> {
        crate::warn::deny(self.deny_warnings);
        match self.command {
            Command::Methods(a) => methods::run(a),
            Command::Derive(a) => derive::run(a),
            Command::Verify(a) => verify::run(a),
            Command::Plot(a) => plot::run(a),
            Command::Overview(a) => overview::run(a),
            Command::Stability(a) => stability::run(a),
            Command::Paper(a) => paper::run(a),
            Command::Tradeoff(a) => tradeoff::run(a),
            Command::Advise(a) => advise::run(*a),
            Command::Scene(a) => scene::run(a),
            Command::Equiv(a) => equiv::run(a),
            Command::Map(a) => map::run(a),
            Command::Drift(a) => drift::run(a),
            Command::Emit(a) => emit::run(a),
            Command::FromTableau(a) => from_tableau::run(a),
            Command::Region(a) => region::run(a),
            Command::Order(a) => order::run(a),
            Command::Design(a) => design::run(a),
            Command::SceneFromMesh(a) => mesh::run(a),
        }
    }
}
