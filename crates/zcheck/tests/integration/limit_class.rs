//! The class exactly at every critical point where the class changes, on
//! every built-in and every catalogue method (issue 27: no "not computed"
//! anywhere), held against an independent float oracle: the roots of χ at
//! a 40-digit approximation of the point, by the companion matrix's
//! eigenvalues (`check`), classified with tolerances far wider than their
//! error and far narrower than the distances that tell the classes apart.

use std::path::Path;

use check::witness::polynomial_roots;
use num_complex::Complex64;
use poly::{Params, RootClass, Sym, Q};

/// χ(z; Φ) at a float Φ, highest power of z first.
fn chi_at(chi: &poly::Poly, phi: f64) -> Vec<f64> {
    let mut c: Vec<f64> = chi
        .coeffs_in(Sym::z())
        .iter()
        .map(|p| {
            let u = p.to_upoly(Sym::phi()).expect("a polynomial in Phi");
            u.coeffs().iter().rev().fold(0.0, |acc, q| acc * phi + check::numeric::q_to_f64(q))
        })
        .collect();
    c.reverse();
    while c.first().is_some_and(|x| x.abs() < 1e-13) {
        c.remove(0);
    }
    c
}

/// The class a float oracle sees at a point where the dominant modulus is
/// 1 (a stability limit): roots within 1e-6 of the circle are on it; two
/// of them within 1e-5 of each other are a repeated root.
fn float_class_on_circle(roots: &[Complex64]) -> Option<RootClass> {
    let on: Vec<Complex64> =
        roots.iter().copied().filter(|z| (z.norm() - 1.0).abs() < 1e-6).collect();
    if on.is_empty() || roots.iter().any(|z| z.norm() > 1.0 + 1e-6) {
        return None;
    }
    let repeated =
        on.iter().enumerate().any(|(i, a)| on[i + 1..].iter().any(|b| (a - b).norm() < 1e-5));
    Some(if repeated {
        RootClass::DoubleRootOnCircle
    } else if on.iter().any(|z| z.im.abs() > 1e-5) {
        RootClass::Harmonic
    } else if on.iter().any(|z| z.re < 0.0) {
        RootClass::Alternating
    } else {
        RootClass::Constant
    })
}

fn methods() -> Vec<(String, poly::Method)> {
    let mut out: Vec<(String, poly::Method)> = poly::advanced::builtins::BUILTINS
        .iter()
        .map(|(name, _)| {
            (name.to_string(), zcheck::api::load(name).expect("built-in").method().clone())
        })
        .collect();
    for kind in ["rk", "lmm"] {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/nodepy").join(kind);
        let mut files: Vec<_> = std::fs::read_dir(dir)
            .expect("catalogue")
            .map(|e| e.expect("entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .collect();
        files.sort();
        for f in files {
            let m = zcheck::api::load(f.to_str().expect("utf-8")).expect("catalogue file");
            out.push((f.file_stem().unwrap().to_string_lossy().into_owned(), m.method().clone()));
        }
    }
    out
}

#[test]
fn every_class_change_has_its_class_and_the_float_roots_agree_at_the_limits() {
    let mut irrational_limits = 0;
    for (name, method) in methods() {
        if method.params().iter().any(|p| p.name() != "Phi") {
            continue;
        }
        let d = poly::derive(&method).expect("derives");
        let report = match d.stability(&Params::new()) {
            Ok(r) => r,
            Err(e) => panic!("{name}: {e}"),
        };
        for change in &report.class_changes {
            let class = change.at_class.unwrap_or_else(|| {
                panic!(
                    "{name}: no class at Phi = {} ({:?} -> {:?})",
                    change.at, change.from, change.to
                )
            });
            let bounded_side =
                change.from.bounded() == Some(true) || change.to.bounded() == Some(true);
            let limit = bounded_side
                && !(change.from.bounded() == Some(true) && change.to.bounded() == Some(true));
            if !limit || change.at.as_rational().is_some() || d.charpoly().symbols().len() > 2 {
                continue;
            }
            let width =
                (0..40).fold(Q::from_integer(1.into()), |w, _| w / Q::from_integer(10.into()));
            let phi = check::numeric::q_to_f64(&change.at.refine(&width).interval().0);
            // Near Φ = 0 every root is near 1 (SSP63 has a critical point at
            // Φ ≈ 3.6e-8, with roots 1 ± 3.7e-8 i): floats cannot tell a
            // double root there, so the oracle checks Φ ≥ 1e-3 only.
            if phi < 1e-3 {
                continue;
            }
            let roots = polynomial_roots(&chi_at(d.charpoly(), phi)).expect("roots");
            assert_eq!(
                float_class_on_circle(&roots),
                Some(class),
                "{name} at Phi = {} ≈ {phi}: roots {roots:?}",
                change.at
            );
            irrational_limits += 1;
        }
    }
    // ab3–ab8, RK4, the catalogue's Runge–Kutta and Adams methods, ...
    assert!(irrational_limits >= 40, "only {irrational_limits} irrational limits checked");
}
