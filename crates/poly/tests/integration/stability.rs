//! Exact stability limits and class changes of the paper's methods, against
//! limits derived by hand from χ(±1), the discriminant and |z|² = q, and
//! against a second, independent classifier at rational sample points.

use std::collections::HashMap;

use poly::advanced::stability::{
    analyze, class_at, classify, classify_roots_by_products, Boundary, StabilityReport,
};
use poly::{q, Algebraic, Method, Poly, RootClass, Sym, UPoly, Q};

/// χ of a built-in method with the given parameter values.
fn chi_of(name: &str, params: &[(&str, Q)]) -> Poly {
    let chi = poly::advanced::charpoly(&poly::builtin(name).unwrap()).unwrap();
    let values: HashMap<Sym, Q> = params.iter().map(|(n, v)| (Sym::new(n), v.clone())).collect();
    chi.eval_partial(&values)
}

/// χ of a user method written in the .zm language.
fn chi_of_source(src: &str) -> Poly {
    poly::advanced::charpoly(&Method::parse("user.zm", src).unwrap()).unwrap()
}

/// The unique root of the integer polynomial `p` (lowest power first) in
/// (lo, hi]: the hand-derived expected value.
#[track_caller]
fn root(p: &[i64], lo: Q, hi: Q) -> Algebraic {
    Algebraic::from_isolating(&UPoly::from_ints(p), &lo, &hi).expect("one root in the interval")
}

/// Where the analysis of χ alone stops: Φ_max, or the point with a
/// repeated root on the circle that only P decides.
fn limit(r: &StabilityReport) -> Option<Algebraic> {
    r.phi_max().or(r.undecided_at()).cloned()
}

fn rat(n: i64, d: i64) -> Algebraic {
    Algebraic::from_rational(q(n, d))
}

/// χ(x) as a polynomial in Φ.
fn chi_at_z(chi: &Poly, x: i64) -> UPoly {
    chi.subs(Sym::z(), &Poly::int(x)).to_upoly(Sym::phi()).unwrap()
}

/// The classes and change points the report should show, increasing in Φ:
/// `(class on the interval, Some((change point, class at the point)))`.
type Expected<'a> = &'a [(RootClass, Option<(Algebraic, RootClass)>)];

#[track_caller]
fn check(
    chi: &Poly,
    phi_max: Option<Algebraic>,
    boundary: Option<Boundary>,
    classes: Expected,
) -> StabilityReport {
    let r = analyze(chi).unwrap();
    assert_eq!(limit(&r), phi_max, "phi_max of {chi}");
    assert_eq!(r.boundary(), boundary, "boundary of {chi}");
    let got: Vec<RootClass> = r.intervals.iter().map(|i| i.class).collect();
    let want: Vec<RootClass> = classes.iter().map(|c| c.0).collect();
    assert_eq!(got, want, "interval classes of {chi}");
    let changes: Vec<_> = classes.iter().filter_map(|c| c.1.clone()).collect();
    assert_eq!(r.class_changes.len(), changes.len(), "{:?}", r.class_changes);
    for (c, (at, at_class)) in r.class_changes.iter().zip(changes) {
        assert_eq!(c.at, at);
        assert_eq!(c.at_class, Some(at_class), "class at {}", c.at);
    }
    // Intervals tile (0, ∞) and each sample lies inside its interval.
    assert_eq!(r.intervals[0].lo, Algebraic::zero());
    assert!(r.intervals.last().unwrap().hi.is_none());
    for w in r.intervals.windows(2) {
        assert_eq!(w[0].hi.as_ref(), Some(&w[1].lo));
    }
    for i in &r.intervals {
        assert!(i.lo.cmp_rational(&i.sample).is_lt());
        if let Some(h) = &i.hi {
            assert!(h.cmp_rational(&i.sample).is_gt());
        }
    }
    check_samples(chi, &r);
    r
}

/// The second classifier (products of roots via Newton's identities, for any
/// degree) agrees with the report at every sample and at nearby rationals.
#[track_caller]
fn check_samples(chi: &Poly, r: &StabilityReport) {
    for i in &r.intervals {
        let f = chi.subs(Sym::phi(), &Poly::constant(i.sample.clone())).to_upoly(Sym::z()).unwrap();
        assert_eq!(classify(&f), i.class, "Phi = {} in {chi}", i.sample);
        assert_eq!(
            classify_roots_by_products(&f),
            i.class,
            "oracle at Phi = {} in {chi}",
            i.sample
        );
        assert_eq!(class_at(chi, &i.sample).unwrap(), i.class);
    }
}

/// Jury's test for a z² + b z + c with a > 0: all roots strictly inside the
/// unit circle iff |c| < a, χ(1) > 0 and χ(−1) > 0 (textbook criterion,
/// independent of the classifier).
fn jury_strictly_stable(chi: &Poly, phi: &Q) -> bool {
    let f = chi.subs(Sym::phi(), &Poly::constant(phi.clone())).to_upoly(Sym::z()).unwrap();
    let (c, b, a) = (f.coeff(0), f.coeff(1), f.coeff(2));
    assert!(a > Q::default());
    c.clone() < a
        && -c.clone() < a
        && &(&a + &b) + &c > Q::default()
        && &(&a - &b) + &c > Q::default()
}

/// False Euler, Damped Euler (D = Φ/2) and Verlet share
/// χ = z² − (2 − Φ²) z + 1: χ(−1) = 4 − Φ² vanishes at 2, where the
/// discriminant Φ²(Φ² − 4) vanishes too: a double root at −1.
#[test]
fn false_euler_family_limit_is_two_with_double_root_at_minus_one() {
    for name in
        ["false_euler", "false_euler_matrix", "damped_euler", "damped_euler_matrix", "verlet"]
    {
        let chi = chi_of(name, &[]);
        let r = check(
            &chi,
            Some(rat(2, 1)),
            Some(Boundary::DoubleRootAtMinusOne),
            &[
                (RootClass::Harmonic, Some((rat(2, 1), RootClass::DoubleRootOnCircle))),
                (RootClass::AlternatingUnstable, None),
            ],
        );
        // χ alone leaves Φ = 2 open; P, not −I there, decides it unbounded.
        assert_eq!(r.undecided_at(), Some(&rat(2, 1)), "{name}");
        let d = poly::derive(&poly::builtin(name).unwrap()).unwrap();
        let full = d.stability(&poly::Params::new()).unwrap();
        assert_eq!(full.phi_max(), Some(&rat(2, 1)), "{name}");
        assert_eq!(full.bounded_at_phi_max(), Some(false), "{name}");
        assert!(chi_at_z(&chi, -1).eval(&q(2, 1)) == Q::default());
        assert!(!jury_strictly_stable(&chi, &q(201, 100)));
    }
}

/// Standard Euler (q = 1 + Φ²) and Standard Heun (q = 1 + Φ⁴/4) have a
/// complex pair (p² − q = −Φ² < 0) outside the circle for every Φ > 0.
#[test]
fn standard_methods_are_unstable_for_every_phi() {
    for name in ["standard_euler", "standard_euler_matrix", "standard_heun", "standard_heun_matrix"]
    {
        let chi = chi_of(name, &[]);
        let r = check(&chi, None, None, &[(RootClass::UnstableOscillation, None)]);
        assert!(!r.bounded_for_all());
        for phi in [q(1, 1000), q(1, 2), q(3, 1), q(100, 1)] {
            assert_eq!(class_at(&chi, &phi).unwrap(), RootClass::UnstableOscillation);
            assert!(!jury_strictly_stable(&chi, &phi));
        }
    }
}

/// False Heun: χ(1) = Φ²(1 − Φ²/2) puts a root through +1 at √2; the
/// discriminant (Φ²/16)(Φ⁶ − 6Φ⁴ + 17Φ² − 16) turns the damped pair into two
/// real roots at Φ ≈ 1.2695, before the limit: a monotonic-stable band that
/// the paper's "either monotonic unstable or a damped oscillation" omits.
#[test]
fn false_heun_limit_is_sqrt_two_with_a_monotonic_stable_band() {
    let sqrt2 = root(&[-2, 0, 1], q(1, 1), q(2, 1));
    let band = root(&[-16, 0, 17, 0, -6, 0, 1], q(5, 4), q(13, 10));
    for name in ["false_heun", "false_heun_matrix"] {
        let chi = chi_of(name, &[]);
        let r = check(
            &chi,
            Some(sqrt2.clone()),
            Some(Boundary::RootThroughPlusOne),
            &[
                (RootClass::DampedOscillation, Some((band.clone(), RootClass::MonotonicStable))),
                (RootClass::MonotonicStable, Some((sqrt2.clone(), RootClass::Constant))),
                (RootClass::MonotonicUnstable, None),
            ],
        );
        assert_eq!(r.phi_max().unwrap().closed_form().as_deref(), Some("sqrt(2)"));
        assert_eq!(r.bounded_at_phi_max(), Some(true));
        assert!(sqrt2.is_root_of(&chi_at_z(&chi, 1)));
        // Strictly inside the band both real roots are in (0, 1).
        assert!(jury_strictly_stable(&chi, &q(7, 5)));
        assert!(!jury_strictly_stable(&chi, &q(3, 2)));
    }
}

/// Semi-False Heun: χ(−1) = 4 − Φ² − Φ⁴/4 vanishes at Φ² = 2√5 − 2, so the
/// paper's "always stable" fails beyond Φ ≈ 1.5723; at Φ = √2, p = q = 0 and
/// χ = z² (deadbeat).
#[test]
fn semi_false_heun_limit_is_sqrt_of_two_sqrt_five_minus_two() {
    let limit = root(&[-16, 0, 4, 0, 1], q(3, 2), q(8, 5));
    let sqrt2 = root(&[-2, 0, 1], q(1, 1), q(2, 1));
    for name in ["semi_false_heun", "semi_false_heun_matrix"] {
        let chi = chi_of(name, &[]);
        let r = check(
            &chi,
            Some(limit.clone()),
            Some(Boundary::RootThroughMinusOne),
            &[
                (RootClass::DampedOscillation, Some((sqrt2.clone(), RootClass::Deadbeat))),
                (RootClass::AlternatingStable, Some((limit.clone(), RootClass::Alternating))),
                (RootClass::AlternatingUnstable, None),
            ],
        );
        let phi_max = r.phi_max().unwrap().clone();
        assert_eq!(phi_max.closed_form().as_deref(), Some("sqrt(2*sqrt(5) - 2)"));
        assert_eq!(phi_max.to_decimal(4), "1.5723");
        assert!(phi_max.is_root_of(&chi_at_z(&chi, -1)));
        assert!(jury_strictly_stable(&chi, &q(157, 100)));
        assert!(!jury_strictly_stable(&chi, &q(158, 100)));
    }
}

/// Damped Euler with a fixed damping ratio D: q − 1 = Φ(Φ − 2D) and
/// p² − q = Φ²(D² − 1).
/// D = 1/2: a damped pair up to Φ = 2D = 1, harmonic there, then unstable.
/// D = 2: real roots 1 − (2 ∓ √3)Φ; the negative one passes −1 at
/// Φ = 4 − 2√3 and overtakes the positive one at p = 0, Φ = 1/D = 1/2.
/// D = 1: a double root 1 − Φ: deadbeat at 1, double root at −1 at 2.
#[test]
fn damped_euler_with_rational_damping() {
    let chi = chi_of("damped_euler_d", &[("D", q(1, 2))]);
    check(
        &chi,
        Some(rat(1, 1)),
        Some(Boundary::ComplexPairLeavesCircle),
        &[
            (RootClass::DampedOscillation, Some((rat(1, 1), RootClass::Harmonic))),
            (RootClass::UnstableOscillation, None),
        ],
    );
    let chi = chi_of("damped_euler_d", &[("D", q(2, 1))]);
    let limit = root(&[4, -8, 1], q(1, 2), q(3, 5));
    let r = check(
        &chi,
        Some(limit.clone()),
        Some(Boundary::RootThroughMinusOne),
        &[
            (RootClass::MonotonicStable, Some((rat(1, 2), RootClass::AlternatingStable))),
            (RootClass::AlternatingStable, Some((limit, RootClass::Alternating))),
            (RootClass::AlternatingUnstable, None),
        ],
    );
    assert_eq!(r.phi_max().unwrap().closed_form().as_deref(), Some("4 - 2*sqrt(3)"));
    let chi = chi_of("damped_euler_d", &[("D", q(1, 1))]);
    check(
        &chi,
        Some(rat(2, 1)),
        Some(Boundary::DoubleRootAtMinusOne),
        &[
            (RootClass::MonotonicStable, Some((rat(1, 1), RootClass::Deadbeat))),
            (RootClass::AlternatingStable, Some((rat(2, 1), RootClass::DoubleRootOnCircle))),
            (RootClass::AlternatingUnstable, None),
        ],
    );
}

/// A parameter left symbolic is an error naming it, not a panic.
#[test]
fn remaining_parameters_are_rejected() {
    let e = analyze(&chi_of("damped_euler_d", &[])).unwrap_err();
    assert!(e.to_string().contains("parameter D"), "{e}");
    let e = analyze(&Poly::parse("Phi^2 + 1").unwrap()).unwrap_err();
    assert!(e.to_string().contains("does not depend on z"), "{e}");
}

/// Degree 3: False Euler (v, y) beside a decoupled Euler-damped x with
/// x' = −ω₀ x / 4: χ = (z² − (2 − Φ²) z + 1)(z − 1 + Φ/4). The real root
/// stays inside until Φ = 8, so the limit is False Euler's 2.
#[test]
fn degree_three_user_method() {
    let chi = chi_of_source(
        "method fe_plus_decay\nstate v y x\nv = v - Phi*y\ny = y + Phi*v\nx = x - 0.25*Phi*x\n",
    );
    assert_eq!(chi.degree_in(Sym::z()), 3);
    let r = analyze(&chi).unwrap();
    assert_eq!(limit(&r), Some(rat(2, 1)));
    assert_eq!(r.boundary(), Some(Boundary::DoubleRootAtMinusOne));
    assert_eq!(r.intervals[0].class, RootClass::Harmonic);
    check_samples(&chi, &r);
    // Above 2 the False Euler root below −1 dominates.
    assert_eq!(class_at(&chi, &q(3, 1)).unwrap(), RootClass::AlternatingUnstable);
}

/// Degree 3 with a complex pair leaving the circle: Damped Euler with D = 1/2
/// (|z|² = 1 − Φ + Φ², limit 1) beside a decay root 1 − Φ/4. The decay root
/// dominates while (1 − Φ/4)² > 1 − Φ + Φ², i.e. for Φ < 8/15.
#[test]
fn degree_three_complex_pair_leaves_circle() {
    let chi = chi_of_source(
        "method de_plus_decay\nstate v y x\nv1 = v - Phi*(v + y)\ny = y + Phi*v\nv = v1\nx = x - 0.25*Phi*x\n",
    );
    let r = analyze(&chi).unwrap();
    assert_eq!(limit(&r), Some(rat(1, 1)));
    assert_eq!(r.boundary(), Some(Boundary::ComplexPairLeavesCircle));
    let classes: Vec<RootClass> = r.intervals.iter().map(|i| i.class).collect();
    assert_eq!(
        classes,
        [RootClass::MonotonicStable, RootClass::DampedOscillation, RootClass::UnstableOscillation]
    );
    assert_eq!(r.class_changes[0].at, rat(8, 15));
    assert_eq!(r.class_changes[0].at_class, Some(RootClass::DampedOscillation)); // tie: pair wins
    assert_eq!(r.class_changes[1].at, rat(1, 1));
    assert_eq!(r.class_changes[1].at_class, Some(RootClass::Harmonic));
    check_samples(&chi, &r);
}

/// Degree 4: two False Euler oscillators at Φ and Φ/2; the faster one fails
/// first, at Φ = 2, with a double root at −1; the slower one at Φ = 4.
#[test]
fn degree_four_user_method() {
    let chi = chi_of_source(
        "method two_oscillators\nstate v y u w\nv = v - Phi*y\ny = y + Phi*v\nu = u - 0.5*Phi*w\nw = w + 0.5*Phi*u\n",
    );
    assert_eq!(chi.degree_in(Sym::z()), 4);
    let r = analyze(&chi).unwrap();
    assert_eq!(limit(&r), Some(rat(2, 1)));
    assert_eq!(r.boundary(), Some(Boundary::DoubleRootAtMinusOne));
    assert_eq!(r.intervals[0].class, RootClass::Harmonic);
    check_samples(&chi, &r);
    assert!(r.critical_points.iter().any(|p| p.at == rat(4, 1)));
}

/// The general classifier agrees with the second-order sign rules on every
/// built-in at many rational Φ, including the exact critical rationals.
#[test]
fn general_classifier_agrees_with_quadratic_rules() {
    let phis: Vec<Q> = (1..=30).map(|k| q(k, 10)).collect();
    // Every built-in whose χ is over Q (constants are analysed elsewhere).
    for name in poly::advanced::builtins::builtin_names()
        .filter(|n| poly::builtin(n).unwrap().constants().is_empty())
    {
        let chi = chi_of(name, &[("D", q(3, 5))]);
        for phi in &phis {
            let f = chi.subs(Sym::phi(), &Poly::constant(phi.clone())).to_upoly(Sym::z()).unwrap();
            assert_eq!(classify(&f), class_at(&chi, phi).unwrap(), "{name} at {phi}");
        }
    }
}

/// Classes of polynomials with known roots, for the general classifier.
#[track_caller]
fn check_class(roots_num_den: &[(i64, i64)], complex: &[(Q, Q)], class: RootClass) {
    let mut f = UPoly::from_ints(&[1]);
    for &(n, d) in roots_num_den {
        f = &f * &UPoly::new(vec![-q(n, d), q(1, 1)]);
    }
    for (re, im) in complex {
        // (z − re)² + im²
        f = &f * &UPoly::new(vec![re * re + im * im, -(re + re), q(1, 1)]);
    }
    assert_eq!(classify(&f), class, "{f}");
    assert_eq!(classify_roots_by_products(&f), class, "oracle: {f}");
}

#[test]
fn classify_roots_on_known_roots() {
    use RootClass::*;
    check_class(&[(1, 2), (-1, 3)], &[], MonotonicStable);
    check_class(&[(1, 1), (-1, 3)], &[], Constant);
    check_class(&[(1, 1), (1, 1)], &[], DoubleRootOnCircle);
    check_class(&[(-1, 1), (-1, 1), (1, 2)], &[], DoubleRootOnCircle);
    check_class(&[(-3, 2), (1, 1)], &[], AlternatingUnstable);
    check_class(&[(-1, 1)], &[(q(0, 1), q(1, 2))], Alternating);
    check_class(&[(9, 10)], &[(q(0, 1), q(1, 1))], Harmonic);
    check_class(&[(1, 1)], &[(q(3, 5), q(4, 5))], Harmonic); // tie: the pair wins
    check_class(&[(1, 1)], &[(q(3, 5), q(4, 5)), (q(3, 5), q(4, 5))], DoubleRootOnCircle);
    check_class(&[(2, 1)], &[(q(1, 1), q(1, 1))], MonotonicUnstable);
    check_class(&[(1, 1)], &[(q(1, 1), q(1, 1))], UnstableOscillation);
    check_class(&[(1, 2), (-1, 2)], &[], AlternatingStable); // tie: alternation wins
    check_class(&[(0, 1), (0, 1)], &[], Deadbeat);
}

/// The class exactly at an irrational limit of a cubic χ, through both
/// ways `rational.rs` decides it. (2z + 1)(z² − 2(1 − Φ²/3)z + 1) keeps
/// the self-reciprocal pair on the circle until p = 1 − Φ²/3 reaches −1 at
/// Φ = √6, where it is a double root at −1: the reciprocal factor sends the
/// point through the gcd over Q(√6).
/// (3z + 1)(z² − (1 − Φ²/5)z + 1/2) has a pair of modulus 1/√2 that turns
/// real, one of its roots leaving through −1 where
/// χ(−1) = 0: 1 + (1 − Φ²/5) + 1/2 = 0, Φ = √(25/2) = 5/√2, with simple
/// roots (the shortcut from the conditions).
#[test]
fn class_at_an_irrational_limit_of_a_cubic() {
    let reciprocal = Poly::parse("(2*z + 1)*(z^2 - 2*(1 - Phi^2/3)*z + 1)").unwrap();
    let r = analyze(&reciprocal).unwrap();
    let six = root(&[-6, 0, 1], q(2, 1), q(3, 1));
    assert_eq!(limit(&r), Some(six.clone()));
    let at = r.class_changes.iter().find(|c| c.at == six).expect("a change at sqrt 6");
    assert_eq!((at.from, at.at_class), (RootClass::Harmonic, Some(RootClass::DoubleRootOnCircle)));

    let simple = Poly::parse("(3*z + 1)*(z^2 - (1 - Phi^2/5)*z + 1/2)").unwrap();
    let r = analyze(&simple).unwrap();
    let lim = limit(&r).expect("a limit");
    assert_eq!(lim, root(&[-25, 0, 2], q(3, 1), q(4, 1)));
    let at = r.class_changes.iter().find(|c| c.at == lim).expect("a change at the limit");
    assert_eq!(at.at_class, Some(RootClass::Alternating), "{r:?}");
}
