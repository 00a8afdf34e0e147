//! `zcheck derive`: a method's derivation as text, JSON or LaTeX.
//! (the arguments and the printing; the answer is `crate::answers::derive`)

use super::format::Format;
use crate::answers::derive::*;
use crate::error::Error;
use crate::load::LoadedMethod;
use poly::Derivation;
use serde_json::json;
use std::process::ExitCode;

/// The formats `zcheck derive` writes.
const FORMATS: &[Format] = &[Format::Text, Format::Json, Format::Latex];

/// Arguments of `zcheck derive`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// A built-in method name, a path to a `.zm` file, or a `.toml` file.
    pub method: String,
    /// A value for a parameter a tableau declares (`params = ["c"]`),
    /// `NAME=VALUE` (exact); repeatable. A program's parameters stay
    /// symbolic.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub params: Vec<crate::values::ParamArg>,
    #[arg(long, value_parser = Format::parser(FORMATS), default_value = "text")]
    pub format: Format,
    /// Also print M(z) with one row per assignment (temporaries included),
    /// for programs of at most 256 assignments; by default M(z) is printed
    /// over the values the step keeps, with the temporaries eliminated.
    #[arg(long)]
    pub full_z_matrix: bool,
}

/// The largest M(z) `--full-z-matrix` prints: 256 rows make 65,536
/// entries, most of them 0.
const FULL_Z_MATRIX_ROWS: usize = 256;

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let method = LoadedMethod::load_with(&args.method, &crate::load::values_of_args(&args.params))?;
    crate::values::check_taken(&args.params, method.tableau_params())?;
    let d = method.derivation()?;
    let full = args.full_z_matrix;
    if full && d.z_matrix().rows() > FULL_Z_MATRIX_ROWS {
        return Err(Error::usage(format!(
            "--full-z-matrix: M(z) of {} has {} rows, and prints at most {FULL_Z_MATRIX_ROWS} ({} entries); expected a shorter program, or no --full-z-matrix for M(z) over the state ({} rows)",
            d.method().name(),
            d.z_matrix().rows(),
            d.z_matrix().rows() * d.z_matrix().rows(),
            d.z_matrix_reduced().labels.len(),
        )));
    }
    let out = match args.format {
        Format::Json => {
            let mut v = to_json(d);
            if full {
                v["z_matrix_full"] = json!(full_rows(d, &Derivation::z_entry_string));
            }
            serde_json::to_string_pretty(&v)? + "\n"
        }
        Format::Latex => latex(d, full),
        _ => text(d, full),
    };
    super::output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
