//! [`Q`], the one exact scalar of the crate: arbitrary-precision rationals
//! (num-rational over num-bigint, behind one alias), and [`q`] to write one.

/// The one exact scalar type: arbitrary-precision rationals.
pub type Q = num_rational::BigRational;

/// The rational `num/den`; panics when `den` is zero (a programmer error).
#[track_caller]
pub fn q(num: i64, den: i64) -> Q {
    assert!(den != 0, "zero denominator");
    Q::new(num.into(), den.into())
}

/// `a * b`, reduced by Lehmer's gcd (`intgcd`) rather than num-rational's
/// binary one: cross-cancel first (Knuth, TAOCP 2, §4.5.1), so the result
/// is already in lowest terms. The same value and representation as
/// `a * b` (the reduced form is unique); a property test checks it.
pub(crate) fn mul(a: &Q, b: &Q) -> Q {
    use crate::arith::intgcd::gcd;
    use num_traits::{One, Zero};
    if a.is_zero() || b.is_zero() {
        return Q::zero();
    }
    if a.denom().is_one() && b.denom().is_one() {
        return Q::from_integer(a.numer() * b.numer());
    }
    // gcd(a_n, a_d) = gcd(b_n, b_d) = 1, so dividing by g1 = gcd(a_n, b_d)
    // and g2 = gcd(b_n, a_d) leaves numerator and denominator coprime; the
    // denominators are positive, so is the result's.
    let g1 = gcd(a.numer(), b.denom());
    let g2 = gcd(b.numer(), a.denom());
    let num = div_exact(a.numer(), &g1) * div_exact(b.numer(), &g2);
    let den = div_exact(a.denom(), &g2) * div_exact(b.denom(), &g1);
    Q::new_raw(num, den)
}

/// `a + b`, reduced as [`mul`] is: with g = gcd(a_d, b_d), the sum is
/// t / (a_d/g · b_d) for t = a_n·(b_d/g) + b_n·(a_d/g), and only gcd(t, g)
/// can remain (Knuth, TAOCP 2, §4.5.1).
pub(crate) fn add(a: &Q, b: &Q) -> Q {
    use crate::arith::intgcd::gcd;
    use num_traits::{One, Zero};
    if a.denom().is_one() && b.denom().is_one() {
        return Q::from_integer(a.numer() + b.numer());
    }
    if a.is_zero() {
        return b.clone();
    }
    if b.is_zero() {
        return a.clone();
    }
    let g = gcd(a.denom(), b.denom());
    if g.is_one() {
        return Q::new_raw(a.numer() * b.denom() + b.numer() * a.denom(), a.denom() * b.denom());
    }
    let (ad, bd) = (div_exact(a.denom(), &g), div_exact(b.denom(), &g));
    let t = a.numer() * &bd + b.numer() * &ad;
    if t.is_zero() {
        return Q::zero();
    }
    let g2 = gcd(&t, &g);
    if g2.is_one() {
        Q::new_raw(t, ad * b.denom())
    } else {
        Q::new_raw(div_exact(&t, &g2), ad * div_exact(b.denom(), &g2))
    }
}

/// `num / den` in lowest terms for `den > 0`, reduced by Lehmer's gcd:
/// the same as `Q::new(num, den)`.
pub(crate) fn ratio(num: num_bigint::BigInt, den: num_bigint::BigInt) -> Q {
    use num_traits::Zero;
    debug_assert!(den > num_bigint::BigInt::zero());
    if num.is_zero() {
        return Q::zero();
    }
    let g = crate::arith::intgcd::gcd(&num, &den);
    Q::new_raw(div_exact(&num, &g), div_exact(&den, &g))
}

/// `a.cmp(b)` by one cross multiplication (denominators are positive),
/// where num-rational's `Ord` runs a continued-fraction comparison, a
/// division per step, to stay within fixed-width integers. The same
/// result; a property test checks it.
pub(crate) fn cmp(a: &Q, b: &Q) -> std::cmp::Ordering {
    use num_traits::Signed;
    let (sa, sb) = (a.numer().sign(), b.numer().sign());
    if sa != sb {
        return sa.cmp(&sb);
    }
    if a.denom() == b.denom() {
        return a.numer().cmp(b.numer());
    }
    if a.numer() == b.numer() {
        // The same numerator (so the same sign): the larger denominator is
        // the smaller magnitude.
        let by_den = b.denom().cmp(a.denom());
        return if a.numer().is_negative() { by_den.reverse() } else { by_den };
    }
    (a.numer() * b.denom()).cmp(&(b.numer() * a.denom()))
}

/// `q / 2^k` in lowest terms by shifts: the numerator loses the twos it
/// has, up to k, the denominator gains the rest (no gcd).
pub(crate) fn shr(q: &Q, k: u64) -> Q {
    use num_traits::Zero;
    if q.is_zero() {
        return Q::zero();
    }
    let tz = q.numer().trailing_zeros().unwrap_or(0).min(k);
    Q::new_raw(q.numer() >> tz, q.denom() << (k - tz))
}

/// The midpoint (a + b)/2, as [`add`] then [`shr`].
pub(crate) fn midpoint(a: &Q, b: &Q) -> Q {
    shr(&add(a, b), 1)
}

/// `a == b` by [`cmp`] (num-rational's `PartialEq` is its `Ord`).
pub(crate) fn eq(a: &Q, b: &Q) -> bool {
    cmp(a, b) == std::cmp::Ordering::Equal
}

fn div_exact(x: &num_bigint::BigInt, g: &num_bigint::BigInt) -> num_bigint::BigInt {
    use num_traits::One;
    if g.is_one() {
        x.clone()
    } else {
        x / g
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt;
    use proptest::prelude::*;

    fn big(limbs: &[u64], negative: bool) -> BigInt {
        let mut x = BigInt::from(0);
        for &l in limbs {
            x = (x << 64) + BigInt::from(l);
        }
        if negative {
            -x
        } else {
            x
        }
    }

    fn rational(n: &[u64], d: &[u64], f: &[u64], neg: bool) -> Q {
        // A shared factor f on both sides, so the gcds are not always 1.
        let f = big(f, false) + 1;
        Q::new(big(n, neg) * &f, (big(d, false) + 1) * f)
    }

    proptest! {
        /// The same value and representation as num-rational's own
        /// product and sum, and the same order (the slow oracles), on rationals of 0–4 limbs
        /// with common factors, integers and zero included.
        #[test]
        fn fast_mul_add_and_cmp_match_num_rational(
            an in proptest::collection::vec(any::<u64>(), 0..4),
            ad in proptest::collection::vec(0..4u64, 0..3),
            bn in proptest::collection::vec(any::<u64>(), 0..4),
            bd in proptest::collection::vec(any::<u64>(), 0..4),
            f in proptest::collection::vec(any::<u64>(), 0..2),
            sa in any::<bool>(),
            sb in any::<bool>(),
        ) {
            let a = rational(&an, &ad, &f, sa);
            let b = rational(&bn, &bd, &f, sb);
            for (x, y) in [(&a, &b), (&b, &a), (&a, &a), (&a, &-a.clone())] {
                let (m, s) = (mul(x, y), add(x, y));
                let (om, os) = (x * y, x + y);
                prop_assert_eq!(m.numer(), om.numer());
                prop_assert_eq!(m.denom(), om.denom());
                prop_assert_eq!(s.numer(), os.numer());
                prop_assert_eq!(s.denom(), os.denom());
                prop_assert_eq!(cmp(x, y), x.cmp(y));
                prop_assert_eq!(cmp(x, &s), x.cmp(&s));
                let k = x.numer().bits() % 70;
                let two_k = Q::from_integer(BigInt::from(1) << k);
                let (h, oh) = (shr(x, k), x / &two_k);
                prop_assert_eq!((h.numer(), h.denom()), (oh.numer(), oh.denom()));
                let (m, om) = (midpoint(x, y), (x + y) / Q::from_integer(2.into()));
                prop_assert_eq!((m.numer(), m.denom()), (om.numer(), om.denom()));
            }
            let r = ratio(a.numer() * b.denom(), b.denom().clone());
            let or = Q::new(a.numer() * b.denom(), b.denom().clone());
            prop_assert_eq!(r.numer(), or.numer());
            prop_assert_eq!(r.denom(), or.denom());
        }
    }
}
