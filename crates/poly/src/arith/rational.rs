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
