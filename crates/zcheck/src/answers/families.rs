//! `zcheck advise --scene FILE --solvers paper,xpbd,soft_step`: each
//! family's cheapest configuration that is stable and meets the scene's
//! targets, side by side in one table ranked by exact operations per tick
//! (ties by family name), with the ns measured on this machine beside it.
//!
//! - `paper`: the force-based advisor (`advise --scene`): the method and
//!   substeps it recommends; its cost is the method's operations per step
//!   of one degree of freedom × substeps × degrees of freedom.
//! - `xpbd`, `xpbd_jacobi`, `soft_step`: the solver search (`advise --scene
//!   --solver`); its cost is the substep kernel's operations on the scene's
//!   constraints (counted by running it once) × substeps.

use serde::Serialize;

use super::advice::scene_advice;
use crate::error::Error;
use crate::scene::advisor::Options;
use crate::scene::file::SceneFile;
use crate::scene::solvers::{solver_advice, Answer, Solver};
use crate::values::ParamArg;

/// What each family's operation count counts.
pub(crate) const OPS_NOTE: &str = "paper: the method's arithmetic per step of one degree of \
freedom x substeps x degrees of freedom (advise's exact cost); xpbd, xpbd_jacobi, soft_step: the \
substep kernel's arithmetic on this scene's constraints x substeps (counted by running it once)";

/// One family's best configuration.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct FamilyRow {
    /// `paper`, `xpbd`, `xpbd_jacobi` or `soft_step`.
    pub family: String,
    /// Its rank by exact operations per tick (1 = cheapest); `None` when it
    /// has no configuration meeting the targets.
    pub rank: Option<usize>,
    /// The method (paper) or solver.
    pub method: Option<String>,
    /// Substeps per tick.
    pub substeps: Option<u64>,
    /// Iterations per substep (solvers only).
    pub iterations: Option<u64>,
    /// Exact arithmetic operations per tick.
    pub ops_per_tick: Option<u64>,
    /// Measured ns per tick on this machine (shown, never ranked by).
    pub ns_per_tick: Option<f64>,
    /// Predicted phase error over the duration, rad.
    pub phase_error_rad: Option<f64>,
    /// Predicted relative amplitude error over the duration.
    pub amplitude_error: Option<f64>,
    /// Why there is no configuration.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

impl FamilyRow {
    /// A family's row before its configuration is known.
    fn empty(family: &str) -> FamilyRow {
        FamilyRow {
            family: family.to_owned(),
            rank: None,
            method: None,
            substeps: None,
            iterations: None,
            ops_per_tick: None,
            ns_per_tick: None,
            phase_error_rad: None,
            amplitude_error: None,
            reason: None,
        }
    }
}

/// The table `--solvers` prints.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct FamilyTable {
    /// Tick rate, Hz.
    pub tick_hz: f64,
    /// Duration, s.
    pub duration_s: f64,
    /// Phase target, rad.
    pub phase_rad: f64,
    /// Amplitude target.
    pub amplitude: f64,
    /// Degrees of freedom.
    pub dof: usize,
    /// The families, by rank (those with no configuration last, in the
    /// order given).
    pub families: Vec<FamilyRow>,
    /// The cheapest family's row.
    pub recommended: Option<FamilyRow>,
    /// How the families are ranked.
    pub ranked_by: &'static str,
    /// What each operation count counts.
    pub ops_counted: &'static str,
}

/// The families named by `--solvers`, each once, checked before any work.
pub(crate) fn parse_families(list: &[String]) -> Result<Vec<String>, Error> {
    let mut out: Vec<String> = Vec::new();
    for word in list.iter().map(|w| w.trim()) {
        if word != "paper" {
            Solver::parse(word).map_err(|_| {
                Error::usage(format!(
                    "--solvers {word}: unknown family, expected paper, xpbd, xpbd_jacobi or soft_step"
                ))
            })?;
        }
        if out.iter().any(|w| w == word) {
            return Err(Error::usage(format!("--solvers: {word} is listed twice")));
        }
        out.push(word.to_owned());
    }
    if out.is_empty() {
        return Err(Error::usage(
            "--solvers: expected at least one of paper, xpbd, xpbd_jacobi, soft_step",
        ));
    }
    Ok(out)
}

/// Every family's best configuration on `scene`, ranked.
pub(crate) fn family_table(
    scene: &SceneFile,
    families: &[String],
    methods: &[String],
    params: &[ParamArg],
    options: Options,
) -> Result<FamilyTable, Error> {
    if let Some(p) = params.first().filter(|_| !families.iter().any(|f| f == "paper")) {
        return Err(Error::usage(format!(
            "--param {}={}: binds a parameter of a tableau among the paper family's --methods; \
             expected paper among --solvers",
            p.name, p.value
        )));
    }
    let mut rows = Vec::with_capacity(families.len());
    for family in families {
        rows.push(if family == "paper" {
            paper_row(scene, methods, params, options)?
        } else {
            solver_row(scene, Solver::parse(family)?)?
        });
    }
    Ok(rank(scene, rows))
}

/// Ranks the rows with a configuration by (ops per tick, family name).
fn rank(scene: &SceneFile, mut rows: Vec<FamilyRow>) -> FamilyTable {
    let mut order: Vec<usize> =
        (0..rows.len()).filter(|&i| rows[i].ops_per_tick.is_some()).collect();
    order.sort_by(|&a, &b| {
        (rows[a].ops_per_tick, &rows[a].family).cmp(&(rows[b].ops_per_tick, &rows[b].family))
    });
    for (r, &i) in order.iter().enumerate() {
        rows[i].rank = Some(r + 1);
    }
    rows.sort_by_key(|r| r.rank.unwrap_or(usize::MAX));
    FamilyTable {
        tick_hz: scene.tick_hz,
        duration_s: scene.duration_s,
        phase_rad: scene.phase_rad,
        amplitude: scene.amplitude,
        dof: scene.dof(),
        recommended: rows.first().filter(|r| r.rank == Some(1)).cloned(),
        families: rows,
        ranked_by:
            "exact operations per tick (ties: family name); ns measured on this machine beside it",
        ops_counted: OPS_NOTE,
    }
}

fn paper_row(
    scene: &SceneFile,
    methods: &[String],
    params: &[ParamArg],
    options: Options,
) -> Result<FamilyRow, Error> {
    let a = scene_advice(scene, methods, params, options)?;
    let mut row = FamilyRow::empty("paper");
    let chosen = a
        .recommended
        .as_ref()
        .and_then(|r| a.candidates.iter().find(|c| c.method == r.method).map(|c| (r, c)));
    match chosen {
        Some((r, c)) => {
            row.method = Some(r.method.clone());
            row.substeps = Some(r.substeps);
            row.ops_per_tick = c.ops_per_tick;
            row.ns_per_tick = c.ns_per_tick;
            row.phase_error_rad = c.predicted.as_ref().map(|e| e.phase_rad);
            row.amplitude_error = c.predicted.as_ref().map(|e| e.amplitude);
        }
        None => row.reason = Some("no force-based method meets the targets".to_owned()),
    }
    Ok(row)
}

fn solver_row(scene: &SceneFile, solver: Solver) -> Result<FamilyRow, Error> {
    let advice = solver_advice(scene, solver, None)?;
    let mut row = FamilyRow::empty(solver.name());
    let Answer::Search(s) = advice.answer else {
        return Err(Error::numeric("the solver search gave one configuration"));
    };
    match s.analysis {
        Some(c) => {
            row.method = Some(solver.name().to_owned());
            row.substeps = Some(c.substeps);
            row.iterations = Some(c.iterations);
            row.ops_per_tick = Some(c.ops_per_tick);
            row.ns_per_tick = c.ns_per_tick;
            row.phase_error_rad = Some(c.phase_error_rad);
            row.amplitude_error = Some(c.amplitude_error);
        }
        None => row.reason = s.reason,
    }
    Ok(row)
}

/// The table as text.
pub(crate) fn family_text(name: &str, t: &FamilyTable) -> String {
    let mut out = format!(
        "scene {name}: {}; tick {} Hz, {} s; target: phase <= {} rad, amplitude <= {}\n",
        super::advice::dof_phrase(t.dof),
        t.tick_hz,
        t.duration_s,
        t.phase_rad,
        t.amplitude
    );
    let dash = || "-".to_owned();
    let rows: Vec<[String; 7]> = t
        .families
        .iter()
        .map(|r| {
            [
                r.rank.map_or(dash(), |k| k.to_string()),
                r.family.clone(),
                match (&r.method, r.substeps, r.iterations) {
                    (Some(m), Some(s), Some(n)) => format!("{m} {s} substeps x {n} iterations"),
                    (Some(m), Some(s), None) => format!("{m} x {s} substeps"),
                    _ => "none".to_owned(),
                },
                r.ops_per_tick.map_or(dash(), |o| o.to_string()),
                r.ns_per_tick.map_or(dash(), |n| format!("{n:.0}")),
                r.phase_error_rad.map_or(dash(), |p| format!("{p:.3e}")),
                r.amplitude_error.map_or(dash(), |a| format!("{a:.3e}")),
            ]
        })
        .collect();
    let header =
        ["rank", "family", "configuration", "ops/tick", "ns/tick", "phase rad", "amplitude"]
            .map(str::to_owned);
    out += &super::advice::table(&header, &rows);
    out += &match &t.recommended {
        Some(r) => format!(
            "recommended: {} ({}), the fewest exact operations per tick\n",
            r.family, rows[0][2]
        ),
        None => "recommended: none (no family meets the targets)\n".to_owned(),
    };
    for r in t.families.iter().filter(|r| r.rank.is_none()) {
        if let Some(why) = &r.reason {
            out += &format!("{}: {why}\n", r.family);
        }
    }
    out += &format!("ops counted: {}\n", t.ops_counted);
    out
}
