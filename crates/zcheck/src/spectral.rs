//! The structural-dynamics figures of a method on the oscillator, as in
//! Hughes (The Finite Element Method, ch. 9): the spectral radius ρ(Φ), and
//! the period elongation T̄/T − 1 and algorithmic damping ξ̄ against Φ/2π.
//!
//! The numbers are floating point, from the roots of the exact χ at each Φ
//! (`check`'s `ExactCharpoly`: coefficients evaluated exactly, roots
//! polished against them). With z the principal root, z = exp(Φ̄(−ξ̄ ± i)):
//! Ω̄ = arg z, ξ̄ = −ln|z|/Ω̄, and T̄/T = Φ/Ω̄. The principal root is
//! followed by continuation from the root nearest e^{iΦ} at the smallest Φ,
//! so a spurious root of a multistep or three-state method is never taken
//! for it; its curve ends where the principal pair meets the real axis (no
//! period is left).

use std::path::Path;

use check::numeric::Params;
use check::witness::{ExactCharpoly, C64};
use plotters::prelude::*;

use crate::error::Error;

/// One point of the period and damping curves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Hughes {
    /// Φ.
    pub phi: f64,
    /// T̄/T − 1 = Φ/Ω̄ − 1.
    pub elongation: f64,
    /// ξ̄ = −ln|z|/Ω̄.
    pub damping: f64,
}

/// A method's curve, named for the legend.
#[derive(Clone, Debug)]
pub(crate) struct Series<T> {
    /// The legend's name.
    pub name: String,
    /// The points.
    pub points: Vec<T>,
}

/// The roots of χ at Φ; `None` where the step is singular or the roots
/// cannot be taken.
fn roots_at(chi: &ExactCharpoly, params: &Params, phi: f64) -> Option<Vec<C64>> {
    let p = params.clone().bind("Phi", check::numeric::f64_to_q(phi)?);
    chi.at(&p).ok().map(|f| f.roots)
}

/// (Φ, ρ(Φ)) at each Φ where the step is defined.
pub(crate) fn spectral_radius(
    chi: &ExactCharpoly,
    params: &Params,
    phis: &[f64],
) -> Vec<(f64, f64)> {
    phis.iter()
        .filter_map(|&phi| {
            let roots = roots_at(chi, params, phi)?;
            Some((phi, roots.iter().map(|z| z.norm()).fold(0.0, f64::max)))
        })
        .collect()
}

/// The period elongation and damping of the principal root at each Φ of
/// the increasing `phis`, until the principal pair turns real.
pub(crate) fn period_damping(chi: &ExactCharpoly, params: &Params, phis: &[f64]) -> Vec<Hughes> {
    let mut out = Vec::new();
    let mut previous: Option<C64> = None;
    for &phi in phis {
        let Some(roots) = roots_at(chi, params, phi) else { continue };
        let target = previous.unwrap_or_else(|| C64::from_polar(1.0, phi));
        let Some(z) = roots
            .iter()
            .filter(|z| z.im >= 0.0)
            .min_by(|a, b| (**a - target).norm().total_cmp(&(**b - target).norm()))
            .copied()
        else {
            break;
        };
        if z.im <= 1e-12 * z.norm() {
            break;
        }
        let omega = z.arg();
        out.push(Hughes { phi, elongation: phi / omega - 1.0, damping: -z.norm().ln() / omega });
        previous = Some(z);
    }
    out
}

/// Ten distinct line colours (matplotlib's tab10), one per method.
const COLOURS: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

fn draw_err(path: &Path) -> impl Fn(&dyn std::fmt::Display) -> Error + '_ {
    move |e| Error::figure(format!("{}: cannot draw: {e}", path.display()))
}

/// Runs of consecutive points inside [lo, hi] in y: a curve leaving the
/// frame is cut, not drawn along its edge.
fn runs(points: &[(f64, f64)], lo: f64, hi: f64) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for &(x, y) in points {
        if (lo..=hi).contains(&y) {
            out.last_mut().expect("one run").push((x, y));
        } else if !out.last().expect("one run").is_empty() {
            out.push(Vec::new());
        }
    }
    out.retain(|r| !r.is_empty());
    out
}

/// The Φ of the spectral-radius figure: log-spaced from 10^-2 to 10^3.
pub(crate) fn radius_phis() -> Vec<f64> {
    (0..=400).map(|k| 10f64.powf(-2.0 + 5.0 * k as f64 / 400.0)).collect()
}

/// The Φ of the period figure: 400 steps up to `phi_max`.
pub(crate) fn period_phis(phi_max: f64) -> Vec<f64> {
    (1..=400).map(|k| phi_max * k as f64 / 400.0).collect()
}

/// Draws ρ(Φ) of each series against a logarithmic Φ axis.
pub(crate) fn radius_figure(series: &[Series<(f64, f64)>], path: &Path) -> Result<(), Error> {
    let err = draw_err(path);
    let root = SVGBackend::new(path, (800, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let (lo, hi) = (0.0, 1.5);
    let result: Result<(), Box<dyn std::error::Error>> = (|| {
        let mut chart = ChartBuilder::on(&root)
            .caption("spectral radius rho(Phi) on the oscillator", ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(36)
            .y_label_area_size(48)
            .build_cartesian_2d((1e-2f64..1e3).log_scale(), lo..hi)?;
        chart
            .configure_mesh()
            .x_desc("Phi = w T (log scale)")
            .y_desc("spectral radius rho")
            .draw()?;
        chart.draw_series(LineSeries::new([(1e-2, 1.0), (1e3, 1.0)], BLACK.mix(0.3)))?;
        for (k, s) in series.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            let style = colour.stroke_width(2);
            for (i, run) in runs(&s.points, lo, hi).into_iter().enumerate() {
                let drawn = chart.draw_series(LineSeries::new(run, style))?;
                if i == 0 {
                    drawn.label(s.name.as_str()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 16, y)], colour.stroke_width(2))
                    });
                }
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.3))
            .position(SeriesLabelPosition::LowerLeft)
            .draw()?;
        Ok(())
    })();
    result.map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

/// Draws the period elongation and the algorithmic damping of each series
/// against Φ/2π, side by side.
pub(crate) fn period_figure(
    series: &[Series<Hughes>],
    phi_max: f64,
    path: &Path,
) -> Result<(), Error> {
    let err = draw_err(path);
    let root = SVGBackend::new(path, (1100, 480)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let panels = root.split_evenly((1, 2));
    let x_max = phi_max / std::f64::consts::TAU;
    let result: Result<(), Box<dyn std::error::Error>> = (|| {
        for (panel, (title, pick, clip)) in panels.iter().zip([
            (
                "period elongation T'/T - 1",
                (|h: &Hughes| h.elongation) as fn(&Hughes) -> f64,
                (-0.5, 1.0),
            ),
            ("algorithmic damping ratio xi'", |h: &Hughes| h.damping, (-0.2, 0.5)),
        ]) {
            let values = series.iter().flat_map(|s| s.points.iter().map(pick));
            let (mut lo, mut hi) = values.fold((0.0f64, 0.0f64), |(a, b), v| (a.min(v), b.max(v)));
            lo = lo.max(clip.0);
            hi = hi.min(clip.1);
            if hi - lo < 1e-3 {
                hi = lo + 1e-3;
            }
            let pad = 0.05 * (hi - lo);
            let (lo, hi) = (lo - pad, hi + pad);
            let mut chart = ChartBuilder::on(panel)
                .caption(title, ("sans-serif", 17))
                .margin(10)
                .x_label_area_size(36)
                .y_label_area_size(56)
                .build_cartesian_2d(0.0..x_max, lo..hi)?;
            chart.configure_mesh().x_desc("Phi / 2 pi = T_step / T").y_desc(title).draw()?;
            for (k, s) in series.iter().enumerate() {
                let colour = COLOURS[k % COLOURS.len()];
                let points: Vec<(f64, f64)> =
                    s.points.iter().map(|h| (h.phi / std::f64::consts::TAU, pick(h))).collect();
                for (i, run) in runs(&points, lo, hi).into_iter().enumerate() {
                    let drawn = chart.draw_series(LineSeries::new(run, colour.stroke_width(2)))?;
                    if i == 0 {
                        drawn.label(s.name.as_str()).legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 16, y)], colour.stroke_width(2))
                        });
                    }
                }
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK.mix(0.3))
                .position(SeriesLabelPosition::UpperLeft)
                .draw()?;
        }
        Ok(())
    })();
    result.map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chi(name: &str) -> ExactCharpoly {
        ExactCharpoly::from_derivation(&poly::derive(&poly::builtin(name).unwrap()).unwrap())
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * b.abs().max(1e-3)
    }

    /// Trapezoidal and implicit midpoint: |z| = 1, so ξ̄ = 0 and ρ = 1, and
    /// Ω̄ = 2 atan(Φ/2): elongation Φ/(2 atan(Φ/2)) − 1, at every Φ up to 3.
    #[test]
    fn trapezoidal_closed_forms() {
        for name in ["trapezoidal", "implicit_midpoint"] {
            let c = chi(name);
            let h = period_damping(&c, &Params::new(), &period_phis(3.0));
            assert_eq!(h.len(), 400, "{name}: the pair stays complex");
            for p in &h {
                let want = p.phi / (2.0 * (p.phi / 2.0).atan()) - 1.0;
                assert!(close(p.elongation, want, 1e-9), "{name} at {}: {p:?} vs {want}", p.phi);
                assert!(p.damping.abs() < 1e-12, "{name}: {p:?}");
            }
            for (phi, rho) in spectral_radius(&c, &Params::new(), &radius_phis()) {
                assert!((rho - 1.0).abs() < 1e-12, "{name} at {phi}: {rho}");
            }
        }
    }

    /// Backward Euler: z = 1/(1 ∓ iΦ), so ρ = 1/√(1 + Φ²), Ω̄ = atan Φ and
    /// ξ̄ = ln(1 + Φ²)/(2 atan Φ).
    #[test]
    fn backward_euler_closed_forms() {
        let c = chi("backward_euler");
        for (phi, rho) in spectral_radius(&c, &Params::new(), &radius_phis()) {
            assert!(close(rho, 1.0 / (1.0 + phi * phi).sqrt(), 1e-12), "{phi}: {rho}");
        }
        let h = period_damping(&c, &Params::new(), &period_phis(6.0));
        assert_eq!(h.len(), 400);
        for p in &h {
            let (phi, a) = (p.phi, p.phi.atan());
            assert!(close(p.elongation, phi / a - 1.0, 1e-9), "{p:?}");
            assert!(close(p.damping, (1.0 + phi * phi).ln() / (2.0 * a), 1e-9), "{p:?}");
        }
    }

    /// False Euler: on the circle with cos Ω̄ = 1 − Φ²/2 below Φ = 2, where
    /// the pair turns real and the period curve ends; beyond, ρ is the
    /// larger real root's modulus, (Φ²/2 − 1) + √((Φ²/2 − 1)² − 1).
    #[test]
    fn false_euler_ends_at_its_limit() {
        let c = chi("false_euler");
        let h = period_damping(&c, &Params::new(), &period_phis(3.0));
        let last = h.last().unwrap().phi;
        assert!(last < 2.0 && last > 1.98, "the curve ends at Phi = 2: {last}");
        for p in &h {
            let want = p.phi / (1.0 - p.phi * p.phi / 2.0).acos() - 1.0;
            assert!(close(p.elongation, want, 1e-7), "{p:?} vs {want}");
            assert!(p.damping.abs() < 1e-7, "{p:?}");
        }
        for (phi, rho) in spectral_radius(&c, &Params::new(), &radius_phis()) {
            let b = phi * phi / 2.0 - 1.0;
            let want = if phi < 2.0 { 1.0 } else { b + (b * b - 1.0).sqrt() };
            assert!(close(rho, want, 1e-6), "{phi}: {rho} vs {want}");
        }
    }

    /// BDF2 has a spurious root (1/3 at Φ = 0): the continuation follows
    /// the principal one, whose phase error starts as Φ³·(small), so the
    /// elongation tends to 0, and the damping is positive.
    #[test]
    fn bdf2_follows_the_principal_root() {
        let c = chi("bdf2");
        let h = period_damping(&c, &Params::new(), &period_phis(1.0));
        assert!(h.len() > 300);
        assert!(h[0].elongation.abs() < 1e-3 && h[0].damping.abs() < 1e-3, "{:?}", h[0]);
        assert!(h.iter().all(|p| p.damping > 0.0), "BDF2 dissipates");
    }

    /// A curve leaving the frame is cut into the runs inside it.
    #[test]
    fn runs_cut_at_the_frame() {
        let pts = [(0.0, 0.5), (1.0, 2.0), (2.0, 0.7), (3.0, 0.8)];
        assert_eq!(runs(&pts, 0.0, 1.0), vec![vec![(0.0, 0.5)], vec![(2.0, 0.7), (3.0, 0.8)]]);
    }
}
