//! `zcheck region`: the method on the scalar test equation y' = λy in the
//! (the arguments and the printing; the answer is `crate::answers::region`)

use super::format::{Format, TEXT_JSON};
use super::output;
use crate::answers::plane::*;
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::values::{self, ParamArg};
use serde_json::Value;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `zcheck region`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// Methods: built-ins, `.zm` files (scalar in `w`, or oscillator), or
    /// `.toml` files (a Butcher tableau, or `alpha`/`beta` of a linear
    /// multistep method).
    #[arg(required = true)]
    pub methods: Vec<String>,
    /// A parameter value, `NAME=VALUE` (exact); repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub params: Vec<ParamArg>,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
    /// Draw the stability regions (overlaid) as SVG here.
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let values = crate::load::values_of_args(&args.params);
    let loaded: Vec<LoadedMethod> = args
        .methods
        .iter()
        .map(|m| LoadedMethod::load_for_plane_with(m, &values))
        .collect::<Result<_, _>>()?;
    let params =
        crate::load::unclaimed(&args.params, |p| &p.name, &loaded.iter().collect::<Vec<_>>());
    let methods: Vec<&poly::Method> = loaded.iter().map(LoadedMethod::method).collect();
    values::check_declared(&params, &methods)?;
    let mut reports = Vec::new();
    for (arg, m) in args.methods.iter().zip(&loaded) {
        let (shown, report, classical) = plane(arg, m, &params)?;
        reports.push((m.method().name().to_owned(), shown, report, classical));
    }
    if let Some(path) = &args.svg {
        let figs: Vec<(String, poly::PlaneReport)> =
            reports.iter().map(|(n, _, r, _)| (n.clone(), r.clone())).collect();
        crate::answers::plane::figure(&figs, path)?;
    }
    let out = match args.format {
        Format::Json => {
            let docs: Vec<Value> =
                reports.iter().map(|(n, p, r, o)| to_json(n, p, r, *o)).collect();
            let doc = if docs.len() == 1 { docs[0].clone() } else { Value::Array(docs) };
            serde_json::to_string_pretty(&doc)? + "\n"
        }
        _ => reports.iter().map(|(n, p, r, o)| to_text(n, p, r, *o)).collect::<Vec<_>>().join("\n"),
    };
    output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
