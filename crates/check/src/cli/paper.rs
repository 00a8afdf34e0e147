//! `zcheck paper`: the main job. Until the proof report lands it prints the
//! derivation table of every built-in.

use std::process::ExitCode;

/// Arguments of `zcheck paper`.
#[derive(clap::Args)]
pub struct Args {}

pub fn run(_: Args) -> anyhow::Result<ExitCode> {
    println!("| method | chi(z) | p | q |\n|---|---|---|---|");
    for name in poly::builtin_names() {
        let d = poly::derive(&poly::builtin(name)?)?;
        let (p, q) = d.p_q().map(|(p, q)| (p.to_string(), q.to_string())).unwrap_or_default();
        println!("| {name} | {} | {p} | {q} |", d.charpoly);
    }
    Ok(ExitCode::SUCCESS)
}
