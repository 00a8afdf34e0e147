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
//! Every entry is exact: an integer, or a string holding an exact number or
//! a constant expression in `+ - * / ^ ( )` with `sqrt(N)`, `cbrt(N)` and
//! `root(K, N)` for positive integers N (TOML floats are binary, so `0.1`
//! must be written `"0.1"`). Each entry is checked by the `.zm` parser
//! itself, so division by an expression that is exactly zero is refused
//! exactly, and every mistake is reported at the entry's line and column.
//!
//! The program: stage slopes `k{i}v`, `k{i}y` of the test equation
//! `v' = −ω y` (damped: `v' = −ω(2D v + y)`), `y' = ω v`, with
//! `k_i = f(x + Φ Σ_j a_ij k_j)` and `x ← x + Φ Σ_i b_i k_i`. A strictly
//! lower triangular `A` gives an explicit program of ordinary temporaries;
//! any other `A` (diagonally or fully implicit) declares every stage an
//! `unknown`, one linear system solved exactly.

use std::fmt::Write as _;
use std::ops::Range;
use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

/// The most stages read: beyond any published method, and a bound on the
/// size of the generated program.
pub(crate) const MAX_STAGES: usize = 64;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    name: Option<Spanned<String>>,
    #[serde(rename = "A")]
    a: Spanned<Vec<Spanned<Vec<Spanned<toml::Value>>>>>,
    b: Spanned<Vec<Spanned<toml::Value>>>,
    c: Option<Spanned<Vec<Spanned<toml::Value>>>>,
}

/// One exact entry: its `.zm` expression (radicals replaced by constant
/// names) and whether it is exactly zero.
#[derive(Clone, Debug)]
struct Entry {
    expr: String,
    zero: bool,
}

/// A Butcher tableau read exactly.
#[derive(Clone, Debug)]
pub struct Tableau {
    name: String,
    source: String,
    a: Vec<Vec<Entry>>,
    b: Vec<Entry>,
    /// `Some(rows)` when `c` was given and differs from A's row sums there.
    c_mismatch: Option<Vec<usize>>,
    c_given: bool,
    /// `(name, radical)`: `("sqrt_3", "sqrt(3)")`, in order of appearance.
    constants: Vec<(String, String)>,
}

use crate::error::{line_col, Error};

/// A name fit for a `.zm` method: letters, digits and `_`, not starting
/// with a digit.
fn method_ident(s: &str) -> String {
    let s: String =
        s.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect();
    if s.is_empty() || s.starts_with(|c: char| c.is_ascii_digit()) {
        format!("rk_{s}")
    } else {
        s
    }
}

impl Tableau {
    /// Reads a tableau file (at most [`check::load::MAX_FILE_BYTES`]).
    pub fn load(path: &Path) -> Result<Tableau, Error> {
        let shown = path.display().to_string();
        let fail = |message: String| Error::file(&shown, 1, 1, &message);
        let meta = std::fs::metadata(path).map_err(|e| fail(format!("cannot read: {e}")))?;
        if meta.is_dir() {
            return Err(fail("is a directory: expected a .toml tableau".to_owned()));
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
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("tableau");
        Tableau::parse(&shown, stem, &text)
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
        let mut constants: Vec<(String, String)> = Vec::new();
        let entry = |v: &Spanned<toml::Value>,
                     what: String,
                     constants: &mut Vec<(String, String)>|
         -> Result<Entry, Error> {
            let at = |m: String| err(Some(v.span()), format!("{what}: {m}"));
            let text = match v.get_ref() {
                toml::Value::Integer(i) => i.to_string(),
                toml::Value::String(s) => s.clone(),
                toml::Value::Float(_) => {
                    return Err(at("a TOML float is binary, not the decimal written: write it \
                                   as a string, \"0.1\", to have it exactly"
                        .to_owned()))
                }
                other => {
                    return Err(at(format!(
                        "expected an exact number (an integer, or a string such as \"1/6\" or \
                         \"1/4 - sqrt(3)/6\"), found a {}",
                        other.type_str()
                    )))
                }
            };
            let expr = replace_radicals(&text, constants).map_err(at)?;
            let zero = probe(&expr, constants).map_err(at)?;
            Ok(Entry { expr, zero })
        };
        let mut a = Vec::with_capacity(s);
        for (i, row) in raw.a.get_ref().iter().enumerate() {
            let mut r = Vec::with_capacity(s);
            for (j, v) in row.get_ref().iter().enumerate() {
                r.push(entry(v, format!("A[{}][{}]", i + 1, j + 1), &mut constants)?);
            }
            a.push(r);
        }
        let mut b = Vec::with_capacity(s);
        for (i, v) in raw.b.get_ref().iter().enumerate() {
            b.push(entry(v, format!("b[{}]", i + 1), &mut constants)?);
        }
        let mut c_mismatch = None;
        if let Some(c) = &raw.c {
            let mut rows = Vec::new();
            for (i, v) in c.get_ref().iter().enumerate() {
                let ci = entry(v, format!("c[{}]", i + 1), &mut constants)?;
                let sum: Vec<String> = a[i].iter().map(|e| format!("({})", e.expr)).collect();
                let diff = format!("({}) - ({})", ci.expr, sum.join(" + "));
                if !probe(&diff, &constants).map_err(|m| err(Some(v.span()), m))? {
                    rows.push(i + 1);
                }
            }
            c_mismatch = Some(rows);
        }
        let name = match &raw.name {
            Some(n) => {
                let id = method_ident(n.get_ref());
                if id != *n.get_ref() {
                    return Err(err(
                        Some(n.span()),
                        format!(
                            "name = {:?}: expected letters, digits and `_` (such as {id:?})",
                            n.get_ref()
                        ),
                    ));
                }
                id
            }
            None => method_ident(stem),
        };
        Ok(Tableau {
            name,
            source: path.to_owned(),
            a,
            b,
            c_given: raw.c.is_some(),
            c_mismatch,
            constants,
        })
    }

    /// The number of stages.
    pub fn stages(&self) -> usize {
        self.b.len()
    }

    /// Whether `A` is strictly lower triangular (an explicit method).
    pub fn is_explicit(&self) -> bool {
        self.a.iter().enumerate().all(|(i, row)| row[i..].iter().all(|e| e.zero))
    }

    /// The `.zm` program of the method on the oscillator, or on the damped
    /// oscillator (`param D`) when `damped`.
    pub fn to_zm(&self, damped: bool) -> String {
        let s = self.stages();
        let explicit = self.is_explicit();
        let mut out = String::new();
        let kind = if explicit {
            "explicit"
        } else if self.a.iter().enumerate().all(|(i, row)| row[i + 1..].iter().all(|e| e.zero)) {
            "diagonally implicit"
        } else {
            "fully implicit"
        };
        let w = |out: &mut String, line: String| writeln!(out, "{line}").expect("string");
        w(
            &mut out,
            format!(
                "# Generated by `zcheck from-tableau` from {}: {s} stages, {kind}.",
                self.source
            ),
        );
        w(
            &mut out,
            if damped {
                "# Test equation v' = -w0 (2 D v + y), y' = w0 v; stage slopes k{i}v, k{i}y."
                    .to_owned()
            } else {
                "# Test equation v' = -w0 y, y' = w0 v; stage slopes k{i}v, k{i}y.".to_owned()
            },
        );
        match &self.c_mismatch {
            Some(rows) if rows.is_empty() => {
                w(&mut out, "# c is A's row sums (c_i = sum_j a_ij), exactly.".to_owned())
            }
            Some(rows) => w(
                &mut out,
                format!(
                    "# c differs from A's row sums in row(s) {:?}; an autonomous equation never reads c.",
                    rows
                ),
            ),
            None if !self.c_given => {}
            None => {}
        }
        w(&mut out, format!("method {}", self.name));
        w(&mut out, "state v y".to_owned());
        if damped {
            w(&mut out, "param D".to_owned());
        }
        for (name, radical) in &self.constants {
            w(&mut out, format!("const {name} = {radical}"));
        }
        if !explicit {
            let names: Vec<String> =
                (1..=s).flat_map(|i| [format!("k{i}v"), format!("k{i}y")]).collect();
            w(&mut out, format!("unknown {}", names.join(" ")));
        }
        // Σ_j a_ij k{j}x, or None when the row is zero.
        let combo = |coefs: &[Entry], x: char| -> Option<String> {
            let terms: Vec<String> = coefs
                .iter()
                .enumerate()
                .filter(|(_, e)| !e.zero)
                .map(|(j, e)| {
                    let c = e.expr.trim();
                    let plain = c.chars().all(|ch| ch.is_ascii_digit() || ch == '/' || ch == '.');
                    match c {
                        "1" => format!("k{}{x}", j + 1),
                        _ if plain => format!("{c}*k{}{x}", j + 1),
                        _ => format!("({c})*k{}{x}", j + 1),
                    }
                })
                .collect();
            (!terms.is_empty()).then(|| terms.join(" + "))
        };
        for (i, row) in self.a.iter().enumerate() {
            let k = i + 1;
            // The stage's state: x + Φ Σ_j a_ij k_j, or x when the row is zero.
            let at = |x: char| match combo(row, x) {
                Some(c) => (format!("{x} + Phi*({c})"), true),
                None => (x.to_string(), false),
            };
            let ((vs, v_sum), (ys, y_sum)) = (at('v'), at('y'));
            let paren = |s: &str, sum: bool| if sum { format!("({s})") } else { s.to_owned() };
            if damped {
                w(&mut out, format!("k{k}v = -(2*D*{} + {ys})", paren(&vs, v_sum)));
            } else {
                w(&mut out, format!("k{k}v = -{}", paren(&ys, y_sum)));
            }
            w(&mut out, format!("k{k}y = {vs}"));
        }
        for x in ['v', 'y'] {
            match combo(&self.b, x) {
                Some(c) => w(&mut out, format!("{x} = {x} + Phi*({c})")),
                None => w(&mut out, format!("{x} = {x}")),
            }
        }
        out
    }
}

/// Replaces each `sqrt(N)`, `cbrt(N)` and `root(K, N)` by a constant name,
/// declaring it in `constants` once; refuses any other name.
fn replace_radicals(text: &str, constants: &mut Vec<(String, String)>) -> Result<String, String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if ch.is_ascii_alphabetic() || ch == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            let mut j = i;
            while j < chars.len() && chars[j] == ' ' {
                j += 1;
            }
            if !matches!(word.as_str(), "sqrt" | "cbrt" | "root") || chars.get(j) != Some(&'(') {
                return Err(format!(
                    "unexpected name `{word}` in an entry: expected numbers, + - * / ^ ( ) and \
                     sqrt(N), cbrt(N) or root(K, N)"
                ));
            }
            let close = chars[j..]
                .iter()
                .position(|&c| c == ')')
                .map(|p| j + p)
                .ok_or_else(|| format!("`{word}(` is not closed: expected `)`"))?;
            let inner: String = chars[j + 1..close].iter().collect();
            let args: Vec<&str> = inner.split(',').map(str::trim).collect();
            let positive = |a: &str| -> Result<u64, String> {
                a.parse::<u64>().ok().filter(|&n| n > 0).ok_or_else(|| {
                    format!("{word}({inner}): expected a positive integer literal, found `{a}`")
                })
            };
            let (k, n) = match (word.as_str(), args.as_slice()) {
                ("sqrt", [n]) => (2, positive(n)?),
                ("cbrt", [n]) => (3, positive(n)?),
                ("root", [k, n]) => {
                    let k = positive(k)?;
                    if k < 2 {
                        return Err(format!("root({inner}): expected a root index K >= 2"));
                    }
                    (k, positive(n)?)
                }
                _ => {
                    return Err(format!(
                        "{word}({inner}): expected {}",
                        if word == "root" { "two arguments, root(K, N)" } else { "one argument" }
                    ))
                }
            };
            let (name, radical) = match k {
                2 => (format!("sqrt_{n}"), format!("sqrt({n})")),
                3 => (format!("cbrt_{n}"), format!("cbrt({n})")),
                _ => (format!("root_{k}_{n}"), format!("root({k}, {n})")),
            };
            if !constants.iter().any(|(c, _)| *c == name) {
                constants.push((name.clone(), radical));
            }
            out.push_str(&name);
            i = close + 1;
        } else if ch.is_ascii_digit() || " \t+-*/^().".contains(ch) {
            out.push(ch);
            i += 1;
        } else {
            return Err(format!(
                "unexpected character {} in an entry: expected numbers, + - * / ^ ( ) and \
                 sqrt(N), cbrt(N) or root(K, N)",
                if ch.is_control() || !ch.is_ascii() {
                    format!("U+{:04X}", ch as u32)
                } else {
                    format!("`{ch}`")
                }
            ));
        }
    }
    if out.trim().is_empty() {
        return Err("the entry is empty: expected an exact number".to_owned());
    }
    Ok(out)
}

/// Checks one expression with the `.zm` parser (exact, constants included)
/// and says whether it is exactly zero.
fn probe(expr: &str, constants: &[(String, String)]) -> Result<bool, String> {
    let mut src = String::from("method probe\nstate v\n");
    for (name, radical) in constants {
        writeln!(src, "const {name} = {radical}").expect("string");
    }
    writeln!(src, "v = ({expr})*v").expect("string");
    let m = poly::Method::parse("entry", &src).map_err(|e| e.message().to_owned())?;
    Ok(m.assigns().last().is_none_or(|a| a.terms.is_empty()))
}
