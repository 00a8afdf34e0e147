//! The README's library route, through the front door, on every built-in,
//! gives the same Φ_max and boundedness as `zcheck stability`; Gauss–Legendre
//! 2 comes out stable for every Φ.

use std::process::Command;

use poly::{q, Params, Stability};

/// The parameters a built-in has besides Φ, each at 1/10.
fn params_of(d: &poly::Derivation) -> Vec<String> {
    d.method()
        .params()
        .iter()
        .map(|s| s.name())
        .filter(|n| *n != "Phi")
        .map(str::to_owned)
        .collect()
}

#[test]
fn the_library_route_gives_the_cli_answer_on_every_builtin() {
    let mut checked = 0;
    for name in poly::advanced::builtins::all_builtin_names() {
        // The README's example, with the method's parameters bound.
        let d = poly::derive(&poly::Method::builtin(name).unwrap()).unwrap();
        let mut params = Params::new();
        let mut args =
            vec!["stability".to_owned(), name.to_owned(), "--format".into(), "json".into()];
        for p in params_of(&d) {
            params.insert(&p, q(1, 10));
            args.push("--param".into());
            args.push(format!("{p}=1/10"));
        }
        let report = d.stability(&params).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_zcheck")).args(&args).output().unwrap();
        assert!(out.status.success(), "{name}: {}", String::from_utf8_lossy(&out.stderr));
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(json["stability"], report.stability.name(), "{name}");
        assert_eq!(
            json["bounded_at_phi_max"],
            serde_json::json!(report.bounded_at_phi_max()),
            "{name}"
        );
        match report.phi_max() {
            Some(m) => {
                let cli = json["phi_max"].as_f64().unwrap();
                let lib: f64 = m.to_decimal(17).parse().unwrap();
                assert!((cli - lib).abs() <= 1e-15 * lib.max(1.0), "{name}: {cli} against {lib}");
            }
            None => assert!(json["phi_max"].is_null(), "{name}"),
        }
        assert!(!matches!(report.stability, Stability::UndecidedAt { .. }), "{name}");
        checked += 1;
    }
    assert!(checked >= 40, "only {checked} built-ins");
}

/// Gauss–Legendre 2 is A-stable: bounded for every Φ, through Φ = 2√3
/// where P = −I (the bare χ cannot tell, the derivation can).
#[test]
fn gauss_legendre_2_is_stable_for_every_phi_by_both_routes() {
    let d = poly::derive(&poly::Method::builtin("gauss_legendre_2").unwrap()).unwrap();
    assert_eq!(d.stability(&Params::new()).unwrap().stability, Stability::BoundedForAllPhi);
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(["stability", "gauss_legendre_2", "--format", "json"])
        .output()
        .unwrap();
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["stability"], "bounded_for_all_phi");
}
