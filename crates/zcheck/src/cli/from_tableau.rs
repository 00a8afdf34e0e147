//! `zcheck from-tableau`: a Butcher tableau (TOML) as the `.zm` program of
//! its Runge–Kutta method on the oscillator (`zcheck::tableau`).

use std::process::ExitCode;

use crate::error::Error;
use crate::tableau::Tableau;
use crate::values::ParamArg;

/// Arguments of `zcheck from-tableau`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// A TOML file with `A`, `b` (and optionally `c`, `name`); entries are
    /// integers or strings of exact numbers and constant expressions, such
    /// as "1/4 - sqrt(3)/6".
    pub file: String,
    /// Write the program for the damped oscillator (`param D`).
    #[arg(long)]
    pub damped: bool,
    /// A value for a parameter the tableau declares (`params = ["c"]`),
    /// `NAME=VALUE` (exact); repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub params: Vec<ParamArg>,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let (shown, stem, text) = crate::tableau::read_file(std::path::Path::new(&args.file))?;
    let values = crate::load::values_of_args(&args.params);
    let tableau = Tableau::parse_bound(&shown, &stem, &text, &values)?;
    crate::values::check_taken(&args.params, tableau.bound().iter().map(|(n, _)| n))?;
    crate::warn::report(tableau.warnings().to_vec())?;
    let src = tableau.to_zm(args.damped);
    // The program parses (and derives) before it is printed.
    poly::Method::parse(&args.file, &src).map_err(|e| {
        Error::method(format!(
            "{}: the generated program does not parse: {}",
            args.file,
            e.message()
        ))
    })?;
    super::output::emit(&src)?;
    Ok(ExitCode::SUCCESS)
}
