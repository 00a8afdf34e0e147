//! `zcheck order` from the outside (issue 35): the issue's 4-stage example,
//! splittings and partitioned pairs, embedded pairs, the literature's
//! values, the JSON's shapes, the default tolerance for long decimals, bad
//! input located, the built-ins' nonlinear readings against their programs,
//! and the library route (`poly::advanced::order`) against the command on
//! every tableau and multistep file the repository holds.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use poly::advanced::order::{self, Options, Order, Ssp};
use poly::advanced::tableau::{Exact, Tableau};
use serde_json::Value;
use testkit::scratch::Scratch;

fn zcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("run zcheck")
}

fn dir(name: &str) -> Scratch {
    Scratch::new(&format!("order-{name}"))
}

fn write(d: &Scratch, name: &str, text: &str) -> String {
    d.file(name, text).display().to_string()
}

/// `zcheck order ARGS --format json`, parsed; the command must succeed.
fn json(args: &[&str]) -> Value {
    let mut a = vec!["order"];
    a.extend_from_slice(args);
    a.extend(["--format", "json"]);
    let out = zcheck(&a);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("json")
}

fn text(args: &[&str]) -> String {
    let mut a = vec!["order"];
    a.extend_from_slice(args);
    let out = zcheck(&a);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap()
}

const ISSUE35: &str = "A = [[0,0,0,0],[1,0,0,0],[0,\"1/2\",0,0],[0,0,\"1/3\",0]]\n\
                       b = [\"5/24\",\"7/24\",\"1/4\",\"1/4\"]\nc = [0,1,\"1/2\",\"1/3\"]\n";

/// The issue's tableau: classical order 2, linear order 4, the tree
/// [[][]] failing with residual 7/144; `zcheck region` now says both.
#[test]
fn the_issues_example() {
    let d = dir("issue");
    let f = write(&d, "issue35.toml", ISSUE35);
    let v = json(&[&f]);
    assert_eq!(
        (&v["kind"], &v["order"], &v["linear_order"]),
        (&"runge_kutta".into(), &2.into(), &4.into())
    );
    let failed = v["failed_conditions"].as_array().unwrap();
    assert_eq!(failed.len(), 1, "{v}");
    assert_eq!(failed[0]["tree"], "[[][]]");
    assert_eq!(failed[0]["differential"], "f''(f,f)");
    assert_eq!(failed[0]["residual"]["exact"], "7/144");
    assert!((failed[0]["residual"]["value"].as_f64().unwrap() - 7.0 / 144.0).abs() < 1e-17);
    let t = text(&[&f]);
    assert!(
        t.contains("classical order        2") && t.contains("linear order           4"),
        "{t}"
    );
    assert!(t.contains("[[][]]") && t.contains("7/144"), "{t}");
    // zcheck region: `order` is the classical order, `linear_order` beside it.
    let out = zcheck(&["region", &f, "--format", "json"]);
    assert!(out.status.success());
    let r: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!((&r["order"], &r["linear_order"]), (&2.into(), &4.into()));
    let out = zcheck(&["region", &f]);
    let t = String::from_utf8(out.stdout).unwrap();
    assert!(
        t.contains("classical order  2") && t.contains("linear order     4 (on y' = λy)"),
        "{t}"
    );
    // A scalar .zm program has no nonlinear reading.
    let zm = write(&d, "euler_w.zm", "method euler_w\nstate y\ny = y + w*y\n");
    let out = zcheck(&["region", &zm, "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let r: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(r["order"].is_null() && r["order_at_least"].is_null(), "{r}");
    assert_eq!(r["linear_order"], 1);
}

/// Strang splitting is order 2 on separable systems, symplectic and
/// symmetric; the Runge–Kutta-only fields are null.
#[test]
fn strang_splitting_is_order_2() {
    let d = dir("strang");
    let f = write(&d, "strang.toml", "drift = [\"1/2\", \"1/2\"]\nkick = [1, 0]\n");
    let v = json(&[&f]);
    assert_eq!((&v["kind"], &v["order"]), (&"splitting".into(), &2.into()));
    assert_eq!((&v["symplectic"], &v["symmetric"]), (&true.into(), &true.into()));
    for key in ["stage_order", "algebraically_stable", "ssp_coefficient", "failed_conditions"] {
        assert!(v[key].is_null(), "{key}: {v}");
    }
    // Symplectic Euler (kick then drift, False Euler's reading): order 1,
    // not symmetric.
    let f = write(&d, "euler.toml", "drift = [0, 1]\nkick = [1, 0]\n");
    let v = json(&[&f]);
    assert_eq!((&v["order"], &v["symmetric"]), (&1.into(), &false.into()));
}

/// Störmer–Verlet as the partitioned pair Lobatto IIIA–IIIB: order 2 on
/// general partitioned systems, symplectic, symmetric.
#[test]
fn partitioned_stormer_verlet() {
    let d = dir("prk");
    let f = write(
        &d,
        "sv.toml",
        "name = \"stormer_verlet\"\n[q]\nA = [[0, 0], [\"1/2\", \"1/2\"]]\nb = [\"1/2\", \"1/2\"]\n\
         [p]\nA = [[\"1/2\", 0], [\"1/2\", 0]]\nb = [\"1/2\", \"1/2\"]\n",
    );
    let v = json(&[&f]);
    assert_eq!((&v["method"], &v["kind"]), (&"stormer_verlet".into(), &"partitioned".into()));
    assert_eq!((&v["order"], &v["linear_order"]), (&2.into(), &2.into()));
    assert_eq!((&v["symplectic"], &v["symmetric"]), (&true.into(), &true.into()));
}

/// Merson's estimator: order 3, but order 5 on y' = λy; the built-in and
/// a file with `bhat` agree.
#[test]
fn merson_embedded_order() {
    let d = dir("merson");
    let f = write(
        &d,
        "merson.toml",
        "A = [[0, 0, 0, 0, 0], [\"1/3\", 0, 0, 0, 0], [\"1/6\", \"1/6\", 0, 0, 0],\n\
         [\"1/8\", 0, \"3/8\", 0, 0], [\"1/2\", 0, \"-3/2\", 2, 0]]\n\
         b = [\"1/6\", 0, 0, \"2/3\", \"1/6\"]\nbhat = [\"1/10\", 0, \"3/10\", \"2/5\", \"1/5\"]\n",
    );
    for v in [json(&[&f]), json(&["merson"])] {
        assert_eq!((&v["kind"], &v["order"]), (&"embedded_pair".into(), &4.into()));
        assert_eq!((&v["embedded_order"], &v["embedded_linear_order"]), (&3.into(), &5.into()));
    }
}

/// Gauss–Legendre with 2 stages: order 4, stage order 2, algebraically
/// stable, symplectic, symmetric.
#[test]
fn gauss_is_symplectic() {
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tableaux/gauss_legendre_2.toml");
    for v in [json(&[file]), json(&["gauss_legendre_2"])] {
        assert_eq!((&v["order"], &v["stage_order"]), (&4.into(), &2.into()), "{v}");
        for key in ["algebraically_stable", "symplectic", "symmetric"] {
            assert_eq!(v[key], true, "{key}: {v}");
        }
        assert_eq!(v["reducible"], false);
    }
}

/// SSPRK(3,3) has SSP coefficient 1, SSPRK(10,4) 6, implicit Euler is
/// unbounded (+∞ as `{"exact": "inf", "value": null}`).
#[test]
fn ssp_coefficients() {
    let d = dir("ssp");
    let f = write(
        &d,
        "ssprk33.toml",
        "A = [[0, 0, 0], [1, 0, 0], [\"1/4\", \"1/4\", 0]]\nb = [\"1/6\", \"1/6\", \"2/3\"]\n",
    );
    let v = json(&[&f]);
    assert_eq!((&v["order"], &v["ssp_coefficient"]["exact"]), (&3.into(), &"1".into()));
    assert_eq!(v["ssp_coefficient"]["value"], 1.0);
    assert_eq!(json(&["ssprk104"])["ssp_coefficient"]["exact"], "6");
    let be = json(&["backward_euler"]);
    assert_eq!(be["ssp_coefficient"], serde_json::json!({"exact": "inf", "value": null}));
}

/// One method gives an object, several an array in argument order; every
/// field is there, null where it does not apply; the modified equation of
/// explicit Euler is f − h/2 f'f + h²(1/12 f''(f,f) + 1/3 f'f'f) (HLW IX).
#[test]
fn json_shapes() {
    let keys = [
        "method",
        "kind",
        "reading",
        "order",
        "order_at_least",
        "linear_order",
        "linear_order_at_least",
        "stage_order",
        "algebraically_stable",
        "symplectic",
        "reducible",
        "symmetric",
        "ssp_coefficient",
        "embedded_order",
        "embedded_order_at_least",
        "embedded_linear_order",
        "embedded_linear_order_at_least",
        "failed_conditions",
        "modified_equation",
        "order_within_tolerance",
        "embedded_order_within_tolerance",
        "notes",
    ];
    let all = json(&["rk4", "verlet", "ab3", "false_heun"]);
    let all = all.as_array().expect("an array for several methods");
    let names: Vec<&str> = all.iter().map(|v| v["method"].as_str().unwrap()).collect();
    assert_eq!(names, ["rk4", "verlet", "ab3", "false_heun"]);
    let kinds: Vec<&str> = all.iter().map(|v| v["kind"].as_str().unwrap()).collect();
    assert_eq!(kinds, ["runge_kutta", "splitting", "multistep", "partitioned"]);
    for v in all {
        let obj = v.as_object().unwrap();
        let mut got: Vec<&str> = obj.keys().map(String::as_str).collect();
        let mut want = keys.to_vec();
        got.sort_unstable();
        want.sort_unstable();
        assert_eq!(got, want, "{v}");
    }
    let ab3 = &all[2];
    assert_eq!((&ab3["order"], &ab3["linear_order"]), (&3.into(), &3.into()));
    for key in ["symplectic", "symmetric", "stage_order", "ssp_coefficient", "modified_equation"] {
        assert!(ab3[key].is_null(), "{key}");
    }
    assert!(json(&["rk4"]).is_object());
    let euler = json(&["standard_euler", "--modified", "2"]);
    let terms: Vec<(u64, &str, &str, &str)> = euler["modified_equation"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| {
            (
                t["power"].as_u64().unwrap(),
                t["tree"].as_str().unwrap(),
                t["differential"].as_str().unwrap(),
                t["coefficient"]["exact"].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        terms,
        [
            (1, "[[]]", "f'f", "-1/2"),
            (2, "[[[]]]", "f'f'f", "1/3"),
            (2, "[[][]]", "f''(f,f)", "1/12")
        ]
    );
    // --modified on a method that is no tableau: null, and a note.
    let v = json(&["verlet", "--modified", "2"]);
    assert!(v["modified_equation"].is_null());
    assert!(v["notes"]
        .as_array()
        .unwrap()
        .iter()
        .any(|n| n.as_str().unwrap().contains("--modified")));
}

/// Decimals of 10 or more significant digits get the order within 1e-12
/// beside the exact order (Tsit5 from its 17-digit floats: exactly 0,
/// within 1e-12 5); `--tolerance` sets it; short decimals get none.
#[test]
fn tolerance_for_long_decimals() {
    let tsit5 = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/nodepy/rk/Tsit5.toml");
    let v = json(&[tsit5]);
    assert_eq!(v["order"], 0);
    let w = &v["order_within_tolerance"];
    assert_eq!((&w["order"], &w["tolerance"]["exact"]), (&5.into(), &"1/1000000000000".into()));
    let v = json(&[tsit5, "--tolerance", "1e-14"]);
    assert_eq!(v["order_within_tolerance"]["order"], 4);
    let d = dir("tol");
    // Bogacki–Shampine 3(2) from 16-digit decimals: the pair within 1e-12 is
    // 3 and its estimator 2, as with the exact fractions.
    let bs3 = write(
        &d,
        "bs3.toml",
        "A = [[0, 0, 0, 0], [0.5, 0, 0, 0], [0, 0.75, 0, 0], \
         [0.2222222222222222, 0.3333333333333333, 0.4444444444444444, 0]]\n\
         b = [0.2222222222222222, 0.3333333333333333, 0.4444444444444444, 0]\n\
         bhat = [0.2916666666666667, 0.25, 0.3333333333333333, 0.125]\n",
    );
    let v = json(&[&bs3]);
    assert_eq!(v["kind"], "embedded_pair");
    assert_eq!(v["order_within_tolerance"]["order"], 3, "{v}");
    assert_eq!(v["embedded_order_within_tolerance"]["order"], 2, "{v}");
    let exact = write(
        &d,
        "bs3_exact.toml",
        "A = [[0, 0, 0, 0], [\"1/2\", 0, 0, 0], [0, \"3/4\", 0, 0], [\"2/9\", \"1/3\", \"4/9\", 0]]\n\
         b = [\"2/9\", \"1/3\", \"4/9\", 0]\nbhat = [\"7/24\", \"1/4\", \"1/3\", \"1/8\"]\n",
    );
    let e = json(&[&exact]);
    assert_eq!((&e["order"], &e["embedded_order"]), (&3.into(), &2.into()), "{e}");
    assert!(e["embedded_order_within_tolerance"].is_null(), "{e}");
    let f = write(&d, "heun.toml", "A = [[0, 0], [1, 0]]\nb = [0.5, 0.5]\n");
    let v = json(&[&f]);
    assert_eq!(v["order"], 2);
    assert!(v["order_within_tolerance"].is_null(), "{v}");
    let v = json(&[&f, "--tolerance", "1/10"]);
    assert_eq!(v["order_within_tolerance"]["order"], 2);
}

/// Bad input: file:line:column, what was expected, exit 2.
#[test]
fn bad_input_is_located() {
    let d = dir("bad");
    for (name, text, at, says) in [
        ("q_only.toml", "[q]\nA = [[0]]\nb = [1]\n", ":1:1", "[q] without [p]"),
        ("p_only.toml", "name = \"x\"\n\n[p]\nA = [[0]]\nb = [1]\n", ":3:1", "[p] without [q]"),
        (
            "bhat.toml",
            "A = [[0]]\nb = [1]\nbhat = [1, 0]\n",
            ":3:8",
            "bhat has 2 entries: expected 1",
        ),
        (
            "unequal.toml",
            "drift = [1, 2]\nkick = [1]\n",
            ":2:8",
            "kick has 1 coefficients and drift 2",
        ),
        ("no_kick.toml", "drift = [1]\n", ":1:1", "no `kick`"),
        (
            "stages.toml",
            "[q]\nA = [[0]]\nb = [1]\n[p]\nA = [[0, 0], [1, 0]]\nb = [\"1/2\", \"1/2\"]\n",
            ":4:1",
            "[p] has 2 stages and [q] 1",
        ),
        ("entry.toml", "[q]\nA = [[x]]\nb = [1]\n[p]\nA = [[0]]\nb = [1]\n", ":2:7", ""),
        (
            "qentry.toml",
            "[q]\nA = [[\"1/0\"]]\nb = [1]\n[p]\nA = [[0]]\nb = [1]\n",
            ":2:7",
            "q.A[1][1]",
        ),
        ("mixed.toml", "A = [[0]]\nb = [1]\n[q]\nA = [[0]]\nb = [1]\n", ":1:1", "unknown field"),
    ] {
        let f = write(&d, name, text);
        let out = zcheck(&["order", &f]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(err.contains(&format!("{name}{at}")), "{name}: {err}");
        assert!(err.contains(says), "{name}: {err}");
        assert!(!err.contains("panicked"), "{name}: {err}");
    }
    for (args, says) in [
        (vec!["order", "rk4", "--modified", "11"], "--modified 11"),
        (vec!["order", "rk4", "--modified", "0"], "expected a power from 1 to 10"),
        (vec!["order", "rk4", "--tolerance", "-1"], "expected a tolerance ≥ 0"),
        (vec!["order", "soft_spring"], "no nonlinear reading"),
        (vec!["order", "no_such_method"], "no built-in method named"),
    ] {
        let out = zcheck(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(says), "{args:?}: {err}");
    }
    let zm = write(&d, "m.zm", "method m\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n");
    let out = zcheck(&["order", &zm]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no nonlinear reading"));
}

/// Every built-in with a nonlinear reading: its linear order is the order
/// `zcheck region` finds from the built-in's program, and `zcheck region`'s
/// classical order is `zcheck order`'s; the paper's methods read as the
/// issue says (Standard Euler and Heun RK 1 and 2, False and Damped Euler
/// the symplectic Euler splittings, Verlet Störmer–Verlet, False and
/// Semi-False Heun partitioned pairs of order 1 and 2).
#[test]
fn builtin_readings_agree_with_their_programs() {
    let names: Vec<&str> = poly::advanced::builtins::all_builtin_names().collect();
    let mut read = Vec::new();
    for name in &names {
        let out = zcheck(&["order", name, "--format", "json"]);
        if out.status.success() {
            read.push((*name, serde_json::from_slice::<Value>(&out.stdout).unwrap()));
        } else {
            assert!(
                String::from_utf8_lossy(&out.stderr).contains("no nonlinear reading"),
                "{name}"
            );
        }
    }
    assert!(read.len() >= 35, "{}", read.len());
    // Tableaux and multistep methods: against the program's w-plane (a
    // partitioned method has no step on y' = λy).
    let on_plane: Vec<&(&str, Value)> = read
        .iter()
        .filter(|(_, v)| !matches!(v["kind"].as_str(), Some("splitting" | "partitioned")))
        .collect();
    let mut args = vec!["region"];
    args.extend(on_plane.iter().map(|(n, _)| *n));
    args.extend(["--format", "json"]);
    let out = zcheck(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let regions: Vec<Value> = serde_json::from_slice(&out.stdout).unwrap();
    for ((name, o), r) in on_plane.iter().zip(&regions) {
        assert_eq!(o["linear_order"], r["linear_order"], "{name}: the reading against the program");
        assert_eq!(o["order"], r["order"], "{name}");
    }
    // Splittings and pairs: the reading's step on the oscillator y' = Φv,
    // v' = −Φy, written out here from its coefficients, has the built-in's χ.
    let split = |drift: &[&str], kick: &[&str]| {
        let mut s = String::from("method r\nstate v y\nconst c = cbrt(2)\n");
        for (a, b) in drift.iter().zip(kick) {
            s += &format!("y = y + ({a})*Phi*v\nv = v - ({b})*Phi*y\n");
        }
        s
    };
    let theta = "1/(2 - c)";
    let fr_d = format!("{theta}/2");
    let fr_m = format!("(1 - {theta})/2");
    let fr_k = format!("1 - 2*{theta}");
    for (name, program) in [
        ("damped_euler", split(&["1"], &["1"])),
        ("false_euler", split(&["0", "1"], &["1", "0"])),
        ("verlet", split(&["1/2", "1/2"], &["1", "0"])),
        ("forest_ruth", split(&[&fr_d, &fr_m, &fr_m, &fr_d], &[theta, &fr_k, theta, "0"])),
        // [q] A = [[0, 0], [1, 0]], [p] A = [[0, 0], [0, 1]], b = b̂ = (1/2, 1/2).
        (
            "semi_false_heun",
            "method r\nstate v y\nY1 = y\nV1 = v\nY2 = y + Phi*V1\nV2 = v - Phi*Y2\n\
             y = y + Phi/2*(V1 + V2)\nv = v - Phi/2*(Y1 + Y2)\n"
                .to_owned(),
        ),
        // [p] A = [[1, 0], [0, 1]]: V1 = v + h g(Y1).
        (
            "false_heun",
            "method r\nstate v y\nY1 = y\nV1 = v - Phi*Y1\nY2 = y + Phi*V1\nV2 = v - Phi*Y2\n\
             y = y + Phi/2*(V1 + V2)\nv = v - Phi/2*(Y1 + Y2)\n"
                .to_owned(),
        ),
    ] {
        let ours = poly::derive(&poly::Method::parse("<reading>", &program).unwrap()).unwrap();
        let theirs = poly::derive(&poly::builtin(name).unwrap()).unwrap();
        assert_eq!(ours.charpoly(), theirs.charpoly(), "{name}");
    }
    let get = |n: &str| &read.iter().find(|(m, _)| *m == n).unwrap().1;
    for (name, kind, order) in [
        ("standard_euler", "runge_kutta", 1),
        ("standard_euler_matrix", "runge_kutta", 1),
        ("standard_heun", "runge_kutta", 2),
        ("false_euler", "splitting", 1),
        ("damped_euler", "splitting", 1),
        ("verlet", "splitting", 2),
        ("false_heun", "partitioned", 1),
        ("semi_false_heun", "partitioned", 2),
        ("forest_ruth", "splitting", 4),
        ("rk4", "runge_kutta", 4),
        ("ab8", "multistep", 8),
        ("nystrom6", "multistep", 6),
    ] {
        let v = get(name);
        assert_eq!((&v["kind"], &v["order"]), (&kind.into(), &order.into()), "{name}");
    }
    assert_eq!(
        (&get("verlet")["symplectic"], &get("damped_euler")["symplectic"]),
        (&true.into(), &true.into())
    );
}

/// `zcheck methods` names the state size and gives the classical order
/// where a built-in has a nonlinear reading, `—` where it has none.
#[test]
fn methods_lists_state_size_and_classical_order() {
    let out = zcheck(&["methods"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("method") && text.lines().next().unwrap().contains("state size"));
    let row = |name: &str| -> Vec<String> {
        let line = text.lines().find(|l| l.split_whitespace().next() == Some(name)).unwrap();
        line.split_whitespace().skip(1).take(3).map(str::to_owned).collect()
    };
    for (name, cells) in [
        ("standard_euler", ["2", "1", "RK"]),
        ("damped_euler", ["2", "1", "split"]),
        ("false_euler", ["2", "1", "split"]),
        ("verlet", ["2", "2", "split"]),
        ("standard_heun", ["2", "2", "RK"]),
        ("false_heun", ["2", "1", "PRK"]),
        ("semi_false_heun", ["2", "2", "PRK"]),
        ("rk4", ["2", "4", "RK"]),
        ("ab8", ["16", "8", "LMM"]),
        ("bdf2", ["4", "2", "LMM"]),
    ] {
        assert_eq!(row(name), cells, "{name}");
    }
    assert_eq!(row("soft_spring")[1], "—");
    assert_eq!(row("false_euler_damped")[1], "—");
}

// ---------------------------------------------------------------------
// The library route against the command.

/// A TOML list of entries as poly's exact entries, as the command reads
/// them (a float as the decimal it prints).
fn entries(v: &toml::Value) -> Vec<Exact> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| {
            let s = match x {
                toml::Value::Integer(i) => i.to_string(),
                toml::Value::Float(f) => format!("{f}"),
                toml::Value::String(s) => s.clone(),
                other => panic!("{other:?}"),
            };
            Exact::parse(&s).unwrap()
        })
        .collect()
}

/// Whether the file (comments aside) holds a decimal of 10 or more
/// significant digits.
fn long_decimal(text: &str) -> bool {
    let text: String =
        text.lines().filter(|l| !l.trim_start().starts_with('#')).collect::<Vec<_>>().join("\n");
    text.split(|c: char| !(c.is_ascii_digit() || c == '.')).filter(|w| w.contains('.')).any(|w| {
        w.chars().filter(char::is_ascii_digit).collect::<String>().trim_start_matches('0').len()
            >= 10
    })
}

fn order_value(o: Order) -> (Value, Value) {
    match o {
        Order::Exact(p) => (p.into(), Value::Null),
        Order::AtLeast(p) => (Value::Null, p.into()),
    }
}

/// Every tableau in `crates/zcheck/tableaux`, every NodePy Runge–Kutta and
/// multistep file in `tests/data/nodepy`: poly's report, computed here from
/// the file's entries, is the command's JSON, field by field.
#[test]
fn library_route_and_cli_agree_on_every_file() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<PathBuf> = Vec::new();
    for sub in ["tableaux", "tests/data/nodepy/rk", "tests/data/nodepy/lmm"] {
        let mut f: Vec<PathBuf> = std::fs::read_dir(root.join(sub))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .collect();
        f.sort();
        files.extend(f);
    }
    assert!(files.len() >= 4 + 50 + 40, "{}", files.len());
    let mut args = vec!["order".to_owned()];
    args.extend(files.iter().map(|p| p.display().to_string()));
    args.extend(["--format".to_owned(), "json".to_owned()]);
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck")).args(&args).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let docs: Vec<Value> = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(docs.len(), files.len());
    let tol = poly::q(1, 1_000_000_000_000);
    for (path, doc) in files.iter().zip(&docs) {
        let text = std::fs::read_to_string(path).unwrap();
        let t: toml::Table = toml::from_str(&text).unwrap();
        let options =
            Options { modified: None, tolerance: long_decimal(&text).then(|| tol.clone()) };
        let r = if t.contains_key("alpha") {
            let m = poly::advanced::multistep::Multistep::new(
                "m",
                entries(&t["alpha"]),
                entries(&t["beta"]),
            )
            .unwrap();
            order::multistep(&m, &options).unwrap()
        } else {
            let a: Vec<Vec<Exact>> = t["A"].as_array().unwrap().iter().map(entries).collect();
            let c = t.get("c").map(entries);
            let tableau = Tableau::new("t", a, entries(&t["b"]), c).unwrap();
            let bhat = t.get("bhat").map(entries);
            order::runge_kutta(&tableau, bhat.as_deref(), &options).unwrap()
        };
        let at = path.display();
        assert_eq!(doc["kind"], r.kind.name(), "{at}");
        assert_eq!(
            (doc["order"].clone(), doc["order_at_least"].clone()),
            order_value(r.order),
            "{at}"
        );
        assert_eq!(
            (doc["linear_order"].clone(), doc["linear_order_at_least"].clone()),
            order_value(r.linear_order),
            "{at}"
        );
        assert_eq!(doc["stage_order"], serde_json::json!(r.stage_order), "{at}");
        assert_eq!(doc["algebraically_stable"], serde_json::json!(r.algebraically_stable), "{at}");
        assert_eq!(doc["symplectic"], serde_json::json!(r.symplectic), "{at}");
        assert_eq!(doc["symmetric"], serde_json::json!(r.symmetric), "{at}");
        assert_eq!(doc["reducible"], serde_json::json!(r.reducible), "{at}");
        match &r.ssp_coefficient {
            None => assert!(doc["ssp_coefficient"].is_null(), "{at}"),
            Some(Ssp::Unbounded) => assert_eq!(doc["ssp_coefficient"]["exact"], "inf", "{at}"),
            Some(Ssp::Radius(x)) => {
                let v = doc["ssp_coefficient"]["value"].as_f64().unwrap();
                let ours = testkit::oracle::nearest_f64(x);
                assert_eq!(v, ours, "{at}");
                if let Some(c) = x.closed_form() {
                    assert_eq!(doc["ssp_coefficient"]["exact"], c, "{at}");
                }
            }
        }
        let failed: Vec<(String, String)> = r
            .failed_conditions
            .iter()
            .flatten()
            .map(|f| (f.tree.clone(), f.residual.to_string()))
            .collect();
        let shown: Vec<(String, String)> = doc["failed_conditions"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|f| {
                (
                    f["tree"].as_str().unwrap().to_owned(),
                    f["residual"]["exact"].as_str().unwrap().to_owned(),
                )
            })
            .collect();
        assert_eq!(shown, failed, "{at}");
        match &r.order_within_tolerance {
            None => assert!(doc["order_within_tolerance"].is_null(), "{at}"),
            Some(w) => {
                let d = &doc["order_within_tolerance"];
                assert_eq!(
                    (d["order"].clone(), d["order_at_least"].clone()),
                    order_value(w.order),
                    "{at}"
                );
            }
        }
    }
}

/// A splitting or a partitioned pair is a method on the oscillator too
/// (q = y, p = v): every command reads it. Its χ is the built-in's that it
/// spells out: Strang and the Lobatto IIIA–IIIB pair are Verlet's, the
/// Forest–Ruth coefficients are `forest_ruth`'s; `stability` and `verify`
/// agree with the built-in; the damped spring (not separable) is refused.
#[test]
fn partitioned_methods_on_the_oscillator() {
    let run = |args: &[&str]| -> Value {
        let out = zcheck(args);
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_slice(&out.stdout).expect("json")
    };
    let d = dir("osc");
    let strang = write(&d, "strang.toml", "drift = [\"1/2\", \"1/2\"]\nkick = [1, 0]\n");
    let pair = write(
        &d,
        "sv.toml",
        "name = \"stormer_verlet\"\n[q]\nA = [[0, 0], [\"1/2\", \"1/2\"]]\nb = [\"1/2\", \"1/2\"]\n\
         [p]\nA = [[\"1/2\", 0], [\"1/2\", 0]]\nb = [\"1/2\", \"1/2\"]\n",
    );
    let fr = write(
        &d,
        "fr.toml",
        "drift = [\"1/(2*(2 - cbrt(2)))\", \"(1 - cbrt(2))/(2*(2 - cbrt(2)))\", \
         \"(1 - cbrt(2))/(2*(2 - cbrt(2)))\", \"1/(2*(2 - cbrt(2)))\"]\n\
         kick = [\"1/(2 - cbrt(2))\", \"-cbrt(2)/(2 - cbrt(2))\", \"1/(2 - cbrt(2))\", 0]\n",
    );
    let chi = |m: &str| run(&["derive", m, "--format", "json"])["charpoly"].clone();
    assert_eq!(chi(&strang), chi("verlet"));
    assert_eq!(chi(&pair), chi("verlet"));
    assert_eq!(chi(&fr), chi("forest_ruth"));
    let phi_max = |m: &str| run(&["stability", m, "--format", "json"])["phi_max_exact"].clone();
    assert_eq!(phi_max("verlet"), "2");
    assert_eq!(phi_max(&strang), phi_max("verlet"));
    assert_eq!(phi_max(&fr), phi_max("forest_ruth"));
    let out = zcheck(&["verify", &pair, "--phi", "1.9"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // The order report still reads the file.
    assert_eq!(json(&[&fr])["order"], 4);
    // The whole-scene advisor's damped spring is not of the form q' = f(p), p' = g(q).
    let scene = write(&d, "s.toml", "tick_hz = 60\n[[mode]]\nhz = 2\n");
    let out = zcheck(&["advise", "--scene", &scene, "--methods", &strang]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("the damped spring (p' depends on p) is not of that form"), "{err}");
}
