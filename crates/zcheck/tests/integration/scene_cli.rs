//! `zcheck scene` from the outside: bad names fail with the list of scenes,
//! every scene prints JSON with its invariant summaries, `--plot` writes SVG,
//! and a rounded summary of each scene is snapshotted.

use std::path::PathBuf;
use std::process::{Command, Output};

fn zcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("run zcheck")
}

fn json(args: &[&str]) -> serde_json::Value {
    let out = zcheck(args);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("json")
}

#[track_caller]
fn check_rejected(args: &[&str], expected: &[&str]) {
    let out = zcheck(args);
    assert!(!out.status.success(), "{args:?} succeeded");
    let stderr = String::from_utf8_lossy(&out.stderr);
    for e in expected {
        assert!(stderr.contains(e), "{args:?}: {stderr:?} lacks {e:?}");
    }
}

#[test]
fn bad_input_is_an_error_listing_the_scenes() {
    check_rejected(
        &["scene", "four_body"],
        &["unknown scene `four_body`", "three_body_false_euler", "aircraft"],
    );
    check_rejected(&["scene", "aircraft", "--steps", "0"], &["--steps"]);
    check_rejected(&["scene", "aircraft", "--format", "xml"], &["xml"]);
}

/// Each invariant summary carries initial, final and max_rel_drift.
#[test]
fn json_holds_the_invariant_summaries() {
    for (name, steps) in [
        ("three_body_false_euler", "1000"),
        ("three_body_euler", "500"),
        ("three_body_euler_energy", "500"),
        ("aircraft", "50"),
    ] {
        let v = json(&["scene", name, "--steps", steps, "--format", "json"]);
        let invariants = v["invariants"].as_object().expect("invariants");
        assert!(!invariants.is_empty(), "{name}");
        for (key, s) in invariants {
            for field in ["initial", "final", "max_rel_drift"] {
                assert!(s.get(field).is_some(), "{name}.{key} lacks {field}");
            }
        }
    }
}

/// `--plot` writes the trajectory and energy figures (three bodies) or the
/// angles (aircraft) as SVG.
#[test]
fn plot_writes_svg() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("scene_cli_plot");
    let _ = std::fs::remove_dir_all(&dir);
    let d = dir.to_str().expect("utf-8 path");
    assert!(zcheck(&["scene", "three_body_false_euler", "--steps", "200", "--plot", d])
        .status
        .success());
    assert!(zcheck(&["scene", "aircraft", "--steps", "100", "--plot", d]).status.success());
    for file in [
        "three_body_false_euler_trajectory.svg",
        "three_body_false_euler_energy.svg",
        "aircraft_angles.svg",
    ] {
        let text =
            std::fs::read_to_string(dir.join(file)).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert!(text.starts_with("<svg") && text.contains("<polyline"), "{file}");
    }
}

/// Three significant digits; tiny values (rounding noise) collapse to 0.
fn round(v: &serde_json::Value) -> serde_json::Value {
    match v {
        serde_json::Value::Number(n) => {
            let x = n.as_f64().unwrap_or(f64::NAN);
            if x.abs() < 1e-6 {
                serde_json::json!(0.0)
            } else {
                let scale = 10f64.powi(2 - x.abs().log10().floor() as i32);
                serde_json::json!((x * scale).round() / scale)
            }
        }
        serde_json::Value::Array(a) => a.iter().map(round).collect(),
        serde_json::Value::Object(m) => m.iter().map(|(k, v)| (k.clone(), round(v))).collect(),
        other => other.clone(),
    }
}

/// Rounded summaries of short runs of every scene.
#[test]
fn rounded_summaries() {
    let mut all = serde_json::Map::new();
    for (name, steps) in [
        ("three_body_false_euler", "1000"),
        ("three_body_euler", "300"),
        ("three_body_euler_energy", "300"),
        ("aircraft", "300"),
    ] {
        let v = json(&["scene", name, "--steps", steps, "--format", "json"]);
        let keep: serde_json::Map<_, _> = [
            "bounded",
            "radius",
            "invariants",
            "steady_turn",
            "settling_time",
            "max_angle_error",
            "first_nonfinite_step",
        ]
        .iter()
        .filter_map(|k| v.get(*k).map(|x| (k.to_string(), round(x))))
        .collect();
        all.insert(name.to_string(), serde_json::Value::Object(keep));
    }
    let json = serde_json::to_string_pretty(&all).expect("json");
    crate::snapshot::in_dir("zcheck")
        .bind(|| insta::assert_snapshot!("scene_rounded_summaries", json));
}
