//! Greatest common divisors of big integers by Lehmer's algorithm.
//!
//! num-bigint's `Integer::gcd` is Stein's binary algorithm: one shift and
//! one subtraction of the whole number per bit, so a gcd of two 400-bit
//! numbers costs hundreds of passes over both. The contents of the
//! remainder sequences and the denominators of the stability analysis are
//! such numbers, and that gcd was over a third of the analysis of AB8.
//! Lehmer's algorithm (Knuth, TAOCP 2, §4.5.2, Algorithm L) runs Euclid on
//! the leading 63 bits of both numbers, as long as the quotients there are
//! provably the true ones, and applies the accumulated 2×2 cofactor matrix
//! to the full numbers once: one pass per ~60 bits instead of one per bit.
//! When the leading bits decide no quotient, one full division step runs
//! instead. Below 2^64 the rest is Euclid on machine words.
//!
//! Checked against num-bigint's gcd (the slow, obvious oracle) by a property
//! test.

use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Signed, ToPrimitive, Zero};

/// gcd(a, b) ≥ 0 (gcd(0, 0) = 0), as num-integer defines it.
pub(crate) fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let (ma, mb) = (a.magnitude(), b.magnitude());
    // Most gcds of the analysis are of words (denominators such as 576 or
    // 6561): no copy of either number.
    if let (Some(x), Some(y)) = (ma.to_u64(), mb.to_u64()) {
        return BigInt::from(gcd_u64(x, y));
    }
    BigInt::from_biguint(Sign::Plus, gcd_nat(ma, mb))
}

/// The least common multiple of positive integers (denominators), 1 for
/// none: one division where a denominator already divides the running
/// multiple (as decimals' powers of ten mostly do), Lehmer's gcd otherwise.
pub(crate) fn lcm_all<'a>(xs: impl IntoIterator<Item = &'a BigInt>) -> BigInt {
    let mut l = BigInt::from(1u8);
    for x in xs {
        if x.is_one() || (&l % x).is_zero() {
            continue;
        }
        l = lcm(&l, x);
    }
    l
}

/// lcm(a, b) ≥ 0 (zero when either is zero).
pub(crate) fn lcm(a: &BigInt, b: &BigInt) -> BigInt {
    if a.is_zero() || b.is_zero() {
        return BigInt::zero();
    }
    let g = gcd(a, b);
    (a / g * b).abs()
}

fn gcd_nat(a: &BigUint, b: &BigUint) -> BigUint {
    let (a, b) = if a >= b { (a, b) } else { (b, a) };
    // A word against a big number: one remainder by the word, no copy.
    if let Some(small) = b.to_u64() {
        if small == 0 {
            return a.clone();
        }
        return BigUint::from(gcd_u64(small, (a % small).to_u64().expect("below 2^64")));
    }
    let (mut a, mut b) = (a.clone(), b.clone());
    // a ≥ b throughout.
    while b.bits() > 64 {
        let n = a.bits();
        if n - b.bits() >= 32 {
            // Very different sizes: the first quotient is large, so one
            // division does what many Lehmer rounds would.
            let r = &a % &b;
            a = b;
            b = r;
            continue;
        }
        // The leading 62 bits of both (the same shift), and the cofactor
        // matrix of Euclid on them: |x|, |y| and every cofactor stay below
        // 2^62 (Knuth), so sums fit an i64 and a product whose result fits
        // is exact in wrapping arithmetic.
        let shift = n - 62;
        let mut x = top_bits(&a, shift);
        let mut y = top_bits(&b, shift);
        let (mut ca, mut cb, mut cc, mut cd) = (1i64, 0i64, 0i64, 1i64);
        loop {
            if y + cc == 0 || y + cd == 0 {
                break;
            }
            let q = (x + ca) / (y + cc);
            if q != (x + cb) / (y + cd) {
                break;
            }
            (ca, cc) = (cc, ca.wrapping_sub(q.wrapping_mul(cc)));
            (cb, cd) = (cd, cb.wrapping_sub(q.wrapping_mul(cd)));
            (x, y) = (y, x.wrapping_sub(q.wrapping_mul(y)));
        }
        if cb == 0 {
            let r = &a % &b;
            a = b;
            b = r;
        } else {
            // (a, b) ← (A·a + B·b, C·a + D·b): both non-negative, and in
            // each pair of cofactors one is positive and one is not.
            let na = combine(&a, ca, &b, cb);
            let nb = combine(&a, cc, &b, cd);
            a = na;
            b = nb;
        }
    }
    if b.is_zero() {
        return a;
    }
    let small = b.to_u64().expect("below 2^64");
    let r = (&a % &b).to_u64().expect("below 2^64");
    BigUint::from(gcd_u64(small, r))
}

/// `x >> shift` for an `x` below 2^(shift + 62), read from its limbs
/// without building the shifted number (the same as `(x >> shift)`, which
/// allocated on every Lehmer round).
fn top_bits(x: &BigUint, shift: u64) -> i64 {
    let (k, r) = ((shift / 64) as usize, shift % 64);
    let mut limbs = x.iter_u64_digits().skip(k);
    let lo = limbs.next().unwrap_or(0);
    let hi = limbs.next().unwrap_or(0);
    let v = if r == 0 { lo } else { (lo >> r) | (hi << (64 - r)) };
    debug_assert!(v < 1 << 62);
    v as i64
}

/// ca·a + cb·b for cofactors of opposite signs (or one zero) whose result
/// is non-negative.
fn combine(a: &BigUint, ca: i64, b: &BigUint, cb: i64) -> BigUint {
    let (pa, pb) = (a * ca.unsigned_abs(), b * cb.unsigned_abs());
    match (ca >= 0, cb >= 0) {
        (true, false) => pa - pb,
        (false, true) => pb - pa,
        _ => pa + pb,
    }
}

/// Stein's binary gcd on words: shifts and subtractions, no division.
fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;
    use proptest::prelude::*;

    fn big(limbs: &[u64], negative: bool) -> BigInt {
        let mut x = BigInt::zero();
        for &l in limbs {
            x = (x << 64) + BigInt::from(l);
        }
        if negative {
            -x
        } else {
            x
        }
    }

    proptest! {
        /// The same gcd and lcm as num-integer's binary algorithm, on
        /// numbers of 0–8 limbs with a random common factor (so the gcd is
        /// not always 1) and random signs.
        #[test]
        fn lehmer_gcd_matches_binary_gcd(
            a in proptest::collection::vec(any::<u64>(), 0..6),
            b in proptest::collection::vec(any::<u64>(), 0..6),
            f in proptest::collection::vec(any::<u64>(), 0..3),
            sa in any::<bool>(),
            sb in any::<bool>(),
        ) {
            let f = big(&f, false) + 1;
            let (a, b) = (big(&a, sa) * &f, big(&b, sb) * &f);
            prop_assert_eq!(gcd(&a, &b), a.gcd(&b));
            prop_assert_eq!(lcm(&a, &b), a.lcm(&b));
            let (pa, pb) = (a.abs() + 1, b.abs() + 1);
            prop_assert_eq!(lcm_all([&pa, &pb, &f, &pa]), pa.lcm(&pb).lcm(&f));
            let m = a.magnitude();
            for shift in [0, 1, 63, 64, 65, 127, 128] {
                if m.bits() <= shift + 62 {
                    prop_assert_eq!(top_bits(m, shift), (m >> shift).to_i64().unwrap());
                }
            }
        }
    }

    proptest! {
        /// Stein's word gcd is Euclid's, common powers of two included.
        #[test]
        fn word_gcd_matches_euclid(a in any::<u64>(), b in any::<u64>(), k in 0u32..40) {
            let euclid = |mut x: u64, mut y: u64| {
                while y != 0 {
                    (x, y) = (y, x % y);
                }
                x
            };
            let (a, b) = (a >> k, b >> (k / 2));
            prop_assert_eq!(gcd_u64(a, b), euclid(a, b));
            prop_assert_eq!(gcd_u64(a << (k % 8), b << (k % 8)), euclid(a << (k % 8), b << (k % 8)));
            prop_assert_eq!(gcd_u64(0, b), b);
            prop_assert_eq!(gcd_u64(a, 0), a);
        }
    }

    /// Consecutive Fibonacci numbers: every quotient is 1, the slowest case
    /// for Euclid, and the cofactors grow as fast as they can.
    #[test]
    fn fibonacci_neighbours_are_coprime() {
        let (mut f0, mut f1) = (BigInt::from(0), BigInt::from(1));
        for _ in 0..2000 {
            (f0, f1) = (f1.clone(), f0 + f1);
        }
        assert_eq!(gcd(&f0, &f1), BigInt::from(1));
        let g = BigInt::from(1u64 << 40) + 7;
        assert_eq!(gcd(&(&f0 * &g), &(&f1 * &g)), g);
    }
}
