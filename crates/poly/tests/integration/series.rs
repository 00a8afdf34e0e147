//! Exact Taylor series of Ψ(Φ) and |z|², against closed-form coefficient
//! formulas, trigonometric identities computed by a different route, and
//! Appendix A's approximations.

use num_bigint::BigInt;
use poly::advanced::series::{
    dispersion_order, dissipation_order, modulus_sq_series, psi_series, psi_series_scaled,
    LeadingTerm, Series,
};
use poly::{q, ErrorKind, Poly, Sym, Q};

fn chi_of(name: &str) -> Poly {
    poly::advanced::charpoly(&poly::builtin(name).unwrap()).unwrap()
}

fn factorial(n: u64) -> BigInt {
    (1..=n).fold(BigInt::from(1), |acc, k| acc * BigInt::from(k))
}

/// asin x = Σ (2k)! / (4^k (k!)² (2k + 1)) x^{2k+1}, the textbook formula.
fn asin_coeffs(order: usize) -> Vec<Q> {
    let mut c = vec![Q::default(); order + 1];
    for k in 0..=(order.saturating_sub(1) / 2) as u64 {
        let num = factorial(2 * k);
        let den =
            BigInt::from(4).pow(k as u32) * factorial(k) * factorial(k) * BigInt::from(2 * k + 1);
        c[2 * k as usize + 1] = Q::new(num, den);
    }
    c
}

/// sin and cos of a series with zero constant term, from s′ = c·u′,
/// c′ = −s·u′ (a route the library does not use).
fn sin_cos(u: &Series) -> (Series, Series) {
    let n = u.order();
    let du = u.derivative();
    let mut s = vec![Q::default(); n + 1];
    let mut c = vec![Q::default(); n + 1];
    c[0] = q(1, 1);
    for k in 1..=n {
        // k s_k = Σ_{j=1}^{k} j u_j c_{k−j}, and likewise for c with −s.
        let (mut ds, mut dc) = (Q::default(), Q::default());
        for j in 1..=k {
            ds += &du.coeff(j - 1) * &c[k - j];
            dc -= &du.coeff(j - 1) * &s[k - j];
        }
        s[k] = ds / Q::from_integer(k.into());
        c[k] = dc / Q::from_integer(k.into());
    }
    (Series::new(s), Series::new(c))
}

/// p and q of χ = z² − 2 p z + q as series (the methods here are monic).
fn p_q(chi: &Poly, order: usize) -> (Series, Series) {
    let c = chi.coeffs_in(Sym::z());
    let up = |p: &Poly| p.to_upoly(Sym::phi()).unwrap();
    let p = Series::from_upoly(&up(&c[1]), order).scale(&q(-1, 2));
    (p, Series::from_upoly(&up(&c[0]), order))
}

/// For every second-order built-in: sin²Ψ·q = q − p² and cos²Ψ·q = p², with
/// sin and cos of the computed Ψ series taken by an independent recurrence
/// (the identities of cos Ψ = p/√q).
#[test]
fn psi_satisfies_cos_psi_equals_p_over_sqrt_q() {
    let order = 16;
    for name in poly::advanced::builtins::paper_builtin_names().filter(|n| *n != "damped_euler_d") {
        let chi = chi_of(name);
        let psi = Series::new(psi_series(&chi, order).unwrap());
        let (s, c) = sin_cos(&psi);
        let (p, qq) = p_q(&chi, order);
        assert_eq!(s.mul(&s).mul(&qq), qq.sub(&p.mul(&p)), "{name}: sin^2 Psi q = q - p^2");
        assert_eq!(c.mul(&c).mul(&qq), p.mul(&p), "{name}: cos^2 Psi q = p^2");
        assert!(c.coeff(0) > Q::default());
    }
}

/// False Euler: cos Ψ = 1 − Φ²/2 gives sin(Ψ/2) = Φ/2, so Ψ = 2 asin(Φ/2).
#[test]
fn false_euler_psi_is_two_arcsin_half_phi() {
    let order = 21;
    let expected: Vec<Q> = asin_coeffs(order)
        .iter()
        .enumerate()
        .map(|(k, c)| c * q(2, 1) / num_traits::pow(q(2, 1), k))
        .collect();
    for name in ["false_euler", "damped_euler", "verlet", "false_euler_matrix"] {
        assert_eq!(psi_series(&chi_of(name), order).unwrap(), expected, "{name}");
    }
    // The library's own asin agrees with the formula too.
    assert_eq!(Series::x(order).asin().unwrap().coeffs(), asin_coeffs(order).as_slice());
}

/// Standard Euler: tan Ψ = Φ, so Ψ = atan Φ = Σ (−1)^k Φ^{2k+1}/(2k+1).
#[test]
fn standard_euler_psi_is_arctan_phi() {
    let order = 15;
    let expected: Vec<Q> = (0..=order)
        .map(|k| match k % 4 {
            1 => q(1, k as i64),
            3 => q(-1, k as i64),
            _ => Q::default(),
        })
        .collect();
    assert_eq!(psi_series(&chi_of("standard_euler"), order).unwrap(), expected);
}

#[track_caller]
fn check_leading(name: &str, dispersion: (usize, Q), dissipation: Option<(usize, Q)>) {
    let chi = chi_of(name);
    let d = dispersion_order(&chi).unwrap().unwrap();
    assert_eq!((d.order, d.coeff), dispersion, "{name} dispersion");
    let s = dissipation_order(&chi).unwrap().map(|LeadingTerm { order, coeff }| (order, coeff));
    assert_eq!(s, dissipation, "{name} dissipation");
}

/// Appendix A: Ψ ≅ Φ(1 + Φ²/24) for False/Damped Euler, Ψ ≅ Φ(1 + Φ²/6) for
/// Standard Heun; extended by hand: Standard Euler atan Φ = Φ − Φ³/3;
/// Semi-False Heun tan Ψ = Φ/√(1 − Φ²/2) gives Φ − Φ³/12; False Heun
/// tan Ψ = Φ(1 + 7Φ²/32 + ...) gives Φ − 11Φ³/96. Dissipation from the
/// paper's r² = q: 1 + Φ² (Euler), 1 (False Euler), 1 + Φ⁴/4 (Heun),
/// 1 − Φ²/2 (False Heun), 1 − Φ⁴/4 (Semi-False Heun).
#[test]
fn appendix_a_and_its_extension() {
    check_leading("false_euler", (3, q(1, 24)), None);
    check_leading("damped_euler", (3, q(1, 24)), None);
    check_leading("verlet", (3, q(1, 24)), None);
    check_leading("standard_heun", (3, q(1, 6)), Some((4, q(1, 4))));
    check_leading("standard_euler", (3, q(-1, 3)), Some((2, q(1, 1))));
    check_leading("semi_false_heun", (3, q(-1, 12)), Some((4, q(-1, 4))));
    check_leading("false_heun", (3, q(-11, 96)), Some((2, q(-1, 2))));
    assert_eq!(
        modulus_sq_series(&chi_of("standard_heun"), 6).unwrap(),
        [q(1, 1), q(0, 1), q(0, 1), q(0, 1), q(1, 4), q(0, 1), q(0, 1)]
    );
}

/// Damped Euler with a fixed D: p² − q = Φ²(D² − 1), so Ψ ≈ Φ√(1 − D²);
/// for D = 1/2 that is √3·Φ/2, not a series over Q.
#[test]
fn fixed_damping_gives_a_scaled_series() {
    let chi =
        chi_of("damped_euler_d").eval_partial(&[(Sym::new("D"), q(1, 2))].into_iter().collect());
    let (d, c) = psi_series_scaled(&chi, 3).unwrap();
    assert_eq!((d, c[1].clone()), (q(3, 1), q(1, 2)));
    assert_eq!(psi_series(&chi, 3).unwrap_err().kind(), ErrorKind::IrrationalSeries);
    // D = 3/5: √(1 − D²) = 4/5 is rational.
    let chi =
        chi_of("damped_euler_d").eval_partial(&[(Sym::new("D"), q(3, 5))].into_iter().collect());
    assert_eq!(psi_series(&chi, 1).unwrap()[1], q(4, 5));
}

/// Bad input is an error, not a panic.
#[test]
fn errors() {
    let e = psi_series(&chi_of("damped_euler_d"), 3).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::ExtraSymbol);
    let cubic = Poly::parse("z^3 - Phi").unwrap();
    assert_eq!(psi_series(&cubic, 3).unwrap_err().kind(), ErrorKind::NotSecondOrder);
    // Real roots near Φ = 0: (z − 1)(z − 1 + Phi).
    let real = Poly::parse("(z - 1)*(z - 1 + Phi)").unwrap();
    assert_eq!(psi_series(&real, 3).unwrap_err().kind(), ErrorKind::NotOscillatory);
}

/// Series arithmetic identities: exp(log(1 + x)) = 1 + x, exp(x)·exp(−x) = 1,
/// sqrt(s)² = s, s·s⁻¹ = 1, atan(x/√(1 − x²)) = asin(x).
#[test]
fn series_identities() {
    let n = 12;
    let x = Series::x(n);
    let one = Series::constant(q(1, 1), n);
    assert_eq!(one.add(&x).log().unwrap().exp().unwrap(), one.add(&x));
    assert_eq!(x.exp().unwrap().mul(&x.scale(&q(-1, 1)).exp().unwrap()), one);
    let s = one.add(&x.scale(&q(3, 1))).add(&x.mul(&x));
    let r = s.sqrt().unwrap();
    assert_eq!(r.mul(&r), s);
    assert_eq!(s.mul(&s.inverse().unwrap()), one);
    let t = x.div(&one.sub(&x.mul(&x)).sqrt().unwrap()).unwrap();
    assert_eq!(t.atan().unwrap().truncate(n), x.asin().unwrap().truncate(n));
    // Composition: (1 + x)² at x ↦ 2x is 1 + 4x + 4x².
    let sq = Series::from_upoly(&poly::UPoly::from_ints(&[1, 2, 1]), n);
    assert_eq!(
        sq.compose(&x.scale(&q(2, 1))).unwrap(),
        Series::from_upoly(&poly::UPoly::from_ints(&[1, 4, 4]), n)
    );
}
