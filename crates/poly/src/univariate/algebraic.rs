//! Real algebraic numbers: exact stability limits such as 2, √2 or
//! √(2√5 − 2).
//!
//! An [`Algebraic`] is either a rational or an irrational real root of a
//! defining polynomial together with an isolating interval. The defining
//! polynomial is kept monic, square-free and free of rational roots (and of
//! the factors x² − y for rational y that do not vanish at the number), so a
//! limit found as a root of Φ²(Φ² − 2) is stored as the root of Φ² − 2, and a
//! root of Φ² − 4 is the rational 2. Everything is decided exactly: signs of
//! polynomials at the number come from gcds and Sturm counts, comparisons
//! refine intervals until they separate, decimals come from refinement, never
//! from floating point.

use std::cmp::Ordering;
use std::fmt;
use std::sync::Arc;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

use crate::arith::rational::{add, cmp, eq, mul, shr};
use crate::univariate::roots::isolate_squarefree;
use crate::univariate::sturm::{
    count_real_roots, refine_int, refine_int_near, refine_quadratic, sign, IntPoly,
};
use crate::{UPoly, Q};

/// The least and the greatest of some real roots.
pub(crate) type Ends = (Algebraic, Algebraic);

/// A real algebraic number, exact.
#[derive(Clone)]
pub struct Algebraic {
    repr: Repr,
}

#[derive(Clone)]
enum Repr {
    Rational(Q),
    /// An irrational root: `poly` monic, square-free, degree ≥ 2, without
    /// rational roots; exactly one root in (lo, hi); poly(lo), poly(hi)
    /// non-zero with opposite signs. `ip` is poly's primitive integer form,
    /// kept so that signs at rationals (comparisons, refinement) cost one
    /// evaluation.
    Root {
        poly: UPoly,
        ip: Arc<IntPoly>,
        lo: Q,
        hi: Q,
    },
}

/// The irrational root of `poly` in (lo, hi) (the invariants of
/// [`Repr::Root`] hold).
fn root(poly: UPoly, lo: Q, hi: Q) -> Algebraic {
    let ip = Arc::new(IntPoly::new(&poly));
    Algebraic { repr: Repr::Root { poly, ip, lo, hi } }
}

impl Algebraic {
    /// The rational `q` as an algebraic number.
    pub fn from_rational(q: Q) -> Algebraic {
        Algebraic { repr: Repr::Rational(q) }
    }

    /// Zero.
    pub fn zero() -> Algebraic {
        Algebraic::from_rational(Q::zero())
    }

    /// Every distinct real root of `p`, increasing (empty for constants and
    /// the zero polynomial).
    pub fn real_roots(p: &UPoly) -> Vec<Algebraic> {
        let sf = p.squarefree();
        let intervals = isolate_squarefree(&sf);
        let (rational, all) = rational_roots(&sf, &intervals);
        // With every interval asked about, the rational roots found are all.
        let all = all.unwrap_or_else(|| rational.iter().flatten().cloned().collect());
        numbers_of(&sf, intervals, rational, &all)
    }

    /// The real roots of `p` in the open interval (0, ∞), increasing.
    pub fn positive_roots(p: &UPoly) -> Vec<Algebraic> {
        // Many conditions have no positive root; Descartes' rule on a few
        // halvings of (0, B) proves that without any isolation (the same,
        // empty, answer). Budget: 16 parts, a measured trade (DESIGN.md).
        if let Some(n) = p.degree().filter(|&n| n > 0) {
            let lowest = p.coeffs().iter().position(|c| !c.is_zero()).unwrap_or(n);
            let zero_free = UPoly::new(p.coeffs()[lowest..].to_vec());
            // An even F(x²) has a positive root exactly when F has one.
            let zero_free = zero_free.even_part().unwrap_or(zero_free);
            let d = zero_free.degree().unwrap_or(0);
            if d == 0 || crate::univariate::roots::no_positive_roots(&zero_free, 16) {
                return Vec::new();
            }
        }
        // Only the positive roots isolated (the same intervals) and made
        // numbers, when every rational root is known without the others.
        let sf = p.squarefree();
        let budget = crate::univariate::isolate::budget(sf.degree().unwrap_or(0));
        if let Some(intervals) = crate::univariate::isolate::isolate(&sf, true, budget) {
            if let Some((all, factors)) = even_rational_roots(&sf) {
                let rational = intervals
                    .iter()
                    .map(|(lo, hi)| {
                        if eq(lo, hi) {
                            Some(lo.clone())
                        } else {
                            all.iter().find(|r| lo < *r && *r < hi).cloned()
                        }
                    })
                    .collect();
                return numbers_with(&sf, intervals, rational, &all, &factors);
            }
            if let (rational, Some(all)) = rational_roots(&sf, &intervals) {
                return numbers_of(&sf, intervals, rational, &all);
            }
        }
        Algebraic::real_roots(p).into_iter().filter(|a| a.sign() == Ordering::Greater).collect()
    }

    /// The isolating intervals of the distinct real roots of the
    /// square-free, monic `sf` (those of
    /// [`crate::univariate::sturm::isolate_real_roots`]), with the least and the
    /// greatest root as numbers (when there is one):
    /// [`Algebraic::real_roots`] without making numbers of the roots in
    /// between.
    pub(crate) fn extreme_real_roots(sf: &UPoly) -> (Vec<(Q, Q)>, Option<Ends>) {
        debug_assert_eq!(&sf.squarefree(), sf, "square-free and monic");
        let intervals = isolate_squarefree(sf);
        let count = intervals.len();
        if count == 0 {
            return (intervals, None);
        }
        let mut ends = vec![intervals[0].clone()];
        if count > 1 {
            ends.push(intervals[count - 1].clone());
        }
        let (rational, all) = rational_roots(sf, &ends);
        let roots = match all {
            Some(all) => numbers_of(sf, ends, rational, &all),
            None => Algebraic::real_roots(sf),
        };
        let (first, last) = (roots[0].clone(), roots[roots.len() - 1].clone());
        (intervals, Some((first, last)))
    }

    /// The unique root of `p` in `(lo, hi]`, or `None` when `(lo, hi]` does
    /// not hold exactly one distinct root.
    pub fn from_isolating(p: &UPoly, lo: &Q, hi: &Q) -> Option<Algebraic> {
        let sf = p.squarefree();
        if sf.degree().unwrap_or(0) == 0 || count_real_roots(&sf, lo, hi) != 1 {
            return None;
        }
        if sf.eval(hi).is_zero() {
            return Some(Algebraic::from_rational(hi.clone()));
        }
        // The root is inside (lo, hi); when lo itself is another root, find
        // the root among the isolating intervals of p instead.
        if sf.eval(lo).is_zero() {
            return Algebraic::real_roots(&sf).into_iter().find(|a| {
                a.cmp_rational(lo) == Ordering::Greater && a.cmp_rational(hi) == Ordering::Less
            });
        }
        Some(reduce(sf, lo.clone(), hi.clone()))
    }

    /// The rational value, when the number is rational.
    pub fn as_rational(&self) -> Option<&Q> {
        match &self.repr {
            Repr::Rational(q) => Some(q),
            Repr::Root { .. } => None,
        }
    }

    /// Whether the number is rational.
    pub fn is_rational(&self) -> bool {
        self.as_rational().is_some()
    }

    /// The defining polynomial: monic, square-free, without rational roots
    /// when the number is irrational; `x − r` for a rational `r`.
    pub fn defining_poly(&self) -> UPoly {
        match &self.repr {
            Repr::Rational(q) => UPoly::new(vec![-q.clone(), Q::one()]),
            Repr::Root { poly, .. } => poly.clone(),
        }
    }

    /// The ends of the isolating interval, borrowed ([`Algebraic::interval`]).
    pub fn ends(&self) -> (&Q, &Q) {
        match &self.repr {
            Repr::Rational(q) => (q, q),
            Repr::Root { lo, hi, .. } => (lo, hi),
        }
    }

    /// Whether `other` is written alike: the same defining polynomial and
    /// the same interval (a cache's test, with no arithmetic; equal numbers
    /// written differently are not alike).
    pub fn same_form(&self, other: &Algebraic) -> bool {
        match (&self.repr, &other.repr) {
            (Repr::Rational(a), Repr::Rational(b)) => eq(a, b),
            (Repr::Root { poly: p, lo: l, hi: h, .. }, Repr::Root { poly: q, lo, hi, .. }) => {
                eq(l, lo)
                    && eq(h, hi)
                    && p.coeffs().len() == q.coeffs().len()
                    && p.coeffs().iter().zip(q.coeffs()).all(|(a, b)| eq(a, b))
            }
            _ => false,
        }
    }

    /// The isolating interval `(lo, hi)`; `(r, r)` for a rational `r`.
    pub fn interval(&self) -> (Q, Q) {
        match &self.repr {
            Repr::Rational(q) => (q.clone(), q.clone()),
            Repr::Root { lo, hi, .. } => (lo.clone(), hi.clone()),
        }
    }

    /// The same number with an isolating interval no wider than `width`.
    pub fn refine(&self, width: &Q) -> Algebraic {
        match &self.repr {
            Repr::Rational(_) => self.clone(),
            Repr::Root { poly, ip, lo, hi } => {
                let (lo, hi) = refine_int(ip, lo, hi, width);
                debug_assert!(lo != hi, "an irrational root was hit exactly");
                Algebraic { repr: Repr::Root { poly: poly.clone(), ip: ip.clone(), lo, hi } }
            }
        }
    }

    /// [`Algebraic::refine`]'s result, found faster from a guess: `(gl, gh)`
    /// an interval believed to hold the number (from floating point, say).
    /// The guess is checked by exact signs and never changes the result; a
    /// wrong one only costs a few evaluations more.
    pub fn refine_near(&self, width: &Q, gl: &Q, gh: &Q) -> Algebraic {
        match &self.repr {
            Repr::Rational(_) => self.clone(),
            Repr::Root { poly, ip, lo, hi } => {
                let (lo, hi) = refine_int_near(ip, lo, hi, width, gl, gh);
                debug_assert!(lo != hi, "an irrational root was hit exactly");
                Algebraic { repr: Repr::Root { poly: poly.clone(), ip: ip.clone(), lo, hi } }
            }
        }
    }

    /// The same irrational number with its interval narrowed to `(lo, hi)`
    /// (intersected with the one held), when it lies strictly inside
    /// `(lo, hi)`: at most three signs decide, with no bisection, so a
    /// bracket from floating point (the midpoints around the nearest f64)
    /// is checked and kept in one step. `None` when it lies outside, and
    /// for a rational.
    pub fn narrowed(&self, lo: &Q, hi: &Q) -> Option<Algebraic> {
        let Repr::Root { poly, ip, lo: l, hi: h } = &self.repr else { return None };
        let (above, below) = (cmp(lo, l) == Ordering::Greater, cmp(hi, h) == Ordering::Less);
        let (new_lo, new_hi) = (if above { lo } else { l }, if below { hi } else { h });
        if cmp(new_lo, new_hi) != Ordering::Less {
            return None;
        }
        // The one root in (l, h) is above a point x inside exactly when
        // there is no sign change in (l, x] (the polynomial has no rational
        // roots, so no sign inside is zero).
        let s_lo = ip.sign_at(l);
        if (above && ip.sign_at(new_lo) != s_lo) || (below && ip.sign_at(new_hi) == s_lo) {
            return None;
        }
        Some(Algebraic {
            repr: Repr::Root {
                poly: poly.clone(),
                ip: ip.clone(),
                lo: new_lo.clone(),
                hi: new_hi.clone(),
            },
        })
    }

    /// A rational within `width` of the number (the midpoint of a refined
    /// interval); the number itself when it is rational.
    pub fn approx(&self, width: &Q) -> Q {
        let (lo, hi) = self.refine(width).interval();
        (lo + hi) / Q::from_integer(2.into())
    }

    /// The sign of the number.
    pub fn sign(&self) -> Ordering {
        self.cmp_rational(&Q::zero())
    }

    /// Compares the number with a rational, exactly.
    pub fn cmp_rational(&self, r: &Q) -> Ordering {
        match &self.repr {
            Repr::Rational(q) => q.cmp(r),
            Repr::Root { ip, lo, hi, .. } => {
                if cmp(r, lo) != Ordering::Greater {
                    Ordering::Greater
                } else if cmp(r, hi) != Ordering::Less {
                    Ordering::Less
                } else if ip.sign_at(r) == ip.sign_at(lo) {
                    // No sign change in (lo, r], so the root lies above r
                    // (poly(r) is non-zero: poly has no rational roots).
                    Ordering::Greater
                } else {
                    Ordering::Less
                }
            }
        }
    }

    /// The sign of `g` at this number, exactly.
    pub fn sign_of(&self, g: &UPoly) -> Ordering {
        match &self.repr {
            Repr::Rational(q) => sign(&g.eval(q)),
            Repr::Root { poly, ip, lo, hi } => sign_at_root(poly, ip, lo, hi, g, None),
        }
    }

    /// [`Algebraic::sign_of`] with the integer form of `g` given (for a
    /// polynomial whose sign is asked at many numbers).
    pub(crate) fn sign_of_with(&self, g: &UPoly, gi: &IntPoly) -> Ordering {
        match &self.repr {
            Repr::Rational(q) => gi.sign_at(q),
            Repr::Root { poly, ip, lo, hi } => sign_at_root(poly, ip, lo, hi, g, Some(gi)),
        }
    }

    /// Whether `g` vanishes at this number.
    pub fn is_root_of(&self, g: &UPoly) -> bool {
        match &self.repr {
            Repr::Rational(q) => g.eval(q).is_zero(),
            Repr::Root { poly, ip, lo, hi } => {
                if g.is_zero() {
                    return true;
                }
                if g.degree() == Some(0) {
                    return false;
                }
                // No sign to find: a sign on the whole interval, or g coprime
                // to the defining polynomial modulo a prime, rules the root
                // out without refining; else the gcd decides.
                let gi = IntPoly::new(g);
                gi.sign_on(lo, hi).is_none()
                    && !crate::arith::zp::coprime_mod_p(ip.coeffs(), gi.coeffs())
                    && (divides(ip, &gi) || vanishes_at_root(poly, lo, hi, g))
            }
        }
    }

    /// The decimal expansion rounded to `digits` places after the point
    /// (half away from zero), exact: the interval is refined until both ends
    /// round alike, which ends because an irrational number never sits on a
    /// rounding boundary.
    pub fn to_decimal(&self, digits: usize) -> String {
        match &self.repr {
            Repr::Rational(q) => round_decimal(q, digits),
            Repr::Root { ip, lo, hi, .. } => {
                // Any interval around the number will do (the rounding is a
                // property of the number, and monotone): the one held
                // decides when its ends round alike, as they do once it has
                // been refined for a finer rendering. Else refine
                // quadratically.
                let (a, b) = (rounded_units(lo, digits), rounded_units(hi, digits));
                if a == b {
                    return units_text(&a, digits);
                }
                if &b - &a == BigInt::one() {
                    // One cell boundary inside the interval (as after a
                    // refinement to 10^−digits): the sign there decides.
                    let two_scale = num_traits::pow(BigInt::from(10), digits) * 2;
                    // Unreduced: a comparison needs no lowest terms.
                    let boundary = Q::new_raw(&a * 2 + 1, two_scale);
                    let n = if self.cmp_rational(&boundary) == Ordering::Less { a } else { b };
                    return units_text(&n, digits);
                }
                let ten = Q::from_integer(10.into());
                let mut width = Q::one() / num_traits::pow(ten.clone(), digits + 2);
                loop {
                    let (lo, hi) = refine_quadratic(ip, lo, hi, &width);
                    let (a, b) = (round_decimal(&lo, digits), round_decimal(&hi, digits));
                    if a == b {
                        return a;
                    }
                    width /= &ten;
                }
            }
        }
    }

    /// A closed form in plain CAS text when one is known: rationals
    /// ("2", "-1/3"), roots of quadratics ("sqrt(2)", "2*sqrt(5) - 2") and of
    /// biquadratics x⁴ + b x² + c ("sqrt(2*sqrt(5) - 2)").
    pub fn closed_form(&self) -> Option<String> {
        let (poly, ip, lo, hi) = match &self.repr {
            Repr::Rational(q) => return Some(q.to_string()),
            Repr::Root { poly, ip, lo, hi } => (poly, ip, lo, hi),
        };
        let c = poly.coeffs();
        match poly.degree() {
            Some(2) => {
                // x² + b x + c: roots −b/2 ± √(b²/4 − c); the number is the
                // larger root exactly when it lies above −b/2.
                let centre = shr(&-c[1].clone(), 1);
                let plus = self.cmp_rational(&centre) == Ordering::Greater;
                Some(quadratic_form(&centre, &add(&mul(&centre, &centre), &-c[0].clone()), plus))
            }
            Some(4) if c[1].is_zero() && c[3].is_zero() => {
                // x⁴ + b x² + c: x² = −b/2 ± √(b²/4 − c).
                let centre = shr(&-c[2].clone(), 1);
                let radicand = add(&mul(&centre, &centre), &-c[0].clone());
                let shifted = UPoly::new(vec![-centre.clone(), Q::zero(), Q::one()]);
                let plus = sign_at_root(poly, ip, lo, hi, &shifted, None) == Ordering::Greater;
                let inner = quadratic_form(&centre, &radicand, plus);
                let negative = self.sign() == Ordering::Less;
                Some(format!("{}sqrt({inner})", if negative { "-" } else { "" }))
            }
            _ => None,
        }
    }

    /// The square of this number, exact. Its defining polynomial comes from
    /// f(x) = E(x²) + x·O(x²): every square of a root of f is a root of
    /// E(y)² − y·O(y)².
    pub fn square(&self) -> Algebraic {
        let (poly, ip, mut lo, mut hi) = match &self.repr {
            Repr::Rational(q) => return Algebraic::from_rational(q * q),
            Repr::Root { poly, ip, lo, hi } => (poly.clone(), ip.clone(), lo.clone(), hi.clone()),
        };
        let even = UPoly::new(poly.coeffs().iter().step_by(2).cloned().collect());
        let odd = UPoly::new(poly.coeffs().iter().skip(1).step_by(2).cloned().collect());
        let sq = (&(&even * &even) - &(&UPoly::x() * &(&odd * &odd))).squarefree();
        let four = Q::from_integer(4.into());
        loop {
            // Once the interval lies on one side of 0 (refinement gets there:
            // the number is not 0), squaring maps it onto an interval.
            if !lo.is_negative() || !hi.is_positive() {
                let (a, b) =
                    if !lo.is_negative() { (&lo * &lo, &hi * &hi) } else { (&hi * &hi, &lo * &lo) };
                if count_real_roots(&sq, &a, &b) == 1 && !sq.eval(&b).is_zero() {
                    if let Some(r) = Algebraic::from_isolating(&sq, &a, &b) {
                        return r;
                    }
                }
            }
            let width = (&hi - &lo) / &four;
            (lo, hi) = refine_int(&ip, &lo, &hi, &width);
        }
    }

    /// The multiplicity of this number as a root of `g` (0 when it is not a
    /// root); `g` must be non-zero.
    pub fn multiplicity_in(&self, g: &UPoly) -> usize {
        let mut k = 0;
        let mut h = g.clone();
        while !h.is_zero() && self.is_root_of(&h) {
            k += 1;
            h = h.derivative();
        }
        k
    }

    /// The negated number −a, exact.
    pub fn neg(&self) -> Algebraic {
        match &self.repr {
            Repr::Rational(q) => Algebraic::from_rational(-q.clone()),
            Repr::Root { poly, lo, hi, .. } => {
                root(poly.negate_x().monic(), -hi.clone(), -lo.clone())
            }
        }
    }

    /// The absolute value |a|.
    pub fn abs(&self) -> Algebraic {
        if self.sign() == Ordering::Less {
            self.neg()
        } else {
            self.clone()
        }
    }

    /// The simplest rational strictly between `lo < hi` (smallest
    /// denominator, then numerator), found by refining both numbers until
    /// their intervals separate.
    ///
    /// Round m quarters both intervals (two bisection steps each), so its
    /// state is the start refined to width w₀/4^m in one go; the first
    /// separating round is found by doubling m and then bisecting on m
    /// (separation only improves with m), with the same result as walking
    /// m = 0, 1, 2, … .
    pub fn rational_between(lo: &Algebraic, hi: &Algebraic) -> Q {
        // m = 0: the intervals as they stand (refining to its own width
        // leaves an interval as it is).
        let ((_, ahi), (blo, _)) = (lo.ends(), hi.ends());
        if cmp(ahi, blo) == Ordering::Less {
            return simplest_between(ahi, blo);
        }
        let (wa, wb) = (lo.width(), hi.width());
        let at = |m: u64| -> (Q, Q) {
            let (_, ahi) = lo.refine(&shr(&wa, 2 * m)).interval();
            let (blo, _) = hi.refine(&shr(&wb, 2 * m)).interval();
            (ahi, blo)
        };
        let separated = |(ahi, blo): &(Q, Q)| cmp(ahi, blo) == Ordering::Less;
        // separated at `bad` is false, at `good` true; `found` is at(good).
        let (mut bad, mut good) = (0u64, 1u64);
        let mut found = at(good);
        while !separated(&found) {
            bad = good;
            good *= 2;
            found = at(good);
        }
        while good - bad > 1 {
            let mid = bad + (good - bad) / 2;
            let ends = at(mid);
            if separated(&ends) {
                (good, found) = (mid, ends);
            } else {
                bad = mid;
            }
        }
        simplest_between(&found.0, &found.1)
    }

    /// The width of the isolating interval (zero for a rational).
    fn width(&self) -> Q {
        let (lo, hi) = self.ends();
        crate::arith::rational::add(hi, &-lo)
    }

    /// Like `Display`, but writes a defining polynomial in the variable `var`.
    pub fn describe(&self, var: &str) -> String {
        if let Some(s) = self.closed_form() {
            return s;
        }
        let (lo, hi) = self.interval();
        format!("root of {} in [{lo}, {hi}]", self.defining_poly().to_string_in(var))
    }
}

/// The larger of two rationals, by [`cmp`].
fn larger<'a>(a: &'a Q, b: &'a Q) -> &'a Q {
    if cmp(a, b) == Ordering::Less {
        b
    } else {
        a
    }
}

/// The smaller of two rationals, by [`cmp`].
fn smaller<'a>(a: &'a Q, b: &'a Q) -> &'a Q {
    if cmp(a, b) == Ordering::Greater {
        b
    } else {
        a
    }
}

/// The rational with the smallest denominator (then numerator) strictly
/// inside (l, r), l < r, by continued fractions.
pub(crate) fn simplest_between(l: &Q, r: &Q) -> Q {
    let (n, d) = simplest_between_int(l.numer(), l.denom(), r.numer(), r.denom());
    Q::new(n, d)
}

/// [`simplest_between`] on numerators and positive denominators, in
/// integers (no fraction is normalised on the way, which cost a gcd per
/// operation): the continued-fraction recursion
/// s(l, r) = ⌊l⌋ + 1 if that is below r, ⌊l⌋ + 1/(⌊1/(r − ⌊l⌋)⌋ + 1) if l
/// is an integer, else ⌊l⌋ + 1/s(1/(r − ⌊l⌋), 1/(l − ⌊l⌋)).
fn simplest_between_int(ln: &BigInt, ld: &BigInt, rn: &BigInt, rd: &BigInt) -> (BigInt, BigInt) {
    let fl = ln.div_floor(ld);
    let next = &fl + BigInt::one();
    if &next * rd < *rn {
        return (next, BigInt::one());
    }
    let frac_l = ln - &fl * ld; // over ld, in [0, ld)
    let frac_r = rn - &fl * rd; // over rd, in (0, rd]
    if frac_l.is_zero() {
        let k = rd.div_floor(&frac_r) + BigInt::one();
        return (&fl * &k + BigInt::one(), k);
    }
    let (sn, sd) = simplest_between_int(rd, &frac_r, ld, &frac_l);
    (&fl * &sn + sd, sn)
}

/// The sign of `g` at the unique root of `poly` in (lo, hi) (`ip` the
/// integer form of `poly`; `poly` square-free, non-zero at lo and hi).
fn sign_at_root(
    poly: &UPoly,
    ip: &IntPoly,
    lo: &Q,
    hi: &Q,
    g: &UPoly,
    gi: Option<&IntPoly>,
) -> Ordering {
    if g.is_zero() {
        return Ordering::Equal;
    }
    if g.degree() == Some(0) {
        return sign(&g.coeff(0));
    }
    let owned;
    let gi = match gi {
        Some(gi) => gi,
        None => {
            owned = IntPoly::new(g);
            &owned
        }
    };
    // A sign on the whole interval (the usual case once it is narrow):
    // then g does not vanish at the number either.
    if let Some(s) = gi.sign_on(lo, hi) {
        return s;
    }
    // Coprime modulo a prime: g cannot vanish at a root of poly, and the
    // gcd over Q is not needed.
    if !crate::arith::zp::coprime_mod_p(ip.coeffs(), gi.coeffs())
        && (divides(ip, gi) || vanishes_at_root(poly, lo, hi, g))
    {
        return Ordering::Equal;
    }
    // g does not vanish at the number: narrow the interval until interval
    // evaluation of g over [lo, hi] excludes zero; that sign is the answer.
    // (The enclosure shrinks with the interval, so this ends.)
    let (mut lo, mut hi) = (lo.clone(), hi.clone());
    // Widths w/4, w/16, w/256, …: the bits asked for double each round.
    let mut shift = 2u32;
    loop {
        if let Some(s) = gi.sign_on(&lo, &hi) {
            return s;
        }
        if eq(&lo, &hi) {
            return gi.sign_at(&lo);
        }
        let width = (&hi - &lo) / Q::from_integer(BigInt::one() << shift);
        (lo, hi) = refine_quadratic(ip, &lo, &hi, &width);
        shift = shift.saturating_mul(2).min(1 << 16);
    }
}

/// Whether the defining polynomial divides `g` (the usual case when g is
/// the condition the number is a root of): a pseudo-remainder in integers,
/// cheaper than the gcd.
fn divides(ip: &IntPoly, gi: &IntPoly) -> bool {
    gi.coeffs().len() >= ip.coeffs().len()
        && crate::univariate::upoly::prem(gi.coeffs(), ip.coeffs()).0.is_empty()
}

/// Whether `g` vanishes at the unique root of the square-free `poly` in
/// (lo, hi), where poly(lo), poly(hi) ≠ 0: h = gcd(poly, g) divides poly,
/// so its roots are simple and at most one lies in (lo, hi), and h is
/// non-zero at lo and hi; it has that root exactly when it changes sign.
fn vanishes_at_root(poly: &UPoly, lo: &Q, hi: &Q, g: &UPoly) -> bool {
    let h = poly.gcd(g);
    match h.degree() {
        None | Some(0) => false,
        Some(d) if Some(d) == poly.degree() => true,
        Some(_) => {
            let hi_poly = IntPoly::new(&h);
            hi_poly.sign_at(lo) != hi_poly.sign_at(hi)
        }
    }
}

/// The numbers isolated by `intervals` (some of the isolation of the
/// square-free `sf`), given the rational root in each (`rational`) and
/// every rational root of `sf` (`all`): the irrational ones reduced with
/// `sf` freed of all its rational roots.
fn numbers_of(
    sf: &UPoly,
    intervals: Vec<(Q, Q)>,
    rational: Vec<Option<Q>>,
    all: &[Q],
) -> Vec<Algebraic> {
    let irrational = without_roots(sf, all);
    let even_factors = even_rational_factors(&irrational);
    numbers_with(sf, intervals, rational, all, &even_factors)
}

/// `sf` freed of its rational roots `all`, in integers (exact synthetic
/// division), made monic.
fn without_roots(sf: &UPoly, all: &[Q]) -> UPoly {
    let mut c = crate::univariate::upoly::int_primitive(sf);
    for r in all {
        c = crate::univariate::upoly::divide_linear(&c, r);
    }
    UPoly::new(c.into_iter().map(Q::from_integer).collect()).monic()
}

/// [`numbers_of`] given the factors x² − y of sf's irrational part when it
/// is even (see [`even_rational_factors`]).
fn numbers_with(
    sf: &UPoly,
    intervals: Vec<(Q, Q)>,
    rational: Vec<Option<Q>>,
    all: &[Q],
    even_factors: &[UPoly],
) -> Vec<Algebraic> {
    // The irrational part is made monic once; its integer form is shared by
    // every root that keeps it as defining polynomial.
    let irrational = without_roots(sf, all);
    // What `reduce_irrational_with` finds for each root, found once: the
    // factors x² − y that divide the irrational part (irreducible: a
    // rational square y would give rational roots, divided out above) and
    // the part freed of them. A root is a factor's when that factor changes
    // sign across its interval (the first such, in order), and the rest's
    // otherwise. The divisions cost as much as the rest together on
    // polynomials of thousand-bit coefficients (SDIRK34's A(α)).
    let mut rest = irrational.clone();
    let mut dividing: Vec<(&UPoly, IntPoly)> = Vec::new();
    for factor in even_factors {
        let (quotient, rem) = rest.div_rem(factor);
        if rem.is_zero() {
            rest = quotient;
            dividing.push((factor, IntPoly::new(factor)));
        }
    }
    let kept = dividing.is_empty();
    let rest = if kept { rest } else { rest.monic() };
    let mut shared: Option<Arc<IntPoly>> = None;
    intervals
        .into_iter()
        .zip(rational)
        .map(|((lo, hi), r)| match r {
            Some(r) => Algebraic::from_rational(r),
            None => {
                if let Some((factor, _)) =
                    dividing.iter().find(|(_, ip)| ip.sign_at(&lo) != ip.sign_at(&hi))
                {
                    return root(factor.monic(), lo, hi);
                }
                let ip = shared.get_or_insert_with(|| Arc::new(IntPoly::new(&rest)));
                debug_assert!(rest.leading().is_one());
                Algebraic { repr: Repr::Root { poly: rest.clone(), ip: Arc::clone(ip), lo, hi } }
            }
        })
        .collect()
}

/// Canonical form of the root of the square-free `f` in the isolating
/// interval (lo, hi) (or the rational `lo` when `lo == hi`).
fn reduce(f: UPoly, lo: Q, hi: Q) -> Algebraic {
    if eq(&lo, &hi) {
        return Algebraic::from_rational(lo);
    }
    if f.degree() == Some(1) {
        return Algebraic::from_rational(-f.coeff(0) / f.coeff(1));
    }
    let (ours, all) = rational_roots(&f, &[(lo.clone(), hi.clone())]);
    if let Some(r) = ours[0].clone() {
        return Algebraic::from_rational(r);
    }
    // Drop the other rational roots: they are not ours and would only hide
    // a closed form.
    let all = all.unwrap_or_else(|| {
        let intervals = isolate_squarefree(&f);
        rational_roots(&f, &intervals).0.into_iter().flatten().collect()
    });
    let mut f = f;
    for r in all {
        f = f.div_rem(&UPoly::new(vec![-r, Q::one()])).0;
    }
    reduce_irrational(f, lo, hi)
}

/// [`reduce`] for an irrational root of a square-free `f` without rational
/// roots.
fn reduce_irrational(f: UPoly, lo: Q, hi: Q) -> Algebraic {
    let factors = even_rational_factors(&f);
    reduce_irrational_with(f, None, &factors, lo, hi)
}

/// For a square-free f(x) = x^k·F(x²), k ≤ 1, F(0) ≠ 0 (conditions in Φ
/// are mostly of this form), from one p-adic run on F (half f's degree):
/// every rational root of f (0 when k = 1, and ±√y for the rational squares
/// y among F's rational roots), increasing, and the factors x² − y for F's
/// other rational roots (those [`even_rational_factors`] gives for f freed
/// of its rational roots). `None` when f is not of that form or no prime
/// suits the lifting.
fn even_rational_roots(f: &UPoly) -> Option<(Vec<Q>, Vec<UPoly>)> {
    let k = f.coeffs().iter().position(|c| !c.is_zero())?;
    if k > 1 {
        return None;
    }
    let big_f = UPoly::new(f.coeffs()[k..].to_vec()).even_part()?;
    let ys = crate::univariate::rational_roots::rational_roots(
        &crate::univariate::upoly::int_primitive(&big_f),
    )?;
    let mut roots = if k == 1 { vec![Q::zero()] } else { Vec::new() };
    let mut factors = Vec::new();
    for y in ys {
        match rational_sqrt(&y) {
            Some(r) => roots.extend([-r.clone(), r]),
            None => factors.push(UPoly::new(vec![-y, Q::zero(), Q::one()])),
        }
    }
    roots.sort();
    Some((roots, factors))
}

/// √y when y is the square of a rational.
fn rational_sqrt(y: &Q) -> Option<Q> {
    if y.is_negative() {
        return None;
    }
    let (n, d) = (y.numer().sqrt(), y.denom().sqrt());
    (&n * &n == *y.numer() && &d * &d == *y.denom()).then(|| Q::new(n, d))
}

/// For an even f(x) = F(x²): the factors x² − y for the rational roots y of
/// F; empty otherwise.
fn even_rational_factors(f: &UPoly) -> Vec<UPoly> {
    if f.degree().unwrap_or(0) < 2
        || !f.coeffs().iter().enumerate().all(|(k, c)| k % 2 == 0 || c.is_zero())
    {
        return Vec::new();
    }
    let big_f = UPoly::new(f.coeffs().iter().step_by(2).cloned().collect()).squarefree();
    // The rational roots y of F, increasing: 0 if F(0) = 0, the others
    // lifted p-adically from F/y^k (no isolation of F needed).
    let lowest = big_f.coeffs().iter().position(|c| !c.is_zero()).unwrap_or(0);
    let zero_free = UPoly::new(big_f.coeffs()[lowest..].to_vec());
    let mut ys = if zero_free.degree().unwrap_or(0) == 0 {
        Vec::new()
    } else if let Some(ys) = crate::univariate::rational_roots::rational_roots(
        &crate::univariate::upoly::int_primitive(&zero_free),
    ) {
        ys
    } else {
        let intervals = isolate_squarefree(&big_f);
        rational_roots(&big_f, &intervals)
            .0
            .into_iter()
            .flatten()
            .filter(|y| !y.is_zero())
            .collect()
    };
    if lowest > 0 {
        ys.push(Q::zero());
        ys.sort();
    }
    ys.into_iter().map(|y| UPoly::new(vec![-y, Q::zero(), Q::one()])).collect()
}

/// [`reduce`] for an irrational root of a square-free `f` without rational
/// roots, given the factors x² − y of an even f: either one is ours (a
/// square root of a rational) or it goes.
///
/// `ip`, when given, is the integer form of a monic `f`, used if `f` stays
/// the defining polynomial.
fn reduce_irrational_with(
    mut f: UPoly,
    ip: Option<&Arc<IntPoly>>,
    factors: &[UPoly],
    lo: Q,
    hi: Q,
) -> Algebraic {
    let mut kept = true;
    for factor in factors {
        if vanishes_at_root(&f, &lo, &hi, factor) {
            f = factor.clone();
            kept = false;
            break;
        }
        let (quotient, rem) = f.div_rem(factor);
        if rem.is_zero() {
            f = quotient;
            kept = false;
        }
    }
    match ip {
        Some(ip) if kept => {
            debug_assert!(f.leading().is_one());
            Algebraic { repr: Repr::Root { poly: f, ip: Arc::clone(ip), lo, hi } }
        }
        _ => root(f.monic(), lo, hi),
    }
}

/// The rational root in each isolating interval of the square-free `f`, if
/// any (the intervals may be a subset of f's). Roots met exactly by
/// bisection come first; then every rational root, by p-adic lifting
/// ([`crate::univariate::rational_roots::rational_roots`]). Only when no prime suits
/// the lifting: when a prime bound
/// ([`crate::arith::zp::rational_root_bound`]) allows more roots,
/// the simplest rational of a narrowed interval is tried in each, and if
/// that finds fewer than the bound the slow, complete search runs.
fn rational_roots(f: &UPoly, intervals: &[(Q, Q)]) -> (Vec<Option<Q>>, Option<Vec<Q>>) {
    let mut out: Vec<Option<Q>> =
        intervals.iter().map(|(lo, hi)| (lo == hi).then(|| lo.clone())).collect();
    // A root at zero is usually met by bisection (0 is a dyadic point), but
    // not when it is alone in the first interval (−B, B): mark it here.
    if f.coeffs().first().is_some_and(Zero::is_zero) {
        let zero = Q::zero();
        if let Some(k) = intervals.iter().position(|(lo, hi)| *lo <= zero && zero <= *hi) {
            out[k] = Some(zero);
        }
    }
    let zero_free = {
        let lowest = f.coeffs().iter().position(|c| !c.is_zero()).unwrap_or(0);
        UPoly::new(f.coeffs()[lowest..].to_vec())
    };
    let zero: Vec<Q> =
        if f.coeffs().first().is_some_and(Zero::is_zero) { vec![Q::zero()] } else { Vec::new() };
    if zero_free.degree().unwrap_or(0) == 0 {
        return (out, Some(zero));
    }
    // Every rational root, by p-adic lifting, placed in its interval.
    if let Some(roots) = crate::univariate::rational_roots::rational_roots(
        &crate::univariate::upoly::int_primitive(&zero_free),
    ) {
        for r in &roots {
            // (The intervals may be a subset of the isolation: `reduce`
            // asks about one.)
            let k =
                intervals.iter().position(|(lo, hi)| (lo == hi && lo == r) || (lo < r && r < hi));
            if let Some(k) = k {
                out[k] = Some(r.clone());
            }
        }
        let mut all = roots;
        all.extend(zero);
        all.sort();
        return (out, Some(all));
    }
    let found_nonzero = out.iter().flatten().filter(|r| !r.is_zero()).count();
    let bound =
        crate::arith::zp::rational_root_bound(&crate::univariate::upoly::int_primitive(&zero_free));
    if bound == Some(found_nonzero) {
        return (out, None);
    }
    let width = Q::new(BigInt::one(), BigInt::one() << 48);
    let mut found = found_nonzero;
    let ip = IntPoly::new(f);
    for (k, (lo, hi)) in intervals.iter().enumerate() {
        if out[k].is_some() {
            continue;
        }
        let (a, b) = refine_quadratic(&ip, lo, hi, &width);
        let c = if a == b { a } else { simplest_between(&a, &b) };
        if ip.sign_at(&c).is_eq() {
            out[k] = Some(c);
            found += 1;
        }
    }
    if bound == Some(found) {
        return (out, None);
    }
    for (k, (lo, hi)) in intervals.iter().enumerate() {
        if out[k].is_none() {
            out[k] = rational_root_in(f, &ip, lo, hi);
        }
    }
    (out, None)
}

/// The rational root of the square-free `f` in (lo, hi), if the root
/// isolated there is rational. By the rational root theorem a root of the
/// primitive integer form with leading coefficient a_n is j / a_n for an
/// integer j, so once the interval is narrower than 1/|a_n| one candidate
/// remains.
fn rational_root_in(f: &UPoly, ip: &IntPoly, lo: &Q, hi: &Q) -> Option<Q> {
    let lead = integer_leading(f);
    let width = Q::new(BigInt::one(), lead.clone()) / Q::from_integer(2.into());
    let (lo, hi) = refine_quadratic(ip, lo, hi, &width);
    if eq(&lo, &hi) {
        return Some(lo);
    }
    let lead_q = Q::from_integer(lead.clone());
    // The smallest j with j / a_n > lo; at most one such candidate fits.
    let j = (&lo * &lead_q).floor().to_integer() + BigInt::one();
    let candidate = Q::new(j, lead);
    (candidate < hi && ip.sign_at(&candidate).is_eq()).then_some(candidate)
}

/// |a_n| of the primitive integer polynomial proportional to `f`.
fn integer_leading(f: &UPoly) -> BigInt {
    let mut den = BigInt::one();
    for c in f.coeffs() {
        den = crate::arith::intgcd::lcm(&den, c.denom());
    }
    let ints: Vec<BigInt> =
        f.coeffs().iter().map(|c| (c * Q::from_integer(den.clone())).to_integer()).collect();
    let mut g = BigInt::zero();
    for i in &ints {
        g = crate::arith::intgcd::gcd(&g, i);
    }
    (ints.last().cloned().unwrap_or_else(BigInt::one) / g).abs()
}

/// `centre ± √radicand` in plain text, simplifying the square root.
fn quadratic_form(centre: &Q, radicand: &Q, plus: bool) -> String {
    let (mut u, d) = sqrt_parts(radicand);
    if !plus {
        u = -u;
    }
    if d.is_one() {
        return (centre + u).to_string();
    }
    let term = |u: &Q| -> String {
        let (a, b) = (u.numer().abs(), u.denom().clone());
        match (a.is_one(), b.is_one()) {
            (true, true) => format!("sqrt({d})"),
            (false, true) => format!("{a}*sqrt({d})"),
            (true, false) => format!("sqrt({d})/{b}"),
            (false, false) => format!("{a}*sqrt({d})/{b}"),
        }
    };
    if centre.is_zero() {
        format!("{}{}", if u.is_negative() { "-" } else { "" }, term(&u))
    } else if u.is_positive() {
        let op = if centre.is_positive() { "+" } else { "-" };
        format!("{} {op} {}", term(&u), centre.abs())
    } else {
        format!("{centre} - {}", term(&u))
    }
}

/// √q = u √d with u rational and d a square-free positive integer (as far as
/// trial division up to 10⁵ can tell); requires q ≥ 0.
fn sqrt_parts(q: &Q) -> (Q, BigInt) {
    let n = q.numer() * q.denom();
    // Large radicands (a float-derived method's 60-digit coefficients) are
    // searched for square factors up to 10³ only: the form stays exact, if
    // less reduced, and printing it no longer costs milliseconds.
    let bound: u64 = if n.bits() > 256 { 1_000 } else { 100_000 };
    let (out, rest) = square_part(&n, bound);
    (crate::arith::rational::ratio(out, q.denom().clone()), rest)
}

/// |n| = out²·rest, with the square of every prime below `bound` divided
/// out of `rest`, and `rest` = 1 when what remains is itself a square.
/// Primes only: a composite's square never divides once its primes'
/// squares are out (the tests' trial division by every integer is the
/// oracle), and each test is a remainder by a word.
pub(crate) fn square_part(n: &BigInt, bound: u64) -> (BigInt, BigInt) {
    if let Some(small) = num_traits::ToPrimitive::to_u64(n.magnitude()) {
        let (out, rest) = square_part_u64(small, bound);
        return (out.into(), rest.into());
    }
    let mut rest = n.magnitude().clone();
    let mut out = BigInt::one();
    for &p in small_primes().iter().take_while(|&&p| p < bound) {
        let pp = p * p;
        if num_traits::ToPrimitive::to_u64(&rest).is_some_and(|r| r < pp) {
            break;
        }
        while (&rest % pp).is_zero() {
            rest /= pp;
            out *= p;
        }
    }
    let mut rest = BigInt::from(rest);
    // A large remaining square (beyond trial division) still simplifies.
    let s = rest.sqrt();
    if &s * &s == rest {
        out *= s;
        rest = BigInt::one();
    }
    (out, rest)
}

/// [`square_part`] of a radicand that fits a word, in words (most do: the
/// radicands of quadratic closed forms), with no big integer made.
fn square_part_u64(n: u64, bound: u64) -> (u64, u64) {
    let (mut rest, mut out) = (n, 1u64);
    for &p in small_primes().iter().take_while(|&&p| p < bound) {
        let pp = p * p;
        if rest < pp {
            break;
        }
        while rest % pp == 0 {
            rest /= pp;
            out *= p;
        }
    }
    let s = rest.isqrt();
    if s * s == rest {
        // out·s ≤ √n: no overflow.
        return (out * s, 1);
    }
    (out, rest)
}

/// The primes below 10⁵ (a sieve, once).
fn small_primes() -> &'static [u64] {
    static PRIMES: std::sync::OnceLock<Vec<u64>> = std::sync::OnceLock::new();
    PRIMES.get_or_init(|| {
        const N: usize = 100_000;
        let mut composite = vec![false; N];
        let mut primes = Vec::new();
        for p in 2..N {
            if !composite[p] {
                primes.push(p as u64);
                for m in (p * p..N).step_by(p) {
                    composite[m] = true;
                }
            }
        }
        primes
    })
}

/// `q` rounded to `digits` decimals, half away from zero.
fn round_decimal(q: &Q, digits: usize) -> String {
    units_text(&rounded_units(q, digits), digits)
}

/// q rounded to `digits` decimals (halves away from zero), in units of
/// 10^−digits: ±⌊|q|·10^digits + 1/2⌋ = ±⌊(2|n|·10^digits + d) / 2d⌋ for
/// q = n/d, d > 0, in integers (no fraction reduced). Monotone in q.
fn rounded_units(q: &Q, digits: usize) -> BigInt {
    let scale = num_traits::pow(BigInt::from(10), digits);
    let two_d = q.denom() * 2;
    let n: BigInt = (q.numer().abs() * &scale * 2 + q.denom()) / two_d;
    if q.is_negative() {
        -n
    } else {
        n
    }
}

/// A number of units of 10^−digits written as a decimal.
fn units_text(n: &BigInt, digits: usize) -> String {
    let scale = num_traits::pow(BigInt::from(10), digits);
    let (int, frac) = n.abs().div_rem(&scale);
    let mut s = String::new();
    if n.is_negative() {
        s.push('-');
    }
    s.push_str(&int.to_string());
    if digits > 0 {
        s.push('.');
        s.push_str(&format!("{:0>width$}", frac.to_string(), width = digits));
    }
    s
}

impl PartialEq for Algebraic {
    /// [`Ord::cmp`]'s test for `Equal` without its refinement: an irrational
    /// number's defining polynomial has no rational root, so it never equals
    /// a rational; two irrational ones are equal exactly when the gcd of
    /// their defining polynomials changes sign across the overlap of their
    /// intervals. Distinct numbers are never refined apart here (merging the
    /// roots of many conditions compares each with every other).
    fn eq(&self, other: &Algebraic) -> bool {
        match (&self.repr, &other.repr) {
            (Repr::Rational(a), Repr::Rational(b)) => eq(a, b),
            (Repr::Rational(_), _) | (_, Repr::Rational(_)) => false,
            (
                Repr::Root { poly: p1, lo: lo1, hi: hi1, .. },
                Repr::Root { poly: p2, lo: lo2, hi: hi2, .. },
            ) => {
                if cmp(hi1, lo2) != Ordering::Greater || cmp(hi2, lo1) != Ordering::Greater {
                    return false;
                }
                let g = p1.gcd(p2);
                let (lo, hi) = (larger(lo1, lo2), smaller(hi1, hi2));
                if g.degree().unwrap_or(0) == 0 || cmp(lo, hi) != Ordering::Less {
                    return false;
                }
                let gi = IntPoly::new(&g);
                gi.sign_at(lo) != gi.sign_at(hi)
            }
        }
    }
}

impl Eq for Algebraic {}

impl PartialOrd for Algebraic {
    fn partial_cmp(&self, other: &Algebraic) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Algebraic {
    /// Exact: equal roots are recognised through the gcd of the defining
    /// polynomials; distinct ones by refining until the intervals separate.
    fn cmp(&self, other: &Algebraic) -> Ordering {
        match (&self.repr, &other.repr) {
            (Repr::Rational(a), Repr::Rational(b)) => cmp(a, b),
            (_, Repr::Rational(b)) => self.cmp_rational(b),
            (Repr::Rational(a), _) => other.cmp_rational(a).reverse(),
            (
                Repr::Root { poly: p1, lo: lo1, hi: hi1, .. },
                Repr::Root { poly: p2, lo: lo2, hi: hi2, .. },
            ) => {
                if cmp(hi1, lo2) != Ordering::Greater {
                    return Ordering::Less;
                }
                if cmp(hi2, lo1) != Ordering::Greater {
                    return Ordering::Greater;
                }
                let g = p1.gcd(p2);
                let lo = larger(lo1, lo2);
                let hi = smaller(hi1, hi2);
                // g divides both square-free polynomials, so it has at most
                // one root in (lo, hi), a simple one, and none at lo or hi
                // (each is an end of an isolating interval of p1 or p2): it
                // has one exactly when it changes sign.
                if g.degree().unwrap_or(0) > 0 && cmp(lo, hi) == Ordering::Less {
                    let gi = IntPoly::new(&g);
                    if gi.sign_at(lo) != gi.sign_at(hi) {
                        return Ordering::Equal;
                    }
                }
                // Distinct: refine both quadratically (on copies, so any
                // intervals will do), asking for twice the bits each round.
                let (ip1, ip2) = match (&self.repr, &other.repr) {
                    (Repr::Root { ip: a, .. }, Repr::Root { ip: b, .. }) => (a, b),
                    _ => unreachable!("both irrational here"),
                };
                let ((mut alo, mut ahi), (mut blo, mut bhi)) = (self.interval(), other.interval());
                let mut shift = 2u32;
                loop {
                    if cmp(&ahi, &blo) != Ordering::Greater {
                        return Ordering::Less;
                    }
                    if cmp(&bhi, &alo) != Ordering::Greater {
                        return Ordering::Greater;
                    }
                    let scale = Q::from_integer(BigInt::one() << shift);
                    (alo, ahi) = refine_quadratic(ip1, &alo, &ahi, &((&ahi - &alo) / &scale));
                    (blo, bhi) = refine_quadratic(ip2, &blo, &bhi, &((&bhi - &blo) / &scale));
                    shift = shift.saturating_mul(2).min(1 << 16);
                }
            }
        }
    }
}

impl fmt::Display for Algebraic {
    /// The closed form when known, else `root of <poly> in [lo, hi]` with
    /// the polynomial written in `Phi`, as the command line prints it: the
    /// numbers the front door returns are values of Φ. [`Algebraic::describe`]
    /// names another variable.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.describe("Phi"))
    }
}

impl fmt::Debug for Algebraic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (lo, hi) = self.interval();
        write!(f, "Algebraic({self} ≈ [{lo}, {hi}])")
    }
}

impl From<Q> for Algebraic {
    fn from(q: Q) -> Algebraic {
        Algebraic::from_rational(q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The integer rounding against the obvious one on fractions, on
    /// halves (ties away from zero), negatives and long denominators.
    #[test]
    fn round_decimal_matches_fraction_arithmetic() {
        let slow = |q: &Q, digits: usize| -> String {
            let scale = num_traits::pow(BigInt::from(10), digits);
            let scaled = q.abs() * Q::from_integer(scale.clone());
            let n = (scaled + Q::new(BigInt::one(), BigInt::from(2))).floor().to_integer();
            let (int, frac) = n.div_rem(&scale);
            let sign = if q.is_negative() && !n.is_zero() { "-" } else { "" };
            if digits == 0 {
                return format!("{sign}{int}");
            }
            format!("{sign}{int}.{:0>width$}", frac.to_string(), width = digits)
        };
        for num in -60i64..=60 {
            for den in [1i64, 2, 3, 7, 8, 20, 40, 125, 999, 1024, 3 * 10i64.pow(12) + 7] {
                let q = Q::new(BigInt::from(num * 37 + 5), BigInt::from(den));
                for digits in [0, 1, 2, 3, 15, 17] {
                    assert_eq!(round_decimal(&q, digits), slow(&q, digits), "{q} to {digits}");
                }
            }
        }
        assert_eq!(round_decimal(&Q::new(BigInt::from(-1), BigInt::from(200)), 2), "-0.01");
        assert_eq!(round_decimal(&Q::new(BigInt::from(-1), BigInt::from(300)), 2), "0.00");
    }

    /// Alike means the same polynomial and interval: a clone is, the same
    /// number refined or isolated by another polynomial is not, and
    /// rationals are alike when equal.
    #[test]
    fn same_form_is_the_written_form() {
        let p = UPoly::from_ints(&[-6, 0, 1]);
        let root = Algebraic::positive_roots(&p).remove(0);
        assert!(root.same_form(&root.clone()));
        let narrow = root.refine(&Q::new(BigInt::one(), BigInt::from(1 << 20)));
        assert!(narrow == root && !narrow.same_form(&root));
        let twice = Algebraic::positive_roots(&UPoly::from_ints(&[-24, 0, 4])).remove(0);
        assert!(twice.same_form(&root), "the primitive square-free form: {twice:?}");
        let other = Algebraic::positive_roots(&UPoly::from_ints(&[-6, 0, 0, 0, 1])).remove(0);
        assert!(!other.same_form(&root));
        let half = Algebraic::from_rational(Q::new(BigInt::one(), BigInt::from(2)));
        assert!(half.same_form(&Algebraic::from_rational(Q::new(BigInt::from(2), BigInt::from(4)))));
        assert!(!half.same_form(&root) && !root.same_form(&half));
    }
    use proptest::prelude::*;

    /// The slow, obvious oracle of [`sqrt_parts`]: trial division by every
    /// integer below the bound.
    fn sqrt_parts_by_trial(q: &Q) -> (Q, BigInt) {
        let n = q.numer() * q.denom();
        let mut rest = n.abs();
        let mut out = BigInt::one();
        let mut p = BigInt::from(2);
        let bound = BigInt::from(if rest.bits() > 256 { 1_000 } else { 100_000 });
        while &p * &p <= rest && p < bound {
            let pp = &p * &p;
            while (&rest % &pp).is_zero() {
                rest /= &pp;
                out *= &p;
            }
            p += BigInt::one();
        }
        let s = rest.sqrt();
        if &s * &s == rest {
            out *= s;
            rest = BigInt::one();
        }
        (Q::new(out, q.denom().clone()), rest)
    }

    proptest! {
        /// Square factors found over the primes are those found over every
        /// integer: radicands with square factors of small primes, of
        /// composites, of a prime near the bound, and a large square.
        #[test]
        fn sqrt_parts_matches_trial_division(
            a in 0u64..1_000_000,
            b in 1u64..10_000,
            f in prop::sample::select(vec![1u64, 4, 36, 49 * 49, 99_991 * 99_991, 1_000_003 * 1_000_003]),
            big in 0u32..3,
        ) {
            let scale = BigInt::from(10).pow(big * 40);
            let q = Q::new(BigInt::from(a) * BigInt::from(f) * &scale * &scale, BigInt::from(b));
            prop_assert_eq!(sqrt_parts(&q), sqrt_parts_by_trial(&q));
        }
    }

    /// The obvious search: the least denominator d with a fraction in
    /// (l, r), and for it the least numerator.
    fn simplest_by_search(l: &Q, r: &Q) -> Q {
        let mut d = BigInt::one();
        loop {
            let n = (l * Q::from_integer(d.clone())).floor().to_integer() + BigInt::one();
            let c = Q::new(n, d.clone());
            if c < *r {
                return c;
            }
            d += 1;
        }
    }

    /// Roots 1 and 1 + P, P the product of every prime the lifting tries:
    /// they meet modulo each of them, so the p-adic path declines and the search
    /// in narrowed intervals (the fallback) must find both.
    #[test]
    fn rational_roots_found_when_no_prime_suits_the_lifting() {
        let mut p = BigInt::one();
        let near_2_20 = [1_048_573u64, 1_048_571, 1_048_559, 1_048_549, 1_048_517, 1_048_507];
        let near_1000 = [1009u64, 1013, 1019, 1021, 1031, 1033, 1039, 1049, 1051, 1061, 1063, 1069];
        for q in near_2_20.into_iter().chain(near_1000) {
            p *= q;
        }
        let (a, b) = (BigInt::one(), BigInt::one() + &p);
        // (x − a)(x − b)(x² − 2)
        let quad =
            UPoly::new(vec![Q::from_integer(&a * &b), Q::from_integer(-(&a + &b)), Q::one()]);
        let f = &quad * &UPoly::from_ints(&[-2, 0, 1]);
        let ints = crate::univariate::upoly::int_primitive(&f);
        assert_eq!(
            crate::univariate::rational_roots::rational_roots(&ints),
            None,
            "no prime suits"
        );
        let roots = Algebraic::real_roots(&f);
        let rational: Vec<Q> = roots.iter().filter_map(|r| r.as_rational().cloned()).collect();
        assert_eq!(rational, vec![Q::from_integer(a), Q::from_integer(b)]);
        assert_eq!(roots.len(), 4);
    }

    proptest! {
        /// For f = x^k·F(x²): the rational roots and the factors x² − y
        /// from one lifting on F are those of the general route (every
        /// rational root of f, then `even_rational_factors` of f freed of
        /// them). F's factors b·y − a include squares (rational roots ±√y).
        #[test]
        fn even_rational_roots_match_the_general_route(
            linear in proptest::collection::vec((-6i64..=6, 1i64..=4), 0..3),
            squares in proptest::collection::vec((1i64..=4, 1i64..=3), 0..2),
            cofactor in proptest::collection::vec(-5i64..=5, 1..3),
            k in 0usize..2,
        ) {
            let mut big_f = UPoly::from_ints(&cofactor);
            prop_assume!(!big_f.is_zero());
            for (a, b) in &linear {
                big_f = &big_f * &UPoly::from_ints(&[-a, *b]);
            }
            for (a, b) in &squares {
                big_f = &big_f * &UPoly::from_ints(&[-a * a, b * b]);
            }
            prop_assume!(big_f.degree().unwrap_or(0) >= 1 && !big_f.coeff(0).is_zero());
            let mut f = big_f.spread();
            if k == 1 {
                f = &f * &UPoly::x();
            }
            let sf = f.squarefree();
            let intervals = isolate_squarefree(&sf);
            let (_, all) = rational_roots(&sf, &intervals);
            let Some(all) = all else { return Ok(()) };
            let factors = even_rational_factors(&without_roots(&sf, &all));
            if let Some((roots, even)) = even_rational_roots(&sf) {
                prop_assert_eq!(roots, all);
                prop_assert_eq!(even, factors);
            }
        }
    }

    proptest! {
        /// `is_root_of` (no sign computed) agrees with the sign being zero,
        /// on the real roots of f = p·q against g = q·r, p, q, r random:
        /// the roots of q are roots of g, the others mostly not.
        #[test]
        fn is_root_of_agrees_with_the_sign(
            p in proptest::collection::vec(-6i64..=6, 2..4),
            q in proptest::collection::vec(-6i64..=6, 2..4),
            r in proptest::collection::vec(-6i64..=6, 1..3),
        ) {
            let (p, q, r) = (UPoly::from_ints(&p), UPoly::from_ints(&q), UPoly::from_ints(&r));
            prop_assume!(!p.is_zero() && !q.is_zero() && !r.is_zero());
            let f = &p * &q;
            let g = &q * &r;
            for root in Algebraic::real_roots(&f) {
                prop_assert_eq!(root.is_root_of(&g), root.sign_of(&g) == Ordering::Equal);
                prop_assert_eq!(root.is_root_of(&p), root.sign_of(&p) == Ordering::Equal);
            }
        }
    }

    proptest! {
        /// `narrowed` keeps the number exactly when it lies strictly inside
        /// the bracket (the oracle: two comparisons), and then its interval
        /// is the intersection of the two; brackets straddle, miss, touch
        /// and contain the interval held, on roots of random quartics.
        #[test]
        fn narrowed_keeps_the_number_exactly_when_inside(
            p in proptest::collection::vec(-9i64..=9, 3..6),
            ends in proptest::collection::vec((-400i64..400, 1i64..64), 2..=2),
            refine_bits in 0usize..12,
        ) {
            let p = UPoly::from_ints(&p);
            prop_assume!(!p.is_zero());
            let (x, y) = (Q::new(ends[0].0.into(), ends[0].1.into()), Q::new(ends[1].0.into(), ends[1].1.into()));
            prop_assume!(x != y);
            let (lo, hi) = if x < y { (x, y) } else { (y, x) };
            let width = Q::new(BigInt::one(), BigInt::one() << refine_bits);
            for a in Algebraic::real_roots(&p) {
                let a = a.refine(&width);
                let inside = a.cmp_rational(&lo) == Ordering::Greater
                    && a.cmp_rational(&hi) == Ordering::Less;
                match a.narrowed(&lo, &hi) {
                    None => prop_assert!(!inside || a.is_rational(), "{a:?} in ({lo}, {hi})"),
                    Some(n) => {
                        prop_assert!(inside && !a.is_rational());
                        prop_assert!(n == a && n.defining_poly() == a.defining_poly());
                        let ((l, h), (nl, nh)) = (a.interval(), n.interval());
                        prop_assert_eq!(nl, l.max(lo.clone()));
                        prop_assert_eq!(nh, h.min(hi.clone()));
                    }
                }
            }
        }
    }

    proptest! {
        #[test]
        fn simplest_between_is_the_least_denominator(
            a in -300i64..300, b in 1i64..40, c in -300i64..300, e in 1i64..40,
        ) {
            let (x, y) = (Q::new(a.into(), b.into()), Q::new(c.into(), e.into()));
            prop_assume!(x != y);
            let (l, r) = if x < y { (x, y) } else { (y, x) };
            prop_assert_eq!(simplest_between(&l, &r), simplest_by_search(&l, &r));
        }
    }
}
