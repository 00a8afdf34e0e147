//! Section 4 (z-Transformation): P = I + TA for Standard Euler, det(Iz − P)
//! as the characteristic equation, the taxonomy of roots with its gaps
//! (negative real roots, repeated roots on the unit circle), Ψ by atan2
//! rather than arctan, the samples per period of the harmonic cases, and
//! the p, q form of second-order χ.

use check::numeric::ParamsF64;
use poly::{Poly, PolyMatrix};
use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("sec04.euler_transition", Confirmed),
    ("sec04.delay_operator", Confirmed),
    ("sec04.characteristic_equation", Confirmed),
    ("sec04.eigenvalues_decide", Refined),
    ("sec04.taxonomy_real", Refined),
    ("sec04.taxonomy_complex", Confirmed),
    ("sec04.psi_arctan", Refined),
    ("sec04.samples_per_period", Confirmed),
    ("sec04.double_root_plus_one", Refined),
    ("sec04.double_root_minus_one", Refined),
    ("sec04.approach_minus_one", Confirmed),
    ("sec04.p_q_roots", Confirmed),
    ("sec04.r_squared_q", Confirmed),
    ("sec04.method_identities", Confirmed),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// Standard Euler's P is I + ΦA for A = [[0, −1], [1, 0]] (v̇ = −ω0 y, ẏ = ω0 v).
#[test]
fn standard_euler_is_identity_plus_phi_a() {
    #[track_caller]
    fn check(name: &str, a: [[&str; 2]; 2]) {
        let phi = parse("Phi");
        let rows = (0..2)
            .map(|i| {
                (0..2).map(|j| &Poly::int((i == j) as i64) + &(&phi * &parse(a[i][j]))).collect()
            })
            .collect();
        assert_eq!(derive(name).transition_matrix(), &PolyMatrix::from_rows(rows), "{name}");
    }
    check("standard_euler", [["0", "-1"], ["1", "0"]]);
    check("damped_euler_d", [["-2*D", "-1"], ["1", "0"]]);
}

/// det(zI − P) by Laplace expansion (the slow oracle) is the derived χ for
/// every built-in.
#[test]
fn characteristic_equation_is_det_z_minus_p() {
    for name in poly::advanced::builtins::paper_builtin_names() {
        let d = derive(name);
        let det = d.transition_matrix().char_matrix(&parse("z")).det_laplace();
        assert_eq!(&det, d.charpoly(), "{name}");
    }
}

/// A repeated root on the unit circle: P = I stays put, a Jordan block grows
/// linearly, P = −I alternates with bounded amplitude. Same eigenvalues,
/// different fates: location alone does not decide.
#[test]
fn repeated_roots_on_the_circle_need_the_jordan_structure() {
    #[track_caller]
    fn check(p: [[f64; 2]; 2], bounded: bool) {
        let p: Vec<Vec<f64>> = p.iter().map(|r| r.to_vec()).collect();
        let xs = run(&p, &[1.0, 1.0], 1000);
        let size = xs[1000][0].abs().max(xs[1000][1].abs());
        assert_eq!(size <= 1.0 + 8.0 * f64::EPSILON, bounded, "{p:?}: |x_1000| = {size}");
    }
    check([[1.0, 0.0], [0.0, 1.0]], true);
    check([[-1.0, 0.0], [0.0, -1.0]], true);
    check([[1.0, 1.0], [0.0, 1.0]], false);
    check([[-1.0, 1.0], [0.0, -1.0]], false);
}

/// The paper's methods do reach negative real dominant roots, which the
/// taxonomy of single real eigenvalues (0 < z, z = 1, z > 1) leaves out.
#[test]
fn negative_real_roots_occur() {
    #[track_caller]
    fn check(name: &str, phi: f64) {
        let r = roots_at(name, phi);
        let dominant = if r[0].norm() >= r[1].norm() { r[0] } else { r[1] };
        assert!(dominant.im == 0.0 && dominant.re < 0.0, "{name} at {phi}: {r:?}");
    }
    check("false_euler", 2.5);
    check("semi_false_heun", 1.5);
    check("semi_false_heun", 1.7);
    let c = claim("sec04.taxonomy_real");
    assert!(c.evidence.contains("alternating"), "{}", c.evidence);
}

/// |z^n| = r^n: the pair's modulus alone decides decay, harmony or growth.
/// The derived recursions of three methods, run from (v, y) = (0, 1), grow
/// per step at exactly ln r1 of their complex pair (r1 < 1, = 1, > 1); the
/// sample amplitude oscillates, so the rate is read between steps 200 and 400
/// with an allowance of 2/200 for that oscillation, far below the gaps
/// between the three rates (−0.067, 0, +0.112).
#[test]
fn modulus_decides_complex_pairs() {
    #[track_caller]
    fn check(name: &str, phi: f64) {
        let [z, _] = roots_at(name, phi);
        assert!(z.im != 0.0, "{name}: not a complex pair at Φ = {phi}");
        let xs = run(&matrix_f64(name, phi), &[0.0, 1.0], 400);
        let norm = |x: &[f64]| x[0].hypot(x[1]).ln();
        let rate = (norm(&xs[400]) - norm(&xs[200])) / 200.0;
        assert!(
            (rate - z.norm().ln()).abs() <= 0.01,
            "{name}: rate {rate} vs ln r1 {}",
            z.norm().ln()
        );
    }
    check("false_heun", 0.5);
    check("false_euler", 0.5);
    check("standard_euler", 0.5);
}

/// arctan(b/a) is off by π when a < 0 (Ψ > π/2); atan2 gives the angle, as
/// False Euler's own samples show: y_n = cos(nΨ) with Ψ = 2 arcsin(Φ/2).
#[test]
fn psi_needs_atan2() {
    let phi: f64 = 1.8;
    let [z, _] = roots_at("false_euler", phi);
    let psi_true = 2.0 * (phi / 2.0).asin();
    let by_atan2 = z.im.abs().atan2(z.re);
    let by_arctan = (z.im.abs() / z.re).atan();
    assert!((by_atan2 - psi_true).abs() <= 16.0 * f64::EPSILON);
    assert!(by_arctan < 0.0, "arctan gives {by_arctan}");
    let ys = run(&matrix_f64("false_euler", phi), &[0.0, 1.0], 7);
    // y_n = cos(nΨ) + c·sin(nΨ) fits y_0 = 1 and y_1; check it at n = 7.
    let c = (ys[1][1] - psi_true.cos()) / psi_true.sin();
    let y7 = (7.0 * psi_true).cos() + c * (7.0 * psi_true).sin();
    assert!((ys[7][1] - y7).abs() <= 1e3 * f64::EPSILON, "{} vs {y7}", ys[7][1]);
    assert_eq!(claim("sec04.psi_arctan").verdict(), Refined);
}

/// 12, 4 and 2.4 samples per period: False Euler tuned to Ψ = 30°, 90°, 150°
/// returns to its start after 12, 4 and 12 steps (12 steps = 5 periods at
/// 2.4 samples per period).
#[test]
fn samples_per_period_of_the_harmonic_cases() {
    #[track_caller]
    fn check(angle_deg: f64, samples: f64, steps_back: usize) {
        assert!((360.0 / angle_deg - samples).abs() <= 4.0 * f64::EPSILON * samples);
        let phi = 2.0 * (angle_deg.to_radians() / 2.0).sin();
        let ys = run(&matrix_f64("false_euler", phi), &[0.0, 1.0], steps_back);
        let back = &ys[steps_back];
        assert!(
            (back[0]).abs() < 1e3 * f64::EPSILON && (back[1] - 1.0).abs() < 1e3 * f64::EPSILON,
            "{back:?}"
        );
    }
    check(30.0, 12.0, 12);
    check(90.0, 4.0, 4);
    check(150.0, 2.4, 12);
}

/// False Euler at Φ = 2 (pair reaching −1): exact samples are
/// (−1)^n (a + b n), a Jordan block, growing linearly.
#[test]
fn pair_reaching_minus_one_grows_linearly() {
    let d = derive("false_euler");
    let xs = run_exact(d.transition_matrix(), &poly::q(2, 1), &[poly::q(0, 1), poly::q(1, 1)], 60);
    let y = |n: usize| if n.is_multiple_of(2) { xs[n][1].clone() } else { -xs[n][1].clone() };
    let (a, b) = (y(0), y(1) - y(0));
    assert_ne!(b, poly::q(0, 1));
    for n in 0..=60 {
        assert_eq!(y(n), &a + &b * poly::q(n as i64, 1), "n = {n}");
    }
}

/// The p, q formulas for the roots and r² = q, checked numerically on
/// seeded pairs (p, q) on both sides of p² = q.
#[test]
fn p_q_formulas() {
    let mut seed = 0x9e37_79b9_u64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 10_000) as f64 / 2_500.0 - 2.0
    };
    for _ in 0..200 {
        let (p, q) = (next(), next());
        let d = p * p - q;
        let zs = if d >= 0.0 {
            [
                num_complex::Complex64::new(p + d.sqrt(), 0.0),
                num_complex::Complex64::new(p - d.sqrt(), 0.0),
            ]
        } else {
            [
                num_complex::Complex64::new(p, (-d).sqrt()),
                num_complex::Complex64::new(p, -(-d).sqrt()),
            ]
        };
        for z in zs {
            let chi = z * z - 2.0 * p * z + q;
            assert!(
                chi.norm() <= 64.0 * f64::EPSILON * (1.0 + p.abs() + q.abs()).powi(2),
                "p {p} q {q}"
            );
        }
        if d < 0.0 {
            assert!((zs[0].norm_sqr() - q).abs() <= 16.0 * f64::EPSILON * (1.0 + q.abs()));
        }
    }
}

/// The exact class changes (poly::advanced::stability, Sturm sequences over Q) agree
/// with the numeric sweep of the check crate (f64 classification on a grid,
/// bisected to adjacent floats): every exact change between different
/// classes has a numeric boundary within 1e-9, and the classes on both
/// sides agree.
#[test]
fn exact_class_changes_agree_with_the_numeric_sweep() {
    for name in [
        "standard_euler",
        "damped_euler",
        "false_euler",
        "standard_heun",
        "false_heun",
        "semi_false_heun",
    ] {
        let d = derive(name);
        let exact = poly::advanced::stability::analyze(d.charpoly()).expect("analysis");
        let numeric = check::sweep::sweep(
            d.method(),
            &check::numeric::Params::phi(1.0),
            &check::sweep::default_grid(),
        )
        .expect("sweep");
        for change in exact.class_changes.iter().filter(|c| c.from != c.to) {
            let at: f64 = change.at.to_decimal(12).parse().unwrap();
            let hit =
                numeric.boundaries.iter().find(|b| b.below - 1e-9 <= at && at <= b.above + 1e-9);
            let b = hit.unwrap_or_else(|| {
                panic!("{name}: no numeric boundary near {at}: {:?}", numeric.boundaries)
            });
            assert_eq!(b.class_below, change.from, "{name} below {at}");
        }
        assert_eq!(numeric.first.1, exact.intervals[0].class, "{name} near Φ = 0");
    }
}
