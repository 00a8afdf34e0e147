//! `zcheck verify`: the four numeric witnesses of each method at a list of
//! (the arguments and the printing; the answer is `crate::answers::verify`)

use super::format::{Format, TEXT_JSON};
use super::output;
use crate::answers::verify::*;
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::values::{self, show_f64, Exact, ParamArg};
use check::numeric::{Params, ParamsF64};
use check::sweep;
use check::witness::{PointReport, Witnesses, DEFAULT_STEPS};
use indicatif::{ProgressBar, ProgressStyle};
use poly::Q;
use serde_json::{json, Value};
use std::io::IsTerminal;
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `zcheck verify`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// Methods: built-in names or `.zm` files.
    #[arg(required = true)]
    methods: Vec<String>,
    /// Comma-separated Φ values (exact decimals, e.g. `0.1`, `1e-300`, `-1`).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true,
          default_values = ["1e-6", "0.1", "0.5", "1", "1.5", "1.9"])]
    phi: Vec<Exact>,
    /// Simulation steps per point (0 skips the simulation).
    #[arg(long, default_value_t = Exact::count(DEFAULT_STEPS), allow_hyphen_values = true)]
    steps: Exact,
    /// Another parameter, as NAME=VALUE (repeatable), e.g. `--param D=0.3`
    /// or `--param D=1/2`.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    params: Vec<ParamArg>,
    /// Also verify both sides of every class boundary found by a sweep of
    /// Φ from 1e-8 to 4.
    #[arg(long)]
    boundaries: bool,
    /// The most state-steps (points × steps) the run may take; longer runs
    /// are refused with an estimate of their time.
    #[arg(long, default_value_t = Exact::count(values::DEFAULT_BUDGET), allow_hyphen_values = true)]
    budget: Exact,
    /// Output format.
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    format: Format,
}

/// A Φ to verify at: its `f64`, and its exact value when the user typed it.
type Point = (f64, Option<Q>);

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let steps = args.steps.to_count("--steps")?;
    let budget = args.budget.to_count("--budget")?;
    // The Φ typed are exact (the exact class is taken there); the numeric
    // witnesses run at the nearest f64, which must exist.
    let mut phis: Vec<Point> = Vec::new();
    for phi in &args.phi {
        phis.push((phi.to_f64("--phi")?, Some(phi.value.clone())));
    }
    let values = crate::load::values_of_args(&args.params);
    let methods = args
        .methods
        .iter()
        .map(|name| LoadedMethod::load_with(name, &values))
        .collect::<Result<Vec<_>, _>>()?;
    let params =
        crate::load::unclaimed(&args.params, |p| &p.name, &methods.iter().collect::<Vec<_>>());
    values::check_declared(&params, &methods.iter().map(|m| m.method()).collect::<Vec<_>>())?;
    let mut base = Params::default();
    for p in &params {
        p.value.to_f64(&format!("--param {}", p.name))?;
        base.insert(&p.name, p.value.value.clone());
    }
    let mut jobs = Vec::new();
    for method in &methods {
        let w = Witnesses::from_derivation(method.derivation()?);
        let mut phis = phis.clone();
        if args.boundaries {
            let s = sweep::sweep_derivation(method.derivation()?, &base, &sweep::default_grid())?;
            for b in &s.boundaries {
                phis.push((b.below, None));
                phis.push((b.above, None));
            }
        }
        jobs.push((w, phis));
    }
    let n_points: u64 = jobs.iter().map(|(_, p)| p.len() as u64).sum();
    let total = n_points.saturating_mul(steps);
    if total > budget {
        return Err(Error::usage(format!(
            "this run is {} state-steps ({n_points} points × {} steps), {}; the budget is {}: \
             pass --budget {} to run it anyway, or ask for fewer --steps",
            show_count(total),
            show_count(steps),
            estimate(&jobs, &base, total),
            show_count(budget),
            total
        )));
    }
    crate::interrupt::install();
    let bar = if std::io::stderr().is_terminal() && total >= 10_000_000 {
        let b = ProgressBar::new(total);
        if let Ok(style) = ProgressStyle::with_template(
            "{msg:24} [{bar:40}] {percent:>3}%  {elapsed} elapsed, about {eta} left",
        ) {
            b.set_style(style);
        }
        b
    } else {
        ProgressBar::hidden()
    };
    let mut all_agree = true;
    let mut out_json = Vec::new();
    let mut out_text = String::new();
    let mut done_before = 0u64;
    for (w, phis) in &jobs {
        let name = w.method().name().to_owned();
        bar.set_message(name.clone());
        let mut points = Vec::new();
        for (phi, exact) in phis {
            let phi = *phi;
            let params = match exact {
                Some(q) => base.clone().bind("Phi", q.clone()),
                None => base.clone().with("Phi", phi),
            };
            let r = w
                .at_with_progress(&params, steps, &mut |k| {
                    bar.set_position(done_before + k);
                    !crate::interrupt::requested()
                })
                .map_err(|e| {
                    Error::from(e).context(format!(
                        "{name} at Phi = {} (other parameters: --param NAME=VALUE)",
                        show_f64(phi)
                    ))
                })?;
            done_before += steps;
            bar.set_position(done_before);
            points.push(r);
        }
        let agree = points.iter().all(PointReport::agree);
        all_agree &= agree;
        match args.format {
            Format::Json => out_json.push(json!({
                "method": name,
                "points": points.iter().map(point_json).collect::<Vec<_>>(),
                "agree": agree,
            })),
            _ => out_text.push_str(&text_table(&name, &points, agree)),
        }
    }
    bar.finish_and_clear();
    let text = match args.format {
        Format::Json => serde_json::to_string_pretty(&Value::Array(out_json))? + "\n",
        _ => out_text,
    };
    output::emit(&text)?;
    Ok(if all_agree { ExitCode::SUCCESS } else { ExitCode::FAILURE })
}

/// A count for a message: exact below a million, else like `6.0e12`.
fn show_count(n: u64) -> String {
    if n < 1_000_000 {
        n.to_string()
    } else {
        format!("{:.1e}", n as f64)
    }
}

/// How long `total` state-steps would take, from a short run of the first
/// point measured now.
fn estimate(jobs: &[(Witnesses, Vec<Point>)], base: &Params, total: u64) -> String {
    const PROBE: u64 = 200_000;
    let Some((w, phi)) = jobs.iter().find_map(|(w, p)| p.first().map(|&(phi, _)| (w, phi))) else {
        return "time unknown".to_owned();
    };
    let params = base.clone().with("Phi", phi);
    let start = Instant::now();
    if w.at(&params, PROBE).is_err() {
        return "time unknown".to_owned();
    }
    let per_step = start.elapsed().as_secs_f64() / PROBE as f64;
    let secs = per_step * total as f64;
    let shown = if secs < 120.0 {
        format!("{secs:.0} s")
    } else if secs < 7200.0 {
        format!("{:.0} min", secs / 60.0)
    } else if secs < 172_800.0 {
        format!("{:.1} h", secs / 3600.0)
    } else {
        format!("{:.0} days", secs / 86400.0)
    };
    format!("about {shown} at {:.1e} steps/s measured now", 1.0 / per_step)
}
