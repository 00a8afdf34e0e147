//! `zcheck advise`: which method and how many substeps for a spring in a
//! game scene, in game units (Hz); or, with `--scene FILE`, for a whole
//! scene of masses and springs (or modes) read from a TOML file.

use crate::error::Error;
use crate::load::LoadedMethod;
use crate::scene::advisor::{self, Options};
use crate::scene::file::SceneFile;
use crate::scene::modal::{self, Modal, Shapes};
use crate::tradeoff::spring_advisor::SpringAdvice;
use crate::values::ParamArg;

/// "1 degree of freedom", "n degrees of freedom".
pub(crate) fn dof_phrase(n: usize) -> String {
    if n == 1 {
        "1 degree of freedom".to_owned()
    } else {
        format!("{n} degrees of freedom")
    }
}

/// `zcheck advise --freq --tick` as JSON: the one-spring advice, plus the
/// whole-scene advisor's keys for the same spring as a one-mode scene.
#[derive(serde::Serialize)]
pub(crate) struct OneSpring<'a> {
    #[serde(flatten)]
    pub(crate) advice: &'a SpringAdvice,
    pub(crate) modes: &'a [advisor::ModeReport],
    pub(crate) candidates: &'a [advisor::CandidateAdvice],
    pub(crate) recommended: &'a Option<advisor::Recommended>,
}

/// The scene reduced to its modes, with mode shapes when the prediction
/// is to be checked by simulation.
pub(crate) fn modal_of(
    scene: &SceneFile,
    simulate: bool,
    route: modal::Route,
) -> Result<Modal, Error> {
    let shapes = if simulate { Shapes::Compute } else { Shapes::WhenNeeded };
    modal::reduce_with_route(scene, shapes, route)
}

/// Rows under a header, each column as wide as its widest cell (phi_max
/// can be a nested root): the first column left-aligned, the rest right.
pub(crate) fn table<const N: usize>(header: &[String; N], rows: &[[String; N]]) -> String {
    let widths: Vec<usize> = (0..N)
        .map(|c| {
            std::iter::once(header).chain(rows).map(|r| r[c].chars().count()).max().unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for row in std::iter::once(header).chain(rows) {
        let cells: Vec<String> = row
            .iter()
            .zip(&widths)
            .enumerate()
            .map(
                |(c, (cell, &w))| {
                    if c == 0 {
                        format!("{cell:<w$}")
                    } else {
                        format!("{cell:>w$}")
                    }
                },
            )
            .collect();
        out += &cells.join("  ");
        out.push('\n');
    }
    out
}

/// The advice as a table and a sentence.
pub(crate) fn text(a: &SpringAdvice) -> String {
    let s = &a.scene;
    let f = |x: f64| crate::values::show_f64(x);
    let mut out = format!(
        "scene: {} Hz spring on a {} Hz tick: Phi = 2*pi*{}/{} = {} rad per tick ({} ticks per period)\n",
        f(s.freq_hz),
        f(s.tick_hz),
        f(s.freq_hz),
        f(s.tick_hz),
        crate::values::show_f64_digits(a.phi, 4),
        crate::values::show_f64_digits(2.0 * std::f64::consts::PI / a.phi, 2)
    );
    out += &format!(
        "target over {} s ({} periods): phase drift <= {} rad, amplitude drift <= {}\n",
        f(s.duration_s),
        f(a.periods),
        f(s.phase_tol),
        f(s.amp_tol)
    );
    out += &match s.damping {
        Some(d) => {
            format!("spring: damped, D = {d}; judged against the exact damped oscillator\n\n")
        }
        None => "spring: undamped\n\n".to_owned(),
    };
    let header = [
        "method",
        "phi_max",
        "stable",
        "substeps stable",
        "substeps tolerance",
        "ops/tick",
        "ns/tick",
    ]
    .map(str::to_owned);
    let rows: Vec<[String; 7]> = a
        .methods
        .iter()
        .map(|m| {
            [
                m.method.clone(),
                m.phi_max.clone(),
                (if m.stable_at_phi { "yes" } else { "no" }).to_owned(),
                m.substeps_stable.map_or("never".to_owned(), |k| k.to_string()),
                m.substeps_tol.map_or("never".to_owned(), |k| k.to_string()),
                m.ops_per_tick.map_or("-".to_owned(), |o| format!("{}m+{}a", o.mul, o.add)),
                m.ns_per_tick.map_or("-".to_owned(), |ns| format!("{ns:.1}")),
            ]
        })
        .collect();
    out += &table(&header, &rows);
    let stable: Vec<&str> =
        a.methods.iter().filter(|m| m.stable_at_phi).map(|m| m.method.as_str()).collect();
    out += &format!(
        "\nstable at Phi = {:.4} with one step per tick: {}\n",
        a.phi,
        if stable.is_empty() { "none".to_owned() } else { stable.join(", ") }
    );
    out += &match a.cheapest.as_ref().and_then(|c| a.methods.iter().find(|m| &m.method == c)) {
        Some(m) => format!(
            "cheapest meeting the tolerance: {} with {} substeps per tick ({} operations, {:.1} ns per tick measured here; {})\n",
            m.method,
            m.substeps_tol.unwrap_or(0),
            m.ops_per_tick.map_or(0, |o| o.mul + o.add),
            m.ns_per_tick.unwrap_or(f64::NAN),
            a.rank.describe()
        ),
        None => "no method meets the tolerance at a stable step\n".to_owned(),
    };
    out
}

/// The advice of `zcheck advise --scene` on a scene read: for `methods`
/// (built-in names, `.zm` files or tableaux, a tableau's parameters bound
/// to their `params` values; none: the seven direct methods).
pub(crate) fn scene_advice(
    scene: &SceneFile,
    methods: &[String],
    params: &[ParamArg],
    options: Options,
) -> Result<advisor::SceneAdvice, Error> {
    let values = crate::load::values_of_args(params);
    let specs: Vec<LoadedMethod> = if methods.is_empty() {
        LoadedMethod::damped_builtins()?
    } else {
        methods.iter().map(|m| LoadedMethod::load_damped(m, &values)).collect::<Result<_, _>>()?
    };
    crate::values::check_taken_then(params, specs.iter().flat_map(|s| s.tableau_params()), "")?;
    let modal = modal_of(scene, options.simulate, options.route)?;
    advisor::advise(scene, &modal, specs, options)
}

/// The scene advice as text: the modes that matter, a table, a sentence.
pub(crate) fn scene_text(name: &str, a: &advisor::SceneAdvice) -> String {
    let mut out = format!(
        "scene {name}: {}, {} modes ({} zero-frequency (rigid) left out: they need no substeps), damping {}\n",
        dof_phrase(a.dof),
        a.modes.iter().filter(|m| !m.sampled).count(),
        a.rigid_modes,
        match a.damping {
            modal::DampingKind::Undamped => "none".to_owned(),
            modal::DampingKind::Rayleigh { alpha, beta } =>
                format!("Rayleigh (alpha = {alpha:.4} 1/s, beta = {beta:.3e} s)"),
            modal::DampingKind::Proportional => "proportional".to_owned(),
            modal::DampingKind::NonProportional =>
                "non-proportional (stability from the full-step matrix)".to_owned(),
        }
    );
    out += &format!(
        "tick {} Hz, {} s; target: phase <= {} rad and amplitude <= {} for {}\n",
        a.tick_hz,
        a.duration_s,
        a.phase_rad,
        a.amplitude,
        match a.max_hz {
            Some(f) => format!("the modes at or below {f} Hz (every mode stable)"),
            None => "every mode".to_owned(),
        }
    );
    if a.spectrum.route == "sparse" {
        out += &format!(
            "spectrum: sparse route: {} modes computed{}, {} sampled frequencies stand for the rest (every mode lies below the certified bound); {} degrees of freedom no spring touches\n",
            a.spectrum.computed,
            match (a.max_hz, a.spectrum.band_complete) {
                (Some(f), Some(true)) => format!(" (every mode at or below {f} Hz)"),
                (Some(f), _) => format!(" (the lowest of those at or below {f} Hz; samples cover the rest of the band)"),
                _ => " (the lowest)".to_owned(),
            },
            a.spectrum.sampled,
            a.spectrum.untouched_dofs,
        );
    }
    let show = |i: usize| {
        format!(
            "{:.3} Hz (ratio {:.4}){}",
            a.modes[i].hz,
            a.modes[i].ratio,
            if a.modes[i].sampled { ", sampled" } else { "" }
        )
    };
    // A long list is cut: the JSON has every mode.
    let list = |keep: &dyn Fn(usize) -> bool| -> Vec<String> {
        let all: Vec<usize> = (0..a.modes.len()).filter(|&i| keep(i)).collect();
        let mut v: Vec<String> = all.iter().take(8).map(|&i| show(i)).collect();
        if all.len() > 8 {
            v.push(format!("and {} more", all.len() - 8));
        }
        v
    };
    let stab = list(&|i| a.modes[i].limits_stability);
    let acc = list(&|i| a.modes[i].limits_accuracy);
    // Modes found, not the sparse route's samples.
    let rest =
        a.modes.iter().filter(|m| !m.sampled && !m.limits_stability && !m.limits_accuracy).count();
    out += &format!(
        "modes limiting stability: {}\n",
        if stab.is_empty() { "none".into() } else { stab.join(", ") }
    );
    out += &format!(
        "modes limiting accuracy:  {}\n",
        if acc.is_empty() { "none".into() } else { acc.join(", ") }
    );
    out += &format!("modes that do not matter: {rest}\n");
    if let (Some(h), Some(b)) = (a.highest_hz, a.highest_hz_bound) {
        out += &format!(
            "highest mode {h:.3} Hz, certified <= {b:.3} Hz ({})",
            match a.spectrum.certificate {
                modal::Certificate::Cholesky =>
                    "Cholesky factor of s I - M^-1/2 K M^-1/2 at s just above the Lanczos value",
                modal::Certificate::Gershgorin => "Gershgorin on M^-1/2 K M^-1/2",
            }
        );
        let certified: Vec<String> = a
            .candidates
            .iter()
            .filter_map(|c| Some(format!("{} {}", c.method, c.substeps_stable_certified?)))
            .collect();
        if !certified.is_empty() {
            out += &format!("; stable substeps at the bound: {}", certified.join(", "));
        }
        out += "\n";
    }
    out += "\n";
    let header = [
        "method",
        "substeps stable",
        "substeps accurate",
        "ops/tick",
        "ns/tick",
        "predicted phase/amp",
        "simulated phase/amp",
        "agree",
    ]
    .map(str::to_owned);
    let rows: Vec<[String; 8]> = a
        .candidates
        .iter()
        .map(|c| {
            [
                c.method.clone(),
                c.substeps_stable.map_or("never".into(), |n| n.to_string()),
                c.substeps_accurate.map_or("never".into(), |n| n.to_string()),
                c.ops_per_tick.map_or("-".into(), |n| n.to_string()),
                c.ns_per_tick.map_or("-".into(), |ns| format!("{ns:.1}")),
                c.predicted
                    .map_or("-".into(), |p| format!("{:.3e}/{:.3e}", p.phase_rad, p.amplitude)),
                c.simulated
                    .as_ref()
                    .map_or("-".into(), |s| format!("{:.3e}/{:.3e}", s.phase_rad, s.amplitude)),
                c.simulated
                    .as_ref()
                    .map_or("-".into(), |s| (if s.agree { "yes" } else { "NO" }).into()),
            ]
        })
        .collect();
    out += &table(&header, &rows);
    out += &format!(
        "\nagreement: simulated within {} of the target (plus 1e-9) of the prediction\n",
        advisor::AGREE_FRACTION
    );
    if !a.simulation_left_out.is_empty() {
        let names: Vec<String> = a
            .simulation_left_out
            .iter()
            .map(|l| match l.cost_ratio {
                Some(r) => format!("{} ({r:.1}x)", l.method),
                None => l.method.clone(),
            })
            .collect();
        out += &format!(
            "not simulated (more than {}x the recommended's cost per tick, as ranked): {}\n",
            advisor::SIM_COST_FACTOR,
            names.join(", ")
        );
    }
    for c in &a.candidates {
        if let Some(s) = &c.simulated {
            if !s.agree {
                out += &format!("WARNING: {}: prediction and simulation disagree\n", c.method);
            }
        }
    }
    out += &match &a.recommended {
        Some(r) => format!(
            "recommended: {} with {} substeps per tick ({})\n",
            r.method,
            r.substeps,
            a.rank.describe()
        ),
        None => "recommended: none meets the target\n".to_owned(),
    };
    if let Some(sweep) = &a.sweep {
        out += "\nGauss-Seidel (bodies in sequence) against all bodies at once:\n";
        for s in sweep {
            out += &format!(
                "  {}: substeps {} (exact, modal) / {} (full step) -> {} (Gauss-Seidel), rho at {} substeps = {} (nalgebra) / {} (faer){}, largest stable step x{}\n",
                s.method,
                s.substeps_modal.map_or("never".into(), |n| n.to_string()),
                s.substeps_vector.map_or("never".into(), |n| n.to_string()),
                s.substeps_gauss_seidel.map_or("never".into(), |n| n.to_string()),
                s.substeps_modal.map_or("-".into(), |n| n.to_string()),
                s.rho_nalgebra.map_or("-".into(), |r| format!("{r:.9}")),
                s.rho_faer.map_or("-".into(), |r| format!("{r:.9}")),
                if s.witnesses_agree { "" } else { " DISAGREE" },
                s.limit_ratio.map_or("-".into(), |r| format!("{r:.4}")),
            );
        }
    }
    out
}

/// `zcheck advise --scene FILE --solver S` as text: one configuration's
/// radius, stability, errors and modes, or the search's recommendation.
pub(crate) fn solver_text(name: &str, a: &crate::scene::solvers::SolverAdvice) -> String {
    use crate::scene::solvers::{Answer, ConfigAdvice};
    let mut out = format!(
        "scene {name}: {}, {} constraints; tick {} Hz, {} s; target: phase <= {} rad, amplitude <= {}\n",
        dof_phrase(a.dof), a.constraints, a.tick_hz, a.duration_s, a.phase_rad, a.amplitude
    );
    let one = |c: &ConfigAdvice| {
        let mut t = format!(
            "{} with {} substeps x {} iterations: spectral radius {:.9}{} ({}), {} ({}); cost {} projections per tick\n",
            c.solver.name(),
            c.substeps,
            c.iterations,
            c.spectral_radius.value,
            c.spectral_radius.exact.as_ref().map_or(String::new(), |e| format!(", exactly {e}")),
            if c.spectral_radius.certified { "certified" } else { "numeric, uncertified" },
            if c.stable { "stable" } else { "UNSTABLE" },
            c.stable_from,
            c.cost
        );
        t += &format!(
            "errors over the duration: phase {:.3e} rad, amplitude {:.3e} ({} the target)\n",
            c.phase_error_rad,
            c.amplitude_error,
            if c.meets_accuracy { "meets" } else { "misses" }
        );
        t += "mode Hz -> effective Hz (damping ratio -> effective ratio):\n";
        for m in c.modes.iter().take(8) {
            t += &format!(
                "  {:.3} -> {:.3} ({:.4} -> {:.4}){}\n",
                m.hz,
                m.effective_hz,
                m.ratio + 0.0, // never -0.0000
                m.effective_ratio + 0.0,
                if m.in_band { "" } else { ", out of the band" }
            );
        }
        if c.modes.len() > 8 {
            t += &format!("  and {} more (the JSON has every mode)\n", c.modes.len() - 8);
        }
        t += &format!("pairing: {}\n", c.pairing);
        t
    };
    match &a.answer {
        Answer::One(c) => out += &one(c),
        Answer::Search(s) => {
            let passing = s.candidates.iter().filter(|c| c.stable && c.meets_accuracy).count();
            out += &format!(
                "{}: searched {}; {} candidates screened, {} stable and accurate\n",
                s.solver.name(),
                s.searched,
                s.candidates.len(),
                passing
            );
            match (&s.recommended, &s.analysis) {
                (Some(r), Some(c)) => {
                    out += &format!(
                        "recommended: {} substeps x {} iterations (the cheapest in projections per tick; ties: fewer iterations, then fewer substeps)\n",
                        r.substeps, r.iterations
                    );
                    out += &one(c);
                }
                _ => {
                    out += &format!(
                        "recommended: none ({})\n",
                        s.reason.as_deref().unwrap_or("no configuration meets the targets")
                    )
                }
            }
        }
    }
    out
}
