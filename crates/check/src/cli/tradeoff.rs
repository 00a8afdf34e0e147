//! `zcheck tradeoff` (placeholder until its issue lands; replace this file).

use std::process::ExitCode;

/// Arguments of `zcheck tradeoff`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("zcheck tradeoff is not implemented yet")
}
