//! `zcheck map`: the exact stability map of a method. With one
//! (the arguments and the printing; the answer is `crate::answers::map`)

use super::format::{Format, TEXT_JSON};
use crate::answers::region::*;
use crate::error::Error;
use crate::load::{self, LoadedMethod};
use std::process::ExitCode;

/// Arguments of `zcheck map`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// A built-in method with a parameter (e.g. false_euler_damped), a `.zm`
    /// file (e.g. crates/zcheck/methods/newmark.zm) or a tableau.
    pub method: String,
    /// The Phi window of a (Phi, NAME) map, LO..HI (exact: 0..5/2 or 0..2.5);
    /// only with one --param range.
    #[arg(long, value_name = "LO..HI", allow_hyphen_values = true)]
    pub phi: Option<String>,
    /// NAME=LO..HI: one range for a (Phi, NAME) map, two for a map over two
    /// parameters coloured by Phi_max; NAME=VALUE binds another parameter
    /// of either map (Newmark's (Phi, beta) map with gamma=1/2). Repeatable.
    #[arg(long = "param", value_name = "NAME=LO..HI", allow_hyphen_values = true)]
    pub params: Vec<String>,
    /// Write the map as SVG here.
    #[arg(long)]
    pub svg: Option<std::path::PathBuf>,
    /// Grid points per axis.
    #[arg(long, default_value_t = 40)]
    pub grid: usize,
    /// Curve samples per axis.
    #[arg(long, default_value_t = 200)]
    pub samples: usize,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let method = LoadedMethod::load_with(&args.method, &load::values_of(&args.params))?;
    let params = load::unclaimed(&args.params, |s| load::arg_name(s), &[&method]);
    crate::interrupt::install();
    let map = compute(&method, args.phi.as_deref(), &params, args.grid, args.samples)?;
    let m = match map {
        Map::PhiParam(m) => m,
        Map::TwoParams(m) => {
            if let Some(path) = &args.svg {
                crate::answers::region::two::draw_svg(&m, path)?;
            }
            match args.format {
                Format::Json => super::output::emitln(&serde_json::to_string_pretty(&m)?)?,
                _ => super::output::emit(&two_text(&m, args.svg.as_deref()))?,
            }
            return Ok(if m.disagreements == 0 { ExitCode::SUCCESS } else { ExitCode::from(1) });
        }
    };
    if let Some(path) = &args.svg {
        crate::answers::region::one::draw_svg(&m, path)?;
    }
    match args.format {
        Format::Json => super::output::emitln(&serde_json::to_string_pretty(&m)?)?,
        _ => {
            use std::fmt::Write as _;
            let mut out = String::new();
            let p = &m.axes[1];
            let bound: String = m.bound.iter().map(|(k, v)| format!(", {k} = {v}")).collect();
            let _ = writeln!(
                out,
                "method {}: Phi in [{}, {}], {p} in [{}, {}]{bound}",
                m.method, m.phi.0, m.phi.1, m.range.0, m.range.1
            );
            let _ = writeln!(
                out,
                "critical curves (exact; the stable region is bounded by some of them):"
            );
            for c in &m.curves {
                let _ = writeln!(
                    out,
                    "  {:<12} {} = 0   (factor {} split off; {} points traced)",
                    c.kind,
                    c.poly,
                    c.monomial,
                    c.points.len()
                );
            }
            let _ = writeln!(out, "Phi_max({p}):");
            for l in &m.limits {
                let _ = writeln!(
                    out,
                    "  {p} = {:<10} Phi_max = {}{}",
                    l.value,
                    l.phi_max,
                    l.exact.as_ref().map_or(String::new(), |e| format!("  ({e})"))
                );
            }
            let mut counts: std::collections::BTreeMap<&str, usize> = Default::default();
            for g in &m.grid {
                *counts.entry(g.class.name()).or_default() += 1;
            }
            let list: Vec<String> = counts.iter().map(|(k, v)| format!("{k} {v}")).collect();
            let _ = writeln!(out, "grid {}x{}: {}", m.size.0, m.size.1, list.join(", "));
            let _ = writeln!(
                out,
                "numeric witnesses (nalgebra, faer eigenvalues) agree with the exact roots at {} of {} grid points",
                m.grid.len() - m.disagreements,
                m.grid.len()
            );
            let _ = writeln!(out, "unconditional: {}", m.unconditional);
            if let Some(p) = &args.svg {
                let _ = writeln!(out, "wrote {}", p.display());
            }
            super::output::emit(&out)?;
        }
    }
    Ok(if m.disagreements == 0 { ExitCode::SUCCESS } else { ExitCode::from(1) })
}
