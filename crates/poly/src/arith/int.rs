//! An integer held in an `i128` while it fits and in a [`BigInt`] once it
//! does not: the ring of the elementary weights on the integer route,
//! where a tableau with small denominators never leaves machine words and
//! one of 17-digit decimals overflows within two products.
//!
//! Exact either way: an `i128` operation is checked, and the one that
//! would overflow is done again on `BigInt`s. A value, once big, stays big
//! (it is not demoted): the weights only grow.

use std::borrow::Cow;

use num_bigint::BigInt;
use num_traits::{ToPrimitive, Zero};

/// An exact integer: small, or big.
#[derive(Clone, Debug)]
pub(crate) enum Int {
    Small(i128),
    Big(BigInt),
}

impl Int {
    pub(crate) const ZERO: Int = Int::Small(0);
    pub(crate) const ONE: Int = Int::Small(1);

    /// Small when it fits.
    pub(crate) fn from_big(x: BigInt) -> Int {
        match x.to_i128() {
            Some(v) => Int::Small(v),
            None => Int::Big(x),
        }
    }

    /// The value as a `BigInt` (borrowed when big).
    pub(crate) fn big(&self) -> Cow<'_, BigInt> {
        match self {
            Int::Small(v) => Cow::Owned(BigInt::from(*v)),
            Int::Big(x) => Cow::Borrowed(x),
        }
    }

    pub(crate) fn is_zero(&self) -> bool {
        match self {
            Int::Small(v) => *v == 0,
            Int::Big(x) => x.is_zero(),
        }
    }

    /// self += a·b.
    pub(crate) fn add_mul(&mut self, a: &Int, b: &Int) {
        if let (Int::Small(s), Int::Small(x), Int::Small(y)) = (&*self, a, b) {
            if let Some(v) = x.checked_mul(*y).and_then(|p| p.checked_add(*s)) {
                *self = Int::Small(v);
                return;
            }
        }
        let product = a.big().into_owned() * &*b.big();
        match self {
            Int::Big(x) => *x += product,
            Int::Small(v) => *self = Int::Big(product + *v),
        }
    }

    /// self·o.
    pub(crate) fn mul(&self, o: &Int) -> Int {
        if let (Int::Small(x), Int::Small(y)) = (self, o) {
            if let Some(v) = x.checked_mul(*y) {
                return Int::Small(v);
            }
        }
        // A big factor times zero is the one product of a big value that
        // fits: keep it small, as `from_big` would.
        if self.is_zero() || o.is_zero() {
            return Int::ZERO;
        }
        Int::Big(&*self.big() * &*o.big())
    }
}

impl From<usize> for Int {
    fn from(n: usize) -> Int {
        Int::Small(n as i128)
    }
}

/// Equal values: a big one may hold a value that would fit.
impl PartialEq for Int {
    fn eq(&self, o: &Int) -> bool {
        match (self, o) {
            (Int::Small(x), Int::Small(y)) => x == y,
            _ => *self.big() == *o.big(),
        }
    }
}

/// Σ xᵢ·yᵢ.
pub(crate) fn dot<'a>(xs: impl IntoIterator<Item = (&'a Int, &'a Int)>) -> Int {
    let mut acc = Int::ZERO;
    for (x, y) in xs {
        if !x.is_zero() && !y.is_zero() {
            acc.add_mul(x, y);
        }
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Small, near the edge of i128, or big.
    fn int() -> impl Strategy<Value = BigInt> {
        prop_oneof![
            (-1000i64..1000).prop_map(BigInt::from),
            any::<i128>().prop_map(BigInt::from),
            (any::<i128>(), any::<i64>()).prop_map(|(a, b)| BigInt::from(a) * BigInt::from(b)),
            (1u32..64).prop_map(|k| BigInt::from(1u8) << (63 + k)),
            Just(BigInt::zero()),
        ]
    }

    proptest! {
        /// Chained products and sums against BigInt arithmetic, the slow
        /// oracle: the same value, small exactly when it fits.
        #[test]
        fn agrees_with_bigint(xs in proptest::collection::vec((int(), int()), 1..8)) {
            let mut acc = Int::ZERO;
            let mut oracle = BigInt::zero();
            for (a, b) in &xs {
                let (ia, ib) = (Int::from_big(a.clone()), Int::from_big(b.clone()));
                acc.add_mul(&ia, &ib);
                oracle += a * b;
                prop_assert_eq!(&*acc.big(), &oracle);
                let p = ia.mul(&ib);
                prop_assert_eq!(&*p.big(), &(a * b));
                prop_assert_eq!(matches!(p, Int::Small(_)), (a * b).to_i128().is_some());
                prop_assert_eq!(acc.is_zero(), oracle.is_zero());
                // Equality by value, small or big.
                prop_assert!(acc == Int::from_big(oracle.clone()));
                prop_assert!(Int::Big(oracle.clone()) == acc);
                prop_assert_eq!(acc == ia, oracle == *a);
            }
        }
    }
}
