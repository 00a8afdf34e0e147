//! The four witnesses agree on every built-in, at ordinary Φ and at every
//! class boundary a sweep finds; the tolerance model is tight enough to
//! notice a small error; sweeps find the boundaries known in closed form.

use check::classify::{classify_pq, classify_roots, PqSigns};
use check::numeric::ParamsF64;
use check::numeric::{Params, Step};
use check::sweep::{default_grid, sweep, Classifier};
use check::witness::{
    eigen_condition, eigenvalues_faer, eigenvalues_nalgebra, pair_up, simulate, tolerances,
    Witnesses, C64,
};
use num_complex::Complex;
use poly::{RootClass, Q};

const STEPS: u64 = 20_000;

fn params() -> Params {
    Params::default().with("D", 0.3)
}

/// Every witness agrees at `phi`, and all four were consulted.
#[track_caller]
fn check_agrees(name: &str, phi: f64, steps: u64) {
    let m = poly::builtin(name).unwrap();
    let w = Witnesses::new(&m).unwrap();
    let r = w.at(&params().with("Phi", phi), steps).unwrap();
    let names: Vec<&str> = r.checks.iter().map(|c| c.witness).collect();
    assert_eq!(names, ["nalgebra", "faer", "simulation", "simulation_norm"], "{name}");
    assert!(r.agree(), "{name} at phi = {phi}: {:?}", r.checks);
}

/// The acceptance list of the issue, for every paper built-in.
#[test]
fn builtins_agree_at_the_default_phis() {
    for name in poly::advanced::builtins::builtin_names() {
        for phi in [1e-6, 0.1, 0.5, 1.0, 1.5, 1.9] {
            check_agrees(name, phi, STEPS);
        }
    }
}

/// The multistep and Runge–Kutta built-ins (χ of degree up to 16). At
/// Φ = 10⁻⁶ a multistep method's principal pair 1 ± iΦ crowds with its own
/// conjugate, and roots from χ's rounded coefficients were off by 10⁻⁵ of Ψ
/// (the eigenvalues disagreed 1000-fold beyond tolerance); the exact Newton
/// polish puts them back. Leapfrog is left out: nalgebra's Schur iteration
/// does not converge on its P (four eigenvalues ±1 ± iΦ of modulus one) and
/// the witness reports that as an error.
#[test]
fn comparison_builtins_agree() {
    for name in poly::advanced::builtins::comparison_builtin_names().filter(|n| *n != "leapfrog") {
        for phi in [1e-6, 0.01, 0.1, 0.5] {
            check_agrees(name, phi, STEPS);
        }
    }
}

/// Both sides of every class boundary a sweep reports, for the built-ins
/// whose index is `part` mod [`PARTS`] (one test per part, so the harness
/// runs them side by side; together they cover every built-in).
fn builtins_agree_at_every_class_boundary(part: usize) {
    let names = poly::advanced::builtins::builtin_names();
    for name in names.enumerate().filter(|(i, _)| i % PARTS == part).map(|(_, n)| n) {
        let m = poly::builtin(name).unwrap();
        let s = sweep(&m, &params(), &default_grid()).unwrap();
        for b in &s.boundaries {
            assert_eq!(b.above, b.below.next_up(), "{name}: bracket is two adjacent floats");
            check_agrees(name, b.below, STEPS);
            check_agrees(name, b.above, STEPS);
        }
    }
}

const PARTS: usize = 4;

#[test]
fn builtins_agree_at_every_class_boundary_part_0() {
    builtins_agree_at_every_class_boundary(0);
}

#[test]
fn builtins_agree_at_every_class_boundary_part_1() {
    builtins_agree_at_every_class_boundary(1);
}

#[test]
fn builtins_agree_at_every_class_boundary_part_2() {
    builtins_agree_at_every_class_boundary(2);
}

#[test]
fn builtins_agree_at_every_class_boundary_part_3() {
    builtins_agree_at_every_class_boundary(3);
}

/// Two real roots of one modulus (χ = z² − r², p = 0): Semi-False Heun on
/// the damped spring at D = 0.3 has them at Φ ≈ 1.8207 and 2.4235, where the
/// simulation follows the root sorted first, and Ψ must be that root's.
#[test]
fn equal_modulus_real_roots_agree() {
    for phi in [1.820667225920887, 2.4235394805662716, 2.423539480566272] {
        let m = poly::builtin("semi_false_heun_damped").unwrap();
        let w = Witnesses::new(&m).unwrap();
        let r = w.at(&params().with("Phi", phi), STEPS).unwrap();
        assert!(r.agree(), "at phi = {phi}: {:?}", r.checks);
    }
}

/// One full-length (10^6 steps) run of an unstable method, and runs whose
/// state grows by 10^(10^6) without overflowing.
#[test]
fn long_and_explosive_simulations_agree() {
    check_agrees("standard_euler", 0.5, 1_000_000);
    check_agrees("standard_heun", 4.0, 200_000); // rho = sqrt(65) per step
    check_agrees("false_heun", 4.0, 200_000); // rho = 106 per step
}

/// Expected boundaries in closed form lie inside the reported brackets (up
/// to one ulp, the f64 value of an irrational boundary).
#[track_caller]
fn check_boundary(name: &str, expected: f64, below: RootClass, above: RootClass) {
    let m = poly::builtin(name).unwrap();
    let s = sweep(&m, &params(), &default_grid()).unwrap();
    let b = s
        .boundaries
        .iter()
        .find(|b| b.class_below == below && b.class_above == above)
        .unwrap_or_else(|| panic!("{name}: no {below} -> {above} boundary in {:?}", s.boundaries));
    assert!(
        b.below.next_down() <= expected && expected <= b.above.next_up(),
        "{name}: {expected} outside [{}, {}]",
        b.below,
        b.above
    );
}

#[test]
fn sweeps_find_the_closed_form_boundaries() {
    use RootClass::*;
    // chi = z^2 - 2(1 - Phi^2/2) z + 1: double root -1 at Phi = 2.
    for name in ["false_euler", "verlet", "damped_euler", "false_euler_matrix"] {
        check_boundary(name, 2.0, Harmonic, DoubleRootOnCircle);
        check_boundary(name, 2.0f64.next_up(), DoubleRootOnCircle, AlternatingUnstable);
    }
    // Semi-False Heun: p = 1 - Phi^2/2, q = 1 - Phi^4/4 vanish together at
    // sqrt 2 (deadbeat), and chi(-1) = 4 - Phi^2 - Phi^4/4 at Phi^2 = 2 sqrt 5 - 2.
    check_boundary("semi_false_heun", 2f64.sqrt(), DampedOscillation, AlternatingStable);
    let limit = (2.0 * 5f64.sqrt() - 2.0).sqrt();
    check_boundary("semi_false_heun", limit, AlternatingStable, AlternatingUnstable);
    // False Heun: chi(1) = Phi^2 (1 - Phi^2/2) vanishes at sqrt 2.
    check_boundary("false_heun", 2f64.sqrt(), MonotonicStable, MonotonicUnstable);
    // Damped Euler with free D: q - 1 = Phi (Phi - 2D) vanishes at 2D.
    check_boundary("damped_euler_d", 0.6, DampedOscillation, Harmonic);
    check_boundary("damped_euler_d", 0.6f64.next_up(), Harmonic, UnstableOscillation);
    // Standard Euler and Standard Heun never change class.
    for name in ["standard_euler", "standard_heun"] {
        let s = sweep(&poly::builtin(name).unwrap(), &params(), &default_grid()).unwrap();
        assert_eq!((s.boundaries.len(), s.first.1), (0, UnstableOscillation), "{name}");
    }
}

/// The fast f64 classifier equals the exact class at every grid point. A
/// method of higher order (BDF2) has no fast path: its classifier *is* the
/// exact χ at Φ, so comparing the two there could not fail, and it is left
/// out (`is_second_order` says which path a method takes).
#[test]
fn fast_classifier_equals_the_exact_class() {
    let mut fast = 0;
    for name in poly::advanced::builtins::builtin_names() {
        let m = poly::builtin(name).unwrap();
        let c = Classifier::new(&m, &params()).unwrap();
        if !c.is_second_order() {
            continue;
        }
        fast += 1;
        let w = Witnesses::new(&m).unwrap();
        for phi in default_grid().into_iter().step_by(7) {
            let exact = w.charpoly().at(&params().with("Phi", phi)).unwrap().class;
            assert_eq!(c.classify(phi), exact, "{name} at {phi}");
        }
    }
    assert!(fast >= 10, "only {fast} built-ins take the fast path");
}

/// An error of 1e-9 in a root, far below what a plot shows, is caught by
/// both eigenvalue witnesses and by the simulation.
#[test]
fn tolerance_catches_a_small_error() {
    for name in ["false_euler", "standard_heun", "false_heun", "verlet", "semi_false_heun"] {
        let m = poly::builtin(name).unwrap();
        let w = Witnesses::new(&m).unwrap();
        let (phi, wrong_phi) = (0.5, 0.5 + 1e-9);
        let step = Step::compile(&m, &Params::phi(phi)).unwrap();
        let p = step.transition_matrix();
        let wrong = w.charpoly().at(&Params::phi(wrong_phi)).unwrap();
        let (tol, _, _) = tolerances(&p, &wrong.coeffs, &wrong.roots);
        for found in [eigenvalues_nalgebra(&p).unwrap(), eigenvalues_faer(&p).unwrap()] {
            let found = pair_up(&wrong.roots, &found);
            let worst = wrong
                .roots
                .iter()
                .zip(&found)
                .zip(&tol)
                .map(|((a, b), t)| (a - b).norm() / t)
                .fold(0.0, f64::max);
            assert!(worst > 1.0, "{name}: an error of 1e-9 passed (ratio {worst})");
        }
        let (_, left) = eigen_condition(&p, wrong.roots[0]);
        let sim = simulate(&step, wrong.roots[0], &left, STEPS, &mut |_| true);
        let err = (sim.growth_per_step.exp() - wrong.spectral_radius)
            .abs()
            .max(wrong.spectral_radius * (sim.psi_per_step - wrong.psi).abs());
        assert!(err > tol[0], "{name}: simulation missed an error of 1e-9 ({err} <= {})", tol[0]);
    }
}

fn signs(v: [i8; 8]) -> PqSigns {
    let o = |x: i8| x.cmp(&0);
    PqSigns {
        disc: o(v[0]),
        p: o(v[1]),
        p_minus_1: o(v[2]),
        p_plus_1: o(v[3]),
        q_minus_1: o(v[4]),
        q_plus_1: o(v[5]),
        chi_1: o(v[6]),
        chi_minus_1: o(v[7]),
    }
}

/// The sign classifier against the roots it describes.
#[track_caller]
fn check_pq(p: f64, q: f64, expected: RootClass) {
    let s = |x: f64| {
        if x > 0.0 {
            1
        } else if x < 0.0 {
            -1
        } else {
            0
        }
    };
    let v = [
        s(p * p - q),
        s(p),
        s(p - 1.0),
        s(p + 1.0),
        s(q - 1.0),
        s(q + 1.0),
        s(1.0 - 2.0 * p + q),
        s(1.0 + 2.0 * p + q),
    ];
    assert_eq!(classify_pq(&signs(v)), expected, "p = {p}, q = {q}");
}

#[test]
fn second_order_sign_classification() {
    use RootClass::*;
    check_pq(0.5, 1.0, Harmonic);
    check_pq(0.5, 0.5, DampedOscillation);
    check_pq(0.5, 2.0, UnstableOscillation);
    check_pq(0.0, 0.0, Deadbeat);
    check_pq(1.0, 1.0, DoubleRootOnCircle);
    check_pq(-1.0, 1.0, DoubleRootOnCircle);
    check_pq(0.5, 0.25, MonotonicStable); // double root 0.5
    check_pq(-2.0, 4.0, AlternatingUnstable); // double root -2
    check_pq(0.75, 0.5, Constant); // roots 1 and 0.5
    check_pq(1.5, 2.0, MonotonicUnstable); // roots 2 and 1
    check_pq(0.3, 0.08, MonotonicStable); // roots 0.4 and 0.2
    check_pq(-0.75, 0.5, Alternating); // roots -1 and -0.5
    check_pq(-0.3, 0.08, AlternatingStable); // roots -0.2 and -0.4
    check_pq(0.0, -4.0, AlternatingUnstable); // roots +-2: z^2 = 4
    check_pq(0.0, -1.0, Alternating); // roots +-1
    check_pq(0.25, -2.0, MonotonicUnstable); // roots 1.69 and -1.19: the positive one dominates
}

/// The tolerance classifier on root lists.
#[track_caller]
fn check_roots(roots: &[(f64, f64)], expected: RootClass) {
    let roots: Vec<C64> = roots.iter().map(|&(a, b)| Complex::new(a, b)).collect();
    let tol = vec![64.0 * f64::EPSILON; roots.len()];
    assert_eq!(classify_roots(&roots, &tol), expected, "{roots:?}");
}

#[test]
fn root_list_classification() {
    use RootClass::*;
    let h = std::f64::consts::FRAC_1_SQRT_2;
    check_roots(&[(h, h), (h, -h), (0.5, 0.0)], Harmonic);
    check_roots(&[(0.5, 0.5), (0.5, -0.5)], DampedOscillation);
    check_roots(&[(-1.0, 0.0), (-1.0, 1e-17)], DoubleRootOnCircle);
    check_roots(&[(-1.0, 0.0), (0.2, 0.0)], Alternating);
    check_roots(&[(1.0 + 1e-17, 0.0), (0.2, 0.0)], Constant);
    check_roots(&[(1.5, 0.0), (-0.2, 0.0), (0.1, 0.3)], MonotonicUnstable);
    check_roots(&[(1e-20, 0.0), (-1e-20, 0.0)], Deadbeat);
}

/// Pairing survives arbitrary order and near-coincident roots.
#[test]
fn pairing_is_order_free() {
    let r = [
        Complex::new(1.0, 1.0),
        Complex::new(1.0, -1.0),
        Complex::new(-0.5, 0.0),
        Complex::new(-0.5, 1e-9),
    ];
    let shuffled = [r[2], r[0], r[3], r[1]];
    assert_eq!(pair_up(&r, &shuffled), r.to_vec());
}

/// Three substeps of False Euler (Φ/3 each), through `check::verify`: at
/// Φ = 3 the substep is exactly 1, P = −I and χ = (z + 1)², a double root on
/// the circle that is bounded (the state's norm never grows); at Φ = 6 χ is
/// (z + 1)² again, but P is a Jordan block and the norm grows like n. Every
/// witness agrees with the exact χ at both.
#[test]
fn a_double_root_on_the_circle_is_bounded_where_p_is_semisimple() {
    let d = poly::derive_source("false_euler_3.zm", testkit::programs::FALSE_EULER_3).unwrap();
    let at3 = check::verify(&d, &Params::phi(3.0), 10_000).unwrap();
    assert!(at3.agree(), "{:?}", at3.checks);
    assert_eq!(at3.exact.class, poly::RootClass::DoubleRootOnCircle);
    let p = &at3.transition_matrix;
    assert!(p.iter().zip([-1.0, 0.0, 0.0, -1.0]).all(|(a, b)| *a == b), "P = {p}");
    let grow3 = at3.sim.as_ref().unwrap().norm_growth_per_step;
    assert!(grow3.abs() < 1e-12, "bounded at 3, norm growth {grow3}");
    let at6 = check::verify(&d, &Params::phi(6.0), 10_000).unwrap();
    assert!(at6.agree(), "{:?}", at6.checks);
    let grow6 = at6.sim.as_ref().unwrap().norm_growth_per_step;
    assert!(grow6 > 1e-4, "a Jordan block at 6 grows like n: norm growth {grow6}");
}

/// The oracle of `exact_value_and_slope`: Horner's scheme term by term in
/// exact rationals (χ′ alongside), each part rounded to f64 at the end.
fn value_and_slope_by_rationals(coeffs: &[Q], z: C64) -> (C64, C64) {
    let (x, y) = (Q::from_float(z.re).unwrap(), Q::from_float(z.im).unwrap());
    let zero = || Q::from_integer(0.into());
    let (mut pr, mut pi, mut dr, mut di) = (zero(), zero(), zero(), zero());
    for a in coeffs {
        let (ndr, ndi) = (&dr * &x - &di * &y + &pr, &dr * &y + &di * &x + &pi);
        let (npr, npi) = (&pr * &x - &pi * &y + a, &pr * &y + &pi * &x);
        (dr, di, pr, pi) = (ndr, ndi, npr, npi);
    }
    let f = |q: &Q| check::numeric::q_to_f64(q);
    (C64::new(f(&pr), f(&pi)), C64::new(f(&dr), f(&di)))
}

proptest::proptest! {
    /// χ and χ′ at a point, on integers, equal the term-by-term rational
    /// evaluation exactly (the same rationals, rounded once), for random
    /// rational coefficients of degree 0 to 6 and points from tiny to large.
    #[test]
    fn exact_value_and_slope_matches_rationals(
        nums in proptest::collection::vec(-50i64..50, 1..8),
        dens in proptest::collection::vec(1i64..40, 8),
        re in -4.0f64..4.0,
        im in -4.0f64..4.0,
        scale in -40i32..40,
    ) {
        let coeffs: Vec<Q> = nums.iter().zip(&dens).map(|(n, d)| poly::q(*n, *d)).collect();
        let z = C64::new(re * 2f64.powi(scale), im * 2f64.powi(-scale / 2));
        let fast = check::witness::exact_value_and_slope(&coeffs, z).unwrap();
        proptest::prop_assert_eq!(fast, value_and_slope_by_rationals(&coeffs, z));
    }
}
