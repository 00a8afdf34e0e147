//! `zcheck derive` and `zcheck methods`, run as a user runs them: the built
//! binary, its exit code, stdout and stderr.

use std::path::PathBuf;
use std::process::{Command, Output};

use poly::{Poly, Sym};
use serde_json::Value;

fn zcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("zcheck runs")
}

fn stdout(out: &Output) -> String {
    String::from_utf8(out.stdout.clone()).expect("utf-8 stdout")
}

fn stderr(out: &Output) -> String {
    String::from_utf8(out.stderr.clone()).expect("utf-8 stderr")
}

/// A fresh directory for this test's files.
fn temp_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("cli_derive_{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Runs `zcheck derive <arg> --format json` and checks the document: the
/// required keys, a square transition matrix of polynomial strings, and
/// charpoly_coeffs (highest power first) that rebuild charpoly when parsed.
#[track_caller]
fn check_json(arg: &str, method: &str, state: &[&str], params: &[&str]) -> Value {
    let out = zcheck(&["derive", arg, "--format", "json"]);
    assert!(out.status.success(), "{arg}: {}", stderr(&out));
    let v: Value = serde_json::from_str(&stdout(&out)).expect("valid JSON");
    assert_eq!(v["method"], method);
    assert_eq!(v["state"], serde_json::json!(state));
    assert_eq!(v["params"], serde_json::json!(params));
    assert_eq!(v["routes_agree"], true);
    // Exact constants print as generator symbols (`sqrt(3)`, `cbrt(2)`),
    // which the plain polynomial parser does not read back.
    let text = stdout(&out);
    if ["sqrt(", "cbrt(", "root("].iter().any(|g| v["charpoly"].as_str().unwrap().contains(g)) {
        assert!(text.contains("charpoly"));
        return v;
    }

    let rows = v["transition_matrix"].as_array().expect("transition_matrix rows");
    for row in rows {
        let row = row.as_array().expect("a row is an array");
        assert_eq!(row.len(), rows.len(), "square");
        for entry in row {
            Poly::parse(entry.as_str().expect("entries are strings")).expect("entry parses");
        }
    }
    let charpoly = Poly::parse(v["charpoly"].as_str().expect("charpoly string")).expect("parses");
    let coeffs: Vec<Poly> = v["charpoly_coeffs"]
        .as_array()
        .expect("charpoly_coeffs array")
        .iter()
        .map(|c| Poly::parse(c.as_str().expect("string")).expect("coefficient parses"))
        .collect();
    assert_eq!(coeffs.len(), rows.len() + 1, "degree = size of P");
    match v["p_denominator"].as_str() {
        // An implicit step: the leading coefficient is det A.
        Some(d) => assert_eq!(coeffs[0], Poly::parse(d).unwrap(), "leading = det A"),
        None => assert!(coeffs[0].is_one(), "monic"),
    }
    let lowest_first: Vec<Poly> = coeffs.iter().rev().cloned().collect();
    assert_eq!(Poly::from_coeffs_in(Sym::z(), &lowest_first), charpoly, "coeffs rebuild charpoly");
    v
}

#[test]
fn derive_every_builtin_in_every_format() {
    for name in poly::advanced::builtins::builtin_names() {
        let m = poly::builtin(name).expect("built-in");
        let state: Vec<&str> = m.state().iter().map(String::as_str).collect();
        let params: Vec<&str> = m.params().iter().map(|p| p.name()).collect();
        let v = check_json(name, name, &state, &params);
        // The JSON agrees with the library's own derivation.
        let d = poly::derive(&m).expect("derives");
        assert_eq!(v["charpoly"], d.charpoly().to_string(), "{name}");

        let text = zcheck(&["derive", name]);
        assert!(text.status.success(), "{name}: {}", stderr(&text));
        let text = stdout(&text);
        assert!(text.contains(&format!("chi(z) = {}", d.charpoly())), "{name}:\n{text}");
        if let Some((p, q)) = d.p_q() {
            assert!(text.contains("z^2 - 2*p*z + q"), "{name}:\n{text}");
            assert!(
                text.contains(&format!("p = {p}")) && text.contains(&format!("q = {q}")),
                "{text}"
            );
        }

        let latex = zcheck(&["derive", name, "--format", "latex"]);
        assert!(latex.status.success(), "{name}: {}", stderr(&latex));
        let latex = stdout(&latex);
        assert!(latex.contains("\\begin{pmatrix}"), "{name}:\n{latex}");
        assert!(latex.contains(&d.charpoly().latex()), "{name}:\n{latex}");
    }
}

/// A method the user writes: three state variables, history, a parameter
/// and a temporary.
#[test]
fn derive_a_user_written_file() {
    let dir = temp_dir("user");
    let path = dir.join("leapfrog_damped.zm");
    std::fs::write(
        &path,
        "# a user's method\nmethod leapfrog_damped\nstate v y x\nparam c\n\
         a = -Phi*y - c*Phi*v\nv = v + a\ny = y + Phi*v - 0.5*x@1\nx = y\n",
    )
    .expect("write");
    let path = path.to_str().expect("utf-8 path");
    let v = check_json(path, "leapfrog_damped", &["v", "y", "x"], &["Phi", "c"]);
    assert_eq!(v["charpoly_coeffs"].as_array().map(Vec::len), Some(5), "order 1 + 1 + 2");
}

#[test]
fn a_bad_file_fails_with_its_location() {
    let dir = temp_dir("bad");
    let path = dir.join("bad.zm");
    std::fs::write(&path, "method bad\nstate v y\nv = v - Phi*y\ny = y + v*y\n").expect("write");
    let path = path.to_str().expect("utf-8 path");
    let out = zcheck(&["derive", path]);
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(err.contains(&format!("{path}:4:9:")), "{err}");
    assert!(err.contains("nonlinear"), "{err}");
    assert!(stdout(&out).is_empty(), "nothing on stdout: {}", stdout(&out));
}

#[test]
fn missing_files_and_unknown_names_are_clear_errors() {
    let dir = temp_dir("missing");
    let path = dir.join("nowhere.zm");
    let path = path.to_str().expect("utf-8 path");
    let out = zcheck(&["derive", path]);
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(err.contains(path) && err.contains("cannot read"), "{err}");

    let out = zcheck(&["derive", "no_such_method"]);
    assert!(!out.status.success());
    let err = stderr(&out);
    assert!(err.contains("no_such_method") && err.contains("standard_euler"), "{err}");
}

#[test]
fn methods_lists_every_builtin() {
    let out = zcheck(&["methods"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = stdout(&out);
    for name in poly::advanced::builtins::builtin_names() {
        let order = poly::builtin(name).expect("built-in").state_size();
        let line = text
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("{name} missing from:\n{text}"));
        assert_eq!(line.split_whitespace().nth(1), Some(order.to_string().as_str()), "{line}");
    }
}
