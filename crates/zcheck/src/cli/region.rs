//! `zcheck region`: the method on the scalar test equation y' = λy in the
//! complex plane of w = hλ — order, error constant, the real and imaginary
//! stability limits, A- and L-stability, A(α) and ρ∞, all exact
//! (`Derivation::plane`) — for one method or several, with an optional SVG
//! of the regions overlaid.
//!
//! A method is a built-in with a scalar form, a Butcher tableau or
//! linear-multistep `.toml`, or a `.zm` program (a scalar one in `w`, or an
//! oscillator one that treats y and v alike).

use std::path::PathBuf;
use std::process::ExitCode;

use poly::Q;
use serde_json::Value;

use super::format::{Format, TEXT_JSON};
use super::output;
use super::values::{self, ParamArg};
use crate::error::Error;
use crate::load::LoadedMethod;

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
    let loaded: Vec<LoadedMethod> =
        args.methods.iter().map(|m| LoadedMethod::load_for_plane(m)).collect::<Result<_, _>>()?;
    let methods: Vec<&poly::Method> = loaded.iter().map(LoadedMethod::method).collect();
    values::check_declared(&args.params, &methods)?;
    let mut reports = Vec::new();
    for (arg, m) in args.methods.iter().zip(&loaded) {
        let (shown, report) = plane(arg, m, &args.params)?;
        reports.push((m.method().name().to_owned(), shown, report));
    }
    if let Some(path) = &args.svg {
        let figs: Vec<(String, poly::PlaneReport)> =
            reports.iter().map(|(n, _, r)| (n.clone(), r.clone())).collect();
        crate::region::figure(&figs, path)?;
    }
    let out = match args.format {
        Format::Json => {
            let docs: Vec<Value> =
                reports.iter().map(|(n, p, r)| crate::region::to_json(n, p, r)).collect();
            let doc = if docs.len() == 1 { docs[0].clone() } else { Value::Array(docs) };
            serde_json::to_string_pretty(&doc)? + "\n"
        }
        _ => reports
            .iter()
            .map(|(n, p, r)| crate::region::to_text(n, p, r))
            .collect::<Vec<_>>()
            .join("\n"),
    };
    output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}

/// The w-plane report of one method (shown as `arg` in an error), with the
/// parameters it declares bound from `params` and the others left out
/// (`zcheck region` takes one list for all its methods): the values bound,
/// and the report.
pub(crate) fn plane(
    arg: &str,
    m: &LoadedMethod,
    params: &[ParamArg],
) -> Result<(Vec<(String, Q)>, poly::PlaneReport), Error> {
    let mut bound = poly::Params::new();
    let mut shown: Vec<(String, Q)> = Vec::new();
    for p in params {
        if m.method().params().iter().any(|s| s.name() == p.name) {
            bound.insert(&p.name, p.value.value.clone());
            shown.push((p.name.clone(), p.value.value.clone()));
        }
    }
    let report = m
        .plane_derivation()?
        .plane(&bound)
        .map_err(|e| Error::from(e).context(format!("method {arg}")))?;
    Ok((shown, report))
}
