//! The exact stability map of a method in (Φ, p), p its one parameter (the
//! damping ratio D of the damped built-ins, or any other): the critical curves of
//! `poly::advanced::region`, traced exactly, over a grid of exact root classes, each
//! grid point cross-checked by the numeric witnesses of `check`
//! (eigenvalues of the numeric transition matrix by nalgebra and faer
//! against the exact roots).
//!
//! Curve points are exact: at each rational D of a fine sample the
//! critical Φ are real algebraic numbers (Sturm isolation), and likewise the
//! critical D at each rational Φ, so steep and flat branches are both drawn;
//! only the final conversion to plot coordinates is a float. Grid points
//! and curve samples are computed in parallel (rayon).

use crate::error::Error;
use crate::load::LoadedMethod;
use check::numeric::{f64_to_q, q_to_f64, Params, ParamsF64};
use check::witness::Witnesses;
use plotters::prelude::*;
use poly::advanced::region::{CurveKind, PhiLimit, Unconditional};
use poly::{RootClass, Sym, Q};
use rayon::prelude::*;
use serde::Serialize;
use std::path::Path;

/// One grid point.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct GridPoint {
    /// Φ (the f64 whose exact value was classified).
    pub phi: f64,
    /// The parameter's value.
    pub value: f64,
    /// The exact class.
    #[serde(serialize_with = "class_name")]
    pub class: RootClass,
    /// Whether the numeric witnesses agree with the exact roots.
    pub witnesses_agree: bool,
}

fn class_name<S: serde::Serializer>(c: &RootClass, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(c.name())
}

/// One critical curve, traced.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct TracedCurve {
    /// Which condition.
    pub kind: String,
    /// Its polynomial in Φ and D (the monomial factor split off).
    pub poly: String,
    /// The monomial factor.
    pub monomial: String,
    /// Points (Φ, p) on the curve inside the window.
    pub points: Vec<(f64, f64)>,
}

/// Φ_max at one value of the parameter.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct LimitAt {
    /// The parameter's value.
    pub value: f64,
    /// Φ_max to 12 decimals, "every" or "none".
    pub phi_max: String,
    /// Its defining polynomial and interval, when algebraic.
    pub exact: Option<String>,
}

/// The map.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct StabilityMap {
    /// The method.
    pub method: String,
    /// The axes: `["Phi", p]`.
    pub axes: [String; 2],
    /// Φ window.
    pub phi: (f64, f64),
    /// The parameter's window.
    pub range: (f64, f64),
    /// The other parameters, bound (exact text), in the order given.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub bound: Vec<(String, String)>,
    /// Grid points, row by row (the parameter outer, Φ inner).
    pub grid: Vec<GridPoint>,
    /// Grid size (Φ, D).
    pub size: (usize, usize),
    /// The critical curves.
    pub curves: Vec<TracedCurve>,
    /// Grid points whose witnesses disagreed.
    pub disagreements: usize,
    /// Φ_max along the parameter's window.
    pub limits: Vec<LimitAt>,
    /// "stable for every Phi > 0 and p >= 0" or the counterexample.
    pub unconditional: String,
}

/// Options of [`map`].
#[derive(Clone, Debug)]
pub(crate) struct MapWindow {
    /// Φ range, exact.
    pub phi: (Q, Q),
    /// The parameter's name.
    pub param: String,
    /// Its range, exact.
    pub range: (Q, Q),
    /// The method's other parameters, bound (`--param NAME=VALUE`).
    pub fixed: Vec<(String, Q)>,
    /// Grid points per axis.
    pub grid: usize,
    /// Curve samples per axis.
    pub samples: usize,
}

pub(crate) fn lin(lo: &Q, hi: &Q, k: usize, n: usize) -> Q {
    let t = Q::new((k as i64).into(), (n.max(2) as i64 - 1).into());
    lo + &((hi - lo) * t)
}

/// Grid cell centres: k + 1/2 of n cells.
pub(crate) fn centre(lo: &Q, hi: &Q, k: usize, n: usize) -> Q {
    let t = Q::new((2 * k as i64 + 1).into(), (2 * n as i64).into());
    lo + &((hi - lo) * t)
}

/// Computes the map of a method over (Φ, `w.param`), from its one
/// derivation. Every other parameter of the method must be bound in
/// `w.fixed`.
pub(crate) fn map(loaded: &LoadedMethod, w: &MapWindow) -> Result<StabilityMap, Error> {
    let method = loaded.method();
    let d_sym = Sym::new(&w.param);
    if !method.params().contains(&d_sym) {
        return Err(Error::usage(format!(
            "--param {}: method {} has no parameter {} (the damped test equation v' = -2*D*v - y, y' = v has `param D`)",
            w.param,
            method.name(),
            w.param
        )));
    }
    let others: Vec<&str> = method
        .params()
        .iter()
        .map(|s| s.name())
        .filter(|n| *n != "Phi" && *n != w.param && !w.fixed.iter().any(|(f, _)| f == n))
        .collect();
    if !others.is_empty() {
        return Err(Error::usage(format!(
            "--param {}: method {} has further parameters ({}), which have no value on a (Phi, {}) map: bind each with --param NAME=VALUE, or give two --param ranges (and no --phi) for a map over two parameters",
            w.param,
            method.name(),
            others.join(", "),
            w.param
        )));
    }
    let bound = w.fixed.iter().fold(poly::Params::new(), |p, (k, v)| p.bind(k, v.clone()));
    let derivation = loaded.derivation()?;
    let r = derivation
        .region_with(d_sym, &bound)
        .map_err(|e| Error::from(e).context(format!("method {}", method.name())))?;
    let fixed_f64: Vec<(&str, f64)> =
        w.fixed.iter().map(|(k, v)| (k.as_str(), q_to_f64(v))).collect();
    let witnesses = Witnesses::from_derivation(derivation);
    let n = w.grid.max(2);
    let cells: Vec<(usize, usize)> = (0..n).flat_map(|j| (0..n).map(move |i| (i, j))).collect();
    // Ctrl-C stops the grid between points (`None`: the run was stopped).
    let grid: Option<Vec<GridPoint>> = cells
        .par_iter()
        .map(|&(i, j)| {
            if crate::interrupt::requested() {
                return None;
            }
            let (phi_q, d_q) =
                (centre(&w.phi.0, &w.phi.1, i, n), centre(&w.range.0, &w.range.1, j, n));
            let (phi, d) = (q_to_f64(&phi_q), q_to_f64(&d_q));
            // Classify the exact value of the float that the witnesses use.
            let (pe, de) = (f64_to_q(phi).unwrap_or(phi_q), f64_to_q(d).unwrap_or(d_q));
            // A point the exact analysis cannot classify is an error, never
            // drawn as some class.
            let class = match r.class_at(&pe, &de) {
                Ok(at) => at.class,
                Err(e) => {
                    return Some(Err(Error::from(e).context(format!(
                        "method {} at Phi = {pe}, {} = {de}",
                        method.name(),
                        w.param
                    ))))
                }
            };
            let at = fixed_f64.iter().fold(Params::phi(phi), |p, (k, v)| p.with(k, *v));
            let agree = witnesses
                .at(&at.with(&w.param, d), 0)
                .is_ok_and(|rep| rep.agree() && rep.exact.class == class);
            Some(Ok(GridPoint { phi, value: d, class, witnesses_agree: agree }))
        })
        .collect::<Option<Vec<Result<GridPoint, Error>>>>()
        .map(|g| g.into_iter().collect::<Result<Vec<_>, _>>())
        .transpose()?;
    let grid = grid
        .ok_or_else(|| Error::interrupted(format!("the map's {n} x {n} grid was not complete")))?;
    let disagreements = grid.iter().filter(|g| !g.witnesses_agree).count();
    let curves = r
        .boundary_curves()
        .map(|c| {
            let s = w.samples.max(2);
            let mut points: Vec<(f64, f64)> = (0..s)
                .into_par_iter()
                .flat_map_iter(|k| {
                    let d = lin(&w.range.0, &w.range.1, k, s);
                    let dv = q_to_f64(&d);
                    r.curve_phis(c, &d, &w.phi.0, &w.phi.1)
                        .into_iter()
                        .map(move |a| (approx(&a), dv))
                })
                .collect();
            points.extend(
                (0..s)
                    .into_par_iter()
                    .flat_map_iter(|k| {
                        let phi = lin(&w.phi.0, &w.phi.1, k, s);
                        let pv = q_to_f64(&phi);
                        r.curve_params(c, &phi, &w.range.0, &w.range.1)
                            .into_iter()
                            .map(move |a| (pv, approx(&a)))
                    })
                    .collect::<Vec<_>>(),
            );
            TracedCurve {
                kind: c.kind.name().to_owned(),
                poly: c.poly.to_string(),
                monomial: c.monomial.to_string(),
                points,
            }
        })
        .collect();
    let limits = (0..5)
        .map(|k| {
            let d = lin(&w.range.0, &w.range.1, k, 5);
            let (phi_max, exact) = match r.phi_max(&d) {
                Ok(PhiLimit::Below(m)) => (m.to_decimal(12), Some(m.describe("Phi"))),
                Ok(PhiLimit::Every) => ("every".to_owned(), None),
                Ok(PhiLimit::Never) => ("none".to_owned(), None),
                Err(e) => (format!("error: {e}"), None),
            };
            LimitAt { value: q_to_f64(&d), phi_max, exact }
        })
        .collect();
    let unconditional = match r.unconditional()? {
        Unconditional::Stable { irrational_lines } => format!(
            "stable for every Phi > 0 and {p} >= 0 ({irrational_lines} irrational critical {p} not analysed on the line itself)",
            p = w.param
        ),
        Unconditional::Unstable { d, limit } => format!(
            "not unconditionally stable: at {} = {d}, {}",
            w.param,
            match *limit {
                PhiLimit::Below(m) => format!("unbounded from Phi_max = {}", m.to_decimal(12)),
                PhiLimit::Never => "unbounded for every small Phi > 0".to_owned(),
                PhiLimit::Every => "bounded".to_owned(),
            }
        ),
    };
    Ok(StabilityMap {
        method: method.name().to_owned(),
        axes: ["Phi".to_owned(), w.param.clone()],
        phi: (q_to_f64(&w.phi.0), q_to_f64(&w.phi.1)),
        range: (q_to_f64(&w.range.0), q_to_f64(&w.range.1)),
        bound: w.fixed.iter().map(|(k, v)| (k.clone(), v.to_string())).collect(),
        grid,
        size: (n, n),
        curves,
        disagreements,
        limits,
        unconditional,
    })
}

pub(crate) fn approx(a: &poly::Algebraic) -> f64 {
    q_to_f64(&a.approx(&poly::q(1, 1 << 40)))
}

fn class_colour(c: RootClass) -> RGBColor {
    match c {
        RootClass::Deadbeat => RGBColor(200, 200, 200),
        RootClass::DampedOscillation => RGBColor(140, 200, 140),
        RootClass::Harmonic => RGBColor(90, 160, 230),
        RootClass::UnstableOscillation => RGBColor(240, 140, 120),
        RootClass::MonotonicStable => RGBColor(190, 230, 160),
        RootClass::Constant => RGBColor(160, 160, 240),
        RootClass::MonotonicUnstable => RGBColor(230, 100, 100),
        RootClass::AlternatingStable => RGBColor(230, 230, 150),
        RootClass::Alternating => RGBColor(200, 160, 230),
        RootClass::AlternatingUnstable => RGBColor(200, 80, 140),
        RootClass::DoubleRootOnCircle => RGBColor(120, 120, 120),
        RootClass::Singular => RGBColor(0, 0, 0),
    }
}

fn curve_colour(kind: &str) -> RGBColor {
    match kind {
        k if k == CurveKind::ChiAtOne.name() => RGBColor(0, 90, 0),
        k if k == CurveKind::ChiAtMinusOne.name() => RGBColor(0, 0, 0),
        k if k == CurveKind::UnitCircle.name() => RGBColor(0, 0, 160),
        _ => RGBColor(120, 0, 120),
    }
}

/// Draws the map as SVG.
pub(crate) fn draw_svg(m: &StabilityMap, path: &Path) -> Result<(), Error> {
    let err =
        |e: &dyn std::fmt::Display| Error::figure(format!("{}: cannot draw: {e}", path.display()));
    let root = SVGBackend::new(path, (900, 680)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("{}: root class over (Phi, {}), exact critical curves", m.method, m.axes[1]),
            ("sans-serif", 18),
        )
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .right_y_label_area_size(10)
        .build_cartesian_2d(m.phi.0..m.phi.1, m.range.0..m.range.1)
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc("Phi = w T")
        .y_desc(if m.axes[1] == "D" { "D (damping ratio)".to_owned() } else { m.axes[1].clone() })
        .draw()
        .map_err(|e| err(&e))?;
    let (n, _) = m.size;
    let (dx, dy) = ((m.phi.1 - m.phi.0) / n as f64, (m.range.1 - m.range.0) / n as f64);
    let mut seen: Vec<RootClass> = Vec::new();
    chart
        .draw_series(m.grid.iter().map(|g| {
            if !seen.contains(&g.class) {
                seen.push(g.class);
            }
            let c = class_colour(g.class);
            Rectangle::new(
                [(g.phi - dx / 2.0, g.value - dy / 2.0), (g.phi + dx / 2.0, g.value + dy / 2.0)],
                c.filled(),
            )
        }))
        .map_err(|e| err(&e))?;
    chart
        .draw_series(
            m.grid
                .iter()
                .filter(|g| !g.witnesses_agree)
                .map(|g| Cross::new((g.phi, g.value), 4, RED.stroke_width(2))),
        )
        .map_err(|e| err(&e))?;
    for c in &m.curves {
        let colour = curve_colour(&c.kind);
        chart
            .draw_series(c.points.iter().map(|&p| Circle::new(p, 1, colour.filled())))
            .map_err(|e| err(&e))?
            .label(format!("{} = 0: {}", c.kind, c.poly))
            .legend(move |(x, y)| Circle::new((x + 8, y), 3, colour.filled()));
    }
    seen.sort();
    for class in seen {
        let colour = class_colour(class);
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
            .map_err(|e| err(&e))?
            .label(class.name())
            .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 16, y + 5)], colour.filled()));
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
