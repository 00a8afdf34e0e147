//! `zcheck advise --scene FILE --solver ...` end to end: one configuration's
//! document (its fields, its cost S·N·constraints, its modes), the search's
//! recommendation or reason, and bad flags as clean errors (exit 2, the
//! flag named, no panic).

use std::process::Command;

use serde_json::Value;

fn zcheck(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("zcheck runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn scene(name: &str) -> String {
    format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// One configuration: the fields of the contract, the cost counted
/// as substeps × iterations × constraints, one mode per non-rigid degree of
/// freedom, and the stability verdict consistent with the stated radius.
#[test]
fn one_configuration_document() {
    let chain = scene("chain10.toml");
    for (solver, s, n) in [("xpbd", 4, 2), ("xpbd_jacobi", 3, 5), ("soft_step", 8, 1)] {
        let (code, out, err) = zcheck(&[
            "advise",
            "--scene",
            &chain,
            "--solver",
            solver,
            "--substeps",
            &s.to_string(),
            "--iterations",
            &n.to_string(),
            "--format",
            "json",
        ]);
        assert_eq!(code, 0, "{solver}: {err}");
        let v: Value = serde_json::from_str(&out).expect("JSON");
        assert_eq!(v["solver"], solver);
        assert_eq!(v["substeps"], s);
        assert_eq!(v["iterations"], n);
        let constraints = v["constraints"].as_u64().unwrap();
        assert_eq!(v["cost"].as_u64(), Some(s * n * constraints), "{solver}");
        let rho = v["spectral_radius"]["non_rigid"].as_f64().unwrap();
        if v["stable"] == true {
            assert!(rho <= 1.0 + 1e-12, "{solver}: stable with rho {rho}");
        }
        let modes = v["modes"].as_array().unwrap();
        assert_eq!(
            modes.len() as u64 + v["rigid_modes"].as_u64().unwrap(),
            v["dof"].as_u64().unwrap()
        );
        for m in modes {
            assert!(m["effective_hz"].as_f64().unwrap() >= 0.0);
            assert!(m["hz"].as_f64().unwrap() > 0.0);
        }
    }
}

/// Without --substeps and --iterations the search answers: a recommendation
/// that is a stable, accurate candidate of least cost, or none with a reason.
#[test]
fn the_search_recommends_the_cheapest_passing_candidate_or_says_why_not() {
    let (code, out, err) = zcheck(&[
        "advise",
        "--scene",
        &scene("spring_120hz.toml"),
        "--solver",
        "xpbd",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).expect("JSON");
    let passing: Vec<&Value> = v["candidates"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c["stable"] == true && c["meets_accuracy"] == true)
        .collect();
    match v["recommended"].as_object() {
        Some(r) => {
            let least = passing.iter().map(|c| c["cost"].as_u64().unwrap()).min().unwrap();
            let chosen = passing
                .iter()
                .find(|c| c["substeps"] == r["substeps"] && c["iterations"] == r["iterations"])
                .expect("the recommendation is a passing candidate");
            assert_eq!(chosen["cost"].as_u64(), Some(least));
        }
        None => {
            assert!(passing.is_empty(), "{passing:?}");
            assert!(v["reason"].as_str().is_some_and(|r| !r.is_empty()), "{out}");
        }
    }
}

/// Bad flags: exit 2, the flag named, no panic.
#[test]
fn bad_solver_flags_are_clean_errors() {
    let chain = scene("chain10.toml");
    for (args, flag) in [
        (vec!["--solver", "pbd"], "--solver"),
        (vec!["--solver", "xpbd", "--substeps", "3", "--iterations", "0"], "--iterations"),
        (vec!["--solver", "xpbd", "--substeps", "0", "--iterations", "1"], "--substeps"),
        (vec!["--solver", "xpbd", "--substeps", "-2", "--iterations", "1"], "--substeps"),
        (vec!["--solver", "soft_step", "--substeps", "4", "--iterations", "2"], "--iterations"),
    ] {
        let mut all = vec!["advise", "--scene", chain.as_str()];
        all.extend(&args);
        let (code, _, err) = zcheck(&all);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}
