//! The w-plane report of `zcheck region`: poly's exact [`PlaneReport`] as
//! JSON, as a table a person reads, and as an SVG figure of the stability
//! region.
//!
//! The figure is numeric (the roots of χ(z, w) on a grid, by the complex
//! Schur decomposition of `check`), and draws what the exact report says:
//! the shaded region, the boundary locus (the w where a root lies on the
//! unit circle), and the exact axis intervals as thick segments.

use super::exact::{constant, fine, nearest_f64, number};
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::values::ParamArg;
use check::witness::{complex_polynomial_roots, C64};
use num_traits::ToPrimitive;
use plotters::prelude::*;
use poly::advanced::order::Order;
use poly::{Algebraic, PlaneReport, Poly, Sector, Sym, Q};
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::Path;

/// A(α) in degrees, within 1e-12: the arctangent of an enclosure of tan α
/// narrower than 1e-20.
pub(crate) fn alpha_degrees(s: &Sector) -> f64 {
    match s {
        Sector::Empty => 0.0,
        Sector::HalfPlane => 90.0,
        Sector::Angle { tan } => {
            let (lo, hi) = tan.refine(&fine()).interval();
            let (lo, hi) = (lo.to_f64().unwrap_or(0.0), hi.to_f64().unwrap_or(0.0));
            ((lo.atan() + hi.atan()) / 2.0).to_degrees()
        }
    }
}

/// The JSON object of `zcheck region`: `order` is the classical order of
/// the method's nonlinear reading (`null` with `order_at_least` past the
/// trees checked; `null` for a `.zm` program, which has none),
/// `linear_order` the order on y' = λy.
pub(crate) fn to_json(
    name: &str,
    params: &[(String, Q)],
    r: &PlaneReport,
    classical: Option<Order>,
) -> Value {
    let (order, order_at_least) = super::order::order_json(classical);
    let params: serde_json::Map<String, Value> =
        params.iter().map(|(n, v)| (n.clone(), json!(v.to_string()))).collect();
    let limit = |l: &Option<Algebraic>| l.as_ref().map(|a| number(a, "r"));
    json!({
        "method": name,
        "params": params,
        "charpoly": r.charpoly.to_string(),
        "zero_stable": r.zero_stable,
        "order": order,
        "order_at_least": order_at_least,
        "linear_order": r.order,
        "error_constant": r.error_constant.as_ref().map(constant),
        "real_limit": limit(&r.real_limit),
        "imag_limit": limit(&r.imag_limit),
        "a_stable": r.a_stable,
        "a_alpha_deg": alpha_degrees(&r.a_alpha),
        "a_alpha_exact": match &r.a_alpha {
            Sector::Empty => json!("0"),
            Sector::HalfPlane => json!("90"),
            Sector::Angle { tan } => json!(format!("atan({})", tan.refine(&fine()).describe("t"))),
        },
        "l_stable": r.l_stable,
        "rho_inf": r.rho_inf.as_ref().map(|a| number(a, "x")),
    })
}

fn show(a: &Algebraic) -> String {
    let exact = a.closed_form().unwrap_or_else(|| a.defining_poly().to_string_in("x"));
    match a.closed_form() {
        Some(c) if a.is_rational() => c,
        Some(_) => format!("{exact} ≈ {}", a.to_decimal(12)),
        None => format!("{} (a root of {exact})", a.to_decimal(12)),
    }
}

/// The table a person reads.
pub(crate) fn to_text(
    name: &str,
    params: &[(String, Q)],
    r: &PlaneReport,
    classical: Option<Order>,
) -> String {
    let mut s = String::new();
    let row = |s: &mut String, k: &str, v: String| {
        let _ = writeln!(s, "  {k:<16} {v}");
    };
    let shown: Vec<String> = params.iter().map(|(n, v)| format!("{n} = {v}")).collect();
    let _ = writeln!(
        s,
        "{name} on y' = λy, w = hλ{}",
        if shown.is_empty() { String::new() } else { format!(" ({})", shown.join(", ")) }
    );
    row(&mut s, "chi(z, w)", r.charpoly.to_string());
    row(
        &mut s,
        "classical order",
        match classical {
            Some(Order::Exact(p)) => format!("{p} (on y' = f(y), zcheck order)"),
            Some(Order::AtLeast(p)) => format!("at least {p} (on y' = f(y), zcheck order)"),
            None => "none: no nonlinear reading (a .zm program is the method on the \
                     oscillator or y' = λy only)"
                .to_owned(),
        },
    );
    row(
        &mut s,
        "linear order",
        match r.order {
            Some(p) => format!("{p} (on y' = λy)"),
            None => "none: no simple root of chi(z, 0) is 1 (not consistent)".to_owned(),
        },
    );
    if let Some(c) = &r.error_constant {
        let v = poly::advanced::field::approx(c, &fine()).to_f64().unwrap_or(f64::NAN);
        row(&mut s, "error constant", format!("{c} ≈ {v:.6e}  (e^w − z1(w) = C w^(p+1) + …)"));
    }
    if !r.zero_stable {
        row(&mut s, "zero-stable", "no: chi(z, 0) breaks the root condition".to_owned());
    }
    row(
        &mut s,
        "real axis",
        match &r.real_limit {
            None => "stable on all of (−∞, 0]".to_owned(),
            Some(l) if l.sign().is_eq() => "unstable just left of 0".to_owned(),
            Some(l) => format!("stable on (−r, 0], r = {}", show(l)),
        },
    );
    row(
        &mut s,
        "imaginary axis",
        match &r.imag_limit {
            None => "stable on the whole axis".to_owned(),
            Some(l) if l.sign().is_eq() => "unstable just off 0".to_owned(),
            Some(l) => format!("stable on i·(−r, r), r = {}", show(l)),
        },
    );
    let yes = |b: bool| if b { "yes" } else { "no" }.to_owned();
    row(&mut s, "A-stable", yes(r.a_stable));
    row(
        &mut s,
        "A(alpha)",
        match &r.a_alpha {
            Sector::Angle { tan } => format!(
                "{:.12}° (tan α = {})",
                alpha_degrees(&r.a_alpha),
                tan.closed_form().unwrap_or_else(|| tan.to_decimal(15))
            ),
            other => format!("{}°", alpha_degrees(other)),
        },
    );
    row(&mut s, "L-stable", yes(r.l_stable));
    row(
        &mut s,
        "rho_inf",
        match &r.rho_inf {
            None => "none: a root tends to ∞ as w → ∞".to_owned(),
            Some(x) => show(x),
        },
    );
    s
}

/// χ(z, w) at a complex w, as complex coefficients in z.
fn chi_at(chi: &Poly, w: C64) -> Vec<C64> {
    let value = |c: &Poly| -> C64 {
        c.coeffs_in(Sym::w())
            .iter()
            .enumerate()
            .map(|(k, a)| {
                let a = poly::advanced::field::approx(a, &fine()).to_f64().unwrap_or(f64::NAN);
                w.powu(k as u32) * a
            })
            .sum()
    };
    chi.coeffs_in(Sym::z()).iter().map(value).collect()
}

/// χ at z = e^{iθ} as a polynomial in w: its roots are the boundary locus.
fn locus_at(chi: &Poly, theta: f64) -> Vec<C64> {
    let z = C64::from_polar(1.0, theta);
    let value = |c: &Poly| -> C64 {
        c.coeffs_in(Sym::z())
            .iter()
            .enumerate()
            .map(|(k, a)| {
                let a = poly::advanced::field::approx(a, &fine()).to_f64().unwrap_or(f64::NAN);
                z.powu(k as u32) * a
            })
            .sum()
    };
    chi.coeffs_in(Sym::w()).iter().map(value).collect()
}

/// The largest |z| of χ(z, w), numerically.
fn max_modulus(chi: &Poly, w: C64) -> f64 {
    complex_polynomial_roots(&chi_at(chi, w))
        .map(|r| r.iter().map(|z| z.norm()).fold(0.0, f64::max))
        .unwrap_or(f64::INFINITY)
}

/// The window a figure shows: wide enough for every finite axis limit.
fn window(reports: &[(String, PlaneReport)]) -> f64 {
    let mut r: f64 = 3.0;
    for (_, p) in reports {
        for l in [&p.real_limit, &p.imag_limit].into_iter().flatten() {
            r = r.max(nearest_f64(l, None) * 1.25);
        }
    }
    r.min(60.0)
}

/// Draws the stability regions of one method or several overlaid.
pub(crate) fn figure(reports: &[(String, PlaneReport)], path: &Path) -> Result<(), Error> {
    let err = |e: &dyn std::error::Error| {
        Error::file(&path.display().to_string(), 1, 1, &format!("cannot draw: {e}"))
    };
    let r = window(reports);
    let (x0, x1, y0, y1) = (-r, r * 0.4, -r * 0.7, r * 0.7);
    let root = SVGBackend::new(path, (900, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let result: Result<(), Box<dyn std::error::Error>> = (|| {
        let mut chart = ChartBuilder::on(&root)
            .caption("stability regions in the w = hλ plane (y' = λy)", ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(40)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart.configure_mesh().x_desc("Re w").y_desc("Im w").draw()?;
        let n = 120;
        for (idx, (name, p)) in reports.iter().enumerate() {
            let colour = Palette99::pick(idx).to_rgba();
            let (dx, dy) = ((x1 - x0) / n as f64, (y1 - y0) / n as f64);
            let mut cells = Vec::new();
            for i in 0..n {
                for j in 0..n {
                    let w = C64::new(x0 + (i as f64 + 0.5) * dx, y0 + (j as f64 + 0.5) * dy);
                    if max_modulus(&p.charpoly, w) <= 1.0 + 1e-9 {
                        cells.push((
                            (w.re - dx / 2.0, w.im - dy / 2.0),
                            (w.re + dx / 2.0, w.im + dy / 2.0),
                        ));
                    }
                }
            }
            chart
                .draw_series(
                    cells
                        .into_iter()
                        .map(|(a, b)| Rectangle::new([a, b], colour.mix(0.18).filled())),
                )?
                .label(name.as_str())
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 12, y + 5)], colour.filled())
                });
            // The boundary locus: w with a root on the circle and none outside.
            let mut locus = Vec::new();
            for k in 0..2000 {
                let theta = std::f64::consts::TAU * k as f64 / 2000.0;
                for w in complex_polynomial_roots(&locus_at(&p.charpoly, theta)).unwrap_or_default()
                {
                    if w.re >= x0
                        && w.re <= x1
                        && w.im >= y0
                        && w.im <= y1
                        && max_modulus(&p.charpoly, w) <= 1.0 + 1e-6
                    {
                        locus.push((w.re, w.im));
                    }
                }
            }
            chart.draw_series(locus.into_iter().map(|q| Circle::new(q, 1, colour.filled())))?;
            // The exact axis intervals.
            let thick = colour.stroke_width(4);
            let re = p.real_limit.as_ref().map_or(-x0, |a| nearest_f64(a, None));
            chart.draw_series(LineSeries::new([(-re.min(-x0), 0.0), (0.0, 0.0)], thick))?;
            let im = p.imag_limit.as_ref().map_or(y1, |a| nearest_f64(a, None)).min(y1);
            chart.draw_series(LineSeries::new([(0.0, -im), (0.0, im)], colour.stroke_width(4)))?;
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

/// The values bound, the w-plane report, and the classical order.
pub(crate) type Plane = (Vec<(String, Q)>, PlaneReport, Option<Order>);

/// The w-plane report of one method (shown as `arg` in an error), with the
/// parameters it declares bound from `params` and the others left out
/// (`zcheck region` takes one list for all its methods): the values bound,
/// the report, and the classical order of the method's nonlinear reading
/// (none for a `.zm` program).
pub(crate) fn plane(arg: &str, m: &LoadedMethod, params: &[ParamArg]) -> Result<Plane, Error> {
    let mut bound = poly::Params::new();
    let mut shown: Vec<(String, Q)> = Vec::new();
    for p in params {
        if m.method().params().iter().any(|s| s.name() == p.name) {
            bound.insert(&p.name, p.value.value.clone());
            shown.push((p.name.clone(), p.value.value.clone()));
        }
    }
    let report = m
        .plane_derivation()?
        .plane(&bound)
        .map_err(|e| Error::from(e).context(format!("method {arg}")))?;
    let classical = m.reading().map(super::order::classical_order).transpose()?;
    Ok((shown, report, classical))
}
