//! Ring laws of `Poly` and the `UPoly` toolkit, on random small inputs.
//!
//! `Poly` equality is structural, so each law below also checks that the
//! representation is canonical: two different computations of the same
//! polynomial must build the same value.

use poly::advanced::Monomial;
use poly::{q, Poly, Sym, UPoly, Q};
use proptest::prelude::*;

use crate::common::{nonzero_q, point, small_poly, small_q, sym};

/// Every coefficient is nonzero and every exponent positive; factors are
/// listed once each, in increasing symbol order.
#[track_caller]
fn check_canonical(p: &Poly) {
    for (m, c) in p.terms() {
        assert!(*c != Q::from_integer(0.into()), "zero coefficient in {p:?}");
        let f: &[(Sym, u32)] = m.factors();
        assert!(f.iter().all(|&(_, e)| e > 0), "zero exponent in {p:?}");
        assert!(f.windows(2).all(|w| w[0].0 < w[1].0), "unsorted monomial in {p:?}");
    }
    let monomials: Vec<&Monomial> = p.terms().map(|(m, _)| m).collect();
    assert!(monomials.windows(2).all(|w| w[0] < w[1]), "unsorted terms in {p:?}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn addition_and_multiplication_commute(a in small_poly(), b in small_poly()) {
        prop_assert_eq!(&a + &b, &b + &a);
        prop_assert_eq!(&a * &b, &b * &a);
        check_canonical(&(&a * &b));
        check_canonical(&(&a + &b));
    }

    #[test]
    fn addition_and_multiplication_associate(
        a in small_poly(), b in small_poly(), c in small_poly()
    ) {
        prop_assert_eq!(&(&a + &b) + &c, &a + &(&b + &c));
        prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
    }

    #[test]
    fn multiplication_distributes(a in small_poly(), b in small_poly(), c in small_poly()) {
        prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
        prop_assert_eq!(&(&a - &b) * &c, &(&a * &c) - &(&b * &c));
    }

    #[test]
    fn identities_and_inverses(a in small_poly(), b in small_poly()) {
        prop_assert_eq!(&a + &Poly::zero(), a.clone());
        prop_assert_eq!(&a * &Poly::one(), a.clone());
        prop_assert!((&a * &Poly::zero()).is_zero());
        prop_assert_eq!(&(&a + &b) - &b, a.clone());
        prop_assert!((&a - &a).is_zero());
        prop_assert_eq!(-(-a.clone()), a.clone());
        prop_assert_eq!(&a + &(-&a), Poly::zero());
    }

    #[test]
    fn scale_is_multiplication_by_a_constant(a in small_poly(), c in small_q()) {
        prop_assert_eq!(a.scale(&c), &a * &Poly::constant(c.clone()));
    }

    #[test]
    fn pow_is_repeated_multiplication(a in small_poly(), n in 0u32..=5) {
        let repeated = (0..n).fold(Poly::one(), |acc, _| &acc * &a);
        prop_assert_eq!(a.pow(n), repeated);
    }

    /// Evaluation at a rational point is a ring homomorphism.
    #[test]
    fn eval_is_a_homomorphism(a in small_poly(), b in small_poly(), at in point()) {
        let ea = a.eval(&at).expect("every symbol has a value");
        let eb = b.eval(&at).expect("every symbol has a value");
        prop_assert_eq!((&a + &b).eval(&at), Some(&ea + &eb));
        prop_assert_eq!((&a * &b).eval(&at), Some(&ea * &eb));
        prop_assert_eq!((&a - &b).eval(&at), Some(&ea - &eb));
    }

    /// Substituting a polynomial for a symbol commutes with the ring
    /// operations and with evaluation.
    #[test]
    fn subs_is_a_homomorphism(
        a in small_poly(), b in small_poly(), v in small_poly(), s in 0usize..3, at in point()
    ) {
        let s = sym(s);
        prop_assert_eq!((&a * &b).subs(s, &v), &a.subs(s, &v) * &b.subs(s, &v));
        prop_assert_eq!((&a + &b).subs(s, &v), &a.subs(s, &v) + &b.subs(s, &v));
        let mut at_v = at.clone();
        at_v.insert(s, v.eval(&at).expect("every symbol has a value"));
        prop_assert_eq!(a.subs(s, &v).eval(&at), a.eval(&at_v));
    }

    #[test]
    fn partial_evaluation_then_evaluation_is_evaluation(a in small_poly(), at in point()) {
        let phi_only = [(Sym::phi(), at[&Sym::phi()].clone())].into_iter().collect();
        let partial = a.eval_partial(&phi_only);
        prop_assert_eq!(partial.degree_in(Sym::phi()), 0);
        prop_assert_eq!(partial.eval(&at), a.eval(&at));
    }

    #[test]
    fn coeffs_in_round_trips(a in small_poly(), s in 0usize..3) {
        let s = sym(s);
        let cs = a.coeffs_in(s);
        prop_assert_eq!(cs.len() as u32, a.degree_in(s) + 1);
        prop_assert!(cs.iter().all(|c| c.degree_in(s) == 0));
        prop_assert_eq!(Poly::from_coeffs_in(s, &cs), a);
    }

    /// The product rule checks `derivative` against multiplication.
    #[test]
    fn derivative_obeys_the_product_rule(a in small_poly(), b in small_poly(), s in 0usize..3) {
        let s = sym(s);
        let lhs = (&a * &b).derivative(s);
        let rhs = &(&a.derivative(s) * &b) + &(&a * &b.derivative(s));
        prop_assert_eq!(lhs, rhs);
    }

    /// The plain-text form parses back to the same polynomial, and the parser
    /// agrees with the arithmetic on compound expressions.
    #[test]
    fn display_parses_back(a in small_poly(), b in small_poly()) {
        let text = a.to_string();
        prop_assert_eq!(Poly::parse(&text).map_err(|e| e.to_string()), Ok(a.clone()), "{}", text);
        let product = format!("({a}) * ({b}) - ({b})^2");
        prop_assert_eq!(
            Poly::parse(&product).map_err(|e| e.to_string()),
            Ok(&(&a * &b) - &b.pow(2))
        );
    }

    #[test]
    fn univariate_view_round_trips(cs in proptest::collection::vec(small_q(), 0..6)) {
        let u = UPoly::new(cs);
        let p = Poly::from_upoly(Sym::phi(), &u);
        prop_assert_eq!(p.to_upoly(Sym::phi()), Some(u.clone()));
        prop_assert_eq!(p.to_upoly(Sym::z()).is_some(), p.degree_in(Sym::phi()) == 0);
    }
}

/// A random dense univariate polynomial of degree below 6.
fn upoly() -> impl Strategy<Value = UPoly> {
    proptest::collection::vec(small_q(), 0..6).prop_map(UPoly::new)
}

/// A random univariate polynomial of degree 1 to 3.
fn nonconstant_upoly() -> impl Strategy<Value = UPoly> {
    (proptest::collection::vec(small_q(), 1..=3), nonzero_q()).prop_map(|(mut cs, lead)| {
        cs.push(lead);
        UPoly::new(cs)
    })
}

#[track_caller]
fn divides(d: &UPoly, p: &UPoly) -> bool {
    p.div_rem(d).1.is_zero()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn upoly_ring_operations_match_evaluation(a in upoly(), b in upoly(), x in small_q()) {
        prop_assert_eq!((&a * &b).eval(&x), a.eval(&x) * b.eval(&x));
        prop_assert_eq!((&a + &b).eval(&x), a.eval(&x) + b.eval(&x));
        prop_assert_eq!((&a - &b).eval(&x), a.eval(&x) - b.eval(&x));
        prop_assert_eq!(a.compose(&b).eval(&x), a.eval(&b.eval(&x)));
        prop_assert_eq!(a.negate_x().eval(&x), a.eval(&-x.clone()));
        prop_assert_eq!(a.shift(2).eval(&x), a.eval(&x) * &x * &x);
        prop_assert_eq!(
            a.derivative(),
            Poly::from_upoly(Sym::phi(), &a).derivative(Sym::phi()).to_upoly(Sym::phi()).expect("univariate")
        );
    }

    /// With a nonzero constant term, reversing keeps the degree n and
    /// computes x^n p(1/x).
    #[test]
    fn reversed_is_x_to_the_n_of_p_of_one_over_x(
        c0 in nonzero_q(), a in nonconstant_upoly(), x in nonzero_q()
    ) {
        let p = &a.shift(1) + &UPoly::constant(c0);
        let n = p.degree().expect("nonzero");
        prop_assert_eq!(p.reversed().degree(), Some(n));
        prop_assert_eq!(p.reversed().eval(&x), num_traits::pow(x.clone(), n) * p.eval(&(q(1, 1) / &x)));
        prop_assert_eq!(p.reversed().reversed(), p);
    }

    #[test]
    fn div_rem_reconstructs(a in upoly(), d in nonconstant_upoly()) {
        let (quot, rem) = a.div_rem(&d);
        prop_assert_eq!(&(&quot * &d) + &rem, a);
        prop_assert!(rem.degree() < d.degree(), "the zero remainder has degree None, below every Some");
    }

    #[test]
    fn gcd_divides_both_and_is_greatest(
        a in nonconstant_upoly(), b in nonconstant_upoly(), c in nonconstant_upoly()
    ) {
        let (ac, bc) = (&a * &c, &b * &c);
        let g = ac.gcd(&bc);
        prop_assert_eq!(g.leading(), q(1, 1));
        prop_assert!(divides(&g, &ac) && divides(&g, &bc));
        // c divides both, hence divides their greatest common divisor.
        prop_assert!(divides(&c, &g));
        prop_assert_eq!(a.gcd(&UPoly::zero()), a.monic());
    }

    /// The square-free part has the same roots, each simple: it divides p, p
    /// divides a power of it, and it shares no factor with its derivative.
    #[test]
    fn squarefree_keeps_roots_and_drops_multiplicity(
        f in nonconstant_upoly(), g in nonconstant_upoly(), k in 1u32..=3
    ) {
        let p = &(0..k).fold(UPoly::constant(q(1, 1)), |acc, _| &acc * &f) * &g;
        let s = p.squarefree();
        prop_assert!(divides(&s, &p));
        let n = p.degree().expect("nonzero");
        let s_n = (0..n).fold(UPoly::constant(q(1, 1)), |acc, _| &acc * &s);
        prop_assert!(divides(&p, &s_n));
        prop_assert_eq!(s.gcd(&s.derivative()).degree(), Some(0));
        prop_assert_eq!(s.leading(), q(1, 1));
        prop_assert!(s.degree() <= f.squarefree().degree().map(|d| d + g.degree().expect("nonzero")));
    }
}

proptest! {
    /// A quadratic's square-free part, read from b² = 4ac, is the gcd
    /// route's (the oracle): p / gcd(p, p′), monic; squares k·(s·x − r)²
    /// and random quadratics alike.
    #[test]
    fn squarefree_of_a_quadratic_is_the_gcd_route(
        (r, s, k) in (-20i64..21, 1i64..9, (-5i64..6).prop_filter("k ≠ 0", |k| *k != 0)),
        (a, b, c) in ((-9i64..10).prop_filter("a ≠ 0", |a| *a != 0), -9i64..10, -9i64..10),
        square in any::<bool>(),
    ) {
        let p = if square {
            let l = UPoly::new(vec![q(-r, 1), q(s, 1)]);
            (&l * &l).scale(&q(k, 3))
        } else {
            UPoly::from_ints(&[c, b, a])
        };
        let g = p.gcd(&p.derivative());
        prop_assert_eq!(p.squarefree(), p.div_rem(&g).0.monic());
    }
}

/// A hand-worked case: (x - 1)^2 (x + 2) has square-free part (x - 1)(x + 2).
#[test]
fn squarefree_of_a_known_cube() {
    let p = UPoly::from_ints(&[2, -3, 0, 1]);
    assert_eq!(p.squarefree(), UPoly::from_ints(&[-2, 1, 1]));
    assert_eq!(p.gcd(&p.derivative()), UPoly::from_ints(&[-1, 1]));
    assert_eq!(p.to_string_in("Phi"), "Phi^3 - 3*Phi + 2");
}
