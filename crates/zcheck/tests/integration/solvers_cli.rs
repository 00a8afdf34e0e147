//! `zcheck advise --scene FILE --solver ...` end to end: one configuration's
//! document (its fields, its cost S·N·constraints, its modes), the search's
//! recommendation or reason, and bad flags as clean errors (exit 2, the
//! flag named, no panic).

use crate::run::zcheck;
use serde_json::Value;
use testkit::scratch::Scratch;

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

/// `--solvers`: one row per family, ranked by the exact operations per
/// tick (recomputed here from the rows' own fields, ties by name), the
/// recommendation the first ranked row; a family with no passing
/// configuration is unranked and says why; the table's solver rows are the
/// searches' own recommendations. Bad lists are clean errors naming the flag.
#[test]
fn families_side_by_side() {
    // rope2d with a looser amplitude target, so XPBD passes too.
    let text = std::fs::read_to_string(scene("rope2d.toml"))
        .unwrap()
        .replace("amplitude = 0.05", "amplitude = 0.5");
    let scratch_path = Scratch::new("families");
    let path = scratch_path.join("families.toml");
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap();
    let (code, out, err) =
        zcheck(&["advise", "--scene", p, "--solvers", "paper,xpbd,soft_step", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).expect("JSON");
    let rows = v["families"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    let mut ranked: Vec<(u64, String)> = rows
        .iter()
        .filter(|r| !r["ops_per_tick"].is_null())
        .map(|r| (r["ops_per_tick"].as_u64().unwrap(), r["family"].as_str().unwrap().to_owned()))
        .collect();
    assert!(ranked.len() >= 2, "paper and xpbd both pass: {v}");
    ranked.sort();
    for (k, (_, family)) in ranked.iter().enumerate() {
        let row = rows.iter().find(|r| r["family"] == family.as_str()).unwrap();
        assert_eq!(row["rank"].as_u64(), Some(k as u64 + 1), "{family}");
        assert!(row["ns_per_tick"].as_f64().is_some_and(|x| x > 0.0), "{row}");
    }
    assert_eq!(v["recommended"]["family"], ranked[0].1.as_str());
    for r in rows.iter().filter(|r| r["rank"].is_null()) {
        assert!(r["reason"].as_str().is_some_and(|s| !s.is_empty()), "{r}");
    }
    // The xpbd row is the search's recommendation, with its exact count.
    let (code, out, err) =
        zcheck(&["advise", "--scene", p, "--solver", "xpbd", "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let search: Value = serde_json::from_str(&out).unwrap();
    let row = rows.iter().find(|r| r["family"] == "xpbd").unwrap();
    assert_eq!(row["substeps"], search["recommended"]["substeps"]);
    assert_eq!(row["iterations"], search["recommended"]["iterations"]);
    assert_eq!(row["ops_per_tick"], search["analysis"]["ops_per_tick"]);
    // The text has the table and the recommendation.
    let (code, out, _) = zcheck(&["advise", "--scene", p, "--solvers", "paper,xpbd"]);
    assert_eq!(code, 0);
    assert!(out.contains("ops/tick") && out.contains("recommended: "), "{out}");
    for (list, want) in [
        ("paper,nope", "--solvers nope: unknown family"),
        ("xpbd,xpbd", "--solvers: xpbd is listed twice"),
    ] {
        let (code, _, err) =
            zcheck(&["advise", "--scene", &scene("chain10.toml"), "--solvers", list]);
        assert_eq!(code, 2, "{list}");
        assert!(err.contains(want), "{list}: {err}");
    }
}

/// `zcheck plot solvers`: the SVG is written with a line per solver and
/// iteration count, and each small-steps verdict it prints is the
/// comparison of the two configurations' own documents (`advise --solver
/// --substeps --iterations`): phase by the phase error, amplitude by the
/// amplitude error and then the damping-ratio gap.
#[test]
fn plot_solvers_and_the_small_steps_verdicts() {
    let scratch = Scratch::new("plot-solvers");
    let dir = scratch.path().to_path_buf();
    let d = dir.to_str().unwrap();
    let quarter = scene("quarter_car.toml");
    let (code, out, err) =
        zcheck(&["plot", "solvers", "--scene", &quarter, "--out", d, "--solvers", "xpbd"]);
    assert_eq!(code, 0, "{err}");
    let svg = std::fs::read_to_string(dir.join("solvers.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("xpbd N = 1") && svg.contains("xpbd N = 16"));
    let doc = |s: u64, n: u64| -> Value {
        let (code, out, err) = zcheck(&[
            "advise",
            "--scene",
            &quarter,
            "--solver",
            "xpbd",
            "--substeps",
            &s.to_string(),
            "--iterations",
            &n.to_string(),
            "--format",
            "json",
        ]);
        assert_eq!(code, 0, "{err}");
        serde_json::from_str(&out).unwrap()
    };
    let gap = |v: &Value| {
        v["modes"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|m| m["in_band"] == true)
            .map(|m| (m["effective_ratio"].as_f64().unwrap() - m["ratio"].as_f64().unwrap()).abs())
            .fold(0.0, f64::max)
    };
    let mut checked = 0;
    for k in [2u64, 4, 8, 16] {
        let (small, iter) = (doc(k, 1), doc(1, k));
        let f = |v: &Value, key: &str| v[key].as_f64().unwrap();
        let stable = |v: &Value| v["stable"] == true;
        let phase = stable(&small)
            && (!stable(&iter) || f(&small, "phase_error_rad") < f(&iter, "phase_error_rad"));
        let amp = stable(&small)
            && (!stable(&iter)
                || (f(&small, "amplitude_error"), gap(&small))
                    < (f(&iter, "amplitude_error"), gap(&iter)));
        let word = |b: bool| if b { "holds" } else { "fails" };
        let line = format!(
            "small steps (xpbd): S x N = {k:2}: {k} substeps x 1 against 1 substep x {k} iterations: \
             phase {}, amplitude {}",
            word(phase),
            word(amp)
        );
        assert!(out.contains(&line), "expected {line:?} in\n{out}");
        checked += 1;
    }
    assert_eq!(checked, 4);
    let (code, _, err) = zcheck(&["plot", "solvers", "--out", d]);
    assert_eq!(code, 2);
    assert!(err.contains("expected --scene FILE"), "{err}");
    let (code, _, err) =
        zcheck(&["plot", "solvers", "--scene", &quarter, "--out", d, "--solvers", "pbd"]);
    assert_eq!(code, 2);
    assert!(err.contains("--solver pbd: unknown solver"), "{err}");
}
