//! `zcheck advise` (placeholder until its issue lands; replace this file).

use std::process::ExitCode;

/// Arguments of `zcheck advise`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("zcheck advise is not implemented yet")
}
