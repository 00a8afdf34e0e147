//! Butcher tableaux as input: `A`, `b` (and `c`) of a Runge–Kutta method
//! become the `.zm` program of the method applied to the oscillator (or the
//! damped oscillator), so an analyst starts from the tableau they know.
//!
//! Every entry is exact: an integer or decimal, a fraction, or a constant
//! expression in `+ - * / ^ ( )` with `sqrt(N)`, `cbrt(N)` and `root(K, N)`
//! for positive integers N, checked by the `.zm` parser itself (division by
//! an expression that is exactly zero is refused exactly).
//!
//! The program: stage slopes `k{i}v`, `k{i}y` of the test equation
//! `v' = −ω y` (damped: `v' = −ω(2D v + y)`), `y' = ω v`, with
//! `k_i = f(x + Φ Σ_j a_ij k_j)` and `x ← x + Φ Σ_i b_i k_i`. A strictly
//! lower triangular `A` gives an explicit program of ordinary temporaries;
//! any other `A` declares every stage an `unknown`, one linear system
//! solved exactly.
//!
//! ```
//! use poly::advanced::tableau::{Exact, Tableau};
//! let e = |s: &str| Exact::parse(s);
//! let a = vec![vec![e("1/4")?, e("1/4 - sqrt(3)/6")?], vec![e("1/4 + sqrt(3)/6")?, e("1/4")?]];
//! let b = vec![e("1/2")?, e("1/2")?];
//! let t = Tableau::new("gauss_legendre_2", a, b, None)?;
//! let d = poly::derive(&t.method(false)?)?;
//! assert_eq!(d.stability(&poly::Params::new())?.stability, poly::Stability::BoundedForAllPhi);
//! # Ok::<(), poly::Error>(())
//! ```

use std::fmt::Write as _;
use std::sync::Arc;

use crate::error::{Error, ErrorKind, Span};
use crate::lang::method::{Method, StabilityFunction};
use crate::multivariate::constants as field;
use crate::{Poly, PolyMatrix, Sym};

/// The most stages read: beyond any published method, and a bound on the
/// size of the generated program.
pub const MAX_STAGES: usize = 64;

/// One exact tableau entry: its `.zm` expression (radicals replaced by
/// constant names), the radicals it names, and whether it is exactly zero.
#[derive(Clone, Debug)]
pub struct Exact {
    pub(crate) expr: String,
    pub(crate) radicals: Vec<(String, String)>,
    pub(crate) zero: bool,
    /// The value of a plain number, read once.
    pub(crate) number: Option<crate::Q>,
    /// The value of an entry with radicals, read once against its own
    /// radicals (see [`entry_value`] for when a method may use it).
    pub(crate) value: Option<Poly>,
}

impl Exact {
    /// Reads one entry. The error says what was expected; its caller knows
    /// where the entry stands (a file position, an index).
    pub fn parse(text: &str) -> Result<Exact, Error> {
        let plain = text.trim();
        if let Some((n, d)) = small_fraction(plain) {
            return Ok(Exact {
                expr: if d == 1 { n.to_string() } else { format!("{n}/{d}") },
                radicals: Vec::new(),
                zero: n == 0,
                number: Some(crate::Q::new_raw(n.into(), d.into())),
                value: None,
            });
        }
        Exact::parse_general(text)
    }

    /// [`Exact::parse`] without the quick path for small fractions (the
    /// tests' oracle for it).
    pub(crate) fn parse_general(text: &str) -> Result<Exact, Error> {
        // A plain number (`-3/8`, `0.125`, `1e-3`) needs no program to test.
        let plain = text.trim();
        let (negative, digits) = match plain.strip_prefix('-') {
            Some(rest) => (true, rest.trim_start()),
            None => (false, plain),
        };
        if let Ok(q) = crate::lang::syntax::parse_number(digits) {
            let q = if negative { -q } else { q };
            let zero = num_traits::Zero::is_zero(&q);
            return Ok(Exact {
                expr: q.to_string(),
                radicals: Vec::new(),
                zero,
                number: Some(q),
                value: None,
            });
        }
        let mut radicals = Vec::new();
        let expr = replace_radicals(text, &mut radicals).map_err(entry_error)?;
        let v = value(&expr, &radicals).map_err(entry_error)?;
        Ok(Exact { expr, radicals, zero: v.is_zero(), number: None, value: Some(v) })
    }

    /// Whether the entry is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.zero
    }
}

/// `[-]N[/D]`, N and D of at most 18 decimal digits and D non-zero (most
/// entries: NodePy's and the catalogue's), in lowest terms with D > 0, read
/// in words; `None` sends anything else (and every error) the general way.
fn small_fraction(text: &str) -> Option<(i64, i64)> {
    let (negative, rest) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text),
    };
    let word = |s: &str| -> Option<i64> {
        if s.is_empty() || s.len() > 18 || !s.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        s.parse().ok()
    };
    let (n, d) = match rest.split_once('/') {
        Some((n, d)) => (word(n)?, word(d)?),
        None => (word(rest)?, 1),
    };
    if d == 0 {
        return None;
    }
    let g = num_integer::Integer::gcd(&n, &d);
    Some((if negative { -n / g } else { n / g }, d / g))
}

pub(crate) fn entry_error(message: String) -> Error {
    Error::new(ErrorKind::BadConstant, Span::default(), message)
}

/// A Butcher tableau read exactly.
#[derive(Clone, Debug)]
pub struct Tableau {
    pub(crate) name: String,
    pub(crate) a: Vec<Vec<Exact>>,
    pub(crate) b: Vec<Exact>,
    /// `c` as given, when it was.
    c: Option<Vec<Exact>>,
    /// `Some(rows)` when `c` was given: the rows where it differs from A's
    /// row sums.
    pub(crate) c_mismatch: Option<Vec<usize>>,
    /// `(name, radical)`: `("sqrt_3", "sqrt(3)")`, in order of appearance.
    pub(crate) constants: Vec<(String, String)>,
    /// R = P/Q, computed once for both programs.
    stability_function: std::sync::OnceLock<StabilityFunction>,
}

impl Tableau {
    /// A tableau from its entries: `A` square with one row per stage (1 to
    /// [`MAX_STAGES`]), `b` and `c` one entry per stage. `name` must be a
    /// `.zm` identifier (letters, digits and `_`).
    pub fn new(
        name: &str,
        a: Vec<Vec<Exact>>,
        b: Vec<Exact>,
        c: Option<Vec<Exact>>,
    ) -> Result<Tableau, Error> {
        let shape = |m: String| Error::new(ErrorKind::Syntax, Span::default(), m);
        let s = a.len();
        if s == 0 || s > MAX_STAGES {
            return Err(shape(format!("A has {s} rows: expected 1 to {MAX_STAGES} stages")));
        }
        for (i, row) in a.iter().enumerate() {
            if row.len() != s {
                return Err(shape(format!(
                    "row {} of A has {} entries: expected {s} (A is square, one row per stage)",
                    i + 1,
                    row.len()
                )));
            }
        }
        if b.len() != s {
            return Err(shape(format!("b has {} entries: expected {s}, one per stage", b.len())));
        }
        if let Some(c) = &c {
            if c.len() != s {
                return Err(shape(format!(
                    "c has {} entries: expected {s}, one per stage",
                    c.len()
                )));
            }
        }
        let id = method_ident(name);
        if id != name {
            return Err(shape(format!(
                "name {name:?}: expected letters, digits and `_` (such as {id:?})"
            )));
        }
        let mut constants: Vec<(String, String)> = Vec::new();
        for e in a.iter().flatten().chain(&b).chain(c.iter().flatten()) {
            for r in &e.radicals {
                if !constants.contains(r) {
                    constants.push(r.clone());
                }
            }
        }
        let c_mismatch = match &c {
            Some(c) => {
                let mut rows = Vec::new();
                for (i, ci) in c.iter().enumerate() {
                    // Plain numbers compare without a program.
                    if let (Some(ci), Some(row)) =
                        (plain(ci), a[i].iter().map(plain).collect::<Option<Vec<_>>>())
                    {
                        if row.into_iter().fold(crate::Q::from_integer(0.into()), |s, x| s + x)
                            != ci
                        {
                            rows.push(i + 1);
                        }
                        continue;
                    }
                    let sum: Vec<String> = a[i].iter().map(|e| format!("({})", e.expr)).collect();
                    let diff = format!("({}) - ({})", ci.expr, sum.join(" + "));
                    if !probe(&diff, &constants).map_err(entry_error)? {
                        rows.push(i + 1);
                    }
                }
                Some(rows)
            }
            None => None,
        };
        Ok(Tableau {
            name: id,
            a,
            b,
            c,
            c_mismatch,
            constants,
            stability_function: std::sync::OnceLock::new(),
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

    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The entries as read: `A` (row by row), `b`, and `c` when it was
    /// given.
    pub fn entries(&self) -> (&[Vec<Exact>], &[Exact], Option<&[Exact]>) {
        (&self.a, &self.b, self.c.as_deref())
    }

    /// Σ b_i, exactly: 1 for a consistent method (order at least 1).
    pub fn weights_sum(&self) -> Result<Poly, Error> {
        sum_of(self.b.iter(), &self.constants)
    }

    /// The row sums of A, exactly: the `c` a tableau without one uses.
    pub fn row_sums(&self) -> Result<Vec<Poly>, Error> {
        self.a.iter().map(|row| sum_of(row.iter(), &self.constants)).collect()
    }

    /// The rows where the given `c` differs from A's row sums (empty when
    /// it matches; `None` when no `c` was given).
    pub fn c_mismatch(&self) -> Option<&[usize]> {
        self.c_mismatch.as_deref()
    }

    /// The method on the oscillator, or on the damped oscillator (`param
    /// D`) when `damped`.
    pub fn method(&self, damped: bool) -> Result<Method, Error> {
        self.program(&format!("<tableau>/{}.zm", self.name), "the tableau", damped)
    }

    /// The method on the scalar test equation y' = λy (a program in `w`),
    /// for the w-plane: one state and one stage value per stage, so it
    /// derives faster than the oscillator's program, to the same χ(z, w).
    pub fn scalar_method(&self) -> Result<Method, Error> {
        self.scalar_program(&format!("<tableau>/{}.zm", self.name), "the tableau")
    }

    /// R(w) = P(w)/Q(w): Q = det(I − wA), P = det(I − wA + w·1bᵀ), exactly.
    /// Explicit: Q = 1 and P = 1 + Σ_k w^(k+1)·bᵀA^k·1 (A is nilpotent).
    pub(crate) fn stability_function(&self) -> Result<StabilityFunction, Error> {
        if let Some(r) = self.stability_function.get() {
            return Ok(r.clone());
        }
        let r = self.compute_stability_function()?;
        Ok(self.stability_function.get_or_init(|| r).clone())
    }

    fn compute_stability_function(&self) -> Result<StabilityFunction, Error> {
        // An explicit tableau of plain numbers (most): P in integers, read
        // from the entries' values, no polynomial made of an entry.
        let plain_row = |row: &[Exact]| row.iter().map(plain).collect::<Option<Vec<_>>>();
        if let (true, Some(b), Some(a)) = (
            self.is_explicit(),
            plain_row(&self.b),
            self.a.iter().map(|row| plain_row(row)).collect::<Option<Vec<_>>>(),
        ) {
            let p = Poly::from_upoly(Sym::w(), &explicit_stability_polynomial(&a, &b));
            return Ok(StabilityFunction(Some(Arc::new((p, Poly::one())))));
        }
        let constants = !self.constants.is_empty();
        let fix = |p: Poly| if constants { field::reduce(&p) } else { p };
        let index = crate::lang::constant::radical_indices(&self.constants);
        let entry = |e: &Exact| -> Result<Poly, Error> {
            match plain(e) {
                Some(q) => Ok(Poly::constant(q)),
                None => entry_value(e, &self.constants, index.as_ref()).map_err(entry_error),
            }
        };
        let a = self
            .a
            .iter()
            .map(|row| {
                row.iter().map(|e| if e.zero { Ok(Poly::zero()) } else { entry(e) }).collect()
            })
            .collect::<Result<Vec<Vec<Poly>>, Error>>()?;
        let b = self
            .b
            .iter()
            .map(|e| if e.zero { Ok(Poly::zero()) } else { entry(e) })
            .collect::<Result<Vec<Poly>, Error>>()?;
        let s = b.len();
        let w = Poly::sym(Sym::w());
        let rationals = |v: &[Poly]| v.iter().map(Poly::as_constant).collect::<Option<Vec<_>>>();
        let (p, q) = if let (true, Some(b), Some(a)) = (
            self.is_explicit(),
            rationals(&b),
            a.iter().map(|row| rationals(row)).collect::<Option<Vec<_>>>(),
        ) {
            (Poly::from_upoly(Sym::w(), &explicit_stability_polynomial(&a, &b)), Poly::one())
        } else if self.is_explicit() {
            let mut p = Poly::one();
            let mut v = vec![Poly::one(); s];
            let mut wk = w.clone();
            for _ in 0..s {
                let mut term = Poly::zero();
                for (bi, vi) in b.iter().zip(&v) {
                    if !bi.is_zero() && !vi.is_zero() {
                        term += &(bi * vi);
                    }
                }
                p += &(&fix(term) * &wk);
                wk = &wk * &w;
                v = a
                    .iter()
                    .map(|row| {
                        let mut acc = Poly::zero();
                        for (aij, vj) in row.iter().zip(&v) {
                            if !aij.is_zero() && !vj.is_zero() {
                                acc += &(aij * vj);
                            }
                        }
                        fix(acc)
                    })
                    .collect();
            }
            (p, Poly::one())
        } else {
            let matrix = |with_b: bool| {
                let rows = (0..s)
                    .map(|i| {
                        (0..s)
                            .map(|j| {
                                let mut x = -&(&a[i][j] * &w);
                                if with_b {
                                    x += &(&b[j] * &w);
                                }
                                if i == j {
                                    x += &Poly::one();
                                }
                                x
                            })
                            .collect()
                    })
                    .collect();
                fix(PolyMatrix::from_rows(rows).det())
            };
            (matrix(true), matrix(false))
        };
        Ok(StabilityFunction(Some(Arc::new((p, q)))))
    }
}

impl Method {
    /// The Runge–Kutta method of a Butcher tableau on the oscillator, from
    /// its entries as text (`"1/4 - sqrt(3)/6"`); an error names the entry
    /// (`A[1][2]`, `b[3]`, `c[1]`, counted from 1).
    ///
    /// ```
    /// let m = poly::Method::from_tableau("heun", &[vec!["0", "0"], vec!["1", "0"]], &["1/2", "1/2"], None)?;
    /// let d = poly::derive(&m)?;
    /// assert_eq!(d.stability(&poly::Params::new())?.stability.name(), "unbounded_for_all_phi");
    /// let bad = poly::Method::from_tableau("t", &[vec!["0", "x"], vec!["1", "0"]], &["1", "0"], None);
    /// assert!(bad.unwrap_err().to_string().starts_with("A[1][2]: unexpected name `x`"));
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn from_tableau(
        name: &str,
        a: &[Vec<&str>],
        b: &[&str],
        c: Option<&[&str]>,
    ) -> Result<Method, Error> {
        Tableau::from_text(name, a, b, c)?.method(false)
    }
}

impl Tableau {
    /// A tableau from its entries as text (`"1/4 - sqrt(3)/6"`), each read
    /// once; an error names the entry (`A[1][2]`, `b[3]`, `c[1]`, counted
    /// from 1), then the shape is checked as [`Tableau::new`] does.
    pub fn from_text(
        name: &str,
        a: &[Vec<&str>],
        b: &[&str],
        c: Option<&[&str]>,
    ) -> Result<Tableau, Error> {
        // The entry's name is written only for an error.
        let entry = |text: &str, at: &dyn Fn() -> String| {
            Exact::parse(text).map_err(|e| {
                Error::new(e.kind(), Span::default(), format!("{}: {}", at(), e.message()))
            })
        };
        let a = a
            .iter()
            .enumerate()
            .map(|(i, row)| {
                row.iter()
                    .enumerate()
                    .map(|(j, t)| entry(t, &|| format!("A[{}][{}]", i + 1, j + 1)))
                    .collect::<Result<Vec<_>, _>>()
            })
            .collect::<Result<Vec<_>, _>>()?;
        let b = b
            .iter()
            .enumerate()
            .map(|(i, t)| entry(t, &|| format!("b[{}]", i + 1)))
            .collect::<Result<Vec<_>, _>>()?;
        let c = c
            .map(|c| {
                c.iter()
                    .enumerate()
                    .map(|(i, t)| entry(t, &|| format!("c[{}]", i + 1)))
                    .collect::<Result<Vec<_>, _>>()
            })
            .transpose()?;
        Tableau::new(name, a, b, c)
    }
}

/// P(w) = 1 + Σ_k w^(k+1)·bᵀA^k·1 of an explicit tableau over Q, in
/// integers: with A = Â/D and b = b̂/D_b, bᵀA^k·1 = b̂ᵀÂ^k·1 / (D_b·D^k),
/// so one rational is reduced per coefficient (not one per product: the
/// decimals of a float-derived tableau are 17-digit fractions). The
/// products run in the order route's [`Int`](crate::arith::int::Int):
/// machine words until a value overflows (the catalogue's tableaux never
/// do), big integers from there.
fn explicit_stability_polynomial(a: &[Vec<crate::Q>], b: &[crate::Q]) -> crate::UPoly {
    use crate::arith::int::{dot, Int};
    use num_bigint::BigInt;
    use num_traits::{One, Zero};
    // Integer entries (zeros above all) change no lcm and scale by d alone.
    let lcm = |qs: &mut dyn Iterator<Item = &crate::Q>| {
        qs.filter(|q| !q.denom().is_one())
            .fold(BigInt::one(), |l, q| num_integer::Integer::lcm(&l, q.denom()))
    };
    let d = lcm(&mut a.iter().flatten());
    let db = lcm(&mut b.iter());
    let scaled = |q: &crate::Q, d: &BigInt| match q {
        _ if q.is_zero() => Int::ZERO,
        _ if q.denom().is_one() => Int::from_big(q.numer() * d),
        _ => Int::from_big(q.numer() * (d / q.denom())),
    };
    let ai: Vec<Vec<Int>> = a.iter().map(|r| r.iter().map(|q| scaled(q, &d)).collect()).collect();
    let bi: Vec<Int> = b.iter().map(|q| scaled(q, &db)).collect();
    let (d, mut den) = (Int::from_big(d), Int::from_big(db));
    let mut v = vec![Int::ONE; b.len()];
    let mut coeffs = vec![crate::Q::from_integer(1.into())];
    for k in 0..b.len() {
        let num = dot(bi.iter().zip(&v));
        coeffs.push(match (&num, &den) {
            (Int::Small(n), Int::Small(e)) => {
                let g = num_integer::Integer::gcd(n, e);
                crate::Q::new_raw((n / g).into(), (e / g).into())
            }
            _ => crate::arith::rational::ratio(num.big().into_owned(), den.big().into_owned()),
        });
        if k + 1 < b.len() {
            v = ai.iter().map(|row| dot(row.iter().zip(&v))).collect();
            den = den.mul(&d);
        }
    }
    crate::UPoly::new(coeffs)
}

/// A name fit for a `.zm` method: letters, digits and `_`, not starting
/// with a digit.
pub fn method_ident(s: &str) -> String {
    let s: String =
        s.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect();
    if s.is_empty() || s.starts_with(|c: char| c.is_ascii_digit()) {
        format!("rk_{s}")
    } else {
        s
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
pub(crate) fn probe(expr: &str, constants: &[(String, String)]) -> Result<bool, String> {
    Ok(value(expr, constants)?.is_zero())
}

/// The exact value of a constant expression in the named radicals, by the
/// `.zm` parser (a polynomial in the radicals' generators, reduced).
pub(crate) fn value(expr: &str, constants: &[(String, String)]) -> Result<Poly, String> {
    let mut src = String::from("method probe\nstate v\n");
    for (name, radical) in constants {
        writeln!(src, "const {name} = {radical}").expect("string");
    }
    writeln!(src, "v = ({expr})*v").expect("string");
    let m = Method::parse("entry", &src).map_err(|e| e.message().to_owned())?;
    Ok(m.assigns().last().and_then(|a| a.terms.first()).map_or_else(Poly::zero, |(_, c)| c.clone()))
}

/// The value of an entry with radicals in the field of a method whose
/// radicals are `constants` (with `index`, their [`radical_indices`]): the
/// value read at parse time when the entry's own generator indices are the
/// method's (the usual case: then both readings name the same generators),
/// else by a program declaring all of them (√2 beside root(4, 2) is the
/// square of the generator 2^(1/4), not a generator of its own).
pub(crate) fn entry_value(
    e: &Exact,
    constants: &[(String, String)],
    index: Option<&std::collections::BTreeMap<u64, u32>>,
) -> Result<Poly, String> {
    if let (Some(v), Some(index)) = (&e.value, index) {
        if crate::lang::constant::radical_indices(&e.radicals)
            .is_some_and(|own| own.iter().all(|(p, l)| index.get(p) == Some(l)))
        {
            return Ok(v.clone());
        }
    }
    value(&e.expr, constants)
}

/// The value of an entry that is a plain number (no radicals), without
/// a program: what `value` gives for it.
fn plain(e: &Exact) -> Option<crate::Q> {
    e.number.clone()
}

/// Σ of exact entries, exactly.
pub(crate) fn sum_of<'a>(
    entries: impl Iterator<Item = &'a Exact> + Clone,
    constants: &[(String, String)],
) -> Result<Poly, Error> {
    if let Some(values) = entries.clone().map(plain).collect::<Option<Vec<_>>>() {
        let sum = values.into_iter().fold(crate::Q::from_integer(0.into()), |s, x| s + x);
        return Ok(Poly::constant(sum));
    }
    let terms: Vec<String> = entries.map(|e| format!("({})", e.expr)).collect();
    value(&format!("0 + {}", terms.join(" + ")), constants).map_err(entry_error)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn e(s: &str) -> Exact {
        Exact::parse(s).unwrap()
    }

    /// P of an explicit tableau in big integers throughout: the oracle.
    fn p_in_big_integers(a: &[Vec<crate::Q>], b: &[crate::Q]) -> crate::UPoly {
        use num_bigint::BigInt;
        let lcm = |qs: &mut dyn Iterator<Item = &crate::Q>| {
            qs.fold(BigInt::from(1), |l, q| num_integer::Integer::lcm(&l, q.denom()))
        };
        let (d, db) = (lcm(&mut a.iter().flatten()), lcm(&mut b.iter()));
        let scaled = |q: &crate::Q, d: &BigInt| q.numer() * (d / q.denom());
        let ai: Vec<Vec<BigInt>> =
            a.iter().map(|r| r.iter().map(|q| scaled(q, &d)).collect()).collect();
        let bi: Vec<BigInt> = b.iter().map(|q| scaled(q, &db)).collect();
        let (mut v, mut den) = (vec![BigInt::from(1); b.len()], db);
        let mut coeffs = vec![crate::Q::from_integer(1.into())];
        for _ in 0..b.len() {
            coeffs.push(crate::Q::new(bi.iter().zip(&v).map(|(x, y)| x * y).sum(), den.clone()));
            v = ai.iter().map(|row| row.iter().zip(&v).map(|(x, y)| x * y).sum()).collect();
            den *= &d;
        }
        crate::UPoly::new(coeffs)
    }

    proptest! {
        /// P of an explicit tableau (machine words until a value
        /// overflows) is P in big integers throughout, on tableaux with
        /// entries up to 2^62 (the words overflow mid-way) and zero weights.
        #[test]
        fn explicit_p_is_p_in_big_integers(
            s in 1usize..6,
            entries in proptest::collection::vec((-(1i64 << 20)..(1i64 << 20), 1i64..1000), 36),
            big in prop::sample::select(vec![1i64, 1, 1 << 40, (1 << 62) - 57]),
        ) {
            // Every seventh entry times `big`.
            let q = |k: usize| {
                let scale: i64 = if k.is_multiple_of(7) { big } else { 1 };
                crate::Q::new(entries[k].0.into(), entries[k].1.into()) * crate::Q::from_integer(scale.into())
            };
            let a: Vec<Vec<crate::Q>> = (0..s)
                .map(|i| (0..s).map(|j| if j < i { q(i * 6 + j) } else { crate::Q::default() }).collect())
                .collect();
            let b: Vec<crate::Q> = (0..s).map(|j| q(30 + j)).collect();
            prop_assert_eq!(explicit_stability_polynomial(&a, &b), p_in_big_integers(&a, &b));
        }
    }

    proptest! {
        /// The quick path for small fractions reads what the general one
        /// reads (text, value, zero, or the same error), on fractions in
        /// and out of its reach: signs, spaces, leading zeros, 17 to 21
        /// digits, zero denominators, decimals and stray characters.
        #[test]
        fn small_fractions_read_as_the_general_path_reads(
            sign in prop::sample::select(vec!["", "-", "+", "- ", " -"]),
            n in "[0-9]{1,21}",
            slash in prop::sample::select(vec!["", "/", "/", " / ", "."]),
            d in "[0-9]{0,20}",
            tail in prop::sample::select(vec!["", " ", "x", "/2"]),
        ) {
            let text = format!("{sign}{n}{slash}{}{tail}", if slash.is_empty() { "" } else { d.as_str() });
            match (Exact::parse(&text), Exact::parse_general(&text)) {
                (Ok(quick), Ok(general)) => {
                    prop_assert_eq!(&quick.expr, &general.expr);
                    prop_assert_eq!(quick.zero, general.zero);
                    prop_assert_eq!(&quick.number, &general.number);
                    prop_assert_eq!(&quick.radicals, &general.radicals);
                    prop_assert_eq!(quick.value.is_some(), general.value.is_some());
                }
                (Err(quick), Err(general)) => prop_assert_eq!(quick, general),
                (quick, general) => prop_assert!(false, "{text:?}: {quick:?} against {general:?}"),
            }
        }
    }

    /// Plain numbers are summed without a program, to what the program
    /// gives.
    #[test]
    fn plain_sums_match_the_program() {
        for entries in [vec!["1/3", "-0.25", "1e-3", "0"], vec!["0.1", "-0.1"], vec!["-3/8"]] {
            let es: Vec<Exact> = entries.iter().map(|t| e(t)).collect();
            let terms: Vec<String> = es.iter().map(|x| format!("({})", x.expr)).collect();
            let by_program = value(&format!("0 + {}", terms.join(" + ")), &[]).unwrap();
            assert_eq!(sum_of(es.iter(), &[]).unwrap(), by_program, "{entries:?}");
        }
    }

    /// A tableau of plain entries gives a method whose program is lowered
    /// only when its lines are read, and then to the program parsed from
    /// its text (equality compares the header and the lowered lines); an
    /// entry with a radical lowers at once.
    #[test]
    fn plain_programs_lower_on_first_use_to_the_parsed_program() {
        let z = || e("0");
        let a = vec![vec![z(), z(), z()], vec![e("1/2"), z(), z()], vec![e("-1"), e("2"), z()]];
        let b = vec![e("1/6"), e("2/3"), e("1/6")];
        let t = Tableau::new("rk3", a, b, None).unwrap();
        for (m, text) in [
            (t.method(false).unwrap(), t.to_zm("the tableau", false)),
            (t.scalar_method().unwrap(), t.to_scalar_zm("the tableau")),
        ] {
            assert!(!m.body.is_lowered());
            assert!(m.stability_function.0.is_some());
            let copy = m.clone();
            assert_eq!(m, Method::parse("rk3.zm", &text).unwrap());
            assert!(m.body.is_lowered() && copy.body.is_lowered(), "clones share the lowering");
            assert_eq!(copy.assigns().len(), if m.is_scalar() { 4 } else { 8 });
        }
        assert!(t.method(true).unwrap().body.is_lowered(), "the damped program is lowered");
        let radical = Tableau::new("r", vec![vec![e("sqrt(2)/4")]], vec![e("1")], None).unwrap();
        assert!(radical.method(false).unwrap().body.is_lowered());
    }

    /// Bad entries and shapes are refused with what was expected.
    #[test]
    fn bad_entries_and_shapes() {
        for (text, says) in [
            ("x", "unexpected name `x`"),
            ("sqrt(-2)", "expected a positive integer literal"),
            ("1/0", ""),
            ("", "empty"),
            ("1 ; 2", "unexpected character `;`"),
        ] {
            let err = Exact::parse(text).unwrap_err();
            assert!(err.message().contains(says), "{text}: {err}");
        }
        let err = Tableau::new("t", vec![vec![e("1"), e("0")]], vec![e("1")], None).unwrap_err();
        assert!(err.message().contains("row 1 of A has 2 entries"), "{err}");
        let err = Tableau::new("a b", vec![vec![e("0")]], vec![e("1")], None).unwrap_err();
        assert!(err.message().contains("expected letters, digits"), "{err}");
    }
}
