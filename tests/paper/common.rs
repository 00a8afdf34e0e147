//! Shared helpers of the proof tests: the claims (computed once), exact
//! derivations of the built-ins, the paper's transcriptions parsed, and
//! independent numeric witnesses (roots by the quadratic formula in complex
//! floating point, plain f64 runs of the step matrices).
//!
//! The tests assert what is true by computing it here, independently of the
//! code that builds the claims; then they assert the claim's verdict.

use std::collections::HashMap;
use std::sync::OnceLock;

use num_complex::Complex64;
use poly::{Derivation, Poly, PolyMatrix, Sym, Q};
use zcheck::paper::{Claim, Verdict};

/// Every claim of sections 4–12 and Appendices A–B, built once per test run.
pub fn claims() -> &'static [Claim] {
    static CLAIMS: OnceLock<Vec<Claim>> = OnceLock::new();
    CLAIMS.get_or_init(zcheck::paper::sections::claims)
}

/// The claim with this id.
#[track_caller]
pub fn claim(id: &str) -> &'static Claim {
    claims().iter().find(|c| c.id == id).unwrap_or_else(|| panic!("no claim {id}"))
}

/// Asserts the verdict of every listed claim.
#[track_caller]
pub fn check_verdicts(expected: &[(&str, Verdict)]) {
    for (id, verdict) in expected {
        let c = claim(id);
        assert_eq!(
            c.verdict(),
            *verdict,
            "{id}: derived {:?}, evidence {:?}",
            c.derived,
            c.evidence
        );
        assert!(
            !c.statement.is_empty() && !c.derived.is_empty() && !c.evidence.is_empty(),
            "{id} is incomplete"
        );
    }
}

/// A built-in's derivation.
#[track_caller]
pub fn derive(name: &str) -> Derivation {
    poly::derive(&poly::builtin(name).expect("built-in")).expect("derivation")
}

/// A transcription in `Poly::parse` syntax.
#[track_caller]
pub fn parse(text: &str) -> Poly {
    Poly::parse(text).unwrap_or_else(|e| panic!("{text:?}: {e}"))
}

/// `p` and `q` of χ = z² − 2pz + q.
#[track_caller]
pub fn p_q(name: &str) -> (Poly, Poly) {
    derive(name).p_q().expect("second order")
}

/// A polynomial in Φ (and other named parameters) in floating point.
pub fn eval(p: &Poly, values: &[(&str, f64)]) -> f64 {
    p.terms()
        .map(|(m, c)| {
            let c = c.numer().to_string().parse::<f64>().unwrap()
                / c.denom().to_string().parse::<f64>().unwrap();
            m.factors().iter().fold(c, |acc, (s, e)| {
                let x = values
                    .iter()
                    .find(|(n, _)| *n == s.name())
                    .map(|(_, x)| *x)
                    .expect("value given");
                acc * x.powi(*e as i32)
            })
        })
        .sum()
}

/// A polynomial at a rational Φ.
pub fn at(p: &Poly, phi: &Q) -> Q {
    p.eval(&HashMap::from([(Sym::phi(), phi.clone())])).expect("a polynomial in Phi")
}

/// The two roots of z² − 2pz + q in complex floating point.
pub fn roots(p: f64, q: f64) -> [Complex64; 2] {
    let disc = Complex64::new(p * p - q, 0.0).sqrt();
    [Complex64::new(p, 0.0) + disc, Complex64::new(p, 0.0) - disc]
}

/// The numeric roots of a built-in's χ at Φ.
pub fn roots_at(name: &str, phi: f64) -> [Complex64; 2] {
    let (p, q) = p_q(name);
    roots(eval(&p, &[("Phi", phi)]), eval(&q, &[("Phi", phi)]))
}

/// The transition matrix of a built-in at Φ in floating point.
pub fn matrix_f64(name: &str, phi: f64) -> Vec<Vec<f64>> {
    let p = derive(name).transition_matrix().clone();
    (0..p.rows()).map(|i| p.row(i).iter().map(|e| eval(e, &[("Phi", phi)])).collect()).collect()
}

/// `n` steps of x ← P x in floating point; the states x_0..x_n.
pub fn run(p: &[Vec<f64>], x0: &[f64], n: usize) -> Vec<Vec<f64>> {
    let mut out = vec![x0.to_vec()];
    for _ in 0..n {
        let x = out.last().unwrap();
        out.push(p.iter().map(|r| r.iter().zip(x).map(|(a, b)| a * b).sum()).collect());
    }
    out
}

/// `n` exact steps of x ← P x.
pub fn run_exact(p: &PolyMatrix, phi: &Q, x0: &[Q], n: usize) -> Vec<Vec<Q>> {
    let m: Vec<Vec<Q>> =
        (0..p.rows()).map(|i| p.row(i).iter().map(|e| at(e, phi)).collect()).collect();
    let mut out = vec![x0.to_vec()];
    for _ in 0..n {
        let x = out.last().unwrap();
        out.push(
            m.iter()
                .map(|r| r.iter().zip(x).fold(poly::q(0, 1), |acc, (a, b)| acc + a * b))
                .collect(),
        );
    }
    out
}

/// The largest modulus of the roots: the growth factor per step.
pub fn spectral_radius(name: &str, phi: f64) -> f64 {
    roots_at(name, phi).iter().map(|z| z.norm()).fold(0.0, f64::max)
}

/// Ψ(Φ) = the argument of the upper root, when the roots are complex.
pub fn psi(name: &str, phi: f64) -> Option<f64> {
    let [z, _] = roots_at(name, phi);
    (z.im.abs() > 0.0).then(|| z.im.abs().atan2(z.re))
}

/// The order k of the error of an approximation f(Φ) ≈ g(Φ): the slope of
/// log|f − g| between Φ and Φ/2 (error ~ c·Φ^k).
pub fn error_order(f: impl Fn(f64) -> f64, g: impl Fn(f64) -> f64, phi: f64) -> f64 {
    let e1 = (f(phi) - g(phi)).abs();
    let e2 = (f(phi / 2.0) - g(phi / 2.0)).abs();
    if e1 <= 64.0 * f64::EPSILON && e2 <= 64.0 * f64::EPSILON {
        // An identity: no error to measure.
        return f64::INFINITY;
    }
    (e1 / e2).log2()
}

/// The claim ids a test module covers, gathered for the coverage test.
pub fn all_covered() -> Vec<&'static str> {
    let mut v = Vec::new();
    for list in [
        crate::sec04_z_transform::COVERED,
        crate::sec05_standard_euler::COVERED,
        crate::sec06_damped_euler::COVERED,
        crate::sec07_false_euler::COVERED,
        crate::sec08_verlet::COVERED,
        crate::sec09_standard_heun::COVERED,
        crate::sec10_false_heun::COVERED,
        crate::sec11_semi_false_heun::COVERED,
        crate::sec12_conclusions::COVERED,
        crate::app_a_taylor::COVERED,
        crate::app_b_source::COVERED,
    ] {
        v.extend(list.iter().map(|(id, _)| *id));
    }
    v
}

/// Every claim of sections 4–12 and Appendices A and B is checked by some
/// test module, and no module lists a claim that does not exist.
#[test]
fn every_claim_is_covered() {
    let covered = all_covered();
    for c in claims() {
        assert!(covered.contains(&c.id.as_str()), "claim {} has no test", c.id);
    }
    for id in &covered {
        assert!(claims().iter().any(|c| c.id == *id), "test lists unknown claim {id}");
    }
    let sections: Vec<&str> = claims().iter().map(|c| c.section.as_str()).collect();
    for s in ["4", "5", "6", "7", "8", "9", "10", "11", "12", "A", "B"] {
        assert!(sections.contains(&s), "section {s} has no claim");
    }
}

/// One step of Appendix B's "Direct Integration" branch, transcribed from
/// the Pascal by hand (independent of the `.zm` built-ins): (v, y) → (v, y).
pub fn pascal_step(name: &str, v0: f64, y0: f64, wot: f64) -> (f64, f64) {
    match name {
        "standard_euler" => (v0 - wot * y0, y0 + wot * v0),
        "damped_euler" => {
            let d = 0.5 * wot;
            (v0 - wot * (y0 + 2.0 * d * v0), y0 + wot * v0)
        }
        "false_euler" => {
            let v1 = v0 - wot * y0;
            (v1, y0 + wot * v1)
        }
        "standard_heun" => {
            let dv1 = -wot * y0;
            let v11 = v0 + dv1;
            let dy1 = wot * v0;
            let y11 = y0 + dy1;
            let dv2 = -wot * y11;
            let dy2 = wot * v11;
            (v0 + 0.5 * (dv1 + dv2), y0 + 0.5 * (dy1 + dy2))
        }
        "false_heun" => {
            let dv1 = -wot * y0;
            let v11 = v0 + dv1;
            let dy1 = wot * v11;
            let y11 = y0 + dy1;
            let dv2 = -wot * y11;
            let v12 = v0 + dv2;
            let dy2 = wot * v12;
            (v0 + 0.5 * (dv1 + dv2), y0 + 0.5 * (dy1 + dy2))
        }
        "semi_false_heun" => {
            let dv1 = -wot * y0;
            let dy1 = wot * v0;
            let y11 = y0 + dy1;
            let dv2 = -wot * y11;
            let v12 = v0 + dv2;
            let dy2 = wot * v12;
            (v0 + 0.5 * (dv1 + dv2), y0 + 0.5 * (dy1 + dy2))
        }
        _ => panic!("no Pascal transcription for {name}"),
    }
}

/// The transition matrix of the Pascal step at Φ, column j = step from e_j.
pub fn pascal_matrix(name: &str, phi: f64) -> [[f64; 2]; 2] {
    let (a, b) = pascal_step(name, 1.0, 0.0, phi);
    let (c, d) = pascal_step(name, 0.0, 1.0, phi);
    [[a, c], [b, d]]
}

/// The sample points of Φ used by the numeric witnesses: small, medium and
/// beyond every stability limit of the paper.
pub const PHIS: [f64; 6] = [0.05, 0.3, 0.9, 1.3, 1.7, 2.6];

/// A printed characteristic equation z² − 2pz + q is what the Pascal
/// program obeys: its y samples satisfy y_(n+2) − 2p y_(n+1) + q y_n = 0
/// (Cayley–Hamilton), and it equals the exact derivation.
#[track_caller]
pub fn check_charpoly(name: &str, printed: &str) {
    let chi = parse(printed);
    assert_eq!(&chi, derive(name).charpoly(), "{name}: printed χ vs derivation");
    let c = chi.coeffs_in(Sym::z());
    assert_eq!(c.len(), 3, "second order");
    for phi in PHIS {
        let (q, minus_2p) = (eval(&c[0], &[("Phi", phi)]), eval(&c[1], &[("Phi", phi)]));
        for start in [(1.0, 0.0), (0.0, 1.0)] {
            let mut ys = vec![start];
            for _ in 0..12 {
                let (v, y) = *ys.last().unwrap();
                ys.push(pascal_step(name, v, y, phi));
            }
            for n in 0..10 {
                let (a, b, c2) = (ys[n].1, ys[n + 1].1, ys[n + 2].1);
                let scale = a.abs() + b.abs() * minus_2p.abs() + c2.abs() + 1.0;
                let residual = c2 + minus_2p * b + q * a;
                assert!(
                    residual.abs() <= 64.0 * f64::EPSILON * scale,
                    "{name} Φ={phi} n={n}: {residual}"
                );
            }
        }
    }
}

/// Printed z-domain rows (coefficients of v z⁻¹ and y z⁻¹) against the
/// Pascal step at several Φ. Returns, per row and column, whether the
/// printed coefficient matches.
pub fn z_rows_match(name: &str, rows: [[&str; 2]; 2]) -> [[bool; 2]; 2] {
    let mut ok = [[true; 2]; 2];
    for phi in PHIS {
        let m = pascal_matrix(name, phi);
        for i in 0..2 {
            for j in 0..2 {
                let printed = eval(&parse(rows[i][j]), &[("Phi", phi)]);
                if (printed - m[i][j]).abs() > 16.0 * f64::EPSILON * (1.0 + printed.abs()) {
                    ok[i][j] = false;
                }
            }
        }
    }
    ok
}

/// Printed eigenvalues p ± j·sqrt(im²) are the roots of the derived χ at
/// every Φ where im² > 0 (numeric, independent quadratic formula).
#[track_caller]
pub fn check_eigenvalues(name: &str, re: &str, im_sq: &str) {
    let (re, im_sq) = (parse(re), parse(im_sq));
    for phi in PHIS {
        let (a, b2) = (eval(&re, &[("Phi", phi)]), eval(&im_sq, &[("Phi", phi)]));
        if b2 <= 0.0 {
            continue;
        }
        let m = pascal_matrix(name, phi);
        let (tr, det) = (m[0][0] + m[1][1], m[0][0] * m[1][1] - m[0][1] * m[1][0]);
        let z = Complex64::new(a, b2.sqrt());
        let chi = z * z - tr * z + det;
        assert!(
            chi.norm() <= 64.0 * f64::EPSILON * (1.0 + tr.abs() + det.abs()) * (1.0 + z.norm_sqr()),
            "{name} Φ={phi}"
        );
    }
}

/// r² of a conjugate pair: the modulus of the Pascal matrix's eigenvalues
/// squared equals the printed r² wherever the roots are complex.
#[track_caller]
pub fn check_r_squared(name: &str, printed: &str) {
    let r2 = parse(printed);
    let mut complex_seen = false;
    for phi in PHIS {
        let m = pascal_matrix(name, phi);
        let (tr, det) = (m[0][0] + m[1][1], m[0][0] * m[1][1] - m[0][1] * m[1][0]);
        let [z, _] = roots(tr / 2.0, det);
        if z.im != 0.0 {
            complex_seen = true;
            let want = eval(&r2, &[("Phi", phi)]);
            assert!(
                (z.norm_sqr() - want).abs() <= 64.0 * f64::EPSILON * (1.0 + want),
                "{name} Φ={phi}"
            );
        }
    }
    assert!(complex_seen, "{name}: no complex pair among the sample Φ");
}

/// The numeric growth of the Pascal program over many steps: the largest
/// |y| over the last `n / 4` of `n` steps from (0, 1).
pub fn late_amplitude(name: &str, phi: f64, n: usize) -> f64 {
    let (mut v, mut y) = (0.0, 1.0);
    let mut late: f64 = 0.0;
    for k in 0..n {
        (v, y) = pascal_step(name, v, y, phi);
        if k >= n - n / 4 {
            late = late.max(y.abs()).max(v.abs());
        }
    }
    late
}

/// max |state| over the last quarter of `n` Pascal steps from (0, 1),
/// divided by the max over the first quarter: about 1 for a bounded
/// sequence, large for a growing one.
pub fn growth_ratio(name: &str, phi: f64, n: usize) -> f64 {
    let (mut v, mut y) = (0.0f64, 1.0f64);
    let (mut early, mut late) = (0.0f64, 0.0f64);
    for k in 0..n {
        (v, y) = pascal_step(name, v, y, phi);
        let size = v.abs().max(y.abs());
        if k < n / 4 {
            early = early.max(size);
        } else if k >= n - n / 4 {
            late = late.max(size);
        }
    }
    late / early
}
