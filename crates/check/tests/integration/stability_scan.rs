//! Issue 10's property test, numeric half: on random linear programs (1–3
//! state variables, history up to 2 steps, small rational coefficients,
//! powers of Φ up to 3), the exact analysis of `poly::advanced::stability` agrees with
//! a dense numeric scan of the spectral radius of P(Φ) (eigenvalues, f64)
//! wherever the scan is conclusive: away from the critical points and where
//! |ρ − 1| is well above rounding. The exact half (Jury's test at the
//! rational samples) is in `poly`'s tests.

use check::witness::{eigenvalues_faer, eigenvalues_nalgebra};
use check::{Params, ParamsF64};
use poly::Stability;
use poly::{Method, Q};
use proptest::prelude::*;

use random_program::program;
use testkit::random_program;

/// |ρ − 1| below this is inconclusive in f64: the eigenvalues of a root
/// repeated m times (identically in Φ) are only accurate to about ε^(1/m).
const INCONCLUSIVE: f64 = 1e-4;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn exact_stability_agrees_with_an_eigenvalue_scan(src in program()) {
        let m = Method::parse("gen.zm", &src).map_err(|e| TestCaseError::fail(format!("{e}\n{src}")))?;
        let Ok(d) = poly::derive(&m) else { return Ok(()) };
        let Ok(r) = d.stability(&poly::Params::new()) else { return Ok(()) };
        let critical: Vec<f64> =
            r.critical_points.iter().map(|p| p.at.to_decimal(12).parse().unwrap()).collect();
        for k in 1..=120i64 {
            // Φ = k/40 exactly on the exact side; its nearest f64 numerically.
            let q = Q::new(k.into(), 40.into());
            let phi = k as f64 / 40.0;
            if critical.iter().any(|c| (c - phi).abs() < 1e-3) {
                continue;
            }
            let step = check::numeric::Step::compile(&m, &Params::phi(phi)).unwrap();
            let p = step.transition_matrix();
            // Either eigen-solver; when neither converges the point says nothing.
            let Ok(eig) = eigenvalues_nalgebra(&p).or_else(|_| eigenvalues_faer(&p)) else {
                continue;
            };
            let rho = eig.iter().map(|z| z.norm()).fold(0.0, f64::max);
            if (rho - 1.0).abs() < INCONCLUSIVE {
                continue;
            }
            let interval = r
                .intervals
                .iter()
                .find(|i| i.lo.cmp_rational(&q).is_lt() && i.hi.as_ref().is_none_or(|h| h.cmp_rational(&q).is_gt()))
                .expect("Phi is not a critical point");
            prop_assert_eq!(rho > 1.0, interval.counts.outside > 0, "Phi = {}, rho = {}\n{}", phi, rho, src);
            prop_assert_eq!(rho < 1.0, interval.class.bounded() == Some(true), "Phi = {}, rho = {}\n{}", phi, rho, src);
            let stable_below_max = match &r.stability {
                Stability::BoundedForAllPhi => true,
                Stability::UnboundedForAllPhi | Stability::UnstableNearZero => false,
                Stability::Limited { phi_max, .. } => phi_max.cmp_rational(&q).is_gt(),
                Stability::UndecidedAt { .. } => panic!("the derivation decides every point"),
            };
            if stable_below_max {
                prop_assert!(rho < 1.0, "below Phi_max = {:?} but rho({}) = {}\n{}", r.phi_max(), phi, rho, src);
            }
        }
    }
}
