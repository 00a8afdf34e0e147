//! The paper's figures, drawn as SVG with plotters: y(t) of a method against
//! the exact cosine (sections 5–11, which the text copy of the paper lacks),
//! and the z-plane with the unit circle and the eigenvalue loci as Φ sweeps.
//!
//! y(t) uses the canonical oscillator of section 3 with ω₀ = 1, so the step
//! is T = Φ, the samples are y_k at t = kΦ from v₀ = 0, y₀ = 1 (Verlet's
//! `y@1 = y₀`, the paper's `y2:=1`), and the exact solution is cos t.

use check::numeric::ParamsF64;
use std::path::Path;

use plotters::prelude::*;
use poly::Method;

use check::numeric::{initial_slots, Params, Step};
use check::witness::ExactCharpoly;

use crate::error::Error;
use crate::load::LoadedMethod;

fn draw_err(path: &Path) -> impl Fn(&dyn std::error::Error) -> Error + '_ {
    move |e| Error::figure(format!("{}: cannot draw: {e}", path.display()))
}

/// The samples (t_k, y_k), k = 0..=n_steps, of `method` at `params` from
/// v₀ = 0, y₀ = 1 (the variable named `y`, else the last state variable,
/// starts at 1; the others at 0).
pub fn samples(
    method: &Method,
    params: &Params,
    n_steps: usize,
) -> Result<Vec<(f64, f64)>, check::Error> {
    let step = Step::compile(method, params)?;
    let y_name = if method.state().iter().any(|s| s == "y") {
        "y".to_owned()
    } else {
        method.state().last().cloned().unwrap_or_default()
    };
    let start = initial_slots(method, |v| if v == y_name { 1.0 } else { 0.0 });
    let y_slot = method
        .slots()
        .iter()
        .position(|&(var, lag)| method.state()[var] == y_name && lag == 0)
        .unwrap_or(0);
    let phi = params.phi_value();
    let mut state = step.state(&start);
    let mut out = vec![(0.0, start[y_slot])];
    for k in 1..=n_steps {
        step.advance(&mut state, 1);
        out.push((k as f64 * phi, state.slots()[y_slot]));
    }
    Ok(out)
}

/// Draws y(t) of `method` at `params` over `t_max` (in units of 1/ω₀) into
/// an SVG at `path`.
pub(crate) fn yt_figure(
    method: &Method,
    params: &Params,
    t_max: f64,
    path: &Path,
) -> Result<(), Error> {
    let root = SVGBackend::new(path, (720, 360)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| draw_err(path)(&e))?;
    draw_yt(&root, method, params, t_max).map_err(|e| draw_err(path)(e.as_ref()))?;
    root.present().map_err(|e| draw_err(path)(&e))?;
    Ok(())
}

/// Draws y(t) of every method in `methods` as a grid of panels.
pub(crate) fn yt_grid(
    methods: &[LoadedMethod],
    params: &Params,
    t_max: f64,
    path: &Path,
) -> Result<(), Error> {
    let rows = methods.len().div_ceil(2);
    let root = SVGBackend::new(path, (1200, 300 * rows as u32)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| draw_err(path)(&e))?;
    for (area, m) in root.split_evenly((rows, 2)).iter().zip(methods) {
        draw_yt(area, m.method(), params, t_max).map_err(|e| draw_err(path)(e.as_ref()))?;
    }
    root.present().map_err(|e| draw_err(path)(&e))?;
    Ok(())
}

type DrawResult = Result<(), Box<dyn std::error::Error>>;

fn draw_yt<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    m: &Method,
    params: &Params,
    t_max: f64,
) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let phi = params.phi_value();
    let n = (t_max / phi).ceil() as usize;
    let pts = samples(m, params, n)?;
    let y_lim = pts.iter().map(|p| p.1.abs()).fold(1.2f64, f64::max).min(3.0);
    let extra: Vec<String> = params
        .iter_f64()
        .into_iter()
        .filter(|(k, _)| *k != "Phi")
        .map(|(k, v)| format!(", {k} = {v}"))
        .collect();
    let mut chart = ChartBuilder::on(area)
        .caption(
            format!("{}: y(t), Phi = {phi}{}, v0 = 0, y0 = 1", m.name(), extra.concat()),
            ("sans-serif", 16),
        )
        .margin(8)
        .x_label_area_size(28)
        .y_label_area_size(40)
        .build_cartesian_2d(0.0..t_max, -y_lim..y_lim)?;
    chart
        .configure_mesh()
        .x_desc("t (1/w0)")
        .y_desc("y")
        .light_line_style(WHITE.mix(0.0))
        .draw()?;
    chart
        .draw_series(LineSeries::new(
            (0..=600).map(|i| t_max * i as f64 / 600.0).map(|t| (t, t.cos())),
            BLACK.mix(0.6),
        ))?
        .label("exact cos t")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], BLACK.mix(0.6)));
    let inside: Vec<(f64, f64)> = pts
        .into_iter()
        .filter(|p| p.0 <= t_max)
        .map(|(t, y)| (t, y.clamp(-y_lim, y_lim)))
        .collect();
    chart
        .draw_series(LineSeries::new(inside.clone(), RED.stroke_width(1)))?
        .label("samples y_k")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], RED));
    chart.draw_series(inside.iter().map(|&p| Circle::new(p, 3, RED.filled())))?;
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK.mix(0.3))
        .draw()?;
    Ok(())
}

/// Draws the z-plane: the unit circle and the roots of each method's χ as
/// Φ runs from 0 to `phi_max` (`points` values), one colour per method.
pub(crate) fn zplane_figure(
    methods: &[LoadedMethod],
    params: &Params,
    phi_max: f64,
    points: usize,
    path: &Path,
) -> Result<(), Error> {
    let mut loci = Vec::new();
    for m in methods {
        let chi = ExactCharpoly::from_derivation(m.derivation()?);
        let mut pts = Vec::new();
        for i in 0..=points {
            let phi = phi_max * i as f64 / points as f64;
            let f = chi.at(&params.clone().with("Phi", phi))?;
            pts.extend(f.roots.iter().map(|z| (z.re, z.im)));
        }
        loci.push((m.method().name().to_owned(), pts));
    }
    let root = SVGBackend::new(path, (720, 720)).into_drawing_area();
    let err = draw_err(path);
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let result: DrawResult = (|| {
        let mut chart = ChartBuilder::on(&root)
            .caption(
                format!("z-plane: roots of chi(z) for 0 <= Phi <= {phi_max}, unit circle"),
                ("sans-serif", 18),
            )
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(40)
            .build_cartesian_2d(-2.5..1.5, -2.0..2.0)?;
        chart.configure_mesh().x_desc("Re z").y_desc("Im z").draw()?;
        chart.draw_series(LineSeries::new(
            (0..=360).map(|i| (i as f64).to_radians()).map(|a| (a.cos(), a.sin())),
            BLACK.stroke_width(2),
        ))?;
        for (idx, (name, pts)) in loci.iter().enumerate() {
            let colour = Palette99::pick(idx).to_rgba();
            chart
                .draw_series(
                    pts.iter()
                        .filter(|p| p.0.abs() <= 2.5 && p.1.abs() <= 2.0)
                        .map(|&p| Circle::new(p, 2, colour.filled())),
                )?
                .label(name.as_str())
                .legend(move |(x, y)| Circle::new((x + 6, y), 4, colour.filled()));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK.mix(0.3))
            .draw()?;
        Ok(())
    })();
    result.map_err(|e| err(e.as_ref()))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}
