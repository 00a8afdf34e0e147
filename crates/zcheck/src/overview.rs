//! Every method side by side: exact stability limit, frequency and amplitude
//! series, and cost per step.
//!
//! Appendix A derives Ψ(Φ) only for Damped/False Euler and Standard Heun.
//! This table extends it to every method the paper analyses, from the exact
//! characteristic polynomial (`poly::advanced::series`), next to the exact limit
//! (`Derivation::stability`) and the operation count (`Derivation::cost`), so a
//! reader can compare the paper's four criteria (stability, frequency
//! deviation, calculations per step, largest step) in one place.

use poly::advanced::series::{self, LeadingTerm};
use poly::{Derivation, Poly, Q};
use serde::Serialize;

use crate::error::Error;
use crate::load::builtin_derivation;

/// One row of the overview.
#[derive(Clone, Debug, Serialize)]
pub struct MethodSummary {
    /// Built-in name.
    pub method: String,
    /// χ(z) in plain text.
    pub charpoly: String,
    /// The exact stability limit (closed form or defining polynomial), or a
    /// sentence when there is none.
    pub phi_max_exact: String,
    /// Its value to 15 significant digits, when it exists.
    pub phi_max: Option<f64>,
    /// Steps per period at the limit, 2π/Φ_max.
    pub min_steps_per_period: Option<f64>,
    /// The spectral radius as Φ → ∞ (exact), `∞` when a root escapes, or
    /// why it is not given.
    pub rho_inf: String,
    /// Ψ(Φ) as an exact truncated series, e.g. `Phi + 1/24*Phi^3 + O(Phi^5)`.
    pub psi_series: String,
    /// |z|² of the complex pair as an exact truncated series.
    pub modulus_sq_series: String,
    /// Leading term of Ψ − Φ (phase error per step), e.g. `1/24*Phi^3`.
    pub phase_error: String,
    /// Leading term of |z|² − 1 (amplitude error per step), or `0`.
    pub amplitude_error: String,
    /// Multiplications per step after constant folding.
    pub mul: u32,
    /// Additions and subtractions per step.
    pub add: u32,
    /// Unknowns of an implicit step's linear system (0 when explicit).
    pub unknowns: usize,
    /// The part of `mul`/`add` that applies the solve, A⁻¹E times the slots,
    /// with the factorisation done once per Φ: `(mul, add)`.
    pub solve: (u32, u32),
}

/// A series that could not be taken, said as `poly` says it.
fn series_error(e: impl std::fmt::Display) -> Error {
    Error::unsupported(e.to_string())
}

/// `Σ c_k Φ^k + O(Φ^(order+1))` in plain text.
fn series_text(c: &[Q], scale: &str) -> String {
    let p = Poly::from_upoly(poly::Sym::phi(), &poly::UPoly::new(c.to_vec()));
    let body = if scale.is_empty() { p.to_string() } else { format!("{scale}*({p})") };
    format!("{body} + O(Phi^{})", c.len())
}

fn leading(t: Option<LeadingTerm>) -> String {
    match t {
        None => "0".to_owned(),
        Some(t) => {
            let p = Poly::term(
                t.coeff,
                poly::advanced::Monomial::power(poly::Sym::phi(), t.order as u32),
            );
            p.to_string()
        }
    }
}

/// The overview row of a method whose χ is in z and Φ only.
pub fn summarize(method: &poly::Method, order: usize) -> Result<MethodSummary, Error> {
    summary_of(&poly::derive(method)?, order)
}

/// The overview row of a derived method whose χ is in z and Φ only.
pub(crate) fn summary_of(d: &Derivation, order: usize) -> Result<MethodSummary, Error> {
    summary_at(d, &poly::Params::new(), order)
}

/// The overview row of a derived method with its parameters bound in
/// `params` (every one it declares; no other): the row is named with them,
/// e.g. `newmark (beta = 1/4, gamma = 1/2)`.
pub(crate) fn summary_at(
    d: &Derivation,
    params: &poly::Params,
    order: usize,
) -> Result<MethodSummary, Error> {
    let method = &d.method();
    // From the derivation: a repeated root on the circle is decided from P
    // (Gauss–Legendre's P is −I at Φ = 2√3: bounded through it).
    let report = d.stability(params)?;
    let values: std::collections::HashMap<poly::Sym, Q> =
        params.iter().map(|(k, v)| (poly::Sym::new(k), v.clone())).collect();
    let bound = d.charpoly().eval_partial(&values);
    let chi = &bound;
    let p_q = d.p_q().map(|(p, q)| (p.eval_partial(&values), q.eval_partial(&values)));
    let shown: Vec<String> = params.iter().map(|(k, v)| format!("{k} = {v}")).collect();
    let name = if shown.is_empty() {
        method.name().to_owned()
    } else {
        format!("{} ({})", method.name(), shown.join(", "))
    };
    let (phi_max_exact, phi_max) = match report.phi_max() {
        Some(a) => {
            let exact = a.closed_form().unwrap_or_else(|| a.describe("Phi"));
            (exact, Some(crate::answers::exact::nearest_f64(a, None)))
        }
        None if report.bounded_for_all() => ("none: bounded for every Phi > 0".to_owned(), None),
        None => ("none: unbounded for every Phi > 0".to_owned(), None),
    };
    // The series are computed over Q: a χ that keeps an exact constant
    // (sqrt(2) in SDIRK's) says so instead of failing on it.
    let constants = poly::advanced::field::has_generators(chi);
    let over_q =
        || ("n/a (χ keeps an exact constant: series over Q only)".to_owned(), "n/a".to_owned());
    let (psi_series, phase_error) = match series::psi_series_scaled(chi, order) {
        _ if constants => over_q(),
        Ok((d, c)) if d == Q::from_integer(1.into()) => {
            (series_text(&c, ""), leading(series::dispersion_order(chi).map_err(series_error)?))
        }
        Ok((d, c)) => (series_text(&c, &format!("sqrt({d})")), "order 1".to_owned()),
        Err(e) => (format!("n/a ({e})"), "n/a".to_owned()),
    };
    // Where the second-order series stop (exact constants, three states),
    // the principal root's own series still give the leading terms.
    let on_circle = report
        .intervals
        .first()
        .is_some_and(|i| i.lo.sign().is_eq() && i.class == poly::RootClass::Harmonic);
    let general = poly::advanced::plane::phase_errors(chi, on_circle).ok();
    // In this table's conventions: Ψ − Φ = −(Φ − Ψ), and |z|² − 1 =
    // −2(1 − |z|) to leading order.
    let term = |c: Poly, power: u32| {
        let c = c.to_string();
        if c.contains(' ') {
            format!("({c})*Phi^{power}")
        } else {
            format!("{c}*Phi^{power}")
        }
    };
    let phase_error = match (&general, phase_error.starts_with("n/a")) {
        (Some(g), true) => match &g.dispersion {
            Some(t) => term(-&t.constant, t.order + 1),
            None => "0".to_owned(),
        },
        _ => phase_error,
    };
    let (modulus_sq_series, amplitude_error) = match series::modulus_sq_series(chi, order) {
        _ if constants => over_q(),
        // For a conjugate pair of a second-order χ, |z|² = z1·z2 = q exactly:
        // a polynomial, not a truncated series.
        Ok(_)
            if p_q
                .as_ref()
                .is_some_and(|(_, q)| (q.degree_in(poly::Sym::phi()) as usize) < order) =>
        {
            let q = p_q.as_ref().map(|(_, q)| q.to_string()).unwrap_or_default();
            (q, leading(series::dissipation_order(chi).map_err(series_error)?))
        }
        Ok(c) => {
            (series_text(&c, ""), leading(series::dissipation_order(chi).map_err(series_error)?))
        }
        Err(e) => (format!("n/a ({e})"), "n/a".to_owned()),
    };
    let amplitude_error = match (&general, amplitude_error.starts_with("n/a")) {
        (Some(g), true) => match &g.dissipation {
            Some(t) => term(t.constant.scale(&Q::from_integer((-2).into())), t.order + 1),
            None => "0".to_owned(),
        },
        _ => amplitude_error,
    };
    let rho_inf = match d.rho_inf(params) {
        Ok(Some(r)) => r.closed_form().unwrap_or_else(|| r.to_decimal(6)),
        Ok(None) => "∞".to_owned(),
        Err(e) => format!("n/a ({})", e.message()),
    };
    let cost = d.cost();
    Ok(MethodSummary {
        method: name,
        charpoly: chi.to_string(),
        phi_max_exact,
        phi_max,
        min_steps_per_period: phi_max.map(|p| std::f64::consts::TAU / p),
        rho_inf,
        psi_series,
        modulus_sq_series,
        phase_error,
        amplitude_error,
        mul: cost.program.mul,
        add: cost.program.add,
        unknowns: method.unknowns().len(),
        solve: (cost.solve.mul, cost.solve.add),
    })
}

/// The overview of the paper's seven methods (derived once per process,
/// with the paper's claims).
pub fn paper_overview(order: usize) -> Result<Vec<MethodSummary>, Error> {
    poly::advanced::builtins::PAPER_METHODS
        .iter()
        .map(|name| summary_of(&builtin_derivation(name), order))
        .collect()
}

/// The overview as a Markdown table (numbers rounded to 4 decimals, the
/// exact limit in the report's notation, Φ). When a row is implicit, a
/// column says what its mul/add include: the solve, applied as A⁻¹E with
/// the LU factorisation once per Φ.
pub fn to_markdown(rows: &[MethodSummary]) -> String {
    let implicit = rows.iter().any(|r| r.unknowns > 0);
    let mut s = String::from(
        "| method | Φ_max (exact) | Φ_max | steps/period at Φ_max | ρ∞ | Ψ(Φ) | \\|z\\|² | phase error Ψ−Φ | amplitude error \\|z\\|²−1 | mul | add |",
    );
    s.push_str(if implicit { " of which the solve |\n" } else { "\n" });
    s.push_str("|---|---|---:|---:|---|---|---|---|---|---:|---:|");
    s.push_str(if implicit { "---|\n" } else { "\n" });
    for r in rows {
        let f = |x: Option<f64>| x.map_or("–".to_owned(), |v| format!("{v:.4}"));
        s.push_str(&format!(
            "| {} | {} | {} | {} | {} | `{}` | `{}` | `{}` | `{}` | {} | {} |",
            r.method,
            crate::paper::notation::math(&r.phi_max_exact),
            f(r.phi_max),
            f(r.min_steps_per_period),
            r.rho_inf,
            r.psi_series,
            r.modulus_sq_series,
            r.phase_error,
            r.amplitude_error,
            r.mul,
            r.add
        ));
        if implicit {
            if r.unknowns == 0 {
                s.push_str(" – |");
            } else {
                s.push_str(&format!(
                    " {} mul + {} add ({} unknown{}; LU once per Φ) |",
                    r.solve.0,
                    r.solve.1,
                    r.unknowns,
                    if r.unknowns == 1 { "" } else { "s" }
                ));
            }
        }
        s.push('\n');
    }
    s
}
