//! `zcheck stability` (placeholder until its issue lands; replace this file).

use std::process::ExitCode;

/// Arguments of `zcheck stability`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("zcheck stability is not implemented yet")
}
