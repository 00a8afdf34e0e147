//! The work-precision figure, in the manner of DiffEqDevTools: log–log,
//! error on the x axis against cost per simulated period on the y axis, one
//! line per method, as SVG (plotters' SVG backend only).
//!
//! Each line sweeps Φ over a log grid from 10⁻³ up to the method's search
//! cap (just below Φ_max, or π); a point is (error over the target's
//! duration, ns per period = ns_per_step · 2π/Φ). The error is the larger of
//! the phase drift (radians) and the relative amplitude drift
//! ([`Accuracy::error`](super::accuracy::Accuracy::error)). Points with an error
//! outside [10⁻¹⁰, 1] or without oscillation are left out.

use std::f64::consts::PI;
use std::path::Path;

use plotters::prelude::*;

use super::accuracy::{Spring, Target};
use super::family::Candidate;
use crate::error::Error;

/// One line of the figure: (error, ns per period) points, cheap steps last.
pub(crate) fn line(
    c: &Candidate,
    spring: Spring,
    target: &Target,
    ns_per_step: f64,
) -> Vec<(f64, f64)> {
    let cap = c.limit.search_cap().unwrap_or(PI).min(PI);
    let n = 240;
    let lo: f64 = 1e-3;
    (0..=n)
        .map(|k| lo * (cap / lo).powf(k as f64 / n as f64))
        .map(|phi| (c.model.accuracy(phi, spring), phi))
        .filter(|(a, _)| a.oscillating)
        .map(|(a, phi)| (a.error(target.periods), ns_per_step * 2.0 * PI / phi))
        .filter(|&(e, _)| (1e-10..=1.0).contains(&e))
        .collect()
}

/// Draws the figure for `candidates` (with their measured ns per step) to
/// `path`.
pub(crate) fn draw(
    path: &Path,
    candidates: &[(&Candidate, f64)],
    spring: Spring,
    target: &Target,
) -> Result<(), Error> {
    let err = |e: &dyn std::fmt::Display| Error::figure(format!("{}: {e}", path.display()));
    let lines: Vec<(String, Vec<(f64, f64)>)> = candidates
        .iter()
        .map(|(c, ns)| {
            let unstable = c.limit.phi_max.is_none() && !c.limit.bounded_for_all;
            let label =
                if unstable { format!("{} (unstable)", c.display) } else { c.display.clone() };
            (label, line(c, spring, target, *ns))
        })
        .collect();
    let all = lines.iter().flat_map(|(_, l)| l.iter());
    let (mut ymin, mut ymax) = (f64::INFINITY, 0.0f64);
    for &(_, y) in all {
        ymin = ymin.min(y);
        ymax = ymax.max(y);
    }
    if !ymin.is_finite() {
        return Err(Error::figure("no method meets any error below 1: nothing to draw"));
    }
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let caption = format!(
        "Work-precision: error after {} periods vs cost per period (undamped spring)",
        target.periods
    );
    let mut chart = ChartBuilder::on(&root)
        .caption(caption, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((1e-10f64..1.0f64).log_scale(), (ymin * 0.8..ymax * 1.25).log_scale())
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc("error: max(phase drift [rad], relative amplitude drift)")
        .y_desc("ns per simulated period")
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()
        .map_err(|e| err(&e))?;
    for (k, (label, pts)) in lines.iter().enumerate() {
        let color = Palette99::pick(k).to_rgba();
        chart
            .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label(label.clone())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}
