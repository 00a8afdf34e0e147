//! Canonical sparse multivariate polynomials over Q.
//!
//! A [`Poly`] is a finite map from [`Monomial`]s to nonzero rational
//! coefficients. The representation is canonical by construction, so `==` is
//! mathematical equality:
//!
//! - every coefficient is a reduced [`Q`] and is never zero;
//! - every monomial lists its symbols in increasing [`Sym`] order with
//!   positive exponents;
//! - terms are kept in a `BTreeMap`, hence sorted.
//!
//! There is intentionally no way to build a `Poly` from a raw term list
//! without passing through the normalising constructors.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt;
use std::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

use num_traits::{One, Signed, Zero};

use crate::{Sym, UPoly, Q};

/// A product of symbols with positive exponents, sorted by symbol id.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Default, Debug)]
pub struct Monomial(Vec<(Sym, u32)>);

impl Monomial {
    /// The empty product, 1.
    pub fn one() -> Monomial {
        Monomial(Vec::new())
    }

    /// `sym^exp`; `exp == 0` gives 1.
    pub fn power(sym: Sym, exp: u32) -> Monomial {
        if exp == 0 {
            Monomial::one()
        } else {
            Monomial(vec![(sym, exp)])
        }
    }

    /// The exponent of `sym` (0 when absent).
    pub fn exponent(&self, sym: Sym) -> u32 {
        self.0.iter().find(|(s, _)| *s == sym).map_or(0, |&(_, e)| e)
    }

    /// The total degree.
    pub fn degree(&self) -> u32 {
        self.0.iter().map(|&(_, e)| e).sum()
    }

    /// `(symbol, exponent)` pairs in symbol-id order.
    pub fn factors(&self) -> &[(Sym, u32)] {
        &self.0
    }

    /// The product of `sym^exp` over distinct symbols, in any order; zero
    /// exponents are dropped.
    pub(crate) fn from_factors(mut factors: Vec<(Sym, u32)>) -> Monomial {
        factors.retain(|&(_, e)| e > 0);
        factors.sort_unstable();
        Monomial(factors)
    }

    /// This monomial with `sym` removed.
    pub fn without(&self, sym: Sym) -> Monomial {
        Monomial(self.0.iter().copied().filter(|&(s, _)| s != sym).collect())
    }

    fn mul(&self, other: &Monomial) -> Monomial {
        let (a, b) = (&self.0, &other.0);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                std::cmp::Ordering::Less => {
                    out.push(a[i]);
                    i += 1;
                }
                std::cmp::Ordering::Greater => {
                    out.push(b[j]);
                    j += 1;
                }
                std::cmp::Ordering::Equal => {
                    out.push((a[i].0, a[i].1 + b[j].1));
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
        Monomial(out)
    }

    /// `self / d` when `d` divides `self` (every exponent of `d` at most
    /// this monomial's).
    fn divide(&self, d: &Monomial) -> Option<Monomial> {
        let mut out = Vec::with_capacity(self.0.len());
        let mut j = 0;
        for &(s, e) in &self.0 {
            let f = match d.0.get(j) {
                Some(&(t, f)) if t == s => {
                    j += 1;
                    f
                }
                Some(&(t, _)) if t < s => return None,
                _ => 0,
            };
            if f > e {
                return None;
            }
            if e > f {
                out.push((s, e - f));
            }
        }
        (j == d.0.len()).then_some(Monomial(out))
    }

    /// The graded lexicographic order: total degree first, then the
    /// exponent of the symbol with the smallest id, and so on. Unlike the
    /// derived `Ord` (which sorts the map), it is a monomial order:
    /// `a < b` implies `a·m < b·m`, which polynomial division needs.
    fn grlex_cmp(&self, other: &Monomial) -> std::cmp::Ordering {
        self.degree().cmp(&other.degree()).then_with(|| {
            let (a, b) = (&self.0, &other.0);
            let (mut i, mut j) = (0, 0);
            loop {
                match (a.get(i), b.get(j)) {
                    (None, None) => return std::cmp::Ordering::Equal,
                    (Some(_), None) => return std::cmp::Ordering::Greater,
                    (None, Some(_)) => return std::cmp::Ordering::Less,
                    (Some(&(s, e)), Some(&(t, f))) => {
                        if s < t {
                            return std::cmp::Ordering::Greater;
                        }
                        if t < s {
                            return std::cmp::Ordering::Less;
                        }
                        if e != f {
                            return e.cmp(&f);
                        }
                        i += 1;
                        j += 1;
                    }
                }
            }
        })
    }

    /// Factors sorted by symbol name, for printing.
    fn by_name(&self) -> Vec<(Sym, u32)> {
        let mut f = self.0.clone();
        f.sort_by_key(|&(s, _)| s.name());
        f
    }
}

/// A polynomial over Q in any number of named symbols.
#[derive(Clone, PartialEq, Eq, Default)]
pub struct Poly {
    terms: BTreeMap<Monomial, Q>,
}

impl Poly {
    /// The zero polynomial, as a constant.
    pub(crate) const ZERO: Poly = Poly { terms: BTreeMap::new() };

    /// The zero polynomial.
    pub fn zero() -> Poly {
        Poly::default()
    }

    /// The constant 1.
    pub fn one() -> Poly {
        Poly::constant(Q::one())
    }

    /// A constant.
    pub fn constant(c: Q) -> Poly {
        Poly::term(c, Monomial::one())
    }

    /// An integer constant.
    pub fn int(n: i64) -> Poly {
        Poly::constant(Q::from_integer(n.into()))
    }

    /// The polynomial consisting of the single symbol `sym`.
    pub fn sym(sym: Sym) -> Poly {
        Poly::term(Q::one(), Monomial::power(sym, 1))
    }

    /// The polynomial consisting of the symbol named `name`.
    pub fn var(name: &str) -> Poly {
        Poly::sym(Sym::new(name))
    }

    /// `c * m`, or zero when `c` is zero.
    pub fn term(c: Q, m: Monomial) -> Poly {
        let mut terms = BTreeMap::new();
        if !c.is_zero() {
            terms.insert(m, c);
        }
        Poly { terms }
    }

    /// Builds the sum of `c * m` over the pairs, combining like terms.
    pub fn from_terms(pairs: impl IntoIterator<Item = (Q, Monomial)>) -> Poly {
        let mut p = Poly::zero();
        for (c, m) in pairs {
            p.add_term(m, c);
        }
        p
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value when the polynomial is a constant (including zero).
    pub fn as_constant(&self) -> Option<Q> {
        match self.terms.len() {
            0 => Some(Q::zero()),
            1 => self.terms.get(&Monomial::one()).cloned(),
            _ => None,
        }
    }

    /// Whether this polynomial is the constant 1.
    pub fn is_one(&self) -> bool {
        self.terms.len() == 1 && self.terms.get(&Monomial::one()).is_some_and(|c| c.is_one())
    }

    /// The coefficient when this is a nonzero constant, without cloning it.
    fn constant_ref(&self) -> Option<&Q> {
        match self.terms.len() {
            1 => self.terms.get(&Monomial::one()),
            _ => None,
        }
    }

    /// Every coefficient times the nonzero constant `c`; the terms stay in
    /// order, so the map is rebuilt in one pass.
    fn times_constant(&self, c: &Q) -> Poly {
        if c.is_one() {
            return self.clone();
        }
        Poly { terms: self.terms.iter().map(|(m, x)| (m.clone(), mul_q(x, c))).collect() }
    }

    /// The terms, each as `(monomial, coefficient)`.
    pub fn terms(&self) -> impl Iterator<Item = (&Monomial, &Q)> {
        self.terms.iter()
    }

    /// The number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether there are no terms (the zero polynomial).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// Every symbol that occurs.
    pub fn symbols(&self) -> BTreeSet<Sym> {
        self.terms.keys().flat_map(|m| m.0.iter().map(|&(s, _)| s)).collect()
    }

    /// The total degree; zero for constants and for the zero polynomial.
    pub fn total_degree(&self) -> u32 {
        self.terms.keys().map(Monomial::degree).max().unwrap_or(0)
    }

    /// The degree in `sym`; zero when `sym` does not occur.
    pub fn degree_in(&self, sym: Sym) -> u32 {
        self.terms.keys().map(|m| m.exponent(sym)).max().unwrap_or(0)
    }

    /// The univariate view in `sym`: entry `k` is the coefficient of `sym^k`,
    /// a polynomial in the remaining symbols. Never empty.
    pub fn coeffs_in(&self, sym: Sym) -> Vec<Poly> {
        let mut out = vec![Poly::zero(); self.degree_in(sym) as usize + 1];
        for (m, c) in &self.terms {
            out[m.exponent(sym) as usize].add_term(m.without(sym), c.clone());
        }
        out
    }

    /// Rebuilds `Σ coeffs[k] * sym^k`.
    pub fn from_coeffs_in(sym: Sym, coeffs: &[Poly]) -> Poly {
        let mut p = Poly::zero();
        for (k, c) in coeffs.iter().enumerate() {
            let s = Monomial::power(sym, k as u32);
            for (m, q) in &c.terms {
                p.add_term(m.mul(&s), q.clone());
            }
        }
        p
    }

    /// This polynomial as a dense univariate polynomial in `sym`, if no other
    /// symbol occurs.
    pub fn to_upoly(&self, sym: Sym) -> Option<UPoly> {
        // Each monomial is 1 or a power of `sym`, else there is another
        // symbol: read the terms in place, without grouping them.
        let mut qs = vec![Q::zero(); self.degree_in(sym) as usize + 1];
        for (m, c) in &self.terms {
            match m.factors() {
                [] => qs[0] = c.clone(),
                [(s, e)] if *s == sym => qs[*e as usize] = c.clone(),
                _ => return None,
            }
        }
        Some(UPoly::new(qs))
    }

    /// The univariate polynomial `u` rewritten in the symbol `sym`.
    pub fn from_upoly(sym: Sym, u: &UPoly) -> Poly {
        Poly::from_terms(
            u.coeffs().iter().enumerate().map(|(k, c)| (c.clone(), Monomial::power(sym, k as u32))),
        )
    }

    /// The leading term in the graded lexicographic order (`None` for zero).
    pub(crate) fn leading_term(&self) -> Option<(&Monomial, &Q)> {
        self.terms.iter().max_by(|a, b| a.0.grlex_cmp(b.0))
    }

    /// `self / d` when `d` divides `self` exactly in Q[symbols], by
    /// multivariate division in the graded lexicographic order (whose
    /// remainder is zero exactly when `d` divides); `None` otherwise, and for
    /// `d = 0`.
    pub(crate) fn div_exact(&self, d: &Poly) -> Option<Poly> {
        let (dm, dc) = d.leading_term()?;
        if let Some(c) = d.constant_ref() {
            return Some(self.times_constant(&c.recip()));
        }
        let mut rest = self.clone();
        let mut quotient = Poly::zero();
        while let Some((m, c)) = rest.leading_term() {
            let t = Poly::term(c / dc, m.divide(dm)?);
            rest -= &(&t * d);
            quotient += &t;
        }
        Some(quotient)
    }

    /// A greatest common divisor in Q[symbols], up to a rational factor
    /// (zero only when both are zero): the recursive primitive remainder
    /// sequence in the largest symbol, with contents taken in the others.
    /// For the small polynomials of a change of variables; the analysis
    /// proper works in one symbol, with [`UPoly::gcd`].
    pub(crate) fn gcd(&self, other: &Poly) -> Poly {
        if self.is_zero() {
            return other.clone();
        }
        if other.is_zero() {
            return self.clone();
        }
        let Some(&x) = self.symbols().union(&other.symbols()).max() else {
            return Poly::one();
        };
        let content = |p: &Poly| {
            p.coeffs_in(x).iter().filter(|c| !c.is_zero()).fold(Poly::zero(), |g, c| g.gcd(c))
        };
        let primitive = |p: &Poly| p.div_exact(&content(p)).expect("the content divides");
        let common = content(self).gcd(&content(other));
        let (mut f, mut g) = (primitive(self), primitive(other));
        if f.degree_in(x) < g.degree_in(x) {
            std::mem::swap(&mut f, &mut g);
        }
        while !g.is_zero() {
            // The pseudo-remainder of f by g in x.
            let (dg, lg) = (g.degree_in(x), g.coeffs_in(x).pop().expect("nonzero"));
            let mut r = f;
            while !r.is_zero() && r.degree_in(x) >= dg {
                let shift = Poly::term(Q::one(), Monomial::power(x, r.degree_in(x) - dg));
                let lr = r.coeffs_in(x).pop().expect("nonzero");
                r = &(&lg * &r) - &(&(&lr * &shift) * &g);
            }
            f = g;
            g = if r.is_zero() { r } else { primitive(&r) };
        }
        &common * &f
    }

    /// Multiplies every coefficient by `c`.
    pub fn scale(&self, c: &Q) -> Poly {
        if c.is_zero() {
            return Poly::zero();
        }
        Poly { terms: self.terms.iter().map(|(m, q)| (m.clone(), mul_q(q, c))).collect() }
    }

    /// `self^exp` by repeated squaring.
    pub fn pow(&self, mut exp: u32) -> Poly {
        let mut base = self.clone();
        let mut acc = Poly::one();
        while exp > 0 {
            if exp & 1 == 1 {
                acc = &acc * &base;
            }
            exp >>= 1;
            if exp > 0 {
                base = &base * &base;
            }
        }
        acc
    }

    /// Substitutes `value` for `sym`.
    pub fn subs(&self, sym: Sym, value: &Poly) -> Poly {
        let cs = self.coeffs_in(sym);
        // Horner in the substituted value.
        let mut acc = Poly::zero();
        for c in cs.iter().rev() {
            acc = &(&acc * value) + c;
        }
        acc
    }

    /// Substitutes rational values for some symbols; the others stay.
    pub fn eval_partial(&self, values: &HashMap<Sym, Q>) -> Poly {
        let mut out = Poly::zero();
        for (m, c) in &self.terms {
            let mut coeff = c.clone();
            let mut rest = Vec::new();
            for &(s, e) in &m.0 {
                match values.get(&s) {
                    Some(v) => coeff *= pow_q(v, e),
                    None => rest.push((s, e)),
                }
            }
            out.add_term(Monomial(rest), coeff);
        }
        out
    }

    /// The value at a full assignment of the symbols; `None` when a symbol
    /// has no value.
    pub fn eval(&self, values: &HashMap<Sym, Q>) -> Option<Q> {
        self.eval_partial(values).as_constant()
    }

    /// The partial derivative with respect to `sym`.
    pub fn derivative(&self, sym: Sym) -> Poly {
        let mut out = Poly::zero();
        for (m, c) in &self.terms {
            let e = m.exponent(sym);
            if e == 0 {
                continue;
            }
            let rest = m.without(sym).mul(&Monomial::power(sym, e - 1));
            out.add_term(rest, c * Q::from_integer(e.into()));
        }
        out
    }

    fn add_term(&mut self, m: Monomial, c: Q) {
        if c.is_zero() {
            return;
        }
        match self.terms.entry(m) {
            std::collections::btree_map::Entry::Vacant(v) => {
                v.insert(c);
            }
            std::collections::btree_map::Entry::Occupied(mut o) => {
                add_assign_q(o.get_mut(), c);
                if o.get().is_zero() {
                    o.remove();
                }
            }
        }
    }

    /// Terms in printing order: descending degree in `z`, then ascending
    /// total degree, then by symbol names.
    fn display_terms(&self) -> Vec<(&Monomial, &Q)> {
        use std::cmp::Reverse;
        let z = Sym::z();
        let mut v: Vec<_> = self.terms.iter().collect();
        // Each key made once: z's exponent down, the degree up, then the
        // factors by name, down.
        v.sort_by_cached_key(|(m, _)| {
            let names: Vec<_> = m.by_name().iter().map(|&(s, e)| (s.name(), e)).collect();
            (Reverse(m.exponent(z)), m.degree(), Reverse(names))
        });
        v
    }

    /// LaTeX source, e.g. `z^{2} - 2 z + 1 + \Phi^{2}`.
    pub fn latex(&self) -> String {
        if self.is_zero() {
            return "0".into();
        }
        let mut s = String::new();
        for (i, (m, c)) in self.display_terms().into_iter().enumerate() {
            let neg = c.is_negative();
            let a = c.abs();
            if i == 0 {
                if neg {
                    s.push('-');
                }
            } else {
                s.push_str(if neg { " - " } else { " + " });
            }
            let mono: Vec<String> = m
                .by_name()
                .iter()
                .map(|&(sym, e)| {
                    let n = latex_name(sym.name());
                    if e == 1 {
                        n
                    } else {
                        format!("{n}^{{{e}}}")
                    }
                })
                .collect();
            let coeff = if a.is_integer() {
                a.numer().to_string()
            } else {
                format!("\\frac{{{}}}{{{}}}", a.numer(), a.denom())
            };
            if mono.is_empty() {
                s.push_str(&coeff);
            } else {
                if !a.is_one() {
                    s.push_str(&coeff);
                    s.push(' ');
                }
                s.push_str(&mono.join(" "));
            }
        }
        s
    }
}

fn latex_name(name: &str) -> String {
    const GREEK: [&str; 8] = ["Phi", "Psi", "Omega", "omega", "tau", "phi", "psi", "theta"];
    if GREEK.contains(&name) {
        format!("\\{name}")
    } else if name.len() > 1 {
        format!("\\mathrm{{{name}}}")
    } else {
        name.to_owned()
    }
}

/// `a * b`. num-rational reduces every product by two binary gcds (one
/// shift of the whole number per bit); `arith::rational::mul` cross-cancels
/// by Lehmer's gcd, and integers need none.
#[inline]
pub(crate) fn mul_q(a: &Q, b: &Q) -> Q {
    crate::arith::rational::mul(a, b)
}

/// `*a += b`, skipping the gcd when both are integers, else by Lehmer's
/// gcd (`arith::rational::add`).
#[inline]
pub(crate) fn add_assign_q(a: &mut Q, b: Q) {
    if a.denom().is_one() && b.denom().is_one() {
        *a = Q::from_integer(a.numer() + b.numer());
    } else {
        *a = crate::arith::rational::add(a, &b);
    }
}

/// `v^e` for a rational `v`.
pub(crate) fn pow_q(v: &Q, e: u32) -> Q {
    num_traits::pow(v.clone(), e as usize)
}

impl fmt::Display for Poly {
    /// Plain text any computer algebra system parses: `^` for powers, `*`
    /// for products, rationals as `a/b`, e.g. `z^2 - 2*z + 1 + Phi^2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return f.write_str("0");
        }
        for (i, (m, c)) in self.display_terms().into_iter().enumerate() {
            let neg = c.is_negative();
            match (i, neg) {
                (0, true) => f.write_str("-")?,
                (0, false) => {}
                (_, true) => f.write_str(" - ")?,
                (_, false) => f.write_str(" + ")?,
            }
            // |c|, written without a copy.
            let (n, d) = (c.numer().magnitude(), c.denom());
            let factors = m.by_name();
            let unit = n.is_one() && d.is_one();
            if factors.is_empty() || !unit {
                write!(f, "{n}")?;
                if !d.is_one() {
                    write!(f, "/{d}")?;
                }
            }
            for (k, &(s, e)) in factors.iter().enumerate() {
                if k > 0 || !unit {
                    f.write_str("*")?;
                }
                f.write_str(s.name())?;
                if e != 1 {
                    write!(f, "^{e}")?;
                }
            }
        }
        Ok(())
    }
}

impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Poly({self})")
    }
}

impl From<Q> for Poly {
    fn from(c: Q) -> Poly {
        Poly::constant(c)
    }
}

impl From<i64> for Poly {
    fn from(n: i64) -> Poly {
        Poly::int(n)
    }
}

impl<'a> Add<&'a Poly> for &'a Poly {
    type Output = Poly;
    fn add(self, rhs: &Poly) -> Poly {
        let mut out = self.clone();
        out += rhs;
        out
    }
}

impl AddAssign<&Poly> for Poly {
    fn add_assign(&mut self, rhs: &Poly) {
        for (m, c) in &rhs.terms {
            self.add_term(m.clone(), c.clone());
        }
    }
}

impl SubAssign<&Poly> for Poly {
    fn sub_assign(&mut self, rhs: &Poly) {
        for (m, c) in &rhs.terms {
            self.add_term(m.clone(), -c.clone());
        }
    }
}

impl<'a> Sub<&'a Poly> for &'a Poly {
    type Output = Poly;
    fn sub(self, rhs: &Poly) -> Poly {
        let mut out = self.clone();
        out -= rhs;
        out
    }
}

impl<'a> Mul<&'a Poly> for &'a Poly {
    type Output = Poly;
    fn mul(self, rhs: &Poly) -> Poly {
        // A constant factor (the common case in lowering and derivation)
        // scales without merging terms.
        if let Some(c) = self.constant_ref() {
            return rhs.times_constant(c);
        }
        if let Some(c) = rhs.constant_ref() {
            return self.times_constant(c);
        }
        let mut out = Poly::zero();
        for (ma, ca) in &self.terms {
            for (mb, cb) in &rhs.terms {
                out.add_term(ma.mul(mb), mul_q(ca, cb));
            }
        }
        out
    }
}

impl Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        Poly { terms: self.terms.iter().map(|(m, c)| (m.clone(), -c.clone())).collect() }
    }
}

macro_rules! owned_ops {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr<Poly> for Poly {
            type Output = Poly;
            fn $f(self, rhs: Poly) -> Poly { (&self).$f(&rhs) }
        }
        impl $tr<&Poly> for Poly {
            type Output = Poly;
            fn $f(self, rhs: &Poly) -> Poly { (&self).$f(rhs) }
        }
        impl $tr<Poly> for &Poly {
            type Output = Poly;
            fn $f(self, rhs: Poly) -> Poly { self.$f(&rhs) }
        }
    )*};
}
owned_ops!(Add add, Sub sub, Mul mul);

impl Neg for Poly {
    type Output = Poly;
    fn neg(mut self) -> Poly {
        for c in self.terms.values_mut() {
            *c = -std::mem::replace(c, Q::zero());
        }
        self
    }
}

impl Zero for Poly {
    fn zero() -> Poly {
        Poly::zero()
    }
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
}

impl One for Poly {
    fn one() -> Poly {
        Poly::one()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The obvious writer: names compared afresh, monomials joined, |c| by num-rational.
    fn written_by_parts(p: &Poly) -> String {
        if p.is_zero() {
            return "0".to_owned();
        }
        let z = Sym::z();
        let mut v: Vec<_> = p.terms.iter().collect();
        v.sort_by(|(a, _), (b, _)| {
            b.exponent(z).cmp(&a.exponent(z)).then(a.degree().cmp(&b.degree())).then_with(|| {
                let na: Vec<_> = a.by_name().iter().map(|&(s, e)| (s.name(), e)).collect();
                let nb: Vec<_> = b.by_name().iter().map(|&(s, e)| (s.name(), e)).collect();
                nb.cmp(&na)
            })
        });
        let mut out = String::new();
        for (i, (m, c)) in v.into_iter().enumerate() {
            out.push_str(match (i, c.is_negative()) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            });
            let a = c.abs();
            let mono: Vec<String> = m
                .by_name()
                .iter()
                .map(|&(s, e)| if e == 1 { s.name().to_owned() } else { format!("{s}^{e}") })
                .collect();
            out.push_str(&if mono.is_empty() {
                a.to_string()
            } else if a.is_one() {
                mono.join("*")
            } else {
                format!("{a}*{}", mono.join("*"))
            });
        }
        out
    }

    proptest! {
        /// `Display` writes what the obvious writer writes, on polynomials in
        /// z, Φ, w and D with coefficients ±1, integers and fractions.
        #[test]
        fn display_is_the_obvious_writing(
            terms in proptest::collection::vec(
                ((-3i64..=3, 1i64..=4), proptest::collection::vec(0u32..4, 4)), 0..8),
        ) {
            let syms = [Sym::z(), Sym::phi(), Sym::w(), Sym::new("D")];
            let p = Poly::from_terms(terms.iter().map(|((n, d), exps)| {
                let factors = syms.iter().copied().zip(exps.iter().copied()).collect();
                (Q::new((*n).into(), (*d).into()), Monomial::from_factors(factors))
            }));
            prop_assert_eq!(p.to_string(), written_by_parts(&p));
        }
    }
}
