//! `zcheck design`: the free parameters of a method chosen for the best
//! exact stability, with a certificate (the arguments and the printing; the
//! answer is `crate::answers::design`).

use std::process::ExitCode;

use super::format::{Format, TEXT_JSON};
use super::output;
use crate::answers::design::{design, to_json, to_text, Request, Subject};
use crate::error::Error;

/// Arguments of `zcheck design`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// The method: a `.zm` program with `param` declarations (an oscillator
    /// program in Phi, or a scalar program in `w` for y' = λy), or a `.toml`
    /// Butcher tableau whose entries name the parameters it declares in
    /// `params = ["c"]`.
    pub method: String,
    /// The objective: phi_max, real_limit, imag_limit or ssp_coefficient.
    #[arg(long, value_name = "OBJECTIVE")]
    pub maximize: String,
    /// NAME=LO..HI: a free parameter and its exact range (one or two);
    /// NAME=VALUE: a bound parameter. Repeatable.
    #[arg(long = "param", value_name = "NAME=LO..HI", allow_hyphen_values = true)]
    pub params: Vec<String>,
    /// Keep only the values where the classical order (a tableau) or the
    /// linear order (a program) is at least P.
    #[arg(long, value_name = "P")]
    pub min_order: Option<usize>,
    /// Divide the objective by the stage count (stage) or by the step's
    /// multiplications (cost).
    #[arg(long, value_name = "stage|cost")]
    pub per: Option<String>,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let request =
        Request::parse(&args.maximize, &args.params, args.min_order, args.per.as_deref())?;
    let subject = Subject::load(&args.method, request.bound())?;
    let answer = design(&subject, &request)?;
    let out = match args.format {
        Format::Json => serde_json::to_string_pretty(&to_json(&answer))? + "\n",
        _ => to_text(&answer),
    };
    output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
