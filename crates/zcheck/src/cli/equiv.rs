//! `zcheck equiv A B`: the strongest identity between two methods (built-in
//! names or `.zm` paths), decided exactly by `poly::advanced::equiv`.

use std::process::ExitCode;

use poly::advanced::equiv::{self, Relation};
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

/// The relation in words, with the permutation and scaling when there are.
pub(crate) fn describe(r: &Relation, a: &poly::Method, b: &poly::Method) -> String {
    let slot = |m: &poly::Method, k: usize| {
        m.slots()
            .get(k)
            .map(|&(v, l)| m.operand_name(poly::advanced::Operand::Start { var: v, lag: l }))
            .unwrap_or_else(|| format!("slot {k}"))
    };
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
        Relation::SameCharpoly => {
            "the same characteristic polynomial, not similar by a permutation or scaling".to_owned()
        }
        Relation::Different => "different characteristic polynomials".to_owned(),
    }
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let a = LoadedMethod::load(&args.a)?;
    let b = LoadedMethod::load(&args.b)?;
    let (da, db) = (a.derivation()?, b.derivation()?);
    let (ma, mb) = (&da.method, &db.method);
    let relation = equiv::relate(da, db);
    let reordered = equiv::reordered_updates(ma, mb);
    let words = describe(&relation, ma, mb);
    let out = match args.format {
        Format::Json => {
            let doc = json!({
                "a": ma.name(),
                "b": mb.name(),
                "relation": relation.name(),
                "description": words,
                "shares_charpoly": relation.shares_charpoly(),
                "reordered_updates": reordered,
                "charpoly_a": da.charpoly.to_string(),
                "charpoly_b": db.charpoly.to_string(),
            });
            serde_json::to_string_pretty(&doc)? + "\n"
        }
        _ => {
            let mut out = format!("{} and {}: {words}\n", ma.name(), mb.name());
            if reordered {
                out.push_str("the second program is the first with its updates reordered\n");
            }
            out.push_str(&format!("chi({}) = {}\n", ma.name(), da.charpoly));
            out.push_str(&format!("chi({}) = {}\n", mb.name(), db.charpoly));
            out
        }
    };
    super::output::emit(&out)?;
    Ok(ExitCode::SUCCESS)
}
