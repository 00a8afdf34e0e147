//! The trade: largest admissible Φ, steps and cost per period, and a ranking.
//!
//! For each candidate and a [`Target`]:
//!
//! 1. `admissible_phi`: the largest Φ strictly below the exact Φ_max such
//!    that every smaller step meets the target ([`SecondOrder::largest_admissible_phi`]);
//!    `None` for a method that is unbounded at every Φ > 0, whatever its
//!    finite-duration error (`tolerance_phi` still reports that, ignoring
//!    stability, for information).
//! 2. `steps_per_period = ⌈2π / admissible_phi⌉`: whole steps, so the step
//!    actually taken, 2π/steps, is at most the admissible Φ.
//! 3. `cost_per_period`: `steps_per_period ×` the exact operations per step,
//!    and `× ns_per_step` measured on this machine.
//!
//! The ranking orders the admissible methods by their exact operations per
//! period, ties broken by name ([`Rank::Exact`], the default: the same order
//! on every run and every machine), or by the ns per period measured here
//! ([`Rank::Measured`]); methods with no admissible Φ come last, unranked.

use std::f64::consts::PI;

use serde::Serialize;

use super::accuracy::{Spring, Target};
use super::family::Candidate;

/// What a ranking orders by.
///
/// Measured times vary 15–30 % between runs on a loaded machine, so two
/// methods of similar cost would swap places from run to run: the default
/// ranks by exact counts, and the measured ns are shown beside them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Rank {
    /// Exact arithmetic operations (multiplications plus additions) of the
    /// method's program × steps (× degrees of freedom for a scene), ties
    /// broken by name: deterministic.
    #[default]
    Exact,
    /// The ns measured on this machine (ties by operations, then name).
    Measured,
}

impl Rank {
    /// `exact` or `measured`.
    pub(crate) fn parse(text: &str) -> Option<Rank> {
        match text {
            "exact" => Some(Rank::Exact),
            "measured" => Some(Rank::Measured),
            _ => None,
        }
    }

    /// How a ranking of this kind is described to the user.
    pub(crate) fn describe(self) -> &'static str {
        match self {
            Rank::Exact => "ranked by exact operations (ties by name); --rank measured ranks by the ns measured here",
            Rank::Measured => "ranked by the ns measured on this machine (--rank measured)",
        }
    }

    /// Orders two costs: (exact operations, measured ns, name).
    pub(crate) fn cmp(self, a: (u64, f64, &str), b: (u64, f64, &str)) -> std::cmp::Ordering {
        match self {
            Rank::Exact => a.0.cmp(&b.0).then_with(|| a.2.cmp(b.2)),
            Rank::Measured => a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)).then_with(|| a.2.cmp(b.2)),
        }
    }
}

/// Operations, for JSON.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub(crate) struct Ops {
    /// Multiplications.
    pub mul: u64,
    /// Additions and subtractions.
    pub add: u64,
    /// Copies and history shifts (no arithmetic).
    pub copy: u64,
}

impl From<poly::OpCount> for Ops {
    fn from(c: poly::OpCount) -> Ops {
        Ops { mul: c.mul.into(), add: c.add.into(), copy: c.copy.into() }
    }
}

/// The cost of simulating one period of the spring.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub(crate) struct CostPerPeriod {
    /// Operations: `steps_per_period ×` [`TradeRow::ops_per_step`].
    pub ops: Ops,
    /// Multiplications plus additions per period.
    pub arithmetic: u64,
    /// Nanoseconds: `steps_per_period × ns_per_step`.
    pub ns: f64,
}

/// One method in the trade.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct TradeRow {
    /// The method's name.
    pub method: String,
    /// Exact operations per step of the program as written.
    pub ops_per_step: Ops,
    /// Exact operations per step of the transition matrix applied directly.
    pub ops_per_step_matrix_form: Ops,
    /// Measured nanoseconds per step of the compiled step, one state.
    pub ns_per_step: f64,
    /// Measured nanoseconds per step of the hand-written kernel, one state
    /// (`None` where there is no hand kernel, e.g. a user's method).
    pub ns_per_step_hand: Option<f64>,
    /// The exact stability limit as a number (`None`: see `phi_max_exact`).
    pub phi_max: Option<f64>,
    /// The exact limit as text ("2", "sqrt(2)", ...), "none" when unbounded
    /// at every Φ > 0, "every phi" when bounded for every Φ > 0.
    pub phi_max_exact: String,
    /// The largest admissible Φ (never at or beyond Φ_max).
    pub admissible_phi: Option<f64>,
    /// The largest Φ meeting the target over the duration, ignoring
    /// stability (information for unstable methods).
    pub tolerance_phi: Option<f64>,
    /// ⌈2π / admissible_phi⌉.
    pub steps_per_period: Option<u64>,
    /// Phase error per step Ψ − Φ at the step taken (2π / steps_per_period).
    pub phase_error_per_step: Option<f64>,
    /// |z|^(2π/Φ) at the step taken.
    pub amplitude_factor_per_period: Option<f64>,
    /// Cost of one simulated period at the step taken.
    pub cost_per_period: Option<CostPerPeriod>,
    /// 1 for the cheapest admissible method per period.
    pub rank: Option<usize>,
}

/// Describes an exact limit for text and JSON.
pub(crate) fn limit_text(c: &Candidate) -> String {
    match (&c.limit.phi_max, c.limit.bounded_for_all) {
        (_, true) => "every phi".to_owned(),
        (Some(m), _) => m.closed_form().unwrap_or_else(|| m.to_decimal(15)),
        (None, false) => "none".to_owned(),
    }
}

/// One row for `c` at `target`, with `ns_per_step` measured by the caller.
pub(crate) fn trade_row(
    c: &Candidate,
    spring: Spring,
    target: &Target,
    ns_per_step: f64,
) -> TradeRow {
    let admissible_phi =
        c.limit.search_cap().and_then(|cap| c.model.largest_admissible_phi(spring, target, cap));
    let tolerance_phi = c.model.largest_admissible_phi(spring, target, PI);
    let steps_per_period = admissible_phi.map(|phi| (2.0 * PI / phi).ceil() as u64);
    let taken = steps_per_period.map(|n| c.model.accuracy(2.0 * PI / n as f64, spring));
    let per_step = c.cost.program;
    let cost_per_period = steps_per_period.map(|n| CostPerPeriod {
        ops: Ops {
            mul: n * u64::from(per_step.mul),
            add: n * u64::from(per_step.add),
            copy: n * u64::from(per_step.copy),
        },
        arithmetic: n * u64::from(per_step.arithmetic()),
        ns: n as f64 * ns_per_step,
    });
    TradeRow {
        method: c.display.clone(),
        ops_per_step: c.cost.program.into(),
        ops_per_step_matrix_form: c.cost.matrix_form.into(),
        ns_per_step,
        ns_per_step_hand: None,
        phi_max: c.limit.phi_max_f64(),
        phi_max_exact: limit_text(c),
        admissible_phi,
        tolerance_phi,
        steps_per_period,
        phase_error_per_step: taken.map(|a| a.phase_error_per_step),
        amplitude_factor_per_period: taken.map(|a| a.amplitude_factor_per_period()),
        cost_per_period,
        rank: None,
    }
}

/// The trade for every candidate, ranked `by` (admissible methods by exact
/// operations per period or by the ns measured), then the rest in the given
/// order. `ns_per_step` gives each candidate's measured time.
pub(crate) fn trade(
    candidates: &[Candidate],
    spring: Spring,
    target: &Target,
    by: Rank,
    mut ns_per_step: impl FnMut(&Candidate) -> f64,
) -> Vec<TradeRow> {
    let mut rows: Vec<TradeRow> =
        candidates.iter().map(|c| trade_row(c, spring, target, ns_per_step(c))).collect();
    rank(&mut rows, by);
    rows
}

/// Sorts rows by cost per simulated period and numbers the admissible ones.
pub(crate) fn rank(rows: &mut [TradeRow], by: Rank) {
    rows.sort_by(|a, b| match (&a.cost_per_period, &b.cost_per_period) {
        (Some(x), Some(y)) => {
            by.cmp((x.arithmetic, x.ns, &a.method), (y.arithmetic, y.ns, &b.method))
        }
        (Some(_), None) => std::cmp::Ordering::Less,
        (None, Some(_)) => std::cmp::Ordering::Greater,
        (None, None) => std::cmp::Ordering::Equal,
    });
    for (k, row) in rows.iter_mut().enumerate() {
        row.rank = row.cost_per_period.map(|_| k + 1);
    }
}
