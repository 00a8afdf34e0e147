//! `zcheck methods`: the built-in methods, with their order and parameters.

use std::process::ExitCode;

use crate::error::Error;

/// Arguments of `zcheck methods`.
#[derive(clap::Args)]
pub(crate) struct Args {}

pub(crate) fn run(_: Args) -> Result<ExitCode, Error> {
    use std::fmt::Write as _;
    let mut out = format!("{:<24} {:>5}  {:<8} first comment line\n", "method", "state", "params");
    for name in poly::advanced::builtins::all_builtin_names() {
        let m = poly::builtin(name)?;
        let src = poly::advanced::builtins::builtin_source(name).unwrap_or_default();
        let about = src.lines().next().unwrap_or("").trim_start_matches('#').trim();
        let params: Vec<&str> = m.params().iter().map(|p| p.name()).collect();
        let _ =
            writeln!(out, "{:<24} {:>5}  {:<8} {}", name, m.state_size(), params.join(","), about);
    }
    super::output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
