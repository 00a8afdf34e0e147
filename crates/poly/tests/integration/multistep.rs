//! Stability limits of multistep and Runge–Kutta methods on the oscillator,
//! written as `.zm` programs with history reads (the built-ins of
//! `poly::advanced::builtins::COMPARISON_BUILTINS`, `methods/*.zm`), with
//! classical values derived by hand, and against a slow, obvious oracle:
//! Schur's recursive test over Q ("every root strictly inside the unit
//! circle") at rationals just below and above each exact limit.

use poly::advanced::stability::{analyze, Boundary, Stability, StabilityReport};
use poly::{q, Algebraic, Derivation, Poly, Sym, UPoly, Q};

fn derivation(name: &str) -> Derivation {
    poly::derive(&poly::builtin(name).expect("a built-in")).expect("derives")
}

fn report(name: &str) -> StabilityReport {
    analyze(derivation(name).charpoly()).expect("analysis")
}

/// χ at a rational Φ as a polynomial in z.
fn chi_at(chi: &Poly, phi: &Q) -> UPoly {
    chi.subs(Sym::phi(), &Poly::constant(phi.clone())).to_upoly(Sym::z()).unwrap()
}

/// Schur's test: every root strictly inside the unit circle iff |a_0| <
/// |a_n| and the Schur transform (a_n f − a_0 f*)/z passes, recursively.
fn schur_strictly_inside(f: &UPoly) -> bool {
    let mut a: Vec<Q> = f.coeffs().to_vec();
    loop {
        while a.last().is_some_and(|c| *c == Q::default()) {
            a.pop();
        }
        let n = a.len() - 1;
        if n == 0 {
            return true;
        }
        let (a0, an) = (a[0].clone(), a[n].clone());
        if num_traits::Signed::abs(&a0) >= num_traits::Signed::abs(&an) {
            return false;
        }
        a = (0..n).map(|k| &an * &a[k + 1] - &a0 * &a[n - k - 1]).collect();
        // Made monic (its leading coefficient a_n² − a_0² > 0), so the sizes
        // stay linear in the degree rather than doubling at every step.
        let lead = a[n - 1].clone();
        a.iter_mut().for_each(|c| *c /= &lead);
    }
}

/// Rationals just below and just above an algebraic number.
fn around(x: &Algebraic) -> (Q, Q) {
    let (lo, hi) = x.refine(&q(1, 1_000_000)).interval();
    let eps = q(1, 1_000_000);
    (lo - &eps, hi + eps)
}

/// The limit agrees with Schur's test on both sides (strictly inside just
/// below, not just above) and at a small Φ.
#[track_caller]
fn check_limit_against_schur(name: &str, r: &StabilityReport) {
    let chi = derivation(name).charpoly().clone();
    let phi_max = r.phi_max().expect("a limit");
    let (below, above) = around(phi_max);
    assert!(schur_strictly_inside(&chi_at(&chi, &below)), "{name} below {phi_max}");
    assert!(!schur_strictly_inside(&chi_at(&chi, &above)), "{name} above {phi_max}");
    assert!(schur_strictly_inside(&chi_at(&chi, &q(1, 100))), "{name} at 1/100");
}

#[test]
fn adams_bashforth_two_is_unstable_for_every_phi() {
    let r = report("ab2");
    assert_eq!(r.stability, Stability::UnboundedForAllPhi);
    assert!(r.stable_intervals.is_empty());
    let chi = derivation("ab2").charpoly().clone();
    for phi in [q(1, 1000), q(1, 10), q(1, 2), q(2, 1)] {
        assert!(!schur_strictly_inside(&chi_at(&chi, &phi)), "AB2 at {phi}");
    }
}

/// AB3: the limit is 12√11/55 ≈ 0.7236 (a root of 3025 Φ² − 1584).
#[test]
fn adams_bashforth_three() {
    let r = report("ab3");
    let m = r.phi_max().unwrap();
    assert_eq!(m.closed_form().as_deref(), Some("12*sqrt(11)/55"));
    assert!(m.is_root_of(&UPoly::from_ints(&[-1584, 0, 3025])));
    assert_eq!(m.to_decimal(4), "0.7236");
    assert_eq!(r.boundary(), Some(Boundary::ComplexPairLeavesCircle));
    assert_eq!(r.bounded_at_phi_max(), Some(true));
    check_limit_against_schur("ab3", &r);
}

/// AB4: Φ_max = 4√65/75 (a root of 5625 Φ² − 1040).
#[test]
fn adams_bashforth_four() {
    let r = report("ab4");
    let m = r.phi_max().unwrap();
    assert!(m.is_root_of(&UPoly::from_ints(&[-1040, 0, 5625])));
    assert_eq!(m.closed_form().as_deref(), Some("4*sqrt(65)/75"));
    check_limit_against_schur("ab4", &r);
}

/// AB5 and AB6 have no stability interval on the imaginary axis.
#[test]
fn adams_bashforth_five_and_six() {
    for name in ["ab5", "ab6"] {
        let r = report(name);
        assert_eq!(r.stability, Stability::UnboundedForAllPhi, "{name}");
        let chi = derivation(name).charpoly().clone();
        assert!(!schur_strictly_inside(&chi_at(&chi, &q(1, 100))), "{name}");
    }
}

/// Leapfrog y_{n+1} = y_{n−1} + 2Φ f_n: roots on the circle (a
/// self-reciprocal χ, the unit-circle resultant vanishes identically) up to
/// Φ_max = 1, where the pairs meet at ±i: defective, so Φ = 1 is unbounded,
/// also from P.
#[test]
fn leapfrog_limit_is_one() {
    let d = derivation("leapfrog");
    // χ alone: bounded below 1, undecided at 1 (a repeated pair at ±i).
    let r = analyze(d.charpoly()).unwrap();
    match &r.stability {
        Stability::UndecidedAt { at, .. } => assert_eq!(at, &Algebraic::from_rational(q(1, 1))),
        other => panic!("{other:?}"),
    }
    assert_eq!(r.intervals[0].counts.on, 4);
    let rp = d.stability(&poly::Params::new()).unwrap();
    assert_eq!(rp.phi_max().cloned(), Some(Algebraic::from_rational(q(1, 1))));
    assert_eq!(rp.bounded_at_phi_max(), Some(false));
    // Just above 1, a root is outside.
    let chi = d.charpoly();
    assert!(!schur_strictly_inside(&chi_at(chi, &q(1001, 1000))));
}

/// The explicit Nyström methods with three or more steps are unstable for
/// every small Φ > 0 on the imaginary axis.
#[test]
fn nystrom_three_to_six() {
    for name in ["nystrom3", "nystrom4", "nystrom5", "nystrom6"] {
        let r = report(name);
        assert_eq!(r.stability, Stability::UnboundedForAllPhi, "{name}");
        let chi = derivation(name).charpoly().clone();
        assert!(!schur_strictly_inside(&chi_at(&chi, &q(1, 100))), "{name}");
    }
}

/// RK4's limit is 2√2 (|R(iΦ)|² = 1 − Φ⁶/72 + Φ⁸/576), RK3's √3
/// (|R(iΦ)|² = 1 − Φ⁴/12 + Φ⁶/36).
#[test]
fn runge_kutta_limits() {
    let r = report("rk4");
    assert_eq!(r.phi_max().unwrap().closed_form().as_deref(), Some("2*sqrt(2)"));
    check_limit_against_schur("rk4", &r);
    let r = report("rk3");
    assert_eq!(r.phi_max().unwrap().closed_form().as_deref(), Some("sqrt(3)"));
    check_limit_against_schur("rk3", &r);
    let r = report("ssprk104");
    check_limit_against_schur("ssprk104", &r);
}

/// Merson 4(3) at Φ = 2√3: a double root at +1 where P = I exactly. From χ
/// alone the limit is undecided; from P it is bounded.
#[test]
fn merson_limit_is_bounded_from_the_transition_matrix() {
    let d = derivation("merson");
    let r = analyze(d.charpoly()).unwrap();
    let Stability::UndecidedAt { at: m, boundary } = r.stability else {
        panic!("{:?}", r.stability)
    };
    assert_eq!(m.closed_form().as_deref(), Some("2*sqrt(3)"));
    assert_eq!(boundary, Boundary::DoubleRootAtPlusOne);
    let rp = d.stability(&poly::Params::new()).unwrap();
    assert_eq!(rp.phi_max().cloned(), Some(m.clone()));
    assert_eq!(rp.bounded_at_phi_max(), Some(true));
    assert!(rp.from_transition_matrix);
    // The oracle: P − I vanishes at Φ² = 12 (every entry is divisible by
    // Φ² − 12 as a polynomial in Φ).
    let phi = Sym::phi();
    let p = &d.transition_matrix();
    let twelve = UPoly::from_ints(&[-12, 0, 1]);
    for i in 0..p.rows() {
        for (j, e) in p.row(i).iter().enumerate() {
            let mut u = e.to_upoly(phi).unwrap();
            if i == j {
                u = &u - &UPoly::from_ints(&[1]);
            }
            assert!(u.is_zero() || u.div_rem(&twelve).1.is_zero(), "P[{i}][{j}] = {e}");
        }
    }
    check_limit_against_schur("merson", &rp);
}

/// AB7 and AB8 have short intervals again (a pair leaves the circle), each
/// limit checked by Schur's test on both sides.
#[test]
fn adams_bashforth_seven_and_eight() {
    for name in ["ab7", "ab8"] {
        let r = derivation(name).stability(&poly::Params::new()).unwrap();
        assert_eq!(r.boundary(), Some(Boundary::ComplexPairLeavesCircle), "{name}");
        assert_eq!(r.bounded_at_phi_max(), Some(true), "{name}");
        check_limit_against_schur(name, &r);
    }
}

/// Φ_max exactly when its closed form is short, else its degree.
fn exact(x: &Algebraic) -> String {
    match x.closed_form() {
        Some(s) if s.len() <= 40 => s,
        _ => format!("root of degree {}", x.defining_poly().degree().unwrap_or(0)),
    }
}

/// The review table of every multistep and Runge–Kutta built-in: limit
/// (exact and to 10 places), boundary, boundedness there (from P), the
/// class changes and the stable intervals (6 places).
#[test]
fn comparison_builtins_summary() {
    let mut out = String::new();
    for name in poly::advanced::builtins::comparison_builtin_names() {
        let d = derivation(name);
        let r = d.stability(&poly::Params::new()).unwrap();
        out += &format!("{name}: degree {}, {}", r.degree, r.stability.name());
        if let Some(m) = r.phi_max() {
            out += &format!(
                ", Phi_max = {} = {}, {}, bounded there: {}",
                exact(m),
                m.to_decimal(10),
                r.boundary().map_or("-", |b| b.name()),
                r.bounded_at_phi_max().map_or("undecided".to_owned(), |b| b.to_string())
            );
        }
        out += "\n  class changes:";
        for c in &r.class_changes {
            out += &format!(" {}->{} at {};", c.from, c.to, c.at.to_decimal(6));
        }
        out += "\n  stable:";
        for s in &r.stable_intervals {
            out += &format!(
                " {}{}, {}{}",
                if s.lo_closed { "[" } else { "(" },
                s.lo.to_decimal(6),
                s.hi.as_ref().map_or("inf".to_owned(), |h| h.to_decimal(6)),
                if s.hi_closed { "]" } else { ")" }
            );
        }
        out += "\n";
    }
    let mut settings = crate::snapshot::in_dir("poly");
    settings.set_omit_expression(true);
    settings.bind(|| insta::assert_snapshot!("comparison_builtins_summary", out));
}
