//! Partitioned Runge–Kutta pairs and splittings as input, for the
//! partitioned system q' = f(p), p' = g(q) (`zcheck order`).
//!
//! A pair holds two tableaux, `[q]` integrating q and `[p]` integrating p
//! (Hairer–Lubich–Wanner's (a, b) and (â, b̂)), each with `A`, `b` and an
//! optional `c`, entries as in a Butcher tableau ([`crate::tableau`]):
//!
//! ```toml
//! name = "lobatto_iiia_iiib_2"   # Störmer–Verlet
//! [q]
//! A = [[0, 0], ["1/2", "1/2"]]
//! b = ["1/2", "1/2"]
//! [p]
//! A = [["1/2", 0], ["1/2", 0]]
//! b = ["1/2", "1/2"]
//! ```
//!
//! A splitting lists the coefficients of its flows: the step is
//! drift(a₁h) kick(b₁h) … drift(a_s h) kick(b_s h), drift q += a h f(p),
//! kick p += b h g(q); a zero coefficient is allowed:
//!
//! ```toml
//! drift = ["1/2", "1/2"]   # Strang: drift h/2, kick h, drift h/2
//! kick = [1, 0]
//! ```
//!
//! The meaning is `poly`'s (`poly::advanced::order`); this module reads the
//! files and blames every mistake on its line and column.

use poly::advanced::tableau::{self as exact, Exact};
use serde::Deserialize;
use toml::Spanned;

use crate::error::{line_col, Error};
use crate::tableau::{entry_list, method_name, read_parts, RawList, MAX_STAGES};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTable {
    #[serde(rename = "A")]
    a: Spanned<Vec<Spanned<Vec<Spanned<toml::Value>>>>>,
    b: RawList,
    c: Option<RawList>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPair {
    name: Option<Spanned<String>>,
    q: Option<Spanned<RawTable>>,
    p: Option<Spanned<RawTable>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSplitting {
    name: Option<Spanned<String>>,
    drift: Option<RawList>,
    kick: Option<RawList>,
}

/// A partitioned Runge–Kutta pair read exactly from a file.
#[derive(Clone, Debug)]
pub(crate) struct Partitioned {
    pub(crate) name: String,
    /// `[q]`: integrates q.
    pub(crate) q: exact::Tableau,
    /// `[p]`: integrates p.
    pub(crate) p: exact::Tableau,
    pub(crate) decimal_digits: usize,
    pub(crate) warnings: Vec<String>,
}

/// A splitting read exactly from a file.
#[derive(Clone, Debug)]
pub(crate) struct Splitting {
    pub(crate) name: String,
    pub(crate) drift: Vec<Exact>,
    pub(crate) kick: Vec<Exact>,
    pub(crate) decimal_digits: usize,
    pub(crate) warnings: Vec<String>,
}

/// Whether a coefficient file holds a partitioned pair (a `[q]` or `[p]`
/// table).
pub(crate) fn is_partitioned(text: &str) -> bool {
    toml::from_str::<toml::Table>(text).is_ok_and(|t| t.contains_key("q") || t.contains_key("p"))
}

/// Whether a coefficient file holds a splitting (`drift` or `kick`).
pub(crate) fn is_splitting(text: &str) -> bool {
    toml::from_str::<toml::Table>(text)
        .is_ok_and(|t| t.contains_key("drift") || t.contains_key("kick"))
}

fn toml_error(path: &str, text: &str, e: &toml::de::Error) -> Error {
    let (line, col) = line_col(text, e.span().map_or(0, |s| s.start));
    Error::file(path, line, col, e.message().trim_end_matches('\n').replace('\n', "; ").as_str())
}

/// The line and column of a table's header `[name]`, else of `span`.
fn header(text: &str, name: &str, span: std::ops::Range<usize>) -> (usize, usize) {
    let at = text
        .match_indices(&format!("[{name}]"))
        .map(|(i, _)| i)
        .find(|&i| text[..i].rsplit('\n').next().is_some_and(|l| l.trim().is_empty()))
        .unwrap_or(span.start);
    line_col(text, at)
}

impl Partitioned {
    /// Parses the text of a pair file; `stem` names the method when the
    /// file has no `name`.
    pub(crate) fn parse(path: &str, stem: &str, text: &str) -> Result<Partitioned, Error> {
        let raw: RawPair = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
        let (q, p) = match (&raw.q, &raw.p) {
            (Some(q), Some(p)) => (q, p),
            (Some(one), None) | (None, Some(one)) => {
                let (has, lacks) = if raw.q.is_some() { ("q", "p") } else { ("p", "q") };
                let (line, col) = header(text, has, one.span());
                return Err(Error::file(
                    path,
                    line,
                    col,
                    &format!(
                        "[{has}] without [{lacks}]: expected both tables of a partitioned pair, \
                         [q] (A, b, c) integrating q and [p] integrating p, for q' = f(p), \
                         p' = g(q)"
                    ),
                ));
            }
            (None, None) => unreachable!("is_partitioned: a [q] or [p] table"),
        };
        let mut warnings = Vec::new();
        let mut digits = 0;
        let mut table = |t: &Spanned<RawTable>, prefix: &str| {
            let t = t.get_ref();
            read_parts(path, text, prefix, (&t.a, &t.b, t.c.as_ref()), &mut warnings, &mut digits)
        };
        let (qa, qb, qc) = table(q, "q.")?;
        let (pa, pb, pc) = table(p, "p.")?;
        if pa.len() != qa.len() {
            let (line, col) = header(text, "p", p.span());
            return Err(Error::file(
                path,
                line,
                col,
                &format!(
                    "[p] has {} stages and [q] {}: expected the same number (stage i of both \
                     tables is one stage of the pair)",
                    pa.len(),
                    qa.len()
                ),
            ));
        }
        let name = method_name(path, text, raw.name.as_ref(), stem)?;
        let made = |which: &str, a, b, c, span| {
            exact::Tableau::new(&format!("{name}_{which}"), a, b, c).map_err(|e: poly::Error| {
                let (line, col) = header(text, which, span);
                Error::file(path, line, col, e.message())
            })
        };
        let q = made("q", qa, qb, qc, q.span())?;
        let p = made("p", pa, pb, pc, p.span())?;
        Ok(Partitioned { name, q, p, decimal_digits: digits, warnings })
    }
}

impl Splitting {
    /// Parses the text of a splitting file; `stem` names the method when
    /// the file has no `name`.
    pub(crate) fn parse(path: &str, stem: &str, text: &str) -> Result<Splitting, Error> {
        let raw: RawSplitting = toml::from_str(text).map_err(|e| toml_error(path, text, &e))?;
        let (Some(drift), Some(kick)) = (&raw.drift, &raw.kick) else {
            let missing = if raw.drift.is_none() { "drift" } else { "kick" };
            return Err(Error::file(
                path,
                1,
                1,
                &format!(
                    "no `{missing}`: expected both `drift = [...]` and `kick = [...]`, the \
                     coefficients of drift(a h) kick(b h), one pair per flow"
                ),
            ));
        };
        let (nd, nk) = (drift.get_ref().len(), kick.get_ref().len());
        let at = |span: std::ops::Range<usize>, m: String| {
            let (line, col) = line_col(text, span.start);
            Error::file(path, line, col, &m)
        };
        if nd != nk {
            return Err(at(
                kick.span(),
                format!(
                    "kick has {nk} coefficients and drift {nd}: expected the same number, one \
                     drift and one kick per flow (write 0 for a flow that is not there)"
                ),
            ));
        }
        if nd == 0 || nd > MAX_STAGES {
            return Err(at(
                drift.span(),
                format!("drift has {nd} coefficients: expected 1 to {MAX_STAGES}"),
            ));
        }
        let mut warnings = Vec::new();
        let mut digits = 0;
        let d = entry_list(path, text, drift, "drift", None, &mut warnings, &mut digits)?;
        let k = entry_list(path, text, kick, "kick", None, &mut warnings, &mut digits)?;
        let name = method_name(path, text, raw.name.as_ref(), stem)?;
        Ok(Splitting { name, drift: d, kick: k, decimal_digits: digits, warnings })
    }
}
