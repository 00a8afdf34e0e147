//! Tableaux whose entries name parameters (issue 37): read by every
//! command with `--param c=1` exactly as the same tableau written with
//! numbers (the oracle), and the errors.

use std::path::PathBuf;
use std::process::Command;

use serde_json::Value;

fn design_file(name: &str) -> String {
    format!("{}/methods/design/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn zcheck(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("zcheck runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[track_caller]
fn json(args: &[&str]) -> Value {
    let mut all = args.to_vec();
    all.extend(["--format", "json"]);
    let (code, out, err) = zcheck(&all);
    assert_eq!(code, 0, "zcheck {all:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("zcheck {all:?}: {e}: {out}"))
}

fn temp_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("zcheck-design-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    path
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
