//! `zcheck overview`: the paper's methods side by side, or any methods given:
//! exact stability limit, Ψ(Φ) and |z|² series (Appendix A, extended), cost.

use std::process::ExitCode;

use super::format::{Format, MARKDOWN_JSON};
use crate::error::Error;
use crate::load::{try_builtin_derivation, LoadedMethod};

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
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    if args.order > 64 {
        return Err(Error::usage(format!(
            "--order {} is too large: expected at most 64",
            args.order
        )));
    }
    let mut rows = if args.methods.is_empty() {
        crate::overview::paper_overview(args.order)?
    } else {
        args.methods
            .iter()
            .map(|m| crate::overview::summary_of(LoadedMethod::load(m)?.derivation()?, args.order))
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
