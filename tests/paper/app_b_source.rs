//! Appendix B (Source code): each method's "Direct Integration" and
//! "Transition matrix" branches compute the same step, Verlet's start
//! y2 := 1 is False Euler from v0 = 0, Damped Euler's D := 0.5*woT is
//! section 6's D = Φ/2, and the listing's slips.

use zcheck::paper::Verdict::{self, *};

use crate::common::*;

pub const COVERED: &[(&str, Verdict)] = &[
    ("appB.standard_euler_branches", Confirmed),
    ("appB.damped_euler_branches", Confirmed),
    ("appB.false_euler_branches", Confirmed),
    ("appB.standard_heun_branches", Confirmed),
    ("appB.false_heun_branches", Confirmed),
    ("appB.semi_false_heun_branches", Confirmed),
    ("appB.verlet_start", Confirmed),
    ("appB.damped_euler_d", Confirmed),
    ("appB.typo_matrixix", Typo),
    ("appB.undeclared_names", Typo),
];

#[test]
fn verdicts() {
    check_verdicts(COVERED);
}

/// The "Transition matrix" branches, transcribed by hand from the Pascal,
/// against the hand-transcribed "Direct Integration" branches, in floating
/// point at several Φ; and the built-in twins have equal exact P.
#[test]
fn branches_agree() {
    type Branch = fn(f64, f64, f64) -> (f64, f64);
    let matrix: [(&str, Branch); 6] = [
        ("standard_euler", |v, y, w| (v - w * y, w * v + y)),
        ("damped_euler", |v, y, w| ((1.0 - w * w) * v - w * y, w * v + y)),
        ("false_euler", |v, y, w| (v - w * y, w * v + (1.0 - w * w) * y)),
        ("standard_heun", |v, y, w| {
            ((1.0 - 0.5 * w * w) * v - w * y, w * v + (1.0 - 0.5 * w * w) * y)
        }),
        ("false_heun", |v, y, w| {
            let h = 1.0 - 0.5 * w * w;
            (h * v - w * h * y, w * h * v + (1.0 - w * w + 0.5 * w.powi(4)) * y)
        }),
        ("semi_false_heun", |v, y, w| {
            let h = 1.0 - 0.5 * w * w;
            (h * v - w * y, w * h * v + h * y)
        }),
    ];
    for (name, branch) in matrix {
        for phi in PHIS {
            for (v, y) in [(1.0, 0.0), (0.0, 1.0), (0.3, -0.8)] {
                let (a, b) = pascal_step(name, v, y, phi);
                let (c, d) = branch(v, y, phi);
                let tol = 64.0 * f64::EPSILON * (1.0 + phi.powi(4));
                assert!((a - c).abs() <= tol && (b - d).abs() <= tol, "{name} Φ={phi}");
            }
        }
        let twin = format!("{name}_matrix");
        assert_eq!(derive(name).transition_matrix(), derive(&twin).transition_matrix(), "{name}");
    }
}

/// Verlet from y0 = y2 = 1 gives exactly False Euler's samples from v0 = 0,
/// y0 = 1 (exact rationals).
#[test]
fn verlet_start_is_false_euler_with_zero_velocity() {
    let fe = derive("false_euler");
    for phi in [poly::q(1, 3), poly::q(7, 5), poly::q(2, 1)] {
        let xs = run_exact(fe.transition_matrix(), &phi, &[poly::q(0, 1), poly::q(1, 1)], 30);
        let (mut prev, mut cur) = (poly::q(1, 1), poly::q(1, 1));
        for x in xs.iter().skip(1) {
            let next = poly::q(2, 1) * &cur - &prev + &phi * &phi * (-&cur);
            prev = std::mem::replace(&mut cur, next);
            assert_eq!(cur, x[1], "Φ = {phi}");
        }
    }
}

/// D := 0.5*woT in the direct branch equals the matrix branch's (1 − woT2).
#[test]
fn damped_euler_d_half_phi() {
    let d = derive("damped_euler_d");
    let p = d.transition_matrix().map(|e| e.subs(poly::Sym::new("D"), &parse("Phi/2")));
    assert_eq!(&p, derive("damped_euler_matrix").transition_matrix());
}
