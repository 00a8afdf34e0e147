//! `zcheck region` from the outside: parity with NodePy's intervals and
//! orders on its RK catalogue, with an independent high-precision
//! computation (SymPy and mpmath, `benches/peers/nodepy_reference.py`) on
//! its multistep catalogue, every field of the JSON, multistep input taken
//! by every command, the SVG figure, and bad input.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;
use testkit::scratch::Scratch;

fn zcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("run zcheck")
}

fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(rel)
}

fn reference() -> Value {
    let text = std::fs::read_to_string(data("nodepy/reference.json")).expect("reference.json");
    serde_json::from_str(&text).expect("json")
}

/// Every catalogue file of a kind, sorted, with whether its coefficients are
/// exact (NodePy holds 11 RK methods only as floats).
fn catalogue(kind: &str) -> Vec<(String, PathBuf, bool)> {
    let mut out: Vec<(String, PathBuf, bool)> = std::fs::read_dir(data(&format!("nodepy/{kind}")))
        .expect("catalogue")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("read");
            let stem = p.file_stem().unwrap().to_string_lossy().into_owned();
            (stem, p, !text.contains("INEXACT"))
        })
        .collect();
    out.sort();
    out
}

/// `zcheck region` on many files in one process: the JSON documents by
/// method file stem.
fn region(files: &[&Path]) -> Vec<Value> {
    let mut args = vec!["region".to_owned()];
    args.extend(files.iter().map(|p| p.display().to_string()));
    args.extend(["--format".to_owned(), "json".to_owned()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = zcheck(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    match serde_json::from_slice(&out.stdout).expect("json") {
        Value::Array(v) => v,
        one => vec![one],
    }
}

fn limit(v: &Value) -> Option<f64> {
    if v.is_null() {
        None
    } else {
        Some(v["value"].as_f64().expect("value"))
    }
}

#[track_caller]
fn close(name: &str, what: &str, ours: Option<f64>, theirs: Option<f64>, tol: f64) {
    match (ours, theirs) {
        (Some(a), Some(b)) => {
            assert!((a - b).abs() <= tol * (1.0 + b.abs()), "{name} {what}: {a} vs {b}")
        }
        (None, None) => {}
        _ => panic!("{name} {what}: {ours:?} vs {theirs:?}"),
    }
}

/// NodePy's real and imaginary intervals (explicit methods: its interval
/// functions fail or return 0 on implicit ones) and the order on y' = λy.
#[test]
fn parity_with_nodepy_on_its_runge_kutta_catalogue() {
    let reference = reference();
    let files = catalogue("rk");
    let paths: Vec<&Path> = files.iter().map(|(_, p, _)| p.as_path()).collect();
    let docs = region(&paths);
    assert_eq!(docs.len(), files.len());
    let mut compared = 0;
    for ((stem, _, exact), doc) in files.iter().zip(&docs) {
        let r = &reference["rk"][stem.as_str()];
        assert!(r.is_object(), "{stem} has a reference");
        let own = &r["own"];
        let nodepy = &r["nodepy"];
        if *exact {
            // The order on y' = λy, and the classical order, NodePy's
            // `order()` (the B-series order) on every exact file.
            assert_eq!(doc["linear_order"], own["linear_order"], "{stem}");
            assert_eq!(doc["order"], nodepy["order"], "{stem}");
            close(
                stem,
                "C",
                limit(&doc["error_constant"]),
                own["error_constant"]["value"].as_f64(),
                1e-14,
            );
            close(
                stem,
                "real",
                limit(&doc["real_limit"]),
                own["real_limit"]["value"].as_f64(),
                1e-12,
            );
            close(
                stem,
                "imag",
                limit(&doc["imag_limit"]),
                own["imag_limit"]["value"].as_f64(),
                1e-12,
            );
        }
        if r["nodepy_class"] == "ExplicitRungeKuttaMethod" && *exact {
            let re = nodepy["real_stability_interval"]["value"].as_f64();
            let im = nodepy["imaginary_stability_interval"]["value"].as_f64();
            close(stem, "NodePy real", limit(&doc["real_limit"]), re, 1e-9);
            // NodePy reports a tiny positive number where the interval is
            // empty; 1e-6 absolute tells them apart.
            let ours = limit(&doc["imag_limit"]).unwrap_or(f64::INFINITY);
            let theirs = im.unwrap_or(0.0);
            assert!(
                (ours - theirs).abs() < 1e-6 * (1.0 + theirs),
                "{stem} imag: {ours} vs NodePy {theirs}"
            );
            compared += 1;
        }
    }
    assert!(compared >= 10, "{compared}");
}

/// The multistep catalogue against the independent 60-digit computation,
/// and BDF's A(α) against NodePy's floor and Hairer–Wanner's digits.
#[test]
fn multistep_catalogue_against_an_independent_computation() {
    let reference = reference();
    let files = catalogue("lmm");
    let paths: Vec<&Path> = files.iter().map(|(_, p, _)| p.as_path()).collect();
    let docs = region(&paths);
    let mut disagreements = Vec::new();
    for ((stem, _, _), doc) in files.iter().zip(&docs) {
        let own = &reference["lmm"][stem.as_str()]["own"];
        assert_eq!(doc["order"], own["order"], "{stem}");
        assert_eq!(doc["linear_order"], own["order"], "{stem}");
        close(
            stem,
            "C",
            limit(&doc["error_constant"]),
            own["error_constant"]["value"].as_f64(),
            1e-14,
        );
        close(stem, "real", limit(&doc["real_limit"]), own["real_limit"]["value"].as_f64(), 1e-12);
        close(stem, "imag", limit(&doc["imag_limit"]), own["imag_limit"]["value"].as_f64(), 1e-12);
        close(stem, "rho_inf", limit(&doc["rho_inf"]), own["rho_inf"]["value"].as_f64(), 1e-12);
        let Some(floor) =
            reference["lmm"][stem.as_str()]["nodepy"]["A_alpha_stability_deg_floor"].as_f64()
        else {
            continue;
        };
        let ours = doc["a_alpha_deg"].as_f64().unwrap();
        if doc["real_limit"].is_null() {
            // NodePy's floor of a float computation: 89 for the exact 90.
            assert!(
                floor <= ours && ours <= floor + 1.0,
                "{stem}: {ours} vs NodePy's floor {floor}"
            );
        } else if floor > 0.0 {
            // NodePy measures the angle of the boundary locus only. Where the
            // negative axis itself is unstable just left of 0 (Milne–Simpson:
            // a parasitic root at −1 − w/3 + …), no sector is stable, as the
            // independent computation also finds.
            assert_eq!(ours, 0.0, "{stem}");
            assert_eq!(own["real_limit"]["value"].as_f64(), Some(0.0), "{stem}");
            disagreements.push(stem.clone());
        }
    }
    // Where NodePy and the exact answer differ (the weakly stable Nyström
    // and Milne–Simpson families, whose ρ has a root at −1), each case was
    // held to the independent computation above; DESIGN.md lists them.
    eprintln!("NodePy's A(α) differs (unstable negative axis) on: {disagreements:?}");
    let bdf: Value = serde_json::from_str(
        &std::fs::read_to_string(data("nodepy/bdf_a_alpha.json")).expect("bdf_a_alpha.json"),
    )
    .expect("json");
    // Each BDF's A(α) against the 50-digit boundary-locus value and the
    // digits Hairer–Wanner print.
    for k in 1..=6 {
        let name = format!("BDF{k}");
        let doc = &docs[files.iter().position(|(s, _, _)| *s == name).expect("in the catalogue")];
        let ours = doc["a_alpha_deg"].as_f64().unwrap();
        let entry = &bdf["bdf"][name.as_str()];
        let digits: f64 = entry["digits"].as_str().unwrap().parse().unwrap();
        assert!((ours - digits).abs() < 1e-10, "{name}: {ours} vs {digits}");
        if let Some(printed) = entry["printed_deg"].as_str() {
            let printed: f64 = printed.parse().unwrap();
            assert!((ours - printed).abs() <= 0.005 + 1e-12, "{name}: {ours} vs printed {printed}");
        }
    }
}

#[test]
fn every_field_of_the_json() {
    let v = &region(&[Path::new("rk4")])[0];
    for key in [
        "order",
        "order_at_least",
        "linear_order",
        "error_constant",
        "real_limit",
        "imag_limit",
        "a_stable",
        "a_alpha_deg",
        "l_stable",
        "rho_inf",
    ] {
        assert!(v.get(key).is_some(), "{key} in {v}");
    }
    assert_eq!((&v["order"], &v["linear_order"]), (&4.into(), &4.into()));
    assert!(v["order_at_least"].is_null());
    assert_eq!(v["imag_limit"]["exact"], "2*sqrt(2)");
    assert!(v["rho_inf"].is_null());
    let bdf2 = &region(&[&data("nodepy/lmm/BDF2.toml")])[0];
    assert_eq!((bdf2["a_stable"].as_bool(), bdf2["l_stable"].as_bool()), (Some(true), Some(true)));
    assert_eq!(bdf2["a_alpha_deg"], 90.0);
    assert_eq!(bdf2["rho_inf"]["exact"], "0");
}

/// A scalar `.zm` program in `w`: explicit and backward Euler, and a
/// history read (leapfrog: the imaginary limit 1, though i itself has a
/// double root).
#[test]
fn scalar_programs() {
    let scratch = Scratch::new("region");
    let dir = scratch.path().to_path_buf();
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let ee = write("ee.zm", "method ee\nstate y\ny = y + w*y\n");
    let be = write("be.zm", "method be\nstate y\ny' = y + w*y'\n");
    let lf = write("lf.zm", "method lf\nstate y\ny = y@1 + 2*w*y\n");
    let docs = region(&[&ee, &be, &lf]);
    assert_eq!(docs[0]["real_limit"]["exact"], "2");
    assert_eq!(docs[1]["l_stable"], true);
    assert_eq!(docs[2]["imag_limit"]["exact"], "1");
    assert_eq!(docs[2]["real_limit"]["exact"], "0");
    // Phi in a scalar program, w in an oscillator one: located errors.
    let mixed = write("mixed.zm", "method m\nstate y v\ny = y + w*v\nv = v - Phi*y\n");
    let out = zcheck(&["region", mixed.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("mixed.zm:4:9"), "{err}");
    let out = zcheck(&["stability", ee.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("y' = λy"));
    // A partitioned method has no scalar form: said, exit 2.
    let out = zcheck(&["region", "false_euler"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("partitioned"));
}

/// Multistep input is taken by every command that takes a method.
#[test]
fn multistep_files_work_in_every_command() {
    let bdf2 = data("nodepy/lmm/BDF2.toml");
    let f = bdf2.to_str().unwrap();
    for args in [
        vec!["derive", f],
        vec!["stability", f],
        vec!["region", f],
        vec!["verify", f, "--phi", "1/2"],
        vec!["overview", f],
    ] {
        let out = zcheck(&args);
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
    // The oscillator's limit of AB3 from its coefficients: 12√11/55.
    let out =
        zcheck(&["stability", data("nodepy/lmm/AB3.toml").to_str().unwrap(), "--format", "json"]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["phi_max_exact"], "12*sqrt(11)/55");
}

#[test]
fn multistep_bad_input_is_located() {
    let scratch = Scratch::new("lmm");
    let dir = scratch.path().to_path_buf();
    for (name, text, at, says) in [
        (
            "lengths.toml",
            "alpha = [-1, 1]\nbeta = [1]\n",
            ":2:8",
            "beta has 1 coefficients and alpha 2",
        ),
        ("zero.toml", "alpha = [-1, 1]\nbeta = [0, 0]\n", ":2:8", "beta is all zero"),
        ("ak.toml", "alpha = [-1, 0]\nbeta = [1, 0]\n", ":1:14", "alpha[1]"),
        (
            "word.toml",
            "alpha = [-1, \"x\"]\nbeta = [1, 0]\n",
            ":1:14",
            "alpha[1]: unexpected name `x`",
        ),
        ("nan.toml", "alpha = [-1, nan]\nbeta = [1, 0]\n", ":1:14", "not a finite number"),
    ] {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        let out = zcheck(&["region", p.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains(&format!("{name}{at}")), "{name}: {err}");
        assert!(err.contains(says), "{name}: {err}");
        assert!(!err.contains("panicked"), "{name}: {err}");
    }
    // A decimal coefficient is the decimal written: 0.5 is 1/2.
    let p = dir.join("decimal.toml");
    std::fs::write(&p, "alpha = [-1, 1]\nbeta = [0.5, 0.5]\n").unwrap();
    let v = &region(&[&p])[0];
    assert_eq!(v["order"], 2, "the trapezoidal rule from decimals");
}

#[test]
fn the_figure_overlays_every_method() {
    let scratch_svg = Scratch::new("region");
    let svg = scratch_svg.join("region.svg");
    let out = zcheck(&["region", "rk4", "trapezoidal", "--svg", svg.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("rk4") && text.contains("trapezoidal"));
    assert!(text.contains("stability regions"));
}

/// Hughes' ρ∞ on the oscillator (The Finite Element Method, ch. 9):
/// (1 + α)/(1 − α) for HHT-α (α ∈ [−1/3, 0]), and the chosen ρ∞ for
/// Chung–Hulbert's generalized-α, from `zcheck stability`'s exact rho_inf.
/// Both are unconditionally stable at these parameters.
#[test]
fn hughes_rho_inf_for_hht_alpha_and_generalized_alpha() {
    let json = |file: &str, param: &str| -> Value {
        let path = data(&format!("structural/{file}"));
        let out =
            zcheck(&["stability", path.to_str().unwrap(), "--param", param, "--format", "json"]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_slice(&out.stdout).unwrap()
    };
    for (num, den) in [(0i64, 1i64), (-1, 10), (-1, 5), (-1, 3)] {
        let a = num as f64 / den as f64;
        let v = json("hht_alpha.zm", &format!("alpha={num}/{den}"));
        let expected = (1.0 + a) / (1.0 - a);
        let got = v["rho_inf"]["value"].as_f64().expect("a finite ρ∞");
        assert!((got - expected).abs() < 1e-15, "HHT-α at {a}: {got} vs {expected}");
        assert_eq!(v["stability"], "bounded_for_all_phi", "HHT-α at {a}");
    }
    for r in ["0", "1/4", "1/2", "9/10", "1"] {
        let v = json("generalized_alpha.zm", &format!("rho_inf={r}"));
        assert_eq!(v["rho_inf"]["exact"], r, "generalized-α at ρ∞ = {r}");
        assert_eq!(v["stability"], "bounded_for_all_phi", "generalized-α at ρ∞ = {r}");
    }
}

/// `overview` shows ρ∞ and, for a three-state method whose Ψ series is
/// n/a, the leading terms from the principal root in its own conventions
/// (Ψ − Φ = −(Φ − Ψ), |z|² − 1 = −2(1 − |z|)), equal to `stability`'s.
#[test]
fn overview_shows_rho_inf_and_the_general_leading_terms() {
    let path = data("structural/hht_alpha.zm");
    let p = path.to_str().unwrap();
    let out = zcheck(&["overview", p, "--param", "alpha=-1/10", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let row = &serde_json::from_slice::<Value>(&out.stdout).unwrap()[0];
    let out = zcheck(&["stability", p, "--param", "alpha=-1/10", "--format", "json"]);
    let st: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(row["rho_inf"], st["rho_inf"]["exact"]);
    let q = st["dispersion_order"].as_u64().unwrap() + 1;
    let c = st["dispersion_constant"]["exact"].as_str().unwrap();
    let negated = c.strip_prefix('-').map_or(format!("-{c}"), str::to_owned);
    assert_eq!(row["phase_error"], format!("{negated}*Phi^{q}"));
}
