//! Sturm counting, root isolation and exact algebraic numbers, checked
//! against polynomials built from known roots and hand-derived closed forms.

use std::cmp::Ordering;

use poly::advanced::sturm::{
    count_all_real_roots, count_real_roots, isolate_real_roots, sturm_sequence,
};
use poly::{q, Algebraic, UPoly, Q};
use proptest::prelude::*;

/// ∏ (x − r) over the given roots (repeats allowed).
fn from_roots(roots: &[Q]) -> UPoly {
    roots
        .iter()
        .fold(UPoly::from_ints(&[1]), |acc, r| &acc * &UPoly::new(vec![-r.clone(), q(1, 1)]))
}

fn qs(v: &[(i64, i64)]) -> Vec<Q> {
    v.iter().map(|&(n, d)| q(n, d)).collect()
}

/// The number of distinct known roots in (lo, hi], counted directly.
fn expected_count(roots: &[Q], lo: &Q, hi: &Q) -> usize {
    let mut distinct: Vec<&Q> = roots.iter().filter(|r| lo < *r && *r <= hi).collect();
    distinct.sort();
    distinct.dedup();
    distinct.len()
}

#[track_caller]
fn check_counts(roots: &[Q]) {
    let p = from_roots(roots);
    let mut points: Vec<Q> = roots.to_vec();
    points.extend([q(-100, 1), q(-1, 3), q(0, 1), q(1, 7), q(5, 2), q(100, 1)]);
    for lo in &points {
        for hi in &points {
            assert_eq!(
                count_real_roots(&p, lo, hi),
                expected_count(roots, lo, hi),
                "roots {roots:?} in ({lo}, {hi}]"
            );
        }
    }
}

/// Sturm's count of distinct roots in (lo, hi] matches the known roots,
/// including intervals that end (or start) exactly at a root.
#[test]
fn counts_match_known_roots() {
    check_counts(&qs(&[(-3, 1), (-1, 2), (0, 1), (1, 3), (2, 1)]));
    check_counts(&qs(&[(2, 1), (2, 1), (2, 1), (-1, 1)])); // repeated roots count once
    check_counts(&qs(&[(1, 1000), (2, 1000), (3, 1000)])); // close roots
    check_counts(&qs(&[(7, 3)]));
}

/// Known irrational and complex roots: x² − 2 has ±√2, x² + 1 none,
/// Chebyshev T₅ = 16x⁵ − 20x³ + 5x has five roots in (−1, 1).
#[test]
fn counts_of_irrational_and_complex_roots() {
    let two = UPoly::from_ints(&[-2, 0, 1]);
    assert_eq!(count_real_roots(&two, &q(1, 1), &q(2, 1)), 1);
    assert_eq!(count_real_roots(&two, &q(-2, 1), &q(0, 1)), 1);
    assert_eq!(count_real_roots(&two, &q(141, 100), &q(142, 100)), 1);
    assert_eq!(count_real_roots(&two, &q(142, 100), &q(2, 1)), 0);
    assert_eq!(count_all_real_roots(&UPoly::from_ints(&[1, 0, 1])), 0);
    let t5 = UPoly::from_ints(&[0, 5, 0, -20, 0, 16]);
    assert_eq!(count_real_roots(&t5, &q(-1, 1), &q(1, 1)), 5);
    assert_eq!(count_all_real_roots(&t5), 5);
    // The sequence of a square-free p starts p, p′ and ends in a constant.
    let seq = sturm_sequence(&t5);
    assert_eq!(seq[1].monic(), t5.derivative().monic());
    assert_eq!(seq.last().unwrap().degree(), Some(0));
}

#[track_caller]
fn check_isolation(roots: &[Q]) {
    let p = from_roots(roots);
    let mut distinct = roots.to_vec();
    distinct.sort();
    distinct.dedup();
    let intervals = isolate_real_roots(&p);
    assert_eq!(intervals.len(), distinct.len(), "roots {roots:?}: {intervals:?}");
    for (k, ((lo, hi), r)) in intervals.iter().zip(&distinct).enumerate() {
        assert!(lo <= r && r <= hi, "root {r} outside [{lo}, {hi}]");
        if lo != hi {
            assert!(lo < r && r < hi);
            // The square-free part changes sign across the interval.
            let (a, b) = (p.squarefree().eval(lo), p.squarefree().eval(hi));
            assert!(!a.is_zero_q() && !b.is_zero_q() && (a < Q::default()) != (b < Q::default()));
        }
        if k > 0 {
            // Open intervals may share an endpoint (which is then no root).
            let (prev_lo, prev_hi) = &intervals[k - 1];
            let shared_ok = prev_lo != prev_hi && lo != hi;
            assert!(
                prev_hi < lo || (prev_hi == lo && shared_ok),
                "intervals overlap: {intervals:?}"
            );
        }
    }
}

trait IsZero {
    fn is_zero_q(&self) -> bool;
}
impl IsZero for Q {
    fn is_zero_q(&self) -> bool {
        *self == Q::default()
    }
}

/// Isolation of products of linear factors: one interval per distinct root,
/// sorted and disjoint, each holding its root.
#[test]
fn isolation_of_known_rational_roots() {
    check_isolation(&qs(&[(-3, 1), (-1, 2), (0, 1), (1, 3), (2, 1)]));
    check_isolation(&qs(&[(1, 1000), (2, 1000), (3, 1000), (-7, 9)]));
    check_isolation(&qs(&[(5, 1), (5, 1), (-5, 1)]));
    check_isolation(&qs(&[(1, 2)]));
}

proptest! {
    #[test]
    fn isolation_of_random_rational_roots(
        raw in proptest::collection::vec((-40i64..40, 1i64..9), 1..7)
    ) {
        let roots: Vec<Q> = raw.iter().map(|&(n, d)| q(n, d)).collect();
        check_isolation(&roots);
    }
}

/// The positive root of `p` in (lo, hi], for building expected numbers.
#[track_caller]
fn root_of(p: &[i64], lo: Q, hi: Q) -> Algebraic {
    Algebraic::from_isolating(&UPoly::from_ints(p), &lo, &hi).expect("one root in the interval")
}

#[track_caller]
fn check_closed_form(a: &Algebraic, expected: Option<&str>) {
    assert_eq!(a.closed_form().as_deref(), expected, "{a:?}");
}

/// Closed forms: rationals, square roots (simplified), quadratic
/// irrationals and square roots of quadratic irrationals.
#[test]
fn closed_forms() {
    check_closed_form(&root_of(&[-2, 0, 1], q(1, 1), q(2, 1)), Some("sqrt(2)"));
    check_closed_form(&root_of(&[-2, 0, 1], q(-2, 1), q(-1, 1)), Some("-sqrt(2)"));
    check_closed_form(&root_of(&[-8, 0, 1], q(2, 1), q(3, 1)), Some("2*sqrt(2)"));
    check_closed_form(&root_of(&[-1, 0, 2], q(0, 1), q(1, 1)), Some("sqrt(2)/2"));
    // x² − 2x − 1 = 0: x = 1 ± √2.
    check_closed_form(&root_of(&[-1, -2, 1], q(2, 1), q(3, 1)), Some("sqrt(2) + 1"));
    check_closed_form(&root_of(&[-1, -2, 1], q(-1, 1), q(0, 1)), Some("1 - sqrt(2)"));
    // Φ⁴ + 4Φ² − 16 = 0: Φ² = −2 + 2√5 (the Semi-False Heun limit).
    check_closed_form(&root_of(&[-16, 0, 4, 0, 1], q(3, 2), q(8, 5)), Some("sqrt(2*sqrt(5) - 2)"));
    // x² − 8x + 4 = 0: x = 4 ± 2√3.
    check_closed_form(&root_of(&[4, -8, 1], q(0, 1), q(1, 1)), Some("4 - 2*sqrt(3)"));
    check_closed_form(&root_of(&[-2, 0, 0, 1], q(1, 1), q(2, 1)), None);
    check_closed_form(&Algebraic::from_rational(q(-3, 4)), Some("-3/4"));
}

/// Reduction: rational roots come out as rationals, other rational roots and
/// foreign x² − y factors leave the defining polynomial.
#[test]
fn defining_polynomials_are_reduced() {
    let two = root_of(&[-4, 0, 1], q(1, 1), q(3, 1));
    assert_eq!(two.as_rational(), Some(&q(2, 1)));
    assert_eq!(two.defining_poly(), UPoly::from_ints(&[-2, 1]));
    // x²(x² − 2)(x − 3): the root near 1.41 is defined by x² − 2.
    let p = &from_roots(&qs(&[(0, 1), (0, 1), (3, 1)])) * &UPoly::from_ints(&[-2, 0, 1]);
    let r = Algebraic::from_isolating(&p, &q(1, 1), &q(2, 1)).unwrap();
    assert_eq!(r.defining_poly(), UPoly::from_ints(&[-2, 0, 1]));
    // (x² − 2)(x² − 3): √3 is defined by x² − 3.
    let r = root_of(&[6, 0, -5, 0, 1], q(3, 2), q(2, 1));
    assert_eq!(r.defining_poly(), UPoly::from_ints(&[-3, 0, 1]));
    assert_eq!(r.to_string(), "sqrt(3)");
    // No closed form: the display names the polynomial and an interval.
    let cube = root_of(&[-2, 0, 0, 1], q(1, 1), q(2, 1));
    assert!(cube.to_string().starts_with("root of Phi^3 - 2 in ["), "{cube}");
}

/// Exact comparisons: with rationals, between equal numbers given by
/// different polynomials, and between close distinct numbers.
#[test]
fn comparisons() {
    let sqrt2 = root_of(&[-2, 0, 1], q(0, 1), q(2, 1));
    assert_eq!(sqrt2.cmp_rational(&q(7, 5)), Ordering::Greater);
    assert_eq!(sqrt2.cmp_rational(&q(3, 2)), Ordering::Less);
    assert_eq!(sqrt2.cmp_rational(&q(1_414_214, 1_000_000)), Ordering::Less);
    // √2 as a root of (x² − 2)(x² − 3) = x⁴ − 5x² + 6, on a different interval.
    let also = root_of(&[6, 0, -5, 0, 1], q(13, 10), q(3, 2));
    assert_eq!(sqrt2, also);
    // 1.41421356237 < √2 < 1.41421356238: a rational squeezed close.
    let close = Algebraic::from_rational(q(141_421_356_237, 100_000_000_000));
    assert!(close < sqrt2);
    let sqrt3 = root_of(&[-3, 0, 1], q(0, 1), q(2, 1));
    assert!(sqrt2 < sqrt3);
    assert_eq!(sqrt2.sign_of(&UPoly::from_ints(&[-2, 0, 1])), Ordering::Equal);
    assert_eq!(sqrt2.sign_of(&UPoly::from_ints(&[-3, 0, 1])), Ordering::Less);
    assert_eq!(sqrt2.multiplicity_in(&UPoly::from_ints(&[4, 0, -4, 0, 1])), 2);
    assert_eq!(sqrt2.square().as_rational(), Some(&q(2, 1)));
    let limit = root_of(&[-16, 0, 4, 0, 1], q(3, 2), q(8, 5));
    assert_eq!(limit.square().closed_form().as_deref(), Some("2*sqrt(5) - 2"));
}

/// `to_decimal(k)` rounds correctly: the defining polynomial changes sign
/// between d − ½·10⁻ᵏ and d + ½·10⁻ᵏ, checked exactly.
#[track_caller]
fn check_decimal(a: &Algebraic, digits: usize, expected: &str) {
    let d = a.to_decimal(digits);
    assert_eq!(d, expected);
    let value: Q = {
        let (int, frac) = d.split_once('.').unwrap();
        let n: Q = format!("{int}{frac}").parse().unwrap();
        n / num_traits::pow(q(10, 1), frac.len())
    };
    let half = q(1, 2) / num_traits::pow(q(10, 1), digits);
    let p = a.defining_poly();
    let (below, above) = (p.eval(&(&value - &half)), p.eval(&(&value + &half)));
    assert!((below < Q::default()) != (above < Q::default()), "{d} does not bracket {a}");
}

#[test]
fn decimals_are_exact() {
    check_decimal(&root_of(&[-2, 0, 1], q(0, 1), q(2, 1)), 15, "1.414213562373095");
    check_decimal(&root_of(&[-16, 0, 4, 0, 1], q(3, 2), q(8, 5)), 12, "1.572302755515");
    check_decimal(&root_of(&[-2, 0, 0, 1], q(1, 1), q(2, 1)), 20, "1.25992104989487316477");
    assert_eq!(Algebraic::from_rational(q(-1, 8)).to_decimal(2), "-0.13");
    assert_eq!(Algebraic::from_rational(q(2, 1)).to_decimal(3), "2.000");
}

/// Refinement keeps the number and narrows its interval below the width.
#[test]
fn refinement_narrows() {
    let a = root_of(&[-16, 0, 4, 0, 1], q(0, 1), q(4, 1));
    let w = q(1, 1) / num_traits::pow(q(10, 1), 15);
    let r = a.refine(&w);
    let (lo, hi) = r.interval();
    assert!(&hi - &lo <= w);
    assert_eq!(r, a);
}

// ---- Fast paths against slow, obvious oracles (issue 10) ----
//
// Refinement by quadratic interval refinement plus one grid-point test,
// comparisons of close algebraic numbers, `rational_between` by doubling and
// signs at a root by interval evaluation are each checked against the plain
// algorithm they replace.

/// A square-free-or-not integer polynomial with known structure: rational
/// roots times x² − k factors (irrational roots when k is not a square).
fn mixed_poly(rational: &[(i64, i64)], squares: &[i64]) -> UPoly {
    let mut p = from_roots(&qs(rational));
    for &k in squares {
        p = &p * &UPoly::from_ints(&[-k, 0, 1]);
    }
    p
}

/// Plain bisection, the obvious algorithm: halve until the width is at most
/// `width`, returning (m, m) for a root met as a midpoint.
fn bisect_oracle(p: &UPoly, lo: &Q, hi: &Q, width: &Q) -> (Q, Q) {
    let (mut lo, mut hi) = (lo.clone(), hi.clone());
    if lo == hi {
        return (lo, hi);
    }
    let s_lo = p.eval(&lo).cmp(&Q::default());
    while &hi - &lo > *width {
        let mid = (&lo + &hi) / q(2, 1);
        let s = p.eval(&mid).cmp(&Q::default());
        if s == Ordering::Equal {
            return (mid.clone(), mid);
        }
        if s == s_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo, hi)
}

/// The old `rational_between`: quarter both intervals until they separate.
fn rational_between_oracle(a: &Algebraic, b: &Algebraic) -> Q {
    let (mut a, mut b) = (a.clone(), b.clone());
    loop {
        let ((alo, ahi), (blo, bhi)) = (a.interval(), b.interval());
        if ahi < blo {
            return simplest_between_oracle(&ahi, &blo);
        }
        a = a.refine(&((&ahi - &alo) / q(4, 1)));
        b = b.refine(&((&bhi - &blo) / q(4, 1)));
    }
}

/// The simplest rational in (l, r) by continued fractions (the library's
/// rule, unchanged by the fast path; the oracle here is for the rounds).
fn simplest_between_oracle(l: &Q, r: &Q) -> Q {
    let fl = l.floor();
    if &fl + q(1, 1) < *r {
        return fl + q(1, 1);
    }
    let (frac_l, frac_r) = (l - &fl, r - &fl);
    if frac_l == Q::default() {
        let k = (q(1, 1) / &frac_r).floor() + q(1, 1);
        return fl + q(1, 1) / k;
    }
    fl + q(1, 1) / simplest_between_oracle(&(q(1, 1) / frac_r), &(q(1, 1) / frac_l))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// `refine_interval` (quadratic refinement + one grid point) returns the
    /// bisection result exactly, for any width.
    #[test]
    fn refinement_equals_bisection(
        rational in proptest::collection::vec((-30i64..30, 1i64..7), 0..4),
        squares in proptest::collection::vec(2i64..40, 0..3),
        bits in 0u32..70,
        decimal in proptest::bool::ANY,
    ) {
        let p = mixed_poly(&rational, &squares);
        prop_assume!(p.degree().unwrap_or(0) > 0);
        let sf = p.squarefree();
        let width = if decimal {
            Q::new(1.into(), num_bigint::BigInt::from(10).pow(bits / 3))
        } else {
            Q::new(1.into(), num_bigint::BigInt::from(1) << bits)
        };
        for (lo, hi) in isolate_real_roots(&p) {
            let fast = poly::advanced::sturm::refine_interval(&sf, &lo, &hi, &width);
            prop_assert_eq!(fast, bisect_oracle(&sf, &lo, &hi, &width));
        }
    }

    /// Refinement from a guess returns the bisection result whatever the
    /// guess: close (a few cells off, as from floating point), wide, on the
    /// wrong side, or a point.
    #[test]
    fn refinement_from_a_guess_equals_bisection(
        rational in proptest::collection::vec((-30i64..30, 1i64..7), 0..4),
        squares in proptest::collection::vec(2i64..40, 1..3),
        bits in 0u32..70,
        (off, spread) in (-40i64..40, 0u32..12),
        scale in 20u32..64,
    ) {
        let p = mixed_poly(&rational, &squares);
        let sf = p.squarefree();
        let width = Q::new(1.into(), num_bigint::BigInt::from(1) << bits);
        let unit = Q::new(1.into(), num_bigint::BigInt::from(1) << scale);
        for (lo, hi) in isolate_real_roots(&p) {
            let near = poly::advanced::sturm::refine_interval(&sf, &lo, &hi, &unit);
            let centre = (&near.0 + &near.1) / q(2, 1) + &unit * q(off, 1);
            let half = &unit * Q::from_integer(num_bigint::BigInt::from(1) << spread);
            let (gl, gh) = (&centre - &half, &centre + &half);
            let fast = poly::advanced::sturm::refine_interval_near(&sf, &lo, &hi, &width, &gl, &gh);
            prop_assert_eq!(&fast, &bisect_oracle(&sf, &lo, &hi, &width));
            let point = poly::advanced::sturm::refine_interval_near(&sf, &lo, &hi, &width, &centre, &centre);
            prop_assert_eq!(point, fast);
        }
    }

    /// The same where the roots and the interval ends are large (2^40 and
    /// more): the `i128` bisection overflows part-way and falls back to
    /// `BigInt`, or never fits.
    #[test]
    fn refinement_with_large_ends_equals_bisection(
        roots in proptest::collection::vec((-(1i64 << 40)..(1i64 << 40), 1i64..(1 << 20)), 1..4),
        pick in 0usize..4,
        halvings in 0u32..70,
        huge in proptest::bool::ANY,
    ) {
        let mut p = UPoly::from_ints(&[1, 0, 3]);
        for &(a, b) in &roots {
            p = &p * &UPoly::from_ints(&[-a, b]);
        }
        if huge {
            p = &p * &UPoly::from_ints(&[i64::MAX / 3, 1]);
        }
        let sf = p.squarefree();
        let intervals = isolate_real_roots(&sf);
        let (lo, hi) = intervals[pick % intervals.len()].clone();
        prop_assume!(lo != hi);
        let width = (&hi - &lo) / Q::from_integer(num_bigint::BigInt::from(1) << halvings) * q(3, 5);
        let fast = poly::advanced::sturm::refine_interval(&sf, &lo, &hi, &width);
        prop_assert_eq!(fast, bisect_oracle(&sf, &lo, &hi, &width));
    }

    /// Comparisons across different polynomials agree with isolating the
    /// product: the merged, deduplicated roots of p and q are the roots of
    /// p·q, in the same order.
    #[test]
    fn comparisons_agree_with_isolating_the_product(
        r1 in proptest::collection::vec((-12i64..12, 1i64..4), 0..3),
        s1 in proptest::collection::vec(2i64..30, 0..3),
        r2 in proptest::collection::vec((-12i64..12, 1i64..4), 0..3),
        s2 in proptest::collection::vec(2i64..30, 0..3),
        shift in -3i64..3,
    ) {
        let p = mixed_poly(&r1, &s1);
        // q: another polynomial, sometimes sharing roots with p, sometimes
        // with roots very close to p's (x² − k against (x − shift/10⁹)² − k).
        let mut q_poly = mixed_poly(&r2, &s2);
        if shift != 0 && !s1.is_empty() {
            let e = q(shift, 1_000_000_000);
            let x_minus_e = UPoly::new(vec![-e, q(1, 1)]);
            let sq = &x_minus_e * &x_minus_e;
            q_poly = &q_poly * &(&sq - &UPoly::constant(Q::from_integer(s1[0].into())));
        }
        let mut merged: Vec<Algebraic> = Algebraic::real_roots(&p);
        merged.extend(Algebraic::real_roots(&q_poly));
        merged.sort();
        merged.dedup();
        let product = Algebraic::real_roots(&(&p * &q_poly));
        prop_assert_eq!(merged.len(), product.len());
        for (a, b) in merged.iter().zip(&product) {
            prop_assert_eq!(a.cmp(b), Ordering::Equal, "{:?} vs {:?}", a, b);
        }
        for w in product.windows(2) {
            prop_assert_eq!(w[0].cmp(&w[1]), Ordering::Less);
            prop_assert_eq!(w[1].cmp(&w[0]), Ordering::Greater);
            prop_assert_eq!(Algebraic::rational_between(&w[0], &w[1]), rational_between_oracle(&w[0], &w[1]));
        }
    }

    /// The sign of g at an algebraic number agrees with a Sturm-certified
    /// oracle: narrow the interval until g has no root in it, then evaluate.
    #[test]
    fn signs_at_roots_agree_with_sturm(
        squares in proptest::collection::vec(2i64..30, 1..3),
        g in proptest::collection::vec(-9i64..9, 1..6),
        share in proptest::bool::ANY,
    ) {
        let p = mixed_poly(&[], &squares);
        let mut g = UPoly::from_ints(&g);
        if share {
            g = &g * &UPoly::from_ints(&[-squares[0], 0, 1]);
        }
        for a in Algebraic::real_roots(&p) {
            let fast = a.sign_of(&g);
            let expected = if g.is_zero() {
                Ordering::Equal
            } else {
                let gsf = g.squarefree();
                let on_g = g.degree().unwrap_or(0) > 0
                    && Algebraic::real_roots(&gsf).iter().any(|r| r == &a);
                if on_g {
                    Ordering::Equal
                } else {
                    let mut w = q(1, 4);
                    loop {
                        let (lo, hi) = a.refine(&w).interval();
                        if count_real_roots(&g, &lo, &hi) == 0 && !g.eval(&lo).is_zero_q() {
                            break g.eval(&hi).cmp(&Q::default());
                        }
                        w /= q(16, 1);
                    }
                }
            };
            prop_assert_eq!(fast, expected, "g = {:?} at {:?}", g, a);
        }
    }

    /// Decimals are correctly rounded: |a − d| ≤ ½·10^−digits.
    #[test]
    fn decimals_are_correctly_rounded(
        squares in proptest::collection::vec(2i64..300, 1..3),
        digits in 0usize..25,
    ) {
        let p = mixed_poly(&[(1, 3)], &squares);
        for a in Algebraic::real_roots(&p) {
            let d: Q = {
                let s = a.to_decimal(digits);
                let (int, frac) = s.split_once('.').unwrap_or((&s, ""));
                let neg = int.starts_with('-');
                let n: num_bigint::BigInt = format!("{}{}", int.trim_start_matches('-'), frac).parse().unwrap();
                let v = Q::new(n, num_bigint::BigInt::from(10).pow(frac.len() as u32));
                if neg { -v } else { v }
            };
            let half = Q::new(1.into(), num_bigint::BigInt::from(10).pow(digits as u32) * 2);
            prop_assert!(a.cmp_rational(&(&d - &half)) != Ordering::Less);
            prop_assert!(a.cmp_rational(&(&d + &half)) != Ordering::Greater);
            // From an interval narrow enough for its ends to decide (no
            // refinement): the same decimals.
            let narrow = a.refine(&Q::new(1.into(), num_bigint::BigInt::from(10).pow(digits as u32 + 4)));
            prop_assert_eq!(narrow.to_decimal(digits), a.to_decimal(digits));
            // From an interval one decimal cell wide (its ends may round
            // apart, and one sign then decides): the same decimals.
            let cell = a.refine(&Q::new(1.into(), num_bigint::BigInt::from(10).pow(digits as u32)));
            prop_assert_eq!(cell.to_decimal(digits), a.to_decimal(digits));
        }
    }
}

proptest! {
    /// Equality (no refinement) agrees with the ordering's `Equal` (which
    /// refines distinct numbers apart), on roots of two polynomials sharing
    /// a random factor, so that equal roots from different polynomials occur.
    #[test]
    fn equality_agrees_with_the_ordering(
        shared in prop::collection::vec(-9i64..=9, 2..5),
        a in prop::collection::vec(-9i64..=9, 1..4),
        b in prop::collection::vec(-9i64..=9, 1..4),
    ) {
        let f = UPoly::from_ints(&shared);
        let p = &f * &UPoly::from_ints(&a);
        let q = &f * &UPoly::from_ints(&b);
        prop_assume!(!p.is_zero() && !q.is_zero());
        let (rp, rq) = (Algebraic::real_roots(&p), Algebraic::real_roots(&q));
        for x in &rp {
            for y in &rq {
                prop_assert_eq!(x == y, x.cmp(y) == Ordering::Equal, "{} vs {}", x, y);
            }
        }
    }
}
