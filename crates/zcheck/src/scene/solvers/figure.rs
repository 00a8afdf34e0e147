//! `zcheck plot solvers --scene FILE --out DIR`: phase and amplitude error
//! against cost for (S, N) pairs, one line per solver and iteration count,
//! S = 1, 2, 4, …, 64 along it; and the "small steps" comparison (Macklin et
//! al. 2019) at equal cost S·N, more substeps against more iterations,
//! said for phase and for amplitude separately.
//!
//! Every point is one configuration analysed as the search screens it
//! (the eigenvalues of the deflated substep map); unstable configurations
//! are left out of the figure and counted.

use std::path::Path;

use plotters::prelude::*;

use super::analysis::{self, Depth, Prepared};
use super::model::{Config, Solver};
use crate::error::Error;
use crate::scene::file::SceneFile;

/// The substep counts along a line.
const SUBSTEPS: [u64; 7] = [1, 2, 4, 8, 16, 32, 64];
/// The iteration counts, one line each (1 only for the soft step).
const ITERATIONS: [u64; 5] = [1, 2, 4, 8, 16];

/// What a panel draws of a point.
type Measure = fn(&Point) -> f64;

/// One configuration's point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Point {
    /// Substeps per tick.
    pub substeps: u64,
    /// Iterations per substep.
    pub iterations: u64,
    /// Constraint projections per tick, S·N·constraints.
    pub cost: u64,
    /// Stable on the non-rigid modes.
    pub stable: bool,
    /// Largest phase error over the duration, rad.
    pub phase: f64,
    /// Largest relative amplitude error over the duration.
    pub amplitude: f64,
    /// Largest |effective − true damping ratio| over the modes in the band:
    /// what tells amplitudes apart where both errors saturate at 1.
    pub ratio_gap: f64,
}

/// One solver's points over the (S, N) grid.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SolverPoints {
    /// The solver.
    pub solver: Solver,
    /// Its points, by iterations then substeps.
    pub points: Vec<Point>,
}

/// The small-steps comparison at one equal cost S·N = k: (k substeps, 1
/// iteration) against (1 substep, k iterations).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SmallSteps {
    /// S·N.
    pub units: u64,
    /// Whether more substeps give the smaller phase error.
    pub phase_holds: bool,
    /// Whether more substeps give the smaller amplitude error.
    pub amplitude_holds: bool,
}

/// Every solver's points on `scene`.
pub(crate) fn points(scene: &SceneFile, solvers: &[Solver]) -> Result<Vec<SolverPoints>, Error> {
    let prep = Prepared::new(scene)?;
    solvers
        .iter()
        .map(|&solver| {
            let mut points = Vec::new();
            for n in ITERATIONS.into_iter().filter(|n| solver.iteration_range().contains(n)) {
                for s in SUBSTEPS {
                    if crate::interrupt::requested() {
                        return Err(Error::interrupted(
                            "the solver figure was stopped before it ended",
                        ));
                    }
                    let a = analysis::analyse(&prep, &Config::new(solver, s, n)?, Depth::Screen)?;
                    points.push(Point {
                        substeps: s,
                        iterations: n,
                        cost: a.cost,
                        stable: a.stable,
                        phase: a.phase_error_rad,
                        amplitude: a.amplitude_error,
                        ratio_gap: a
                            .modes
                            .iter()
                            .filter(|m| m.in_band)
                            .map(|m| (m.effective_ratio - m.ratio).abs())
                            .fold(0.0, f64::max),
                    });
                }
            }
            Ok(SolverPoints { solver, points })
        })
        .collect()
}

/// The small-steps comparison of one solver's points, at every equal cost
/// the grid has both ends of (k substeps × 1 iteration, 1 substep × k
/// iterations, k > 1). "Holds" needs the substep configuration stable and
/// its error strictly smaller (or the iteration one unstable); amplitude
/// compares the amplitude error, then (where both saturate alike) the
/// damping-ratio gap.
pub(crate) fn small_steps(points: &[Point]) -> Vec<SmallSteps> {
    let at = |s: u64, n: u64| points.iter().find(|p| p.substeps == s && p.iterations == n);
    let better = |a: &Point, b: &Point, f: fn(&Point) -> (f64, f64)| {
        a.stable && (!b.stable || f(a).partial_cmp(&f(b)) == Some(std::cmp::Ordering::Less))
    };
    ITERATIONS
        .into_iter()
        .filter(|&k| k > 1)
        .filter_map(|k| {
            let (sub, it) = (at(k, 1)?, at(1, k)?);
            Some(SmallSteps {
                units: k,
                phase_holds: better(sub, it, |p| (p.phase, 0.0)),
                amplitude_holds: better(sub, it, |p| (p.amplitude, p.ratio_gap)),
            })
        })
        .collect()
}

/// Draws `solvers.svg` in `dir`: phase error (left) and amplitude error
/// (right) against constraint projections per tick.
pub(crate) fn draw(
    dir: &Path,
    name: &str,
    all: &[SolverPoints],
) -> Result<std::path::PathBuf, Error> {
    let path = dir.join("solvers.svg");
    let err = |e: &dyn std::fmt::Display| Error::figure(format!("{}: {e}", path.display()));
    let shown = |v: f64| v.is_finite() && v > 0.0;
    let stable = || all.iter().flat_map(|s| s.points.iter()).filter(|p| p.stable);
    let xmax = stable().map(|p| p.cost).max().ok_or_else(|| {
        Error::figure(format!("{name}: no configuration is stable: nothing to draw"))
    })? as f64;
    let xmin = stable().map(|p| p.cost).min().unwrap_or(1) as f64;
    let range = |f: fn(&Point) -> f64| {
        let (lo, hi) = stable()
            .map(f)
            .filter(|&v| shown(v))
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
        if lo.is_finite() {
            (lo * 0.5, hi * 2.0)
        } else {
            (1e-6, 1.0)
        }
    };
    let left_out: usize = all.iter().flat_map(|s| s.points.iter()).filter(|p| !p.stable).count();
    let root = SVGBackend::new(&path, (1200, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let root = root
        .titled(
            &format!(
                "{name}: error over the duration vs cost, lines of equal iterations N, substeps S = 1..64 \
                 ({left_out} unstable configurations left out)"
            ),
            ("sans-serif", 16),
        )
        .map_err(|e| err(&e))?;
    let panels = root.split_evenly((1, 2));
    let which: [(&str, Measure); 2] =
        [("phase error [rad]", |p| p.phase), ("relative amplitude error", |p| p.amplitude)];
    for (area, (label, f)) in panels.iter().zip(which) {
        let (ylo, yhi) = range(f);
        let mut chart = ChartBuilder::on(area)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d((xmin * 0.8..xmax * 1.25).log_scale(), (ylo..yhi).log_scale())
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .x_desc("constraint projections per tick (S x N x constraints)")
            .y_desc(label)
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()
            .map_err(|e| err(&e))?;
        let mut k = 0;
        for s in all {
            for n in ITERATIONS {
                let pts: Vec<(f64, f64)> = s
                    .points
                    .iter()
                    .filter(|p| p.iterations == n && p.stable && shown(f(p)))
                    .map(|p| (p.cost as f64, f(p)))
                    .collect();
                if pts.is_empty() {
                    continue;
                }
                let color = Palette99::pick(k).to_rgba();
                k += 1;
                chart
                    .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
                    .map_err(|e| err(&e))?
                    .label(format!("{} N = {n}", s.solver.name()))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                    });
                chart
                    .draw_series(pts.iter().map(|&(x, y)| Circle::new((x, y), 3, color.filled())))
                    .map_err(|e| err(&e))?;
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(|e| err(&e))?;
    }
    root.present().map_err(|e| err(&e))?;
    Ok(dir.join("solvers.svg"))
}
