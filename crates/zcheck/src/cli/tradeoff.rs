//! `zcheck tradeoff`: cost, accuracy and admissible step of every method,
//! side by side and ranked by cost per simulated period.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use super::format::{Format, TEXT_JSON};
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::tradeoff::accuracy::{Spring, Target};
use crate::tradeoff::family::{self, Candidate};
use crate::tradeoff::measure::measure_ns_per_step_within;
use crate::tradeoff::rank::{trade, TradeRow};
use crate::tradeoff::{figure, kernels};
use crate::values::ParamArg;
use check::numeric::{q_to_f64, Params, ParamsF64};

/// Arguments of `zcheck tradeoff`.
#[derive(clap::Args)]
pub(crate) struct Args {
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
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
    /// Also rank this method: a built-in name, a path to a `.zm` file or a
    /// `.toml` tableau (repeatable). Its compiled step is timed like every other.
    #[arg(long = "method", value_name = "METHOD")]
    pub methods: Vec<String>,
    /// A value for a parameter of a `--method` other than Phi (a program's
    /// `param`, or a tableau's `params`), `NAME=VALUE` (exact: integer,
    /// fraction or decimal); repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub params: Vec<ParamArg>,
    /// Also rank every implicit and algebraic built-in whose χ is of
    /// second order (all but BDF2): trapezoidal, backward Euler, Newmark,
    /// Gauss-Legendre, Radau IIA, SDIRK, Forest-Ruth, soft spring.
    #[arg(long)]
    pub implicit: bool,
    /// Also draw the work-precision figure (SVG) of the seven direct methods here.
    #[arg(long)]
    pub svg: Option<PathBuf>,
    /// What the ranking orders by: `exact` operations per period (the same
    /// order on every machine; ties by name) or the ns `measured` here.
    #[arg(long, value_parser = ["exact", "measured"], default_value = "exact")]
    pub rank: String,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let target = Target { phase_tol: args.phase_tol, amp_tol: args.amp_tol, periods: args.periods };
    for (name, x) in [
        ("--phase-tol", target.phase_tol),
        ("--amp-tol", target.amp_tol),
        ("--periods", target.periods),
    ] {
        if !(x.is_finite() && x > 0.0) {
            return Err(Error::usage(format!("{name} {x}: expected a finite number > 0")));
        }
    }
    let budget = Duration::from_millis(args.budget_ms.max(1));
    let mut candidates = family::undamped_family()?;
    let mut wanted = args.methods.clone();
    if args.implicit {
        for name in poly::advanced::builtins::IMPLICIT_METHODS {
            // BDF2 is a two-step method (χ of degree 4): no principal pair
            // model, so it is left to `zcheck overview` and `stability`.
            let second_order = poly::builtin(name)?.state_size() == 2;
            if second_order && !wanted.iter().any(|w| w == name) {
                wanted.push(name.to_owned());
            }
        }
    }
    candidates.extend(user_candidates(&wanted, &args.params, &candidates)?);
    // Every candidate's native step in one rustc call (or from the cache).
    let timing: Vec<Params> = candidates.iter().map(timing_params).collect();
    let _ = crate::native::prepare(
        &candidates.iter().zip(&timing).map(|(c, p)| (&c.method, p)).collect::<Vec<_>>(),
    );
    crate::interrupt::install();
    let mut ns = Vec::with_capacity(candidates.len());
    let mut hand = Vec::with_capacity(candidates.len());
    for (k, c) in candidates.iter().enumerate() {
        crate::interrupt::check(|| {
            format!("{k} of {} methods timed; no ranking without them all", candidates.len())
        })?;
        ns.push(measure(c, budget)?);
        // A built-in's hand kernel; a user's method (built-ins named by
        // --method too) has none.
        hand.push(c.hand_kernel.and_then(|name| kernels::time_hand_kernel(name, 0.0, budget)));
    }
    let mut k = 0;
    let by = crate::tradeoff::Rank::parse(&args.rank).unwrap_or_default();
    let mut rows = trade(&candidates, Spring::UNDAMPED, &target, by, |_| {
        k += 1;
        ns[k - 1]
    });
    for row in &mut rows {
        let i =
            candidates.iter().position(|c| c.display == row.method).expect("a row per candidate");
        row.ns_per_step_hand = hand[i];
    }
    if let Some(path) = &args.svg {
        let direct: Vec<(&Candidate, f64)> = candidates
            .iter()
            .zip(&ns)
            .filter(|(c, _)| poly::advanced::builtins::PAPER_METHODS.contains(&c.name.as_str()))
            .map(|(c, &n)| (c, n))
            .collect();
        figure::draw(path, &direct, Spring::UNDAMPED, &target)?;
    }
    match args.format {
        Format::Json => {
            super::output::emitln(&serde_json::to_string_pretty(&serde_json::json!({ "target": {
                "phase_tol": target.phase_tol, "amp_tol": target.amp_tol, "periods": target.periods },
                "rank": by, "methods": rows }))?)?
        }
        _ => super::output::emit(&format!("{}{}\n", text(&rows, &target), by.describe()))?,
    }
    Ok(ExitCode::SUCCESS)
}

/// The compiled step of `c` timed at the timing Φ (and `c`'s other
/// parameters).
pub(crate) fn measure(c: &Candidate, budget: Duration) -> Result<f64, Error> {
    measure_ns_per_step_within(&c.method, &timing_params(c), budget)
        .map_err(|e| e.context(format!("method {}", c.display)))
}

/// The parameters `c` is timed at: the timing Φ and its own values.
pub(crate) fn timing_params(c: &Candidate) -> Params {
    let mut params = Params::phi(kernels::TIMING_PHI);
    for (sym, q) in &c.params {
        params.set(sym.name(), q_to_f64(q));
    }
    params
}

/// The `--method` candidates: each shown by its argument (a path or a
/// built-in name), with the `--param` values it declares; a tableau's
/// parameters are bound as it is read. A `--param` that no candidate
/// declares is refused.
fn user_candidates(
    methods: &[String],
    params: &[ParamArg],
    family: &[Candidate],
) -> Result<Vec<Candidate>, Error> {
    let values = crate::load::values_of_args(params);
    let mut loaded: Vec<LoadedMethod> = Vec::new();
    for arg in methods {
        if family.iter().any(|c| &c.display == arg) || loaded.iter().any(|m| m.display() == arg) {
            return Err(Error::usage(format!("--method {arg}: already in the comparison")));
        }
        loaded.push(LoadedMethod::load_with(arg, &values)?);
    }
    let left = crate::load::unclaimed(params, |p| &p.name, &loaded.iter().collect::<Vec<_>>());
    crate::values::check_declared(
        &left,
        &loaded.iter().map(LoadedMethod::method).collect::<Vec<_>>(),
    )?;
    let mut out: Vec<Candidate> = Vec::new();
    for (arg, method) in methods.iter().zip(&loaded) {
        let mut values = Vec::new();
        for sym in method.method().params().iter().filter(|s| s.name() != "Phi") {
            let Some(p) = left.iter().find(|p| p.name == sym.name()) else {
                return Err(Error::usage(format!(
                    "--method {arg}: parameter {} has no value: expected --param {}=VALUE",
                    sym.name(),
                    sym.name()
                )));
            };
            values.push((*sym, p.value.value.clone()));
        }
        out.push(Candidate::new(method, values).map_err(|e| e.context(format!("--method {arg}")))?);
    }
    Ok(out)
}

fn opt(x: Option<f64>, digits: usize) -> String {
    x.map_or("-".to_owned(), |x| format!("{x:.digits$}"))
}

/// The ranked table.
pub(crate) fn text(rows: &[TradeRow], target: &Target) -> String {
    let mut out = format!(
        "target over {} periods: phase drift <= {} rad, amplitude drift <= {}; undamped spring\n\
         ns/step: the compiled step of each method, one state, measured now on this machine \
         (hand: the hand-written kernel, where there is one)\n\n",
        target.periods, target.phase_tol, target.amp_tol
    );
    out += &format!(
        "{:<4} {:<24} {:>16} {:>8} {:>8} {:>10} {:>10} {:>9} {:>10} {:>11}\n",
        "rank",
        "method",
        "ops/step",
        "ns/step",
        "hand",
        "phi_max",
        "adm. phi",
        "steps/T",
        "ops/T",
        "ns/T"
    );
    for r in rows {
        let ops = format!("{}m+{}a", r.ops_per_step.mul, r.ops_per_step.add);
        out += &format!(
            "{:<4} {:<24} {:>16} {:>8.2} {:>8} {:>10} {:>10} {:>9} {:>10} {:>11}\n",
            r.rank.map_or("-".to_owned(), |k| k.to_string()),
            r.method,
            ops,
            r.ns_per_step,
            opt(r.ns_per_step_hand, 2),
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
