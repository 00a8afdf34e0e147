//! `zcheck overview`: the paper's methods side by side, or any methods given:
//! exact stability limit, Ψ(Φ) and |z|² series (Appendix A, extended), cost.

use std::process::ExitCode;

use super::format::{Format, MARKDOWN_JSON};
use crate::error::Error;
use crate::load::{try_builtin_derivation, LoadedMethod};
use crate::values::{self, ParamArg};

/// Arguments of `zcheck overview`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// Built-in names or `.zm` paths (default: the paper's seven methods).
    pub methods: Vec<String>,
    /// The highest power of Phi shown in the series.
    #[arg(long, default_value_t = 5)]
    pub order: usize,
    #[arg(long, value_parser = Format::parser(MARKDOWN_JSON), default_value = "markdown")]
    pub format: Format,
    /// Also every implicit and algebraic built-in (trapezoidal, backward
    /// Euler, BDF2, Newmark, Gauss-Legendre, Radau IIA, SDIRK, Forest-Ruth,
    /// soft spring) after the methods given or the paper's seven.
    #[arg(long)]
    pub implicit: bool,
    /// A parameter value, `NAME=VALUE` (exact: 1/4, 0.25), bound in every
    /// method that declares NAME; repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub params: Vec<ParamArg>,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    if args.order > 64 {
        return Err(Error::usage(format!(
            "--order {} is too large: expected at most 64",
            args.order
        )));
    }
    let mut rows = if args.methods.is_empty() && args.params.is_empty() {
        crate::overview::paper_overview(args.order)?
    } else {
        let names: Vec<String> = if args.methods.is_empty() {
            poly::advanced::builtins::PAPER_METHODS.iter().map(|s| s.to_string()).collect()
        } else {
            args.methods.clone()
        };
        let values = crate::load::values_of_args(&args.params);
        let loaded = names
            .iter()
            .map(|m| LoadedMethod::load_with(m, &values))
            .collect::<Result<Vec<_>, _>>()?;
        let params =
            crate::load::unclaimed(&args.params, |p| &p.name, &loaded.iter().collect::<Vec<_>>());
        let methods: Vec<&poly::Method> = loaded.iter().map(|m| m.method()).collect();
        values::check_declared(&params, &methods)?;
        loaded
            .iter()
            .map(|m| {
                crate::overview::summary_at(m.derivation()?, &bind(&params, m.method()), args.order)
                    .map_err(|e| e.context(format!("method {}", m.method().name())))
            })
            .collect::<Result<Vec<_>, Error>>()?
    };
    if args.implicit {
        for name in poly::advanced::builtins::IMPLICIT_METHODS {
            rows.push(crate::overview::summary_of(&try_builtin_derivation(name)?, args.order)?);
        }
    }
    match args.format {
        Format::Json => super::output::emitln(&serde_json::to_string_pretty(&rows)?)?,
        _ => super::output::emit(&crate::overview::to_markdown(&rows))?,
    }
    Ok(ExitCode::SUCCESS)
}

/// The `--param` values that `method` declares.
fn bind(params: &[ParamArg], method: &poly::Method) -> poly::Params {
    params
        .iter()
        .filter(|p| method.params().iter().any(|s| s.name() == p.name))
        .fold(poly::Params::new(), |acc, p| acc.bind(&p.name, p.value.value.clone()))
}
