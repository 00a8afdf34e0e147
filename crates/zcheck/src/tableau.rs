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

use poly::advanced::tableau::{self as exact, method_ident, Exact};
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

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    name: Option<Spanned<String>>,
    #[serde(rename = "A")]
    a: Spanned<Vec<Spanned<Vec<Spanned<toml::Value>>>>>,
    b: Spanned<Vec<Spanned<toml::Value>>>,
    c: Option<Spanned<Vec<Spanned<toml::Value>>>>,
}

/// A Butcher tableau read exactly from a file.
#[derive(Clone, Debug)]
pub struct Tableau {
    source: String,
    tableau: exact::Tableau,
    warnings: Vec<String>,
}

impl Tableau {
    /// Reads a tableau file (at most [`check::load::MAX_FILE_BYTES`]).
    pub fn load(path: &Path) -> Result<Tableau, Error> {
        let (shown, stem, text) = read_file(path)?;
        Tableau::parse(&shown, &stem, &text)
    }

    /// Parses the text of a tableau file; `stem` names the method when the
    /// file has no `name`.
    pub fn parse(path: &str, stem: &str, text: &str) -> Result<Tableau, Error> {
        let err = |span: Option<Range<usize>>, message: String| {
            let (line, col) = line_col(text, span.map_or(0, |s| s.start));
            Error::file(path, line, col, &message)
        };
        let raw: Raw = toml::from_str(text).map_err(|e| {
            err(e.span(), e.message().trim_end_matches('\n').replace('\n', "; ").to_string())
        })?;
        let s = raw.a.get_ref().len();
        if s == 0 || s > MAX_STAGES {
            return Err(err(
                Some(raw.a.span()),
                format!("A has {s} rows: expected 1 to {MAX_STAGES} stages"),
            ));
        }
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
        }
        if raw.b.get_ref().len() != s {
            return Err(err(
                Some(raw.b.span()),
                format!("b has {} entries: expected {s}, one per stage", raw.b.get_ref().len()),
            ));
        }
        if let Some(c) = &raw.c {
            if c.get_ref().len() != s {
                return Err(err(
                    Some(c.span()),
                    format!("c has {} entries: expected {s}, one per stage", c.get_ref().len()),
                ));
            }
        }
        let mut warnings = Vec::new();
        let mut entry = |v: &Spanned<toml::Value>, what: String| {
            warnings.extend(entry_hint(path, text, v, &what));
            exact_entry(path, text, v, &what)
        };
        let mut a = Vec::with_capacity(s);
        for (i, row) in raw.a.get_ref().iter().enumerate() {
            let mut r = Vec::with_capacity(s);
            for (j, v) in row.get_ref().iter().enumerate() {
                r.push(entry(v, format!("A[{}][{}]", i + 1, j + 1))?);
            }
            a.push(r);
        }
        let mut b = Vec::with_capacity(s);
        for (i, v) in raw.b.get_ref().iter().enumerate() {
            b.push(entry(v, format!("b[{}]", i + 1))?);
        }
        let c = match &raw.c {
            Some(c) => Some(
                c.get_ref()
                    .iter()
                    .enumerate()
                    .map(|(i, v)| entry(v, format!("c[{}]", i + 1)))
                    .collect::<Result<Vec<_>, _>>()?,
            ),
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
        Ok(Tableau { source: path.to_owned(), tableau, warnings })
    }

    /// What the file says that it probably does not mean, located.
    pub(crate) fn warnings(&self) -> &[String] {
        &self.warnings
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
