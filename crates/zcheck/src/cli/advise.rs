//! `zcheck advise`: which method and how many substeps for a spring in a
//! game scene, in game units (Hz).

use std::process::ExitCode;
use std::time::Duration;

use poly::Q;
use zcheck::tradeoff::{self, family, kernels, Advice, Candidate, Scene};

use super::values::Exact;

/// Output format of `zcheck advise`.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum Format {
    Text,
    Json,
}

/// Arguments of `zcheck advise`.
#[derive(clap::Args)]
pub struct Args {
    /// The spring's natural frequency, Hz.
    #[arg(long)]
    pub freq: f64,
    /// The simulation tick rate, Hz.
    #[arg(long)]
    pub tick: f64,
    /// How long the scene must stay within tolerance, seconds.
    #[arg(long, default_value_t = Scene::DEFAULT_DURATION_S)]
    pub duration: f64,
    /// Largest accumulated phase error over the duration, radians.
    #[arg(long, default_value_t = Scene::DEFAULT_PHASE_TOL)]
    pub phase_tol: f64,
    /// Largest relative amplitude error over the duration (0.01 = 1 %).
    #[arg(long, default_value_t = Scene::DEFAULT_AMP_TOL)]
    pub amp_tol: f64,
    /// Physical damping ratio D (0 <= D < 1), an exact decimal (`0.1` is
    /// 1/10); without it the spring is undamped.
    #[arg(long, allow_negative_numbers = true)]
    pub damping: Option<Exact>,
    #[arg(long, value_enum, default_value = "text")]
    pub format: Format,
}

/// The candidates for a scene: the seven direct methods, on the spring with
/// the exact damping ratio `damping` when there is one.
pub fn candidates(damping: Option<&Q>) -> anyhow::Result<Vec<Candidate>> {
    Ok(match damping {
        Some(q) => family::damped_family(q)?,
        None => family::undamped_family()?
            .into_iter()
            .filter(|c| family::direct_names().contains(&c.name.as_str()))
            .collect(),
    })
}

pub fn run(args: Args) -> anyhow::Result<ExitCode> {
    let scene = Scene {
        freq_hz: args.freq,
        tick_hz: args.tick,
        duration_s: args.duration,
        phase_tol: args.phase_tol,
        amp_tol: args.amp_tol,
        damping: args.damping.as_ref().map(|d| d.to_f64("--damping")).transpose()?,
    };
    scene.validate()?;
    let cands = candidates(args.damping.as_ref().map(|d| &d.value))?;
    let d = scene.damping.unwrap_or(0.0);
    let advice = tradeoff::advise(&scene, &cands, |c| {
        kernels::time_hand_kernel(c.kernel_name(), d, Duration::from_millis(3)).unwrap_or(f64::NAN)
    })?;
    match args.format {
        Format::Json => super::output::emitln(&serde_json::to_string_pretty(&advice)?)?,
        Format::Text => super::output::emit(&text(&advice))?,
    }
    Ok(ExitCode::SUCCESS)
}

/// The advice as a table and a sentence.
pub fn text(a: &Advice) -> String {
    let s = &a.scene;
    let f = |x: f64| super::values::show_f64(x);
    let mut out = format!(
        "scene: {} Hz spring on a {} Hz tick: Phi = 2*pi*{}/{} = {} rad per tick ({} ticks per period)\n",
        f(s.freq_hz),
        f(s.tick_hz),
        f(s.freq_hz),
        f(s.tick_hz),
        super::values::show_f64_digits(a.phi, 4),
        super::values::show_f64_digits(2.0 * std::f64::consts::PI / a.phi, 2)
    );
    out += &format!(
        "target over {} s ({} periods): phase drift <= {} rad, amplitude drift <= {}\n",
        f(s.duration_s),
        f(a.periods),
        f(s.phase_tol),
        f(s.amp_tol)
    );
    out += &match s.damping {
        Some(d) => {
            format!("spring: damped, D = {d}; judged against the exact damped oscillator\n\n")
        }
        None => "spring: undamped\n\n".to_owned(),
    };
    let header = [
        "method",
        "phi_max",
        "stable",
        "substeps stable",
        "substeps tolerance",
        "ops/tick",
        "ns/tick",
    ]
    .map(str::to_owned);
    let rows: Vec<[String; 7]> = a
        .methods
        .iter()
        .map(|m| {
            [
                m.method.clone(),
                m.phi_max.clone(),
                (if m.stable_at_phi { "yes" } else { "no" }).to_owned(),
                m.substeps_stable.map_or("never".to_owned(), |k| k.to_string()),
                m.substeps_tol.map_or("never".to_owned(), |k| k.to_string()),
                m.ops_per_tick.map_or("-".to_owned(), |o| format!("{}m+{}a", o.mul, o.add)),
                m.ns_per_tick.map_or("-".to_owned(), |ns| format!("{ns:.1}")),
            ]
        })
        .collect();
    // Columns as wide as their widest cell: phi_max can be a nested root.
    let widths: Vec<usize> = (0..7)
        .map(|c| {
            std::iter::once(&header).chain(&rows).map(|r| r[c].chars().count()).max().unwrap_or(0)
        })
        .collect();
    for row in std::iter::once(&header).chain(&rows) {
        let cells: Vec<String> = row
            .iter()
            .zip(&widths)
            .enumerate()
            .map(
                |(c, (cell, &w))| {
                    if c == 0 {
                        format!("{cell:<w$}")
                    } else {
                        format!("{cell:>w$}")
                    }
                },
            )
            .collect();
        out += &cells.join("  ");
        out.push('\n');
    }
    let stable: Vec<&str> =
        a.methods.iter().filter(|m| m.stable_at_phi).map(|m| m.method.as_str()).collect();
    out += &format!(
        "\nstable at Phi = {:.4} with one step per tick: {}\n",
        a.phi,
        if stable.is_empty() { "none".to_owned() } else { stable.join(", ") }
    );
    out += &match a.cheapest.as_ref().and_then(|c| a.methods.iter().find(|m| &m.method == c)) {
        Some(m) => format!(
            "cheapest meeting the tolerance: {} with {} substeps per tick ({:.1} ns per tick measured here)\n",
            m.method,
            m.substeps_tol.unwrap_or(0),
            m.ns_per_tick.unwrap_or(f64::NAN)
        ),
        None => "no method meets the tolerance at a stable step\n".to_owned(),
    };
    out
}
