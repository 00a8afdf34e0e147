//! The drift figure: RMS round-off drift of the conserved form against the
//! number of steps, measured and modelled, on log–log axes (SVG).

use std::path::Path;

use plotters::prelude::*;

use crate::error::Error;

/// One method's measured and modelled RMS drift, `(N, drift in ε)`.
pub(crate) struct Line {
    /// The legend label.
    pub label: String,
    /// Measured RMS drift at each checkpoint.
    pub measured: Vec<(f64, f64)>,
    /// The model's RMS drift at each checkpoint.
    pub predicted: Vec<(f64, f64)>,
}

/// Draws `lines` to `path`.
pub(crate) fn draw(path: &Path, lines: &[Line]) -> Result<(), Error> {
    let err =
        |e: &dyn std::fmt::Display| Error::figure(format!("{}: cannot draw: {e}", path.display()));
    let pts =
        || lines.iter().flat_map(|l| l.measured.iter().chain(&l.predicted)).filter(|p| p.1 > 0.0);
    let xmax = pts().map(|p| p.0).fold(10.0f64, f64::max);
    let ymin = pts().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let ymax = pts().map(|p| p.1).fold(0.0f64, f64::max);
    if !ymin.is_finite() {
        return Err(Error::figure("no nonzero drift to draw"));
    }
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Round-off drift of the conserved form: RMS over starts (solid) and model (dashed)",
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((1.0f64..xmax).log_scale(), (ymin * 0.5..ymax * 2.0).log_scale())
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc("steps N")
        .y_desc("RMS |Q(x_N)/Q(x_0) - 1| in units of eps")
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()
        .map_err(|e| err(&e))?;
    for (k, l) in lines.iter().enumerate() {
        let color = Palette99::pick(k).to_rgba();
        let measured: Vec<(f64, f64)> = l.measured.iter().copied().filter(|p| p.1 > 0.0).collect();
        chart
            .draw_series(LineSeries::new(measured, color.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label(l.label.clone())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
        let predicted: Vec<(f64, f64)> =
            l.predicted.iter().copied().filter(|p| p.1 > 0.0).collect();
        chart
            .draw_series(DashedLineSeries::new(predicted, 6, 4, color.stroke_width(1)))
            .map_err(|e| err(&e))?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperLeft)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}
