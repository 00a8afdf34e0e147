//! The w-plane (y' = λy, w = hλ): exact answers against slow, independent
//! oracles — floating-point roots of χ(z, w) at points of the plane, a
//! boundary-locus scan for A(α), series by long division for the order and
//! error constant — and against closed forms.

use num_complex::Complex64 as C64;
use num_traits::{One, ToPrimitive, Zero};
use poly::{q, Algebraic, Derivation, Method, Params, PlaneReport, Poly, Sector, Sym, Q};

fn derivation(name: &str) -> Derivation {
    poly::derive(&poly::builtin(name).expect("a built-in")).expect("derives")
}

fn plane(d: &Derivation) -> PlaneReport {
    d.plane(&Params::new()).expect("a plane report")
}

fn f(x: &Q) -> f64 {
    x.to_f64().expect("finite")
}

fn alg(x: &Algebraic) -> f64 {
    f(&x.approx(&q(1, 1_000_000_000_000)))
}

/// χ(z, w) as complex coefficients in z (lowest first) at a complex w.
fn chi_at(chi: &Poly, w: C64) -> Vec<C64> {
    chi.coeffs_in(Sym::z())
        .iter()
        .map(|c| {
            c.coeffs_in(Sym::w())
                .iter()
                .enumerate()
                .map(|(k, a)| {
                    let a = a.as_constant().expect("rational χ in these tests");
                    w.powu(k as u32) * f(&a)
                })
                .sum()
        })
        .collect()
}

/// The roots of a complex polynomial (Durand–Kerner, then Newton polish):
/// slow and obvious, and independent of everything in poly.
fn roots(c: &[C64]) -> Vec<C64> {
    let mut c = c.to_vec();
    while c.last().is_some_and(|x| x.norm() == 0.0) {
        c.pop();
    }
    let n = c.len() - 1;
    let lead = c[n];
    let c: Vec<C64> = c.iter().map(|x| x / lead).collect();
    let eval = |z: C64| c.iter().rev().fold(C64::zero(), |acc, a| acc * z + a);
    let deval = |z: C64| {
        c.iter().enumerate().skip(1).rev().fold(C64::zero(), |acc, (k, a)| acc * z + a * k as f64)
    };
    let mut r: Vec<C64> = (0..n).map(|k| C64::new(0.4, 0.9).powu(k as u32)).collect();
    for _ in 0..2000 {
        for i in 0..n {
            let mut den = C64::one();
            for j in 0..n {
                if i != j {
                    den *= r[i] - r[j];
                }
            }
            let step = eval(r[i]) / den;
            r[i] -= step;
        }
    }
    for z in r.iter_mut() {
        for _ in 0..5 {
            let d = deval(*z);
            if d.norm() > 0.0 {
                *z -= eval(*z) / d;
            }
        }
    }
    r
}

fn max_modulus(chi: &Poly, w: C64) -> f64 {
    roots(&chi_at(chi, w)).iter().map(|z| z.norm()).fold(0.0, f64::max)
}

/// The root condition, numerically, with a margin: every |z| ≤ 1 + tol.
fn stable_at(chi: &Poly, w: C64, tol: f64) -> bool {
    max_modulus(chi, w) <= 1.0 + tol
}

/// A limit along a direction checked against the oracle: stable at 99.9%
/// of it, unstable at 100.1% (or stable far out when there is none).
#[track_caller]
fn check_limit(name: &str, chi: &Poly, limit: &Option<Algebraic>, dir: C64) {
    match limit {
        None => {
            for r in [1e-3, 0.5, 3.0, 40.0, 1e3] {
                assert!(stable_at(chi, dir * r, 1e-9), "{name}: unstable at {}", dir * r);
            }
        }
        Some(l) if l.sign().is_eq() => {
            // Unstable just after 0; near 0 the growth is tiny (|z| − 1 ~
            // r^(p+1)), so probe where floats resolve it.
            assert!(
                [0.05, 0.1, 0.2].iter().any(|&r| !stable_at(chi, dir * r, 1e-12)),
                "{name}: stable near 0 along {dir}"
            );
        }
        Some(l) => {
            let l = alg(l);
            assert!(stable_at(chi, dir * (l * 0.999), 1e-9), "{name}: unstable below {l}");
            assert!(!stable_at(chi, dir * (l * 1.001), 1e-12), "{name}: stable above {l}");
        }
    }
}

/// The methods with a scalar form: every built-in that treats y and v
/// alike.
fn scalar_builtins() -> Vec<(&'static str, Derivation)> {
    poly::advanced::builtins::all_builtin_names()
        .filter_map(|n| {
            let d = derivation(n);
            d.scalar_charpoly(&Params::new()).ok().map(|_| (n, d))
        })
        .collect()
}

#[test]
fn the_axes_limits_agree_with_the_roots_on_every_builtin() {
    let all = scalar_builtins();
    assert!(all.len() >= 25, "only {} built-ins have a scalar form", all.len());
    for (name, d) in &all {
        let r = plane(d);
        if r.charpoly.symbols().iter().any(|s| s.name().contains('(')) {
            continue; // exact constants: the numeric oracle reads rationals
        }
        check_limit(name, &r.charpoly, &r.real_limit, C64::new(-1.0, 0.0));
        check_limit(name, &r.charpoly, &r.imag_limit, C64::new(0.0, 1.0));
    }
}

/// e^w − R(w) by long division of the series of P/Q: the order and error
/// constant of a one-step method, independently of the root's lifting.
fn one_step_error(chi: &Poly) -> (u32, Q) {
    let cz = chi.coeffs_in(Sym::z());
    let coeffs = |p: &Poly| -> Vec<Q> {
        p.coeffs_in(Sym::w()).iter().map(|c| c.as_constant().unwrap()).collect()
    };
    let (qc, pc) = (coeffs(&cz[1]), coeffs(&-&cz[0]));
    let get = |v: &Vec<Q>, k: usize| v.get(k).cloned().unwrap_or_default();
    let mut r: Vec<Q> = Vec::new();
    let mut fact = Q::one();
    for n in 0..30 {
        // Q·R = P: r_n = (p_n − Σ_{k≥1} q_k r_{n−k}) / q_0.
        let mut acc = get(&pc, n);
        for k in 1..=n {
            acc -= get(&qc, k) * &r[n - k];
        }
        r.push(acc / &qc[0]);
        if n > 0 {
            fact *= Q::from_integer((n as i64).into());
        }
        let d = Q::one() / &fact - &r[n];
        if !d.is_zero() {
            return (n as u32 - 1, d);
        }
    }
    panic!("no error term")
}

#[test]
fn order_and_error_constant_of_one_step_methods_match_long_division() {
    let mut checked = 0;
    for (name, d) in scalar_builtins() {
        let r = plane(&d);
        if r.charpoly.degree_in(Sym::z()) != 1 || poly::advanced::field::has_generators(&r.charpoly)
        {
            continue;
        }
        let (p, c) = one_step_error(&r.charpoly);
        assert_eq!(r.order, Some(p), "{name}");
        assert_eq!(r.error_constant.as_ref().and_then(Poly::as_constant), Some(c), "{name}");
        checked += 1;
    }
    assert!(checked >= 12, "{checked}");
}

/// BDF k: ρ(z) = Σ_{j=1..k} (1/j) z^(k−j) (z − 1)^j, σ(z) = z^k.
fn bdf(k: usize) -> (Vec<Q>, Vec<Q>) {
    let mut rho = vec![Q::zero(); k + 1];
    for j in 1..=k {
        // z^(k−j) (z − 1)^j
        let mut p = vec![Q::one()];
        for _ in 0..j {
            let mut next = vec![Q::zero(); p.len() + 1];
            for (i, c) in p.iter().enumerate() {
                next[i + 1] += c;
                next[i] -= c;
            }
            p = next;
        }
        for (i, c) in p.iter().enumerate() {
            rho[i + k - j] += c / Q::from_integer((j as i64).into());
        }
    }
    let mut sigma = vec![Q::zero(); k + 1];
    sigma[k] = Q::one();
    (rho, sigma)
}

fn multistep(name: &str, alpha: &[Q], beta: &[Q]) -> Derivation {
    let a: Vec<String> = alpha.iter().map(|x| x.to_string()).collect();
    let b: Vec<String> = beta.iter().map(|x| x.to_string()).collect();
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    let b: Vec<&str> = b.iter().map(String::as_str).collect();
    poly::derive(&Method::from_multistep(name, &a, &b).expect("coefficients")).expect("derives")
}

/// The classical C_{p+1} = Σ_j (α_j j^(p+1)/(p+1)! − β_j j^p/p!), over σ(1).
fn multistep_error(alpha: &[Q], beta: &[Q]) -> (u32, Q) {
    let pow = |j: usize, e: usize| Q::from_integer((j as i64).pow(e as u32).into());
    let mut fact = vec![Q::one()];
    for n in 1..40 {
        let last = fact[n - 1].clone();
        fact.push(last * Q::from_integer((n as i64).into()));
    }
    let sigma1: Q = beta.iter().sum();
    for p in 0..30usize {
        let c: Q = (0..alpha.len())
            .map(|j| &alpha[j] * pow(j, p + 1) / &fact[p + 1] - &beta[j] * pow(j, p) / &fact[p])
            .sum();
        if !c.is_zero() {
            return (p as u32, c / sigma1);
        }
    }
    panic!("no error term")
}

/// Hairer & Wanner, Solving ODEs II, Table V.2.3: A(α) of BDF 1–6, as printed.
const HAIRER_WANNER_BDF_ALPHA: [f64; 6] = [90.0, 90.0, 86.03, 73.35, 51.84, 17.84];

/// min over the boundary locus in Re w < 0 of |arg(−w)|, by a fine scan of
/// θ with golden-section polish: the floating-point oracle for A(α).
fn locus_alpha(rho: &[Q], sigma: &[Q]) -> f64 {
    let ev = |c: &[Q], z: C64| c.iter().rev().fold(C64::zero(), |acc, a| acc * z + f(a));
    let angle = |t: f64| {
        let z = C64::from_polar(1.0, t);
        let w = ev(rho, z) / ev(sigma, z);
        if w.re < 0.0 {
            (w.im / w.re).abs().atan().to_degrees()
        } else {
            90.0
        }
    };
    let n = 200_000;
    let (mut best, mut at) = (90.0, 0.0);
    for i in 1..n {
        let t = std::f64::consts::PI * i as f64 / n as f64;
        let a = angle(t);
        if a < best {
            (best, at) = (a, t);
        }
    }
    let h = std::f64::consts::PI / n as f64;
    let (mut lo, mut hi) = (at - h, at + h);
    for _ in 0..100 {
        let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
        if angle(m1) < angle(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    best.min(angle((lo + hi) / 2.0))
}

fn alpha_degrees(s: &Sector) -> f64 {
    match s {
        Sector::Empty => 0.0,
        Sector::HalfPlane => 90.0,
        Sector::Angle { tan } => alg(tan).atan().to_degrees(),
    }
}

#[test]
fn bdf_one_to_six_against_hairer_wanner_and_the_boundary_locus() {
    for k in 1..=6 {
        let (rho, sigma) = bdf(k);
        let d = multistep(&format!("bdf{k}"), &rho, &sigma);
        let r = plane(&d);
        let alpha = alpha_degrees(&r.a_alpha);
        let printed = HAIRER_WANNER_BDF_ALPHA[k - 1];
        assert!((alpha - printed).abs() < 0.005 + 1e-12, "BDF{k}: {alpha} against {printed}");
        assert!((alpha - locus_alpha(&rho, &sigma)).abs() < 1e-7, "BDF{k}: {alpha}");
        assert_eq!(r.a_stable, k <= 2, "BDF{k}");
        assert_eq!(r.l_stable, k <= 2, "BDF{k}");
        assert_eq!(r.rho_inf.as_ref().map(|x| x.sign().is_eq()), Some(true), "BDF{k} ρ∞ = 0");
        assert_eq!(r.real_limit, None, "BDF{k} is stable on the negative axis");
        assert_eq!((r.order, r.error_constant.and_then(|c| c.as_constant())), {
            let (p, c) = multistep_error(&rho, &sigma);
            (Some(p), Some(c))
        });
        assert_eq!(r.order, Some(k as u32));
    }
}

/// Adams–Bashforth 2 and 3 from their coefficients: the same plane as the
/// built-ins written as history programs.
#[test]
fn multistep_coefficients_and_history_programs_agree() {
    let ab2 = multistep("ab2c", &[q(0, 1), q(-1, 1), q(1, 1)], &[q(-1, 2), q(3, 2), q(0, 1)]);
    let (a, b) = (plane(&ab2), plane(&derivation("ab2")));
    assert_eq!(a.charpoly, b.charpoly);
    assert_eq!((a.order, a.real_limit, a.imag_limit), (b.order, b.real_limit, b.imag_limit));
    let (p, c) = multistep_error(&[q(0, 1), q(-1, 1), q(1, 1)], &[q(-1, 2), q(3, 2), q(0, 1)]);
    assert_eq!((a.order, a.error_constant.and_then(|c| c.as_constant())), (Some(p), Some(c)));
}

/// ρ∞ against the largest root modulus at |w| = 10⁸, for every method whose
/// roots stay finite.
#[test]
fn rho_inf_matches_the_roots_far_out() {
    let mut checked = 0;
    for (name, d) in scalar_builtins() {
        let r = plane(&d);
        if poly::advanced::field::has_generators(&r.charpoly) {
            continue;
        }
        // Roots tend to their limits like |w|^(−1/k): far out, and loosely.
        let far = max_modulus(&r.charpoly, C64::new(-1e16, 3e15));
        match &r.rho_inf {
            Some(x) => {
                assert!((alg(x) - far).abs() < 1e-2, "{name}: ρ∞ {} against {far}", alg(x));
                checked += 1;
            }
            None => assert!(far > 1e3, "{name}: a root should escape, max |z| = {far}"),
        }
    }
    assert!(checked >= 8, "{checked}");
}

/// A-stability against a polar grid of the left half-plane.
#[test]
fn a_stability_against_a_grid_of_the_left_half_plane() {
    for (name, d) in scalar_builtins() {
        let r = plane(&d);
        if poly::advanced::field::has_generators(&r.charpoly) {
            continue;
        }
        let mut all = true;
        for i in 0..60 {
            let rad = 10f64.powf(-3.0 + 7.0 * i as f64 / 59.0);
            for j in 0..=40 {
                let phi = std::f64::consts::PI * (0.5 + j as f64 / 40.0);
                if !stable_at(&r.charpoly, C64::from_polar(rad, phi), 1e-9) {
                    all = false;
                }
            }
        }
        assert_eq!(r.a_stable, all, "{name}");
    }
}

#[test]
fn closed_forms() {
    let euler = plane(&derivation("standard_euler"));
    assert_eq!(euler.charpoly.to_string(), "z - 1 - w");
    assert_eq!((euler.order, euler.real_limit.unwrap().to_string()), (Some(1), "2".into()));
    assert_eq!(euler.imag_limit.unwrap().to_string(), "0");
    assert_eq!((euler.a_alpha, euler.rho_inf), (Sector::Empty, None));
    let rk4 = plane(&derivation("rk4"));
    assert_eq!(rk4.imag_limit.unwrap().to_string(), "2*sqrt(2)");
    let leapfrog = plane(&derivation("leapfrog"));
    assert_eq!(leapfrog.imag_limit.unwrap().to_string(), "1");
    assert_eq!(leapfrog.real_limit.unwrap().to_string(), "0");
    // Gauss–Legendre 2: |R(iy)| = 1 on the whole axis, though R(±2√3 i) = −1.
    let gl2 = plane(&derivation("gauss_legendre_2"));
    assert!(gl2.a_stable && !gl2.l_stable && gl2.imag_limit.is_none());
    assert_eq!(gl2.rho_inf.unwrap().to_string(), "1");
    // SDIRK 2 (γ = 1 − 1/√2), with its constant: L-stable.
    let sdirk = plane(&derivation("sdirk2"));
    assert!(sdirk.a_stable && sdirk.l_stable, "{sdirk:?}");
    assert_eq!(sdirk.order, Some(2));
}

#[test]
fn partitioned_methods_have_no_scalar_form() {
    for name in ["false_euler", "verlet", "semi_false_heun", "forest_ruth", "newmark_linear"] {
        let e = derivation(name).plane(&Params::new()).unwrap_err();
        assert_eq!(e.kind(), poly::ErrorKind::TestEquation, "{name}: {e}");
    }
}

#[test]
fn a_scalar_program_reads_w() {
    let m = Method::parse("be.zm", "method be\nstate y\ny' = y + w*y'\n").unwrap();
    assert!(m.is_scalar());
    let d = poly::derive(&m).unwrap();
    let r = plane(&d);
    assert!(r.a_stable && r.l_stable);
    assert_eq!(d.stability(&Params::new()).unwrap_err().kind(), poly::ErrorKind::TestEquation);
    let mixed = Method::parse("m.zm", "method m\nstate y\ny = y + Phi*y + w*y\n").unwrap_err();
    assert_eq!((mixed.span().line, mixed.span().col), (3, 17), "{mixed}");
}

#[test]
fn multistep_input_errors() {
    let e = |a: &[&str], b: &[&str]| Method::from_multistep("m", a, b).unwrap_err().to_string();
    assert!(e(&["-1", "1"], &["1"]).contains("alpha has 2 coefficients and beta 1"));
    assert!(e(&["-1", "1"], &["0", "0"]).contains("beta is all zero"));
    assert!(e(&["-1", "0"], &["1", "0"]).contains("alpha[1]"));
    assert!(e(&["-1", "x"], &["1", "0"]).starts_with("alpha[1]:"));
}
