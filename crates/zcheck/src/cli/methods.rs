//! `zcheck methods`: the built-in methods, with their state size, their
//! classical order (where the built-in has a nonlinear reading) and their
//! parameters.

use std::process::ExitCode;

use poly::advanced::order::Order;

use crate::answers::order::classical_order;
use crate::error::Error;
use crate::readings::{Form, Reading};

/// Arguments of `zcheck methods`.
#[derive(clap::Args)]
pub(crate) struct Args {}

/// The classical order column: the order and the kind of reading it is
/// read on, `—` for a built-in without one.
fn classical(name: &str) -> Result<String, Error> {
    let Some(reading) = Reading::builtin(name).transpose()? else {
        return Ok("—".to_owned());
    };
    let kind = match reading.form {
        Form::RungeKutta { .. } => "RK",
        Form::Partitioned { .. } => "PRK",
        Form::Splitting { .. } => "split",
        Form::Multistep(_) => "LMM",
    };
    Ok(match classical_order(&reading)? {
        Order::Exact(p) => format!("{p} {kind}"),
        Order::AtLeast(p) => format!("≥{p} {kind}"),
    })
}

pub(crate) fn run(_: Args) -> Result<ExitCode, Error> {
    use std::fmt::Write as _;
    let mut out = format!(
        "{:<24} {:>10}  {:<15} {:<8} first comment line\n",
        "method", "state size", "classical order", "params"
    );
    for name in poly::advanced::builtins::all_builtin_names() {
        let m = poly::builtin(name)?;
        let src = poly::advanced::builtins::builtin_source(name).unwrap_or_default();
        let about = src.lines().next().unwrap_or("").trim_start_matches('#').trim();
        let params: Vec<&str> = m.params().iter().map(|p| p.name()).collect();
        let _ = writeln!(
            out,
            "{:<24} {:>10}  {:<15} {:<8} {}",
            name,
            m.state_size(),
            classical(name)?,
            params.join(","),
            about
        );
    }
    out.push_str(
        "\nstate size: the size of the transition matrix P (the degree of chi).\n\
         classical order: the order on y' = f(y) of the built-in's nonlinear reading (`zcheck \
         order NAME`): a Runge-Kutta tableau (RK), a partitioned pair (PRK) or a splitting on \
         y' = f(v), v' = g(y), or a linear multistep method (LMM). False Heun and Semi-False \
         Heun are partitioned pairs, read from their programs. — : no nonlinear reading (a \
         damped spring with a free D, Newmark on y'' = g(y), the soft spring).\n",
    );
    super::output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
