//! `zcheck map`: the exact stability region of a method in (Φ, D), drawn
//! over a grid of exact root classes, every grid point cross-checked by the
//! numeric witnesses.

use std::process::ExitCode;

use poly::Q;

use super::format::{Format, TEXT_JSON};
use super::values::Exact;
use crate::error::Error;
use crate::load::LoadedMethod;

/// Arguments of `zcheck map`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// A built-in method with `param D` (e.g. false_euler_damped) or a `.zm` file.
    pub method: String,
    /// The Phi window, LO..HI (exact: 0..5/2 or 0..2.5).
    #[arg(long, value_name = "LO..HI", allow_hyphen_values = true)]
    pub phi: String,
    /// The D window, D=LO..HI.
    #[arg(long = "param", value_name = "D=LO..HI", allow_hyphen_values = true)]
    pub param: String,
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

/// `LO..HI` as exact rationals with LO < HI.
pub(crate) fn parse_range(flag: &str, s: &str) -> Result<(Q, Q), Error> {
    let Some((lo, hi)) = s.split_once("..") else {
        return Err(Error::usage(format!("{flag} {s}: expected LO..HI, e.g. 0..2.5")));
    };
    let read = |part: &str, which: &str| -> Result<Q, Error> {
        part.parse::<Exact>().map(|e| e.value).map_err(|e| {
            Error::usage(format!(
                "{flag} {s}: {which}: expected a number such as 2, 5/2 or 2.5: {e}"
            ))
        })
    };
    let (lo, hi) = (read(lo, "LO")?, read(hi, "HI")?);
    if lo >= hi {
        return Err(Error::usage(format!("{flag} {s}: expected LO < HI")));
    }
    Ok((lo, hi))
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let method = LoadedMethod::load(&args.method)?;
    let phi = parse_range("--phi", &args.phi)?;
    if phi.0 < Q::from_integer(0.into()) {
        return Err(Error::usage(format!("--phi {}: expected Phi >= 0", args.phi)));
    }
    let Some(("D", range)) = args.param.split_once('=').map(|(n, r)| (n.trim(), r)) else {
        return Err(Error::usage(format!("--param {}: expected D=LO..HI", args.param)));
    };
    let d = parse_range("--param D", range)?;
    if !(2..=400).contains(&args.grid) || !(2..=5000).contains(&args.samples) {
        return Err(Error::usage(format!(
            "--grid {} --samples {}: expected 2..=400 grid points and 2..=5000 samples",
            args.grid, args.samples
        )));
    }
    let window = crate::map::MapWindow { phi, d, grid: args.grid, samples: args.samples };
    let m = crate::map::map(&method, &window)?;
    if let Some(path) = &args.svg {
        crate::map::draw_svg(&m, path)?;
    }
    match args.format {
        Format::Json => super::output::emitln(&serde_json::to_string_pretty(&m)?)?,
        _ => {
            use std::fmt::Write as _;
            let mut out = String::new();
            let _ = writeln!(
                out,
                "method {}: Phi in [{}, {}], D in [{}, {}]",
                m.method, m.phi.0, m.phi.1, m.d.0, m.d.1
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
            let _ = writeln!(out, "Phi_max(D):");
            for l in &m.limits {
                let _ = writeln!(
                    out,
                    "  D = {:<10} Phi_max = {}{}",
                    l.d,
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
