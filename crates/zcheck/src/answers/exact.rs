//! Exact numbers as JSON, one shape for the documents that share it
//! (`zcheck region`, `zcheck order`): `{"exact", "value"}`, the exact text
//! and the nearest f64 (`null` where there is none, as for +∞), and for a
//! real algebraic number its defining polynomial and an isolating interval.

use num_traits::ToPrimitive;
use poly::{Algebraic, Poly, Q};
use serde_json::{json, Value};

/// Width to which exact numbers are narrowed before they become floats:
/// 1e-20, made once.
pub(crate) fn fine() -> Q {
    static FINE: std::sync::LazyLock<Q> =
        std::sync::LazyLock::new(|| Q::new(1.into(), num_traits::pow(10.into(), 20)));
    FINE.clone()
}

/// An interval believed to hold an irrational algebraic number, from
/// Newton's method in f64 on its defining polynomial, kept inside the
/// isolating interval by bisection: a guess for
/// [`Algebraic::refine_near`], which checks it exactly (so a wrong guess
/// costs time, never the answer). `None` where f64 cannot tell (a
/// rational, overflow, no sign change seen).
pub(crate) fn guess(a: &Algebraic) -> Option<(Q, Q)> {
    let x = newton(a)?;
    // Rounding in Horner's rule blurs the sign within a few ulps of a
    // well-conditioned root: a margin of 8 ulps either side.
    let m = x.abs() * f64::EPSILON;
    let spread = 8.0 * if m > 0.0 { m } else { f64::MIN_POSITIVE };
    Some((dyadic(x - spread)?, dyadic(x + spread)?))
}

/// Where Newton's method in f64 settles on an irrational `a`, kept inside
/// its isolating interval by bisection ([`guess`]); `None` where f64
/// cannot tell.
fn newton(a: &Algebraic) -> Option<f64> {
    let (lo, hi) = a.ends();
    let p = a.defining_poly();
    if p.degree().unwrap_or(0) < 2 {
        return None;
    }
    let c: Vec<f64> = p.coeffs().iter().map(|q| q.to_f64()).collect::<Option<_>>()?;
    // p and p′ together by Horner's rule.
    let f = |x: f64| c.iter().rev().fold((0.0, 0.0), |(v, d), &ci| (v * x + ci, d * x + v));
    let (lo, hi) = (lo.to_f64()?, hi.to_f64()?);
    let (mut l, mut h) = (lo, hi);
    let (fl, fh) = (f(l).0, f(h).0);
    if !(fl.is_finite() && fh.is_finite()) || fl == 0.0 || fh == 0.0 || (fl < 0.0) == (fh < 0.0) {
        return None;
    }
    let rising = fl < 0.0;
    let mut x = 0.5 * (l + h);
    for _ in 0..100 {
        let (v, d) = f(x);
        if v == 0.0 {
            break;
        }
        if (v < 0.0) == rising {
            l = x;
        } else {
            h = x;
        }
        // Newton's step where it stays inside the bracket, else bisection.
        let n = x - v / d;
        let next = if n > l && n < h { n } else { 0.5 * (l + h) };
        if next == x || !(l < next && next < h) {
            break;
        }
        x = next;
    }
    // Plain Horner's rounding leaves x an ulp or so off the root; Newton's
    // steps on the value by compensated Horner (as if in twice the
    // precision) settle on the nearest f64 of a well-conditioned root,
    // where the rendering's bracket check wants it. Plain Horner's signs
    // placed the bracket (l, h), so only the isolating interval bounds
    // these steps.
    for _ in 0..3 {
        let (v, d) = (compensated_horner(&c, x), f(x).1);
        let n = x - v / d;
        if !(v.is_finite() && d != 0.0 && lo < n && n < hi) || n == x {
            break;
        }
        x = n;
    }
    Some(x)
}

/// p(x) by compensated Horner (Graillat, Langlois and Louvet, 2005): the
/// rounding errors of each product and sum, found exactly by FMA and
/// TwoSum, summed by Horner's rule alongside; `c` lowest power first.
fn compensated_horner(c: &[f64], x: f64) -> f64 {
    let Some((&top, rest)) = c.split_last() else { return 0.0 };
    let (mut s, mut err) = (top, 0.0);
    for &ci in rest.iter().rev() {
        let p = s * x;
        let pe = s.mul_add(x, -p);
        let t = p + ci;
        let z = t - p;
        let se = (p - (t - z)) + (ci - z);
        s = t;
        err = err * x + (pe + se);
    }
    s + err
}

/// A finite f64 as the exact rational it is (num-rational's `from_float`
/// goes through a general big-integer path).
pub(crate) fn dyadic(x: f64) -> Option<Q> {
    let (m, e) = parts(x)?;
    Some(scaled(m.into(), e))
}

/// x = m·2^e exactly, for a finite x.
fn parts(x: f64) -> Option<(i64, i64)> {
    if !x.is_finite() {
        return None;
    }
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if exp == 0 { (frac, -1074) } else { (frac | (1i64 << 52), exp - 1075) };
    Some((if x < 0.0 { -m } else { m }, e))
}

/// n·2^e as a rational in lowest terms.
fn scaled(n: i128, e: i64) -> Q {
    if n == 0 {
        return Q::default();
    }
    let tz = (n.trailing_zeros() as i64).min(if e < 0 { -e } else { 0 });
    let (n, e) = (n >> tz, e + tz);
    let n = Q::from_integer(n.into());
    if e >= 0 {
        Q::from_integer(n.numer() << e as usize)
    } else {
        let one = Q::from_integer(1.into());
        Q::new_raw(n.numer().clone(), one.numer() << (-e) as usize)
    }
}

/// The exact midpoint of two finite f64s.
fn midpoint(x: f64, y: f64) -> Option<Q> {
    let ((mx, ex), (my, ey)) = (parts(x)?, parts(y)?);
    let e = ex.min(ey);
    let (sx, sy) = ((ex - e) as u32, (ey - e) as u32);
    if sx > 60 || sy > 60 {
        return None;
    }
    Some(scaled((mx as i128) * (1i128 << sx) + (my as i128) * (1i128 << sy), e - 1))
}

/// The f64 nearest an algebraic number (correctly rounded): refined
/// narrower than a quarter of the ulp there (from `guess` when given, see
/// [`guess`]), the ends of its interval round to one f64, or to two
/// neighbours whose exact midpoint a sign test places it beside.
pub(crate) fn nearest_f64(a: &Algebraic, guess: Option<&(Q, Q)>) -> f64 {
    if let Some(q) = a.as_rational() {
        return q.to_f64().unwrap_or(f64::NAN);
    }
    // num-rational's `to_f64` rounds correctly, and rounding is monotone:
    // ends that round alike (as they mostly do once refined for a
    // rendering) round `a` there too.
    let (lo, hi) = a.ends();
    if let (Some(xl), Some(xh)) = (lo.to_f64(), hi.to_f64()) {
        if xl == xh && xl.is_finite() && xl != 0.0 {
            return xl;
        }
    }
    if let Some(x) = nearest_by_midpoints(a) {
        return x;
    }
    let mut b = a.clone();
    for _ in 0..64 {
        let (lo, hi) = b.interval();
        let (Some(xl), Some(xh)) = (lo.to_f64(), hi.to_f64()) else { break };
        if !(xl.is_finite() && xh.is_finite()) {
            break;
        }
        if xl == xh {
            return xl;
        }
        if xl.next_up() == xh {
            // The midpoint of neighbours, exact: half their sum has one
            // more bit than either.
            let Some(mid) = midpoint(xl, xh) else { break };
            return if b.cmp_rational(&mid) == std::cmp::Ordering::Less { xl } else { xh };
        }
        // Narrower than a quarter ulp, the ends round alike or to neighbours.
        let top = xl.abs().max(xh.abs());
        let width = dyadic((top.next_up() - top) / 4.0)
            .filter(|w| w > &Q::default())
            .unwrap_or_else(|| (&hi - &lo) / Q::from_integer(1024.into()));
        b = match guess {
            Some((gl, gh)) => a.refine_near(&width, gl, gh),
            None => b.refine(&width),
        };
    }
    a.to_decimal(17).parse().unwrap_or(f64::NAN)
}

/// The f64 nearest an irrational `a` whose interval spans a few f64s,
/// with no refinement: the exact midpoints between neighbouring f64s, from
/// below the interval up, until one lies above `a` (a midpoint outside the
/// interval is placed without a sign). `None` past 16 steps, or where the
/// start below `a` cannot be checked.
fn nearest_by_midpoints(a: &Algebraic) -> Option<f64> {
    use std::cmp::Ordering;
    let (lo, hi) = a.ends();
    let (xl, xh) = (lo.to_f64()?, hi.to_f64()?);
    if !(xl.is_finite() && xh.is_finite()) || xl > xh {
        return None;
    }
    // Two below where lo rounds (in case that rounding is off by one), with
    // a above the midpoint under it: then a rounds to x once it lies below
    // the midpoint over x.
    let mut x = xl.next_down().next_down();
    if a.cmp_rational(&midpoint(x.next_down(), x)?) != Ordering::Greater {
        return None;
    }
    for _ in 0..16 {
        let up = x.next_up();
        if a.cmp_rational(&midpoint(x, up)?) == Ordering::Less {
            return Some(x);
        }
        x = up;
    }
    None
}

/// `a` with an isolating interval no wider than `width`, and the f64
/// nearest it (correctly rounded), for a rendering. The quick way first:
/// where the two midpoints around Newton's f64 `x` lie within `width` of
/// each other and bracket `a` ([`Algebraic::narrowed`], at most three
/// signs), `x` is the nearest f64 and the bracket the interval. Else (`x`
/// off by an ulp, an ulp wider than `width`, f64 out of range) `a`
/// [`refined`] and [`nearest_f64`]; either way the value is the same, and
/// the interval an isolating one no wider than `width`.
pub(crate) fn narrowed_with_value(a: &Algebraic, width: &Q) -> (Algebraic, f64) {
    if let Some(q) = a.as_rational() {
        return (a.clone(), q.to_f64().unwrap_or(f64::NAN));
    }
    if let Some(x) = newton(a) {
        let (below, above) = (x.next_down(), x.next_up());
        // The bracket's width, (ulp below + ulp above)/2, is exact in f64.
        let span = dyadic(0.5 * (above - below));
        if let (Some(m1), Some(m2), Some(span)) = (midpoint(below, x), midpoint(x, above), span) {
            if span <= *width {
                if let Some(n) = a.narrowed(&m1, &m2) {
                    return (n, x);
                }
            }
        }
    }
    let (fine, g) = refined(a, width);
    let value = nearest_f64(&fine, g.as_ref());
    (fine, value)
}

/// `a` refined to `width`, from an f64 guess where one is found (the
/// result is [`Algebraic::refine`]'s either way), and the guess.
pub(crate) fn refined(a: &Algebraic, width: &Q) -> (Algebraic, Option<(Q, Q)>) {
    let g = guess(a);
    let r = match &g {
        Some((gl, gh)) => a.refine_near(width, gl, gh),
        None => a.refine(width),
    };
    (r, g)
}

/// A real algebraic number as JSON: its exact form (the closed form, else
/// the defining polynomial in `var` and an interval), its value, its
/// defining polynomial and an isolating interval narrower than 1e-20.
pub(crate) fn number(a: &Algebraic, var: &str) -> Value {
    // Refined once: the interval, the description and the value read the
    // same number.
    let (fine_a, value) = narrowed_with_value(a, &fine());
    let (lo, hi) = fine_a.interval();
    json!({
        "exact": fine_a.describe(var),
        "value": value,
        "defining_poly": a.defining_poly().to_string_in(var),
        "interval": [lo.to_string(), hi.to_string()],
    })
}

/// A constant of the method's field (rational, or with radicals) as JSON.
pub(crate) fn constant(c: &Poly) -> Value {
    if let Some(q) = c.as_constant() {
        return json!({ "exact": c.to_string(), "value": q.to_f64() });
    }
    let v = poly::advanced::field::approx(c, &fine());
    json!({ "exact": c.to_string(), "value": v.to_f64() })
}

/// +∞ as JSON: exact text `inf`, no f64 value.
pub(crate) fn infinity() -> Value {
    json!({ "exact": "inf", "value": null })
}

#[cfg(test)]
mod tests {
    use super::*;
    use poly::UPoly;
    use proptest::prelude::*;

    proptest! {
        /// `dyadic` is num-rational's exact `from_float`, and `midpoint`
        /// half the exact sum, for every finite f64 (subnormals, zero and
        /// the binade edges included).
        #[test]
        fn floats_are_read_exactly(bits in any::<u64>(), step in 0u32..3) {
            let x = f64::from_bits(bits);
            prop_assume!(x.is_finite());
            prop_assert_eq!(dyadic(x), Q::from_float(x));
            let mut y = x;
            for _ in 0..=step {
                y = y.next_up();
            }
            prop_assume!(y.is_finite());
            let sum = Q::from_float(x).unwrap() + Q::from_float(y).unwrap();
            prop_assert_eq!(midpoint(x, y), Some(sum / Q::from_integer(2.into())));
        }

        /// The value is the f64 nearest the number (the slow oracle halves
        /// until both ends round alike), and the refinement from the f64
        /// guess is bisection's, for roots of products of x² − k and of
        /// (d·x − n) scaled so that the roots span tiny to large.
        #[test]
        fn values_are_the_nearest_float_and_refinements_bisection(
            squares in proptest::collection::vec(2i64..5000, 1..3),
            linear in proptest::collection::vec((-50i64..50, 1i64..9), 0..3),
            shift in -60i32..40,
            width_bits in 20u32..80,
        ) {
            let mut p = UPoly::from_ints(&[1]);
            for &k in &squares {
                p = &p * &UPoly::from_ints(&[-k, 0, 1]);
            }
            for &(n, d) in &linear {
                p = &p * &UPoly::from_ints(&[-n, d]);
            }
            // Roots times 2^shift: p(x / 2^shift).
            let two = poly::q(2, 1);
            let s = if shift >= 0 {
                num_traits::pow(two.recip(), shift as usize)
            } else {
                num_traits::pow(two.clone(), (-shift) as usize)
            };
            let p = UPoly::new(
                p.coeffs()
                    .iter()
                    .enumerate()
                    .map(|(k, c)| c * num_traits::pow(s.clone(), k))
                    .collect(),
            );
            let width = num_traits::pow(two.recip(), width_bits as usize);
            for a in Algebraic::real_roots(&p) {
                // The rendering's one step: the nearest f64, and an
                // isolating interval inside the one held, no wider than
                // `width`, of the same number.
                let (narrow, value) = narrowed_with_value(&a, &width);
                prop_assert_eq!(value.to_bits(), testkit::oracle::nearest_f64(&a).to_bits());
                let ((l, h), (nl, nh)) = (a.interval(), narrow.interval());
                prop_assert!(narrow == a && narrow.defining_poly() == a.defining_poly());
                prop_assert!(l <= nl && nh <= h && &nh - &nl <= width, "{:?} in {:?}", narrow, a);
                let (fast, g) = refined(&a, &width);
                prop_assert_eq!(fast.interval(), a.refine(&width).interval());
                let want = testkit::oracle::nearest_f64(&a);
                prop_assert_eq!(nearest_f64(&fast, g.as_ref()).to_bits(), want.to_bits());
                prop_assert_eq!(nearest_f64(&a, None).to_bits(), want.to_bits());
            }
        }
    }
}
