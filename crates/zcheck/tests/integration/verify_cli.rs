//! `zcheck verify` end to end: JSON shape, the acceptance run over every
//! built-in with class boundaries, exit statuses and error messages.

use std::process::Command;

use serde_json::Value;

fn zcheck(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Built-ins of every kind (the paper's seven, implicit one-step methods, a
/// damped-spring twin) at the default Φ list and both sides of every
/// boundary, through the command line: exit 0, every point agrees, and each
/// point has the documented fields. Every built-in's boundaries are checked
/// through the library by check's `builtins_agree_at_every_class_boundary`
/// (the same sweep and witnesses); this is the command's document.
#[test]
fn builtins_verify_with_boundaries() {
    let names: Vec<&str> = poly::advanced::builtins::PAPER_METHODS
        .iter()
        .copied()
        .chain(["trapezoidal", "backward_euler", "gauss_legendre_2", "semi_false_heun_damped"])
        .collect();
    let mut args = vec!["verify"];
    args.extend(&names);
    args.extend(["--steps", "5000", "--boundaries", "--param", "D=0.3", "--format", "json"]);
    let (code, out, err) = zcheck(&args);
    assert_eq!(code, 0, "stderr: {err}");
    let v: Value = serde_json::from_str(&out).expect("json");
    let methods = v.as_array().expect("array");
    assert_eq!(methods.len(), names.len());
    for m in methods {
        assert_eq!(m["agree"], true, "{}", m["method"]);
        let points = m["points"].as_array().unwrap();
        assert!(points.len() >= 6);
        for p in points {
            let psi = p["psi"].as_f64().unwrap();
            assert!((0.0..=std::f64::consts::PI).contains(&psi), "psi {psi}");
            let eig = p["eigenvalues"].as_array().unwrap();
            let rho = eig
                .iter()
                .map(|z| z[0].as_f64().unwrap().hypot(z[1].as_f64().unwrap()))
                .fold(0.0, f64::max);
            let stated = p["spectral_radius"].as_f64().unwrap();
            assert!(
                (rho - stated).abs() <= 4.0 * f64::EPSILON * stated.max(1.0),
                "{rho} vs {stated}"
            );
            assert!(poly::RootClass::from_name(p["class"].as_str().unwrap()).is_some());
            assert_eq!(p["sim"]["steps"], 5000);
            assert!(p["sim"]["growth_per_step"].is_f64() && p["sim"]["psi_per_step"].is_f64());
            assert_eq!(p["agree"], true);
        }
    }
}

/// The text table names each method and says whether it agrees.
#[test]
fn text_output_lists_points() {
    let (code, out, _) = zcheck(&["verify", "false_euler", "--phi", "0.5,2", "--steps", "1000"]);
    assert_eq!(code, 0);
    assert!(out.starts_with("false_euler: witnesses agree\n"), "{out}");
    assert!(out.contains("double_root_on_circle"), "{out}");
}

/// Bad input is an error (exit 2) that says what was expected.
#[track_caller]
fn check_error(args: &[&str], expected: &str) {
    let (code, _, err) = zcheck(args);
    assert_eq!(code, 2, "{args:?}");
    assert!(err.contains(expected), "{args:?}: {err}");
}

#[test]
fn bad_input_is_reported() {
    check_error(&["verify", "damped_euler_d", "--steps", "10"], "needs a value for parameter `D`");
    check_error(&["verify", "false_euler", "--param", "D"], "expected NAME=VALUE");
    check_error(&["verify", "false_euler", "--param", "D=x"], "expected a number");
    check_error(&["verify", "no_such_method"], "no_such_method");
}
