//! Real-root isolation by Descartes' rule of signs, returning the very
//! intervals of Sturm bisection.
//!
//! [`crate::univariate::sturm`] isolates the real roots of a square-free f by bisecting
//! (−B, B] (B a power of two above every root) and counting roots in each
//! half with the Sturm chain, whose remainders grow to numbers of thousands
//! of bits on the stability conditions. Its intervals are part of every
//! report (each critical Φ is printed with an interval refined from them),
//! so a faster isolation must reproduce them exactly. This module does so:
//!
//! 1. The positive and negative roots of f located by the
//!    Vincent–Collins–Akritas bisection: on a dyadic interval (a, a + w),
//!    Descartes' rule on (1 + x)^n·h(1/(1 + x)), h(x) = f(a + w·x) scaled
//!    to integers, bounds the number of roots in the open interval; 0 or 1
//!    sign change is exact. A root at a halving point is seen there
//!    exactly. Only Taylor shifts by one and shifts of bits: no remainder
//!    sequence. The bisection starts from Fujiwara's bound (often far below
//!    Cauchy's), and an even f(x) = F(x²) is located through the positive
//!    roots of F.
//! 2. Sturm's bisection replayed on the roots now located: its only
//!    questions are "how many roots in (lo, mid]" and "is mid a root", and a
//!    located root answers "are you below x" with at most one sign of f,
//!    narrowing its interval for the next question.
//!
//! The result is identical to [`crate::univariate::sturm::isolate_squarefree_sturm`]
//! (a property test holds the two together). Descartes' bisection is slow
//! where complex roots crowd the real axis; past a budget of parts it gives
//! up (`None`) and the caller runs the Sturm chain.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use crate::arith::rational::{cmp, midpoint};
use crate::univariate::sturm::{root_bound, CmpZero, IntPoly};
use crate::{UPoly, Q};

/// A real root of f as the replay sees it.
enum Root {
    Rational(Q),
    /// The one root of the located polynomial P in the open interval
    /// (lo, hi); `s_hi` is the sign of P on (root, hi). P is f itself, or
    /// F for an even f(x) = F(x²), and then the root of f is ±√ of P's
    /// (`neg` for the minus sign).
    Between {
        lo: Q,
        hi: Q,
        s_hi: Ordering,
        neg: bool,
    },
    /// ±√y for a positive rational y that is not a square.
    Sqrt {
        y: Q,
        neg: bool,
    },
}

impl Root {
    /// The root against `x`: `Less` when the root is below. Narrows the
    /// interval of a root to the side of `x` that holds it (or makes the
    /// root rational when it is `x`).
    fn cmp_point(&mut self, x: &Q, located: &Located) -> Ordering {
        // Roots ±√y: compare y with x² on the side of zero that x is on.
        let (t, neg) = match self {
            Root::Rational(r) => return cmp(r, x),
            Root::Sqrt { neg, .. } | Root::Between { neg, .. } if located.squared => {
                let neg = *neg;
                if !neg && !x.is_positive() {
                    return Ordering::Greater;
                }
                if neg && !x.is_negative() {
                    return Ordering::Less;
                }
                // A reduced fraction's square is reduced: no gcd.
                (Q::new_raw(x.numer() * x.numer(), x.denom() * x.denom()), neg)
            }
            _ => (x.clone(), false),
        };
        let o = match self {
            Root::Rational(_) => unreachable!("returned above"),
            Root::Sqrt { y, .. } => cmp(y, &t),
            Root::Between { lo, hi, s_hi, .. } => {
                if cmp(&t, lo) != Ordering::Greater {
                    Ordering::Greater
                } else if cmp(&t, hi) != Ordering::Less {
                    Ordering::Less
                } else {
                    let s = located.poly.sign_at(&t);
                    if s == Ordering::Equal {
                        Ordering::Equal
                    } else if s == *s_hi {
                        *hi = t;
                        Ordering::Less
                    } else {
                        *lo = t;
                        Ordering::Greater
                    }
                }
            }
        };
        if o == Ordering::Equal {
            *self = Root::Rational(x.clone());
        }
        if neg {
            o.reverse()
        } else {
            o
        }
    }
}

/// The polynomial whose roots the [`Root`]s locate.
struct Located {
    poly: IntPoly,
    /// Whether `poly` is F of an even f(x) = F(x²).
    squared: bool,
}

/// The parts Descartes' bisection may take on each side of zero before
/// [`isolate`] gives up for the Sturm chain: generous for well-separated
/// roots (the built-ins' conditions take 1–30), cut short where complex
/// roots crowd the axis and the chain is cheaper (DESIGN.md).
pub(crate) fn budget(degree: usize) -> usize {
    4 * degree + 16
}

/// Sturm's isolating intervals of the square-free `sf` (degree ≥ 1): all
/// of them, or with `positive_only` those of the roots in (0, ∞). `None`
/// when Descartes' bisection needs more than `budget` parts on a side.
pub(crate) fn isolate(sf: &UPoly, positive_only: bool, mut budget: usize) -> Option<Vec<(Q, Q)>> {
    let b = root_bound(sf);
    let c = crate::univariate::upoly::int_primitive(sf);
    let lowest = c.iter().position(|x| !x.is_zero()).expect("non-zero");
    // The Sturm chain's remainders grow with the coefficients far faster
    // than Descartes' parts do: past 256 bits the budget grows with the
    // bits, one more budget per 96 (A(α) of SDIRK34 read from its decimals:
    // degree 18 and 1500 bits, 4 budgets of parts in 1.6 ms against 70 ms
    // for the chain; degree 6 and 750 bits, 8 budgets in 0.9 ms against
    // 2.1 ms).
    let bits = c.iter().map(BigInt::bits).max().unwrap_or(0);
    if bits > 256 {
        budget = budget.saturating_mul(usize::try_from(bits / 96).unwrap_or(usize::MAX));
    }
    // f without its root at zero (square-free: at most a simple one).
    let g = &c[lowest..];
    let e = b.numer().bits() - 1; // B = 2^e
    debug_assert!(b.denom().is_one() && (BigInt::one() << e) == *b.numer());
    let zero = (lowest > 0).then(|| Root::Rational(Q::zero()));
    let squared = g.len() > 2 && g.iter().skip(1).step_by(2).all(Zero::is_zero);
    let mut roots: Vec<Root> = Vec::new();
    let located = if squared {
        // g(x) = F(x²): the roots of F in (0, B²), and ±√ of each.
        let big_f: Vec<BigInt> = g.iter().step_by(2).cloned().collect();
        let positive: Vec<Root> = descartes_isolate(&big_f, 2 * e, false, budget)?
            .into_iter()
            .map(|found| match found {
                Found::At(y) => match exact_sqrt(&y) {
                    Some(r) => Root::Rational(r),
                    None => Root::Sqrt { y, neg: false },
                },
                Found::Between { lo, hi, s_hi, .. } => Root::Between { lo, hi, s_hi, neg: false },
            })
            .collect();
        for r in positive.iter().rev() {
            roots.push(match r {
                Root::Rational(q) => Root::Rational(-q),
                Root::Sqrt { y, .. } => Root::Sqrt { y: y.clone(), neg: true },
                Root::Between { lo, hi, s_hi, .. } => {
                    Root::Between { lo: lo.clone(), hi: hi.clone(), s_hi: *s_hi, neg: true }
                }
            });
        }
        roots.extend(zero);
        roots.extend(positive);
        Located { poly: IntPoly::from_ints(big_f), squared: true }
    } else {
        // The negative roots of g as the positive roots of g(−x) (only the
        // largest, when only positives are wanted), then its positive roots.
        if g.len() > 1 {
            let mirrored: Vec<BigInt> = g
                .iter()
                .enumerate()
                .map(|(k, x)| if k % 2 == 1 { -x } else { x.clone() })
                .collect();
            let mut negative = descartes_isolate(&mirrored, e, positive_only, budget)?;
            negative.reverse();
            roots.extend(negative.into_iter().map(|found| match found {
                Found::At(r) => Root::Rational(-r),
                Found::Between { lo, hi, s_lo, .. } => {
                    Root::Between { lo: -hi, hi: -lo, s_hi: s_lo, neg: false }
                }
            }));
        }
        roots.extend(zero);
        if g.len() > 1 {
            roots.extend(descartes_isolate(g, e, false, budget)?.into_iter().map(
                |found| match found {
                    Found::At(r) => Root::Rational(r),
                    Found::Between { lo, hi, s_hi, .. } => {
                        Root::Between { lo, hi, s_hi, neg: false }
                    }
                },
            ));
        }
        Located { poly: IntPoly::from_ints(g.to_vec()), squared: false }
    };
    let mut out = Vec::new();
    let mut replay = Replay { located: &located, out: &mut out };
    let lo = -b.clone();
    if positive_only {
        replay.positive(&mut roots, lo, b);
    } else {
        replay.isolate_in(&mut roots, lo, b);
    }
    Some(out)
}

/// √y when it is rational (y > 0 in lowest terms: both parts squares).
fn exact_sqrt(y: &Q) -> Option<Q> {
    let (a, b) = (y.numer().sqrt(), y.denom().sqrt());
    (&a * &a == *y.numer() && &b * &b == *y.denom()).then(|| Q::new(a, b))
}

/// A root in (0, 2^e) found by Descartes' bisection.
#[derive(Debug, PartialEq)]
pub(crate) enum Found {
    /// A root at a halving point.
    At(Q),
    /// The one root in the open interval (lo, hi); `s_lo`, `s_hi` the signs
    /// of the polynomial on (lo, root) and (root, hi).
    Between { lo: Q, hi: Q, s_lo: Ordering, s_hi: Ordering },
}

/// The roots of `g` (g(0) ≠ 0) in (0, 2^e), increasing. With `first_only`,
/// stops after the first. `None` past `budget` parts.
///
/// The bisection runs on `i128` coefficients while every shift and sum
/// fits (the stability conditions of small methods stay far inside), and
/// on `BigInt` from the start when one does not: the same steps, so the
/// same answer (a property test holds the two together).
pub(crate) fn descartes_isolate(
    g: &[BigInt],
    e: u64,
    first_only: bool,
    budget: usize,
) -> Option<Vec<Found>> {
    use num_traits::ToPrimitive;
    if let Some(small) = g.iter().map(BigInt::to_i128).collect::<Option<Vec<i128>>>() {
        if let Ok(found) = bisect(&small, e, first_only, budget) {
            return found;
        }
    }
    bisect(g, e, first_only, budget).unwrap_or_else(|Overflow| unreachable!("BigInt overflowed"))
}

/// An `i128` step of the bisection that would overflow.
#[derive(Debug)]
pub(crate) struct Overflow;

/// A coefficient of Descartes' bisection: a `BigInt`, whose operations
/// never fail, or an `i128`, whose every shift and sum is checked.
pub(crate) trait Coef: Clone {
    fn vanishes(&self) -> bool;
    fn sign_of(&self) -> Ordering;
    /// The bits of the magnitude (0 for zero).
    fn bit_len(&self) -> u64;
    fn shifted(&self, k: u64) -> Result<Self, Overflow>;
    fn add_checked(&mut self, other: &Self) -> Result<(), Overflow>;
    fn twos(&self) -> Option<u64>;
    fn halve_by(&mut self, k: u64);
}

impl Coef for BigInt {
    fn vanishes(&self) -> bool {
        Zero::is_zero(self)
    }
    fn sign_of(&self) -> Ordering {
        self.sign().cmp_zero()
    }
    fn bit_len(&self) -> u64 {
        BigInt::bits(self)
    }
    fn shifted(&self, k: u64) -> Result<Self, Overflow> {
        Ok(self << k)
    }
    fn add_checked(&mut self, other: &Self) -> Result<(), Overflow> {
        *self += other;
        Ok(())
    }
    fn twos(&self) -> Option<u64> {
        BigInt::trailing_zeros(self)
    }
    fn halve_by(&mut self, k: u64) {
        *self >>= k;
    }
}

impl Coef for i128 {
    fn vanishes(&self) -> bool {
        *self == 0
    }
    fn sign_of(&self) -> Ordering {
        self.cmp(&0)
    }
    fn bit_len(&self) -> u64 {
        u64::from(128 - self.unsigned_abs().leading_zeros())
    }
    fn shifted(&self, k: u64) -> Result<Self, Overflow> {
        // Fits when shifting back gives the number again (sign kept).
        let k = u32::try_from(k).ok().filter(|&k| k < 128).ok_or(Overflow);
        match k {
            _ if *self == 0 => Ok(0),
            Ok(k) if (self << k) >> k == *self => Ok(self << k),
            _ => Err(Overflow),
        }
    }
    fn add_checked(&mut self, other: &Self) -> Result<(), Overflow> {
        *self = self.checked_add(*other).ok_or(Overflow)?;
        Ok(())
    }
    fn twos(&self) -> Option<u64> {
        (*self != 0).then(|| u64::from(i128::trailing_zeros(*self)))
    }
    fn halve_by(&mut self, k: u64) {
        *self >>= k;
    }
}

/// [`descartes_isolate`] on one kind of coefficient: `Err` at the first
/// `i128` overflow.
pub(crate) fn bisect<C: Coef>(
    g: &[C],
    e: u64,
    first_only: bool,
    budget: usize,
) -> Result<Option<Vec<Found>>, Overflow> {
    let n = g.len() - 1;
    let mut out = Vec::new();
    // No sign change: no positive root at all.
    if changes(g) == 0 {
        return Ok(Some(out));
    }
    // Cauchy's bound (Sturm's) can be far above the roots; bisect from
    // Fujiwara's, which is as safe and often much smaller.
    let e = e.min(fujiwara_exponent(g));
    // h(x) = g(2^e·x) on (0, 1); a part (h, k, d) stands for the interval
    // 2^e·(k, k + 1)/2^d, and a point k for 2^e·k/2^d.
    enum Item<C> {
        Part(Vec<C>, BigInt, u64),
        Point(BigInt, u64),
    }
    let at = |j: BigInt, d: u64| {
        if d >= e {
            Q::new(j, BigInt::one() << (d - e))
        } else {
            Q::from_integer(j << (e - d))
        }
    };
    let top =
        g.iter().enumerate().map(|(k, x)| x.shifted(e * k as u64)).collect::<Result<_, _>>()?;
    let mut stack = vec![Item::Part(strip_twos(top), BigInt::zero(), 0u64)];
    let mut parts = 0;
    while let Some(item) = stack.pop() {
        let (h, k, d) = match item {
            Item::Point(k, d) => {
                out.push(Found::At(at(k, d)));
                if first_only {
                    break;
                }
                continue;
            }
            Item::Part(h, k, d) => (h, k, d),
        };
        parts += 1;
        if parts > budget {
            return Ok(None);
        }
        // Its sign changes bound the roots in (0, 1); zero coefficients
        // (roots of h at 0 or 1, met as halving points) are skipped.
        let mut rev: Vec<C> = h.iter().rev().cloned().collect();
        shift_by_one(&mut rev)?;
        match changes(&rev) {
            0 => continue,
            1 => {
                // Near x = 1⁻ (y = 0⁺ in rev(1 + y)) and x = 0⁺, h has the
                // sign of its lowest non-zero coefficient there.
                let lowest_sign = |c: &[C]| {
                    c.iter().find(|x| !x.vanishes()).map_or(Ordering::Equal, Coef::sign_of)
                };
                out.push(Found::Between {
                    lo: at(k.clone(), d),
                    hi: at(k + 1, d),
                    s_lo: lowest_sign(&h),
                    s_hi: lowest_sign(&rev),
                });
                if first_only {
                    break;
                }
                continue;
            }
            _ => {}
        }
        // Halves: 2^n·h(x/2) on the left, that shifted by one on the right;
        // left(1) = 2^n·h(1/2) tells a root at the halving point.
        let left: Vec<C> = h
            .iter()
            .enumerate()
            .map(|(j, x)| x.shifted((n - j) as u64))
            .collect::<Result<_, _>>()?;
        let mut right = left.clone();
        shift_by_one(&mut right)?;
        let k2: BigInt = k << 1;
        let mid_is_root = right[0].vanishes();
        stack.push(Item::Part(strip_twos(right), &k2 + 1, d + 1));
        if mid_is_root {
            stack.push(Item::Point(&k2 + 1, d + 1));
        }
        stack.push(Item::Part(strip_twos(left), k2, d + 1));
    }
    Ok(Some(out))
}

/// Sign changes of a coefficient sequence, zeros skipped.
fn changes<C: Coef>(c: &[C]) -> usize {
    let mut last = Ordering::Equal;
    let mut count = 0;
    for s in c.iter().map(Coef::sign_of).filter(|s| *s != Ordering::Equal) {
        if last != Ordering::Equal && s != last {
            count += 1;
        }
        last = s;
    }
    count
}

/// g(x) ↦ g(x + 1) in place (coefficients lowest first), by repeated
/// synthetic division: n(n+1)/2 additions.
pub(crate) fn shift_by_one<C: Coef>(c: &mut [C]) -> Result<(), Overflow> {
    let n = c.len();
    for i in 0..n {
        for j in (i..n - 1).rev() {
            let (lo, hi) = c.split_at_mut(j + 1);
            lo[j].add_checked(&hi[0])?;
        }
    }
    Ok(())
}

/// An e with every root of `g` (degree ≥ 1) below 2^e in modulus, by
/// Fujiwara's bound 2·max_k |a_{n−k}/a_n|^{1/k} (the last term halved),
/// each ratio bounded by bit lengths: |a| < 2^bits(a), |a_n| ≥ 2^(bits(a_n) − 1).
fn fujiwara_exponent<C: Coef>(g: &[C]) -> u64 {
    let n = g.len() - 1;
    let lead = g[n].bit_len() as i64;
    let mut e = i64::MIN;
    for k in 1..=n {
        let a = &g[n - k];
        if a.vanishes() {
            continue;
        }
        // |a_{n−k}/a_n| < 2^t, so its k-th root is below 2^⌈t/k⌉.
        let t = a.bit_len() as i64 - lead + 1 - i64::from(k == n);
        e = e.max(t.div_euclid(k as i64) + i64::from(t.rem_euclid(k as i64) != 0));
    }
    // The factor 2, and at least 2^0 (a part of (0, 1) is the least).
    u64::try_from(e + 1).unwrap_or(0)
}

/// Divides out the largest power of two common to the coefficients.
fn strip_twos<C: Coef>(mut c: Vec<C>) -> Vec<C> {
    let t = c.iter().filter_map(Coef::twos).min().unwrap_or(0);
    if t > 0 {
        for x in &mut c {
            x.halve_by(t);
        }
    }
    c
}

/// Sturm's bisection ([`crate::univariate::sturm::isolate_squarefree_sturm`]) replayed
/// on located roots.
struct Replay<'a> {
    located: &'a Located,
    out: &'a mut Vec<(Q, Q)>,
}

impl Replay<'_> {
    /// The intervals of the roots in `roots` (increasing, exactly the roots
    /// in (lo, hi]).
    fn isolate_in(&mut self, roots: &mut [Root], lo: Q, hi: Q) {
        match roots.len() {
            0 => {}
            1 => {
                if roots[0].cmp_point(&hi, self.located) == Ordering::Equal {
                    self.out.push((hi.clone(), hi));
                } else {
                    self.out.push((lo, hi));
                }
            }
            _ => {
                let mid = midpoint(&lo, &hi);
                let (left, at_mid) = self.split(roots, &mid);
                if at_mid {
                    let i = left - 1;
                    let below = self.beside(roots, i, &lo, &mid);
                    let above = self.beside(roots, i, &hi, &mid);
                    let (head, tail) = roots.split_at_mut(i);
                    self.isolate_in(head, lo, below);
                    self.out.push((mid.clone(), mid));
                    self.isolate_in(&mut tail[1..], above, hi);
                } else {
                    let (head, tail) = roots.split_at_mut(left);
                    self.isolate_in(head, lo, mid.clone());
                    self.isolate_in(tail, mid, hi);
                }
            }
        }
    }

    /// The top level of the bisection of (lo, hi] = (−B, B], keeping only
    /// the roots in (0, ∞) (`roots` holds every positive root and, of the
    /// others, at least the largest when there is one).
    fn positive(&mut self, roots: &mut [Root], lo: Q, hi: Q) {
        if roots.len() < 2 {
            if roots.first_mut().is_some_and(|r| r.cmp_point(&Q::zero(), self.located).is_gt()) {
                self.isolate_in(roots, lo, hi);
            }
            return;
        }
        let zero = Q::zero();
        let (left, at_zero) = self.split(roots, &zero);
        if at_zero {
            let i = left - 1;
            let above = self.beside(roots, i, &hi, &zero);
            self.isolate_in(&mut roots[left..], above, hi);
        } else {
            self.isolate_in(&mut roots[left..], zero, hi);
        }
    }

    /// How many of the roots are at most `mid`, and whether `mid` is one.
    fn split(&self, roots: &mut [Root], mid: &Q) -> (usize, bool) {
        let mut left = 0;
        let mut at_mid = false;
        for r in roots.iter_mut() {
            match r.cmp_point(mid, self.located) {
                Ordering::Less => left += 1,
                Ordering::Equal => {
                    left += 1;
                    at_mid = true;
                    break;
                }
                Ordering::Greater => break,
            }
        }
        (left, at_mid)
    }

    /// Sturm's point beside the rational root `roots[i]` = `r` toward
    /// `toward`: r + (toward − r)/2^k for the least k ≥ 1 that leaves no
    /// other root between it and r (nor on it).
    fn beside(&self, roots: &mut [Root], i: usize, toward: &Q, r: &Q) -> Q {
        let two = Q::from_integer(2.into());
        let mut step = (toward - r) / &two;
        loop {
            let x = r + &step;
            let clear = if x < *r {
                i == 0 || roots[i - 1].cmp_point(&x, self.located) == Ordering::Less
            } else {
                i + 1 == roots.len()
                    || roots[i + 1].cmp_point(&x, self.located) == Ordering::Greater
            };
            if clear {
                return x;
            }
            step /= &two;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::univariate::sturm::{count_real_roots, isolate_squarefree_sturm};
    use proptest::prelude::*;

    /// The full isolation and the positive one against Sturm's bisection,
    /// which defines the intervals: the positive roots are the last ones.
    fn agrees_with_sturm(p: &UPoly) -> Result<(), TestCaseError> {
        let sf = p.squarefree();
        prop_assume!(sf.degree().unwrap_or(0) > 0);
        let sturm = isolate_squarefree_sturm(&sf);
        let full = isolate(&sf, false, usize::MAX).expect("no budget");
        prop_assert_eq!(&full, &sturm);
        let positive = count_real_roots(&sf, &Q::zero(), &root_bound(&sf));
        let only = isolate(&sf, true, usize::MAX).expect("no budget");
        prop_assert_eq!(&only[..], &sturm[sturm.len() - positive..]);
        Ok(())
    }

    fn product(factors: &[UPoly]) -> UPoly {
        factors.iter().fold(UPoly::from_ints(&[1]), |acc, f| &acc * f)
    }

    proptest! {
        /// The bisection on i128 against the same on BigInt: the same
        /// roots, intervals and signs, or an overflow. Coefficients shifted
        /// by up to 90 bits overflow often, at the start or deep in it.
        #[test]
        fn machine_integers_agree_with_big_ones(
            c in proptest::collection::vec((-20i64..20, prop_oneof![3 => 0u32..4, 1 => 0u32..90]), 2..10),
            e in prop_oneof![Just(u64::MAX), 0u64..8],
            first_only in any::<bool>(),
            budget in 1usize..40,
        ) {
            prop_assume!(c[0].0 != 0 && c.last().unwrap().0 != 0);
            let big: Vec<BigInt> = c.iter().map(|&(x, s)| BigInt::from(x) << s).collect();
            let want = bisect(&big, e, first_only, budget).unwrap();
            let small: Vec<i128> = c.iter().map(|&(x, s)| i128::from(x) << s).collect();
            if let Ok(got) = bisect(&small, e, first_only, budget) {
                prop_assert_eq!(got, want);
            }
        }

        /// Random integer polynomials (roots anywhere, complex ones near
        /// the axis, a root at zero when c0 = 0).
        #[test]
        fn random_polynomials(c in proptest::collection::vec(-20i64..20, 2..12)) {
            prop_assume!(*c.last().unwrap() != 0);
            agrees_with_sturm(&UPoly::from_ints(&c))?;
        }

        /// Rational roots with small denominators, many of them dyadic, so
        /// that Sturm's halving points (and Descartes') hit roots, with a
        /// factor without real roots or with irrational ones beside them.
        #[test]
        fn rational_and_dyadic_roots(
            roots in proptest::collection::vec((-40i64..40, prop_oneof![Just(1i64), Just(2), Just(4), Just(8), Just(3)]), 1..7),
            extra in proptest::collection::vec(-6i64..6, 3),
        ) {
            let mut factors: Vec<UPoly> =
                roots.iter().map(|&(a, b)| UPoly::from_ints(&[-a, b])).collect();
            if extra[2] != 0 {
                factors.push(UPoly::from_ints(&extra));
            }
            agrees_with_sturm(&product(&factors))?;
        }

        /// Even and odd polynomials f(x) = x^k·F(x²): the squared path,
        /// with rational squares, non-square rationals and irrational roots.
        #[test]
        fn even_polynomials(
            ys in proptest::collection::vec((-30i64..60, prop_oneof![Just(1i64), Just(4), Just(2), Just(9)]), 1..5),
            odd in any::<bool>(),
        ) {
            // ∏ (b·x² − a): roots ±√(a/b) for a > 0.
            let mut factors: Vec<UPoly> =
                ys.iter().map(|&(a, b)| UPoly::from_ints(&[-a, 0, b])).collect();
            if odd {
                factors.push(UPoly::from_ints(&[0, 1]));
            }
            agrees_with_sturm(&product(&factors))?;
        }
    }

    /// Close roots (a cluster Descartes must split deeply) and a budget too
    /// small for them: `None`, so the caller runs the Sturm chain.
    #[test]
    fn cluster_and_budget() {
        // (x − 1)(1000x − 1001)(1000000x − 1000001)(x² − 2)
        let p = product(&[
            UPoly::from_ints(&[-1, 1]),
            UPoly::from_ints(&[-1001, 1000]),
            UPoly::from_ints(&[-1000001, 1000000]),
            UPoly::from_ints(&[-2, 0, 1]),
        ]);
        assert_eq!(isolate(&p, false, usize::MAX).unwrap(), isolate_squarefree_sturm(&p));
        assert!(isolate(&p, false, 4).is_none());
    }

    /// Fujiwara's exponent bounds every root: 2^e exceeds the largest
    /// modulus (the roots here are known), and it is far below Cauchy's for
    /// a polynomial with a huge constant term.
    #[test]
    fn fujiwara_bounds_roots() {
        // (x − 3)(x + 5)(x − 1/2)·2 = 2x³ + 3x² − 32x + 15 → max |root| 5 < 2^e.
        let e = fujiwara_exponent(&[15, -32, 3, 2].map(BigInt::from));
        assert!(e >= 3, "5 < 2^e");
        // x^10 − 2^40: roots of modulus 16; Cauchy's bound is 2^40 + 1.
        let mut c = vec![BigInt::zero(); 11];
        c[0] = -(BigInt::one() << 40usize);
        c[10] = BigInt::one();
        let e = fujiwara_exponent(&c);
        assert!((5..=7).contains(&e), "16 < 2^e, and not far above: e = {e}");
    }
}
