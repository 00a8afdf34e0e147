//! The stability map of a method over two of its parameters (Newmark's β
//! and γ, say): each grid point coloured by its exact Φ_max, the one-variable
//! analysis of `Derivation::stability` with both parameters bound, and ∞
//! where every Φ > 0 is bounded (unconditional stability).
//!
//! The exact curves drawn are those of the limit Φ → ∞. With χ(z; Φ, p, q) =
//! Σ_j Φ^j c_j(z; p, q) and c_d the top coefficient in Φ, the roots of χ tend
//! to the roots of L = c_d as Φ grows (and to ∞ when L has a lower degree in
//! z). So a root at large Φ crosses the unit circle only on the zero sets of
//! L's leading coefficient in z, L(1), L(−1) and L's unit-circle condition
//! (the same four conditions as `poly::advanced::region`, on L): for Newmark
//! L = β z² + (1/2 + γ − 2β) z + (1/2 − γ + β), whose curves 2β − γ = 0
//! (L(−1)) and 2γ − 1 = 0 (unit circle) bound the region 2β ≥ γ ≥ 1/2.
//!
//! Φ_max = ∞ can also change where a finite critical Φ appears, which these
//! curves do not see. So the map checks itself on its grid: every pair of
//! neighbouring points whose "Φ_max = ∞" differs must be separated by one
//! of the curves (an exact sign change), and the curves that separate some
//! pair, each with the side the unconditional points are on, must describe
//! exactly the grid's unconditional points. Where they do not, the output
//! says so and the region's edge is only the grid's.
//!
//! Each grid point is also checked by the numeric witnesses of `check`
//! (eigenvalues of the numeric transition matrix against the exact roots)
//! at Φ_max/2 and 3Φ_max/2 (at Φ = 1/2 and 4 when there is no Φ_max), and
//! the exact class there must agree with the exact verdict.

use std::cmp::Ordering;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

use check::numeric::{f64_to_q, q_to_f64};
use check::witness::Witnesses;
use num_traits::{One, Signed, Zero};
use plotters::prelude::*;
use poly::{Algebraic, Poly, Stability, StabilityReport, Sym, Q};
use rayon::prelude::*;
use serde::Serialize;

use super::one::{approx, centre, lin};
use crate::error::Error;
use crate::load::LoadedMethod;

/// The window of a two-parameter map.
#[derive(Clone, Debug)]
pub(crate) struct ParamWindow {
    /// The two parameters, in axis order (x, y).
    pub names: [String; 2],
    /// Their ranges, exact.
    pub ranges: [(Q, Q); 2],
    /// The method's other parameters, bound.
    pub fixed: Vec<(String, Q)>,
    /// Grid points per axis.
    pub grid: usize,
    /// Curve samples per axis.
    pub samples: usize,
}

/// One grid point.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct ParamPoint {
    /// The two parameters' values (the f64 whose exact value was analysed).
    pub values: [f64; 2],
    /// The verdict's name (`limited`, `bounded_for_all_phi`, ...).
    pub stability: String,
    /// Φ_max, when the verdict is `limited`.
    pub phi_max: Option<f64>,
    /// Φ_max exactly (closed form, or defining polynomial and interval).
    pub phi_max_exact: Option<String>,
    /// Every Φ > 0 bounded (Φ_max = ∞).
    pub unconditional: bool,
    /// The Φ at which the witnesses checked the point.
    pub witness_phis: Vec<f64>,
    /// Whether they agreed with the exact roots and verdict at every one.
    pub witnesses_agree: bool,
}

/// One exact curve of the limit Φ → ∞.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct LimitCurve {
    /// Which condition on L: `leading`, `chi(1)`, `chi(-1)`, `unit_circle`.
    pub kind: String,
    /// The polynomial in the two parameters (integer, primitive).
    pub poly: String,
    /// Points on the curve inside the window.
    pub points: Vec<(f64, f64)>,
    /// Whether it separates some pair of neighbouring grid points whose
    /// Φ_max = ∞ differs.
    pub bounds_region: bool,
    /// `poly >= 0` (or its negation) when every unconditional grid point
    /// lies on that side of a bounding curve.
    pub inequality: Option<String>,
}

/// The map.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct ParamMap {
    /// The method.
    pub method: String,
    /// The axes, the two parameters.
    pub axes: [String; 2],
    /// Their windows.
    pub ranges: [(f64, f64); 2],
    /// The other parameters' values, exact.
    pub fixed: BTreeMap<String, String>,
    /// Grid size (x, y).
    pub size: (usize, usize),
    /// Grid points, row by row (y outer, x inner).
    pub grid: Vec<ParamPoint>,
    /// L(z), the top coefficient of χ in Φ.
    pub limit_polynomial: String,
    /// The exact curves of the limit Φ → ∞.
    pub curves: Vec<LimitCurve>,
    /// Neighbouring grid pairs whose Φ_max = ∞ differs.
    pub class_edges: usize,
    /// Those separated by an exact curve.
    pub edges_on_curves: usize,
    /// Whether the bounding curves' inequalities give exactly the grid's
    /// unconditional points.
    pub region_matches_grid: bool,
    /// The unconditional region, in words.
    pub region: String,
    /// Grid points whose witnesses disagreed.
    pub disagreements: usize,
}

/// Whether Φ lies in one of the report's bounded intervals.
fn bounded_at(report: &StabilityReport, phi: &Q) -> bool {
    report.stable_intervals.iter().any(|s| {
        let lo = match s.lo.cmp_rational(phi) {
            Ordering::Less => true,
            Ordering::Equal => s.lo_closed,
            Ordering::Greater => false,
        };
        let hi = s.hi.as_ref().is_none_or(|h| match h.cmp_rational(phi) {
            Ordering::Greater => true,
            Ordering::Equal => s.hi_closed,
            Ordering::Less => false,
        });
        lo && hi
    })
}

/// The largest rational g with every coefficient of `p` an integer multiple
/// of it (Euclid on rationals), and `p / g`.
fn primitive(p: &Poly) -> Poly {
    let mut g = Q::zero();
    for (_, c) in p.terms() {
        let (mut a, mut b) = (g.abs(), c.abs());
        while !b.is_zero() {
            let r = &a - &b * (&a / &b).floor();
            a = b;
            b = r;
        }
        g = a;
    }
    if g.is_zero() {
        p.clone()
    } else {
        p.scale(&(Q::one() / g))
    }
}

/// L, the top coefficient of `chi` in Φ, and the four conditions on it
/// (non-constant ones only, primitive, without repeats).
fn limit_conditions(chi: &Poly) -> (Poly, Vec<(&'static str, Poly)>) {
    let l = chi.coeffs_in(Sym::phi()).into_iter().rev().find(|c| !c.is_zero()).unwrap_or_default();
    let mut a = l.coeffs_in(Sym::z());
    while a.last().is_some_and(Poly::is_zero) {
        a.pop();
    }
    if a.len() < 2 {
        return (l, Vec::new());
    }
    let n = a.len() - 1;
    let c = poly::advanced::circle_conditions(&a);
    let mut conditions =
        vec![("leading", c.leading), ("chi(1)", c.at_one), ("chi(-1)", c.at_minus_one)];
    if n >= 2 {
        conditions.push(("unit_circle", c.unit_circle));
    }
    let mut out: Vec<(&'static str, Poly)> = Vec::new();
    for (kind, p) in conditions {
        if p.is_zero() || p.as_constant().is_some() {
            continue;
        }
        let p = primitive(&p);
        if !out.iter().any(|(_, q)| *q == p || *q == -&p) {
            out.push((kind, p));
        }
    }
    (l, out)
}

/// The real roots of `u` strictly inside (lo, hi).
fn roots_inside(u: &poly::UPoly, lo: &Q, hi: &Q) -> Vec<Algebraic> {
    if u.is_zero() || u.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    Algebraic::real_roots(u)
        .into_iter()
        .filter(|r| r.cmp_rational(lo) == Ordering::Greater && r.cmp_rational(hi) == Ordering::Less)
        .collect()
}

/// Points on the zero set of `p` in the window: at each sample of one axis
/// the exact roots along the other.
fn trace(p: &Poly, syms: [Sym; 2], w: &ParamWindow) -> Vec<(f64, f64)> {
    let s = w.samples.max(2);
    let along = |axis: usize| -> Vec<(f64, f64)> {
        let (fixed_sym, free_sym) = (syms[axis], syms[1 - axis]);
        let (lo, hi) = &w.ranges[axis];
        let (flo, fhi) = &w.ranges[1 - axis];
        (0..s)
            .into_par_iter()
            .flat_map_iter(|k| {
                let v = lin(lo, hi, k, s);
                let f = p.eval_partial(&[(fixed_sym, v.clone())].into_iter().collect());
                let vf = q_to_f64(&v);
                let roots = f.to_upoly(free_sym).map_or(Vec::new(), |u| roots_inside(&u, flo, fhi));
                roots.into_iter().map(move |r| {
                    let x = approx(&r);
                    if axis == 0 {
                        (vf, x)
                    } else {
                        (x, vf)
                    }
                })
            })
            .collect()
    };
    let mut points = along(0);
    points.extend(along(1));
    points
}

/// The sign of `p` at the point, when it evaluates to a rational.
fn sign_at(p: &Poly, at: &HashMap<Sym, Q>) -> Option<Ordering> {
    p.eval(at).map(|v| v.cmp(&Q::zero()))
}

/// Computes the two-parameter map of a method from its one derivation.
pub(crate) fn param_map(loaded: &LoadedMethod, w: &ParamWindow) -> Result<ParamMap, Error> {
    let derivation = loaded.derivation()?;
    let method = &derivation.method();
    let syms = [Sym::new(&w.names[0]), Sym::new(&w.names[1])];
    let n = w.grid.max(2);
    let witnesses = Witnesses::from_derivation(derivation);
    let base = w.fixed.iter().fold(poly::Params::new(), |p, (k, v)| p.bind(k, v.clone()));
    // The exact point the witnesses see: each value's nearest f64.
    let exact_value = |axis: usize, k: usize| -> (f64, Q) {
        let q = centre(&w.ranges[axis].0, &w.ranges[axis].1, k, n);
        let x = q_to_f64(&q);
        (x, f64_to_q(x).unwrap_or(q))
    };
    let cells: Vec<(usize, usize)> = (0..n).flat_map(|j| (0..n).map(move |i| (i, j))).collect();
    // Ctrl-C stops the grid between points (`None`: the run was stopped).
    let grid: Option<Vec<(ParamPoint, HashMap<Sym, Q>)>> = cells
        .par_iter()
        .map(|&(i, j)| {
            if crate::interrupt::requested() {
                return None;
            }
            let ((x, xq), (y, yq)) = (exact_value(0, i), exact_value(1, j));
            let params = base.clone().bind(&w.names[0], xq.clone()).bind(&w.names[1], yq.clone());
            let at: HashMap<Sym, Q> = [(syms[0], xq), (syms[1], yq)].into_iter().collect();
            let point = match derivation.stability(&params) {
                Ok(report) => grid_point([x, y], &report, derivation, &witnesses, &params),
                Err(e) => ParamPoint {
                    values: [x, y],
                    stability: format!("error: {e}"),
                    phi_max: None,
                    phi_max_exact: None,
                    unconditional: false,
                    witness_phis: Vec::new(),
                    witnesses_agree: false,
                },
            };
            Some((point, at))
        })
        .collect();
    let grid = grid
        .ok_or_else(|| Error::interrupted(format!("the map's {n} x {n} grid was not complete")))?;
    let fixed_values: HashMap<Sym, Q> =
        w.fixed.iter().map(|(k, v)| (Sym::new(k), v.clone())).collect();
    let chi = derivation.charpoly().eval_partial(&fixed_values);
    let (l, conditions) = limit_conditions(&chi);
    // Neighbouring pairs whose Φ_max = ∞ differs, and the curves that
    // separate each (an exact sign change, or a zero at either end).
    let mut separates = vec![false; conditions.len()];
    let (mut class_edges, mut edges_on_curves) = (0, 0);
    for j in 0..n {
        for i in 0..n {
            let a = j * n + i;
            for b in [(i + 1 < n).then(|| a + 1), (j + 1 < n).then(|| a + n)].into_iter().flatten()
            {
                if grid[a].0.unconditional == grid[b].0.unconditional {
                    continue;
                }
                class_edges += 1;
                let mut on_curve = false;
                for (k, (_, p)) in conditions.iter().enumerate() {
                    let (sa, sb) = (sign_at(p, &grid[a].1), sign_at(p, &grid[b].1));
                    if let (Some(sa), Some(sb)) = (sa, sb) {
                        if sa != sb || sa == Ordering::Equal {
                            separates[k] = true;
                            on_curve = true;
                        }
                    }
                }
                if on_curve {
                    edges_on_curves += 1;
                }
            }
        }
    }
    // Each separating curve, oriented so that the unconditional points are
    // where it is >= 0 (when they all are on one side).
    let oriented: Vec<Option<Poly>> = conditions
        .iter()
        .zip(&separates)
        .map(|((_, p), &sep)| {
            if !sep {
                return None;
            }
            let signs: Vec<Option<Ordering>> =
                grid.iter().filter(|g| g.0.unconditional).map(|g| sign_at(p, &g.1)).collect();
            if signs.iter().all(|s| matches!(s, Some(Ordering::Greater | Ordering::Equal))) {
                Some(p.clone())
            } else if signs.iter().all(|s| matches!(s, Some(Ordering::Less | Ordering::Equal))) {
                Some(-p)
            } else {
                None
            }
        })
        .collect();
    let inequalities: Vec<&Poly> = oriented.iter().flatten().collect();
    let unconditional = grid.iter().filter(|g| g.0.unconditional).count();
    let region_matches_grid = !inequalities.is_empty()
        && grid.iter().all(|g| {
            let inside = inequalities
                .iter()
                .all(|p| matches!(sign_at(p, &g.1), Some(Ordering::Greater | Ordering::Equal)));
            inside == g.0.unconditional
        });
    let region = if unconditional == 0 {
        "no grid point is unconditionally stable (Phi_max is finite or there is none)".to_owned()
    } else if unconditional == grid.len() {
        "every grid point is unconditionally stable (Phi_max = infinity)".to_owned()
    } else if region_matches_grid && edges_on_curves == class_edges {
        let list: Vec<String> = inequalities.iter().map(|p| format!("{p} >= 0")).collect();
        format!(
            "Phi_max = infinity exactly where {} at every grid point; the edge is on the exact curves of the limit Phi -> infinity",
            list.join(" and ")
        )
    } else {
        format!(
            "the exact curves of the limit Phi -> infinity do not account for the whole edge: {} of {} neighbouring grid pairs where Phi_max = infinity changes are separated by them{}; elsewhere the edge is only the grid's",
            edges_on_curves,
            class_edges,
            if region_matches_grid { "" } else { ", and their inequalities do not reproduce the grid" }
        )
    };
    let curves = conditions
        .iter()
        .zip(&separates)
        .zip(&oriented)
        .map(|(((kind, p), &bounds_region), o)| LimitCurve {
            kind: (*kind).to_owned(),
            poly: p.to_string(),
            points: trace(p, syms, w),
            bounds_region,
            inequality: o.as_ref().map(|o| format!("{o} >= 0")),
        })
        .collect();
    let grid: Vec<ParamPoint> = grid.into_iter().map(|g| g.0).collect();
    Ok(ParamMap {
        method: method.name().to_owned(),
        axes: w.names.clone(),
        ranges: [
            (q_to_f64(&w.ranges[0].0), q_to_f64(&w.ranges[0].1)),
            (q_to_f64(&w.ranges[1].0), q_to_f64(&w.ranges[1].1)),
        ],
        fixed: w.fixed.iter().map(|(k, v)| (k.clone(), v.to_string())).collect(),
        size: (n, n),
        disagreements: grid.iter().filter(|g| !g.witnesses_agree).count(),
        grid,
        limit_polynomial: l.to_string(),
        curves,
        class_edges,
        edges_on_curves,
        region_matches_grid,
        region,
    })
}

/// One grid point: the exact verdict, and the witnesses at two Φ.
fn grid_point(
    values: [f64; 2],
    report: &StabilityReport,
    derivation: &poly::Derivation,
    witnesses: &Witnesses,
    params: &poly::Params,
) -> ParamPoint {
    let phi_max = report.phi_max().map(approx);
    let phis: Vec<f64> = match phi_max {
        Some(m) => vec![m / 2.0, 1.5 * m],
        None => vec![0.5, 4.0],
    };
    // A Φ where the step is singular (det A = 0) has no roots to compare:
    // the witness moves to a Φ 1/64 further on.
    let check = |phi: f64| -> Option<bool> {
        let phi_q = f64_to_q(phi)?;
        let class = derivation.class_at(params, &phi_q).ok()?;
        let rep = witnesses.at(&params.clone().bind("Phi", phi_q.clone()), 0).ok()?;
        Some(
            class.bounded == bounded_at(report, &phi_q)
                && rep.agree()
                && rep.exact.class == class.class,
        )
    };
    let mut phis = phis;
    let agree = phis.iter_mut().all(|phi| {
        check(*phi).or_else(|| {
            *phi *= 65.0 / 64.0;
            check(*phi)
        }) == Some(true)
    });
    ParamPoint {
        values,
        stability: report.stability.name().to_owned(),
        phi_max,
        phi_max_exact: report
            .phi_max()
            .map(|a| a.closed_form().unwrap_or_else(|| a.describe("Phi"))),
        unconditional: report.stability == Stability::BoundedForAllPhi,
        witness_phis: phis,
        witnesses_agree: agree,
    }
}

/// Φ_max = ∞.
const INFINITE: RGBColor = RGBColor(35, 70, 160);
/// No Φ_max: unbounded for small Φ.
const NONE: RGBColor = RGBColor(215, 215, 215);

/// The colour of a finite Φ_max at `t` of the grid's logarithmic scale:
/// from red (small) to pale blue (large), short of [`INFINITE`].
fn finite_colour(t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let mix = |a: u8, b: u8| (a as f64 + (b as f64 - a as f64) * t).round() as u8;
    RGBColor(mix(225, 160), mix(80, 210), mix(55, 235))
}

fn curve_colour(kind: &str) -> RGBColor {
    match kind {
        "chi(1)" => RGBColor(0, 110, 0),
        "chi(-1)" => RGBColor(0, 0, 0),
        "unit_circle" => RGBColor(150, 0, 150),
        _ => RGBColor(200, 120, 0),
    }
}

/// Draws the map as SVG.
pub(crate) fn draw_svg(m: &ParamMap, path: &Path) -> Result<(), Error> {
    let err =
        |e: &dyn std::fmt::Display| Error::figure(format!("{}: cannot draw: {e}", path.display()));
    let root = SVGBackend::new(path, (900, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let [(x0, x1), (y0, y1)] = m.ranges;
    let fixed: Vec<String> = m.fixed.iter().map(|(k, v)| format!(", {k} = {v}")).collect();
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!(
                "{}: exact Phi_max over ({}, {}){}; curves of Phi -> infinity",
                m.method,
                m.axes[0],
                m.axes[1],
                fixed.concat()
            ),
            ("sans-serif", 18),
        )
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .right_y_label_area_size(10)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc(m.axes[0].as_str())
        .y_desc(m.axes[1].as_str())
        .draw()
        .map_err(|e| err(&e))?;
    let (n, _) = m.size;
    let (dx, dy) = ((x1 - x0) / n as f64, (y1 - y0) / n as f64);
    // A logarithmic scale between the smallest and largest finite Φ_max:
    // near the unconditional region Φ_max grows without bound.
    let finite = m.grid.iter().filter_map(|g| g.phi_max);
    let (smallest, largest) =
        finite.fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let scale = |v: f64| {
        if largest > smallest {
            (v / smallest).ln() / (largest / smallest).ln()
        } else {
            1.0
        }
    };
    let colour = |g: &ParamPoint| match g.phi_max {
        _ if g.unconditional => INFINITE,
        Some(v) => finite_colour(scale(v)),
        None => NONE,
    };
    chart
        .draw_series(m.grid.iter().map(|g| {
            let [x, y] = g.values;
            Rectangle::new(
                [(x - dx / 2.0, y - dy / 2.0), (x + dx / 2.0, y + dy / 2.0)],
                colour(g).filled(),
            )
        }))
        .map_err(|e| err(&e))?;
    chart
        .draw_series(
            m.grid
                .iter()
                .filter(|g| !g.witnesses_agree)
                .map(|g| Cross::new((g.values[0], g.values[1]), 4, RED.stroke_width(2))),
        )
        .map_err(|e| err(&e))?;
    for c in &m.curves {
        let colour = curve_colour(&c.kind);
        let size = if c.bounds_region { 2 } else { 1 };
        let role = if c.bounds_region { "bounds the region" } else { "critical at infinity" };
        chart
            .draw_series(c.points.iter().map(|&p| Circle::new(p, size, colour.filled())))
            .map_err(|e| err(&e))?
            .label(format!("{} = 0 ({}, {role})", c.poly, c.kind))
            .legend(move |(x, y)| Circle::new((x + 8, y), 3, colour.filled()));
    }
    let mut swatches: Vec<(String, RGBColor)> = vec![("Phi_max = infinity".to_owned(), INFINITE)];
    if largest > 0.0 {
        let middle = (smallest * largest).sqrt();
        for v in [largest, middle, smallest] {
            swatches.push((format!("Phi_max = {v:.3}"), finite_colour(scale(v))));
        }
    }
    swatches.push(("no Phi_max: unbounded for small Phi".to_owned(), NONE));
    for (label, c) in swatches {
        chart
            .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
            .map_err(|e| err(&e))?
            .label(label)
            .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 16, y + 5)], c.filled()));
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Newmark's limit polynomial and its curves, by hand: L = β z² +
    /// (1/2 + γ − 2β) z + (1/2 − γ + β), L(1) = 1 (no curve), L(−1) =
    /// 4β − 2γ, the unit circle a₂ − a₀ = γ − 1/2, the leading β.
    #[test]
    fn newmark_limit_curves() {
        let src = include_str!("../../../methods/newmark.zm");
        let d = poly::derive_source("newmark.zm", src).unwrap();
        let (l, curves) = limit_conditions(d.charpoly());
        let (b, g, z) = (Poly::var("beta"), Poly::var("gamma"), Poly::sym(Sym::z()));
        let half = Poly::constant(poly::q(1, 2));
        let want = &(&(&b * &z.pow(2)) + &(&(&(&half + &g) - &b.scale(&poly::q(2, 1))) * &z))
            + &(&(&half - &g) + &b);
        assert_eq!(l, want);
        let found: Vec<(&str, String)> = curves.iter().map(|(k, p)| (*k, p.to_string())).collect();
        let expect = |kind: &str, p: &Poly| {
            assert!(
                curves.iter().any(|(k, q)| *k == kind && (q == p || *q == -p)),
                "{kind}: {p} not in {found:?}"
            );
        };
        expect("leading", &b);
        expect("chi(-1)", &(&b.scale(&poly::q(2, 1)) - &g));
        expect("unit_circle", &(&g.scale(&poly::q(2, 1)) - &Poly::one()));
        assert_eq!(curves.len(), 3, "{found:?}");
    }

    /// The primitive part: integer coefficients without a common factor.
    #[test]
    fn primitive_parts() {
        let p = &Poly::var("a").scale(&poly::q(4, 3)) - &Poly::var("b").scale(&poly::q(2, 9));
        assert_eq!(primitive(&p), &Poly::var("a").scale(&poly::q(6, 1)) - &Poly::var("b"));
    }

    /// The reciprocal resultant of a cubic in z vanishes where a root pair
    /// has z_i z_j = 1: (z − 2)(z − 1/2)(z − c) at every c.
    #[test]
    fn resultant_sees_reciprocal_pairs() {
        let c = Poly::var("c");
        let z = Poly::sym(Sym::z());
        let f = &(&(&z - &Poly::int(2)) * &(&z - &Poly::constant(poly::q(1, 2)))) * &(&z - &c);
        let a = f.coeffs_in(Sym::z());
        let rev: Vec<Poly> = a.iter().rev().cloned().collect();
        assert!(poly::advanced::resultant(&a, &rev).is_zero());
        let g = &(&(&z - &Poly::int(3)) * &(&z - &Poly::constant(poly::q(1, 2)))) * &(&z - &c);
        let a = g.coeffs_in(Sym::z());
        let rev: Vec<Poly> = a.iter().rev().cloned().collect();
        assert!(!poly::advanced::resultant(&a, &rev).is_zero());
    }
}
