//! `zcheck tradeoff`: cost, accuracy and admissible step of every method,
//! side by side and ranked by cost per simulated period.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use zcheck::tradeoff::{self, family, figure, kernels, Spring, Target, TradeRow};

/// Output format of `zcheck tradeoff`.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Format {
    Text,
    Json,
}

/// Arguments of `zcheck tradeoff`.
#[derive(clap::Args)]
pub struct Args {
    #[arg(long, value_enum, default_value = "text")]
    pub format: Format,
    /// Largest accumulated phase error over the duration, radians.
    #[arg(long, default_value_t = Target::DEFAULT.phase_tol)]
    pub phase_tol: f64,
    /// Largest relative amplitude change over the duration (0.01 = 1 %).
    #[arg(long, default_value_t = Target::DEFAULT.amp_tol)]
    pub amp_tol: f64,
    /// The duration, in periods of the spring.
    #[arg(long, default_value_t = Target::DEFAULT.periods)]
    pub periods: f64,
    /// Time budget per method for the in-process ns/step measurement, ms.
    #[arg(long, default_value_t = 3)]
    pub budget_ms: u64,
    /// Also draw the work-precision figure (SVG) of the seven direct methods here.
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

pub fn run(args: Args) -> anyhow::Result<ExitCode> {
    let target = Target { phase_tol: args.phase_tol, amp_tol: args.amp_tol, periods: args.periods };
    for (name, x) in [
        ("--phase-tol", target.phase_tol),
        ("--amp-tol", target.amp_tol),
        ("--periods", target.periods),
    ] {
        anyhow::ensure!(x.is_finite() && x > 0.0, "{name} {x}: expected a finite number > 0");
    }
    let budget = Duration::from_millis(args.budget_ms.max(1));
    let candidates = family::undamped_family()?;
    let ns: Vec<f64> = candidates
        .iter()
        .map(|c| kernels::time_hand_kernel(c.kernel_name(), 0.0, budget).unwrap_or(f64::NAN))
        .collect();
    let mut k = 0;
    let rows = tradeoff::trade(&candidates, Spring::UNDAMPED, &target, |_| {
        k += 1;
        ns[k - 1]
    });
    if let Some(path) = &args.svg {
        let direct: Vec<(&tradeoff::Candidate, f64)> = candidates
            .iter()
            .zip(&ns)
            .filter(|(c, _)| family::direct_names().contains(&c.name.as_str()))
            .map(|(c, &n)| (c, n))
            .collect();
        figure::draw(path, &direct, Spring::UNDAMPED, &target)?;
    }
    match args.format {
        Format::Json => {
            super::output::emitln(&serde_json::to_string_pretty(&serde_json::json!({ "target": {
                "phase_tol": target.phase_tol, "amp_tol": target.amp_tol, "periods": target.periods },
                "methods": rows }))?)?
        }
        Format::Text => super::output::emit(&text(&rows, &target))?,
    }
    Ok(ExitCode::SUCCESS)
}

fn opt(x: Option<f64>, digits: usize) -> String {
    x.map_or("-".to_owned(), |x| format!("{x:.digits$}"))
}

/// The ranked table.
pub fn text(rows: &[TradeRow], target: &Target) -> String {
    let mut out = format!(
        "target over {} periods: phase drift <= {} rad, amplitude drift <= {}; undamped spring\n\
         ns/step: hand-written kernel, one state, measured now on this machine\n\n",
        target.periods, target.phase_tol, target.amp_tol
    );
    out += &format!(
        "{:<4} {:<24} {:>16} {:>8} {:>10} {:>10} {:>9} {:>10} {:>11}\n",
        "rank", "method", "ops/step", "ns/step", "phi_max", "adm. phi", "steps/T", "ops/T", "ns/T"
    );
    for r in rows {
        let ops = format!("{}m+{}a", r.ops_per_step.mul, r.ops_per_step.add);
        out += &format!(
            "{:<4} {:<24} {:>16} {:>8.2} {:>10} {:>10} {:>9} {:>10} {:>11}\n",
            r.rank.map_or("-".to_owned(), |k| k.to_string()),
            r.method,
            ops,
            r.ns_per_step,
            r.phi_max_exact,
            opt(r.admissible_phi, 5),
            r.steps_per_period.map_or("-".to_owned(), |n| n.to_string()),
            r.cost_per_period.map_or("-".to_owned(), |c| c.arithmetic.to_string()),
            opt(r.cost_per_period.map(|c| c.ns), 1),
        );
    }
    let unstable: Vec<String> = rows
        .iter()
        .filter(|r| r.admissible_phi.is_none())
        .map(|r| match r.tolerance_phi {
            Some(p) => format!(
                "{} (meets the target up to phi = {p:.5} but is unbounded at every phi > 0)",
                r.method
            ),
            None => format!("{} (no step meets the target)", r.method),
        })
        .collect();
    if !unstable.is_empty() {
        out += &format!("\nnever recommended: {}\n", unstable.join("; "));
    }
    out
}
