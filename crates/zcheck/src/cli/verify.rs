//! `zcheck verify`: the four numeric witnesses of each method at a list of
//! Φ (and, with `--boundaries`, at both sides of every class change a sweep
//! finds), as a table or JSON. Exits non-zero when any point disagrees.

use check::numeric::ParamsF64;
use std::io::IsTerminal;
use std::process::ExitCode;

use anyhow::{bail, Context};
use check::classify::psi_of;
use check::numeric::Params;
use check::sweep;
use check::witness::{PointReport, Witnesses, DEFAULT_STEPS};
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::{json, Value};

/// Arguments of `zcheck verify`.
#[derive(clap::Args)]
pub struct Args {
    /// Methods: built-in names or `.zm` files.
    #[arg(required = true)]
    methods: Vec<String>,
    /// Comma-separated Φ values.
    #[arg(long, value_delimiter = ',', default_values_t = [1e-6, 0.1, 0.5, 1.0, 1.5, 1.9])]
    phi: Vec<f64>,
    /// Simulation steps per point (0 skips the simulation).
    #[arg(long, default_value_t = DEFAULT_STEPS)]
    steps: u64,
    /// Another parameter, as NAME=VALUE (repeatable), e.g. `--param D=0.3`.
    #[arg(long = "param", value_name = "NAME=VALUE")]
    params: Vec<String>,
    /// Also verify both sides of every class boundary found by a sweep of
    /// Φ from 1e-8 to 4.
    #[arg(long)]
    boundaries: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum Format {
    Text,
    Json,
}

fn parse_param(s: &str) -> anyhow::Result<(String, f64)> {
    let Some((name, value)) = s.split_once('=') else {
        bail!("--param `{s}`: expected NAME=VALUE, e.g. D=0.3");
    };
    let v: f64 = value
        .trim()
        .parse()
        .with_context(|| format!("--param `{s}`: expected a number after `=`"))?;
    if !v.is_finite() {
        bail!("--param `{s}`: expected a finite number");
    }
    Ok((name.trim().to_owned(), v))
}

pub fn run(args: Args) -> anyhow::Result<ExitCode> {
    let mut base = Params::default();
    for s in &args.params {
        let (n, v) = parse_param(s)?;
        if n == "Phi" {
            bail!("--param `{s}`: Phi is given by --phi");
        }
        base.set(&n, v);
    }
    if let Some(bad) = args.phi.iter().find(|x| !x.is_finite()) {
        bail!("--phi {bad}: expected finite numbers");
    }
    let mut jobs = Vec::new();
    for name in &args.methods {
        let method = check::load::load_method(name)?;
        let w = Witnesses::new(&method)?;
        let mut phis = args.phi.clone();
        if args.boundaries {
            let s = sweep::sweep(&method, &base, &sweep::default_grid())?;
            for b in &s.boundaries {
                phis.push(b.below);
                phis.push(b.above);
            }
        }
        jobs.push((w, phis));
    }
    let total: u64 = jobs.iter().map(|(_, p)| p.len() as u64 * args.steps.max(1)).sum();
    let bar = if std::io::stderr().is_terminal() && args.steps >= 100_000 {
        let b = ProgressBar::new(total);
        b.set_style(
            ProgressStyle::with_template("{msg:24} [{bar:40}] {percent:>3}% {eta}")
                .expect("valid template"),
        );
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
        for &phi in phis {
            let params = base.clone().with("Phi", phi);
            let r = w
                .at_with_progress(&params, args.steps, &mut |k| bar.set_position(done_before + k))
                .with_context(|| {
                    format!("{name} at Phi = {phi} (other parameters: --param NAME=VALUE)")
                })?;
            done_before += args.steps.max(1);
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
            Format::Text => out_text.push_str(&text_table(&name, &points, agree)),
        }
    }
    bar.finish_and_clear();
    let text = match args.format {
        Format::Json => serde_json::to_string_pretty(&Value::Array(out_json))? + "\n",
        Format::Text => out_text,
    };
    // A closed pipe (`| head`) is not an error worth a panic.
    let _ = std::io::Write::write_all(&mut std::io::stdout().lock(), text.as_bytes());
    Ok(if all_agree { ExitCode::SUCCESS } else { ExitCode::FAILURE })
}

fn pair(z: &num_complex::Complex<f64>) -> Value {
    json!([z.re, z.im])
}

fn finite_or_null(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// One point as JSON; `sim` is null when no simulation ran, and
/// `growth_per_step` is null when the state vanished (ln 0).
pub fn point_json(r: &PointReport) -> Value {
    let sim = r.sim.as_ref().map(|s| {
        json!({
            "steps": s.steps,
            "growth_per_step": finite_or_null(s.growth_per_step),
            "psi_per_step": s.psi_per_step,
            "norm_growth_per_step": finite_or_null(s.norm_growth_per_step),
        })
    });
    json!({
        "phi": r.phi(),
        "eigenvalues": r.exact.roots.iter().map(pair).collect::<Vec<_>>(),
        "spectral_radius": r.exact.spectral_radius,
        "psi": r.exact.psi,
        "class": r.exact.class.name(),
        "sim": sim,
        "agree": r.agree(),
        "growth_per_step": finite_or_null(r.exact.growth_per_step),
        "witnesses": {
            "nalgebra": r.nalgebra.iter().map(pair).collect::<Vec<_>>(),
            "faer": r.faer.iter().map(pair).collect::<Vec<_>>(),
            "tolerance": r.tolerance,
            "checks": r.checks.iter().map(|c| json!({"witness": c.witness, "agree": c.agree, "error_over_tolerance": c.worst_ratio})).collect::<Vec<_>>(),
        },
    })
}

/// The text table of one method (values rounded for reading).
pub fn text_table(name: &str, points: &[PointReport], agree: bool) -> String {
    let mut s =
        format!("{name}: {}\n", if agree { "witnesses agree" } else { "WITNESSES DISAGREE" });
    s.push_str(&format!(
        "  {:>22}  {:<22} {:>12} {:>10} {:>13} {:>13} {:>10} {:>5}\n",
        "phi", "class", "rho", "psi", "ln rho/step", "sim ln/step", "sim psi", "agree"
    ));
    for r in points {
        let (g, sp) =
            r.sim.as_ref().map_or((f64::NAN, f64::NAN), |s| (s.growth_per_step, s.psi_per_step));
        let failing: Vec<&str> = r.checks.iter().filter(|c| !c.agree).map(|c| c.witness).collect();
        s.push_str(&format!(
            "  {:>22}  {:<22} {:>12.9} {:>10.7} {:>13.6e} {:>13.6e} {:>10.7} {:>5}{}\n",
            format!("{}", r.phi()),
            r.exact.class.name(),
            r.exact.spectral_radius,
            psi_of(r.exact.roots.first().copied().unwrap_or_default()),
            r.exact.growth_per_step,
            g,
            sp,
            if r.agree() { "yes" } else { "NO" },
            if failing.is_empty() { String::new() } else { format!("  ({})", failing.join(", ")) }
        ));
    }
    s
}
