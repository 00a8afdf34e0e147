//! A repeated root on the unit circle is bounded exactly when the transition
//! matrix P is semisimple there, so every route that gives a verdict either
//! asks P or says it cannot decide. Three substeps of False Euler (Φ/3 each)
//! at Φ = 3 have P = −I and χ = (z + 1)²: bounded. At Φ = 6 (each substep
//! at False Euler's limit Φ = 2) χ = (z + 1)² again, but P is a Jordan
//! block: unbounded. 2-stage Gauss–Legendre has P = −I at its double root
//! Φ = 2√3.

use poly::advanced::stability::{analyze, class_at, ClassAt};
use poly::{q, Params, Poly, PolyMatrix, RootClass, Stability, Sym, Q};

use testkit::programs::FALSE_EULER_3;

/// The same with the damping of the test equation v' = −2Dv − y, y' = v
/// (D = 0 is [`FALSE_EULER_3`]), for the (Φ, D) region.
const FALSE_EULER_3_DAMPED: &str = "\
method false_euler_3_damped
state v y
param D
v = v - Phi/3*y - 2*D*Phi/3*v
y = y + Phi/3*v
v = v - Phi/3*y - 2*D*Phi/3*v
y = y + Phi/3*v
v = v - Phi/3*y - 2*D*Phi/3*v
y = y + Phi/3*v
";

fn derivation() -> poly::Derivation {
    poly::derive_source("false_euler_3.zm", FALSE_EULER_3).expect("derives")
}

fn at_phi(p: &Poly, phi: i64) -> Poly {
    p.subs(Sym::phi(), &Poly::int(phi))
}

#[test]
fn three_substeps_at_three_have_p_minus_identity_and_a_double_root_at_minus_one() {
    let d = derivation();
    assert!(d.p_denominator().is_one());
    let chi = d.charpoly();
    assert_eq!(at_phi(chi, 3), Poly::parse("z^2 + 2*z + 1").unwrap());
    assert_eq!(at_phi(chi, 6), Poly::parse("z^2 + 2*z + 1").unwrap());
    let p3 = d.transition_matrix().map(|e| at_phi(e, 3));
    assert_eq!(p3, PolyMatrix::identity(2).map(|e| -e));
    // At Φ = 6 each substep is False Euler's Jordan block at −1: P is not −I.
    let p6 = d.transition_matrix().map(|e| at_phi(e, 6));
    assert_ne!(p6, PolyMatrix::identity(2).map(|e| -e));
}

#[test]
fn derivation_stability_decides_the_double_root_from_p() {
    let r = derivation().stability(&Params::new()).unwrap();
    assert_eq!(r.phi_max().unwrap().to_string(), "6");
    assert_eq!(r.bounded_at_phi_max(), Some(false));
    let three = r.critical_points.iter().find(|c| c.at.to_string() == "3").expect("Φ = 3");
    assert_eq!(three.bounded, Some(true));
    assert!(r.is_stable_below(&q(6, 1)));
    assert_eq!(r.stable_intervals.len(), 1);
    let s = &r.stable_intervals[0];
    assert_eq!(s.hi.as_ref().unwrap().to_string(), "6");
    assert!(!s.hi_closed);
    let change = r.class_changes.iter().find(|c| c.at.to_string() == "3").expect("a change at 3");
    assert_eq!(change.at_class, Some(RootClass::DoubleRootOnCircle));
}

#[test]
fn derivation_class_at_decides_the_double_root_from_p() {
    let d = derivation();
    let at3 = d.class_at(&Params::new(), &q(3, 1)).unwrap();
    assert_eq!(at3, ClassAt { class: RootClass::DoubleRootOnCircle, bounded: true });
    let at6 = d.class_at(&Params::new(), &q(6, 1)).unwrap();
    assert_eq!(at6, ClassAt { class: RootClass::DoubleRootOnCircle, bounded: false });
    let below = d.class_at(&Params::new(), &q(5, 2)).unwrap();
    assert_eq!(below, ClassAt { class: RootClass::Harmonic, bounded: true });
    // False Euler itself at Φ = 2: the same χ shape, a Jordan block.
    let fe = poly::derive(&poly::builtin("false_euler").unwrap()).unwrap();
    let at2 = fe.class_at(&Params::new(), &q(2, 1)).unwrap();
    assert_eq!(at2, ClassAt { class: RootClass::DoubleRootOnCircle, bounded: false });
}

#[test]
fn the_bare_chi_route_says_undecided_not_unbounded() {
    let d = derivation();
    let class = class_at(d.charpoly(), &q(3, 1)).unwrap();
    assert_eq!(class, RootClass::DoubleRootOnCircle);
    assert_eq!(class.bounded(), None);
    let bare = analyze(d.charpoly()).unwrap();
    match &bare.stability {
        Stability::UndecidedAt { at, .. } => assert_eq!(at.to_string(), "3"),
        other => panic!("{other:?}"),
    }
    let three = bare.critical_points.iter().find(|c| c.at.to_string() == "3").unwrap();
    assert_eq!(three.bounded, None);
}

#[test]
fn root_classes_tell_bounded_unbounded_or_undecided() {
    for c in RootClass::ALL {
        let expected = match c {
            RootClass::DoubleRootOnCircle => None,
            RootClass::UnstableOscillation
            | RootClass::MonotonicUnstable
            | RootClass::AlternatingUnstable
            | RootClass::Singular => Some(false),
            _ => Some(true),
        };
        assert_eq!(c.bounded(), expected, "{c}");
    }
}

#[test]
fn the_region_asks_p() {
    let d = poly::derive_source("damped.zm", FALSE_EULER_3_DAMPED).unwrap();
    let r = d.region(Sym::new("D")).unwrap();
    let zero = Q::from_integer(0.into());
    let at = r.class_at(&q(3, 1), &zero).unwrap();
    assert_eq!(at, ClassAt { class: RootClass::DoubleRootOnCircle, bounded: true });
    assert!(r.contains(&q(3, 1), &zero).unwrap());
    assert!(!r.contains(&q(6, 1), &zero).unwrap());
    assert!(r.contains(&q(1, 1), &q(1, 10)).unwrap());
}

/// Gauss–Legendre 2 at Φ = 2√3: a double root at −1 with P = −I, bounded;
/// χ alone stops there.
#[test]
fn gauss_legendre_2_at_its_double_root() {
    let d = poly::derive(&poly::builtin("gauss_legendre_2").unwrap()).unwrap();
    // d·P = [[α, β], [−β, α]] with β = 0 and α = −d where Φ² = 12: P = −I.
    let p = d.transition_matrix();
    let den = d.p_denominator();
    let phi2 = Poly::parse("Phi^2 - 12").unwrap();
    let rem = |e: &Poly| {
        let u = e.to_upoly(Sym::phi()).unwrap();
        u.div_rem(&phi2.to_upoly(Sym::phi()).unwrap()).1
    };
    assert!(rem(&p.row(0)[1]).is_zero() && rem(&p.row(1)[0]).is_zero());
    assert_eq!(rem(&p.row(0)[0]), rem(&-den));
    assert_eq!(rem(&p.row(1)[1]), rem(&-den));
    let full = d.stability(&Params::new()).unwrap();
    assert_eq!(full.stability, Stability::BoundedForAllPhi);
    let point = full
        .critical_points
        .iter()
        .find(|c| c.at.to_string() == "2*sqrt(3)")
        .expect("the double root is a critical point");
    assert_eq!(point.bounded, Some(true));
    let bare = analyze(d.charpoly()).unwrap();
    assert_eq!(bare.undecided_at().unwrap().to_string(), "2*sqrt(3)");
}
