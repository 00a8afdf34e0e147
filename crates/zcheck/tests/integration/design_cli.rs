//! `zcheck design` end to end (issue 37): the seven known optima, each
//! checked independently first (by hand in `methods/design/`'s comments and
//! in poly's `tests/integration/design.rs`, and by a float scan), their
//! exact JSON (`optimum`, `at`, `attained`, the grid check never above the
//! optimum), the text, `--per`, and the errors; a tableau whose entries name
//! a parameter, read by every command with `--param c=1` exactly as the
//! same tableau written with numbers (the oracle).

use crate::run::zcheck;
use serde_json::Value;
use testkit::scratch::ScratchFile;

fn method(name: &str) -> String {
    format!("{}/methods/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn design_file(name: &str) -> String {
    method(&format!("design/{name}"))
}

/// `design FILE --maximize OBJECTIVE --param P...` and then `extra`.
fn design_args<'a>(
    file: &'a str,
    objective: &'a str,
    params: &[&'a str],
    extra: &[&'a str],
) -> Vec<&'a str> {
    let mut args = vec!["design", file, "--maximize", objective];
    for p in params {
        args.extend(["--param", p]);
    }
    args.extend(extra);
    args
}

#[track_caller]
fn json(args: &[&str]) -> Value {
    let mut all = args.to_vec();
    all.extend(["--format", "json"]);
    let (code, out, err) = zcheck(&all);
    assert_eq!(code, 0, "zcheck {all:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("zcheck {all:?}: {e}: {out}"))
}

/// The exact text of a `{"exact", "value"}` number.
fn exact(v: &Value) -> &str {
    v["exact"].as_str().unwrap_or_else(|| panic!("no exact text: {v}"))
}

/// The document's shape, and what every design must satisfy: the eight
/// fields of the contract, exact numbers with a float beside them (none
/// for +inf), the grid's size and its maximum never above the optimum
/// (compared as floats only when both are finite and the exact texts
/// differ: the exact comparison is poly's, which refuses a grid above).
#[track_caller]
fn check_document(d: &Value, free: usize, grid_points: usize) {
    let keys: Vec<&str> = d.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(
        keys,
        ["at", "attained", "certificate", "grid_check", "method", "objective", "optimum", "params"],
        "{d}"
    );
    assert_eq!(d["params"].as_object().unwrap().len(), free, "{d}");
    assert_eq!(d["at"].as_object().unwrap().len(), free, "{d}");
    for (name, range) in d["params"].as_object().unwrap() {
        assert!(range["lo"]["exact"].is_string() && range["hi"]["value"].is_number(), "{name}");
    }
    let g = &d["grid_check"];
    assert!(g["points"].as_u64().unwrap() as usize >= grid_points, "{g}");
    let (opt, max) = (&d["optimum"], &g["max"]);
    match (opt["value"].as_f64(), max["value"].as_f64()) {
        (Some(o), Some(m)) => assert!(m <= o || exact(max) == exact(opt), "{m} > {o}"),
        (None, _) => assert_eq!(exact(opt), "inf", "{opt}"),
        (Some(_), None) => panic!("the grid reaches inf above a finite optimum: {d}"),
    }
    let certificate = d["certificate"].as_array().unwrap();
    assert!(certificate.len() >= 3, "{d}");
    assert!(certificate.iter().any(|l| l.as_str().unwrap().starts_with("optimum ")), "{d}");
}

/// `at` as NAME = exact text.
fn at(d: &Value) -> Vec<(String, String)> {
    d["at"].as_object().unwrap().iter().map(|(k, v)| (k.clone(), exact(v).to_owned())).collect()
}

fn pairs(p: &[(&str, &str)]) -> Vec<(String, String)> {
    p.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect()
}

/// Chebyshev's 2s² for s = 2: R = 1 + w + a₂w², best real limit 8 at a₂ =
/// 1/8 (R(−8) = 1, and R = −1 only touched at x = 4).
#[test]
fn chebyshev_real_limit() {
    let d = json(&design_args(&design_file("chebyshev2.zm"), "real_limit", &["a2=0..1/2"], &[]));
    check_document(&d, 1, 200);
    assert_eq!((exact(&d["optimum"]), &d["attained"]), ("8", &Value::Bool(true)));
    assert_eq!(at(&d), pairs(&[("a2", "1/8")]));
    assert_eq!(
        (d["method"].as_str(), d["objective"].as_str()),
        (Some("chebyshev2"), Some("real_limit"))
    );
}

/// Kinnmark–Gray: |R(iy)|² = 1 + (1/4 − 2a₃)y⁴ + a₃²y⁶, best imaginary
/// limit 2 at a₃ = 1/4; with order ≥ 3 only a₃ = 1/6 is allowed: √3.
#[test]
fn kinnmark_gray_imag_limit() {
    let kg = design_file("kinnmark_gray.zm");
    let d = json(&design_args(&kg, "imag_limit", &["a3=0..1/2"], &[]));
    check_document(&d, 1, 200);
    assert_eq!((exact(&d["optimum"]), &d["attained"]), ("2", &Value::Bool(true)));
    assert_eq!(at(&d), pairs(&[("a3", "1/4")]));
    let d = json(&design_args(&kg, "imag_limit", &["a3=0..1/2"], &["--min-order", "3"]));
    // The allowed set is the single point a3 = 1/6: the grid is that point.
    check_document(&d, 1, 1);
    assert_eq!((exact(&d["optimum"]), &d["attained"]), ("sqrt(3)", &Value::Bool(true)));
    assert_eq!(at(&d), pairs(&[("a3", "1/6")]));
    let text = d["certificate"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_str().unwrap())
        .collect::<Vec<_>>()
        .join("\n");
    assert!(text.contains("order conditions hold only at a3 = 1/6"), "{text}");
}

/// The θ-method, R = (1 + (1 − θ)w)/(1 − θw): real limit 2/(1 − 2θ) below
/// θ = 1/2, +∞ from there.
#[test]
fn theta_method_real_limit() {
    let theta = design_file("theta.zm");
    let d = json(&design_args(&theta, "real_limit", &["theta=0..2/5"], &[]));
    check_document(&d, 1, 200);
    assert_eq!((exact(&d["optimum"]), &d["attained"]), ("10", &Value::Bool(true)));
    assert_eq!(at(&d), pairs(&[("theta", "2/5")]));
    let d = json(&design_args(&theta, "real_limit", &["theta=0..1/2"], &[]));
    check_document(&d, 1, 200);
    assert_eq!(d["optimum"], serde_json::json!({ "exact": "inf", "value": null }));
    assert_eq!(d["attained"], true);
    assert_eq!(at(&d), pairs(&[("theta", "1/2")]));
}

/// Φ_max over Newmark's (β, γ) box, through the disk bound: 2√5 at
/// (1/5, 1/2) (Hughes: 1/√(γ/2 − β), least γ/2 − β there), the
/// certificate naming the bound and the engine's value at the optimum; a
/// box whose bound's maximiser has an unbounded repeated root on the
/// circle below it is refused in one line, exit 2.
#[test]
fn newmark_phi_max_over_beta_and_gamma() {
    let newmark = method("newmark.zm");
    let d = json(&design_args(&newmark, "phi_max", &["beta=0..1/5", "gamma=1/2..3/5"], &[]));
    check_document(&d, 2, 2500);
    assert_eq!((exact(&d["optimum"]), &d["attained"]), ("2*sqrt(5)", &Value::Bool(true)));
    assert_eq!(at(&d), pairs(&[("beta", "1/5"), ("gamma", "1/2")]));
    let text = d["certificate"].to_string();
    assert!(text.contains("disk bound") && text.contains("gives phi_max = 2*sqrt(5)"), "{text}");
    let tangent = temp_file(
        "tangent.zm",
        "method tangent\nparam a\nparam c\nstate v y\ny' = y + Phi*v\n\
         v' = v + Phi*(a*Phi^2 - c)*y'\n",
    );
    let args = [
        "design",
        tangent.to_str().unwrap(),
        "--maximize",
        "phi_max",
        "--param",
        "a=1/2..1",
        "--param",
        "c=3..4",
    ];
    let (code, out, err) = zcheck(&args);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty(), "{out}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("phi_max is 2*sqrt(6)/3") && !err.contains("panicked"), "{err}");
}

/// Newmark with γ = 1/2: χ(−1) = 4 + (4β − 1)Φ², so Φ_max = 2/√(1 − 4β):
/// 2√5 at β = 1/5. Over [0, 1/2] every β ≥ 1/4 is unconditionally stable:
/// +inf, at the set's least point 1/4, the set described.
#[test]
fn newmark_phi_max_with_gamma_bound() {
    let newmark = method("newmark.zm");
    let args = [
        "design",
        &newmark,
        "--maximize",
        "phi_max",
        "--param",
        "beta=0..1/5",
        "--param",
        "gamma=1/2",
    ];
    let d = json(&args);
    check_document(&d, 1, 200);
    assert_eq!((exact(&d["optimum"]), &d["attained"]), ("2*sqrt(5)", &Value::Bool(true)));
    assert!((d["optimum"]["value"].as_f64().unwrap() - 2.0 * 5f64.sqrt()).abs() < 1e-12);
    assert_eq!(at(&d), pairs(&[("beta", "1/5")]));
    // The bound value is named in the certificate.
    assert!(d["certificate"][0].as_str().unwrap().contains("with gamma=1/2"), "{d}");
    let d = json(&design_args(&newmark, "phi_max", &["gamma=1/2", "beta=0..1/2"], &[]));
    check_document(&d, 1, 200);
    assert_eq!(exact(&d["optimum"]), "inf");
    assert_eq!(at(&d), pairs(&[("beta", "1/4")]));
    let text = d["certificate"].to_string();
    assert!(text.contains("the maximisers form a set"), "{text}");
}

/// The explicit 2-stage order-2 family, a tableau whose entries name c:
/// SSP coefficient min(2 − 1/c, 1/c) for c ≥ 1/2, best 1 at c = 1 (Heun);
/// per stage, 1/2.
#[test]
fn two_stage_family_ssp_coefficient() {
    let rk2 = design_file("rk2_family.toml");
    let d = json(&design_args(&rk2, "ssp_coefficient", &["c=1/4..2"], &[]));
    check_document(&d, 1, 200);
    assert_eq!((exact(&d["optimum"]), &d["attained"]), ("1", &Value::Bool(true)));
    assert_eq!(at(&d), pairs(&[("c", "1")]));
    assert_eq!(d["method"], "rk2_family");
    let d = json(&design_args(&rk2, "ssp_coefficient", &["c=1/4..2"], &["--per", "stage"]));
    check_document(&d, 1, 200);
    assert_eq!(exact(&d["optimum"]), "1/2");
    assert_eq!(at(&d), pairs(&[("c", "1")]));
    // Per multiplication: at c = 1 (A[2][1] = 1, b₁ = b₂ = 1/2 sharing one
    // multiplication) the step takes 3, not 5, so no one count divides over
    // [3/4, 2]: refused, naming the point; over [1/4, 2] the first such point
    // is c = 1/4, where b₁ = −1 needs no multiplication.
    let per_cost = |range: &str| {
        zcheck(&design_args(
            &rk2,
            "ssp_coefficient",
            &[range],
            &["--per", "cost", "--format", "json"],
        ))
    };
    let (code, _, err) = per_cost("c=3/4..2");
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("3 at c = 1 (A[2][1] = 1), 5 elsewhere"), "{err}");
    let (code, _, err) = per_cost("c=1/4..2");
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("4 at c = 1/4 (b[1] = -1), 5 elsewhere"), "{err}");
    // Over [9/8, 2] no entry is 0 or ±1, the step takes 5 multiplications
    // (w·y, c·k1, w·(y + c·k1), b1·k1, b2·k2) everywhere, and the SSP
    // coefficient min(2 − 1/c, 1/c) = 1/c is best at 9/8: 8/9 / 5 = 8/45.
    let (code, out, err) = per_cost("c=9/8..2");
    assert_eq!(code, 0, "{err}");
    let d: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(exact(&d["optimum"]), "8/45");
    assert_eq!(at(&d), pairs(&[("c", "9/8")]));
}

/// Two parameters: 1 + w + a₂w² + a₃w³ over [0, 1/2] × [0, 1/6] with order
/// ≥ 1: 18 at (4/27, 4/729), the shifted Chebyshev T₃(1 + w/9). No grid
/// point hits the isolated optimum: the grid's best is strictly below.
#[test]
fn shifted_chebyshev_two_parameters() {
    let d = json(&design_args(
        &design_file("cubic.zm"),
        "real_limit",
        &["a2=0..1/2", "a3=0..1/6"],
        &["--min-order", "1"],
    ));
    check_document(&d, 2, 2500);
    assert_eq!((exact(&d["optimum"]), &d["attained"]), ("18", &Value::Bool(true)));
    assert_eq!(at(&d), pairs(&[("a2", "4/27"), ("a3", "4/729")]));
    assert!(d["grid_check"]["max"]["value"].as_f64().unwrap() < 18.0, "{d}");
}

/// A tableau with a second parameter bound (`--param d=1`): the value is
/// substituted into the entries as the file is read, so the search sees
/// the one-parameter family (poly's ParamTableau would keep d a symbol
/// there and answer for the wrong method).
#[test]
fn tableau_with_a_bound_parameter() {
    let file = temp_file(
        "rk2_cd.toml",
        "params = [\"c\", \"d\"]\nA = [[0, 0], [\"c*d\", 0]]\nb = [\"1 - 1/(2*c)\", \"1/(2*c)\"]\n",
    );
    let file = file.to_str().unwrap();
    let args = |objective| {
        ["design", file, "--maximize", objective, "--param", "c=1/4..2", "--param", "d=1"]
    };
    let d = json(&args("ssp_coefficient"));
    check_document(&d, 1, 200);
    assert_eq!(exact(&d["optimum"]), "1");
    assert_eq!(at(&d), pairs(&[("c", "1")]));
    assert!(d["certificate"][0].as_str().unwrap().contains("with d=1"), "{d}");
    // R = 1 + w + w^2/2 for every c: the real limit is 2 throughout.
    let d = json(&args("real_limit"));
    check_document(&d, 1, 200);
    assert_eq!(exact(&d["optimum"]), "2");
}

/// The text a person reads: the optimum, where, the grid check and the
/// certificate.
#[test]
fn text_report() {
    let (code, out, err) =
        zcheck(&design_args(&method("newmark.zm"), "phi_max", &["beta=0..1/5", "gamma=1/2"], &[]));
    assert_eq!(code, 0, "{err}");
    for wanted in [
        "design newmark: maximise phi_max",
        "optimum     2*sqrt(5) ≈ 4.472136",
        "at          beta = 1/5 (attained)",
        "grid check  201 points",
        "certificate (",
    ] {
        assert!(out.contains(wanted), "{wanted}\n{out}");
    }
}

/// Bad input: a clean one-line message, exit 2, no panic.
#[test]
fn errors_are_clean() {
    let (kg, rk2) = (design_file("kinnmark_gray.zm"), design_file("rk2_family.toml"));
    let cubic = design_file("cubic.zm");
    let big = temp_file(
        "big.zm",
        "method big\nparam a\nstate y\n\
         y = y + w*y + a^64*a^64*a^64*a^64*a^64*a^64*a^64*w^2*y\n",
    );
    let big = big.to_str().unwrap();
    // R = 1 + w + a2 w^2 + a3 w^3 over a box: a tangency system of degree
    // 78 in (a2, a3), whose gcd would run for minutes.
    let cubic_box = temp_file(
        "cubic_box.zm",
        "method cubic_box\nparam a2\nparam a3\nstate y\ny = y + w*y + a2*w^2*y + a3*w^3*y\n",
    );
    let cubic_box = cubic_box.to_str().unwrap();
    for (args, wanted) in [
        (
            &["design", &kg, "--maximize", "imag_limit", "--param", "a3=1..0"][..],
            "--param a3=1..0: the range is empty",
        ),
        (
            &["design", &kg, "--maximize", "imag_limit", "--param", "b=0..1"][..],
            "method `kinnmark_gray` has no parameter b",
        ),
        (
            &[
                "design",
                &rk2,
                "--maximize",
                "ssp_coefficient",
                "--param",
                "c=1..2",
                "--param",
                "d=1",
            ][..],
            "--param d: tableau",
        ),
        (
            &["design", &kg, "--maximize", "ssp_coefficient", "--param", "a3=0..1"][..],
            "ssp_coefficient applies to a Butcher tableau",
        ),
        (
            &["design", &kg, "--maximize", "speed", "--param", "a3=0..1"][..],
            "unknown objective \"speed\"",
        ),
        (
            &[
                "design",
                &cubic,
                "--maximize",
                "real_limit",
                "--param",
                "a2=0..1",
                "--param",
                "a3=0..1",
                "--param",
                "a4=0..1",
            ][..],
            "3 free parameters",
        ),
        (&["design", &kg, "--maximize", "imag_limit"][..], "no free parameter"),
        (
            &["design", &kg, "--maximize", "imag_limit", "--param", "a3=0..1", "--per", "stage"][..],
            "--per stage: `kinnmark_gray` is a program",
        ),
        (
            &["design", &method("newmark.zm"), "--maximize", "phi_max", "--param", "beta=0..1"][..],
            "parameter gamma is neither free nor bound",
        ),
        // The exact search stops at its size bounds and names them.
        (
            &["design", big, "--maximize", "real_limit", "--param", "a=0..1"][..],
            "past the bound MAX_BREAKPOINT_DEGREE = 400",
        ),
        (
            &[
                "design",
                cubic_box,
                "--maximize",
                "imag_limit",
                "--param",
                "a2=2/5..1/2",
                "--param",
                "a3=1/8..1/4",
            ][..],
            "past the bound MAX_SYSTEM_DEGREE = 32",
        ),
    ] {
        let (code, out, err) = zcheck(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert!(err.contains(wanted), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    // The 1-line check is relaxed for a file error, which shows its line.
    let (code, _, err) =
        zcheck(&design_args(&kg.replace(".zm", "_missing.zm"), "imag_limit", &["a3=0..1"], &[]));
    assert_eq!(code, 2, "{err}");
}

fn temp_file(name: &str, text: &str) -> ScratchFile {
    ScratchFile::new(name, text)
}

/// A tableau whose entries name c, read by the other commands with
/// `--param c=1`, is the same tableau as Heun's written with numbers (the
/// oracle): the same documents, byte for byte (both are named `rk2_family`).
#[test]
fn parameterised_tableau_agrees_with_numbers() {
    let family = design_file("rk2_family.toml");
    let numbers = temp_file(
        "rk2_family.toml",
        "name = \"rk2_family\"\nA = [[0, 0], [1, 0]]\nb = [\"1/2\", \"1/2\"]\n",
    );
    let numbers = numbers.to_str().unwrap();
    for command in ["stability", "order", "region", "derive"] {
        let bound = json(&[command, &family, "--param", "c=1"]);
        let written = json(&[command, numbers]);
        assert_eq!(bound, written, "zcheck {command}");
    }
    // c = 1/2, the explicit midpoint rule: the same stability, another
    // tableau (order 2 either way).
    let midpoint = json(&["order", &family, "--param", "c=1/2"]);
    assert_eq!(midpoint["order"], 2, "{midpoint}");
    let (code, out, err) = zcheck(&["verify", &family, "--param", "c=1", "--phi", "1/2"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("witnesses agree"), "{out}");
}

/// A tableau's parameter without a value, or a value for a parameter
/// nothing declares: a clean error (located at the declaration).
#[test]
fn parameterised_tableau_errors() {
    let family = design_file("rk2_family.toml");
    for (args, wanted) in [
        (
            &["stability", &family][..],
            "rk2_family.toml:5:11: parameter c has no value: give it one with --param c=VALUE",
        ),
        (&["order", &family][..], "parameter c has no value"),
        (&["region", &family, "--param", "c=1", "--param", "d=2"][..], "has no parameter d"),
        (
            &["order", &family, "--param", "c=1", "--param", "d=2"][..],
            "no tableau here declares a parameter d",
        ),
        (&["stability", &family, "--param", "c=0"][..], "b[1]: division by zero"),
    ] {
        let (code, _, err) = zcheck(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(wanted), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

/// `zcheck equiv`, `tradeoff` and `advise --scene` read the tableau with
/// `--param c=1` as Heun's tableau written with numbers (the oracle): the
/// same relation, the same ranked row, the same scene candidate. Every
/// c ≠ 0 gives R = 1 + w + w²/2 (b₂c = 1/2), so `equiv` finds the family
/// members equal to Heun's.
#[test]
fn equiv_tradeoff_and_advise_bind_a_tableau() {
    let family = design_file("rk2_family.toml");
    let numbers = temp_file(
        "heun_numbers.toml",
        "name = \"rk2_family\"\nA = [[0, 0], [1, 0]]\nb = [\"1/2\", \"1/2\"]\n",
    );
    let numbers = numbers.to_str().unwrap();
    for c in ["1", "2", "1/2"] {
        let d = json(&["equiv", &family, numbers, "--param", &format!("c={c}")]);
        assert_eq!(d["relation"], "equal", "c = {c}: {d}");
        assert_eq!(d["charpoly_a"], d["charpoly_b"], "c = {c}");
    }
    // The rows of `tradeoff`, timing aside.
    let row = |args: &[&str], shown: &str| -> Value {
        let mut all = vec!["tradeoff", "--budget-ms", "1"];
        all.extend(args);
        let v = json(&all);
        let rows = v["methods"].as_array().unwrap();
        let mut r = rows.iter().find(|r| r["method"] == shown).expect("the row").clone();
        for k in ["method", "ns_per_step", "ns_per_step_hand", "cost_per_period"] {
            r.as_object_mut().unwrap().remove(k);
        }
        r
    };
    let bound = row(&["--method", &family, "--param", "c=1"], &family);
    assert_eq!(bound, row(&["--method", numbers], numbers));
    assert_eq!(bound["phi_max_exact"], "none", "{bound}");
    // A damped mode (RK2 is unstable on the undamped oscillator).
    let scene = temp_file("mode.toml", "tick_hz = 60\n[[mode]]\nhz = 5\nratio = 0.3\n");
    let scene = scene.to_str().unwrap();
    let candidate = |args: &[&str]| -> Value {
        let mut all = vec!["advise", "--scene", scene, "--no-simulate"];
        all.extend(args);
        let v = json(&all);
        let mut c = v["candidates"][0].clone();
        for k in ["method", "ns_per_step", "ns_per_tick"] {
            c.as_object_mut().unwrap().remove(k);
        }
        c
    };
    let bound = candidate(&["--methods", &family, "--param", "c=1"]);
    assert_eq!(bound, candidate(&["--methods", numbers]));
    assert!(bound["substeps_stable"].as_u64().is_some_and(|n| n >= 1), "{bound}");
}

/// The same three commands: a tableau's parameter without a value, or a
/// value nothing declares, is a clean error (exit 2) naming it.
#[test]
fn equiv_tradeoff_and_advise_parameter_errors() {
    let family = design_file("rk2_family.toml");
    let scene = temp_file("mode_errors.toml", "tick_hz = 60\n[[mode]]\nhz = 5\nratio = 0.3\n");
    let scene = scene.to_str().unwrap();
    let advise = |more: &[&'static str]| -> Vec<String> {
        let mut a: Vec<String> =
            ["advise", "--scene", scene, "--no-simulate", "--methods", &family]
                .iter()
                .map(|s| s.to_string())
                .collect();
        a.extend(more.iter().map(|s| s.to_string()));
        a
    };
    let owned = |args: &[&str]| args.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    for (args, wanted) in [
        (
            owned(&["equiv", &family, "verlet"]),
            "parameter c has no value: give it one with --param c=VALUE",
        ),
        (
            owned(&["equiv", &family, "verlet", "--param", "c=1", "--param", "d=2"]),
            "no tableau here declares a parameter d",
        ),
        (owned(&["tradeoff", "--method", &family]), "parameter c has no value"),
        (
            owned(&["tradeoff", "--method", &family, "--param", "c=1", "--param", "d=2"]),
            "has no parameter d",
        ),
        (owned(&["tradeoff", "--param", "d=2"]), "none of the methods declares a parameter d"),
        (advise(&[]), "parameter c has no value"),
        (advise(&["--param", "c=1", "--param", "d=2"]), "no tableau here declares a parameter d"),
        (
            owned(&["advise", "--freq", "5", "--tick", "60", "--param", "c=1"]),
            "--param c=1: binds a parameter of a tableau",
        ),
    ] {
        let (code, out, err) = zcheck(&args.iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert!(err.contains(wanted), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

/// Two free parameters under `--min-order` (cubic.zm, R = 1 + w + a₂w² +
/// a₃w³): order 3 leaves the one point (1/2, 1/6), whose real limit is the
/// real root of x³ − 3x² + 6x − 12 (≈ 2.512745); order 2 the line
/// a₂ = 1/2, best at a₃ = 1/16 with the real root of x³ − 8x² + 16x − 32
/// (≈ 6.260791): both checked by hand and by a float scan (poly's
/// `tests/integration/design.rs`), the line also against the one-parameter
/// design with a₂ bound (the oracle).
#[test]
fn min_order_with_two_free_parameters() {
    let cubic = design_file("cubic.zm");
    let args = |order: &'static str| {
        vec![
            "design".to_owned(),
            cubic.clone(),
            "--maximize".into(),
            "real_limit".into(),
            "--param".into(),
            "a2=0..1/2".into(),
            "--param".into(),
            "a3=0..1/6".into(),
            "--min-order".into(),
            order.into(),
        ]
    };
    let run = |a: Vec<String>| json(&a.iter().map(String::as_str).collect::<Vec<_>>());
    let d = run(args("3"));
    check_document(&d, 2, 1);
    assert_eq!(d["grid_check"]["points"], 1);
    assert_eq!(d["optimum"]["defining_poly"], "x^3 - 3*x^2 + 6*x - 12", "{d}");
    assert!((d["optimum"]["value"].as_f64().unwrap() - 2.512745).abs() < 1e-6, "{d}");
    assert_eq!(at(&d), pairs(&[("a2", "1/2"), ("a3", "1/6")]));
    let d = run(args("2"));
    check_document(&d, 2, 200);
    assert_eq!(d["optimum"]["defining_poly"], "x^3 - 8*x^2 + 16*x - 32", "{d}");
    assert!((d["optimum"]["value"].as_f64().unwrap() - 6.260791).abs() < 1e-6, "{d}");
    assert_eq!(at(&d), pairs(&[("a2", "1/2"), ("a3", "1/16")]));
    let cert = d["certificate"].to_string();
    assert!(cert.contains("on the line a2 = 1/2 with a3 in [0, 1/6]"), "{cert}");
    let one = json(&design_args(&cubic, "real_limit", &["a2=1/2", "a3=0..1/6"], &[]));
    assert_eq!(one["optimum"], d["optimum"]);
    assert_eq!(one["at"]["a3"], d["at"]["a3"]);
    // A tableau whose order-2 condition c*d = 1/2 is not affine.
    let cd = temp_file(
        "rk2cd_order.toml",
        "params = [\"c\", \"d\"]\nA = [[0, 0], [\"c\", 0]]\nb = [\"1 - d\", \"d\"]\n",
    );
    let (code, out, err) = zcheck(&design_args(
        cd.to_str().unwrap(),
        "ssp_coefficient",
        &["c=0..1", "d=0..1"],
        &["--min-order", "2"],
    ));
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty() && err.contains("no order condition is affine in (c, d)"), "{err}");
}

/// The one-parameter `--min-order` grid at irrational allowed points: R =
/// 1 + w + a²w² has order 2 at a = ±√2/2, both with real limit 2; the grid
/// check evaluates both exactly (it once had none).
#[test]
fn min_order_grid_at_irrational_points() {
    let half = temp_file("half.zm", "method half\nparam a\nstate y\ny = y + w*y + a^2*w^2*y\n");
    let d = json(&design_args(
        half.to_str().unwrap(),
        "real_limit",
        &["a=-1..1"],
        &["--min-order", "2"],
    ));
    check_document(&d, 1, 2);
    assert_eq!(d["grid_check"]["points"], 2);
    assert_eq!(exact(&d["optimum"]), "2");
    assert_eq!(exact(&d["grid_check"]["max"]), "2");
    assert_eq!(exact(&d["grid_check"]["at"]["a"]), "-sqrt(2)/2");
    assert_eq!(at(&d), pairs(&[("a", "-sqrt(2)/2")]));
}
