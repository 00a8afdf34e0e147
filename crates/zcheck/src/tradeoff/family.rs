//! The methods a trade-off compares, each with its exact stability limit.
//!
//! The undamped family is every built-in except `damped_euler_d` (whose
//! damping ratio is free): the seven methods of sections 5–11 and their
//! Appendix B "Transition matrix" twins. The damped family, used only when a
//! scene has physical damping D, is each direct method applied to
//! v̇ = −ω₀(y + 2Dv), ẏ = ω₀v: the built-ins [`poly::advanced::builtins::DAMPED_METHODS`]
//! (`crates/poly/methods/*_damped.zm`, and `damped_euler_d` for Standard Euler). At D = 0 each has its undamped
//! method's characteristic polynomial (tested).

use std::cmp::Ordering;
use std::collections::HashMap;
use std::f64::consts::PI;

use poly::advanced::cost::StepCost;
use poly::{Algebraic, Method, Sym, Q};

use super::accuracy::SecondOrder;
use crate::error::Error;
use crate::load::LoadedMethod;
use check::numeric::{f64_to_q, q_to_f64};

/// The exact stability limit of one method (at fixed other parameters).
#[derive(Clone, Debug)]
pub(crate) struct Limit {
    /// Φ_max from `poly::advanced::stability::analyze`: every 0 < Φ < Φ_max is
    /// bounded. `None` with `bounded_for_all == false`: unbounded for every
    /// small Φ > 0 (Standard Euler, Standard Heun).
    pub phi_max: Option<Algebraic>,
    /// Bounded for every Φ > 0.
    pub bounded_for_all: bool,
}

impl Limit {
    /// Whether Φ (the exact value of this `f64`) is strictly below Φ_max,
    /// decided exactly.
    pub(crate) fn is_below(&self, phi: f64) -> bool {
        if self.bounded_for_all {
            return phi > 0.0;
        }
        match (&self.phi_max, f64_to_q(phi)) {
            (Some(max), Some(q)) => phi > 0.0 && max.cmp_rational(&q) == Ordering::Greater,
            _ => false,
        }
    }

    /// Φ_max to f64 precision (`None` when there is none).
    ///
    /// To relative precision: an absolute 10⁻¹⁸ is only 10⁻¹¹ relative at
    /// Φ_max ≈ 10⁻⁷ (a tiny damping ratio), and [`Limit::search_cap`] would
    /// then step down thousands of ulps one exact comparison at a time.
    pub(crate) fn phi_max_f64(&self) -> Option<f64> {
        let m = self.phi_max.as_ref()?;
        let coarse = q_to_f64(&m.approx(&poly::q(1, 1_000_000_000_000_000)));
        let width = f64_to_q(coarse.abs() * 2f64.powi(-60))
            .filter(|w| *w > Q::from_integer(0.into()))
            .unwrap_or_else(|| poly::q(1, 1_000_000_000_000_000));
        Some(q_to_f64(&m.approx(&width)))
    }

    /// The largest step a search may try: the largest `f64` strictly below
    /// Φ_max (checked exactly), π when every Φ is bounded (beyond π the
    /// phase per step is ambiguous, Nyquist), `None` when no Φ is stable.
    pub(crate) fn search_cap(&self) -> Option<f64> {
        if self.bounded_for_all {
            return Some(PI);
        }
        let mut cap = self.phi_max_f64()?.min(PI);
        while !self.is_below(cap) {
            cap *= 1.0 - 2.0 * f64::EPSILON;
        }
        Some(cap)
    }

    /// The smallest number of substeps k with Φ/k strictly below Φ_max
    /// (exact comparison); `None` when no Φ > 0 is stable, or when more than
    /// [`MAX_SUBSTEPS`] would be needed.
    pub(crate) fn substeps_for(&self, phi: f64) -> Option<u64> {
        if self.bounded_for_all {
            return Some(1);
        }
        let max = self.phi_max_f64()?;
        let guess = (phi / max).floor();
        if guess.is_nan() || guess >= MAX_SUBSTEPS as f64 {
            return None;
        }
        let mut k = (guess as u64).max(1);
        while !self.is_below(phi / k as f64) {
            k += 1;
            if k > MAX_SUBSTEPS {
                return None;
            }
        }
        // The float guess may overshoot by one; step back while still stable.
        while k > 1 && self.is_below(phi / (k - 1) as f64) {
            k -= 1;
        }
        Some(k)
    }
}

/// The most substeps per tick ever counted: beyond it a step is "never"
/// practical, and the count would leave the exact range of `f64`.
pub(crate) const MAX_SUBSTEPS: u64 = 1_000_000_000_000_000;

/// One method ready to trade: its definition, exact cost, accuracy model
/// and stability limit, at fixed values of its parameters other than Φ.
#[derive(Clone, Debug)]
pub(crate) struct Candidate {
    /// The method's name (its `.zm` name).
    pub name: String,
    /// The name shown to a user: a built-in's base name (the damped
    /// variants drop `_damped`), a user's method as its argument.
    pub display: String,
    /// The lowered method.
    pub method: Method,
    /// Its hand-written kernel, for a built-in (see
    /// `LoadedMethod::hand_kernel`).
    pub hand_kernel: Option<&'static str>,
    /// Values of the parameters other than Φ (the damping D).
    pub params: Vec<(Sym, Q)>,
    /// Exact operations per step.
    pub cost: StepCost,
    /// The second-order accuracy model.
    pub model: SecondOrder,
    /// The exact stability limit at these parameter values.
    pub limit: Limit,
}

impl Candidate {
    /// Builds a candidate from a loaded method (derived once, there) and
    /// the values of its parameters other than Φ: count, model and analyse
    /// exactly.
    pub(crate) fn new(loaded: &LoadedMethod, params: Vec<(Sym, Q)>) -> Result<Candidate, Error> {
        let method = loaded.method().clone();
        let name = method.name().to_owned();
        let derivation = loaded.derivation().map_err(|e| e.context(format!("method `{name}`")))?;
        let values: HashMap<Sym, Q> = params.iter().cloned().collect();
        let charpoly = derivation.charpoly().eval_partial(&values);
        // From the derivation, so a repeated root on the circle is decided
        // from P (Gauss–Legendre stays bounded through Φ = 2√3).
        let bound = params
            .iter()
            .filter(|(s, _)| s.name() != "Phi")
            .fold(poly::Params::new(), |p, (s, v)| p.bind(s.name(), v.clone()));
        let report = derivation
            .stability(&bound)
            .map_err(|e| Error::from(e).context(format!("method `{name}`: stability")))?;
        let limit =
            Limit { phi_max: report.phi_max().cloned(), bounded_for_all: report.bounded_for_all() };
        let model =
            SecondOrder::new(&charpoly, &[]).map_err(|e| e.context(format!("method `{name}`")))?;
        let cost = derivation.cost();
        Ok(Candidate {
            name,
            display: loaded.display().to_owned(),
            method,
            hand_kernel: loaded.hand_kernel(),
            params,
            cost,
            model,
            limit,
        })
    }
}

/// Every paper built-in with no free parameter but Φ, in built-in order.
pub(crate) fn undamped_family() -> Result<Vec<Candidate>, Error> {
    let mut family = Vec::new();
    for name in poly::advanced::builtins::paper_builtin_names() {
        let method = builtin(name)?;
        if method.method().params().len() == 1 {
            family.push(Candidate::new(&method, Vec::new())?);
        }
    }
    Ok(family)
}

/// The damped `methods` (with `param D`) as candidates at the damping
/// ratio `d`.
pub(crate) fn damped_candidates(methods: &[LoadedMethod], d: &Q) -> Result<Vec<Candidate>, Error> {
    let dsym = Sym::new("D");
    methods.iter().map(|m| Candidate::new(m, vec![(dsym, d.clone())])).collect()
}

fn builtin(name: &str) -> Result<LoadedMethod, Error> {
    LoadedMethod::builtin(name).map_err(|e| e.context(format!("built-in `{name}`")))
}
