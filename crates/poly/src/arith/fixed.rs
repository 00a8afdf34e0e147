//! A real number known to within a bound, in fixed point: x̃ = m·2⁻⁶⁴ on
//! an `i128`, with |x − x̃| ≤ e·2⁻⁶⁴. The filter in front of an exact
//! decision: a comparison the bound settles needs no big integer, and one it
//! does not settle falls back to the exact arithmetic. An overflow gives
//! [`Fixed::UNKNOWN`], which settles nothing.
//!
//! No floating point: the mantissa and the bound are integers, and every
//! rounding is counted in the bound.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{Signed, ToPrimitive, Zero};

/// Fractional bits.
const BITS: u32 = 64;
const LOW: u128 = (1u128 << BITS) - 1;

/// m·2⁻⁶⁴ within e·2⁻⁶⁴ (`e == u128::MAX`: unknown).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Fixed {
    m: i128,
    e: u128,
}

impl Fixed {
    /// Nothing known (an overflow on the way).
    pub(crate) const UNKNOWN: Fixed = Fixed { m: 0, e: u128::MAX };
    pub(crate) const ZERO: Fixed = Fixed { m: 0, e: 0 };
    pub(crate) const ONE: Fixed = Fixed { m: 1 << BITS, e: 0 };

    pub(crate) fn is_unknown(&self) -> bool {
        self.e == u128::MAX
    }

    /// Exactly zero.
    pub(crate) fn is_exact_zero(&self) -> bool {
        self.m == 0 && self.e == 0
    }

    /// n/d (d > 0), truncated: within one unit, exact when 2⁶⁴·n/d is an
    /// integer.
    pub(crate) fn ratio(n: &BigInt, d: &BigInt) -> Fixed {
        debug_assert!(d.is_positive());
        let (q, r) = (n << BITS).div_rem(d);
        match q.to_i128() {
            Some(m) => Fixed { m, e: u128::from(!r.is_zero()) },
            None => Fixed::UNKNOWN,
        }
    }

    /// The bound on |x|: |m|/2⁶⁴ rounded up, plus one.
    fn magnitude(&self) -> u128 {
        (self.m.unsigned_abs() >> BITS) + 1
    }

    pub(crate) fn add(&self, o: &Fixed) -> Fixed {
        if self.is_unknown() || o.is_unknown() {
            return Fixed::UNKNOWN;
        }
        match (self.m.checked_add(o.m), self.e.checked_add(o.e)) {
            (Some(m), Some(e)) if e != u128::MAX => Fixed { m, e },
            _ => Fixed::UNKNOWN,
        }
    }

    /// x·y: the product of the mantissas shifted back (truncated), the
    /// bound |x̃|e_y + |ỹ|e_x + e_x·e_y·2⁻⁶⁴ plus the truncation's unit.
    pub(crate) fn mul(&self, o: &Fixed) -> Fixed {
        if self.is_unknown() || o.is_unknown() {
            return Fixed::UNKNOWN;
        }
        self.try_mul(o).unwrap_or(Fixed::UNKNOWN)
    }

    fn try_mul(&self, o: &Fixed) -> Option<Fixed> {
        let (ua, ub) = (self.m.unsigned_abs(), o.m.unsigned_abs());
        let negative = (self.m < 0) != (o.m < 0);
        if (ua | ub) >> BITS == 0 {
            // Both below 1: one 64×64-bit product, and |x̃|, |ỹ| ≤ 1.
            let product = ua * ub;
            let mag = (product >> BITS) as i128;
            let cross = match self.e.checked_mul(o.e)? {
                0 => 0,
                p => (p >> BITS) + 1,
            };
            let e = self
                .e
                .checked_add(o.e)?
                .checked_add(cross)?
                .checked_add(u128::from(product & LOW != 0))?;
            let m = if negative { -mag } else { mag };
            return (e != u128::MAX).then_some(Fixed { m, e });
        }
        let (ah, al, bh, bl) = (ua >> BITS, ua & LOW, ub >> BITS, ub & LOW);
        // (ua·ub) >> 64 = ah·bh·2⁶⁴ + ah·bl + al·bh + (al·bl >> 64).
        let hh = ah.checked_mul(bh)?;
        let top = if hh >> (127 - BITS) != 0 { return None } else { hh << BITS };
        let mag = top
            .checked_add(ah.checked_mul(bl)?)?
            .checked_add(al.checked_mul(bh)?)?
            .checked_add((al * bl) >> BITS)?;
        let mag = i128::try_from(mag).ok()?;
        let m = if negative { -mag } else { mag };
        let cross = match self.e.checked_mul(o.e)? {
            0 => 0,
            p => (p >> BITS) + 1,
        };
        let lost = u128::from((al * bl) & LOW != 0);
        let e = self
            .magnitude()
            .checked_mul(o.e)?
            .checked_add(o.magnitude().checked_mul(self.e)?)?
            .checked_add(cross)?
            .checked_add(lost)?;
        (e != u128::MAX).then_some(Fixed { m, e })
    }

    /// Whether |x − y| ≤ t is settled by the bounds: `Some(true)` when it
    /// holds for every x and y the bounds allow, `Some(false)` when it fails
    /// for every one, `None` when the bounds do not tell.
    pub(crate) fn within(&self, y: &Fixed, t: &Fixed) -> Option<bool> {
        if self.is_unknown() || y.is_unknown() || t.is_unknown() {
            return None;
        }
        let gap = self.m.checked_sub(y.m)?.unsigned_abs();
        let err = self.e.checked_add(y.e)?;
        let t_lo = t.m.checked_sub_unsigned(t.e)?;
        let t_hi = u128::try_from(t.m.checked_add_unsigned(t.e)?.max(0)).ok()?;
        if u128::try_from(t_lo).is_ok_and(|lo| gap.checked_add(err).is_some_and(|g| g <= lo)) {
            return Some(true);
        }
        if gap.checked_sub(err).is_some_and(|g| g > t_hi) {
            return Some(false);
        }
        None
    }
}

/// The i128 mantissa as an exact rational's numerator over 2⁶⁴, for tests.
#[cfg(test)]
fn exact(x: &Fixed) -> crate::Q {
    crate::Q::new(BigInt::from(x.m), BigInt::from(1u8) << BITS)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Q;
    use num_traits::One;
    use proptest::prelude::*;

    fn q(n: i64, d: i64) -> Q {
        crate::q(n, d)
    }

    fn fx(x: &Q) -> Fixed {
        Fixed::ratio(x.numer(), x.denom())
    }

    /// |x − x̃| ≤ e·2⁻⁶⁴, decided on rationals.
    fn covers(f: &Fixed, x: &Q) -> bool {
        let unit = Q::new(BigInt::one(), BigInt::one() << BITS);
        !f.is_unknown() && (x - exact(f)).abs() <= unit * Q::from_integer(BigInt::from(f.e))
    }

    proptest! {
        /// A product and sum of rationals with denominators up to 10¹⁷ (as
        /// 17-digit decimals have), chained: the exact value stays within
        /// the bound at every step.
        #[test]
        fn bounds_cover_the_exact_value(
            xs in proptest::collection::vec((-10i64.pow(17)..10i64.pow(17), 1i64..10i64.pow(17)), 2..12)
        ) {
            let mut exact_acc = Q::one();
            let mut acc = Fixed::ONE;
            for (k, &(n, d)) in xs.iter().enumerate() {
                let x = q(n, d);
                let f = fx(&x);
                prop_assert!(covers(&f, &x));
                if k % 2 == 0 {
                    exact_acc = &exact_acc * &x;
                    acc = acc.mul(&f);
                } else {
                    exact_acc = &exact_acc + &x;
                    acc = acc.add(&f);
                }
                if acc.is_unknown() {
                    break;
                }
                prop_assert!(covers(&acc, &exact_acc), "step {k}: {acc:?} vs {exact_acc}");
            }
        }
    }

    proptest! {
        /// `within` settles only what the exact comparison agrees with.
        #[test]
        fn within_agrees_with_the_exact_comparison(
            (xn, xd) in (-10i64.pow(15)..10i64.pow(15), 1i64..10i64.pow(15)),
            (yn, yd) in (-10i64.pow(15)..10i64.pow(15), 1i64..10i64.pow(15)),
            (tn, td) in (0i64..10i64.pow(6), 1i64..10i64.pow(18)),
        ) {
            let (x, y, t) = (q(xn, xd), q(yn, yd), q(tn, td));
            let exact = (&x - &y).abs() <= t;
            let three = fx(&x).mul(&fx(&Q::from_integer(3.into())));
            let three_x = &x * Q::from_integer(3.into());
            if let Some(v) = fx(&x).within(&fx(&y), &fx(&t)) {
                prop_assert_eq!(v, exact);
            }
            if let Some(v) = three.within(&fx(&y), &fx(&t)) {
                prop_assert_eq!(v, (&three_x - &y).abs() <= t);
            }
        }
    }

    #[test]
    fn boundaries_and_overflow() {
        // |1/3 − 1/3| ≤ 0 holds exactly, but 1/3 is not exact in binary:
        // the filter cannot tell.
        let third = fx(&q(1, 3));
        assert_eq!(third.within(&third, &Fixed::ZERO), None);
        // Exact binary values are settled either way.
        let half = fx(&q(1, 2));
        assert_eq!(half.within(&half, &Fixed::ZERO), Some(true));
        assert_eq!(half.within(&Fixed::ZERO, &fx(&q(1, 4))), Some(false));
        // 2⁶⁰ · 2⁶⁰ does not fit: unknown, and unknown settles nothing.
        let big = Fixed::ratio(&(BigInt::one() << 60), &BigInt::one());
        assert!(big.mul(&big).is_unknown());
        assert_eq!(big.mul(&big).within(&Fixed::ZERO, &Fixed::ONE), None);
        assert!(Fixed::ratio(&(BigInt::one() << 70), &BigInt::one()).is_unknown());
        // Signs: (−3/2)(5/4) = −15/8, exact.
        let p = fx(&q(-3, 2)).mul(&fx(&q(5, 4)));
        assert_eq!((exact(&p), p.e), (q(-15, 8), 0));
    }
}
