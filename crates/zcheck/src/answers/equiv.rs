//! `zcheck equiv A B`: the strongest identity between two methods (built-in
//! names or `.zm` paths), decided exactly by `poly::advanced::equiv`: equal
//! P, a signed permutation or scaling, a change of variables T(Φ) (printed,
//! with what it does to the observed samples), the same χ only, or nothing.

use poly::advanced::equiv::{Change, Relation};
use poly::{Poly, Sym};

/// The name of slot `k` of a method's state: `v`, `y@1`.
pub(crate) fn slot(m: &poly::Method, k: usize) -> String {
    m.slots()
        .get(k)
        .map(|&(v, l)| m.operand_name(poly::advanced::Operand::Start { var: v, lag: l }))
        .unwrap_or_else(|| format!("slot {k}"))
}

/// The parameters a change of variables depends on: `Phi` or `Phi, D`.
pub(crate) fn parameters(change: &Change) -> String {
    let mut symbols = std::collections::BTreeSet::new();
    for m in [&change.t, &change.inverse] {
        for i in 0..m.rows() {
            symbols.extend(m.row(i).iter().flat_map(Poly::symbols));
        }
    }
    let names: Vec<&str> = symbols.into_iter().map(Sym::name).collect();
    if names.is_empty() {
        "constant".to_owned()
    } else {
        names.join(", ")
    }
}

/// Each slot of `to` as a combination of the slots of `from`, one equation
/// per slot: `v = (y - y@1)/Phi` (the report's claims print them too).
pub(crate) fn equations(
    row: impl Fn(usize) -> (Vec<Poly>, Poly),
    from: &poly::Method,
    to: &poly::Method,
) -> Vec<String> {
    (0..to.state_size())
        .map(|i| {
            let (entries, den) = row(i);
            let sum = combination(&entries, from);
            let rhs = match (den.is_one(), entries.iter().filter(|e| !e.is_zero()).count() > 1) {
                (true, _) => sum,
                (false, true) => format!("({sum})/{}", divisor(&den)),
                (false, false) => format!("{sum}/{}", divisor(&den)),
            };
            format!("{} = {rhs}", slot(to, i))
        })
        .collect()
}

/// `Σ entries[j]·(slot j of m)`, the added terms before the subtracted
/// ones: `y - y@1`, `y - Phi*v`.
pub(crate) fn combination(entries: &[Poly], m: &poly::Method) -> String {
    use num_traits::Signed;
    let mut terms: Vec<(bool, String)> = entries
        .iter()
        .enumerate()
        .filter(|(_, e)| !e.is_zero())
        .map(|(j, e)| {
            let negative = e.len() == 1 && e.terms().all(|(_, c)| c.is_negative());
            let e = if negative { -e } else { e.clone() };
            let name = slot(m, j);
            let body = if e.is_one() {
                name
            } else if e.len() == 1 {
                format!("{e}*{name}")
            } else {
                format!("({e})*{name}")
            };
            (negative, body)
        })
        .collect();
    terms.sort_by_key(|(negative, _)| *negative);
    let mut out = String::new();
    for (k, (negative, body)) in terms.iter().enumerate() {
        out.push_str(match (k, negative) {
            (0, true) => "-",
            (0, false) => "",
            (_, true) => " - ",
            (_, false) => " + ",
        });
        out.push_str(body);
    }
    if out.is_empty() {
        "0".to_owned()
    } else {
        out
    }
}

/// A denominator as written after `/`: bare when it is one name (`Phi`),
/// in parentheses otherwise.
pub(crate) fn divisor(den: &Poly) -> String {
    let text = den.to_string();
    if text.chars().all(|c| c.is_alphanumeric() || c == '_') {
        text
    } else {
        format!("({text})")
    }
}

/// A matrix over a common denominator, on one line: `[[1, -1], [Phi, 0]] / Phi`.
pub(crate) fn fraction(m: &poly::PolyMatrix, den: &Poly) -> String {
    let rows: Vec<String> = (0..m.rows())
        .map(|i| {
            format!("[{}]", m.row(i).iter().map(ToString::to_string).collect::<Vec<_>>().join(", "))
        })
        .collect();
    let body = format!("[{}]", rows.join(", "));
    if den.is_one() {
        body
    } else {
        format!("{body} / {}", divisor(den))
    }
}

/// The relation in words, with the permutation and scaling when there are.
pub(crate) fn describe(r: &Relation, a: &poly::Method, b: &poly::Method) -> String {
    let mapping = |perm: &[usize]| {
        perm.iter()
            .enumerate()
            .map(|(i, p)| format!("{} ↔ {}", slot(b, i), slot(a, *p)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let scales = |scale: &[poly::Q]| {
        scale
            .iter()
            .enumerate()
            .map(|(i, s)| format!("{} × {s}", slot(b, i)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    match r {
        Relation::Equal => "equal transition matrices".to_owned(),
        Relation::Permutation { perm } => {
            format!("similar by a permutation of the state ({})", mapping(perm))
        }
        Relation::Scaling { scale } => {
            format!("similar by a diagonal scaling of the state ({})", scales(scale))
        }
        Relation::PermutationAndScaling { perm, scale } => format!(
            "similar by a permutation and a diagonal scaling of the state ({}; {})",
            mapping(perm),
            scales(scale)
        ),
        Relation::ChangeOfVariables(change) => format!(
            "similar by a change of variables T({}), not by a permutation or scaling",
            parameters(change)
        ),
        Relation::SameCharpoly => "the same characteristic polynomial, not similar: no change of \
                                   variables over the rational functions of the parameters"
            .to_owned(),
        Relation::Different => "different characteristic polynomials".to_owned(),
    }
}
