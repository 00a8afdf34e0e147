//! `zcheck equiv A B`: the strongest identity between two methods (built-in
//! names or `.zm` paths), decided exactly by `poly::advanced::equiv`: equal
//! P, a signed permutation or scaling, a change of variables T(Φ) (printed,
//! with what it does to the observed samples), the same χ only, or nothing.

use std::process::ExitCode;

use poly::advanced::equiv::{self, Change, Relation};
use poly::{Poly, Sym};
use serde_json::json;

use super::format::{Format, TEXT_JSON};
use crate::error::Error;
use crate::load::LoadedMethod;

/// Arguments of `zcheck equiv`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// The first method: a built-in name or a `.zm` path.
    pub a: String,
    /// The second method: a built-in name or a `.zm` path.
    pub b: String,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
}

/// The name of slot `k` of a method's state: `v`, `y@1`.
fn slot(m: &poly::Method, k: usize) -> String {
    m.slots()
        .get(k)
        .map(|&(v, l)| m.operand_name(poly::advanced::Operand::Start { var: v, lag: l }))
        .unwrap_or_else(|| format!("slot {k}"))
}

/// The parameters a change of variables depends on: `Phi` or `Phi, D`.
fn parameters(change: &Change) -> String {
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
    (0..to.order())
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
fn combination(entries: &[Poly], m: &poly::Method) -> String {
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
fn divisor(den: &Poly) -> String {
    let text = den.to_string();
    if text.chars().all(|c| c.is_alphanumeric() || c == '_') {
        text
    } else {
        format!("({text})")
    }
}

/// A matrix over a common denominator, on one line: `[[1, -1], [Phi, 0]] / Phi`.
fn fraction(m: &poly::PolyMatrix, den: &Poly) -> String {
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

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let a = LoadedMethod::load(&args.a)?;
    let b = LoadedMethod::load(&args.b)?;
    let (da, db) = (a.derivation()?, b.derivation()?);
    let (ma, mb) = (&da.method(), &db.method());
    let relation = equiv::relate(da, db);
    let reordered = equiv::reordered_updates(ma, mb);
    let words = describe(&relation, ma, mb);
    let change = match &relation {
        Relation::ChangeOfVariables(change) => Some(change.as_ref()),
        _ => None,
    };
    let samples = |c: &Change| {
        c.observed.as_ref().map(|y| {
            format!(
                "the samples of {y} are identical: {y}_n of {b} from T x0 equals {y}_n of {a} from x0, \
                 for every n >= 0 and every start x0",
                a = ma.name(),
                b = mb.name()
            )
        })
    };
    let out = match args.format {
        Format::Json => {
            let change_doc = change.map(|c| {
                let matrix = |m: &poly::PolyMatrix| {
                    (0..m.rows())
                        .map(|i| m.row(i).iter().map(ToString::to_string).collect::<Vec<_>>())
                        .collect::<Vec<_>>()
                };
                json!({
                    "t": matrix(&c.t),
                    "t_denominator": c.t_denominator.to_string(),
                    "inverse": matrix(&c.inverse),
                    "inverse_denominator": c.inverse_denominator.to_string(),
                    "b_from_a": equations(|i| c.t_row(i), ma, mb),
                    "a_from_b": equations(|i| c.inverse_row(i), mb, ma),
                    "undefined_where_zero": c.undefined_at().to_string(),
                    "observed": c.observed,
                    "samples": samples(c),
                })
            });
            let doc = json!({
                "a": ma.name(),
                "b": mb.name(),
                "relation": relation.name(),
                "description": words,
                "shares_charpoly": relation.shares_charpoly(),
                "reordered_updates": reordered,
                "charpoly_a": da.charpoly().to_string(),
                "charpoly_b": db.charpoly().to_string(),
                "change": change_doc,
            });
            serde_json::to_string_pretty(&doc)? + "\n"
        }
        _ => {
            let mut out = format!("{} and {}: {words}\n", ma.name(), mb.name());
            if reordered {
                out.push_str("the second program is the first with its updates reordered\n");
            }
            if let Some(c) = change {
                out.push_str(&format!("{} from {} (x_b = T x_a):\n", mb.name(), ma.name()));
                for e in equations(|i| c.t_row(i), ma, mb) {
                    out.push_str(&format!("  {e}\n"));
                }
                out.push_str(&format!("{} from {} (x_a = T^-1 x_b):\n", ma.name(), mb.name()));
                for e in equations(|i| c.inverse_row(i), mb, ma) {
                    out.push_str(&format!("  {e}\n"));
                }
                out.push_str(&format!("T = {}\n", fraction(&c.t, &c.t_denominator)));
                out.push_str(&format!("T^-1 = {}\n", fraction(&c.inverse, &c.inverse_denominator)));
                let undefined = c.undefined_at();
                if undefined.as_constant().is_none() {
                    out.push_str(&format!("T and T^-1 exist wherever {undefined} != 0\n"));
                }
                match samples(c) {
                    Some(s) => out.push_str(&format!("{s}\n")),
                    None => out.push_str(&format!(
                        "no such T keeps the samples of {}: it is missing, or its samples do not \
                         determine the state\n",
                        equiv::OBSERVED
                    )),
                }
            }
            out.push_str(&format!("chi({}) = {}\n", ma.name(), da.charpoly()));
            out.push_str(&format!("chi({}) = {}\n", mb.name(), db.charpoly()));
            out
        }
    };
    super::output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
