//! Numbers and parameters typed on the command line, read in one place.
//!
//! A number the user types is the exact decimal they wrote: `0.1` is 1/10,
//! read by the same lexer as a `.zm` file ([`poly::advanced::parse_number`]). Numeric
//! work takes its nearest `f64`, and a value no `f64` can hold (beyond
//! ±1.8e308, or a nonzero value below 4.9e-324) is refused by name instead
//! of silently becoming ∞ or 0.

use std::fmt;
use std::str::FromStr;

use num_traits::{Signed, ToPrimitive, Zero};
use poly::{Method, Q};

use crate::error::Error;

/// An exact number from the command line, with the text the user typed.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Exact {
    /// The exact value.
    pub value: Q,
    /// The text as typed (trimmed).
    pub text: String,
}

impl FromStr for Exact {
    type Err = String;

    fn from_str(s: &str) -> Result<Exact, String> {
        let text = s.trim();
        match poly::advanced::parse_number(text) {
            Ok(value) => Ok(Exact { value, text: text.to_owned() }),
            Err(e) => Err(format!("column {}: {}", e.span().col, e.message())),
        }
    }
}

impl fmt::Display for Exact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// The default budget of a long run, in state-steps (one state advanced by
/// one step): about a minute of simulation on a laptop core.
pub(crate) const DEFAULT_BUDGET: u64 = 10_000_000_000;

impl Exact {
    /// The count `n`, as if typed.
    pub(crate) fn count(n: u64) -> Exact {
        Exact { value: Q::from_integer(n.into()), text: n.to_string() }
    }

    /// The nearest `f64`, or an error naming `what` when no finite `f64`
    /// represents the value (overflow) or a nonzero value rounds to 0
    /// (underflow).
    pub(crate) fn to_f64(&self, what: &str) -> Result<f64, Error> {
        q_to_f64_checked(&self.value, &format!("{what} {}", self.text))
    }

    /// The value as a count: a non-negative integer that fits in `u64`.
    pub(crate) fn to_count(&self, what: &str) -> Result<u64, Error> {
        if !self.value.is_integer() || self.value.is_negative() {
            return Err(Error::usage(format!(
                "{what} {}: expected a non-negative whole number",
                self.text
            )));
        }
        self.value.to_integer().to_u64().ok_or_else(|| {
            Error::usage(format!("{what} {}: too large: expected at most {}", self.text, u64::MAX))
        })
    }
}

/// The nearest `f64` to `q`, or an error naming `what` when `q` is beyond
/// the finite `f64` range or is nonzero and rounds to zero.
pub(crate) fn q_to_f64_checked(q: &Q, what: &str) -> Result<f64, Error> {
    let x = q.to_f64().unwrap_or(f64::INFINITY);
    if !x.is_finite() {
        return Err(Error::usage(format!(
            "{what}: beyond the range of f64 (about ±1.8e308): f64 cannot represent it"
        )));
    }
    if x == 0.0 && !q.is_zero() {
        return Err(Error::usage(format!(
            "{what}: below the smallest positive f64 (about 4.9e-324): f64 cannot represent it"
        )));
    }
    Ok(x)
}

/// `--param NAME=VALUE`: a parameter's exact value.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ParamArg {
    /// The parameter's name.
    pub name: String,
    /// Its value.
    pub value: Exact,
}

impl FromStr for ParamArg {
    type Err = String;

    fn from_str(s: &str) -> Result<ParamArg, String> {
        let Some((name, value)) = s.split_once('=') else {
            return Err("expected NAME=VALUE, e.g. D=0.3 or D=1/2".into());
        };
        let name = name.trim();
        if name.is_empty() {
            return Err("expected a parameter name before `=`".into());
        }
        if !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            return Err(format!(
                "`{}` is not a parameter name: expected letters, digits and `_`",
                poly::advanced::show_invisible(name)
            ));
        }
        if name == "Phi" {
            return Err(
                "Phi is the step size, not a --param (verify takes it as --phi; stability sweeps it)"
                    .into(),
            );
        }
        let value: Exact = value.parse().map_err(|e| format!("the value after `=`: {e}"))?;
        Ok(ParamArg { name: name.to_owned(), value })
    }
}

/// Checks that every `--param` names a parameter that one of `methods`
/// declares, and that no parameter is given twice.
pub(crate) fn check_declared(params: &[ParamArg], methods: &[&Method]) -> Result<(), Error> {
    for (k, p) in params.iter().enumerate() {
        if params[..k].iter().any(|q| q.name == p.name) {
            return Err(Error::usage(format!("--param {}: given twice", p.name)));
        }
        let declared = methods.iter().any(|m| m.params().iter().any(|s| s.name() == p.name));
        if !declared {
            let mut known: Vec<&str> = methods
                .iter()
                .flat_map(|m| m.params().iter().map(|s| s.name()))
                .filter(|n| *n != "Phi")
                .collect();
            known.sort_unstable();
            known.dedup();
            let declared = if known.is_empty() { "none".to_owned() } else { known.join(", ") };
            return Err(Error::usage(match methods {
                [m] => format!(
                    "--param {}={}: method {} has no parameter {} (declared: {declared})",
                    p.name,
                    p.value,
                    m.name(),
                    p.name
                ),
                _ => format!(
                    "--param {}={}: none of the methods declares a parameter {} \
                     (declared: {declared})",
                    p.name, p.value, p.name
                ),
            }));
        }
    }
    Ok(())
}

/// Checks that every `--param` names a parameter that a tableau among the
/// methods declared (`taken`): for the commands that bind only a tableau's
/// parameters (`zcheck order`, `derive`, `from-tableau`).
pub(crate) fn check_taken<'a>(
    params: &[ParamArg],
    taken: impl IntoIterator<Item = &'a String>,
) -> Result<(), Error> {
    check_taken_then(params, taken, "; a program's parameters stay symbolic in this command")
}

/// [`check_taken`], with `then` after the list of declared names in the
/// error (what the command does with a program's parameters).
pub(crate) fn check_taken_then<'a>(
    params: &[ParamArg],
    taken: impl IntoIterator<Item = &'a String>,
    then: &str,
) -> Result<(), Error> {
    let taken: Vec<&String> = taken.into_iter().collect();
    for (k, p) in params.iter().enumerate() {
        if params[..k].iter().any(|q| q.name == p.name) {
            return Err(Error::usage(format!("--param {}: given twice", p.name)));
        }
        if !taken.contains(&&p.name) {
            let listed: Vec<&str> = taken.iter().map(|s| s.as_str()).collect();
            let listed = if listed.is_empty() { "none".to_owned() } else { listed.join(", ") };
            return Err(Error::usage(format!(
                "--param {}={}: no tableau here declares a parameter {} (declared in `params`: \
                 {listed}){then}",
                p.name, p.value, p.name
            )));
        }
    }
    Ok(())
}

/// An `f64` for a table: plain decimal between 1e-4 and 1e16, otherwise in
/// exponent form (never a 309-digit integer).
pub(crate) fn show_f64(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// [`show_f64`] with `digits` digits after the point (in either form).
pub(crate) fn show_f64_digits(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e16).contains(&x.abs()) {
        format!("{x:.digits$}")
    } else {
        format!("{x:.digits$e}")
    }
}

/// Parses `NAME=VALUE` with an exact VALUE into its parts.
pub(crate) fn parse_param(s: &str) -> Result<(String, poly::Q), Error> {
    let p: ParamArg = s.parse().map_err(|e: String| Error::usage(format!("--param {s}: {e}")))?;
    Ok((p.name, p.value.value))
}
