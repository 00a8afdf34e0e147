//! `zcheck verify` (placeholder until its issue lands; replace this file).

use std::process::ExitCode;

/// Arguments of `zcheck verify`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("zcheck verify is not implemented yet")
}
