//! `zcheck stability` from the outside: the JSON fields the issue asks for,
//! the paper's limits as f64 within a few ulps of values computed here from
//! their closed forms, parameters, and bad input reported as errors.

use std::process::{Command, Output};

use serde_json::Value;

fn zcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("run zcheck")
}

fn json(args: &[&str]) -> Value {
    let mut all = vec!["stability"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--format", "json"]);
    let out = zcheck(&all);
    assert!(out.status.success(), "{all:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("json")
}

/// `phi_max` within 2 ulps of `expected`, the exact form, the boundary kind,
/// and the (from, to) class pairs in order.
#[track_caller]
fn check(
    args: &[&str],
    expected: Option<(f64, &str)>,
    boundary: Option<&str>,
    changes: &[(&str, &str)],
) {
    let v = json(args);
    match expected {
        Some((phi, exact)) => {
            let got = v["phi_max"].as_f64().expect("phi_max is a number");
            assert!((got - phi).abs() <= 2.0 * f64::EPSILON * phi, "{args:?}: {got} vs {phi}");
            assert_eq!(v["phi_max_exact"], exact, "{args:?}");
        }
        None => {
            assert!(v["phi_max"].is_null(), "{args:?}");
            assert!(v["phi_max_exact"].is_null(), "{args:?}");
        }
    }
    assert_eq!(v["boundary"].as_str(), boundary, "{args:?}");
    let got: Vec<(String, String)> = v["class_changes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            assert!(c["phi"].is_f64() && c["phi_exact"].is_string(), "{c}");
            (c["from"].as_str().unwrap().to_owned(), c["to"].as_str().unwrap().to_owned())
        })
        .collect();
    let want: Vec<(String, String)> =
        changes.iter().map(|(a, b)| ((*a).to_owned(), (*b).to_owned())).collect();
    assert_eq!(got, want, "{args:?}");
}

#[test]
fn paper_limits() {
    check(
        &["false_euler"],
        Some((2.0, "2")),
        Some("double_root_at_minus_one"),
        &[("harmonic", "alternating_unstable")],
    );
    check(&["standard_euler"], None, None, &[]);
    check(&["standard_heun"], None, None, &[]);
    check(
        &["false_heun"],
        Some((2f64.sqrt(), "sqrt(2)")),
        Some("root_through_plus_one"),
        &[("damped_oscillation", "monotonic_stable"), ("monotonic_stable", "monotonic_unstable")],
    );
    check(
        &["semi_false_heun"],
        Some(((2.0 * 5f64.sqrt() - 2.0).sqrt(), "sqrt(2*sqrt(5) - 2)")),
        Some("root_through_minus_one"),
        &[
            ("damped_oscillation", "alternating_stable"),
            ("alternating_stable", "alternating_unstable"),
        ],
    );
    check(
        &["damped_euler_d", "--param", "D=0.5"],
        Some((1.0, "1")),
        Some("complex_pair_leaves_circle"),
        &[("damped_oscillation", "unstable_oscillation")],
    );
    check(
        &["damped_euler_d", "--param", "D=2"],
        Some((4.0 - 2.0 * 3f64.sqrt(), "4 - 2*sqrt(3)")),
        Some("root_through_minus_one"),
        &[
            ("monotonic_stable", "alternating_stable"),
            ("alternating_stable", "alternating_unstable"),
        ],
    );
}

/// An irrational limit without a closed form is given by its defining
/// polynomial and an isolating interval no wider than 1e-15.
#[test]
fn exact_detail_of_the_limit() {
    let v = json(&["semi_false_heun"]);
    let d = &v["phi_max_detail"];
    assert_eq!(d["defining_poly"], "Phi^4 + 4*Phi^2 - 16");
    assert_eq!(d["decimal"], "1.572302755514847");
    let parse = |s: &Value| -> (i128, i128) {
        let s = s.as_str().unwrap();
        let (n, d) = s.split_once('/').unwrap_or((s, "1"));
        (n.parse().unwrap(), d.parse().unwrap())
    };
    let ((ln, ld), (hn, hd)) = (parse(&d["interval"][0]), parse(&d["interval"][1]));
    // hi − lo = (hn·ld − ln·hd)/(hd·ld) ≤ 1e-15, in integers.
    assert!((hn * ld - ln * hd) * 1_000_000_000_000_000 <= hd * ld);
    let v = json(&["false_heun"]);
    let first = &v["class_changes"][0]["phi_exact"];
    assert!(
        first.as_str().unwrap().starts_with("root of Phi^6 - 6*Phi^4 + 17*Phi^2 - 16 in ["),
        "{first}"
    );
}

#[test]
fn text_format_names_the_limit() {
    let out = zcheck(&["stability", "semi_false_heun"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("stable for 0 < Phi < sqrt(2*sqrt(5) - 2) ≈ 1.572302755514847"),
        "{text}"
    );
    assert!(text.contains("root_through_minus_one"), "{text}");
}

/// A limit without a closed form (AB8's, a root of a degree-20
/// polynomial with 60-digit coefficients) is named r1 wherever it bounds
/// an interval, and its defining polynomial is printed once, with an
/// isolating interval narrower than 1e-15, not at every mention.
#[test]
fn text_format_names_roots_once() {
    let out = zcheck(&["stability", "ab8"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("stable for 0 < Phi < 0.029489552040055 (r1)"), "{text}");
    assert_eq!(text.matches("root of Phi^20").count(), 1, "{text}");
    let def = text.lines().find(|l| l.starts_with("  r1 = root of Phi^20")).expect("defined");
    assert!(def.contains(" in ["), "{def}");
    assert!(!text.contains("(r2)"), "one number without a closed form: {text}");
    // Every name used is defined.
    let out = zcheck(&["stability", "ssprk104"]);
    let text = String::from_utf8(out.stdout).unwrap();
    for k in 1..=5 {
        assert!(text.contains(&format!("(r{k})")), "{text}");
        assert!(text.contains(&format!("\n  r{k} = root of ")), "{text}");
    }
}

#[track_caller]
fn check_rejected(args: &[&str], expected: &str) {
    let out = zcheck(args);
    assert!(!out.status.success(), "{args:?} succeeded");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains(expected), "{args:?}: {stderr:?} lacks {expected:?}");
}

#[test]
fn bad_input_is_an_error() {
    check_rejected(&["stability", "damped_euler_d"], "still contains the parameter D");
    check_rejected(&["stability", "damped_euler_d", "--param", "X=1"], "has no parameter X");
    check_rejected(&["stability", "damped_euler_d", "--param", "D"], "expected NAME=VALUE");
    check_rejected(&["stability", "damped_euler_d", "--param", "D=abc"], "expected a number");
    check_rejected(&["stability", "false_euler", "--param", "Phi=1"], "Phi is the step size");
    check_rejected(&["stability", "no_such_method"], "no_such_method");
}
