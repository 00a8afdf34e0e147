//! `zcheck drift`: round-off drift of a method's exact conserved quadratic
//! form over long runs, against a stated model (`check::drift`).

use std::collections::HashMap;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};

use check::drift::{Run, Study};
use check::kernel::{Kernel, Real};
use check::numeric::{q_to_f64, Params, ParamsF64, Step};
use num_traits::Zero;
use poly::advanced::invariant::{conserved_form, form_text, is_positive_definite};
use poly::{Derivation, Sym, Q};
use serde_json::{json, Value};

use super::format::{Format, TEXT_JSON};
use super::output;
use crate::error::Error;
use crate::load::LoadedMethod;

/// Floating-point precision of the run.
#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum Precision {
    F64,
    F32,
}

/// Arguments of `zcheck drift`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// Built-in method names or paths to `.zm` files (each needs |z| = 1
    /// at Phi); several are studied in turn and drawn together.
    #[arg(required = true)]
    pub methods: Vec<String>,
    /// The step Phi, exact: an integer, a fraction (`1/10`) or a decimal (`0.1`).
    #[arg(long)]
    pub phi: String,
    /// Steps per start.
    #[arg(long, default_value_t = 1_000_000)]
    pub steps: u64,
    #[arg(long, value_enum, default_value = "f64")]
    pub precision: Precision,
    /// Independent starts (their spread is the drift's RMS).
    #[arg(long, default_value_t = 32)]
    pub starts: usize,
    /// Threads (default: every core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// A value for a parameter other than Phi, `NAME=VALUE`; repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE")]
    pub params: Vec<String>,
    /// Also draw RMS drift against N (SVG).
    #[arg(long)]
    pub svg: Option<PathBuf>,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
}

/// One method's study, ready to print.
pub(crate) struct Report {
    pub method: String,
    pub phi: Q,
    pub form: String,
    pub measured_form: &'static str,
    pub precision: &'static str,
    pub epsilon: f64,
    pub starts: usize,
    pub steps: u64,
    pub one_step: check::drift::OneStep,
    pub run: Run,
}

/// Checkpoints from this many steps on are held against the model.
pub(crate) const MODEL_FROM: u64 = 100;

impl Report {
    /// Which term of the model dominates at the run's length.
    pub(crate) fn model(&self) -> &'static str {
        if self.run.linear() {
            "linear, N*b*eps (biased rounding dominates)"
        } else {
            "random walk, sqrt(N)*s*eps"
        }
    }

    /// The largest factor between measured and modelled RMS (N >= 100).
    pub(crate) fn ratio(&self) -> Option<f64> {
        self.run.worst_ratio(MODEL_FROM)
    }

    /// Whether every checkpoint (N >= 100) lies within a factor 3 of the model.
    pub(crate) fn within_model(&self) -> bool {
        self.ratio().is_some_and(|r| r <= 3.0)
    }
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    if args.starts == 0 {
        return Err(Error::usage("--starts 0: expected at least one start"));
    }
    let phi = args
        .phi
        .parse::<crate::values::Exact>()
        .map_err(|e| Error::usage(format!("--phi {}: {e}", args.phi)))?
        .value;
    if phi <= Q::from_integer(0.into()) {
        return Err(Error::usage(format!("--phi {}: expected a step > 0", args.phi)));
    }
    let mut extra = Vec::new();
    for p in &args.params {
        let (name, value) = crate::values::parse_param(p)?;
        if name == "Phi" {
            return Err(Error::usage(format!("--param {p}: give the step with --phi")));
        }
        extra.push((name, value));
    }
    let threads = args
        .threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    crate::interrupt::install();
    let stop = crate::interrupt::flag();
    let mut reports = Vec::new();
    for name in &args.methods {
        let r = match args.precision {
            Precision::F64 => study::<f64>(name, &phi, &extra, &args, threads, stop)?,
            Precision::F32 => study::<f32>(name, &phi, &extra, &args, threads, stop)?,
        };
        let interrupted = r.run.interrupted;
        reports.push(r);
        if interrupted {
            break;
        }
    }
    if let Some(path) = &args.svg {
        crate::drift_figure::draw(path, &reports_for_figure(&reports))?;
    }
    match args.format {
        Format::Json => output::emitln(&serde_json::to_string_pretty(
            &json!({ "runs": reports.iter().map(to_json).collect::<Vec<_>>() }),
        )?)?,
        _ => output::emit(&reports.iter().map(text).collect::<Vec<_>>().join("\n"))?,
    }
    // Ctrl-C: the partial result is printed above; the exit code says so.
    if reports.iter().any(|r| r.run.interrupted) {
        output::print_error("interrupted: partial result printed");
        return Ok(ExitCode::from(crate::interrupt::EXIT_CODE));
    }
    Ok(ExitCode::SUCCESS)
}

fn reports_for_figure(reports: &[Report]) -> Vec<crate::drift_figure::Line> {
    reports
        .iter()
        .map(|r| crate::drift_figure::Line {
            label: format!("{} ({})", r.method, r.precision),
            measured: r.run.checkpoints.iter().map(|c| (c.steps as f64, c.rms_eps)).collect(),
            predicted: r
                .run
                .checkpoints
                .iter()
                .map(|c| (c.steps as f64, c.predicted_rms_eps))
                .collect(),
        })
        .collect()
}

fn study<T: Real>(
    name: &str,
    phi: &Q,
    extra: &[(String, Q)],
    args: &Args,
    threads: usize,
    stop: &AtomicBool,
) -> Result<Report, Error> {
    let loaded = LoadedMethod::load_with(name, extra)?;
    let method = loaded.method();
    let mut exact: HashMap<Sym, Q> = HashMap::new();
    let mut params = Params::new();
    for sym in method.params() {
        let value = if sym.name() == "Phi" {
            phi.clone()
        } else {
            extra.iter().find(|(n, _)| n == sym.name()).map(|(_, v)| v.clone()).ok_or_else(
                || Error::usage(format!("method {name} needs --param {}=VALUE", sym.name())),
            )?
        };
        params.set(sym.name(), q_to_f64(&value));
        exact.insert(*sym, value);
    }
    let p =
        transition_matrix_at(loaded.derivation()?, &exact).expect("every parameter has a value");
    let step = Step::compile(method, &params)?;
    let names = step.slot_names().to_vec();
    let form = match conserved_form(&p) {
        Ok(f) if is_positive_definite(&f) => f,
        Ok(_) => {
            return Err(Error::unsupported(format!(
                "{name}: at Phi = {phi} the roots are real (the conserved form is indefinite): \
             expected a method with |z| = 1 at Phi, e.g. false_euler or verlet below Phi = 2"
            )))
        }
        Err(e) => {
            return Err(Error::unsupported(format!(
                "{name}: no single conserved quadratic form at Phi = {phi} ({e:?}): expected a \
             method with |z| = 1 at Phi, e.g. false_euler or verlet below Phi = 2"
            )))
        }
    };
    let kernel = Kernel::<T>::new(&step);
    // The form the rounded program conserves exactly, else the exact Φ's.
    let (study, measured_form) = match Study::new(kernel.clone(), args.starts) {
        Ok(s) => (s, "the rounded program's own (round-off of the arithmetic alone)"),
        Err(_) => (
            Study::with_form(kernel, args.starts, form.clone()),
            "the exact Phi's: the rounded coefficients conserve no form, their rounding drifts too",
        ),
    };
    // The native step (feature `jit`) runs the lanes: the same operations.
    #[cfg(feature = "jit")]
    let study = study.with_native(&step)?;
    let one_step = study.one_step();
    let bar = indicatif::ProgressBar::new(args.steps);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{msg} [{bar:30}] {human_pos}/{human_len} steps, {per_sec}, eta {eta}",
        )
        .expect("valid template")
        .progress_chars("=> "),
    );
    bar.set_message(format!("{name} {}", T::NAME));
    let mut run = study.run(args.steps, threads, |done| {
        bar.set_position(done);
        !stop.load(Ordering::SeqCst)
    });
    bar.finish_and_clear();
    run.fit_model(&one_step);
    Ok(Report {
        method: method.name().to_owned(),
        phi: phi.clone(),
        form: form_text(&form, &names),
        measured_form,
        precision: T::NAME,
        epsilon: T::EPSILON,
        starts: args.starts,
        steps: args.steps,
        one_step,
        run,
    })
}

/// P at exact values of every parameter, from the derivation's d·P and d
/// (d = det A of an implicit step, 1 otherwise); `None` where the step's
/// system is singular.
fn transition_matrix_at(d: &Derivation, values: &HashMap<Sym, Q>) -> Option<Vec<Vec<Q>>> {
    let den = d.p_denominator().eval(values)?;
    if den.is_zero() {
        return None;
    }
    let p = &d.transition_matrix();
    (0..p.rows())
        .map(|i| p.row(i).iter().map(|e| e.eval(values).map(|x| x / &den)).collect())
        .collect()
}

fn sci(x: f64) -> String {
    format!("{x:.3e}")
}

/// The report as text.
pub(crate) fn text(r: &Report) -> String {
    let mut out = format!(
        "{} at Phi = {} in {} ({} starts, eps = {:e})\n",
        r.method, r.phi, r.precision, r.starts, r.epsilon
    );
    out += &format!(
        "conserved form: Q = {}  (exact at Phi; P^T Q P = Q, positive definite)\n",
        r.form
    );
    out += &format!("form measured: {}\n", r.measured_form);
    out += &format!(
        "one step of rounding changes Q by s = {:.4} eps (std over {} steps of one orbit; mean {:+.4} +- {:.4} eps)\n",
        r.one_step.std_eps,
        r.one_step.samples,
        r.one_step.mean_eps,
        r.one_step.mean_se_eps(),
    );
    out += &format!(
        "model: rms drift = sqrt(N*s^2 + N^2*b^2) eps, s from one step, bias b = {:.3e} eps per step from the final excess\n\
         dominant term at N = {}: {}\n\n",
        r.run.bias_eps,
        r.run.steps_done,
        r.model()
    );
    out += &format!(
        "{:>12}  {:>11}  {:>11}  {:>7}  {:>11}  {:>11}\n",
        "steps", "rms [eps]", "model", "ratio", "mean [eps]", "max [eps]"
    );
    for c in &r.run.checkpoints {
        out += &format!(
            "{:>12}  {:>11}  {:>11}  {:>7.3}  {:>11}  {:>11}\n",
            c.steps,
            sci(c.rms_eps),
            sci(c.predicted_rms_eps),
            c.rms_eps / c.predicted_rms_eps,
            sci(c.mean_eps),
            sci(c.max_abs_eps)
        );
    }
    if r.run.interrupted {
        out += &format!(
            "\ninterrupted after {} of {} steps: partial result\n",
            r.run.steps_done, r.steps
        );
    }
    out += &format!(
        "\nslope of log rms against log N (N >= 1000): {}\n",
        r.run.slope(1000).map_or("-".to_owned(), |s| format!("{s:.3} (random walk 0.5, linear 1)"))
    );
    out += &format!(
        "verdict: {} (largest factor between measured and model for N >= 100: {}; within means at most 3)\n",
        if r.within_model() { "within the model" } else { "OUTSIDE the model" },
        r.ratio().map_or("-".to_owned(), |x| format!("{x:.3}"))
    );
    out += &format!(
        "speed: {:.2e} state-steps/s ({:.2} s)\n",
        r.run.throughput(r.starts),
        r.run.seconds
    );
    out
}

/// The report as JSON.
pub(crate) fn to_json(r: &Report) -> Value {
    json!({
        "method": r.method,
        "phi": r.phi.to_string(),
        "phi_f64": q_to_f64(&r.phi),
        "precision": r.precision,
        "epsilon": r.epsilon,
        "form": r.form,
        "form_measured": r.measured_form,
        "starts": r.starts,
        "steps_requested": r.steps,
        "steps_done": r.run.steps_done,
        "interrupted": r.run.interrupted,
        "one_step": {
            "mean_eps": r.one_step.mean_eps,
            "mean_se_eps": r.one_step.mean_se_eps(),
            "std_eps": r.one_step.std_eps,
            "samples": r.one_step.samples,
        },
        "bias_eps": r.run.bias_eps,
        "model": r.model(),
        "checkpoints": r.run.checkpoints.iter().map(|c| json!({
            "steps": c.steps,
            "rms_eps": c.rms_eps,
            "predicted_rms_eps": c.predicted_rms_eps,
            "mean_eps": c.mean_eps,
            "max_abs_eps": c.max_abs_eps,
        })).collect::<Vec<_>>(),
        "slope": r.run.slope(1000),
        "ratio": r.ratio(),
        "within_model": r.within_model(),
        "seconds": r.run.seconds,
        "state_steps_per_second": r.run.throughput(r.starts),
    })
}
