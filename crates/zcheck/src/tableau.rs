//! Butcher tableaux as input: a TOML file with `A`, `b` (and `c`) becomes
//! the `.zm` program of the Runge–Kutta method applied to the oscillator
//! (or to the damped oscillator), so a numerical analyst starts from the
//! tableau they know instead of writing four lines per stage by hand.
//!
//! ```toml
//! name = "gauss_legendre_2"                 # optional: the file's stem
//! A = [["1/4", "1/4 - sqrt(3)/6"],
//!      ["1/4 + sqrt(3)/6", "1/4"]]
//! b = ["1/2", "1/2"]
//! c = ["1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6"]  # optional, checked
//! ```
//!
//! An optional `bhat` (one entry per stage) makes the tableau an embedded
//! pair for `zcheck order`; the other commands read `A`, `b` and `c`.
//!
//! A family of tableaux names its parameters in `params`, and its entries
//! are expressions in them (numbers, names, `+ - * / ^`, brackets):
//!
//! ```toml
//! params = ["c"]
//! A = [[0, 0], ["c", 0]]
//! b = ["1 - 1/(2*c)", "1/(2*c)"]
//! ```
//!
//! Every command reads it with the values given by `--param c=1`
//! (`Tableau::parse_bound`, once, as the file is loaded: each value is
//! substituted into the entries, which are then read exactly as written
//! numbers are); `zcheck design` reads it with some parameters free
//! (`family`, poly's `ParamTableau`).
//!
//! The meaning of a tableau is `poly`'s (`poly::advanced::tableau`): this
//! module reads the TOML file and blames every mistake on its line and
//! column.
//!
//! Every entry is exact: an integer, or a string holding an exact number or
//! a constant expression in `+ - * / ^ ( )` with `sqrt(N)`, `cbrt(N)` and
//! `root(K, N)` for positive integers N, or a TOML float, read as the
//! decimal written (`0.1` is 1/10: the shortest decimal that gives the same
//! float back). Each entry is checked by the `.zm` parser
//! itself, so division by an expression that is exactly zero is refused
//! exactly, and every mistake is reported at the entry's line and column.
//!
//! The program: stage slopes `k{i}v`, `k{i}y` of the test equation
//! `v' = −ω y` (damped: `v' = −ω(2D v + y)`), `y' = ω v`, with
//! `k_i = f(x + Φ Σ_j a_ij k_j)` and `x ← x + Φ Σ_i b_i k_i`. A strictly
//! lower triangular `A` gives an explicit program of ordinary temporaries;
//! any other `A` (diagonally or fully implicit) declares every stage an
//! `unknown`, one linear system solved exactly.

use std::ops::Range;
use std::path::Path;

use poly::advanced::design::ParamTableau;
use poly::advanced::tableau::{self as exact, method_ident, Exact};
use poly::Q;
use serde::Deserialize;
use toml::Spanned;

pub(crate) use poly::advanced::tableau::MAX_STAGES;

use crate::error::{line_col, Error};

/// Reads a coefficient file (a tableau or a multistep method, at most
/// [`check::load::MAX_FILE_BYTES`]): the path as shown, the file's stem, and
/// its text.
pub(crate) fn read_file(path: &Path) -> Result<(String, String, String), Error> {
    let shown = path.display().to_string();
    let fail = |message: String| Error::file(&shown, 1, 1, &message);
    let meta = std::fs::metadata(path).map_err(|e| fail(format!("cannot read: {e}")))?;
    if meta.is_dir() {
        return Err(fail(
            "is a directory: expected a .toml file (a Butcher tableau or a multistep method)"
                .to_owned(),
        ));
    }
    if meta.len() > check::load::MAX_FILE_BYTES {
        return Err(fail(format!(
            "file too large: expected at most {} MiB",
            check::load::MAX_FILE_BYTES >> 20
        )));
    }
    let bytes = std::fs::read(path).map_err(|e| fail(format!("cannot read: {e}")))?;
    let text = match String::from_utf8(bytes) {
        Ok(t) => t,
        Err(e) => {
            let good = e.utf8_error().valid_up_to();
            let text = String::from_utf8_lossy(&e.as_bytes()[..good]).into_owned();
            let (line, col) = line_col(&text, good);
            return Err(Error::file(
                &shown,
                line,
                col,
                "invalid UTF-8: expected a UTF-8 text file",
            ));
        }
    };
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("method").to_owned();
    Ok((shown, stem, text))
}

/// One exact coefficient from a TOML value, blamed on its location: an
/// integer, a string holding an exact number or constant expression, or a
/// TOML float read as the decimal the user wrote (the shortest decimal that
/// gives the same float back, so `0.1` is 1/10).
pub(crate) fn exact_entry(
    path: &str,
    text: &str,
    v: &Spanned<toml::Value>,
    what: &str,
) -> Result<Exact, Error> {
    let at = |m: String| {
        let (line, col) = line_col(text, v.span().start);
        Error::file(path, line, col, &format!("{what}: {m}"))
    };
    let entry = match v.get_ref() {
        toml::Value::Integer(i) => i.to_string(),
        toml::Value::String(s) => s.clone(),
        toml::Value::Float(f) if f.is_finite() => format!("{f}"),
        toml::Value::Float(f) => {
            return Err(at(format!("{f} is not a finite number: expected an exact coefficient")))
        }
        other => {
            return Err(at(format!(
                "expected an exact number (an integer, a decimal, or a string such as \"1/6\" or \
                 \"1/4 - sqrt(3)/6\"), found a {}",
                other.type_str()
            )))
        }
    };
    Exact::parse(&entry).map_err(|e| at(e.message().to_owned()))
}

/// The warning for an entry written as a long decimal that is within 1e-12
/// of a simple closed form (`0.3333333333333333` for 1/3), at the entry.
pub(crate) fn entry_hint(
    path: &str,
    text: &str,
    v: &Spanned<toml::Value>,
    what: &str,
) -> Option<String> {
    let decimal = match v.get_ref() {
        toml::Value::Float(f) if f.is_finite() => format!("{f}"),
        toml::Value::String(s) => s.trim().to_owned(),
        _ => return None,
    };
    let hint = crate::warn::closed_form_hint(&decimal)?;
    let (line, col) = line_col(text, v.span().start);
    Some(format!(
        "{path}:{line}:{col}: {what} = {decimal} is within 1e-12 of {hint}: write \"{hint}\" if that is meant (the analysis uses the decimal as written)"
    ))
}

/// The method's name in a coefficient file: its `name`, which must be a
/// `.zm` identifier (blamed on its location), else the file's stem made one.
pub(crate) fn method_name(
    path: &str,
    text: &str,
    name: Option<&Spanned<String>>,
    stem: &str,
) -> Result<String, Error> {
    let Some(n) = name else {
        return Ok(method_ident(stem));
    };
    let id = method_ident(n.get_ref());
    if id != *n.get_ref() {
        let (line, col) = line_col(text, n.span().start);
        return Err(Error::file(
            path,
            line,
            col,
            &format!("name = {:?}: expected letters, digits and `_` (such as {id:?})", n.get_ref()),
        ));
    }
    Ok(id)
}

/// Whether a coefficient file holds a linear multistep method (`alpha`,
/// `beta`) rather than a Butcher tableau.
pub(crate) fn is_multistep(text: &str) -> bool {
    toml::from_str::<toml::Table>(text)
        .is_ok_and(|t| t.contains_key("alpha") || t.contains_key("beta"))
}

/// A TOML list of entries, with its location.
pub(crate) type RawList = Spanned<Vec<Spanned<toml::Value>>>;

/// `A`, `b` and `c` of one tableau as TOML, with their locations.
pub(crate) type RawParts<'a> =
    (&'a Spanned<Vec<Spanned<Vec<Spanned<toml::Value>>>>>, &'a RawList, Option<&'a RawList>);

/// A tableau's exact `A`, `b` and optional `c`.
pub(crate) type Parts = (Vec<Vec<Exact>>, Vec<Exact>, Option<Vec<Exact>>);

/// A tableau's `A`, `b` and optional `c`, shapes checked and entries read
/// exactly, each mistake blamed on its location; `prefix` names the table
/// in messages (`q.` for `[q]` of a partitioned pair).
pub(crate) fn read_parts(
    path: &str,
    text: &str,
    prefix: &str,
    (raw_a, raw_b, raw_c): RawParts<'_>,
    warnings: &mut Vec<String>,
    digits: &mut usize,
) -> Result<Parts, Error> {
    let err = |span: Range<usize>, message: String| {
        let (line, col) = line_col(text, span.start);
        Error::file(path, line, col, &message)
    };
    let s = raw_a.get_ref().len();
    if s == 0 || s > MAX_STAGES {
        return Err(err(
            raw_a.span(),
            format!("{prefix}A has {s} rows: expected 1 to {MAX_STAGES} stages"),
        ));
    }
    for (i, row) in raw_a.get_ref().iter().enumerate() {
        if row.get_ref().len() != s {
            return Err(err(
                row.span(),
                format!(
                    "row {} of {prefix}A has {} entries: expected {s} (A is square, one row per \
                     stage)",
                    i + 1,
                    row.get_ref().len()
                ),
            ));
        }
    }
    let mut a = Vec::with_capacity(s);
    for (i, row) in raw_a.get_ref().iter().enumerate() {
        let mut r = Vec::with_capacity(s);
        for (j, v) in row.get_ref().iter().enumerate() {
            let what = format!("{prefix}A[{}][{}]", i + 1, j + 1);
            warnings.extend(entry_hint(path, text, v, &what));
            *digits = (*digits).max(decimal_digits(v.get_ref()));
            r.push(exact_entry(path, text, v, &what)?);
        }
        a.push(r);
    }
    let b = entry_list(path, text, raw_b, &format!("{prefix}b"), Some(s), warnings, digits)?;
    let c = match raw_c {
        Some(c) => {
            Some(entry_list(path, text, c, &format!("{prefix}c"), Some(s), warnings, digits)?)
        }
        None => None,
    };
    Ok((a, b, c))
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    name: Option<Spanned<String>>,
    params: Option<Spanned<Vec<Spanned<String>>>>,
    #[serde(rename = "A")]
    a: Spanned<Vec<Spanned<Vec<Spanned<toml::Value>>>>>,
    b: Spanned<Vec<Spanned<toml::Value>>>,
    c: Option<Spanned<Vec<Spanned<toml::Value>>>>,
    bhat: Option<Spanned<Vec<Spanned<toml::Value>>>>,
}

/// A Butcher tableau read exactly from a file.
#[derive(Clone, Debug)]
pub struct Tableau {
    source: String,
    tableau: exact::Tableau,
    bhat: Option<Vec<Exact>>,
    decimal_digits: usize,
    warnings: Vec<String>,
    /// The values of the parameters the file declares (`params`), bound.
    bound: Vec<(String, Q)>,
}

/// Names a tableau's parameter may not take: the variables of the programs
/// made from it and the functions of an entry.
const RESERVED: [&str; 6] = ["w", "z", "Phi", "sqrt", "cbrt", "root"];

/// The parameters a tableau file declares (`params = ["c"]`), each checked
/// (a name of letters, digits and `_`, not reserved, declared once), with
/// the span of its declaration.
fn declared_params(
    path: &str,
    text: &str,
    list: &Spanned<Vec<Spanned<String>>>,
) -> Result<Vec<(String, Range<usize>)>, Error> {
    let mut out: Vec<(String, Range<usize>)> = Vec::new();
    for p in list.get_ref() {
        let name = p.get_ref().trim();
        let at = |m: String| {
            let (line, col) = line_col(text, p.span().start);
            Error::file(path, line, col, &m)
        };
        let ident = name.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if !ident {
            return Err(at(format!(
                "params: {:?} is not a parameter name: expected letters, digits and `_`, starting \
                 with a letter",
                p.get_ref()
            )));
        }
        if RESERVED.contains(&name) {
            return Err(at(format!(
                "params: {name} is reserved (w, z and Phi are the programs' variables; sqrt, cbrt \
                 and root are functions): choose another name"
            )));
        }
        if out.iter().any(|(n, _)| n == name) {
            return Err(at(format!("params: {name} is declared twice")));
        }
        out.push((name.to_owned(), p.span()));
    }
    Ok(out)
}

/// An entry's text with each name of `values` replaced by its value in
/// brackets (`1/(2*c)` with c = 1/2 is `1/(2*(1/2))`); numbers, functions
/// and other names are left as written.
fn substitute(text: &str, values: &[(String, Q)]) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < chars.len() {
        let start = i;
        if chars[i].is_alphabetic() || chars[i] == '_' {
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            match values.iter().find(|(n, _)| *n == word) {
                Some((_, v)) => out.push_str(&format!("({v})")),
                None => out.push_str(&word),
            }
        } else if chars[i].is_ascii_digit() || chars[i] == '.' {
            // A number with its exponent letter (`1e5`) is no name.
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '.') {
                i += 1;
            }
            out.extend(&chars[start..i]);
        } else {
            out.push(chars[i]);
            i += 1;
        }
    }
    out
}

/// Each string entry of `list` with `values` substituted.
fn bind_list(list: &mut RawList, values: &[(String, Q)]) {
    for v in list.get_mut() {
        if let toml::Value::String(s) = v.get_mut() {
            *s = substitute(s, values);
        }
    }
}

/// An entry's text, as a tableau with parameters reads it: an integer, a
/// finite float, or a string.
fn entry_text(
    path: &str,
    text: &str,
    v: &Spanned<toml::Value>,
    what: &str,
) -> Result<String, Error> {
    match v.get_ref() {
        toml::Value::Integer(i) => Ok(i.to_string()),
        toml::Value::Float(f) if f.is_finite() => Ok(format!("{f}")),
        toml::Value::String(s) => Ok(s.clone()),
        other => {
            let (line, col) = line_col(text, v.span().start);
            Err(Error::file(
                path,
                line,
                col,
                &format!(
                    "{what}: expected an exact number or an expression in the parameters (such \
                     as \"1/(2*c)\"), found a {}",
                    other.type_str()
                ),
            ))
        }
    }
}

/// A tableau file whose entries name parameters, as `zcheck design` reads
/// it: poly's [`ParamTableau`] over every declared parameter, with the
/// values in `bound` substituted (each must be declared) and the others
/// free. Every mistake is blamed on its line and column.
pub(crate) fn family(
    path: &str,
    stem: &str,
    text: &str,
    bound: &[(String, Q)],
) -> Result<ParamTableau, Error> {
    let err = |span: Option<Range<usize>>, message: String| {
        let (line, col) = line_col(text, span.map_or(0, |s| s.start));
        Error::file(path, line, col, &message)
    };
    let raw: Raw = toml::from_str(text).map_err(|e| {
        err(e.span(), e.message().trim_end_matches('\n').replace('\n', "; ").to_string())
    })?;
    let declared = match &raw.params {
        Some(list) => declared_params(path, text, list)?,
        None => Vec::new(),
    };
    let names: Vec<&str> = declared.iter().map(|(n, _)| n.as_str()).collect();
    for (name, _) in bound {
        if !names.contains(&name.as_str()) {
            let listed = if names.is_empty() { "none".to_owned() } else { names.join(", ") };
            return Err(Error::usage(format!(
                "--param {name}: tableau {path} has no parameter {name} (declared in its \
                 `params`: {listed})"
            )));
        }
    }
    let s = raw.a.get_ref().len();
    if s == 0 || s > MAX_STAGES {
        return Err(err(
            Some(raw.a.span()),
            format!("A has {s} rows: expected 1 to {MAX_STAGES} stages"),
        ));
    }
    let mut a = Vec::with_capacity(s);
    for (i, row) in raw.a.get_ref().iter().enumerate() {
        if row.get_ref().len() != s {
            return Err(err(
                Some(row.span()),
                format!(
                    "row {} of A has {} entries: expected {s} (A is square, one row per stage)",
                    i + 1,
                    row.get_ref().len()
                ),
            ));
        }
        let mut r = Vec::with_capacity(s);
        for (j, v) in row.get_ref().iter().enumerate() {
            r.push((format!("A[{}][{}]", i + 1, j + 1), v));
        }
        a.push(r);
    }
    if raw.b.get_ref().len() != s {
        return Err(err(
            Some(raw.b.span()),
            format!("b has {} entries: expected {s}, one per stage", raw.b.get_ref().len()),
        ));
    }
    let name = method_name(path, text, raw.name.as_ref(), stem)?;
    // Each entry read alone first, so that a mistake is blamed on it.
    let entry = |(what, v): &(String, &Spanned<toml::Value>)| -> Result<String, Error> {
        let e = substitute(&entry_text(path, text, v, what)?, bound);
        ParamTableau::new(&name, &names, &[vec![e.as_str()]], &[e.as_str()]).map_err(|e| {
            let (line, col) = line_col(text, v.span().start);
            Error::file(path, line, col, &format!("{what}: {}", e.message()))
        })?;
        Ok(e)
    };
    let a: Vec<Vec<String>> =
        a.iter().map(|row| row.iter().map(entry).collect()).collect::<Result<_, _>>()?;
    let b: Vec<String> = raw
        .b
        .get_ref()
        .iter()
        .enumerate()
        .map(|(i, v)| entry(&(format!("b[{}]", i + 1), v)))
        .collect::<Result<_, _>>()?;
    let a_ref: Vec<Vec<&str>> = a.iter().map(|r| r.iter().map(String::as_str).collect()).collect();
    let b_ref: Vec<&str> = b.iter().map(String::as_str).collect();
    ParamTableau::new(&name, &names, &a_ref, &b_ref).map_err(|e| err(None, e.message().to_owned()))
}

/// The most significant digits of a decimal literal in an entry (`0` when it
/// has none): the app knows the text, `poly`'s exact number does not, and a
/// long decimal is a float written out (`zcheck order` then reads the order
/// within a tolerance too).
pub(crate) fn decimal_digits(v: &toml::Value) -> usize {
    match v {
        toml::Value::Float(f) if f.is_finite() => decimal_digits_in(&format!("{f:e}")),
        toml::Value::String(s) => decimal_digits_in(s),
        _ => 0,
    }
}

/// [`decimal_digits`] of an entry's text.
pub(crate) fn decimal_digits_in(text: &str) -> usize {
    let mut best = 0;
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        if !(bytes[i].is_ascii_digit() || bytes[i] == b'.') {
            i += 1;
            continue;
        }
        let start = i;
        while i < bytes.len() && (bytes[i].is_ascii_digit() || bytes[i] == b'.') {
            i += 1;
        }
        let literal = &text[start..i];
        let exponent = i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E');
        if literal.contains('.') || exponent {
            let digits: String = literal.chars().filter(char::is_ascii_digit).collect();
            best = best.max(digits.trim_start_matches('0').len());
        }
        // Skip the exponent's digits: they are no significant digits.
        if exponent {
            i += 1;
            while i < bytes.len()
                && (bytes[i].is_ascii_digit() || bytes[i] == b'+' || bytes[i] == b'-')
            {
                i += 1;
            }
        }
    }
    best
}

/// A list of exact entries (`b`, `c`, `bhat`, `drift`, …) of `s` entries,
/// blamed on the list when its length is wrong and on the entry when it does
/// not read; `digits` keeps the longest decimal seen.
pub(crate) fn entry_list(
    path: &str,
    text: &str,
    list: &Spanned<Vec<Spanned<toml::Value>>>,
    what: &str,
    s: Option<usize>,
    warnings: &mut Vec<String>,
    digits: &mut usize,
) -> Result<Vec<Exact>, Error> {
    if let Some(s) = s {
        if list.get_ref().len() != s {
            let (line, col) = line_col(text, list.span().start);
            return Err(Error::file(
                path,
                line,
                col,
                &format!(
                    "{what} has {} entries: expected {s}, one per stage",
                    list.get_ref().len()
                ),
            ));
        }
    }
    list.get_ref()
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let name = format!("{what}[{}]", i + 1);
            warnings.extend(entry_hint(path, text, v, &name));
            *digits = (*digits).max(decimal_digits(v.get_ref()));
            exact_entry(path, text, v, &name)
        })
        .collect()
}

impl Tableau {
    /// Reads a tableau file (at most [`check::load::MAX_FILE_BYTES`]).
    pub fn load(path: &Path) -> Result<Tableau, Error> {
        let (shown, stem, text) = read_file(path)?;
        Tableau::parse(&shown, &stem, &text)
    }

    /// Parses the text of a tableau file; `stem` names the method when the
    /// file has no `name`. A file that declares parameters (`params`) needs
    /// their values: `Tableau::parse_bound`.
    pub fn parse(path: &str, stem: &str, text: &str) -> Result<Tableau, Error> {
        Tableau::parse_bound(path, stem, text, &[])
    }

    /// [`Tableau::parse`], with the parameters the file declares (`params =
    /// ["c"]`, entries such as `"1 - 1/(2*c)"`) bound to their values in
    /// `values` (the command's `--param NAME=VALUE`; names the file does
    /// not declare are left for the command to check). A declared
    /// parameter without a value is an error at its declaration.
    pub(crate) fn parse_bound(
        path: &str,
        stem: &str,
        text: &str,
        values: &[(String, Q)],
    ) -> Result<Tableau, Error> {
        let err = |span: Option<Range<usize>>, message: String| {
            let (line, col) = line_col(text, span.map_or(0, |s| s.start));
            Error::file(path, line, col, &message)
        };
        let mut raw: Raw = toml::from_str(text).map_err(|e| {
            err(e.span(), e.message().trim_end_matches('\n').replace('\n', "; ").to_string())
        })?;
        let mut bound = Vec::new();
        if let Some(list) = &raw.params {
            for (name, span) in declared_params(path, text, list)? {
                match values.iter().find(|(n, _)| *n == name) {
                    Some(v) => bound.push(v.clone()),
                    None => {
                        return Err(err(
                            Some(span),
                            format!(
                                "parameter {name} has no value: give it one with --param \
                                 {name}=VALUE (`zcheck design` chooses it)"
                            ),
                        ))
                    }
                }
            }
            for row in raw.a.get_mut() {
                bind_list(row, &bound);
            }
            bind_list(&mut raw.b, &bound);
            for list in [raw.c.as_mut(), raw.bhat.as_mut()].into_iter().flatten() {
                bind_list(list, &bound);
            }
        }
        let mut warnings = Vec::new();
        let mut digits = 0;
        let (a, b, c) = read_parts(
            path,
            text,
            "",
            (&raw.a, &raw.b, raw.c.as_ref()),
            &mut warnings,
            &mut digits,
        )?;
        let s = a.len();
        let bhat = match &raw.bhat {
            Some(bh) => {
                Some(entry_list(path, text, bh, "bhat", Some(s), &mut warnings, &mut digits)?)
            }
            None => None,
        };
        let name = method_name(path, text, raw.name.as_ref(), stem)?;
        // The shape and the name were checked above, with their locations.
        let tableau =
            exact::Tableau::new(&name, a, b, c).map_err(|e| err(None, e.message().to_owned()))?;
        let at = |span: Range<usize>, message: String| {
            let (line, col) = line_col(text, span.start);
            format!("{path}:{line}:{col}: {message}")
        };
        let exact_err = |e: poly::Error| err(None, e.message().to_owned());
        let sum = tableau.weights_sum().map_err(exact_err)?;
        if !sum.is_one() {
            warnings.push(at(
                raw.b.span(),
                format!(
                    "b sums to {}, not 1: the method is not consistent (not even order 1)",
                    crate::warn::value_near(&sum, &poly::Poly::one())
                ),
            ));
        }
        if let (Some(rows), Some(c)) = (tableau.c_mismatch(), &raw.c) {
            let sums = tableau.row_sums().map_err(exact_err)?;
            for &i in rows {
                warnings.push(at(
                    c.get_ref()[i - 1].span(),
                    format!(
                        "c[{i}] differs from row {i} of A, which sums to {}: expected c_i = Σ_j a_ij (the stage is evaluated at the time A gives)",
                        crate::warn::value(&sums[i - 1])
                    ),
                ));
            }
        }
        Ok(Tableau {
            source: path.to_owned(),
            tableau,
            bhat,
            decimal_digits: digits,
            warnings,
            bound,
        })
    }

    /// The values of the parameters the file declares, as bound.
    pub(crate) fn bound(&self) -> &[(String, Q)] {
        &self.bound
    }

    /// What the file says that it probably does not mean, located.
    pub(crate) fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// The exact tableau (`poly`'s).
    pub(crate) fn exact(&self) -> &exact::Tableau {
        &self.tableau
    }

    /// The embedded weights b̂ of a pair, when the file gives `bhat`.
    pub(crate) fn bhat(&self) -> Option<&[Exact]> {
        self.bhat.as_deref()
    }

    /// The most significant digits of a decimal entry ([`decimal_digits`]).
    pub(crate) fn decimal_digits(&self) -> usize {
        self.decimal_digits
    }

    /// The number of stages.
    pub fn stages(&self) -> usize {
        self.tableau.stages()
    }

    /// Whether `A` is strictly lower triangular (an explicit method).
    pub fn is_explicit(&self) -> bool {
        self.tableau.is_explicit()
    }

    /// The `.zm` program of the method on the oscillator, or on the damped
    /// oscillator (`param D`) when `damped`.
    pub fn to_zm(&self, damped: bool) -> String {
        self.tableau.to_zm(&self.source, damped)
    }

    /// The method of [`Tableau::to_zm`], parsed as the file `file` (poly's
    /// `Tableau::program`: it carries the stability function).
    pub(crate) fn program(&self, file: &str, damped: bool) -> Result<poly::Method, poly::Error> {
        self.tableau.program(file, &self.source, damped)
    }

    /// The method on y' = λy (a program in `w`), parsed as the file `file`.
    pub(crate) fn scalar_program(&self, file: &str) -> Result<poly::Method, poly::Error> {
        self.tableau.scalar_program(file, &self.source)
    }
}
