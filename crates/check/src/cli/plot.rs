//! `zcheck plot` (placeholder until its issue lands; replace this file).

use std::process::ExitCode;

/// Arguments of `zcheck plot`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("zcheck plot is not implemented yet")
}
