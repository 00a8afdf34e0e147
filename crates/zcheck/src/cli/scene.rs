//! `zcheck scene <name>`: run an appendix scene (three bodies or aircraft),
//! report its invariants and its accuracy against a reference, and draw its
//! figures.

use std::fmt::Write as _;
use std::io::{IsTerminal, Write as _};
use std::path::PathBuf;
use std::process::ExitCode;

use super::format::{Format, TEXT_JSON};
use crate::error::Error;
use crate::scene::aircraft::{self, AircraftRun};
use crate::scene::three_body::{
    self, EnergyControl, EnergyDefinition, FirstStep, ForceLaw, InitialVelocities, ThreeBodyRun,
};
use crate::scene::{figure, Scene};
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;

use crate::values::{Exact, DEFAULT_BUDGET};

/// Force law of the three-body scenes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum Law {
    /// |F| = 1/r, the paper's code.
    InverseDistance,
    /// |F| = 1/r^2, Newton.
    InverseSquare,
}

/// Energy the control term measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum Energy {
    /// Appendix D as printed (kinetic - sum 1/r).
    Paper,
    /// The energy the force law conserves.
    Consistent,
}

/// Initial velocities of the three-body scenes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub(crate) enum Velocities {
    /// Appendix C: tangential.
    Tangential,
    /// Appendix D as printed: radial.
    Radial,
}

/// Arguments of `zcheck scene`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// The scene: three_body_false_euler (C), three_body_euler,
    /// three_body_euler_energy (D) or aircraft (E).
    pub name: String,
    /// Number of steps (default: 10^6 for C, 100,000 for D, 600 for E).
    #[arg(long)]
    pub steps: Option<u64>,
    /// Output format.
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
    /// Write SVG figures into this directory.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Three bodies: force law (default: the paper's 1/r).
    #[arg(long, value_enum)]
    pub force_law: Option<Law>,
    /// Three bodies: energy measured by the control term (default:
    /// consistent); with three_body_euler it switches the control on.
    #[arg(long, value_enum)]
    pub energy: Option<Energy>,
    /// Three bodies: the printed first step (force from zeroed new positions).
    #[arg(long)]
    pub literal_first_step: bool,
    /// Three bodies: initial velocities (default: C tangential, D radial).
    #[arg(long, value_enum)]
    pub velocities: Option<Velocities>,
    /// Three bodies: the asymmetry eps (default: C 0, D 0.01).
    #[arg(long)]
    pub eps: Option<f64>,
    /// The most steps the run may take; longer runs are refused.
    #[arg(long, default_value_t = Exact::count(DEFAULT_BUDGET))]
    pub budget: Exact,
    /// Aircraft: commanded roll angle Phic in degrees (default 30).
    #[arg(long)]
    pub phic: Option<f64>,
    /// Aircraft: commanded pitch angle Thec in degrees (default 10).
    #[arg(long)]
    pub thec: Option<f64>,
}

/// Steps compared with the reference (the reference is the slow part).
const ACCURACY_STEPS: u64 = 1000;

fn progress_bar(n: u64) -> ProgressBar {
    // Long runs only, and only when a person is watching.
    if n < 200_000 || !std::io::stderr().is_terminal() || !std::io::stdout().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(n);
    if let Ok(style) = ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} steps ({eta})") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let scene = Scene::by_name(&args.name)?;
    let n = args.steps.unwrap_or_else(|| scene.default_steps());
    if n == 0 {
        return Err(Error::usage("--steps: expected a positive number of steps, got 0"));
    }
    let budget = args.budget.to_count("--budget")?;
    if n > budget {
        return Err(Error::usage(format!(
            "--steps {n} is beyond the budget of {budget} steps: pass --budget {n} to run it anyway"
        )));
    }
    if let Some(dir) = &args.plot {
        std::fs::create_dir_all(dir)
            .map_err(|e| Error::io(format!("cannot create {}", dir.display()), e))?;
    }
    let bar = progress_bar(n);
    bar.set_message(args.name.clone());
    let mut progress = |k: u64| bar.set_position(k);
    match scene {
        Scene::ThreeBody(mut config) => {
            if let Some(law) = args.force_law {
                config.force_law = match law {
                    Law::InverseDistance => ForceLaw::InverseDistance,
                    Law::InverseSquare => ForceLaw::InverseSquare,
                };
            }
            if let Some(energy) = args.energy {
                let energy = match energy {
                    Energy::Paper => EnergyDefinition::Paper,
                    Energy::Consistent => EnergyDefinition::Consistent,
                };
                let factor = config.control.map_or(0.3, |c| c.factor);
                config.control = Some(EnergyControl { factor, energy });
            }
            if args.literal_first_step {
                config.first_step = FirstStep::ZeroedNewPositions;
            }
            if let Some(v) = args.velocities {
                config.velocities = match v {
                    Velocities::Tangential => InitialVelocities::Tangential,
                    Velocities::Radial => InitialVelocities::Radial,
                };
            }
            if let Some(eps) = args.eps {
                if !(eps.is_finite()) {
                    return Err(Error::usage(format!(
                        "--eps: expected a finite number, got {eps}"
                    )));
                }
                config.eps = eps;
            }
            let run = three_body::simulate(&config, n, &mut progress);
            bar.finish_and_clear();
            let accuracy = three_body::accuracy(&config, n.min(ACCURACY_STEPS));
            let report = three_body_json(&args.name, &run, &accuracy);
            print(&args, &report)?;
            if let Some(dir) = &args.plot {
                for file in figure::three_body(dir, &args.name, &run)? {
                    let _ = writeln!(std::io::stderr(), "wrote {}", file.display());
                }
            }
        }
        Scene::Aircraft(mut config) => {
            if let Some(phic) = args.phic {
                if !(phic.is_finite()) {
                    return Err(Error::usage(format!(
                        "--phic: expected a finite angle in degrees, got {phic}"
                    )));
                }
                config.phi_command = phic;
            }
            if let Some(thec) = args.thec {
                if !(thec.is_finite()) {
                    return Err(Error::usage(format!(
                        "--thec: expected a finite angle in degrees, got {thec}"
                    )));
                }
                config.theta_command = thec;
            }
            let run = aircraft::simulate(&config, n, &mut progress);
            bar.finish_and_clear();
            print(&args, &aircraft_json(&run))?;
            if let Some(dir) = &args.plot {
                for file in figure::aircraft(dir, &run)? {
                    let _ = writeln!(std::io::stderr(), "wrote {}", file.display());
                }
            }
        }
    }
    Ok(ExitCode::SUCCESS)
}

fn three_body_json(
    name: &str,
    run: &ThreeBodyRun,
    accuracy: &Result<three_body::Accuracy, crate::error::Error>,
) -> serde_json::Value {
    json!({
        "scene": name,
        "appendix": Scene::appendix(name),
        "config": run.config,
        "steps": run.n_steps,
        "completed_steps": run.completed_steps,
        "first_nonfinite_step": run.first_nonfinite_step,
        "bounded": run.bounded(),
        "radius": { "min": run.radius_min, "max": run.radius_max, "mean": run.radius_mean },
        "distance_min": run.distance_min,
        "invariants": {
            "energy_paper": run.energy_paper.summary(),
            "energy_consistent": run.energy_consistent.summary(),
            "angular_momentum": run.angular_momentum.summary(),
            "momentum_x": run.momentum_x.summary(),
            "momentum_y": run.momentum_y.summary(),
            "centre_of_mass_drift": run.centre_of_mass_drift.summary(),
        },
        "accuracy": match accuracy {
            Ok(a) => json!(a),
            Err(e) => json!({ "error": e.to_string() }),
        },
    })
}

fn aircraft_json(run: &AircraftRun) -> serde_json::Value {
    json!({
        "scene": "aircraft",
        "appendix": "E",
        "config": run.config,
        "steps": run.n_steps,
        "final": run.final_state,
        "reference_final": run.reference_final_state,
        "steady_turn": run.steady_turn,
        "settling_time": run.settling_time,
        "settling_criterion": "roll and pitch stay within 0.1 degrees of the steady turn",
        "max_angle_error": { "phi": run.max_angle_error[0], "theta": run.max_angle_error[1] },
        "invariants": {
            "orthonormality_error": run.orthonormality.summary(),
            "kinetic_energy": run.kinetic_energy.summary(),
        },
        "kinematics_error": run.kinematics_error,
    })
}

fn print(args: &Args, report: &serde_json::Value) -> Result<(), Error> {
    match args.format {
        Format::Json => {
            super::output::emitln(&serde_json::to_string_pretty(report)?)?;
        }
        _ => {
            let mut text = String::new();
            render_text(report, "", &mut text);
            super::output::emit(&text)?;
        }
    }
    Ok(())
}

/// The JSON report as indented `key: value` lines, numbers to 6 digits.
fn render_text(value: &serde_json::Value, indent: &str, out: &mut String) {
    let Some(map) = value.as_object() else { return };
    for (key, v) in map {
        match v {
            serde_json::Value::Object(_) => {
                let _ = writeln!(out, "{indent}{key}:");
                render_text(v, &format!("{indent}  "), out);
            }
            serde_json::Value::Number(x) if x.is_f64() => {
                let _ = writeln!(out, "{indent}{key}: {:.6e}", x.as_f64().unwrap_or(f64::NAN));
            }
            serde_json::Value::Array(items) => {
                let items: Vec<String> = items
                    .iter()
                    .map(|i| i.as_f64().map_or(i.to_string(), |x| format!("{x:.6}")))
                    .collect();
                let _ = writeln!(out, "{indent}{key}: [{}]", items.join(", "));
            }
            _ => {
                let _ = writeln!(out, "{indent}{key}: {v}");
            }
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_scene_name_resolves() {
        for name in crate::scene::SCENES {
            assert!(super::Scene::by_name(name).is_ok(), "{name}");
        }
    }
}
