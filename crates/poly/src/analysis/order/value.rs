//! The exact numbers of the order analysis: a [`Value`] is a rational, or an
//! element of the number field spanned by the method's radicals (√3 in
//! Gauss' tableaux, ∛2 in Yoshida's), kept as a reduced polynomial in the
//! generator symbols of [`crate::multivariate::constants`], where `==` is
//! equality of real numbers and the sign is decided exactly.
//!
//! Entries are read here too: every entry of one method is read against the
//! radicals of the whole method, so that √2 and root(4, 2) share one
//! generator and the representation stays canonical.

use std::cmp::Ordering;
use std::fmt;

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use crate::arith::rational::{add as qadd, mul as qmul};
use crate::error::Error;
use crate::lang::constant::radical_indices;
use crate::lang::tableau::{entry_error, entry_value, Exact};
use crate::multivariate::constants as field;
use crate::multivariate::poly::Monomial;
use crate::{Poly, Q};

/// An exact real number: a rational, or an element of Q(√n, ∛n, …).
///
/// ```
/// use poly::advanced::order::Value;
/// let v = Value::from(poly::q(7, 144));
/// assert_eq!(v.to_string(), "7/144");
/// assert_eq!(v.as_rational(), Some(&poly::q(7, 144)));
/// ```
#[derive(Clone, PartialEq, Eq)]
pub struct Value(Repr);

#[derive(Clone, PartialEq, Eq)]
enum Repr {
    Rational(Q),
    /// a + b√p (b ≠ 0), p > 1 squarefree and `g` the monomial √p, a
    /// product of distinct square-root generators (√15 = √3·√5): Gauss',
    /// Radau's and Lobatto's entries, whose arithmetic needs no polynomial.
    Quadratic {
        a: Q,
        b: Q,
        p: u64,
        g: Monomial,
    },
    /// A reduced polynomial in generator symbols that is neither a
    /// constant nor of the quadratic form.
    Field(Poly),
}

/// The monomial's radicand when it is √p for a squarefree p > 1: distinct
/// square-root generators to the first power, of pairwise coprime
/// squarefree radicands.
fn square_root_radicand(m: &Monomial) -> Option<u64> {
    let mut p: u64 = 1;
    for &(g, e) in m.factors() {
        let (r, 2) = field::generator_of(g)? else { return None };
        let squarefree = (2..).take_while(|k: &u64| k * k <= r).all(|k| r % (k * k) != 0);
        if e != 1 || !squarefree || num_integer::gcd(p, r) != 1 {
            return None;
        }
        p = p.checked_mul(r)?;
    }
    (p > 1).then_some(p)
}

/// a + b√p as a value: rational when b = 0.
fn quadratic(a: Q, b: Q, p: u64, g: Monomial) -> Value {
    if b.is_zero() {
        Value(Repr::Rational(a))
    } else {
        Value(Repr::Quadratic { a, b, p, g })
    }
}

impl Value {
    /// Zero.
    pub fn zero() -> Value {
        Value(Repr::Rational(Q::zero()))
    }

    /// One.
    pub fn one() -> Value {
        Value(Repr::Rational(Q::one()))
    }

    /// An element of the field of constants: a polynomial in generator
    /// symbols (`sqrt(3)`, `cbrt(2)`, …), reduced here.
    pub fn from_poly(p: &Poly) -> Value {
        let p = field::reduce(p);
        if let Some(q) = p.as_constant() {
            return Value(Repr::Rational(q));
        }
        // a + b·g with g = √p one monomial: the quadratic form.
        let (mut a, mut root, mut roots) = (Q::zero(), None, 0);
        for (m, c) in p.terms() {
            match m.degree() {
                0 => a = c.clone(),
                _ => (root, roots) = (Some((m, c)), roots + 1),
            }
        }
        if let (Some((m, b)), 1) = (root, roots) {
            if let Some(radicand) = square_root_radicand(m) {
                return quadratic(a, b.clone(), radicand, m.clone());
            }
        }
        Value(Repr::Field(p))
    }

    /// Reads exact entries as numbers of one field, each against the
    /// radicals of all of them (so √2 and root(4, 4) are one number).
    ///
    /// ```
    /// use poly::advanced::tableau::Exact;
    /// let e = [Exact::parse("sqrt(2)")?, Exact::parse("root(4, 4)")?];
    /// let v = poly::advanced::order::Value::read(&e)?;
    /// assert_eq!(v[0], v[1]);
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn read(entries: &[Exact]) -> Result<Vec<Value>, Error> {
        Ok(read(&[("entry", entries)])?.remove(0))
    }

    /// The rational value, when the number is rational.
    pub fn as_rational(&self) -> Option<&Q> {
        match &self.0 {
            Repr::Rational(q) => Some(q),
            _ => None,
        }
    }

    /// The number as a polynomial in the generator symbols (a constant
    /// polynomial when it is rational).
    pub fn to_poly(&self) -> Poly {
        match &self.0 {
            Repr::Rational(q) => Poly::constant(q.clone()),
            Repr::Quadratic { a, b, g, .. } => {
                Poly::from_terms([(a.clone(), Monomial::one()), (b.clone(), g.clone())])
            }
            Repr::Field(p) => p.clone(),
        }
    }

    /// Whether the number is exactly zero.
    pub fn is_zero(&self) -> bool {
        matches!(&self.0, Repr::Rational(q) if q.is_zero())
    }

    /// The exact sign.
    pub fn sign(&self) -> Ordering {
        match &self.0 {
            Repr::Rational(q) => q.cmp(&Q::zero()),
            // b ≠ 0 and √p is irrational, so a² ≠ b²p: the larger term's
            // sign.
            Repr::Quadratic { a, b, p, .. } => {
                let (sa, sb) = (a.cmp(&Q::zero()), b.cmp(&Q::zero()));
                if sa == sb || sa == Ordering::Equal || a * a < b * b * Q::from_integer((*p).into())
                {
                    sb
                } else {
                    sa
                }
            }
            Repr::Field(p) => field::sign(p),
        }
    }

    /// A rational within `width` of the number.
    pub fn approx(&self, width: &Q) -> Q {
        match &self.0 {
            Repr::Rational(q) => q.clone(),
            _ => field::approx(&self.to_poly(), width),
        }
    }

    /// The inverse; `None` for zero.
    pub fn inverse(&self) -> Option<Value> {
        match &self.0 {
            Repr::Rational(q) if q.is_zero() => None,
            Repr::Rational(q) => Some(Value(Repr::Rational(q.recip()))),
            // (a − b√p)/(a² − b²p), the norm nonzero as √p is irrational.
            Repr::Quadratic { a, b, p, g } => {
                let norm = a * a - b * b * Q::from_integer((*p).into());
                Some(quadratic(a / &norm, -(b / &norm), *p, g.clone()))
            }
            Repr::Field(p) => field::inverse(p).map(|i| Value::from_poly(&i)),
        }
    }

    /// |self|.
    pub fn abs(&self) -> Value {
        if self.sign() == Ordering::Less {
            self.neg()
        } else {
            self.clone()
        }
    }

    pub(crate) fn neg(&self) -> Value {
        match &self.0 {
            Repr::Rational(q) => Value(Repr::Rational(-q.clone())),
            Repr::Quadratic { a, b, p, g } => {
                Value(Repr::Quadratic { a: -a.clone(), b: -b.clone(), p: *p, g: g.clone() })
            }
            Repr::Field(p) => Value(Repr::Field(-p)),
        }
    }

    pub(crate) fn add(&self, o: &Value) -> Value {
        match (&self.0, &o.0) {
            (Repr::Rational(a), Repr::Rational(b)) => Value(Repr::Rational(qadd(a, b))),
            (Repr::Quadratic { a, b, p, g }, Repr::Rational(q))
            | (Repr::Rational(q), Repr::Quadratic { a, b, p, g }) => {
                Value(Repr::Quadratic { a: qadd(a, q), b: b.clone(), p: *p, g: g.clone() })
            }
            (Repr::Quadratic { a, b, p, g }, Repr::Quadratic { a: a2, b: b2, g: g2, .. })
                if g == g2 =>
            {
                quadratic(qadd(a, a2), qadd(b, b2), *p, g.clone())
            }
            _ => Value::from_poly(&(&self.to_poly() + &o.to_poly())),
        }
    }

    pub(crate) fn sub(&self, o: &Value) -> Value {
        self.add(&o.neg())
    }

    pub(crate) fn mul(&self, o: &Value) -> Value {
        match (&self.0, &o.0) {
            (Repr::Rational(a), Repr::Rational(b)) => Value(Repr::Rational(qmul(a, b))),
            (Repr::Rational(a), Repr::Field(p)) | (Repr::Field(p), Repr::Rational(a)) => {
                if a.is_zero() {
                    Value::zero()
                } else {
                    Value(Repr::Field(p.scale(a)))
                }
            }
            (Repr::Rational(q), Repr::Quadratic { a, b, p, g })
            | (Repr::Quadratic { a, b, p, g }, Repr::Rational(q)) => {
                quadratic(qmul(a, q), qmul(b, q), *p, g.clone())
            }
            (Repr::Quadratic { a, b, p, g }, Repr::Quadratic { a: a2, b: b2, g: g2, .. })
                if g == g2 =>
            {
                let pq = Q::from_integer((*p).into());
                quadratic(
                    qadd(&qmul(a, a2), &qmul(&qmul(b, b2), &pq)),
                    qadd(&qmul(a, b2), &qmul(a2, b)),
                    *p,
                    g.clone(),
                )
            }
            _ => Value::from_poly(&(&self.to_poly() * &o.to_poly())),
        }
    }

    /// self ≤ bound, in absolute value: |self| ≤ bound.
    pub(crate) fn within(&self, bound: &Q) -> bool {
        match &self.0 {
            Repr::Rational(q) => q.abs() <= *bound,
            _ => self.abs().sub(&Value::from(bound.clone())).sign() != Ordering::Greater,
        }
    }

    pub(crate) fn sum<'a>(values: impl IntoIterator<Item = &'a Value>) -> Value {
        values.into_iter().fold(Value::zero(), |s, v| s.add(v))
    }
}

impl From<Q> for Value {
    fn from(q: Q) -> Value {
        Value(Repr::Rational(q))
    }
}

impl fmt::Display for Value {
    /// Plain text: `7/144`, `1/4 - 1/6*sqrt(3)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Rational(q) => write!(f, "{q}"),
            Repr::Quadratic { .. } => write!(f, "{}", self.to_poly()),
            Repr::Field(p) => write!(f, "{p}"),
        }
    }
}

impl fmt::Debug for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self}")
    }
}

/// The exact values of groups of entries of one method, each group read
/// against the radicals of all of them. An error names the group and the
/// entry (`bhat[2]`), counted from 1.
pub(crate) fn read(groups: &[(&str, &[Exact])]) -> Result<Vec<Vec<Value>>, Error> {
    let mut constants: Vec<(String, String)> = Vec::new();
    for (_, entries) in groups {
        for e in entries.iter() {
            for r in &e.radicals {
                if !constants.contains(r) {
                    constants.push(r.clone());
                }
            }
        }
    }
    let index = radical_indices(&constants);
    groups
        .iter()
        .map(|(name, entries)| {
            entries
                .iter()
                .enumerate()
                .map(|(i, e)| match &e.number {
                    Some(q) => Ok(Value::from(q.clone())),
                    None if e.zero => Ok(Value::zero()),
                    None => entry_value(e, &constants, index.as_ref())
                        .map(|p| Value::from_poly(&p))
                        .map_err(|m| entry_error(format!("{name}[{}]: {m}", i + 1))),
                })
                .collect()
        })
        .collect()
}

/// A square matrix of values, row by row.
pub(crate) type Matrix = Vec<Vec<Value>>;

/// A tableau's A, read row by row with the other groups: `rows` entries
/// flattened into groups named `A[i]`.
pub(crate) fn read_matrix(
    a: &[Vec<Exact>],
    others: &[(&str, &[Exact])],
) -> Result<(Matrix, Vec<Vec<Value>>), Error> {
    let names: Vec<String> = (1..=a.len()).map(|i| format!("A[{i}]")).collect();
    let mut groups: Vec<(&str, &[Exact])> =
        a.iter().zip(&names).map(|(row, n)| (n.as_str(), row.as_slice())).collect();
    groups.extend_from_slice(others);
    let mut all = read(&groups)?;
    let rest = all.split_off(a.len());
    Ok((all, rest))
}

/// Whether every value is rational.
pub(crate) fn all_rational<'a>(values: impl IntoIterator<Item = &'a Value>) -> bool {
    values.into_iter().all(|v| v.as_rational().is_some())
}

/// `1/n` as a value.
pub(crate) fn inverse_int(n: u64) -> Value {
    Value::from(Q::new(1.into(), n.into()))
}

/// Rationals as integers over their common denominator: (d, d·x for each
/// x).
pub(crate) fn over_common(xs: &[&Q]) -> (BigInt, Vec<BigInt>) {
    let d = crate::arith::intgcd::lcm_all(xs.iter().map(|q| q.denom()));
    let ints = xs.iter().map(|q| q.numer() * (&d / q.denom())).collect();
    (d, ints)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lang::tableau::value;
    use proptest::prelude::*;

    proptest! {
        /// The quadratic form a + b√p agrees with the polynomial route
        /// (multiply the polynomials, reduce modulo g² − p, decide the sign
        /// by refinement) on sums, products, inverses and signs.
        #[test]
        fn quadratic_form_agrees_with_polynomial_route(
            (a1, b1, a2, b2) in (-40i64..40, -40i64..40, -40i64..40, -40i64..40),
            (d1, d2) in (1i64..30, 1i64..30),
            ps in prop::sample::select(vec![vec![2u64], vec![3], vec![5], vec![2, 3], vec![3, 5], vec![2, 3, 5]]),
        ) {
            let g = Monomial::from_factors(ps.iter().map(|&p| (field::generator(p, 2), 1)).collect());
            let v = |a: i64, b: i64, d: i64| {
                Value::from_poly(&Poly::from_terms([
                    (crate::q(a, d), Monomial::one()),
                    (crate::q(b, d), g.clone()),
                ]))
            };
            let (x, y) = (v(a1, b1, d1), v(a2, b2, d2));
            prop_assert_eq!(b1 != 0, matches!(x.0, Repr::Quadratic { .. }));
            // Two radicals are not of the form.
            let two = Value::from_poly(&Poly::from_terms([
                (crate::q(a1, d1), Monomial::power(field::generator(2, 2), 1)),
                (crate::q(b1, d1), Monomial::power(field::generator(3, 2), 1)),
            ]));
            prop_assert_eq!(a1 != 0 && b1 != 0, matches!(two.0, Repr::Field(_)));
            let (px, py) = (x.to_poly(), y.to_poly());
            prop_assert_eq!(x.add(&y).to_poly(), field::reduce(&(&px + &py)));
            prop_assert_eq!(x.mul(&y).to_poly(), field::reduce(&(&px * &py)));
            prop_assert_eq!(x.sign(), field::sign(&px));
            prop_assert_eq!(x.sub(&y).sign(), field::sign(&field::reduce(&(&px - &py))));
            prop_assert_eq!(x.to_string(), px.to_string());
            if let Some(inv) = x.inverse() {
                prop_assert_eq!(Some(inv.to_poly()), field::inverse(&px));
                prop_assert_eq!(inv.mul(&x), Value::one());
            }
        }
    }

    #[test]
    fn radicals_share_one_field() {
        let e = |s: &str| Exact::parse(s).unwrap();
        let v = read(&[("x", &[e("sqrt(2)"), e("root(4, 4)"), e("1/3")])]).unwrap();
        assert_eq!(v[0][0], v[0][1]);
        assert_eq!(v[0][0].mul(&v[0][0]), Value::from(Q::from_integer(2.into())));
        assert_eq!(v[0][2].as_rational(), Some(&crate::q(1, 3)));
        assert_eq!(v[0][0].sub(&Value::from(crate::q(3, 2))).sign(), Ordering::Less);
        let inv = v[0][0].inverse().unwrap();
        assert_eq!(inv.mul(&v[0][0]), Value::one());
        assert!(Value::from(crate::q(-1, 3)).within(&crate::q(1, 3)));
        assert!(!v[0][0].within(&crate::q(141, 100)));
    }

    /// An entry's value read at parse time is what a program declaring all
    /// of a method's radicals gives, whenever `entry_value` takes it; where
    /// the method's field has another generator (√2 beside root(4, 2)),
    /// the program's reading is taken.
    #[test]
    fn entry_values_read_once_match_the_program() {
        let methods: [&[&str]; 4] = [
            &["1/4 - sqrt(3)/6", "sqrt(15)/10 + 1/2", "sqrt(5)*sqrt(3)", "7*sqrt(5)/60 - 1/6"],
            &["1/(2 - cbrt(2))", "-cbrt(2)/(2 - cbrt(2))", "cbrt(4)/3"],
            &["sqrt(2)", "root(4, 2)", "sqrt(8) - 1"],
            &["sqrt(12)", "root(6, 3)", "sqrt(3)/2", "root(6, 27)"],
        ];
        let mut read_once = 0;
        for texts in methods {
            let es: Vec<Exact> = texts.iter().map(|t| Exact::parse(t).unwrap()).collect();
            let mut constants: Vec<(String, String)> = Vec::new();
            for r in es.iter().flat_map(|x| &x.radicals) {
                if !constants.contains(r) {
                    constants.push(r.clone());
                }
            }
            let index = radical_indices(&constants);
            assert!(index.is_some());
            for x in &es {
                let by_program = value(&x.expr, &constants).unwrap();
                assert_eq!(entry_value(x, &constants, index.as_ref()).unwrap(), by_program);
                if x.value.as_ref() == Some(&by_program) {
                    read_once += 1;
                }
            }
        }
        // √2 and √8 − 1 beside root(4, 2), and √12, √3/2 and root(6, 27) = √3
        // beside root(6, 3),
        // differ from their own reading; the rest do not.
        assert_eq!(read_once, 9);
    }
}
