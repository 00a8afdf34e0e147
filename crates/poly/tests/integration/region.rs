//! The exact (Φ, D) region against oracles written here: False Euler's
//! limit Φ < 2(√(1 + D²) − D) as the sign of Φ² + 4DΦ − 4, closed forms of
//! Φ_max at rational D, and the verdict on unconditional stability for
//! methods known to have it (backward Euler, the trapezoidal rule) or not.

use std::cmp::Ordering;

use num_traits::Zero;
use poly::advanced::region::{CurveKind, PhiLimit, Region, Unconditional};
use poly::{q, Algebraic, Poly, Sym, Q};

fn d() -> Sym {
    Sym::new("D")
}

/// The (Φ, D) region of a built-in.
fn region_of(name: &str) -> Region {
    poly::derive(&poly::builtin(name).unwrap()).unwrap().region(d()).unwrap()
}

/// The (Φ, D) region of a `.zm` program.
fn region_of_source(src: &str) -> Region {
    poly::derive_source("test.zm", src).unwrap().region(d()).unwrap()
}

/// Membership of every rational (Φ, D) on a grid equals the oracle
/// Φ² + 4DΦ − 4 < 0 (Φ > 0, D ≥ 0), boundary points included: on the curve
/// one root is −1, simple and bounded when D > 0 (the other is 1 − 2DΦ,
/// inside the circle), double and unbounded at D = 0.
#[test]
fn false_euler_membership_is_the_closed_form() {
    let r = region_of("false_euler_damped");
    let mut on_boundary = 0;
    for i in 1..=30 {
        for j in 0..=20 {
            let (phi, dd) = (q(i, 10), q(j, 8));
            let g =
                &phi * &phi + Q::from_integer(4.into()) * &dd * &phi - Q::from_integer(4.into());
            on_boundary += usize::from(g.is_zero());
            let inside = g < Q::zero() || (g.is_zero() && dd > Q::zero());
            assert_eq!(r.contains(&phi, &dd).unwrap(), inside, "Phi {phi}, D {dd}");
        }
    }
    assert!(on_boundary > 0, "the grid should hit the boundary exactly somewhere");
}

/// Φ_max(D) = 2(√(1 + D²) − D): rational where 1 + D² is a square, else the
/// positive root of Φ² + 4DΦ − 4, within 1e-12 of the closed form.
#[test]
fn false_euler_phi_max_is_the_closed_form() {
    let r = region_of("false_euler_damped");
    for (dd, expected) in
        [(q(0, 1), q(2, 1)), (q(3, 4), q(1, 1)), (q(5, 12), q(4, 3)), (q(8, 15), q(6, 5))]
    {
        assert_eq!(
            r.phi_max(&dd).unwrap(),
            PhiLimit::Below(Algebraic::from_rational(expected)),
            "D = {dd}"
        );
    }
    for (num, den) in [(1, 1), (1, 2), (3, 1), (1, 10)] {
        let dd = q(num, den);
        let PhiLimit::Below(m) = r.phi_max(&dd).unwrap() else { panic!("D = {dd}") };
        let x = num as f64 / den as f64;
        let closed = 2.0 * ((1.0 + x * x).sqrt() - x);
        let approx: f64 = m.to_decimal(16).parse().unwrap();
        assert!((approx - closed).abs() < 1e-12, "D = {dd}: {approx} vs {closed}");
        // The defining polynomial divides Φ² + 4DΦ − 4 at this D.
        let g = poly::UPoly::new(vec![
            -Q::from_integer(4.into()),
            Q::from_integer(4.into()) * &dd,
            Q::from_integer(1.into()),
        ]);
        assert!(m.is_root_of(&g));
    }
}

/// The curves of False Euler: χ(−1) = Φ² + 4DΦ − 4 and χ(1) = Φ² (only
/// Φ = 0), the unit circle 2DΦ (only the axes).
#[test]
fn false_euler_curves() {
    let r = region_of("false_euler_damped");
    let kinds: Vec<CurveKind> = r.boundary_curves().map(|c| c.kind).collect();
    assert_eq!(kinds, [CurveKind::ChiAtMinusOne]);
    let c = r.boundary_curves().next().unwrap();
    assert_eq!(c.poly, Poly::parse("Phi^2 + 4*D*Phi - 4").unwrap());
    // The curve's Φ at D = 3/4 is exactly 1.
    let phis = r.curve_phis(c, &q(3, 4), &q(0, 1), &q(3, 1));
    assert_eq!(phis, [Algebraic::from_rational(q(1, 1))]);
}

/// Unconditional stability: backward Euler and the trapezoidal rule on the
/// damped oscillator (χ written out here) are bounded at every Φ > 0,
/// D ≥ 0; the explicit methods are not.
#[test]
fn unconditional_stability() {
    // Backward Euler and the trapezoidal rule on v' = −2Dv − y, y' = v.
    let backward =
        "method backward\nstate v y\nparam D\nv' = v - Phi*(2*D*v' + y')\ny' = y + Phi*v'\n";
    let trapezoid = "method trapezoid\nstate v y\nparam D\n\
        v' = v - Phi/2*(2*D*v + y + 2*D*v' + y')\ny' = y + Phi/2*(v + v')\n";
    for (name, src) in [("backward", backward), ("trapezoid", trapezoid)] {
        let r = region_of_source(src);
        let chi = r.charpoly().clone();
        let expected = match name {
            "backward" => "(1 + 2*D*Phi + Phi^2)*z^2 - (2 + 2*D*Phi)*z + 1",
            _ => "(1 + D*Phi + Phi^2/4)*z^2 - (2 - Phi^2/2)*z + (1 - D*Phi + Phi^2/4)",
        };
        // The programs are the systems intended: χ up to a constant factor.
        let want = Poly::parse(expected).unwrap();
        assert!(proportional(&chi, &want), "{name}: {chi}");
        assert!(matches!(r.unconditional().unwrap(), Unconditional::Stable { .. }), "{name}");
    }
    for name in poly::advanced::builtins::DAMPED_METHODS {
        let r = region_of(name);
        match r.unconditional().unwrap() {
            Unconditional::Unstable { d, limit } => {
                // The counterexample is real: some Φ is unbounded there.
                assert_ne!(*limit, PhiLimit::Every, "{name} at D = {d}");
            }
            u => panic!("{name}: {u:?}"),
        }
    }
}

/// Membership agrees with the one-variable analysis: below Φ_max(D) inside,
/// just above outside, for every damped built-in at a few D.
#[test]
fn membership_agrees_with_phi_max() {
    let eps = q(1, 1000);
    for name in poly::advanced::builtins::DAMPED_METHODS {
        let r = region_of(name);
        for dd in [q(0, 1), q(1, 10), q(1, 2), q(2, 1)] {
            if let PhiLimit::Below(m) = r.phi_max(&dd).unwrap() {
                let (lo, hi) = m.refine(&q(1, 1 << 20)).interval();
                let below = &lo - &eps;
                if below > Q::zero() {
                    assert!(r.contains(&below, &dd).unwrap(), "{name}: D {dd}, Phi {below}");
                }
                assert_eq!(m.cmp_rational(&(&hi + &eps)), Ordering::Less);
            }
        }
    }
}

/// Whether a = c·b for a nonzero rational c.
fn proportional(a: &Poly, b: &Poly) -> bool {
    let (z, phi) = (Sym::z(), Sym::phi());
    let lead = |p: &Poly| p.coeffs_in(z).last().cloned().unwrap().coeffs_in(phi)[0].clone();
    let (la, lb) = (lead(a), lead(b));
    a * &lb == b * &la
}
