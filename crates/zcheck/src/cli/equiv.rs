//! `zcheck equiv A B`: the strongest identity between two methods (built-in
//! (the arguments and the printing; the answer is `crate::answers::equiv`)

use super::format::{Format, TEXT_JSON};
use crate::answers::equiv::*;
use crate::error::Error;
use crate::load::LoadedMethod;
use poly::advanced::equiv::{self, Change, Relation};
use serde_json::json;
use std::process::ExitCode;

/// Arguments of `zcheck equiv`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// The first method: a built-in name, a `.zm` path or a `.toml` file.
    pub a: String,
    /// The second method: a built-in name, a `.zm` path or a `.toml` file.
    pub b: String,
    /// A value for a parameter a tableau declares (`params = ["c"]`),
    /// `NAME=VALUE` (exact); repeatable. A program's parameters stay
    /// symbolic.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub params: Vec<crate::values::ParamArg>,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let values = crate::load::values_of_args(&args.params);
    let a = LoadedMethod::load_with(&args.a, &values)?;
    let b = LoadedMethod::load_with(&args.b, &values)?;
    crate::values::check_taken(&args.params, a.tableau_params().iter().chain(b.tableau_params()))?;
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
