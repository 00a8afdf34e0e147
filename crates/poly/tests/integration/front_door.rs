//! The front door answers every built-in, and the bare-χ route never
//! contradicts it: where χ alone cannot decide boundedness (a repeated root
//! on the unit circle), it says so, and everywhere else it agrees with the
//! analysis that has the transition matrix.

use poly::advanced::builtins::all_builtin_names;
use poly::{q, Params, Stability, StabilityReport};

/// The parameters a built-in needs besides Φ, at a value away from any
/// boundary.
fn params_for(d: &poly::Derivation) -> Params {
    let mut p = Params::new();
    for s in d.method().params() {
        if s.name() != "Phi" {
            p.insert(s.name(), q(1, 10));
        }
    }
    p
}

/// Every critical point where χ alone decides agrees with P's verdict;
/// where χ alone does not, P decides.
fn agree(name: &str, bare: &StabilityReport, full: &StabilityReport) {
    assert_eq!(bare.critical_points.len(), full.critical_points.len(), "{name}");
    for (b, f) in bare.critical_points.iter().zip(&full.critical_points) {
        assert_eq!(b.at, f.at, "{name}");
        if let Some(bounded) = b.bounded {
            assert_eq!(Some(bounded), f.bounded, "{name} at {}", b.at);
        }
    }
    assert!(!matches!(full.stability, Stability::UndecidedAt { .. }), "{name}");
    match &bare.stability {
        Stability::UndecidedAt { at, .. } => {
            // Bounded below the undecided point, by both.
            let limit = full.phi_max().is_none_or(|m| m >= at);
            assert!(limit, "{name}: P's limit lies below the undecided point {at}");
        }
        other => assert_eq!(other, &full.stability, "{name}"),
    }
}

#[test]
fn the_bare_analysis_is_never_unbounded_where_p_is_bounded() {
    let mut undecided = Vec::new();
    for name in all_builtin_names() {
        let d = poly::derive(&poly::builtin(name).unwrap()).unwrap();
        let params = params_for(&d);
        let full = d.stability(&params).unwrap();
        let chi = {
            let mut values = std::collections::HashMap::new();
            for (k, v) in params.iter() {
                values.insert(poly::Sym::new(k), v.clone());
            }
            d.charpoly().eval_partial(&values)
        };
        let bare = poly::advanced::stability::analyze(&chi).unwrap();
        agree(name, &bare, &full);
        if matches!(bare.stability, Stability::UndecidedAt { .. }) {
            undecided.push(name);
        }
    }
    // The methods whose limit is a repeated root on the circle: χ alone
    // leaves them open (False Euler's double root at −1 among them).
    assert!(undecided.contains(&"false_euler"), "{undecided:?}");
    assert!(undecided.contains(&"gauss_legendre_2"), "{undecided:?}");
}

/// Gauss–Legendre 2 is stable for every Φ: at Φ = 2√3 both roots of χ meet
/// at −1, but P = −I there, which is bounded. χ alone cannot see that.
#[test]
fn gauss_legendre_2_is_stable_for_every_phi() {
    let d = poly::derive(&poly::builtin("gauss_legendre_2").unwrap()).unwrap();
    let full = d.stability(&Params::new()).unwrap();
    assert_eq!(full.stability, Stability::BoundedForAllPhi);
    let bare = poly::advanced::stability::analyze(d.charpoly()).unwrap();
    match bare.stability {
        Stability::UndecidedAt { at, .. } => assert_eq!(at.to_string(), "2*sqrt(3)"),
        other => panic!("{other:?}"),
    }
}

/// Verlet as 8 substeps per step: P⁸ has an eigenvalue repeated on the
/// circle wherever Φ/8 makes a root a 16th root of unity, but the limit is
/// the single-step one scaled: Φ < 16.
#[test]
fn verlet_as_eight_substeps_is_limited_at_sixteen() {
    let mut src = String::from("method verlet8\nstate v y\n");
    for _ in 0..8 {
        src.push_str("v = v - Phi/8*y\ny = y + Phi/8*v\n");
    }
    let d = poly::derive_source("verlet8.zm", &src).unwrap();
    let full = d.stability(&Params::new()).unwrap();
    assert_eq!(full.phi_max().unwrap().to_string(), "16");
    assert_eq!(full.bounded_at_phi_max(), Some(false));
}

/// A parameter the method does not have, or Φ itself, is refused.
#[test]
fn parameters_the_method_lacks_are_refused() {
    let d = poly::derive(&poly::builtin("false_euler").unwrap()).unwrap();
    let e = d.stability(&Params::new().bind("D", q(1, 2))).unwrap_err();
    assert!(e.to_string().contains("has no parameter D"), "{e}");
    let e = d.stability(&Params::new().bind("Phi", q(1, 2))).unwrap_err();
    assert!(e.to_string().contains("covers every Phi"), "{e}");
    let damped = poly::derive(&poly::builtin("false_euler_damped").unwrap()).unwrap();
    let e = damped.stability(&Params::new()).unwrap_err();
    assert!(e.to_string().contains("still contains the parameter D"), "{e}");
}

/// A step that grows for small Φ and is bounded on [1, 2] (its one root is
/// 1 + Φ − Φ²) is unstable near zero, not "unbounded for every Φ": the
/// headline never contradicts the stable intervals.
#[test]
fn unstable_near_zero_but_bounded_further_out() {
    let d =
        poly::derive_source("late.zm", "method late\nstate y\ny = y + Phi*y - Phi^2*y\n").unwrap();
    let r = d.stability(&Params::new()).unwrap();
    assert_eq!(r.stability, Stability::UnstableNearZero);
    assert_eq!(r.stable_intervals.len(), 1);
    let s = &r.stable_intervals[0];
    assert_eq!((s.lo.to_string(), s.lo_closed), ("1".to_owned(), true));
    assert_eq!((s.hi.as_ref().unwrap().to_string(), s.hi_closed), ("2".to_owned(), true));
    // Standard Euler is unbounded everywhere, and says so.
    let euler = poly::derive(&poly::builtin("standard_euler").unwrap()).unwrap();
    let r = euler.stability(&Params::new()).unwrap();
    assert_eq!(r.stability, Stability::UnboundedForAllPhi);
    assert!(r.stable_intervals.is_empty());
}
