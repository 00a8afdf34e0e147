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

use num_traits::{One, Signed, Zero};

use crate::error::Error;
use crate::lang::tableau::{entry_error, value, Exact};
use crate::multivariate::constants as field;
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
    /// A reduced polynomial in generator symbols that is not a constant.
    Field(Poly),
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
        match p.as_constant() {
            Some(q) => Value(Repr::Rational(q)),
            None => Value(Repr::Field(p)),
        }
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
            Repr::Field(_) => None,
        }
    }

    /// The number as a polynomial in the generator symbols (a constant
    /// polynomial when it is rational).
    pub fn to_poly(&self) -> Poly {
        match &self.0 {
            Repr::Rational(q) => Poly::constant(q.clone()),
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
            Repr::Field(p) => field::sign(p),
        }
    }

    /// A rational within `width` of the number.
    pub fn approx(&self, width: &Q) -> Q {
        match &self.0 {
            Repr::Rational(q) => q.clone(),
            Repr::Field(p) => field::approx(p, width),
        }
    }

    /// The inverse; `None` for zero.
    pub fn inverse(&self) -> Option<Value> {
        match &self.0 {
            Repr::Rational(q) if q.is_zero() => None,
            Repr::Rational(q) => Some(Value(Repr::Rational(q.recip()))),
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
            Repr::Field(p) => Value(Repr::Field(-p)),
        }
    }

    pub(crate) fn add(&self, o: &Value) -> Value {
        match (&self.0, &o.0) {
            (Repr::Rational(a), Repr::Rational(b)) => Value(Repr::Rational(a + b)),
            _ => Value::from_poly(&(&self.to_poly() + &o.to_poly())),
        }
    }

    pub(crate) fn sub(&self, o: &Value) -> Value {
        self.add(&o.neg())
    }

    pub(crate) fn mul(&self, o: &Value) -> Value {
        match (&self.0, &o.0) {
            (Repr::Rational(a), Repr::Rational(b)) => Value(Repr::Rational(a * b)),
            (Repr::Rational(a), Repr::Field(p)) | (Repr::Field(p), Repr::Rational(a)) => {
                if a.is_zero() {
                    Value::zero()
                } else {
                    Value(Repr::Field(p.scale(a)))
                }
            }
            (Repr::Field(p), Repr::Field(r)) => Value::from_poly(&(p * r)),
        }
    }

    /// self ≤ bound, in absolute value: |self| ≤ bound.
    pub(crate) fn within(&self, bound: &Q) -> bool {
        match &self.0 {
            Repr::Rational(q) => q.abs() <= *bound,
            Repr::Field(_) => {
                self.abs().sub(&Value::from(bound.clone())).sign() != Ordering::Greater
            }
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
    groups
        .iter()
        .map(|(name, entries)| {
            entries
                .iter()
                .enumerate()
                .map(|(i, e)| match &e.number {
                    Some(q) => Ok(Value::from(q.clone())),
                    None if e.zero => Ok(Value::zero()),
                    None => value(&e.expr, &constants)
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
