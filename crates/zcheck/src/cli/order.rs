//! `zcheck order`: the classical order and what an analyst asks next, of
//! methods read as tableaux, partitioned pairs, splittings or multistep
//! methods (the arguments and the printing; the answer is
//! `crate::answers::order`).

use std::process::ExitCode;

use super::format::{Format, TEXT_JSON};
use super::output;
use crate::answers::order::{document, report, to_text, Request};
use crate::error::Error;
use crate::readings::Reading;
use crate::values::ParamArg;

/// Arguments of `zcheck order`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// Methods: `.toml` files (a Butcher tableau `A`, `b`, `c`, with `bhat`
    /// for an embedded pair; a partitioned pair `[q]`, `[p]`; a splitting
    /// `drift`, `kick`; a multistep method `alpha`, `beta`) or built-ins
    /// with a nonlinear reading (`zcheck methods`).
    #[arg(required = true)]
    pub methods: Vec<String>,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
    /// The modified equation up to h^N (Runge–Kutta tableaux), N from 1 to 10.
    #[arg(long, value_name = "N")]
    pub modified: Option<usize>,
    /// The order whose conditions hold to within T as well (default: 1e-12
    /// when an entry is a decimal of 10 or more significant digits).
    #[arg(long, value_name = "T")]
    pub tolerance: Option<String>,
    /// A value for a parameter a tableau declares (`params = ["c"]`),
    /// `NAME=VALUE` (exact); repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub params: Vec<ParamArg>,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let request = Request::parse(args.modified, args.tolerance.as_deref())?;
    let values = crate::load::values_of_args(&args.params);
    let mut reports = Vec::new();
    for arg in &args.methods {
        let reading = Reading::load(arg, &values)?;
        let r = report(&reading, &request)?;
        reports.push((arg.clone(), reading, r));
    }
    crate::values::check_taken(&args.params, reports.iter().flat_map(|(_, g, _)| &g.params))?;
    let out = match args.format {
        Format::Json => serde_json::to_string_pretty(&document(&reports))? + "\n",
        _ => reports.iter().map(|(a, g, r)| to_text(a, g, r)).collect::<Vec<_>>().join("\n"),
    };
    output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
