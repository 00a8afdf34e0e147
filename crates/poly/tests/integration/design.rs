//! The exact optimiser (issue 37): the known optima, each checked
//! independently first (SymPy, and by hand in the comments), the engine's
//! value at rational points against the front door (the slow oracles:
//! `Derivation::plane`, `Derivation::stability`, `order::ssp_coefficient`),
//! and bisection on rational parameters near each optimum.

use poly::advanced::design::{
    maximize, objective_at, Design, FreeParam, Objective, ParamTableau, Problem, Score, Subject,
};
use poly::{q, Derivation, Params, Q};

fn derive(src: &str) -> Derivation {
    poly::derive_source("design.zm", src).unwrap()
}

fn problem<'a>(d: &'a Derivation, objective: Objective, free: Vec<FreeParam>) -> Problem<'a> {
    Problem { subject: Subject::Program(d), objective, free, bound: Params::new(), min_order: None }
}

/// The design of `p`. Its speed (1 s for one parameter, 10 s for two, in
/// release) is a criterion figure, never a test's: a test that reads the
/// clock fails on a loaded machine.
fn solve(p: &Problem) -> Design {
    maximize(p).unwrap()
}

fn finite(s: &Score) -> String {
    s.to_string()
}

/// Every rational grid value never exceeds the optimum (asserted inside
/// `maximize` too), and the points around the maximiser, on a finer
/// bisection toward it, stay below.
fn bisect_around(p: &Problem, name: &str, at: &Q, lo: &Q, hi: &Q, optimum: &Score) {
    let mut h = q(1, 16);
    for _ in 0..12 {
        for x in [at - &h, at + &h] {
            if &x >= lo && &x <= hi {
                let v = objective_at(p, &[(name, x.clone())]).unwrap();
                assert!(&v <= optimum, "{name} = {x}: {v} > {optimum}");
            }
        }
        h = &h / Q::from_integer(3.into());
    }
}

const CHEB: &str = "method cheb\nparam a2\nstate y\ny = y + w*y + a2*w^2*y\n";

/// Chebyshev's 2s² for s = 2: R = 1 + w + a₂w², best real limit 8 at a₂ =
/// 1/8 (R(−x) = 1 − x + x²/8: R = 1 at x = 8, and R = −1 only touched at
/// x = 4, a tangency).
#[test]
fn chebyshev_two_stages() {
    let d = derive(CHEB);
    let p = problem(&d, Objective::RealLimit, vec![FreeParam::new("a2", q(0, 1), q(1, 2))]);
    let r = solve(&p);
    assert_eq!(finite(&r.optimum), "8", "{:#?}", r.certificate);
    assert!(r.attained);
    assert_eq!(r.at[0].1.to_string(), "1/8");
    assert!(r.grid_check.points >= 200 && r.grid_check.max <= r.optimum);
    bisect_around(&p, "a2", &q(1, 8), &q(0, 1), &q(1, 2), &r.optimum);
}

/// The engine's value at rational points equals `Derivation::plane`'s.
#[test]
fn engine_matches_plane_at_rational_points() {
    let d = derive(CHEB);
    for obj in [Objective::RealLimit, Objective::ImagLimit] {
        let p = problem(&d, obj, vec![FreeParam::new("a2", q(0, 1), q(1, 2))]);
        for k in 0..=20 {
            let a = q(k, 40);
            let mine = objective_at(&p, &[("a2", a.clone())]).unwrap();
            let plane = d.plane(&Params::new().bind("a2", a.clone())).unwrap();
            let limit =
                if obj == Objective::RealLimit { plane.real_limit } else { plane.imag_limit };
            let theirs = limit.map_or(Score::Infinite, Score::Finite);
            assert_eq!(mine, theirs, "{obj} at a2 = {a}");
        }
    }
}

const KG: &str = "method kg\nparam a3\nstate y\ny = y + w*y + 1/2*w^2*y + a3*w^3*y\n";

/// Kinnmark–Gray: |R(iy)|² = 1 + (1/4 − 2a₃)y⁴ + a₃²y⁶; the imaginary limit
/// is √((2a₃ − 1/4)/a₃²)... for a₃ < 1/8 it is 0... best 2 at a₃ = 1/4
/// (|R|² − 1 = y⁴(y² − 4)/16). With order ≥ 3 only a₃ = 1/6: √3.
#[test]
fn kinnmark_gray() {
    let d = derive(KG);
    let p = problem(&d, Objective::ImagLimit, vec![FreeParam::new("a3", q(0, 1), q(1, 2))]);
    let r = solve(&p);
    assert_eq!(finite(&r.optimum), "2", "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.to_string(), "1/4");
    bisect_around(&p, "a3", &q(1, 4), &q(0, 1), &q(1, 2), &r.optimum);
    let mut p3 = p.clone();
    p3.min_order = Some(3);
    let r = solve(&p3);
    assert_eq!(finite(&r.optimum), "sqrt(3)", "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.to_string(), "1/6");
}

const THETA: &str = "method theta\nparam theta\nstate y\ny' = y + w*((1 - theta)*y + theta*y')\n";

/// The θ-method R = (1 + (1 − θ)w)/(1 − θw): the real limit is 2/(1 − 2θ)
/// below θ = 1/2 and +∞ from there.
#[test]
fn theta_method() {
    let d = derive(THETA);
    let p = problem(&d, Objective::RealLimit, vec![FreeParam::new("theta", q(0, 1), q(2, 5))]);
    let r = solve(&p);
    assert_eq!(finite(&r.optimum), "10", "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.to_string(), "2/5");
    let p = problem(&d, Objective::RealLimit, vec![FreeParam::new("theta", q(0, 1), q(1, 2))]);
    let r = solve(&p);
    assert_eq!(r.optimum, Score::Infinite, "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.to_string(), "1/2");
    assert!(r.attained);
}

const NEWMARK: &str = "method newmark\nparam beta\nparam gamma\nstate v y\n\
    y' = y + Phi*v + Phi^2*((1/2 - beta)*(-y) + beta*(-y'))\n\
    v' = v + Phi*((1 - gamma)*(-y) + gamma*(-y'))\n";

/// Newmark with γ = 1/2: Φ_max = 2/√(1 − 4β) (χ(−1) = 4 + (4β − 1)Φ²), so
/// 2√5 at β = 1/5.
#[test]
fn newmark_phi_max() {
    let d = derive(NEWMARK);
    let mut p = problem(&d, Objective::PhiMax, vec![FreeParam::new("beta", q(0, 1), q(1, 5))]);
    p.bound = Params::new().bind("gamma", q(1, 2));
    let r = solve(&p);
    assert_eq!(finite(&r.optimum), "2*sqrt(5)", "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.to_string(), "1/5");
    assert!(r.attained);
    // The oracle: the front door at rational β.
    for k in 0..=10 {
        let b = q(k, 50);
        let mine = objective_at(&p, &[("beta", b.clone())]).unwrap();
        let s = d.stability(&Params::new().bind("gamma", q(1, 2)).bind("beta", b.clone())).unwrap();
        assert_eq!(mine.finite(), s.phi_max(), "beta = {b}");
    }
}

fn heun_family() -> ParamTableau {
    ParamTableau::new("rk2", &["c"], &[vec!["0", "0"], vec!["c", "0"]], &["1 - 1/(2*c)", "1/(2*c)"])
        .unwrap()
}

/// The explicit 2-stage order-2 family: SSP coefficient min(2 − 1/c, 1/c)
/// for c ≥ 1/2 (0 below, where b₁ < 0): 1 at c = 1 (Heun).
#[test]
fn two_stage_ssp() {
    let t = heun_family();
    let p = Problem {
        subject: Subject::Tableau(&t),
        objective: Objective::SspCoefficient,
        free: vec![FreeParam::new("c", q(1, 4), q(2, 1))],
        bound: Params::new(),
        min_order: None,
    };
    let r = solve(&p);
    assert_eq!(finite(&r.optimum), "1", "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.to_string(), "1");
    bisect_around(&p, "c", &q(1, 1), &q(1, 4), &q(2, 1), &r.optimum);
    // The oracle: order::ssp_coefficient on the tableau at rational c.
    for k in 1..=16 {
        let c = q(k, 8);
        let mine = objective_at(&p, &[("c", c.clone())]).unwrap();
        let tab = t.at(&[(poly::Sym::new("c"), c.clone())]).unwrap();
        let theirs = match poly::advanced::order::ssp_coefficient(&tab).unwrap() {
            poly::advanced::order::Ssp::Radius(r) => Score::Finite(r),
            poly::advanced::order::Ssp::Unbounded => Score::Infinite,
        };
        assert_eq!(mine, theirs, "c = {c}");
    }
}

/// Bad input gets a clean error.
#[test]
fn bad_input() {
    let d = derive(CHEB);
    let p = problem(&d, Objective::RealLimit, vec![FreeParam::new("a2", q(1, 1), q(0, 1))]);
    assert!(maximize(&p).unwrap_err().to_string().contains("empty"));
    let p = problem(&d, Objective::RealLimit, vec![FreeParam::new("b", q(0, 1), q(1, 1))]);
    assert!(maximize(&p).unwrap_err().to_string().contains("no parameter b"));
    let p = problem(&d, Objective::SspCoefficient, vec![FreeParam::new("a2", q(0, 1), q(1, 1))]);
    assert!(maximize(&p).unwrap_err().to_string().contains("tableau"));
    assert!(Objective::parse("speed").is_err());
}

/// The certificate names the optimum, the equation it solves and the
/// conditions on each side.
#[test]
fn certificate_reads() {
    let d = derive(CHEB);
    let p = problem(&d, Objective::RealLimit, vec![FreeParam::new("a2", q(0, 1), q(1, 2))]);
    let r = maximize(&p).unwrap();
    let text = r.certificate.join("\n");
    println!("{text}");
    assert!(text.contains("optimum 8 at a2 = 1/8, attained"), "{text}");
    assert!(text.contains("just below") && text.contains("just above"), "{text}");
    assert!(text.contains("R = -1") && text.contains("R = 1"), "{text}");
    let d = derive(NEWMARK);
    let mut p = problem(&d, Objective::PhiMax, vec![FreeParam::new("beta", q(0, 1), q(1, 2))]);
    p.bound = Params::new().bind("gamma", q(1, 2));
    let r = maximize(&p).unwrap();
    println!("{}", r.certificate.join("\n"));
    assert_eq!(r.optimum, Score::Infinite);
    assert_eq!(r.at[0].1.to_string(), "1/4");
}

const CUBIC: &str =
    "method cubic\nparam a2\nparam a3\nstate y\ny = y + w*y + a2*w^2*y + a3*w^3*y\n";

/// Two parameters: 1 + w + a₂w² + a₃w³ over [0, 1/2] × [0, 1/6], order ≥ 1:
/// 18 at (4/27, 4/729), the shifted Chebyshev T₃(1 + w/9), whose interior
/// points with |R| = 1 (x = 9/2 and 27/2) are tangencies, not exits. The
/// grid's best is below (no grid point hits the isolated optimum).
#[test]
fn shifted_chebyshev_two_parameters() {
    let d = derive(CUBIC);
    let mut p = problem(
        &d,
        Objective::RealLimit,
        vec![FreeParam::new("a2", q(0, 1), q(1, 2)), FreeParam::new("a3", q(0, 1), q(1, 6))],
    );
    p.min_order = Some(1);
    let r = solve(&p);
    println!("{}", r.certificate.join("\n"));
    assert_eq!(finite(&r.optimum), "18", "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.to_string(), "4/27");
    assert_eq!(r.at[1].1.to_string(), "4/729");
    assert_eq!(r.grid_check.points, 2500);
    assert!(r.grid_check.max < r.optimum);
    // The tangencies: R(−x) = −1 touched at 9/2, +1 at 27/2, exit at 18.
    let at = |x: Q| {
        let (a2, a3) = (q(4, 27), q(4, 729));
        Q::from_integer(1.into()) - &x + &a2 * &x * &x - &a3 * &x * &x * &x
    };
    assert_eq!(at(q(9, 2)), q(-1, 1));
    assert_eq!(at(q(27, 2)), q(1, 1));
    assert_eq!(at(q(18, 1)), q(-1, 1));
    // Bisection-style oracle: rational points near the optimum stay below.
    for k in 1..6 {
        let h = Q::new(1.into(), num_bigint::BigInt::from(10u64.pow(k)));
        for (da, db) in [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1)] {
            let a2 = q(4, 27) + &h * Q::from_integer(da.into());
            let a3 = q(4, 729) + &h * Q::from_integer(db.into()) / Q::from_integer(100.into());
            let v = objective_at(&p, &[("a2", a2.clone()), ("a3", a3.clone())]).unwrap();
            assert!(v <= r.optimum, "({a2}, {a3}): {v}");
        }
    }
}

/// Bound values enter a tableau's entries: the 2-stage family written in
/// c·d with d bound to 1 designs as the family written in c alone (the
/// oracle), for the SSP coefficient (1 at c = 1) and the real limit (2).
#[test]
fn bound_values_enter_a_tableau() {
    let two = ParamTableau::new(
        "rk2cd",
        &["c", "d"],
        &[vec!["0", "0"], vec!["c*d", "0"]],
        &["1 - 1/(2*c*d)", "1/(2*c*d)"],
    )
    .unwrap();
    let one = ParamTableau::new(
        "rk2",
        &["c"],
        &[vec!["0", "0"], vec!["c", "0"]],
        &["1 - 1/(2*c)", "1/(2*c)"],
    )
    .unwrap();
    for objective in [Objective::SspCoefficient, Objective::RealLimit] {
        let free = vec![FreeParam::new("c", q(1, 4), q(2, 1))];
        let bound = Problem {
            subject: Subject::Tableau(&two),
            objective,
            free: free.clone(),
            bound: Params::new().bind("d", q(1, 1)),
            min_order: None,
        };
        let plain = Problem {
            subject: Subject::Tableau(&one),
            objective,
            free,
            bound: Params::new(),
            min_order: None,
        };
        let (a, b) = (maximize(&bound).unwrap(), maximize(&plain).unwrap());
        assert_eq!(a.optimum, b.optimum, "{objective}");
        assert_eq!(a.at, b.at, "{objective}");
        let at = [("c", q(3, 2))];
        assert_eq!(objective_at(&bound, &at).unwrap(), objective_at(&plain, &at).unwrap());
    }
    let d = maximize(&Problem {
        subject: Subject::Tableau(&one),
        objective: Objective::SspCoefficient,
        free: vec![FreeParam::new("c", q(1, 4), q(2, 1))],
        bound: Params::new(),
        min_order: None,
    })
    .unwrap();
    assert_eq!(d.optimum.to_string(), "1");
}

/// The optimum's value as an algebraic number, with its defining
/// polynomial in x (for a finite optimum).
fn defining(s: &Score) -> String {
    s.finite().expect("a finite optimum").defining_poly().to_string_in("x")
}

fn two_free<'a>(d: &'a Derivation, a: (&str, Q, Q), b: (&str, Q, Q), order: usize) -> Problem<'a> {
    let mut p = problem(
        d,
        Objective::RealLimit,
        vec![FreeParam::new(a.0, a.1, a.2), FreeParam::new(b.0, b.1, b.2)],
    );
    p.min_order = Some(order);
    p
}

/// Two free coefficients, order ≥ 3: R − e^w = O(w⁴) forces a₂ = 1/2 and
/// a₃ = 1/6, one point, where R(−x) = 1 − x + x²/2 − x³/6 never exceeds 1
/// (x(x² − 3x + 6) > 0) and reaches −1 at the real root of
/// x³ − 3x² + 6x − 12 (≈ 2.512745; SymPy's nroots, and a float scan). The
/// grid is that point.
#[test]
fn min_order_cuts_two_parameters_to_a_point() {
    let d = derive(CUBIC);
    let p = two_free(&d, ("a2", q(0, 1), q(1, 2)), ("a3", q(0, 1), q(1, 6)), 3);
    let r = solve(&p);
    assert_eq!(defining(&r.optimum), "x^3 - 3*x^2 + 6*x - 12", "{:#?}", r.certificate);
    let x = r.optimum.finite().unwrap();
    assert!(x.cmp_rational(&q(2512, 1000)).is_gt() && x.cmp_rational(&q(2513, 1000)).is_lt());
    assert_eq!((r.at[0].1.to_string(), r.at[1].1.to_string()), ("1/2".into(), "1/6".into()));
    assert!(r.attained);
    assert_eq!((r.grid_check.points, &r.grid_check.max), (1, &r.optimum));
    // The oracle: the engine at that rational point, with no order asked.
    let mut free = p.clone();
    free.min_order = None;
    assert_eq!(objective_at(&free, &[("a2", q(1, 2)), ("a3", q(1, 6))]).unwrap(), r.optimum);
    // A box that misses the point: no allowed point, a clean error.
    let p = two_free(&d, ("a2", q(0, 1), q(1, 4)), ("a3", q(0, 1), q(1, 6)), 3);
    assert!(maximize(&p).unwrap_err().to_string().contains("no (a2, a3) in the box has order 3"));
}

/// Order ≥ 2 forces only a₂ = 1/2: the line a₂ = 1/2, searched along a₃.
/// By hand: R(−x) − 1 = −x(1 − x/2 + a₃x²) has a double root (x = 4) at
/// a₃ = 1/16, where the exit moves on to R = −1, the real root of
/// x³ − 8x² + 16x − 32 (≈ 6.260791; below 1/16 R exceeds 1 before x = 4,
/// above it the exit at R = −1 comes earlier; a float scan agrees). The
/// oracle: the one-parameter problem with a₂ bound to 1/2.
#[test]
fn min_order_cuts_two_parameters_to_a_line() {
    let d = derive(CUBIC);
    let p = two_free(&d, ("a2", q(0, 1), q(1, 2)), ("a3", q(0, 1), q(1, 6)), 2);
    let r = solve(&p);
    assert_eq!(defining(&r.optimum), "x^3 - 8*x^2 + 16*x - 32", "{:#?}", r.certificate);
    assert_eq!((r.at[0].1.to_string(), r.at[1].1.to_string()), ("1/2".into(), "1/16".into()));
    assert!(r.grid_check.points >= 200 && r.grid_check.max <= r.optimum);
    let text = r.certificate.join("\n");
    assert!(text.contains("on the line a2 = 1/2 with a3 in [0, 1/6]"), "{text}");
    let mut bound = problem(&d, Objective::RealLimit, vec![FreeParam::new("a3", q(0, 1), q(1, 6))]);
    bound.bound = Params::new().bind("a2", q(1, 2));
    let b = solve(&bound);
    assert_eq!((&b.optimum, b.at[0].1.to_string()), (&r.optimum, "1/16".into()));
    bisect_around(&bound, "a3", &q(1, 16), &q(0, 1), &q(1, 6), &r.optimum);
}

/// A slanted line: R = 1 + (a + b)w + (b/2)w², order ≥ 1 asks a + b = 1,
/// so b = 1 − a and R = 1 + w + ((1 − a)/2)w², Chebyshev's family: 8
/// where (1 − a)/2 = 1/8, at (a, b) = (3/4, 1/4). The box b ≤ 1/2 cuts the
/// line to a ∈ [1/2, 1].
#[test]
fn min_order_on_a_slanted_line() {
    let d =
        derive("method slant\nparam a\nparam b\nstate y\ny = y + (a + b)*w*y + (1/2)*b*w^2*y\n");
    let p = two_free(&d, ("a", q(0, 1), q(1, 1)), ("b", q(0, 1), q(1, 2)), 1);
    let r = solve(&p);
    assert_eq!(finite(&r.optimum), "8", "{:#?}", r.certificate);
    assert_eq!((r.at[0].1.to_string(), r.at[1].1.to_string()), ("3/4".into(), "1/4".into()));
    let text = r.certificate.join("\n");
    assert!(text.contains("b = 1 - a with a in [1/2, 1]"), "{text}");
    assert_eq!(r.grid_check.points, 201);
    assert!(r.grid_check.at.iter().all(|(_, v)| v.is_rational()));
    // Every grid point is on the line.
    let sum = r.grid_check.at.iter().map(|(_, v)| v.as_rational().unwrap().clone());
    assert_eq!(sum.fold(q(0, 1), |s, v| s + v), q(1, 1));
}

/// An order condition that is not affine: on the line a₂ = 1/2 order 3
/// asks b² = 1/6, so the allowed set is the point (1/2, 1/√6), irrational,
/// where R is the same cubic as above: the real root of x³ − 3x² + 6x − 12.
/// The grid is that point, evaluated exactly.
#[test]
fn min_order_line_with_an_irrational_point() {
    let d = derive("method sq\nparam a2\nparam b\nstate y\ny = y + w*y + a2*w^2*y + b^2*w^3*y\n");
    let p = two_free(&d, ("a2", q(0, 1), q(1, 1)), ("b", q(0, 1), q(1, 1)), 3);
    let r = solve(&p);
    assert_eq!(defining(&r.optimum), "x^3 - 3*x^2 + 6*x - 12", "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.to_string(), "1/2");
    let b = &r.at[1].1;
    assert!(!b.is_rational() && b.is_root_of(&poly::UPoly::new(vec![q(-1, 1), q(0, 1), q(6, 1)])));
    assert!(b.sign().is_gt());
    assert_eq!((r.grid_check.points, &r.grid_check.max), (1, &r.optimum));
}

/// One parameter whose allowed points are irrational: R = 1 + w + a²w²
/// has order 2 at a = ±1/√2, both with R = 1 + w + w²/2 (real limit 2).
/// The grid is those two points, evaluated exactly (never empty).
#[test]
fn min_order_grid_at_irrational_points() {
    let d = derive("method half\nparam a\nstate y\ny = y + w*y + a^2*w^2*y\n");
    let mut p = problem(&d, Objective::RealLimit, vec![FreeParam::new("a", q(-1, 1), q(1, 1))]);
    p.min_order = Some(2);
    let r = solve(&p);
    assert_eq!(finite(&r.optimum), "2", "{:#?}", r.certificate);
    assert_eq!(r.at[0].1.closed_form().as_deref(), Some("-sqrt(2)/2"));
    assert_eq!(r.grid_check.points, 2);
    assert_eq!(r.grid_check.max, r.optimum);
    assert_eq!(r.grid_check.at[0].1, r.at[0].1);
}

/// A tableau's classical conditions, affine in its weights b₁, b₂ (A =
/// [[0, 0], [1, 0]]): order 2 asks b₁ + b₂ = 1 and b₂ = 1/2, Heun's
/// method, whose SSP coefficient is 1 (the oracle: order::ssp_coefficient
/// at that point). Order 1 leaves the line b₂ = 1 − b₁, R = 1 + w +
/// (1 − b₁)w²; on the oscillator |R(iΦ)|² = 1 + (1 − 2β)Φ² + β²Φ⁴ with
/// β = 1 − b₁, so Φ_max = √(2β − 1)/β for β > 1/2, largest (1) at β = 1.
/// With A's entry c and b = (1 − d, d) order 2 asks c·d = 1/2, not
/// affine: a clean error.
#[test]
fn min_order_on_a_tableau_with_two_parameters() {
    let t =
        ParamTableau::new("rk2b", &["b1", "b2"], &[vec!["0", "0"], vec!["1", "0"]], &["b1", "b2"])
            .unwrap();
    let box2 = vec![FreeParam::new("b1", q(0, 1), q(1, 1)), FreeParam::new("b2", q(0, 1), q(1, 1))];
    let mut p = Problem {
        subject: Subject::Tableau(&t),
        objective: Objective::SspCoefficient,
        free: box2,
        bound: Params::new(),
        min_order: Some(2),
    };
    let r = solve(&p);
    assert_eq!((r.at[0].1.to_string(), r.at[1].1.to_string()), ("1/2".into(), "1/2".into()));
    let heun = t.at(&[(poly::Sym::new("b1"), q(1, 2)), (poly::Sym::new("b2"), q(1, 2))]).unwrap();
    match poly::advanced::order::ssp_coefficient(&heun).unwrap() {
        poly::advanced::order::Ssp::Radius(c) => assert_eq!(r.optimum, Score::Finite(c)),
        other => panic!("{other:?}"),
    }
    assert_eq!(finite(&r.optimum), "1");
    p.objective = Objective::PhiMax;
    p.min_order = Some(1);
    let r = solve(&p);
    assert_eq!(finite(&r.optimum), "1", "{:#?}", r.certificate);
    assert_eq!((r.at[0].1.to_string(), r.at[1].1.to_string()), ("0".into(), "1".into()));
    assert!(r.attained && r.grid_check.points >= 200);
    // β = 2/3 (b₁ = 1/3): √(1/3)/(2/3) = √3/2, the engine at that point.
    let mut free = p.clone();
    free.min_order = None;
    let v = objective_at(&free, &[("b1", q(1, 3)), ("b2", q(2, 3))]).unwrap();
    assert_eq!(finite(&v), "sqrt(3)/2");
    let cd =
        ParamTableau::new("rk2cd", &["c", "d"], &[vec!["0", "0"], vec!["c", "0"]], &["1 - d", "d"])
            .unwrap();
    let p = Problem {
        subject: Subject::Tableau(&cd),
        objective: Objective::SspCoefficient,
        free: vec![FreeParam::new("c", q(0, 1), q(1, 1)), FreeParam::new("d", q(0, 1), q(1, 1))],
        bound: Params::new(),
        min_order: Some(2),
    };
    let e = maximize(&p).unwrap_err().to_string();
    assert!(e.contains("no order condition is affine in (c, d)"), "{e}");
}

fn two_phi<'a>(d: &'a Derivation, a: (&str, Q, Q), b: (&str, Q, Q)) -> Problem<'a> {
    problem(
        d,
        Objective::PhiMax,
        vec![FreeParam::new(a.0, a.1, a.2), FreeParam::new(b.0, b.1, b.2)],
    )
}

/// Φ_max over a box of Newmark's β and γ, through the disk bound. By hand
/// (Hughes, ch. 9, undamped): Φ_max = 1/√(γ/2 − β) for 2β < γ, γ ≥ 1/2,
/// and every Φ is stable for 2β ≥ γ ≥ 1/2. So over [0, 1/5] × [1/2, 3/5]
/// the least γ/2 − β is 1/20 at (1/5, 1/2): 2√5; over [0, 1/10] ×
/// [3/5, 1] it is 1/5 at (1/10, 3/5): √5; over [0, 1/2] × [1/2, 1] +inf,
/// whose maximisers' least point is (1/4, 1/2).
#[test]
fn phi_max_over_a_box_of_newmark() {
    let d = derive(NEWMARK);
    for (b, g, optimum, at) in [
        ((q(0, 1), q(1, 5)), (q(1, 2), q(3, 5)), "2*sqrt(5)", ("1/5", "1/2")),
        ((q(0, 1), q(1, 10)), (q(3, 5), q(1, 1)), "sqrt(5)", ("1/10", "3/5")),
        ((q(0, 1), q(1, 2)), (q(1, 2), q(1, 1)), "inf", ("1/4", "1/2")),
    ] {
        let p = two_phi(&d, ("beta", b.0.clone(), b.1.clone()), ("gamma", g.0, g.1));
        let r = solve(&p);
        assert_eq!(finite(&r.optimum), optimum, "{:#?}", r.certificate);
        assert!(r.attained);
        assert_eq!((r.at[0].1.to_string(), r.at[1].1.to_string()), (at.0.into(), at.1.into()));
        assert_eq!(r.grid_check.points, 2500);
        assert!(r.grid_check.max <= r.optimum);
        let text = r.certificate.join("\n");
        assert!(
            text.contains("disk bound") && text.contains("the stability engine gives phi_max"),
            "{text}"
        );
        // The engine at the optimum, and on a finer bisection toward it
        // along each coordinate, never above.
        let at_q = (q_of(at.0), q_of(at.1));
        let v = objective_at(&p, &[("beta", at_q.0.clone()), ("gamma", at_q.1.clone())]).unwrap();
        assert_eq!(v, r.optimum);
        let mut h = q(1, 64);
        for _ in 0..6 {
            for (x, y) in [(&at_q.0 - &h, at_q.1.clone()), (at_q.0.clone(), &at_q.1 + &h)] {
                if x >= b.0 && x <= b.1 {
                    let v = objective_at(&p, &[("beta", x.clone()), ("gamma", y.clone())]).unwrap();
                    assert!(v <= r.optimum, "({x}, {y}): {v}");
                }
            }
            h = &h / Q::from_integer(4.into());
        }
    }
}

fn q_of(s: &str) -> Q {
    s.parse().unwrap()
}

/// A tableau's Φ_max is its imaginary-axis limit (R(±iΦ) are χ's roots,
/// and R(ΦJ) is normal): the disk search on the tableau R = 1 + a₁w +
/// a₂w² (A = [[0,0],[1,0]], b = [a₁ − a₂, a₂]) agrees with the sign
/// search of imag_limit on the same R as a program. By hand: |R(iy)|² =
/// 1 + (a₁² − 2a₂)y² + a₂²y⁴, so y² ≤ (2a₂ − a₁²)/a₂², at most 1/a₁²
/// (at a₂ = a₁²): 2 at (1/2, 1/4) over [1/2, 1] × [1/4, 1]; with a₂ ≥
/// 1/3 the bound falls in a₂, so √15/2 at (1/2, 1/3).
#[test]
fn phi_max_of_a_tableau_is_its_imaginary_limit() {
    let t = ParamTableau::new(
        "fam2",
        &["a1", "a2"],
        &[vec!["0", "0"], vec!["1", "0"]],
        &["a1 - a2", "a2"],
    )
    .unwrap();
    let d = derive("method fam2\nparam a1\nparam a2\nstate y\ny = y + a1*w*y + a2*w^2*y\n");
    for (a2lo, optimum, at) in [(q(1, 4), "2", "1/4"), (q(1, 3), "sqrt(15)/2", "1/3")] {
        let free = vec![
            FreeParam::new("a1", q(1, 2), q(1, 1)),
            FreeParam::new("a2", a2lo.clone(), q(1, 1)),
        ];
        let on_tableau = Problem {
            subject: Subject::Tableau(&t),
            objective: Objective::PhiMax,
            free: free.clone(),
            bound: Params::new(),
            min_order: None,
        };
        let r = solve(&on_tableau);
        let s = solve(&problem(&d, Objective::ImagLimit, free));
        assert_eq!(finite(&r.optimum), optimum, "{:#?}", r.certificate);
        assert_eq!(r.optimum, s.optimum);
        assert_eq!(r.at, s.at);
        assert_eq!(r.at[1].1.to_string(), at);
        assert!(r.certificate.join(" ").contains("normal matrix"), "{:#?}", r.certificate);
    }
}

/// Where the disk bound's maximiser is a point where χ has a repeated,
/// unbounded root on the circle below the bound, the search stops rather
/// than report the bound. P = [[1, Φ], [Φg, 1 + Φ²g]], g = aΦ² − c: det 1,
/// trace 2 + aΦ⁴ − cΦ². The disk bound is √(c/a) where c² ≤ 16a, largest
/// at (9/16, 3): 4/√3; there trace = −2 touches at Φ² = 8/3, a Jordan
/// block, so Φ_max = √(8/3) = 2√6/3. A chi of degree 3 is refused too.
#[test]
fn phi_max_over_a_box_refuses_what_it_cannot_certify() {
    let d = derive("method tangent\nparam a\nparam c\nstate v y\ny' = y + Phi*v\nv' = v + Phi*(a*Phi^2 - c)*y'\n");
    let p = two_phi(&d, ("a", q(1, 2), q(1, 1)), ("c", q(3, 1), q(4, 1)));
    let e = maximize(&p).unwrap_err().to_string();
    assert!(
        e.contains("at a = 9/16, c = 3") && e.contains("4*sqrt(3)/3") && e.contains("2*sqrt(6)/3"),
        "{e}"
    );
    let v = objective_at(&p, &[("a", q(9, 16)), ("c", q(3, 1))]).unwrap();
    assert_eq!(finite(&v), "2*sqrt(6)/3");
    let d = derive("method three\nparam a\nparam b\nstate u v y\ny' = y + Phi*v\nv' = v - Phi*y' + a*Phi*u\nu' = b*u + Phi*v'\n");
    let e = maximize(&two_phi(&d, ("a", q(0, 1), q(1, 1)), ("b", q(0, 1), q(1, 2))))
        .unwrap_err()
        .to_string();
    assert!(e.contains("degree 3 in z"), "{e}");
}
