//! `zcheck paper`: the main job. Prints the executable proof of the paper,
//! every claim of sections 4–12 and Appendices A–E with what zcheck derived,
//! the verdict and the evidence, as Markdown or JSON.

use std::io::Write as _;
use std::process::ExitCode;

use check::paper::{all_claims, report};

/// Output format of `zcheck paper`.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Format {
    Markdown,
    Json,
}

/// Arguments of `zcheck paper`.
#[derive(clap::Args)]
pub struct Args {
    #[arg(long, value_enum, default_value = "markdown")]
    pub format: Format,
}

pub fn run(args: Args) -> anyhow::Result<ExitCode> {
    let claims = all_claims();
    let out = match args.format {
        Format::Markdown => report::to_markdown(&claims),
        Format::Json => serde_json::to_string_pretty(&report::to_json(&claims))? + "\n",
    };
    std::io::stdout().lock().write_all(out.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}
