//! Dense univariate polynomials over Q.
//!
//! [`UPoly`] is the workhorse for exact analysis once every symbol but one
//! has a value: Sturm sequences, the Schur–Cohn test, series. Coefficients are
//! stored lowest power first and the vector never ends in a zero, so the zero
//! polynomial is the empty vector and `==` is equality.

use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use crate::Q;

/// A univariate polynomial `Σ c[k] x^k` over Q.
#[derive(Clone, PartialEq, Eq, Default, Hash)]
pub struct UPoly {
    c: Vec<Q>,
}

impl UPoly {
    /// From coefficients, lowest power first; trailing zeros are dropped.
    pub fn new(mut c: Vec<Q>) -> UPoly {
        while c.last().is_some_and(Zero::is_zero) {
            c.pop();
        }
        UPoly { c }
    }

    /// From integer coefficients, lowest power first.
    pub fn from_ints(c: &[i64]) -> UPoly {
        UPoly::new(c.iter().map(|&n| Q::from_integer(n.into())).collect())
    }

    /// The zero polynomial.
    pub fn zero() -> UPoly {
        UPoly { c: Vec::new() }
    }

    /// A constant.
    pub fn constant(q: Q) -> UPoly {
        UPoly::new(vec![q])
    }

    /// The monomial `x`.
    pub fn x() -> UPoly {
        UPoly::from_ints(&[0, 1])
    }

    /// Coefficients, lowest power first.
    pub fn coeffs(&self) -> &[Q] {
        &self.c
    }

    /// The coefficient of `x^k` (zero past the degree).
    pub fn coeff(&self, k: usize) -> Q {
        self.c.get(k).cloned().unwrap_or_else(Q::zero)
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }

    /// The degree; `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }

    /// The leading coefficient (zero for the zero polynomial).
    pub fn leading(&self) -> Q {
        self.c.last().cloned().unwrap_or_else(Q::zero)
    }

    /// The value at `x`, by Horner's rule.
    pub fn eval(&self, x: &Q) -> Q {
        let mut acc = Q::zero();
        for c in self.c.iter().rev() {
            acc = acc * x + c;
        }
        acc
    }

    /// Multiplies every coefficient by `q`.
    pub fn scale(&self, q: &Q) -> UPoly {
        UPoly::new(self.c.iter().map(|c| c * q).collect())
    }

    /// This polynomial divided by its leading coefficient.
    pub fn monic(&self) -> UPoly {
        if self.is_zero() {
            return UPoly::zero();
        }
        self.scale(&(Q::one() / self.leading()))
    }

    /// The derivative.
    pub fn derivative(&self) -> UPoly {
        UPoly::new(
            self.c.iter().enumerate().skip(1).map(|(k, c)| c * Q::from_integer(k.into())).collect(),
        )
    }

    /// Quotient and remainder; panics on division by zero (a programmer error).
    #[track_caller]
    pub fn div_rem(&self, d: &UPoly) -> (UPoly, UPoly) {
        assert!(!d.is_zero(), "UPoly::div_rem by the zero polynomial");
        let dd = d.c.len() - 1;
        let lead_inv = Q::one() / d.leading();
        let mut r = self.c.clone();
        if r.len() <= dd {
            return (UPoly::zero(), self.clone());
        }
        let mut q = vec![Q::zero(); r.len() - dd];
        for k in (0..q.len()).rev() {
            let f = &r[k + dd] * &lead_inv;
            if !f.is_zero() {
                for (j, dc) in d.c.iter().enumerate() {
                    r[k + j] -= &f * dc;
                }
            }
            q[k] = f;
        }
        r.truncate(dd);
        (UPoly::new(q), UPoly::new(r))
    }

    /// The monic greatest common divisor (zero when both are zero).
    ///
    /// Coprime inputs (the common case) are recognised by one Euclid run
    /// modulo a 62-bit prime dividing neither leading coefficient (the gcd
    /// modulo p has at least the true gcd's degree); otherwise the primitive
    /// pseudo-remainder sequence over Z gives the gcd without fractions.
    pub fn gcd(&self, other: &UPoly) -> UPoly {
        if self.is_zero() {
            return other.monic();
        }
        if other.is_zero() {
            return self.monic();
        }
        if self.degree() == Some(0) || other.degree() == Some(0) {
            return UPoly::constant(Q::one());
        }
        // gcd(x^i·p, x^j·q) = x^min(i, j)·gcd(p, q): powers of x are split
        // off first (a cheap, common factor of the conditions in Φ).
        let (i, j) = (self.low_order(), other.low_order());
        if i > 0 || j > 0 {
            let g = self.shifted_down(i).gcd(&other.shifted_down(j));
            return g.shifted_up(i.min(j));
        }
        let (mut a, mut b) = (int_primitive(self), int_primitive(other));
        if crate::stability::modular::coprime_mod_p(&a, &b) {
            return UPoly::constant(Q::one());
        }
        if a.len() < b.len() {
            std::mem::swap(&mut a, &mut b);
        }
        while !b.is_empty() {
            let (r, _) = prem(&a, &b);
            a = b;
            b = primitive(r);
        }
        UPoly::new(a.into_iter().map(Q::from_integer).collect()).monic()
    }

    /// The exponent of the largest power of x dividing a non-zero `p`.
    fn low_order(&self) -> usize {
        self.c.iter().position(|c| !c.is_zero()).unwrap_or(0)
    }

    /// `p / x^k`, for x^k dividing `p`.
    fn shifted_down(&self, k: usize) -> UPoly {
        UPoly { c: self.c[k..].to_vec() }
    }

    /// `x^k·p`.
    fn shifted_up(mut self, k: usize) -> UPoly {
        if k > 0 && !self.c.is_empty() {
            self.c.splice(0..0, std::iter::repeat_n(Q::zero(), k));
        }
        self
    }

    /// The square-free part `p / gcd(p, p')`, monic.
    pub fn squarefree(&self) -> UPoly {
        if self.degree().unwrap_or(0) == 0 {
            return self.monic();
        }
        // A factor x^k (conditions in Φ often carry a high power of Φ, and
        // with it a gcd of high degree): sf(x^k·q) = x·sf(q) for q(0) ≠ 0,
        // so the gcd runs on q alone, which is usually coprime to q′ (a
        // check modulo a prime, no remainder sequence).
        let low = self.low_order();
        if low > 0 {
            return self.shifted_down(low).squarefree().shifted_up(1);
        }
        let g = self.gcd(&self.derivative());
        if g.degree() == Some(0) {
            return self.monic();
        }
        // g divides p; over Z (Gauss) the quotient of the primitive forms is
        // exact, so divide without fractions.
        let q = exact_div_int(&int_primitive(self), &int_primitive(&g));
        UPoly::new(q.into_iter().map(Q::from_integer).collect()).monic()
    }

    /// `p(q(x))`.
    pub fn compose(&self, q: &UPoly) -> UPoly {
        let mut acc = UPoly::zero();
        for c in self.c.iter().rev() {
            acc = &(&acc * q) + &UPoly::constant(c.clone());
        }
        acc
    }

    /// `x^n p(1/x)` where `n` is the degree: the coefficient list reversed.
    pub fn reversed(&self) -> UPoly {
        UPoly::new(self.c.iter().rev().cloned().collect())
    }

    /// `p(-x)`.
    pub fn negate_x(&self) -> UPoly {
        UPoly::new(
            self.c
                .iter()
                .enumerate()
                .map(|(k, c)| if k % 2 == 1 { -c } else { c.clone() })
                .collect(),
        )
    }

    /// `x^k p(x)`.
    pub fn shift(&self, k: usize) -> UPoly {
        if self.is_zero() {
            return UPoly::zero();
        }
        let mut c = vec![Q::zero(); k];
        c.extend(self.c.iter().cloned());
        UPoly { c }
    }

    /// The polynomial written in the variable `var`, in the crate's plain
    /// text form (highest power first).
    pub fn to_string_in(&self, var: &str) -> String {
        if self.is_zero() {
            return "0".into();
        }
        let mut s = String::new();
        for (k, c) in self.c.iter().enumerate().rev().filter(|(_, c)| !c.is_zero()) {
            let neg = c.is_negative();
            let a = c.abs();
            if s.is_empty() {
                if neg {
                    s.push('-');
                }
            } else {
                s.push_str(if neg { " - " } else { " + " });
            }
            let mono = match k {
                0 => String::new(),
                1 => var.to_owned(),
                _ => format!("{var}^{k}"),
            };
            match (mono.is_empty(), a.is_one()) {
                (true, _) => s.push_str(&a.to_string()),
                (false, true) => s.push_str(&mono),
                (false, false) => s.push_str(&format!("{a}*{mono}")),
            }
        }
        s
    }
}

impl fmt::Display for UPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_string_in("x"))
    }
}

impl fmt::Debug for UPoly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "UPoly({self})")
    }
}

impl<'a> Add<&'a UPoly> for &'a UPoly {
    type Output = UPoly;
    fn add(self, rhs: &UPoly) -> UPoly {
        let n = self.c.len().max(rhs.c.len());
        UPoly::new((0..n).map(|k| self.coeff(k) + rhs.coeff(k)).collect())
    }
}

impl<'a> Sub<&'a UPoly> for &'a UPoly {
    type Output = UPoly;
    fn sub(self, rhs: &UPoly) -> UPoly {
        let n = self.c.len().max(rhs.c.len());
        UPoly::new((0..n).map(|k| self.coeff(k) - rhs.coeff(k)).collect())
    }
}

impl<'a> Mul<&'a UPoly> for &'a UPoly {
    type Output = UPoly;
    fn mul(self, rhs: &UPoly) -> UPoly {
        if self.is_zero() || rhs.is_zero() {
            return UPoly::zero();
        }
        let mut c = vec![Q::zero(); self.c.len() + rhs.c.len() - 1];
        for (i, a) in self.c.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for (j, b) in rhs.c.iter().enumerate() {
                c[i + j] += a * b;
            }
        }
        UPoly::new(c)
    }
}

impl Neg for &UPoly {
    type Output = UPoly;
    fn neg(self) -> UPoly {
        UPoly { c: self.c.iter().map(|c| -c).collect() }
    }
}

/// The coefficients scaled by a positive rational to primitive integers.
pub(crate) fn int_primitive(p: &UPoly) -> Vec<BigInt> {
    let mut den = BigInt::one();
    for q in p.coeffs() {
        den = crate::intgcd::lcm(&den, q.denom());
    }
    primitive(p.coeffs().iter().map(|q| q.numer() * (&den / q.denom())).collect())
}

/// a / b for integer polynomials (lowest power first) when b divides a in
/// Z[x]; every division of coefficients is exact.
pub(crate) fn exact_div_int(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    let n = b.len() - 1;
    let lb = &b[n];
    let mut r = a.to_vec();
    if r.len() <= n {
        return Vec::new();
    }
    let mut q = vec![BigInt::zero(); r.len() - n];
    for k in (0..q.len()).rev() {
        let c = &r[k + n] / lb;
        debug_assert!((&c * lb) == r[k + n], "exact division");
        if !c.is_zero() {
            for (j, bj) in b.iter().enumerate() {
                r[k + j] -= &c * bj;
            }
        }
        q[k] = c;
    }
    debug_assert!(r.iter().all(Zero::is_zero), "b divides a");
    q
}

/// The non-negative gcd of the integers, with the running gcd reduced into
/// each next number first (a cheap remainder when the gcd is small, which
/// binary gcd on a long number is not), stopping at 1.
pub(crate) fn content<'a>(xs: impl IntoIterator<Item = &'a BigInt>) -> BigInt {
    let mut g = BigInt::zero();
    for x in xs {
        if x.is_zero() {
            continue;
        }
        g = if g.is_zero() { x.abs() } else { crate::intgcd::gcd(&g, &(x % &g)) };
        if g.is_one() {
            break;
        }
    }
    g
}

/// Divides by the (positive) gcd of the coefficients; trailing zeros dropped.
pub(crate) fn primitive(mut c: Vec<BigInt>) -> Vec<BigInt> {
    while c.last().is_some_and(Zero::is_zero) {
        c.pop();
    }
    // Smallest first: the running gcd is small from the start.
    let mut order: Vec<&BigInt> = c.iter().filter(|x| !x.is_zero()).collect();
    order.sort_by_key(|x| x.bits());
    let g = content(order);
    if !g.is_zero() && !g.is_one() {
        for x in &mut c {
            *x /= &g;
        }
    }
    c
}

/// The pseudo-remainder over Z: (r, k) with lc(b)^k·a = q·b + r, deg r <
/// deg b; `b` non-zero.
pub(crate) fn prem(a: &[BigInt], b: &[BigInt]) -> (Vec<BigInt>, usize) {
    let n = b.len() - 1;
    let lb = &b[n];
    let mut r = a.to_vec();
    let mut k = 0;
    while r.len() > n && !r.is_empty() {
        let s = r.len() - 1 - n;
        let lr = r.last().expect("non-empty").clone();
        for x in r.iter_mut() {
            *x *= lb;
        }
        for (j, bj) in b.iter().enumerate() {
            r[s + j] -= &lr * bj;
        }
        k += 1;
        while r.last().is_some_and(Zero::is_zero) {
            r.pop();
        }
    }
    (r, k)
}
