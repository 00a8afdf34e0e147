//! `zcheck stability`: the exact stability limit, the boundary kind and
//! (the arguments and the printing; the answer is `crate::answers::stability`)

use super::format::{Format, TEXT_JSON};
use super::output;
use crate::answers::stability::*;
use crate::error::Error;
use crate::load::{self, LoadedMethod};
use crate::values::ParamArg;
use std::process::ExitCode;

/// Arguments of `zcheck stability`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// A built-in method name, a path to a `.zm` file, or a `.toml` file (a
    /// Butcher tableau, or multistep coefficients).
    pub method: String,
    /// A parameter value, `NAME=VALUE`, with VALUE an integer, a fraction
    /// (`1/2`) or a decimal (`0.5`, `1e-12`, read exactly); repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub params: Vec<ParamArg>,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let loaded = LoadedMethod::load_with(&args.method, &load::values_of_args(&args.params))?;
    let params = load::unclaimed(&args.params, |p| &p.name, &[&loaded]);
    // The one derivation: χ, the report and the implicit facts all read it.
    let analysis = Analysis::of(loaded.derivation()?, &params)?;
    let out = match args.format {
        Format::Json => serde_json::to_string_pretty(&analysis.to_json())? + "\n",
        _ => analysis.text(),
    };
    output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
