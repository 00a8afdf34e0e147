//! The paper's four criteria (section 1) measured for a method, exactly,
//! so that advice such as "not recommended" or "cannot be recommended"
//! becomes a comparison: stability limit, frequency (phase) error,
//! amplitude error and operations per step.

use std::cmp::Ordering;

use num_traits::Signed;

use poly::{Algebraic, Q};

use super::ranges;
use crate::load::builtin_derivation;

/// The criteria of one method.
pub(crate) struct Criteria {
    /// The built-in's name.
    pub method: &'static str,
    /// Φ_max (`None`: no stable Φ > 0 for the methods compared here).
    pub limit: Option<Algebraic>,
    /// The leading term of Ψ − Φ: (power of Φ, coefficient).
    pub phase: Option<(usize, Q)>,
    /// The leading term of |z|² − 1: (power of Φ, coefficient).
    pub amplitude: Option<(usize, Q)>,
    /// Multiplications plus additions per step.
    pub operations: u32,
}

fn leading(c: &[Q], skip: usize) -> Option<(usize, Q)> {
    use num_traits::Zero;
    c.iter().enumerate().skip(skip).find(|(_, x)| !x.is_zero()).map(|(k, x)| (k, x.clone()))
}

/// The criteria of a built-in, from its exact χ.
pub(crate) fn criteria(method: &'static str) -> Criteria {
    let d = builtin_derivation(method);
    let mut psi = poly::advanced::series::psi_series(d.charpoly(), 7).expect("Ψ series");
    if psi.len() > 1 {
        psi[1] -= poly::q(1, 1);
    }
    let mut modulus =
        poly::advanced::series::modulus_sq_series(d.charpoly(), 7).expect("|z|² series");
    if !modulus.is_empty() {
        modulus[0] -= poly::q(1, 1);
    }
    let c = poly::advanced::cost::step_cost(d.method()).program;
    Criteria {
        method,
        limit: ranges::limit_of(&ranges::report(method)),
        phase: leading(&psi, 0),
        amplitude: leading(&modulus, 0),
        operations: c.mul + c.add,
    }
}

/// How `a` compares with `b` on an error term: `Less` when `a` is smaller
/// (a higher power, or the same power with a smaller coefficient; none is
/// smallest).
fn error_cmp(a: &Option<(usize, Q)>, b: &Option<(usize, Q)>) -> Ordering {
    match (a, b) {
        (None, None) => Ordering::Equal,
        (None, Some(_)) => Ordering::Less,
        (Some(_), None) => Ordering::Greater,
        (Some((ka, ca)), Some((kb, cb))) => kb.cmp(ka).then(ca.abs().cmp(&cb.abs())),
    }
}

/// The criteria on which `a` is better than `b`, and those on which it is
/// worse, by name.
pub(crate) fn compare(a: &Criteria, b: &Criteria) -> (Vec<&'static str>, Vec<&'static str>) {
    let mut better = Vec::new();
    let mut worse = Vec::new();
    let limit = match (&a.limit, &b.limit) {
        (Some(x), Some(y)) => x.cmp(y),
        (Some(_), None) => Ordering::Greater,
        (None, Some(_)) => Ordering::Less,
        (None, None) => Ordering::Equal,
    };
    let rows = [
        ("stability limit", limit),
        ("phase error", error_cmp(&b.phase, &a.phase)),
        ("amplitude error", error_cmp(&b.amplitude, &a.amplitude)),
        ("operations per step", b.operations.cmp(&a.operations)),
    ];
    for (name, ord) in rows {
        match ord {
            Ordering::Greater => better.push(name),
            Ordering::Less => worse.push(name),
            Ordering::Equal => {}
        }
    }
    (better, worse)
}

/// One method's criteria in words.
pub(crate) fn text(c: &Criteria) -> String {
    let term = |t: &Option<(usize, Q)>| match t {
        None => "0".to_owned(),
        Some((k, x)) => format!("{x}·Φ^{k}"),
    };
    format!(
        "{}: Φ_max = {}, Ψ − Φ = {}, |z|² − 1 = {}, {} operations",
        ranges::title(c.method),
        c.limit.as_ref().map(ranges::show).unwrap_or_else(|| "none".to_owned()),
        term(&c.phase),
        term(&c.amplitude),
        c.operations
    )
}

/// "`a` is dominated": some built-in of the paper is at least as good on all
/// four criteria and better on one. Returns the dominating methods.
pub(crate) fn dominated_by(
    a: &Criteria,
    others: &[&'static str],
) -> Vec<(Criteria, Vec<&'static str>)> {
    others
        .iter()
        .filter(|m| **m != a.method)
        .map(|m| criteria(m))
        .filter_map(|b| {
            let (better, worse) = compare(&b, a);
            (worse.is_empty() && !better.is_empty()).then_some((b, better))
        })
        .collect()
}
