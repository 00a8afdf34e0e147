//! Implicit programs and exact constants: every located error of the
//! extension, the two routes on implicit steps, exact arithmetic in the
//! field of the constants, and the known facts of the implicit built-ins.

use std::cmp::Ordering;

use num_traits::One;

use poly::advanced::field::{self, Radical};
use poly::advanced::stability::{analyze, Boundary};
use poly::{ErrorKind, Method, Poly, Sym, Q};

use crate::errors::check;

const HEAD: &str = "method m\nstate v y\nparam D\n";

fn q(n: i64, d: i64) -> Q {
    poly::q(n, d)
}

#[test]
fn an_unknown_needs_exactly_one_equation() {
    check(
        "method m\nstate v y\nunknown k\nv = v - Phi*k\n",
        ErrorKind::Equation,
        3,
        9,
        "unknown `k` has no equation",
    );
    check(
        "method m\nstate v y\nunknown k\nk = -y\nk = v\nv = v + Phi*k\n",
        ErrorKind::Equation,
        5,
        1,
        "a second equation for `k` (the first is on line 4)",
    );
    check(
        &format!("{HEAD}v' = v - Phi*y\nv' = v\n"),
        ErrorKind::Equation,
        5,
        1,
        "a second equation for `v'`",
    );
    // A primed state read without its equation.
    check(&format!("{HEAD}v = v - Phi*y'\n"), ErrorKind::Equation, 4, 13, "`y` has no equation");
}

#[test]
fn a_prime_only_on_state_variables() {
    check(&format!("{HEAD}t = v\nv' = v - Phi*t'\n"), ErrorKind::BadPrime, 5, 14, "a temporary");
    check(&format!("{HEAD}v' = v - D'*y\n"), ErrorKind::BadPrime, 4, 10, "a parameter");
    check(&format!("{HEAD}v' = v - Phi'*y\n"), ErrorKind::BadPrime, 4, 10, "a parameter");
    check(
        &format!("{HEAD}v' = v - Phi*y'@1\ny' = y\n"),
        ErrorKind::BadPrime,
        4,
        14,
        "primes a history read",
    );
    check(
        "method m\nstate v y\nconst c = sqrt(2)\nv' = v - c'*y\n",
        ErrorKind::BadPrime,
        4,
        10,
        "a constant",
    );
    check(
        "method m\nstate v y\nunknown k\nk' = v\nv = v + k\n",
        ErrorKind::BadPrime,
        4,
        1,
        "an unknown",
    );
}

#[test]
fn an_equation_for_an_undeclared_name() {
    check(&format!("{HEAD}q' = v\n"), ErrorKind::Equation, 4, 1, "`q` is not declared");
    // A state variable may be assigned before its equation, never after.
    check(
        &format!("{HEAD}v' = v - Phi*y\nv = v\n"),
        ErrorKind::Equation,
        5,
        1,
        "assigned after its equation",
    );
}

#[test]
fn a_nonlinear_system_is_an_error() {
    check(
        &format!("{HEAD}v' = v - v'*y'\ny' = y + Phi*v\n"),
        ErrorKind::Nonlinear,
        4,
        10,
        "nonlinear term",
    );
    // A declaration may follow assignments, never a use of its name.
    check(
        &format!("{HEAD}v = v + Phi*k\nunknown k\nk = v\n"),
        ErrorKind::Declaration,
        4,
        13,
        "`k` is used before its declaration on line 5",
    );
    check(
        "method m\nstate v y\nunknown k\nk = v/k\nv = v + k\n",
        ErrorKind::BadDivision,
        4,
        7,
        "state-dependent",
    );
}

/// A singular system is located on the first equation, in file order,
/// that depends on the equations above it.
#[test]
fn a_system_singular_for_every_phi_is_an_error() {
    check(
        &format!("{HEAD}v' = v' + y\n"),
        ErrorKind::Singular,
        4,
        1,
        "singular for every Phi: its determinant",
    );
    // Rows (1, −2) and (−1/2, 1): the second equation is −1/2 times the first.
    check(
        "method m\nstate v y\nunknown a b\na = 2*b + v\nb = a/2 + Phi*y\nv = v + a\n",
        ErrorKind::Singular,
        5,
        1,
        "is 0, and this equation is a combination of the equations above it (line 4)",
    );
}

#[test]
fn a_system_singular_at_isolated_phi_is_not_an_error() {
    // v' = v − Φ y', y' = y − Φ v': det A = 1 − Φ², singular at Φ = 1 only.
    let m = Method::parse("s.zm", "method s\nstate v y\nv' = v - Phi*y'\ny' = y - Phi*v'\n")
        .expect("parses");
    let d = poly::derive(&m).expect("derives");
    assert_eq!(*d.p_denominator(), Poly::parse("1 - Phi^2").unwrap());
    let pts = d.singular_points();
    assert_eq!(pts.len(), 1);
    assert_eq!(pts[0].as_rational(), Some(&Q::one()));
}

#[test]
fn constants_must_be_roots_of_positive_integers() {
    let c = |rhs: &str| format!("method m\nstate v y\nconst c = {rhs}\nv = v - c*y\n");
    check(&c("sqrt(0)"), ErrorKind::BadConstant, 3, 16, "not a positive integer");
    check(&c("sqrt(1/2)"), ErrorKind::Syntax, 3, 17, "expected");
    check(&c("sqrt(0.5)"), ErrorKind::BadConstant, 3, 16, "not a positive integer");
    check(&c("exp(2)"), ErrorKind::BadConstant, 3, 11, "expected `sqrt(N)`");
    check(&c("root(1, 5)"), ErrorKind::BadConstant, 3, 16, "root index 1");
    check(&c("sqrt(2, 3)"), ErrorKind::BadConstant, 3, 11, "2 argument(s)");
    check(&c("cbrt(-2)"), ErrorKind::BadConstant, 3, 16, "negative");
    check(
        "method m\nstate v y\nconst c = sqrt(2)\nc = v\nv = v - c*y\n",
        ErrorKind::Declaration,
        4,
        1,
        "is a constant",
    );
}

#[test]
fn division_by_a_constant_expression_is_exact() {
    let m = Method::parse(
        "d.zm",
        "method d\nstate v y\nconst c = cbrt(2)\nv = v - 1/(2 - c)*Phi*y\ny = y + Phi*v\n",
    )
    .expect("parses");
    let theta = &m.assigns()[0]
        .terms
        .iter()
        .find(|(op, _)| op.ne(&poly::advanced::Operand::Start { var: 0, lag: 0 }))
        .unwrap()
        .1;
    // θ·(2 − c) = 1 exactly: −θ·Φ⁻¹ times (2 − c) is −1.
    let c = Poly::sym(field::generator(2, 3));
    let prod = field::reduce(&(theta * &(&Poly::int(2) - &c)));
    assert_eq!(prod, -&Poly::sym(Sym::phi()));
    check(
        "method m\nstate v y\nconst c = sqrt(4)\nv = v - 1/(2 - c)*y\n",
        ErrorKind::BadDivision,
        4,
        11,
        "division by zero",
    );
}

/// Exact field arithmetic against an obvious oracle: x^K − N has the
/// radical as a root, and reduction keeps every exponent below the index.
#[test]
fn radicals_and_their_minimal_polynomials() {
    for (k, n, coeff, parts) in [
        (2, 12, 2, vec![(3, 1, 2)]),
        (2, 8, 2, vec![(2, 1, 2)]),
        (3, 16, 2, vec![(2, 1, 3)]),
        (4, 9, 1, vec![(3, 1, 2)]),
        (6, 64, 2, vec![]),
        (2, 6, 1, vec![(2, 1, 2), (3, 1, 2)]),
    ] {
        let r = Radical::root(k, n);
        assert_eq!(r.coeff, Q::from_integer(coeff.into()), "root({k}, {n})");
        assert_eq!(r.parts, parts, "root({k}, {n})");
        // value^deg is the rational N' of the minimal polynomial x^deg − N'.
        let idx = field::generator_indices([&r]);
        let (deg, nn) = r.minimal_polynomial();
        let v = r.to_poly(&idx);
        assert_eq!(field::reduce(&v.pow(deg)), Poly::constant(nn.clone()));
        // No lower power is rational (the degree is minimal).
        for j in 1..deg {
            assert!(field::reduce(&v.pow(j)).as_constant().is_none(), "root({k}, {n})^{j}");
        }
    }
}

#[test]
fn field_inverse_sign_and_norm() {
    let idx = field::generator_indices([&Radical::root(2, 2), &Radical::root(2, 3)]);
    let s2 = Radical::root(2, 2).to_poly(&idx);
    let s3 = Radical::root(2, 3).to_poly(&idx);
    let x = &(&s2 + &s3) - &Poly::constant(q(3, 1));
    let inv = field::inverse(&x).unwrap();
    assert!(field::reduce(&(&x * &inv)).is_one());
    // √2 + √3 − 3 ≈ 0.146: above 0, below 1/6.
    assert_eq!(field::sign(&x), Ordering::Greater);
    assert_eq!(field::sign(&(&x - &Poly::constant(q(1, 6)))), Ordering::Less);
    // √2 + √3 has minimal polynomial x⁴ − 10x² + 1: its norm is 1.
    let n = field::norm(&(&s2 + &s3));
    assert_eq!(n, Poly::one());
    assert!(field::norm(&Poly::zero()).is_zero());
}

fn chi(name: &str) -> Poly {
    poly::derive(&poly::builtin(name).unwrap()).unwrap().charpoly().clone()
}

/// Both routes run on every implicit built-in (derive refuses to answer when
/// they disagree), and reading the routes separately gives the same χ.
#[test]
fn both_routes_agree_on_every_implicit_builtin() {
    for name in poly::advanced::builtins::IMPLICIT_METHODS {
        let m = poly::builtin(name).unwrap();
        let d = poly::derive(&m).unwrap_or_else(|e| panic!("{e}"));
        let z = poly::advanced::charpoly_z_route(&m).unwrap();
        assert_eq!(&z, d.charpoly(), "{name}");
        // The leading coefficient is det A (1 for the explicit Forest–Ruth).
        assert_eq!(&d.coeffs()[0], d.p_denominator(), "{name}");
    }
}

/// The trapezoidal rule and implicit midpoint: |z|² = c/a = 1 and
/// cos Ψ = −b/(2a) = cos(2·atan(Φ/2)) = (1 − Φ²/4)/(1 + Φ²/4), identically.
#[test]
fn trapezoidal_and_midpoint_stay_on_the_circle() {
    for name in ["trapezoidal", "implicit_midpoint", "newmark_average"] {
        let c = chi(name).coeffs_in(Sym::z());
        assert_eq!(c[0], c[2], "{name}: |z|^2 = 1");
        let t2 = Poly::parse("Phi^2/4").unwrap();
        let lhs = &(-&c[1]) * &(&Poly::one() + &t2);
        let rhs = &(&Poly::int(2) * &c[2]) * &(&Poly::one() - &t2);
        if name == "newmark_average" {
            continue;
        }
        assert_eq!(lhs, rhs, "{name}: Psi = 2 atan(Phi/2)");
        let r = analyze(&chi(name)).unwrap();
        assert!(r.bounded_for_all());
        assert!(r.intervals.iter().all(|i| i.class == poly::RootClass::Harmonic));
    }
}

#[test]
fn backward_euler_and_the_soft_spring_damp() {
    for name in ["backward_euler", "soft_spring", "bdf2", "radau_iia_2", "sdirk2"] {
        let r = analyze(&chi(name)).unwrap();
        assert!(r.bounded_for_all(), "{name}");
        assert!(r.phi_max().is_none(), "{name}");
        assert!(
            r.intervals.iter().all(|i| !matches!(i.class, poly::RootClass::Harmonic)),
            "{name} damps"
        );
        assert_eq!(
            poly::advanced::stability::limit_at_infinity(&chi(name)).unwrap(),
            poly::advanced::stability::LimitAtInfinity::ToZero,
            "{name}"
        );
    }
    for name in ["trapezoidal", "implicit_midpoint", "gauss_legendre_2", "newmark_average"] {
        assert_eq!(
            poly::advanced::stability::limit_at_infinity(&chi(name)).unwrap(),
            poly::advanced::stability::LimitAtInfinity::ToCircle,
            "{name}"
        );
    }
}

#[test]
fn newmark_linear_is_stable_below_two_sqrt_three() {
    let r = front_door("newmark_linear");
    let m = r.phi_max().expect("limited");
    assert!(m.is_root_of(&poly::UPoly::from_ints(&[-12, 0, 1])));
    assert_eq!(m.closed_form().as_deref(), Some("2*sqrt(3)"));
}

/// Gauss–Legendre's stability function is the (2,2) Padé approximant
/// R = P/Q, P(w) = 1 + w/2 + w²/12, Q(w) = P(−w): on the oscillator's
/// eigenvalues w = ±iΦ, χ = (Q(iΦ) z − P(iΦ))(Q(−iΦ) z − P(−iΦ))
/// = |Q|² z² − 2 Re(P·conj Q) z + |P|², with conj Q(iΦ) = P(iΦ).
#[test]
fn gauss_legendre_is_the_two_two_pade_approximant() {
    let re = Poly::parse("1 - Phi^2/12").unwrap();
    let im = Poly::parse("Phi/2").unwrap();
    let mod2 = &(&re * &re) + &(&im * &im);
    let re_p2 = &(&re * &re) - &(&im * &im);
    let z = Poly::sym(Sym::z());
    let expected = &(&(&mod2 * &z.pow(2)) - &(&(&Poly::int(2) * &re_p2) * &z)) + &mod2;
    assert_eq!(chi("gauss_legendre_2"), expected);
}

#[test]
fn forest_ruth_has_an_exact_algebraic_limit() {
    // χ alone leaves the double root at +1 open; P (not a multiple of I
    // there) decides it unbounded.
    let bare = analyze(&chi("forest_ruth")).unwrap();
    assert!(matches!(bare.stability, poly::Stability::UndecidedAt { .. }), "{:?}", bare.stability);
    let r = front_door("forest_ruth");
    assert_eq!(r.bounded_at_phi_max(), Some(false));
    let m = r.phi_max().expect("limited");
    let approx = m.approx(&q(1, 1_000_000));
    assert!(approx > q(15733, 10000) && approx < q(15735, 10000), "{}", m.to_decimal(8));
    // Symplectic: q = 1, the pair stays on the circle until it meets at +1
    // (p = cos Ψ returns to 1), decided from the exact classes either side.
    assert_eq!(r.boundary(), Some(Boundary::DoubleRootAtPlusOne));
    // Its defining polynomial is over Q and has it as a root.
    assert!(m.is_root_of(&m.defining_poly()));
    assert!(r.intervals[0].class == poly::RootClass::Harmonic);
}

#[test]
fn sdirk2_keeps_sqrt_two_and_is_bounded_for_all_phi() {
    let c = chi("sdirk2");
    assert!(c.symbols().contains(&field::generator(2, 2)));
    let r = analyze(&c).unwrap();
    assert!(r.bounded_for_all());
}

/// `derive` lists every read of a value an earlier line already updated.
#[test]
fn gauss_seidel_reads_are_listed() {
    let reads = |name: &str| {
        poly::builtin(name)
            .unwrap()
            .gauss_seidel_reads()
            .iter()
            .map(|r| (r.line, r.name.clone(), r.updated_on))
            .collect::<Vec<_>>()
    };
    // soft_spring: `y = y + Phi*v` (line 10) reads v from line 9.
    assert_eq!(reads("soft_spring"), vec![(10, "v".to_owned(), 9)]);
    // Standard Euler keeps the old v in a temporary: no such read.
    assert_eq!(reads("standard_euler"), vec![]);
    // The trapezoidal rule reads only start values and unknowns.
    assert_eq!(reads("trapezoidal"), vec![]);
}

fn report_of(source: &str) -> poly::advanced::stability::StabilityReport {
    let d = poly::derive_source("test.zm", source).unwrap();
    d.stability(&poly::Params::new()).unwrap()
}

/// At Φ = 2√3 Gauss–Legendre's P is exactly −I: a double root at −1 that is
/// semisimple, so the step stays bounded and the method is bounded for all
/// Φ, although χ alone (a double root on the circle) cannot tell.
#[test]
fn gauss_legendre_is_bounded_through_its_double_root() {
    let src = poly::advanced::builtins::builtin_source("gauss_legendre_2").unwrap();
    let r = report_of(src);
    assert!(r.bounded_for_all(), "{:?}", r.stability);
    assert!(!analyze(&chi("gauss_legendre_2")).unwrap().bounded_for_all());
}

/// Boundedness at a repeated root is decided from P = numerator / det A,
/// never from the numerator alone. False Euler written implicitly, with
/// both equations multiplied through by 1 + Φ², has False Euler's P, and so
/// its defective double root at −1 at Φ = 2 (unbounded there); the
/// numerator (1 + Φ²)·P would look semisimple.
#[test]
fn boundedness_at_a_double_root_reads_p_not_its_numerator() {
    let scaled = "method fe_scaled\nstate v y\n\
                  v' = (1 + Phi^2)*(v - Phi*y) - Phi^2*v'\n\
                  y' = (1 + Phi^2)*(y + Phi*v') - Phi^2*y'\n";
    let d = poly::derive_source("scaled.zm", scaled).unwrap();
    assert!(!d.p_denominator().is_one(), "{}", d.p_denominator());
    let (implicit, explicit) = (
        report_of(scaled),
        report_of(poly::advanced::builtins::builtin_source("false_euler").unwrap()),
    );
    assert_eq!(implicit.phi_max().map(|m| m.to_string()), Some("2".to_owned()));
    assert_eq!(
        implicit.phi_max().map(|m| m.to_string()),
        explicit.phi_max().map(|m| m.to_string())
    );
    assert_eq!(implicit.boundary(), Some(Boundary::DoubleRootAtMinusOne));
    assert_eq!(implicit.bounded_at_phi_max(), explicit.bounded_at_phi_max());
    assert_eq!(implicit.bounded_at_phi_max(), Some(false));
}

/// The stability report of a built-in through the front door.
fn front_door(name: &str) -> poly::StabilityReport {
    poly::derive(&poly::builtin(name).unwrap()).unwrap().stability(&poly::Params::new()).unwrap()
}

/// The equation that makes the system singular, in a few shapes: a sum of
/// the two above it, a row of zeros, rows dependent through Φ, and rows
/// dependent over Q(√2) only.
#[test]
#[rustfmt::skip]
fn a_singular_system_is_located_on_the_equation_that_makes_it_singular() {
    use ErrorKind::Singular;
    const H: &str = "method m\nstate v y\nconst r = sqrt(2)\nunknown a b c\n";
    const USE: &str = "v = v + Phi*(a + b + c)\ny = y + Phi*v\n";
    // Lines 5, 6, 7: the third is the sum of the first two.
    check(&format!("{H}a + b = v\nb + c = y\na + 2*b + c = v + y\n{USE}"), Singular, 7, 1, "a combination of the equations above it (lines 5, 6)");
    // The first equation in file order that depends on those above it,
    // not the first that could be dropped: here the second.
    check(&format!("{H}a + b = v\n2*a + 2*b = y\nc = v\n{USE}"), Singular, 6, 1, "(line 5)");
    // `c = c + v` determines nothing: its row of A is 0.
    check(&format!("{H}a = v\nb = y\nc = c + v\n{USE}"), Singular, 7, 1, "this equation determines no unknown");
    check(&format!("{H}  c = c + v\na = v\nb = y\n{USE}"), Singular, 5, 3, "determines no unknown");
    // Rows (1, Φ, 0) and (Φ, Φ², 0): dependent for every Φ.
    check(&format!("{H}a + Phi*b = v\nPhi*a + Phi^2*b = y\nc = v\n{USE}"), Singular, 6, 1, "(line 5)");
    // Rows (1, r) and (r, 2) with r = √2: dependent over Q(√2), not over Q.
    check(&format!("{H}a + r*b = v\nr*a + 2*b = y\nc = v\n{USE}"), Singular, 6, 1, "(line 5)");
    // The same rows with 3 for 2 are independent.
    assert!(Method::parse("ok.zm", &format!("{H}a + r*b = v\nr*a + 3*b = y\nc = v\n{USE}")).is_ok());
}

/// Random systems of up to four equations, some rows combinations of
/// earlier ones: the error names the first row whose prefix has rank below
/// its length, found here by brute force over every maximal minor (Laplace
/// expansion), the slow oracle of the Gram-determinant search.
mod singular_oracle {
    use super::*;
    use poly::PolyMatrix;
    use proptest::prelude::*;

    /// A coefficient a + b·Φ of a row entry.
    fn entry(a: i64, b: i64) -> Poly {
        Poly::int(a) + &Poly::int(b) * &Poly::sym(Sym::phi())
    }

    /// Rows of n entries; a row is fresh or a combination of earlier rows.
    fn rows() -> impl Strategy<Value = Vec<Vec<Poly>>> {
        (1usize..=4).prop_flat_map(|n| {
            let row = (
                prop::collection::vec((-2i64..=2, -1i64..=1), n),
                0u8..3,
                (0usize..4, 0usize..4, -2i64..=2, -2i64..=2),
            );
            prop::collection::vec(row, n).prop_map(move |spec| {
                let mut out: Vec<Vec<Poly>> = Vec::new();
                for (fresh, kind, (p, q, cp, cq)) in spec {
                    let mut r: Vec<Poly> = if kind == 0 && !out.is_empty() {
                        let (p, q) = (&out[p % out.len()], &out[q % out.len()]);
                        p.iter()
                            .zip(q)
                            .map(|(x, y)| &x.scale(&poly::q(cp, 1)) + &y.scale(&poly::q(cq, 1)))
                            .collect()
                    } else {
                        fresh.iter().map(|&(a, b)| entry(a, b)).collect()
                    };
                    if r.iter().all(Poly::is_zero) {
                        r[0] = Poly::one();
                    }
                    out.push(r);
                }
                out
            })
        })
    }

    /// Whether the rows are linearly dependent: every k×k minor is 0.
    fn dependent(rows: &[Vec<Poly>]) -> bool {
        let (k, n) = (rows.len(), rows[0].len());
        if k > n {
            return true;
        }
        let mut cols: Vec<usize> = (0..k).collect();
        loop {
            let minor = PolyMatrix::from_rows(
                rows.iter().map(|r| cols.iter().map(|&c| r[c].clone()).collect()).collect(),
            );
            if !minor.det_laplace().is_zero() {
                return false;
            }
            // The next k-subset of 0..n in lexicographic order.
            let Some(i) = (0..k).rev().find(|&i| cols[i] < n - k + i) else { return true };
            cols[i] += 1;
            for j in i + 1..k {
                cols[j] = cols[j - 1] + 1;
            }
        }
    }

    /// The program: each row as an equation `Σ (c_j)*k_j = v` (or y).
    fn program(rows: &[Vec<Poly>]) -> String {
        let n = rows[0].len();
        let ks: Vec<String> = (1..=n).map(|j| format!("k{j}")).collect();
        let mut src = format!("method m\nstate v y\nunknown {}\n", ks.join(" "));
        for (i, r) in rows.iter().enumerate() {
            let lhs: Vec<String> = r
                .iter()
                .zip(&ks)
                .filter(|(c, _)| !c.is_zero())
                .map(|(c, k)| format!("({c})*{k}"))
                .collect();
            src += &format!("{} = {}\n", lhs.join(" + "), if i % 2 == 0 { "v" } else { "y" });
        }
        src += &format!("v = v + Phi*({})\ny = y + Phi*v\n", ks.join(" + "));
        src
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        #[test]
        fn the_error_names_the_first_dependent_equation(rows in rows()) {
            let src = program(&rows);
            let expected = (1..=rows.len()).find(|&k| dependent(&rows[..k]));
            match (Method::parse("gen.zm", &src), expected) {
                (Ok(_), None) => {}
                (Err(e), Some(k)) => {
                    prop_assert_eq!(e.kind(), ErrorKind::Singular, "{}\n{}", e, src);
                    // Three header lines, then one equation per row.
                    prop_assert_eq!(e.span().line as usize, 3 + k, "{}\n{}", e, src);
                }
                (got, want) => prop_assert!(false, "{:?} vs first dependent row {:?}\n{}", got.map(|m| m.to_string()), want, src),
            }
        }
    }
}

/// Where the step's system is singular (det A = 0) the step is undefined:
/// its own class, never bounded, and a stability limit even between two
/// bounded intervals (here the trapezoidal rule with a stage k = y + Φk
/// that nothing reads, singular at Φ = 1 only).
#[test]
fn a_singular_step_is_its_own_class_and_ends_stability() {
    let src = "method trap_sing\nstate v y\nunknown k\nk = y + Phi*k\n\
               v' = v - Phi*(y + y')/2\ny' = y + Phi*(v + v')/2\n";
    let d = poly::derive(&poly::Method::parse("s.zm", src).unwrap()).unwrap();
    let one = poly::q(1, 1);
    // The oracle: det A vanishes at Φ = 1, by direct evaluation.
    let at_one = d.p_denominator().subs(poly::Sym::phi(), &poly::Poly::constant(one.clone()));
    assert!(at_one.is_zero(), "det A at 1 is {at_one}");
    let params = poly::Params::new();
    assert_eq!(d.class_at(&params, &one).unwrap().class, poly::RootClass::Singular);
    assert_eq!(d.class_at(&params, &poly::q(1, 2)).unwrap().class, poly::RootClass::Harmonic);
    let r = d.stability(&params).unwrap();
    match &r.stability {
        poly::Stability::Limited { phi_max, bounded_at_phi_max, boundary } => {
            assert_eq!(phi_max.to_string(), "1");
            assert!(!bounded_at_phi_max);
            assert_eq!(*boundary, poly::Boundary::SingularStep);
        }
        other => panic!("{other:?}"),
    }
    assert!(r.class_changes.iter().any(|c| c.at_class == Some(poly::RootClass::Singular)));
}
