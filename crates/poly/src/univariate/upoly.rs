//! Dense univariate polynomials over Q.
//!
//! [`UPoly`] is the workhorse for exact analysis once every symbol but one
//! has a value: Sturm sequences, the Schur–Cohn test, series. Coefficients are
//! stored lowest power first and the vector never ends in a zero, so the zero
//! polynomial is the empty vector and `==` is equality.

use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::{Arc, OnceLock};

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use crate::Q;

/// A univariate polynomial `Σ c[k] x^k` over Q.
#[derive(Clone, Default)]
pub struct UPoly {
    c: Vec<Q>,
    /// The primitive integer form ([`int_primitive`]), kept once computed
    /// or once known (a monic polynomial made from integers): the analysis
    /// asks for it on the same square-free part many times, and each time
    /// was an lcm of the denominators and a content. Never part of `==`.
    ints: OnceLock<Arc<[BigInt]>>,
}

impl PartialEq for UPoly {
    fn eq(&self, other: &UPoly) -> bool {
        self.c == other.c
    }
}

impl Eq for UPoly {}

impl std::hash::Hash for UPoly {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.c.hash(state);
    }
}

impl UPoly {
    /// From coefficients, lowest power first; trailing zeros are dropped.
    pub fn new(mut c: Vec<Q>) -> UPoly {
        while c.last().is_some_and(Zero::is_zero) {
            c.pop();
        }
        UPoly { c, ints: OnceLock::new() }
    }

    /// From integer coefficients, lowest power first.
    pub fn from_ints(c: &[i64]) -> UPoly {
        UPoly::new(c.iter().map(|&n| Q::from_integer(n.into())).collect())
    }

    /// The zero polynomial.
    pub fn zero() -> UPoly {
        UPoly::new(Vec::new())
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
        // Over a common denominator d of the coefficients, with x = p/q:
        // Σ C_k p^k q^(n−k) / (d·q^n), one reduction at the end instead of
        // one per step of Horner's rule over Q.
        let Some(n) = self.degree() else { return Q::zero() };
        let (num, den) = self.common_denominator();
        let (p, q) = (x.numer(), x.denom());
        let mut acc = BigInt::zero();
        let mut qpow = BigInt::one();
        for (k, c) in num.iter().enumerate().rev() {
            acc = acc * p + c * &qpow;
            if k > 0 {
                qpow *= q;
            }
        }
        debug_assert_eq!(qpow, num_traits::pow(q.clone(), n));
        reduced(acc, den * qpow)
    }

    /// The coefficients as integers over one positive denominator (the lcm
    /// of theirs).
    fn common_denominator(&self) -> (Vec<BigInt>, BigInt) {
        if self.c.iter().all(|c| c.denom().is_one()) {
            return (self.c.iter().map(|c| c.numer().clone()).collect(), BigInt::one());
        }
        let mut den = BigInt::one();
        for c in &self.c {
            if !c.denom().is_one() {
                den = crate::arith::intgcd::lcm(&den, c.denom());
            }
        }
        let num = self.c.iter().map(|c| c.numer() * (&den / c.denom())).collect();
        (num, den)
    }

    /// Σ num[k] x^k / den, each coefficient reduced once.
    fn from_common(num: Vec<BigInt>, den: &BigInt) -> UPoly {
        if den.is_one() {
            return UPoly::new(num.into_iter().map(Q::from_integer).collect());
        }
        UPoly::new(num.into_iter().map(|c| reduced(c, den.clone())).collect())
    }

    /// Multiplies every coefficient by `q`.
    pub fn scale(&self, q: &Q) -> UPoly {
        if q.is_zero() {
            return UPoly::zero();
        }
        let (num, den) = self.common_denominator();
        let num = num.into_iter().map(|c| c * q.numer()).collect();
        UPoly::from_common(num, &(den * q.denom()))
    }

    /// This polynomial divided by its leading coefficient.
    pub fn monic(&self) -> UPoly {
        if self.is_zero() {
            return UPoly::zero();
        }
        let (num, _) = self.common_denominator();
        let lead = num.last().expect("non-zero").clone();
        let out = UPoly::new(num.iter().map(|c| reduced(c.clone(), lead.clone())).collect());
        // The monic polynomial's primitive integer form is num's, with the
        // sign that makes its leading coefficient positive.
        let mut ints = primitive(num);
        if lead.is_negative() {
            ints.iter_mut().for_each(|x| *x = -&*x);
        }
        let _ = out.ints.set(ints.into());
        out
    }

    /// The derivative.
    pub fn derivative(&self) -> UPoly {
        let (num, den) = self.common_denominator();
        let num = num.into_iter().enumerate().skip(1).map(|(k, c)| c * BigInt::from(k)).collect();
        UPoly::from_common(num, &den)
    }

    /// Quotient and remainder; panics on division by zero (a programmer error).
    #[track_caller]
    pub fn div_rem(&self, d: &UPoly) -> (UPoly, UPoly) {
        assert!(!d.is_zero(), "UPoly::div_rem by the zero polynomial");
        let dd = d.c.len() - 1;
        let lead_inv = d.leading().recip();
        let mut r = self.c.clone();
        if r.len() <= dd {
            return (UPoly::zero(), self.clone());
        }
        // Products and sums reduced by Lehmer's gcd (`arith::rational`),
        // not num-rational's binary one.
        use crate::arith::rational::{add, mul};
        let minus: Vec<Q> = d.c.iter().map(|c| -c).collect();
        let mut q = vec![Q::zero(); r.len() - dd];
        for k in (0..q.len()).rev() {
            let f = mul(&r[k + dd], &lead_inv);
            if !f.is_zero() {
                for (j, dc) in minus.iter().enumerate() {
                    if !dc.is_zero() {
                        r[k + j] = add(&r[k + j], &mul(&f, dc));
                    }
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
        if crate::arith::zp::coprime_mod_p(&a, &b) {
            return UPoly::constant(Q::one());
        }
        // Modulo primes first; the remainder sequence (the oracle of the
        // tests) only when they do not settle it.
        if let Some(g) = crate::arith::zp::gcd_int(&a, &b) {
            return UPoly::new(g.into_iter().map(Q::from_integer).collect()).monic();
        }
        if a.len() < b.len() {
            std::mem::swap(&mut a, &mut b);
        }
        gcd_prs(a, b)
    }

    /// F with p(x) = F(x²), for an even p of degree ≥ 2 (`None` otherwise).
    pub(crate) fn even_part(&self) -> Option<UPoly> {
        let even =
            self.c.len() >= 3 && self.c.iter().enumerate().all(|(k, c)| k % 2 == 0 || c.is_zero());
        even.then(|| UPoly::new(self.c.iter().step_by(2).cloned().collect()))
    }

    /// F(x²) for this F (the inverse of [`UPoly::even_part`]).
    pub(crate) fn spread(&self) -> UPoly {
        let mut c = Vec::with_capacity(2 * self.c.len());
        for (k, x) in self.c.iter().enumerate() {
            if k > 0 {
                c.push(Q::zero());
            }
            c.push(x.clone());
        }
        UPoly::new(c)
    }

    /// The exponent of the largest power of x dividing a non-zero `p`.
    fn low_order(&self) -> usize {
        self.c.iter().position(|c| !c.is_zero()).unwrap_or(0)
    }

    /// `p / x^k`, for x^k dividing `p`.
    fn shifted_down(&self, k: usize) -> UPoly {
        UPoly::new(self.c[k..].to_vec())
    }

    /// `x^k·p`.
    fn shifted_up(mut self, k: usize) -> UPoly {
        if k > 0 && !self.c.is_empty() {
            self.c.splice(0..0, std::iter::repeat_n(Q::zero(), k));
            self.ints = OnceLock::new();
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
        // An even p = F(x²) with F(0) ≠ 0: sf(p) = sf(F)(x²) (each square-free
        // factor f of F gives f(x²), square-free since f(0) ≠ 0), at half
        // the degree.
        if let Some(big_f) = self.even_part() {
            return big_f.squarefree().spread();
        }
        // a·x² + b·x + c is a square exactly when b² = 4ac, then sf = x + b/(2a)
        // (a second-order χ's discriminant is often minus a square; no gcd).
        if let [c, b, a] = &self.ints.get_or_init(|| int_primitive_of(self).into())[..] {
            return if b * b != ((a * c) << 2) {
                self.monic()
            } else {
                UPoly::new(vec![Q::new(b.clone(), a << 1), Q::one()])
            };
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
        UPoly::new(c)
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
        combine(self, rhs, false)
    }
}

impl<'a> Sub<&'a UPoly> for &'a UPoly {
    type Output = UPoly;
    fn sub(self, rhs: &UPoly) -> UPoly {
        combine(self, rhs, true)
    }
}

impl<'a> Mul<&'a UPoly> for &'a UPoly {
    type Output = UPoly;
    fn mul(self, rhs: &UPoly) -> UPoly {
        if self.is_zero() || rhs.is_zero() {
            return UPoly::zero();
        }
        let ((a, da), (b, db)) = (self.common_denominator(), rhs.common_denominator());
        let mut c = vec![BigInt::zero(); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            if x.is_zero() {
                continue;
            }
            for (j, y) in b.iter().enumerate() {
                c[i + j] += x * y;
            }
        }
        UPoly::from_common(c, &(da * db))
    }
}

/// a ± b over the least common denominator, each coefficient reduced once.
fn combine(a: &UPoly, b: &UPoly, subtract: bool) -> UPoly {
    let ((mut x, dx), (y, dy)) = (a.common_denominator(), b.common_denominator());
    let den = if dx == dy { dx.clone() } else { crate::arith::intgcd::lcm(&dx, &dy) };
    let (fx, fy) = (&den / &dx, &den / &dy);
    if !fx.is_one() {
        for c in &mut x {
            *c *= &fx;
        }
    }
    if x.len() < y.len() {
        x.resize(y.len(), BigInt::zero());
    }
    for (c, d) in x.iter_mut().zip(y) {
        let d = if fy.is_one() { d } else { d * &fy };
        if subtract {
            *c -= d;
        } else {
            *c += d;
        }
    }
    UPoly::from_common(x, &den)
}

/// n/d in lowest terms with d > 0 (d ≠ 0), by Lehmer's gcd (num-rational
/// reduces with num-bigint's binary gcd, one pass per bit even when d = 1).
pub(crate) fn reduced(n: BigInt, d: BigInt) -> Q {
    debug_assert!(!d.is_zero());
    if n.is_zero() {
        return Q::zero();
    }
    let (n, d) = if d.is_negative() { (-n, -d) } else { (n, d) };
    if d.is_one() {
        return Q::from_integer(n);
    }
    let g = crate::arith::intgcd::gcd(&n, &d);
    if g.is_one() {
        Q::new_raw(n, d)
    } else {
        Q::new_raw(n / &g, d / g)
    }
}

impl Neg for &UPoly {
    type Output = UPoly;
    fn neg(self) -> UPoly {
        UPoly::new(self.c.iter().map(|c| -c).collect())
    }
}

/// The coefficients scaled by a positive rational to primitive integers.
/// The quotient of the integer polynomial `c` (lowest first) by x − r for
/// a rational root r = a/b of it: by Gauss's lemma the quotient by b·x − a
/// has integer coefficients, the same up to the positive factor b.
/// Synthetic division from the top, each step an exact division by b.
pub(crate) fn divide_linear(c: &[BigInt], r: &Q) -> Vec<BigInt> {
    let (a, b) = (r.numer(), r.denom());
    let m = c.len() - 1;
    let mut q = vec![BigInt::zero(); m];
    q[m - 1] = &c[m] / b;
    for k in (1..m).rev() {
        q[k - 1] = (&c[k] + a * &q[k]) / b;
    }
    debug_assert!((&c[0] + a * &q[0]).is_zero(), "r is a root");
    q
}

/// The monic gcd of two primitive integer polynomials (lowest first,
/// `a` at least as long as `b`) by the primitive remainder sequence: the
/// slow oracle of [`crate::arith::zp::gcd_int`], and its fallback.
pub(crate) fn gcd_prs(mut a: Vec<BigInt>, mut b: Vec<BigInt>) -> UPoly {
    while !b.is_empty() {
        let (r, _) = prem(&a, &b);
        a = b;
        b = primitive(r);
    }
    UPoly::new(a.into_iter().map(Q::from_integer).collect()).monic()
}

pub(crate) fn int_primitive(p: &UPoly) -> Vec<BigInt> {
    p.ints.get_or_init(|| int_primitive_of(p).into()).to_vec()
}

/// [`int_primitive`] computed afresh: the oracle of the kept form.
pub(crate) fn int_primitive_of(p: &UPoly) -> Vec<BigInt> {
    let mut den = BigInt::one();
    for q in p.coeffs() {
        if !q.denom().is_one() {
            den = crate::arith::intgcd::lcm(&den, q.denom());
        }
    }
    // Integer coefficients (χ's, scaled once, and their combinations) are
    // taken as they are: no division by one.
    let num =
        |q: &Q| if *q.denom() == den { q.numer().clone() } else { q.numer() * (&den / q.denom()) };
    primitive(p.coeffs().iter().map(num).collect())
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
        g = if g.is_zero() { x.abs() } else { crate::arith::intgcd::gcd(&g, &(x % &g)) };
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

/// For a palindromic g of even degree 2m (coefficients lowest first), G with
/// g(z) = z^m G(z + 1/z): G = c_m + Σ_k c_{m+k} D_k(x), D_k(z + 1/z) = z^k + z^{−k}.
pub(crate) fn reciprocal_reduce<T: Clone>(
    c: &[T],
    zero: T,
    add: impl Fn(&T, &T) -> T,
    scale_int: impl Fn(&T, i64) -> T,
) -> Vec<T> {
    let m = (c.len() - 1) / 2;
    // D_k as integer polynomials in x.
    let mut d: Vec<Vec<i64>> = vec![vec![2], vec![0, 1]];
    for k in 2..=m {
        let mut next = vec![0i64; k + 1];
        for (i, &v) in d[k - 1].iter().enumerate() {
            next[i + 1] += v;
        }
        for (i, &v) in d[k - 2].iter().enumerate() {
            next[i] -= v;
        }
        d.push(next);
    }
    let mut g = vec![zero.clone(); m + 1];
    g[0] = add(&g[0], &c[m]);
    for k in 1..=m {
        for (i, &v) in d[k].iter().enumerate() {
            if v != 0 {
                g[i] = add(&g[i], &scale_int(&c[m + k], v));
            }
        }
    }
    g
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn rational_poly() -> impl Strategy<Value = UPoly> {
        proptest::collection::vec((-60i64..60, 1i64..13), 0..7).prop_map(|c| {
            UPoly::new(c.into_iter().map(|(n, d)| Q::new(n.into(), d.into())).collect())
        })
    }

    /// The obvious coefficient-wise arithmetic over Q (num-rational).
    fn coeff(p: &UPoly, k: usize) -> Q {
        p.c.get(k).cloned().unwrap_or_else(Q::zero)
    }

    proptest! {
        /// The integer form kept by `monic`, `squarefree` and `gcd` is the
        /// one computed afresh, as is the one kept after `shifted_up`.
        #[test]
        fn kept_integer_form_is_the_fresh_one(
            num in proptest::collection::vec(-60i64..60, 1..8),
            den in proptest::collection::vec(1i64..30, 1..8),
            k in 0usize..3,
        ) {
            let p = UPoly::new(num.iter().zip(den.iter().cycle()).map(|(&n, &d)| Q::new(n.into(), d.into())).collect());
            prop_assume!(!p.is_zero());
            let q = &p * &p;
            // `monic` seeds the form: what is compared below is the seed.
            prop_assert!(p.monic().ints.get().is_some());
            for u in [p.monic(), p.squarefree(), q.squarefree(), q.gcd(&p), p.monic().shifted_up(k)] {
                prop_assert_eq!(int_primitive(&u), int_primitive_of(&u));
            }
            // The fresh form against the obvious one: times the product of
            // the denominators, over the gcd of the integers (with integer
            // coefficients, and without).
            let ints = UPoly::new(num.iter().map(|&n| Q::from_integer(n.into())).collect());
            for u in [p, q, ints] {
                let all: BigInt = u.coeffs().iter().map(|c| c.denom().clone()).product();
                let scaled: Vec<BigInt> = u.coeffs().iter().map(|c| (c * Q::from_integer(all.clone())).to_integer()).collect();
                let g = scaled.iter().fold(BigInt::zero(), |g, x| num_integer::Integer::gcd(&g, x));
                let slow: Vec<BigInt> = scaled.iter().map(|x| x / &g).collect();
                prop_assert_eq!(int_primitive_of(&u), slow);
            }
        }
    }

    proptest! {
        /// Synthetic division by x − a/b returns q from q·(b·x − a) exactly
        /// (times b/b′ when a/b reduces to a′/b′: it divides by b′·x − a′).
        #[test]
        fn divide_linear_undoes_the_product(
            q in proptest::collection::vec(-50i64..50, 1..7), a in -30i64..30, b in 1i64..12,
        ) {
            prop_assume!(*q.last().unwrap() != 0);
            let qp = UPoly::from_ints(&q);
            let f = &qp * &UPoly::from_ints(&[-a, b]);
            let c: Vec<BigInt> = f.coeffs().iter().map(|x| x.to_integer()).collect();
            let r = Q::new(a.into(), b.into());
            let scale = BigInt::from(b) / r.denom();
            let expected: Vec<BigInt> = q.iter().map(|&x| BigInt::from(x) * &scale).collect();
            prop_assert_eq!(divide_linear(&c, &r), expected);
        }
    }

    proptest! {
        /// The modular gcd agrees with the primitive remainder sequence, on
        /// products with a common factor, with large coefficients (scaled
        /// by a 200-bit number) and with leading coefficients that share
        /// factors.
        #[test]
        fn modular_gcd_matches_the_remainder_sequence(
            f in proptest::collection::vec(-40i64..40, 1..6),
            g in proptest::collection::vec(-40i64..40, 1..6),
            h in proptest::collection::vec(-40i64..40, 1..6),
            big in 0u32..3,
        ) {
            let (f, g, h) = (UPoly::from_ints(&f), UPoly::from_ints(&g), UPoly::from_ints(&h));
            prop_assume!(!f.is_zero() && !g.is_zero() && !h.is_zero());
            let lift = Q::from_integer(BigInt::from(3).pow(40 * big) + 1);
            let (a, b) = (&(&f * &h) * &h, &(&g * &h).scale(&lift) + &f.scale(&Q::from_integer(BigInt::from(big))));
            prop_assume!(!a.is_zero() && !b.is_zero() && a.degree() > Some(0) && b.degree() > Some(0));
            let (ia, ib) = (int_primitive(&a), int_primitive(&b));
            let oracle = if ia.len() >= ib.len() { gcd_prs(ia.clone(), ib.clone()) } else { gcd_prs(ib.clone(), ia.clone()) };
            match crate::arith::zp::gcd_int(&ia, &ib) {
                Some(g) => prop_assert_eq!(UPoly::new(g.into_iter().map(Q::from_integer).collect()).monic(), oracle),
                None => prop_assert!(false, "the modular gcd gave up"),
            }
        }
    }

    proptest! {
        /// The even route of `squarefree` (through F with p = F(x²)) agrees
        /// with p / gcd(p, p′), on products with repeated even factors.
        #[test]
        fn even_squarefree_matches_the_gcd_route(
            f in proptest::collection::vec(-9i64..9, 1..4),
            g in proptest::collection::vec(-9i64..9, 1..4),
            power in 1usize..3,
        ) {
            prop_assume!(f[0] != 0 && g[0] != 0);
            let (f, g) = (UPoly::from_ints(&f), UPoly::from_ints(&g));
            prop_assume!(!f.is_zero() && !g.is_zero());
            let mut big_f = f.clone();
            for _ in 0..power {
                big_f = &big_f * &f;
            }
            let big_f = &big_f * &g;
            let p = big_f.spread();
            prop_assume!(p.degree().unwrap_or(0) >= 2);
            prop_assert_eq!(p.even_part(), Some(big_f));
            let oracle = p.div_rem(&p.gcd(&p.derivative())).0.monic();
            prop_assert_eq!(p.squarefree(), oracle);
        }
    }

    proptest! {
        /// The common-denominator paths agree with plain rational arithmetic.
        #[test]
        fn integer_paths_match_rational_arithmetic(
            a in rational_poly(), b in rational_poly(), n in -40i64..40, d in 1i64..9,
        ) {
            let x = Q::new(n.into(), d.into());
            let len = a.c.len().max(b.c.len());
            let sum = UPoly::new((0..len).map(|k| coeff(&a, k) + coeff(&b, k)).collect());
            let diff = UPoly::new((0..len).map(|k| coeff(&a, k) - coeff(&b, k)).collect());
            prop_assert_eq!(&a + &b, sum);
            prop_assert_eq!(&a - &b, diff);
            let mut prod = vec![Q::zero(); (a.c.len() + b.c.len()).saturating_sub(1)];
            for (i, u) in a.c.iter().enumerate() {
                for (j, v) in b.c.iter().enumerate() {
                    prod[i + j] += u * v;
                }
            }
            prop_assert_eq!(&a * &b, UPoly::new(prod));
            prop_assert_eq!(a.scale(&x), UPoly::new(a.c.iter().map(|c| c * &x).collect()));
            let deriv = a.c.iter().enumerate().skip(1).map(|(k, c)| c * Q::from_integer(k.into()));
            prop_assert_eq!(a.derivative(), UPoly::new(deriv.collect()));
            let horner = a.c.iter().rev().fold(Q::zero(), |acc, c| acc * &x + c);
            prop_assert_eq!(a.eval(&x), horner);
            if !a.is_zero() {
                let lead = a.leading();
                prop_assert_eq!(a.monic(), UPoly::new(a.c.iter().map(|c| c / &lead).collect()));
            }
            // Canonical form: every coefficient in lowest terms, positive
            // denominator (what `==` and hashing of Q rely on).
            let value = a.eval(&x);
            for c in (&a * &b).c.iter().chain((&a - &b).c.iter()).chain([&value]) {
                let r = Q::new(c.numer().clone(), c.denom().clone());
                prop_assert_eq!(r.numer(), c.numer());
                prop_assert_eq!(r.denom(), c.denom());
            }
        }
    }
}
