//! `zcheck scene` (placeholder until its issue lands; replace this file).

use std::process::ExitCode;

/// Arguments of `zcheck scene`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("zcheck scene is not implemented yet")
}
