//! Butcher tableaux whose entries name free parameters: each entry a
//! rational function of the parameters (`1 - 1/(2*c)`), read by a small
//! exact parser (numbers, names, + − × ÷, integer powers, brackets). At a
//! rational point the tableau becomes an ordinary [`Tableau`]; for the
//! search its entries share one denominator δ, so A = Ã/δ and b = b̃/δ with
//! Ã, b̃ and δ polynomials in the parameters.

use num_traits::Zero;

use crate::error::{Error, ErrorKind, Span};
use crate::lang::tableau::{Exact, Tableau};
use crate::{Poly, PolyMatrix, Sym, Q};

/// A rational function num/den of the parameters.
#[derive(Clone, Debug, PartialEq)]
struct Ratio {
    num: Poly,
    den: Poly,
}

impl Ratio {
    fn poly(p: Poly) -> Ratio {
        Ratio { num: p, den: Poly::one() }
    }

    fn reduced(num: Poly, den: Poly) -> Ratio {
        if num.is_zero() {
            return Ratio::poly(Poly::zero());
        }
        let g = num.gcd(&den);
        let (num, den) = match (num.div_exact(&g), den.div_exact(&g)) {
            (Some(n), Some(d)) => (n, d),
            _ => (num, den),
        };
        // A constant denominator is folded into the numerator.
        match den.as_constant() {
            Some(c) => Ratio::poly(num.scale(&c.recip())),
            None => Ratio { num, den },
        }
    }

    fn add(&self, o: &Ratio, sign: i64) -> Ratio {
        let n = &(&self.num * &o.den) + &(&o.num * &self.den).scale(&Q::from_integer(sign.into()));
        Ratio::reduced(n, &self.den * &o.den)
    }

    fn mul(&self, o: &Ratio) -> Ratio {
        Ratio::reduced(&self.num * &o.num, &self.den * &o.den)
    }

    fn div(&self, o: &Ratio) -> Option<Ratio> {
        if o.num.is_zero() {
            return None;
        }
        Some(Ratio::reduced(&self.num * &o.den, &self.den * &o.num))
    }
}

struct Parser<'a> {
    chars: Vec<char>,
    at: usize,
    params: &'a [Sym],
    text: &'a str,
}

impl Parser<'_> {
    fn err(&self, msg: &str) -> Error {
        Error::new(
            ErrorKind::BadConstant,
            Span::default(),
            format!("entry {:?}: {msg} (at character {})", self.text, self.at + 1),
        )
    }

    fn skip(&mut self) {
        while self.chars.get(self.at).is_some_and(|c| c.is_whitespace()) {
            self.at += 1;
        }
    }

    fn peek(&mut self) -> Option<char> {
        self.skip();
        self.chars.get(self.at).copied()
    }

    fn expr(&mut self) -> Result<Ratio, Error> {
        let mut acc = self.term()?;
        while let Some(c @ ('+' | '-')) = self.peek() {
            self.at += 1;
            let t = self.term()?;
            acc = acc.add(&t, if c == '+' { 1 } else { -1 });
        }
        Ok(acc)
    }

    fn term(&mut self) -> Result<Ratio, Error> {
        let mut acc = self.unary()?;
        while let Some(c @ ('*' | '/')) = self.peek() {
            self.at += 1;
            let t = self.unary()?;
            acc = if c == '*' {
                acc.mul(&t)
            } else {
                acc.div(&t).ok_or_else(|| self.err("division by zero"))?
            };
        }
        Ok(acc)
    }

    fn unary(&mut self) -> Result<Ratio, Error> {
        if self.peek() == Some('-') {
            self.at += 1;
            let u = self.unary()?;
            return Ok(Ratio { num: -&u.num, den: u.den });
        }
        if self.peek() == Some('+') {
            self.at += 1;
        }
        self.power()
    }

    fn power(&mut self) -> Result<Ratio, Error> {
        let base = self.atom()?;
        if self.peek() != Some('^') {
            return Ok(base);
        }
        self.at += 1;
        self.skip();
        let start = self.at;
        while self.chars.get(self.at).is_some_and(char::is_ascii_digit) {
            self.at += 1;
        }
        let e: u32 = self.chars[start..self.at]
            .iter()
            .collect::<String>()
            .parse()
            .ok()
            .filter(|&e| e <= 64)
            .ok_or_else(|| self.err("expected an exponent from 0 to 64"))?;
        Ok(Ratio { num: base.num.pow(e), den: base.den.pow(e) })
    }

    fn atom(&mut self) -> Result<Ratio, Error> {
        match self.peek() {
            Some('(') => {
                self.at += 1;
                let e = self.expr()?;
                if self.peek() != Some(')') {
                    return Err(self.err("expected `)`"));
                }
                self.at += 1;
                Ok(e)
            }
            Some(c) if c.is_ascii_digit() || c == '.' => {
                let start = self.at;
                while self.chars.get(self.at).is_some_and(|c| c.is_ascii_digit() || *c == '.') {
                    self.at += 1;
                }
                let s: String = self.chars[start..self.at].iter().collect();
                let q = crate::lang::syntax::parse_number(&s)
                    .map_err(|_| self.err("expected a number"))?;
                Ok(Ratio::poly(Poly::constant(q)))
            }
            Some(c) if c.is_alphabetic() || c == '_' => {
                let start = self.at;
                while self.chars.get(self.at).is_some_and(|c| c.is_alphanumeric() || *c == '_') {
                    self.at += 1;
                }
                let s: String = self.chars[start..self.at].iter().collect();
                match self.params.iter().find(|p| p.name() == s) {
                    Some(&p) => Ok(Ratio::poly(Poly::sym(p))),
                    None => Err(self.err(&format!(
                        "`{s}` is not a declared parameter (radicals and other names are not \
                         read in a tableau with parameters)"
                    ))),
                }
            }
            _ => Err(self.err("expected a number, a parameter or `(`")),
        }
    }
}

fn parse(text: &str, params: &[Sym]) -> Result<Ratio, Error> {
    let mut p = Parser { chars: text.chars().collect(), at: 0, params, text };
    let r = p.expr()?;
    if p.peek().is_some() {
        return Err(p.err("unexpected text after the expression"));
    }
    Ok(r)
}

/// A Butcher tableau whose entries are rational functions of free
/// parameters.
#[derive(Clone, Debug)]
pub struct ParamTableau {
    name: String,
    params: Vec<Sym>,
    a: Vec<Vec<Ratio>>,
    b: Vec<Ratio>,
}

impl ParamTableau {
    /// Reads `A` (row by row) and `b`, each entry an expression in the
    /// declared `params`. A is square with one row per stage.
    ///
    /// ```
    /// use poly::advanced::design::ParamTableau;
    /// let t = ParamTableau::new("rk2", &["c"], &[vec!["0", "0"], vec!["c", "0"]], &["1 - 1/(2*c)", "1/(2*c)"])?;
    /// assert_eq!(t.stages(), 2);
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn new(
        name: &str,
        params: &[&str],
        a: &[Vec<&str>],
        b: &[&str],
    ) -> Result<ParamTableau, Error> {
        let syms: Vec<Sym> = params.iter().map(|p| Sym::new(p)).collect();
        let s = a.len();
        if s == 0 || b.len() != s || a.iter().any(|r| r.len() != s) {
            return Err(Error::new(
                ErrorKind::Syntax,
                Span::default(),
                format!("A must be square with one row per stage and b one entry per stage; got {s} rows and {} weights", b.len()),
            ));
        }
        let a = a
            .iter()
            .map(|row| row.iter().map(|e| parse(e, &syms)).collect::<Result<Vec<_>, _>>())
            .collect::<Result<Vec<_>, _>>()?;
        let b = b.iter().map(|e| parse(e, &syms)).collect::<Result<Vec<_>, _>>()?;
        Ok(ParamTableau { name: name.to_owned(), params: syms, a, b })
    }

    /// The tableau with the parameters in `values` replaced by their
    /// values (the declared list is kept, so a bound name still checks).
    pub(crate) fn bind(
        &self,
        values: &std::collections::HashMap<Sym, Q>,
    ) -> Result<ParamTableau, Error> {
        let bind = |r: &Ratio| -> Result<Ratio, Error> {
            let den = r.den.eval_partial(values);
            if den.is_zero() {
                return Err(Error::analysis(
                    ErrorKind::Singular,
                    format!("an entry's denominator {} vanishes at the bound values", r.den),
                ));
            }
            Ok(Ratio::reduced(r.num.eval_partial(values), den))
        };
        let a = self
            .a
            .iter()
            .map(|row| row.iter().map(bind).collect::<Result<Vec<_>, _>>())
            .collect::<Result<Vec<_>, _>>()?;
        let b = self.b.iter().map(bind).collect::<Result<Vec<_>, _>>()?;
        Ok(ParamTableau { name: self.name.clone(), params: self.params.clone(), a, b })
    }

    /// The number of stages.
    pub fn stages(&self) -> usize {
        self.b.len()
    }

    /// The declared parameters.
    pub fn params(&self) -> &[Sym] {
        &self.params
    }

    /// The tableau's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The ordinary tableau at rational values of the parameters (every
    /// one given); an error where an entry's denominator vanishes.
    pub fn at(&self, values: &[(Sym, Q)]) -> Result<Tableau, Error> {
        let map: std::collections::HashMap<Sym, Q> = values.iter().cloned().collect();
        let value = |r: &Ratio| -> Result<Exact, Error> {
            let (n, d) = (r.num.eval(&map), r.den.eval(&map));
            match (n, d) {
                (Some(n), Some(d)) if !d.is_zero() => Exact::parse(&(n / d).to_string()),
                (Some(_), Some(_)) => Err(Error::analysis(
                    ErrorKind::Singular,
                    format!("an entry's denominator {} vanishes there", r.den),
                )),
                _ => Err(Error::analysis(
                    ErrorKind::ExtraSymbol,
                    "every parameter of the tableau needs a value".to_owned(),
                )),
            }
        };
        let a = self
            .a
            .iter()
            .map(|row| row.iter().map(value).collect::<Result<Vec<_>, _>>())
            .collect::<Result<Vec<_>, _>>()?;
        let b = self.b.iter().map(value).collect::<Result<Vec<_>, _>>()?;
        Tableau::new(&crate::lang::tableau::method_ident(&self.name), a, b, None)
    }

    /// The points of `[lo, hi]` where a step's multiply count can differ
    /// from its count elsewhere, with `free` the one parameter left (the
    /// others bound to `values`): where an entry of A or b that varies is 0
    /// or ±1, or equals another entry of its combination (a row of A, or b)
    /// up to sign, as equal coefficients share a multiplication. Each point comes once, in
    /// increasing order, with the first reason found (`A[2][1] = 1`, `b[1] =
    /// b[2]`; entries named from 1).
    ///
    /// ```
    /// use poly::advanced::design::ParamTableau;
    /// let t = ParamTableau::new("rk2", &["c"], &[vec!["0", "0"], vec!["c", "0"]], &["1 - 1/(2*c)", "1/(2*c)"])?;
    /// let c = poly::Sym::new("c");
    /// let points = t.cost_breaks(&[], c, &poly::q(1, 4), &poly::q(2, 1));
    /// let shown: Vec<String> = points.iter().map(|(x, why)| format!("{} ({why})", x.describe("c"))).collect();
    /// assert_eq!(shown, ["1/4 (b[1] = -1)", "1/2 (b[1] = 0)", "1 (A[2][1] = 1)"]);
    /// // With A[2][1] fixed, the point c = 1 comes from b₁ = b₂ alone.
    /// let u = ParamTableau::new("u", &["c"], &[vec!["0", "0"], vec!["2/3", "0"]], &["1 - 1/(2*c)", "1/(2*c)"])?;
    /// let points = u.cost_breaks(&[], c, &poly::q(3, 4), &poly::q(2, 1));
    /// let shown: Vec<String> = points.iter().map(|(x, why)| format!("{} ({why})", x.describe("c"))).collect();
    /// assert_eq!(shown, ["1 (b[1] = b[2])"]);
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn cost_breaks(
        &self,
        values: &[(Sym, Q)],
        free: Sym,
        lo: &Q,
        hi: &Q,
    ) -> Vec<(crate::Algebraic, String)> {
        let map: std::collections::HashMap<Sym, Q> = values.iter().cloned().collect();
        let entries: Vec<(String, Poly, Poly)> = self
            .a
            .iter()
            .enumerate()
            .flat_map(|(i, row)| {
                row.iter().enumerate().map(move |(j, r)| (format!("A[{}][{}]", i + 1, j + 1), r))
            })
            .chain(self.b.iter().enumerate().map(|(i, r)| (format!("b[{}]", i + 1), r)))
            .map(|(n, r)| (n, r.num.eval_partial(&map), r.den.eval_partial(&map)))
            .filter(|(_, n, d)| n.symbols().contains(&free) || d.symbols().contains(&free))
            .collect();
        let mut out: Vec<(crate::Algebraic, String)> = Vec::new();
        let mut add = |p: Poly, why: String| {
            let Some(u) = p.to_upoly(free).filter(|u| u.degree().is_some_and(|d| d > 0)) else {
                return;
            };
            for x in crate::Algebraic::real_roots(&u) {
                let inside = x.cmp_rational(lo) != std::cmp::Ordering::Less
                    && x.cmp_rational(hi) != std::cmp::Ordering::Greater;
                if inside && !out.iter().any(|(y, _)| *y == x) {
                    out.push((x, why.clone()));
                }
            }
        };
        for (k, (name, num, den)) in entries.iter().enumerate() {
            for v in [0i64, 1, -1] {
                add(num - &den.scale(&Q::from_integer(v.into())), format!("{name} = {v}"));
            }
            // Coefficients share a multiplication within one combination:
            // a stage's row of A, or the weights b.
            let group = |n: &str| match n.starts_with('b') {
                true => "b".to_owned(),
                false => n.split(']').next().unwrap_or(n).to_owned(),
            };
            for (other, n2, d2) in entries[k + 1..].iter().filter(|e| group(&e.0) == group(name)) {
                // num/den = ±n2/d2: num·d2 ∓ n2·den = 0.
                add(&(num * d2) - &(n2 * den), format!("{name} = {other}"));
                add(&(num * d2) + &(n2 * den), format!("{name} = -{other}"));
            }
        }
        out.sort_by(|x, y| x.0.cmp(&y.0));
        out
    }

    /// Ã, b̃ and δ: A = Ã/δ and b = b̃/δ, δ the product of the distinct
    /// denominators.
    pub(crate) fn common(&self) -> (Vec<Vec<Poly>>, Vec<Poly>, Poly) {
        let mut dens: Vec<Poly> = Vec::new();
        for r in self.a.iter().flatten().chain(&self.b) {
            if r.den.as_constant().is_none() && !dens.contains(&r.den) {
                dens.push(r.den.clone());
            }
        }
        let delta = dens.iter().fold(Poly::one(), |acc, d| &acc * d);
        let lift = |r: &Ratio| &r.num * &delta.div_exact(&r.den).expect("a factor of δ");
        let a = self.a.iter().map(|row| row.iter().map(lift).collect()).collect();
        let b = self.b.iter().map(lift).collect();
        (a, b, delta)
    }

    /// The stability function R = P/Q as (P, Q), polynomials in w and the
    /// parameters: Q = det(δI − wÃ), P = det(δI − wÃ + w e b̃ᵀ).
    pub(crate) fn p_q(&self) -> (Poly, Poly) {
        let (a, b, delta) = self.common();
        let s = self.stages();
        let w = Poly::sym(Sym::w());
        let q_rows: Vec<Vec<Poly>> = (0..s)
            .map(|i| {
                (0..s)
                    .map(|j| {
                        let e = -&(&w * &a[i][j]);
                        if i == j {
                            &e + &delta
                        } else {
                            e
                        }
                    })
                    .collect()
            })
            .collect();
        let p_rows: Vec<Vec<Poly>> = q_rows
            .iter()
            .map(|row| row.iter().enumerate().map(|(j, e)| e + &(&w * &b[j])).collect())
            .collect();
        (PolyMatrix::from_rows(p_rows).det(), PolyMatrix::from_rows(q_rows).det())
    }
}
