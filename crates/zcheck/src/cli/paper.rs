//! `zcheck paper`: the main job. Prints the executable proof of the paper,
//! every claim of sections 4–12 and Appendices A–E with what zcheck derived,
//! the verdict and the evidence, as Markdown or JSON.

use std::process::ExitCode;

use super::format::{Format, MARKDOWN_JSON};
use crate::error::Error;
use crate::paper::{all_claims, report};

/// Arguments of `zcheck paper`.
#[derive(clap::Args)]
pub(crate) struct Args {
    #[arg(long, value_parser = Format::parser(MARKDOWN_JSON), default_value = "markdown")]
    pub format: Format,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let out = match args.format {
        Format::Json => serde_json::to_string_pretty(&crate::paper::json_document()?)? + "\n",
        _ => format!(
            "{}\n## Beyond the paper: every method side by side\n\n\
             Appendix A derives Ψ(Φ) for two methods; here it is for all seven, exact, with the \
             exact stability limit and the operations per step (`zcheck overview`).\n\n{}",
            report::to_markdown(&all_claims()),
            crate::overview::to_markdown(&crate::overview::paper_overview(
                crate::paper::OVERVIEW_ORDER
            )?)
        ),
    };
    super::output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
