//! The scenes' SVG figures (plotters, SVG backend): the three-body
//! trajectories (Appendix C's clover leaf over the first 100 steps, beside
//! the exact circle; Appendix D's whole run), the energies over time, and
//! the aircraft's angles over time beside the reference.

use std::path::{Path, PathBuf};

use plotters::prelude::*;

use super::aircraft::AircraftRun;
use super::three_body::{Integrator, ThreeBodyRun};
use crate::error::Error;

const BODY_COLOURS: [RGBColor; 3] =
    [RGBColor(214, 39, 40), RGBColor(44, 160, 44), RGBColor(31, 119, 180)];

fn figure_error(path: &Path) -> impl Fn(&dyn std::fmt::Display) -> Error + '_ {
    move |e| Error::figure(format!("cannot draw figure {}: {e}", path.display()))
}

fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !lo.is_finite() {
        return (-1.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(1e-9 * (1.0 + hi.abs()));
    (lo - pad, hi + pad)
}

/// Draw the trajectory and energy figures of a three-body run into `dir`;
/// returns the files written.
pub(crate) fn three_body(
    dir: &Path,
    name: &str,
    run: &ThreeBodyRun,
) -> Result<Vec<PathBuf>, Error> {
    let trajectory = dir.join(format!("{name}_trajectory.svg"));
    let energy = dir.join(format!("{name}_energy.svg"));
    draw_trajectory(&trajectory, name, run)?;
    draw_energy(&energy, name, run)?;
    Ok(vec![trajectory, energy])
}

fn draw_trajectory(path: &Path, name: &str, run: &ThreeBodyRun) -> Result<(), Error> {
    let err = figure_error(path);
    // Appendix C's image is the first 100 steps; Appendix D's the whole run.
    let clover = run.config.integrator == Integrator::FalseEuler;
    let points: Vec<[[f64; 2]; 3]> = if clover {
        run.first_steps.clone()
    } else {
        run.samples.iter().map(|s| s.position).collect()
    };
    let (xlo, xhi) = range(points.iter().flat_map(|p| p.iter().map(|b| b[0])));
    let (ylo, yhi) = range(points.iter().flat_map(|p| p.iter().map(|b| b[1])));
    let half = (xhi - xlo).max(yhi - ylo) / 2.0;
    let (cx, cy) = ((xlo + xhi) / 2.0, (ylo + yhi) / 2.0);
    let root = SVGBackend::new(path, (700, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let caption = if clover {
        format!(
            "{name}: first {} steps (dT = {}) and the exact circle",
            points.len() - 1,
            run.config.dt
        )
    } else {
        format!("{name}: {} steps (dT = {})", run.completed_steps, run.config.dt)
    };
    let mut chart = ChartBuilder::on(&root)
        .caption(caption, ("sans-serif", 16))
        .margin(12)
        .x_label_area_size(35)
        .y_label_area_size(45)
        .build_cartesian_2d(cx - half..cx + half, cy - half..cy + half)
        .map_err(|e| err(&e))?;
    chart.configure_mesh().x_desc("x").y_desc("y").draw().map_err(|e| err(&e))?;
    if clover {
        let circle = (0..=360).map(|d| {
            let a = f64::from(d).to_radians();
            (a.cos(), a.sin())
        });
        chart
            .draw_series(LineSeries::new(circle, BLACK.mix(0.5).stroke_width(1)))
            .map_err(|e| err(&e))?
            .label("reference: circle r = 1")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.mix(0.5)));
    }
    for (b, colour) in BODY_COLOURS.iter().enumerate() {
        let line = points.iter().map(|p| (p[b][0], p[b][1]));
        chart
            .draw_series(LineSeries::new(line, colour.stroke_width(1)))
            .map_err(|e| err(&e))?
            .label(format!("body {}", b + 1))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        if clover {
            chart
                .draw_series(
                    points.iter().map(|p| Circle::new((p[b][0], p[b][1]), 2, colour.filled())),
                )
                .map_err(|e| err(&e))?;
        }
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))
}

fn draw_energy(path: &Path, name: &str, run: &ThreeBodyRun) -> Result<(), Error> {
    let err = figure_error(path);
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let panels = root.split_evenly((2, 1));
    let t_end = run.samples.last().map_or(1.0, |s| s.time).max(run.config.dt);
    type Value = fn(&super::three_body::Sample) -> f64;
    let series: [(&str, Value); 2] = [
        ("energy conserved by the force law (sum v^2/2 + sum ln r or - sum 1/r)", |s| {
            s.energy_consistent
        }),
        ("the paper's \"total energy\" (sum v^2/2 - sum 1/r)", |s| s.energy_paper),
    ];
    for (panel, (label, get)) in panels.iter().zip(series) {
        let (lo, hi) = range(run.samples.iter().map(get));
        let mut chart = ChartBuilder::on(panel)
            .caption(format!("{name}: {label}"), ("sans-serif", 14))
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..t_end, lo..hi)
            .map_err(|e| err(&e))?;
        chart.configure_mesh().x_desc("t").draw().map_err(|e| err(&e))?;
        chart
            .draw_series(LineSeries::new(
                run.samples.iter().filter(|s| get(s).is_finite()).map(|s| (s.time, get(s))),
                BLUE.stroke_width(1),
            ))
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))
}

/// Draw the aircraft's angles over time (False Euler against the reference,
/// with the command) into `dir`.
pub(crate) fn aircraft(dir: &Path, run: &AircraftRun) -> Result<Vec<PathBuf>, Error> {
    let path = dir.join("aircraft_angles.svg");
    let err = figure_error(&path);
    let root = SVGBackend::new(&path, (900, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let panels = root.split_evenly((2, 1));
    let t_end = run.samples.last().map_or(1.0, |s| s.time).max(run.config.dt);
    let commands = [Some(run.config.phi_command), Some(run.config.theta_command), None];
    let names = ["Phi (roll)", "The (pitch)", "Psi (yaw)"];
    let groups: [&[usize]; 2] = [&[0, 1], &[2]];
    for (panel, group) in panels.iter().zip(groups) {
        let values = run
            .samples
            .iter()
            .flat_map(|s| group.iter().flat_map(move |&i| [s.angles[i], s.reference_angles[i]]));
        let extra = group.iter().filter_map(|&i| commands[i]);
        let (lo, hi) = range(values.chain(extra));
        let title = if group.len() == 2 {
            format!(
                "aircraft: roll and pitch [deg], command Phic = {}, Thec = {} (dashed: RK4 reference)",
                run.config.phi_command, run.config.theta_command
            )
        } else {
            "aircraft: yaw [deg] (the steady turn)".to_string()
        };
        let mut chart = ChartBuilder::on(panel)
            .caption(title, ("sans-serif", 14))
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(55)
            .build_cartesian_2d(0.0..t_end, lo..hi)
            .map_err(|e| err(&e))?;
        chart.configure_mesh().x_desc("t [s]").draw().map_err(|e| err(&e))?;
        for &i in group {
            let colour = BODY_COLOURS[i];
            chart
                .draw_series(LineSeries::new(
                    run.samples.iter().map(|s| (s.time, s.angles[i])),
                    colour.stroke_width(2),
                ))
                .map_err(|e| err(&e))?
                .label(format!("{} False Euler dT = {}", names[i], run.config.dt))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
            chart
                .draw_series(DashedLineSeries::new(
                    run.samples.iter().map(|s| (s.time, s.reference_angles[i])),
                    4,
                    3,
                    BLACK.stroke_width(1),
                ))
                .map_err(|e| err(&e))?;
            if let Some(c) = commands[i] {
                chart
                    .draw_series(DashedLineSeries::new(
                        [(0.0, c), (t_end, c)],
                        8,
                        4,
                        colour.mix(0.5).stroke_width(1),
                    ))
                    .map_err(|e| err(&e))?
                    .label(format!("{} command", names[i]))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], colour.mix(0.5))
                    });
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))?;
    drop(root);
    Ok(vec![dir.join("aircraft_angles.svg")])
}
