//! `zcheck verify`: the four numeric witnesses of each method at a list of
//! Φ (and, with `--boundaries`, at both sides of every class change a sweep
//! finds), as a table or JSON. Exits non-zero when any point disagrees.

use crate::values::show_f64;
use check::classify::psi_of;
use check::witness::PointReport;
use serde_json::{json, Value};

pub(crate) fn pair(z: &num_complex::Complex<f64>) -> Value {
    json!([z.re, z.im])
}

pub(crate) fn finite_or_null(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// One point as JSON; `sim` is null when no simulation ran, and
/// `growth_per_step` is null when the state vanished (ln 0).
pub(crate) fn point_json(r: &PointReport) -> Value {
    let sim = r.sim.as_ref().map(|s| {
        json!({
            "steps": s.steps,
            "growth_per_step": finite_or_null(s.growth_per_step),
            "psi_per_step": s.psi_per_step,
            "norm_growth_per_step": finite_or_null(s.norm_growth_per_step),
        })
    });
    json!({
        "phi": r.phi(),
        "eigenvalues": r.exact.roots.iter().map(pair).collect::<Vec<_>>(),
        "spectral_radius": r.exact.spectral_radius,
        "psi": r.exact.psi,
        "class": r.exact.class.name(),
        "sim": sim,
        "agree": r.agree(),
        "growth_per_step": finite_or_null(r.exact.growth_per_step),
        "witnesses": {
            "nalgebra": r.nalgebra.iter().map(pair).collect::<Vec<_>>(),
            "faer": r.faer.iter().map(pair).collect::<Vec<_>>(),
            "tolerance": r.tolerance,
            "checks": r.checks.iter().map(|c| json!({"witness": c.witness, "agree": c.agree, "error_over_tolerance": c.worst_ratio})).collect::<Vec<_>>(),
        },
    })
}

/// The text table of one method (values rounded for reading).
pub(crate) fn text_table(name: &str, points: &[PointReport], agree: bool) -> String {
    let mut s =
        format!("{name}: {}\n", if agree { "witnesses agree" } else { "WITNESSES DISAGREE" });
    s.push_str(&format!(
        "  {:>22}  {:<22} {:>12} {:>10} {:>13} {:>13} {:>10} {:>5}\n",
        "phi", "class", "rho", "psi", "ln rho/step", "sim ln/step", "sim psi", "agree"
    ));
    for r in points {
        let (g, sp) =
            r.sim.as_ref().map_or((f64::NAN, f64::NAN), |s| (s.growth_per_step, s.psi_per_step));
        let failing: Vec<&str> = r.checks.iter().filter(|c| !c.agree).map(|c| c.witness).collect();
        s.push_str(&format!(
            "  {:>22}  {:<22} {:>12.9} {:>10.7} {:>13.6e} {:>13.6e} {:>10.7} {:>5}{}\n",
            show_f64(r.phi()),
            r.exact.class.name(),
            r.exact.spectral_radius,
            psi_of(r.exact.roots.first().copied().unwrap_or_default()),
            r.exact.growth_per_step,
            g,
            sp,
            if r.agree() { "yes" } else { "NO" },
            if failing.is_empty() { String::new() } else { format!("  ({})", failing.join(", ")) }
        ));
    }
    s
}
