//! Sturm sequences over Q: exact counting and isolation of real roots.
//!
//! For a square-free polynomial p the Sturm sequence p₀ = p, p₁ = p′,
//! p_{k+1} = −rem(p_{k−1}, p_k) satisfies Sturm's theorem: the number of
//! distinct real roots in (a, b] is V(a) − V(b), where V(x) counts the sign
//! changes of the sequence at x (zeros skipped). The half-open interval comes
//! for free: at a root c of a square-free p the remaining terms keep their
//! signs, so V(c) = V(c⁺). Every count here works on the square-free part, so
//! repeated roots count once.
//!
//! Isolation bisects a power-of-two Cauchy bound, so every endpoint is a
//! dyadic rational. An isolating interval `(lo, hi)` with `lo < hi` holds
//! exactly one root strictly inside, and p(lo), p(hi) are non-zero with
//! opposite signs, which lets callers refine by sign alone; a rational root
//! met on the way is returned as the degenerate interval `(r, r)`.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

use crate::arith::rational::{eq, ratio};
use crate::{UPoly, Q};

/// A polynomial scaled by a positive rational to primitive integer
/// coefficients: the same signs everywhere, evaluated without fractions.
///
/// When every coefficient fits in an `i64` a copy is kept in that form:
/// evaluations then run in `i128` with checked operations and fall back to
/// `BigInt` on overflow (the same values, so the same signs).
#[derive(Clone, Debug)]
pub(crate) struct IntPoly {
    c: Vec<BigInt>,
    small: Option<Box<[i64]>>,
}

/// The least and the greatest of x·y over x ∈ [l, u], y ∈ [a, b] (l ≤ u,
/// a ≤ b): two products where the signs of a and b tell which, four
/// otherwise.
fn interval_product(l: &BigInt, u: &BigInt, a: &BigInt, b: &BigInt) -> (BigInt, BigInt) {
    if !a.is_negative() {
        // y ≥ 0: x·y grows with x, and |y| is largest at b.
        return if !l.is_negative() {
            (l * a, u * b)
        } else if !u.is_positive() {
            (l * b, u * a)
        } else {
            (l * b, u * b)
        };
    }
    if !b.is_positive() {
        // y ≤ 0: x·y = −(x·(−y)), with −y ∈ [−b, −a] not negative.
        let (min, max) = interval_product(l, u, &-b, &-a);
        return (-max, -min);
    }
    let p = [l * a, l * b, u * a, u * b];
    let min = p.iter().min().expect("four products").clone();
    let max = p.iter().max().expect("four products").clone();
    (min, max)
}

/// t when `q` = 2^t (q > 0).
fn power_of_two(q: &BigInt) -> Option<u64> {
    let t = q.trailing_zeros()?;
    (q.bits() == t + 1).then_some(t)
}

/// `x` as an `i128` when it fits in an `i64` (so products of two fit).
fn small(x: &BigInt) -> Option<i128> {
    num_traits::ToPrimitive::to_i64(x).map(i128::from)
}

/// Σ c_k p^k q^(n−k) in `i128`, `None` on overflow.
fn homogeneous_small(c: &[i64], p: i128, q: i128) -> Option<i128> {
    let (&top, rest) = c.split_last()?;
    let mut acc = i128::from(top);
    let mut qk: i128 = 1;
    for &ck in rest.iter().rev() {
        qk = qk.checked_mul(q)?;
        acc = acc.checked_mul(p)?.checked_add(i128::from(ck).checked_mul(qk)?)?;
    }
    Some(acc)
}

/// [`IntPoly::sign_on`] on `i128` (`None` on overflow, `Some(None)` when
/// the enclosure holds zero).
fn sign_on_small(c: &[i64], a: i128, b: i128, q: i128) -> Option<Option<Ordering>> {
    let (&top, rest) = c.split_last()?;
    let (mut l, mut u) = (i128::from(top), i128::from(top));
    let mut qk: i128 = 1;
    for &ck in rest.iter().rev() {
        qk = qk.checked_mul(q)?;
        let p = [l.checked_mul(a)?, l.checked_mul(b)?, u.checked_mul(a)?, u.checked_mul(b)?];
        let (min, max) = (p.iter().min()?, p.iter().max()?);
        let t = i128::from(ck).checked_mul(qk)?;
        (l, u) = (min.checked_add(t)?, max.checked_add(t)?);
    }
    Some(if l > 0 {
        Some(Ordering::Greater)
    } else if u < 0 {
        Some(Ordering::Less)
    } else {
        None
    })
}

impl IntPoly {
    /// The primitive integer form of `p` (the one `p` keeps, once known).
    pub(crate) fn new(p: &UPoly) -> IntPoly {
        IntPoly::from_ints(crate::univariate::upoly::int_primitive(p))
    }

    /// From integer coefficients (lowest power first, trimmed), taken as
    /// they are: the signs, not the scale, are what the evaluations give.
    pub(crate) fn from_ints(c: Vec<BigInt>) -> IntPoly {
        debug_assert!(c.last().is_none_or(|x| !x.is_zero()));
        let small = c.iter().map(num_traits::ToPrimitive::to_i64).collect();
        IntPoly { c, small }
    }

    /// The integer coefficients, lowest power first.
    pub(crate) fn coeffs(&self) -> &[BigInt] {
        &self.c
    }

    pub(crate) fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }

    fn leading_sign(&self) -> Ordering {
        self.c.last().map_or(Ordering::Equal, |x| x.sign().cmp_zero())
    }

    /// The sign of the polynomial at `x`: the sign of Σ c_k p^k q^(n−k) for
    /// x = p/q, q > 0.
    pub(crate) fn sign_at(&self, x: &Q) -> Ordering {
        let Some(n) = self.degree() else { return Ordering::Equal };
        let (p, q) = (x.numer(), x.denom());
        if let (Some(c), Some(ps), Some(qs)) = (&self.small, small(p), small(q)) {
            if let Some(v) = homogeneous_small(c, ps, qs) {
                return v.cmp(&0);
            }
        }
        if q.is_one() {
            let mut acc = BigInt::zero();
            for c in self.c.iter().rev() {
                acc = acc * p + c;
            }
            return acc.sign().cmp_zero();
        }
        let mut acc = self.c[n].clone();
        let mut qk = BigInt::one();
        for c in self.c[..n].iter().rev() {
            qk *= q;
            acc = acc * p + c * &qk;
        }
        acc.sign().cmp_zero()
    }
}

impl IntPoly {
    /// Σ c_k p^k q^(n−k) for x = p/q (q > 0, not necessarily in lowest
    /// terms): the value at x times q^n, an integer of the value's sign.
    fn scaled_value_parts(&self, p: &BigInt, q: &BigInt) -> BigInt {
        let Some(n) = self.degree() else { return BigInt::zero() };
        if let (Some(c), Some(ps), Some(qs)) = (&self.small, small(p), small(q)) {
            if let Some(v) = homogeneous_small(c, ps, qs) {
                return BigInt::from(v);
            }
        }
        if let Some(t) = power_of_two(q) {
            // q = 2^t (bisection of a dyadic interval): q^k is a shift.
            let mut acc = self.c[n].clone();
            for (j, c) in self.c[..n].iter().rev().enumerate() {
                acc = acc * p + (c << (t * (j as u64 + 1)));
            }
            return acc;
        }
        let mut acc = self.c[n].clone();
        let mut qk = BigInt::one();
        for c in self.c[..n].iter().rev() {
            qk *= q;
            acc = acc * p + c * &qk;
        }
        acc
    }

    /// The sign of the polynomial on the whole closed interval [lo, hi]
    /// (lo ≤ hi) when interval Horner evaluation proves it constant and
    /// non-zero; `None` when the enclosure contains zero (the polynomial may
    /// or may not vanish there). Exact: integers throughout, the interval
    /// written over a common denominator q > 0 and the polynomial in its
    /// homogeneous form Σ c_k X^k q^(n−k).
    pub(crate) fn sign_on(&self, lo: &Q, hi: &Q) -> Option<Ordering> {
        let n = self.degree()?;
        if let Some(c) = &self.small {
            if let (Some(ln), Some(ld), Some(hn), Some(hd)) =
                (small(lo.numer()), small(lo.denom()), small(hi.numer()), small(hi.denom()))
            {
                // Over the common denominator q = lcm(ld, hd).
                let g = num_integer::gcd(ld, hd);
                if let Some(q) = (ld / g).checked_mul(hd) {
                    if let (Some(a), Some(b)) = (ln.checked_mul(q / ld), hn.checked_mul(q / hd)) {
                        if let Some(s) = sign_on_small(c, a, b, q) {
                            return s;
                        }
                    }
                }
            }
        }
        let q = crate::arith::intgcd::lcm(lo.denom(), hi.denom());
        let a = lo.numer() * (&q / lo.denom());
        let b = hi.numer() * (&q / hi.denom());
        let (mut l, mut u) = (self.c[n].clone(), self.c[n].clone());
        let shift = power_of_two(&q);
        let mut qk = BigInt::one();
        for (j, c) in self.c[..n].iter().rev().enumerate() {
            let t = match shift {
                // q = 2^s: c·q^(j+1) is a shift.
                Some(s) => c << (s * (j as u64 + 1)),
                None => {
                    qk *= &q;
                    c * &qk
                }
            };
            let (min, max) = interval_product(&l, &u, &a, &b);
            (l, u) = (min + &t, max + &t);
        }
        if l.is_positive() {
            Some(Ordering::Greater)
        } else if u.is_negative() {
            Some(Ordering::Less)
        } else {
            None
        }
    }
}

pub(crate) trait CmpZero {
    fn cmp_zero(self) -> Ordering;
}

impl CmpZero for num_bigint::Sign {
    fn cmp_zero(self) -> Ordering {
        match self {
            num_bigint::Sign::Minus => Ordering::Less,
            num_bigint::Sign::NoSign => Ordering::Equal,
            num_bigint::Sign::Plus => Ordering::Greater,
        }
    }
}

/// The Sturm sequence of `p` (of its square-free part, so that counts see
/// each distinct root once), each term scaled by a positive rational to
/// primitive integer coefficients. Empty for the zero polynomial.
pub fn sturm_sequence(p: &UPoly) -> Vec<UPoly> {
    chain(p)
        .into_iter()
        .map(|ip| UPoly::new(ip.c.into_iter().map(Q::from_integer).collect()))
        .collect()
}

fn chain(p: &UPoly) -> Vec<IntPoly> {
    if p.is_zero() {
        return Vec::new();
    }
    chain_squarefree(&p.squarefree())
}

fn chain_squarefree(sf: &UPoly) -> Vec<IntPoly> {
    let a = crate::univariate::upoly::int_primitive(sf);
    let mut b = crate::univariate::upoly::int_primitive(&sf.derivative());
    let mut seq = vec![IntPoly::from_ints(a.clone())];
    let mut a = a;
    while !b.is_empty() {
        // lc(b)^k·a = q·b + r, so −rem(a, b) is a positive multiple of
        // −sign(lc(b))^k·r.
        let (r, k) = crate::univariate::upoly::prem(&a, &b);
        let negative_lead = b.last().is_some_and(|x| x.is_negative());
        let flip = !(negative_lead && k % 2 == 1);
        let next: Vec<BigInt> = if flip { r.into_iter().map(|x| -x).collect() } else { r };
        seq.push(IntPoly::from_ints(b.clone()));
        a = b;
        b = crate::univariate::upoly::primitive(next);
    }
    seq
}

/// Sign changes of the sequence at `x`, zeros skipped.
fn variations(seq: &[IntPoly], x: &Q) -> usize {
    let mut count = 0;
    let mut last = Ordering::Equal;
    for p in seq {
        let s = p.sign_at(x);
        if s != Ordering::Equal {
            if last != Ordering::Equal && s != last {
                count += 1;
            }
            last = s;
        }
    }
    count
}

/// Sign changes at +∞ (leading coefficients) or −∞.
fn variations_at_infinity(seq: &[IntPoly], positive: bool) -> usize {
    let mut count = 0;
    let mut last = Ordering::Equal;
    for p in seq {
        let mut s = p.leading_sign();
        if !positive && p.degree().unwrap_or(0) % 2 == 1 {
            s = s.reverse();
        }
        if s != Ordering::Equal {
            if last != Ordering::Equal && s != last {
                count += 1;
            }
            last = s;
        }
    }
    count
}

/// The sign of a rational as an ordering against zero.
pub(crate) fn sign(q: &Q) -> Ordering {
    if q.is_zero() {
        Ordering::Equal
    } else if q.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

/// The number of distinct real roots of `p` in the half-open interval
/// `(lo, hi]`; zero when `hi <= lo` or `p` is zero.
pub fn count_real_roots(p: &UPoly, lo: &Q, hi: &Q) -> usize {
    if hi <= lo || p.is_zero() {
        return 0;
    }
    let seq = chain(p);
    count_with(&seq, lo, hi)
}

fn count_with(seq: &[IntPoly], lo: &Q, hi: &Q) -> usize {
    variations(seq, lo).saturating_sub(variations(seq, hi))
}

/// The number of distinct real roots of `p` (zero for the zero polynomial).
pub fn count_all_real_roots(p: &UPoly) -> usize {
    if p.is_zero() {
        return 0;
    }
    let seq = chain(p);
    variations_at_infinity(&seq, false).saturating_sub(variations_at_infinity(&seq, true))
}

/// A power of two strictly greater than the modulus of every root of `p`
/// (Cauchy's bound 1 + max |a_k / a_n|, rounded up).
pub fn root_bound(p: &UPoly) -> Q {
    // The largest |a_k| by cross-multiplication (no gcd), one division.
    let c = p.coeffs();
    let mut largest: Option<&Q> = None;
    for x in &c[..c.len().saturating_sub(1)] {
        if x.is_zero() {
            continue;
        }
        let bigger = largest.is_none_or(|m| {
            (x.numer().abs() * m.denom()).cmp(&(m.numer().abs() * x.denom())) == Ordering::Greater
        });
        if bigger {
            largest = Some(x);
        }
    }
    // bound = |m|/|lead| + 1, and the least 2^e > bound: 2^e is an integer,
    // so 2^e > ⌊bound⌋ suffices, e = bits(⌊bound⌋) (bound ≥ 1). The floor
    // by one integer division of positive numbers (no gcd).
    let lead = p.leading();
    let floor = match largest {
        None => BigInt::one(),
        Some(m) => {
            (m.numer().abs() * lead.denom()) / (m.denom() * lead.numer().abs()) + BigInt::one()
        }
    };
    Q::from_integer(BigInt::one() << floor.bits())
}

/// [`isolate_squarefree`] by bisection with the Sturm chain's counts: the
/// definition of the intervals, and the oracle of [`crate::univariate::isolate`].
pub(crate) fn isolate_squarefree_sturm(sf: &UPoly) -> Vec<(Q, Q)> {
    if sf.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    let seq = chain_squarefree(sf);
    let b = root_bound(sf);
    let mut out = Vec::new();
    let lo = -b.clone();
    let n = count_with(&seq, &lo, &b);
    isolate_in(&seq[0], &seq, lo, b, n, &mut out);
    out
}

/// Isolates the `n` roots in `(lo, hi]`, appending them in increasing order.
/// `lo` is never a root here: it is the (root-free) bound or a bisection
/// point that was tested.
fn isolate_in(sf: &IntPoly, seq: &[IntPoly], lo: Q, hi: Q, n: usize, out: &mut Vec<(Q, Q)>) {
    if n == 0 {
        return;
    }
    if n == 1 {
        if sf.sign_at(&hi).is_eq() {
            out.push((hi.clone(), hi));
        } else {
            out.push((lo, hi));
        }
        return;
    }
    let two = Q::from_integer(2.into());
    let mid = (&lo + &hi) / &two;
    let left = count_with(seq, &lo, &mid);
    if sf.sign_at(&mid).is_eq() {
        // `mid` is a root: isolate the others on either side from points
        // next to it that are not roots, so every endpoint stays non-zero.
        let below = beside(sf, seq, &lo, &mid);
        let above = beside(sf, seq, &hi, &mid);
        isolate_in(sf, seq, lo, below, left - 1, out);
        out.push((mid.clone(), mid));
        isolate_in(sf, seq, above, hi, n - left, out);
    } else {
        isolate_in(sf, seq, lo, mid.clone(), left, out);
        isolate_in(sf, seq, mid, hi, n - left, out);
    }
}

/// A point strictly between `toward` and the root `r`, not a root itself,
/// with no root between it and `r`. Roots are isolated, so halving the step
/// ends.
fn beside(sf: &IntPoly, seq: &[IntPoly], toward: &Q, r: &Q) -> Q {
    let two = Q::from_integer(2.into());
    let mut step = (toward - r) / &two;
    loop {
        let x = r + &step;
        let (a, b) = if x < *r { (x.clone(), r.clone()) } else { (r.clone(), x.clone()) };
        // (a, b] holds r when x is below, nothing else wanted either way.
        let expected = usize::from(x < *r);
        if !sf.sign_at(&x).is_eq() && count_with(seq, &a, &b) == expected {
            return x;
        }
        step /= &two;
    }
}

/// Narrows an interval `(lo, hi)` on which the polynomial `ip` changes
/// sign (non-zero at both ends) to a sub-interval of width at most `width`
/// on which it still changes sign, or to `(r, r)` for a root `r` met
/// exactly. Quadratic interval refinement (Abbott): split the interval into
/// N equal parts, guess the part holding the root from the secant through
/// the ends, and check the guess with two signs; a right guess squares N
/// (the number of correct bits doubles, as with Newton's method), a wrong
/// one halves log N, down to plain bisection. Exact: every point is a
/// rational and every decision a sign. The result is *not* the bisection
/// result of [`refine_interval`]; use it where only the number matters.
pub(crate) fn refine_quadratic(ip: &IntPoly, lo: &Q, hi: &Q, width: &Q) -> (Q, Q) {
    if eq(lo, hi) {
        return (lo.clone(), hi.clone());
    }
    // Integers throughout: a = A/E, b = B/E over one denominator E > 0, and
    // values f(x)·E^n (the same positive factor at every point).
    let mut e = crate::arith::intgcd::lcm(lo.denom(), hi.denom());
    let mut a = lo.numer() * (&e / lo.denom());
    let mut b = hi.numer() * (&e / hi.denom());
    let value = |x: &BigInt, e: &BigInt| ip.scaled_value_parts(x, e);
    let sgn = |v: &BigInt| v.sign().cmp_zero();
    let mut fa = value(&a, &e);
    let mut fb = value(&b, &e);
    let s_a = sgn(&fa);
    debug_assert!(s_a != Ordering::Equal && s_a != sgn(&fb), "a sign change");
    let (wn, wd) = (width.numer(), width.denom());
    // Whether (b − a)/e > width.
    let wide = |a: &BigInt, b: &BigInt, e: &BigInt| (b - a) * wd > wn * e;
    // N = 2^k parts.
    let mut k: u32 = 2;
    while wide(&a, &b, &e) {
        // No finer grid than the target needs: 2^k ≤ 2(b − a)/width.
        let ratio_bits = ((&b - &a) * wd).bits().saturating_sub((wn * &e).bits()) + 2;
        k = k.min(u32::try_from(ratio_bits).unwrap_or(u32::MAX)).max(1);
        let parts = BigInt::one() << k;
        // Refine the grid: denominators times 2^k.
        let (a2, b2, e2) = (&a << k, &b << k, &e << k);
        let step = &b - &a; // (b2 − a2)/2^k
        let (fa2, fb2) = (&fa << (k as usize * n_of(ip)), &fb << (k as usize * n_of(ip)));
        let i = if k == 1 {
            BigInt::one()
        } else {
            // The secant's zero a + t(b − a), t = fa/(fa − fb) ∈ (0, 1),
            // rounded to the nearest inner grid point.
            let mut den = &fa - &fb;
            let mut num2 = (&fa * &parts) << 1u32;
            if den.is_negative() {
                den = -den;
                num2 = -num2;
            }
            let i = (num2 + &den).div_floor(&(&den << 1u32));
            i.clamp(BigInt::one(), &parts - BigInt::one())
        };
        let x = &a2 + &step * &i;
        let fx = value(&x, &e2);
        let sx = sgn(&fx);
        if sx == Ordering::Equal {
            let r = Q::new(x, e2);
            return (r.clone(), r);
        }
        if k == 1 {
            // Plain bisection.
            (a, fa, b, fb, e) = if sx == s_a { (x, fx, b2, fb2, e2) } else { (a2, fa2, x, fx, e2) };
            k = 2;
            continue;
        }
        // The neighbouring grid point on the side of the root.
        let y = if sx == s_a { &x + &step } else { &x - &step };
        let fy = value(&y, &e2);
        let sy = sgn(&fy);
        if sy == Ordering::Equal {
            let r = Q::new(y, e2);
            return (r.clone(), r);
        }
        e = e2;
        if sx == s_a && sy != s_a {
            (a, fa, b, fb) = (x, fx, y, fy);
            k = k.saturating_mul(2);
        } else if sx != s_a && sy == s_a {
            (a, fa, b, fb) = (y, fy, x, fx);
            k = k.saturating_mul(2);
        } else {
            // Wrong guess: keep the side of x that holds the root.
            if sx == s_a {
                (a, fa, b, fb) = (y, fy, b2, fb2);
            } else {
                (a, fa, b, fb) = (a2, fa2, y, fy);
            }
            k /= 2;
        }
    }
    (Q::new(a, e.clone()), Q::new(b, e))
}

fn n_of(ip: &IntPoly) -> usize {
    ip.degree().unwrap_or(0)
}

/// Narrows an isolating interval `(lo, hi)` (as returned by
/// `isolate_real_roots`) of a square-free `p` by bisection until its width
/// is at most `width`. A rational root hit exactly becomes `(r, r)`.
pub fn refine_interval(p: &UPoly, lo: &Q, hi: &Q, width: &Q) -> (Q, Q) {
    if eq(lo, hi) {
        return (lo.clone(), hi.clone());
    }
    refine_int(&IntPoly::new(p), lo, hi, width)
}

/// [`refine_interval`]'s result, found faster when `(gl, gh)` is a good
/// guess of an interval around the root (checked by exact signs at the
/// grid level the guess resolves); the guess never changes the result.
pub fn refine_interval_near(p: &UPoly, lo: &Q, hi: &Q, width: &Q, gl: &Q, gh: &Q) -> (Q, Q) {
    if eq(lo, hi) {
        return (lo.clone(), hi.clone());
    }
    refine_int_near(&IntPoly::new(p), lo, hi, width, gl, gh)
}

/// [`refine_interval`] with the integer form of the polynomial given: the
/// same result as bisection, computed faster when many halvings are due.
///
/// After k halvings bisection stops on the cell lo + [j, j + 1)·h,
/// h = (hi − lo)/2^k, that holds the root, or on a grid point lo + j·h
/// that is the root (met as a midpoint, where it returns `(r, r)`). So the
/// root is located by quadratic refinement to within one cell, and at most
/// one grid point then needs a sign; the result is identical.
pub(crate) fn refine_int(ip: &IntPoly, lo: &Q, hi: &Q, width: &Q) -> (Q, Q) {
    if eq(lo, hi) {
        return (lo.clone(), hi.clone());
    }
    // (hi − lo)/width = num/den in integers, nothing reduced: hi − lo is
    // (hn·ld − ln·hd)/(ld·hd) and width > 0.
    let num = (hi.numer() * lo.denom() - lo.numer() * hi.denom()) * width.denom();
    let den = lo.denom() * hi.denom() * width.numer();
    if num <= den {
        return (lo.clone(), hi.clone());
    }
    // k = ⌈log2((hi − lo)/width)⌉ halvings: the bits of ⌈num/den⌉ − 1.
    let ceil_bits = ((num + &den - BigInt::one()) / den - BigInt::one()).bits();
    if ceil_bits <= BISECTION_HALVINGS {
        return bisect_int(ip, lo, hi, ceil_bits);
    }
    // k = ⌈log2((hi − lo)/width)⌉ halvings: the least k with 2^k ≥ ratio.
    let k = ceil_bits;
    let h = (hi - lo) / Q::from_integer(BigInt::one() << k);
    let (a, b) = refine_quadratic(ip, lo, hi, &h);
    let cell = |x: &Q| ((x - lo) / &h).floor().to_integer();
    let at = |j: &BigInt| lo + &h * Q::from_integer(j.clone());
    if a == b {
        // A rational root: bisection meets it exactly when it is a grid
        // point, and otherwise ends on the cell around it.
        let j = cell(&a);
        if at(&j) == a {
            return (a.clone(), a);
        }
        return (at(&j), at(&(j + BigInt::one())));
    }
    let (ja, jb) = (cell(&a), cell(&b));
    if ja == jb || at(&jb) == b {
        // (a, b) inside one cell (b may be that cell's upper end).
        return (at(&ja), at(&(ja + BigInt::one())));
    }
    // b − a ≤ h: one grid point g = at(jb) strictly inside (a, b).
    let g = at(&jb);
    match ip.sign_at(&g) {
        Ordering::Equal => (g.clone(), g),
        s if s == ip.sign_at(&a) => (g, at(&(jb + BigInt::one()))),
        _ => (at(&ja), g),
    }
}

/// [`refine_int`]'s result (the bisection result), found from a guess:
/// `(gl, gh)` is an interval the caller believes holds the root, from
/// floating point say, and nothing is assumed of it. At the finest level
/// of bisection's grid whose cells are at least as wide as the guess, the
/// cell under the guess's midpoint is tested by the signs at its ends,
/// and a wrong cell is left for its neighbour on the side the signs point
/// to; a few evaluations, then bisection within the cell for the levels
/// left. A guess that misses by more than a few cells costs those tests
/// and then [`refine_int`] itself: the result never depends on the guess.
pub(crate) fn refine_int_near(ip: &IntPoly, lo: &Q, hi: &Q, width: &Q, gl: &Q, gh: &Q) -> (Q, Q) {
    if eq(lo, hi) {
        return (lo.clone(), hi.clone());
    }
    // Integers throughout: lo = a/e, hi = b/e, d = b − a > 0.
    let e = crate::arith::intgcd::lcm(lo.denom(), hi.denom());
    let a = lo.numer() * (&e / lo.denom());
    let b = hi.numer() * (&e / hi.denom());
    let d = &b - &a;
    // k = ⌈log2((hi − lo)/width)⌉ halvings, (hi − lo)/width = d·w_d/(e·w_n).
    let (num, den) = (&d * width.denom(), &e * width.numer());
    if num <= den {
        return (lo.clone(), hi.clone());
    }
    let k = ((num + &den - BigInt::one()) / den - BigInt::one()).bits();
    // The guess's ends on the finest grid: ⌊(g − lo)·2^k/(hi − lo)⌋ =
    // ⌊(g_n·e − a·g_d)·2^k/(g_d·d)⌋, clamped to the cells [0, 2^k).
    let cells = BigInt::one() << k;
    let at = |g: &Q| {
        let j = ((g.numer() * &e - &a * g.denom()) << k).div_floor(&(g.denom() * &d));
        j.clamp(BigInt::zero(), &cells - BigInt::one())
    };
    let (jl, jh) = (at(gl), at(gh));
    if jh < jl {
        return refine_int(ip, lo, hi, width);
    }
    // The finest level kp at which the guess spans at most two cells.
    let kp = k.saturating_sub((&jh - &jl).bits());
    if kp < 4 {
        return refine_int(ip, lo, hi, width);
    }
    let shift = k - kp;
    let mut j = &jl >> shift;
    let top = BigInt::one() << kp;
    // Grid point j of level kp: (a·2^kp + j·d)/(e·2^kp).
    let (base, scale) = (&a << kp, &e << kp);
    let s_lo = ip.sign_at(lo);
    let point = |j: &BigInt| &base + j * &d;
    let sign = |j: &BigInt| -> Ordering {
        if j.is_zero() {
            s_lo
        } else if *j == top {
            s_lo.reverse()
        } else {
            ip.scaled_value_parts(&point(j), &scale).sign().cmp_zero()
        }
    };
    let (mut sl, mut sh) = (sign(&j), sign(&(&j + BigInt::one())));
    for _ in 0..4 {
        if sl == Ordering::Equal || sh == Ordering::Equal {
            let r = ratio(point(&if sl == Ordering::Equal { j } else { j + BigInt::one() }), scale);
            return (r.clone(), r);
        }
        if sl == s_lo && sh != s_lo {
            // The cell holds the root: bisection passes through it.
            let (ca, cb) = (point(&j), point(&(&j + BigInt::one())));
            return bisect_parts(ip, ca, cb, scale, shift, s_lo);
        }
        if sl != s_lo {
            // The root lies below the cell (j > 0, since sign(0) = s_lo).
            j -= 1;
            sh = sl;
            sl = sign(&j);
        } else {
            j += 1;
            sl = sh;
            sh = sign(&(&j + BigInt::one()));
        }
    }
    refine_int(ip, lo, hi, width)
}

/// Up to this many halvings [`refine_int`] bisects (one sign each, in
/// machine integers when they fit); beyond, quadratic refinement.
const BISECTION_HALVINGS: u64 = 64;

/// Plain bisection of a sign-changing interval: `k` halvings, a root met
/// as a midpoint returned as (m, m). Integers over one denominator, so no
/// fraction is reduced before the end.
fn bisect_int(ip: &IntPoly, lo: &Q, hi: &Q, k: u64) -> (Q, Q) {
    let e = crate::arith::intgcd::lcm(lo.denom(), hi.denom());
    let a = lo.numer() * (&e / lo.denom());
    let b = hi.numer() * (&e / hi.denom());
    let s_lo = ip.sign_at(lo);
    bisect_parts(ip, a, b, e, k, s_lo)
}

/// [`bisect_int`] on a/e < b/e (e > 0, nothing reduced), `s_lo` the sign
/// at a/e.
fn bisect_parts(ip: &IntPoly, a: BigInt, b: BigInt, e: BigInt, k: u64, s_lo: Ordering) -> (Q, Q) {
    let (mut a, mut b, mut e, mut k) = (a, b, e, k);
    // lo = a/e, hi = b/e; after j halvings the points are over e·2^j. From
    // `i64` ends, 61 doublings stay inside `i128`; an evaluation that
    // overflows hands the halvings left to `BigInt`, from where it stopped.
    if let (Some(c), Some(sa), Some(sb), Some(se)) = (&ip.small, small(&a), small(&b), small(&e)) {
        if k <= 61 {
            match bisect_small(c, (sa, sb, se), s_lo, k) {
                Ok(r) => return r,
                Err((sa, sb, se, left)) => {
                    (a, b, e, k) = (sa.into(), sb.into(), se.into(), left);
                }
            }
        }
    }
    for _ in 0..k {
        let m = &a + &b;
        (a, b, e) = (a << 1u32, b << 1u32, e << 1u32);
        let s = ip.scaled_value_parts(&m, &e).sign().cmp_zero();
        if s == Ordering::Equal {
            let r = ratio(m, e);
            return (r.clone(), r);
        }
        if s == s_lo {
            a = m;
        } else {
            b = m;
        }
    }
    (ratio(a, e.clone()), ratio(b, e))
}

/// [`bisect_int`] in `i128`: the result, or where it stopped when an
/// evaluation overflowed, `(a, b, e, halvings left)`.
fn bisect_small(
    c: &[i64],
    (mut a, mut b, mut e): (i128, i128, i128),
    s_lo: Ordering,
    k: u64,
) -> Result<(Q, Q), (i128, i128, i128, u64)> {
    for done in 0..k {
        let m = a + b;
        let Some(v) = homogeneous_small(c, m, 2 * e) else {
            return Err((a, b, e, k - done));
        };
        (a, b, e) = (2 * a, 2 * b, 2 * e);
        let s = v.cmp(&0);
        if s == Ordering::Equal {
            let r = small_ratio(m, e);
            return Ok((r.clone(), r));
        }
        if s == s_lo {
            a = m;
        } else {
            b = m;
        }
    }
    Ok((small_ratio(a, e), small_ratio(b, e)))
}

/// n/e in lowest terms for e > 0, reduced in machine words.
fn small_ratio(n: i128, e: i128) -> Q {
    let g = num_integer::Integer::gcd(&n, &e);
    Q::new_raw((n / g).into(), (e / g).into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The `i128` paths of the evaluations give what the `BigInt` ones
        /// give (an `IntPoly` without its small form), including values
        /// that overflow and fall back.
        #[test]
        fn small_evaluations_match_big(
            c in proptest::collection::vec(-(1i64 << 40)..(1i64 << 40), 1..9),
            (p, q, r, e) in (-(1i64 << 30)..(1i64 << 30), 1i64..(1 << 30), 0i64..(1 << 20), 0u32..24),
        ) {
            prop_assume!(*c.last().unwrap() != 0);
            let ints: Vec<BigInt> = c.iter().map(|&x| BigInt::from(x)).collect();
            let fast = IntPoly::from_ints(ints.clone());
            prop_assert!(fast.small.is_some());
            let slow = IntPoly { c: ints, small: None };
            let lo = Q::new(p.into(), q.into());
            let hi = &lo + Q::new(r.into(), BigInt::one() << e);
            prop_assert_eq!(fast.sign_at(&lo), slow.sign_at(&lo));
            prop_assert_eq!(fast.sign_on(&lo, &hi), slow.sign_on(&lo, &hi));
            let (pn, qn) = (BigInt::from(p), BigInt::from(q));
            prop_assert_eq!(fast.scaled_value_parts(&pn, &qn), slow.scaled_value_parts(&pn, &qn));
        }
    }

    proptest! {
        /// Σ c_k p^k q^(n−k) term by term, the slow oracle, against the
        /// Horner evaluation: at powers of two (shifts) and elsewhere, with
        /// big coefficients (no small form).
        #[test]
        fn scaled_values_are_the_sum(
            c in proptest::collection::vec(any::<i64>(), 1..9),
            scale in 0u32..100,
            p in any::<i64>(),
            t in 0u64..200,
            odd in 1i64..1000,
        ) {
            prop_assume!(*c.last().unwrap() != 0);
            let ints: Vec<BigInt> = c.iter().map(|&x| BigInt::from(x) << scale).collect();
            let ip = IntPoly { c: ints.clone(), small: None };
            let p = BigInt::from(p);
            let n = ints.len() - 1;
            for q in [BigInt::one() << t, (BigInt::one() << t) * (2 * odd + 1)] {
                let sum: BigInt = ints
                    .iter()
                    .enumerate()
                    .map(|(k, ck)| ck * p.pow(k as u32) * q.pow((n - k) as u32))
                    .sum();
                prop_assert_eq!(ip.scaled_value_parts(&p, &q), sum);
            }
        }
    }

    proptest! {
        /// The interval product against the least and greatest of the four
        /// corner products, its oracle, over every sign pattern.
        #[test]
        fn interval_products_are_the_corners(
            x in (-50i64..50, 0i64..50),
            y in (-50i64..50, 0i64..50),
        ) {
            let (l, u) = (BigInt::from(x.0), BigInt::from(x.0 + x.1));
            let (a, b) = (BigInt::from(y.0), BigInt::from(y.0 + y.1));
            let corners = [&l * &a, &l * &b, &u * &a, &u * &b];
            let expected = (corners.iter().min().unwrap().clone(), corners.iter().max().unwrap().clone());
            prop_assert_eq!(interval_product(&l, &u, &a, &b), expected);
        }
    }

    /// Cauchy's bound as written: 1 + max |a_k / a_n|, then doubling from
    /// one until above it. The oracle of [`root_bound`].
    fn root_bound_slow(p: &UPoly) -> Q {
        let lead = p.leading().abs();
        let mut m = Q::zero();
        for c in &p.coeffs()[..p.coeffs().len() - 1] {
            m = m.max(c.abs() / &lead);
        }
        let bound = m + Q::one();
        let mut b = Q::one();
        while b <= bound {
            b *= Q::from_integer(2.into());
        }
        b
    }

    proptest! {
        #[test]
        fn root_bound_matches_cauchy(
            c in proptest::collection::vec((-300i64..300, 1i64..40), 1..8),
            scale in 0u32..3,
        ) {
            let coeffs: Vec<Q> = c
                .iter()
                .map(|&(a, b)| Q::new(BigInt::from(a), BigInt::from(b).pow(scale + 1)))
                .collect();
            let p = UPoly::new(coeffs);
            prop_assume!(p.degree().unwrap_or(0) > 0);
            prop_assert_eq!(root_bound(&p), root_bound_slow(&p));
        }
    }

    /// Exact powers of two at the boundary: 1 + |a_k/a_n| equal to a power
    /// of two must give the next one (the bound is strict).
    #[test]
    fn root_bound_at_powers_of_two() {
        for (c, expected) in
            [(vec![3, 1], 8), (vec![-7, 0, 1], 16), (vec![0, 1], 2), (vec![1, 2], 2)]
        {
            let p = UPoly::from_ints(&c);
            assert_eq!(root_bound(&p), Q::from_integer(expected.into()), "{c:?}");
            assert_eq!(root_bound_slow(&p), root_bound(&p));
        }
    }
}
