//! `zcheck advise --scene` and `zcheck map` end to end: the acceptance
//! facts of the scene advisor against oracles computed here (ω_max of a
//! chain by nalgebra's dense symmetric eigensolver, the bound
//! 2(√(1 + ζ²) − ζ) in closed form), prediction against simulation on every
//! example scene, located errors for bad scene files, and the (Φ, D) map.

use std::path::PathBuf;
use std::process::Command;

use nalgebra::DMatrix;
use serde_json::Value;

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
    let (code, out, err) = zcheck(args);
    assert_eq!(code, 0, "zcheck {args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("zcheck {args:?}: {e}: {out}"))
}

fn write(name: &str, text: &str) -> PathBuf {
    let path =
        std::env::temp_dir().join(format!("zcheck-scene-{}-{name}.toml", std::process::id()));
    std::fs::write(&path, text).unwrap();
    path
}

fn candidate<'a>(v: &'a Value, method: &str) -> &'a Value {
    v["candidates"].as_array().unwrap().iter().find(|c| c["method"] == method).expect("candidate")
}

/// An undamped chain of unequal masses and springs: False Euler's
/// `substeps_stable` is the smallest n with ω_max·T/n < 2, ω_max from an
/// independent dense eigensolver.
#[test]
fn undamped_false_euler_substeps_are_omega_max_t_over_two() {
    for (n, tick) in [(3usize, 60.0), (7, 30.0), (12, 120.0)] {
        let masses: Vec<f64> = (0..n).map(|i| 0.2 + 0.13 * i as f64).collect();
        let stiff: Vec<f64> = (0..n).map(|i| 900.0 + 370.0 * ((i * 7) % 5) as f64).collect();
        let mut text = format!("tick_hz = {tick}\nduration_s = 0.5\n");
        for (i, m) in masses.iter().enumerate() {
            text += &format!("[[mass]]\nname = \"m{i}\"\nkg = {m}\n");
        }
        let mut k = DMatrix::<f64>::zeros(n, n);
        for i in 0..n {
            let prev = if i == 0 { "ground".to_owned() } else { format!("m{}", i - 1) };
            text += &format!(
                "[[spring]]\nbetween = [\"{prev}\", \"m{i}\"]\nstiffness = {}\n",
                stiff[i]
            );
            k[(i, i)] += stiff[i];
            if i > 0 {
                k[(i - 1, i - 1)] += stiff[i];
                k[(i - 1, i)] -= stiff[i];
                k[(i, i - 1)] -= stiff[i];
            }
        }
        let kt = DMatrix::from_fn(n, n, |i, j| k[(i, j)] / (masses[i] * masses[j]).sqrt());
        let omega_max = kt.symmetric_eigenvalues().max().sqrt();
        let phi = omega_max / tick;
        let expected = (phi / 2.0).floor() as u64 + 1;
        assert!((phi / 2.0 - (phi / 2.0).round()).abs() > 1e-6, "tie: choose other numbers");
        let path = write(&format!("chain{n}"), &text);
        let v = json(&[
            "advise",
            "--scene",
            path.to_str().unwrap(),
            "--methods",
            "false_euler",
            "--format",
            "json",
            "--no-simulate",
        ]);
        assert_eq!(
            candidate(&v, "false_euler")["substeps_stable"],
            expected,
            "n = {n}, Phi = {phi}"
        );
        // The mode that limits is the highest.
        let modes = v["modes"].as_array().unwrap();
        assert_eq!(modes.last().unwrap()["limits_stability"], true);
    }
}

/// With damping ratio ζ the bound 2 becomes 2(√(1 + ζ²) − ζ).
#[test]
fn damped_false_euler_substeps_follow_the_damped_bound() {
    for (hz, zeta) in [(120.0, 0.3f64), (47.0, 1.5), (200.0, 0.05), (95.0, 0.8)] {
        let tick = 60.0;
        let phi = 2.0 * std::f64::consts::PI * hz / tick;
        let bound = 2.0 * ((1.0 + zeta * zeta).sqrt() - zeta);
        let expected = (phi / bound).floor() as u64 + 1;
        let path = write(
            &format!("mode{hz}"),
            &format!("tick_hz = {tick}\n[[mode]]\nhz = {hz}\nratio = {zeta}\n"),
        );
        let v = json(&[
            "advise",
            "--scene",
            path.to_str().unwrap(),
            "--methods",
            "false_euler",
            "--format",
            "json",
            "--no-simulate",
        ]);
        assert_eq!(
            candidate(&v, "false_euler")["substeps_stable"],
            expected,
            "{hz} Hz, zeta {zeta}"
        );
    }
}

fn example(name: &str) -> String {
    format!("{}/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"))
}

/// On every example scene each candidate's simulated errors agree with the
/// predicted ones, and there is a recommendation with every JSON field.
#[test]
fn prediction_agrees_with_simulation_on_every_example() {
    for name in ["chain10", "quarter_car", "cloth_strip", "building3", "spring_120hz"] {
        let v = json(&["advise", "--scene", &example(name), "--format", "json"]);
        let rec = &v["recommended"];
        assert!(rec["method"].is_string() && rec["substeps"].is_u64(), "{name}: {rec}");
        for m in v["modes"].as_array().unwrap() {
            for f in ["hz", "ratio", "limits_stability", "limits_accuracy"] {
                assert!(!m[f].is_null(), "{name}: mode without {f}");
            }
        }
        for c in v["candidates"].as_array().unwrap() {
            for f in [
                "method",
                "substeps_stable",
                "substeps_accurate",
                "ns_per_tick",
                "predicted",
                "simulated",
            ] {
                assert!(c.get(f).is_some(), "{name}: candidate without {f}");
            }
            if c["substeps_accurate"].is_u64() {
                let s = &c["simulated"];
                assert_eq!(s["agree"], true, "{name} {}: {c}", c["method"]);
                let (p, q) = (&c["predicted"], s);
                assert!(p["phase_rad"].as_f64().unwrap() <= v["phase_rad"].as_f64().unwrap());
                assert!(q["modes_checked"].as_u64().unwrap() > 0);
            }
        }
    }
}

/// The 120 Hz spring on a 60 Hz tick: False Euler needs 7 substeps to be
/// stable (4π/n < 2), Standard Euler and Standard Heun never are.
#[test]
fn the_papers_stiff_spring() {
    let v =
        json(&["advise", "--scene", &example("spring_120hz"), "--format", "json", "--no-simulate"]);
    assert_eq!(candidate(&v, "false_euler")["substeps_stable"], 7);
    assert!(candidate(&v, "standard_euler")["substeps_stable"].is_null());
    assert!(candidate(&v, "standard_heun")["substeps_stable"].is_null());
}

/// Bad scene files: a located error, exit status 2.
#[test]
fn bad_scene_files_are_located_errors() {
    let head = "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 1.0\n";
    for (name, text, at, needle) in [
        (
            "unknown",
            format!("{head}[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 1.0\n"),
            ":6:17:",
            "unknown mass \"b\"",
        ),
        ("mass", "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 0\n".to_owned(), ":4:6:", "kg = 0"),
        (
            "stiffness",
            format!("{head}[[spring]]\nbetween = [\"a\", \"ground\"]\nstiffness = -3\n"),
            ":7:13:",
            "stiffness = -3",
        ),
        ("tick", "[[mode]]\nhz = 3\n".to_owned(), ":1:1:", "missing tick rate"),
        ("empty", "tick_hz = 60\nduration_s = 1\n".to_owned(), ":1:1:", "empty scene"),
        ("syntax", "tick_hz = 60\n[[mass]\n".to_owned(), ":2:", ""),
    ] {
        let path = write(&format!("bad-{name}"), &text);
        let (code, out, err) = zcheck(&["advise", "--scene", path.to_str().unwrap()]);
        assert_eq!(code, 2, "{name}: {out}{err}");
        assert!(err.contains(&format!("{}{at}", path.display())), "{name}: {err}");
        assert!(err.contains(needle), "{name}: {err}");
        assert!(!err.contains("panicked"), "{name}: {err}");
    }
}

/// Gauss–Seidel: the full-step spectral radius by nalgebra and faer agree,
/// and for one mass the sweep changes nothing; where the exact modal
/// answer exists the numeric full-step search finds it too.
#[test]
fn gauss_seidel_report() {
    let v = json(&[
        "advise",
        "--scene",
        &example("chain10"),
        "--sweep",
        "gauss-seidel",
        "--format",
        "json",
        "--no-simulate",
    ]);
    for s in v["sweep"].as_array().unwrap() {
        assert_eq!(s["witnesses_agree"], true, "{s}");
    }
    let one = write("one", "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 2.0\n[[spring]]\nbetween = [\"a\", \"ground\"]\nstiffness = 3000.0\n");
    let v = json(&[
        "advise",
        "--scene",
        one.to_str().unwrap(),
        "--sweep",
        "gauss-seidel",
        "--format",
        "json",
        "--no-simulate",
    ]);
    for s in v["sweep"].as_array().unwrap() {
        assert_eq!(s["substeps_vector"], s["substeps_gauss_seidel"], "{s}");
        if s["substeps_modal"].is_u64() {
            assert_eq!(s["substeps_modal"], s["substeps_vector"], "{s}");
        }
    }
}

/// `zcheck map`: exact curves, every grid point witnessed, an SVG.
#[test]
fn map_of_false_euler() {
    let svg = std::env::temp_dir().join(format!("zcheck-map-{}.svg", std::process::id()));
    let v = json(&[
        "map",
        "false_euler_damped",
        "--phi",
        "0..3",
        "--param",
        "D=0..2",
        "--grid",
        "12",
        "--samples",
        "40",
        "--svg",
        svg.to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert_eq!(v["disagreements"], 0);
    assert_eq!(v["grid"].as_array().unwrap().len(), 144);
    let curves = v["curves"].as_array().unwrap();
    assert!(curves.iter().any(|c| c["poly"] == "-4 + Phi^2 + 4*D*Phi"), "{curves:?}");
    // Every traced point of χ(−1) lies on Φ = 2(√(1 + D²) − D).
    for c in curves {
        for p in c["points"].as_array().unwrap() {
            let (phi, d) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
            assert!((phi - 2.0 * ((1.0 + d * d).sqrt() - d)).abs() < 1e-9, "({phi}, {d})");
        }
    }
    // Grid classes: bounded exactly below the closed-form limit.
    for g in v["grid"].as_array().unwrap() {
        let (phi, d) = (g["phi"].as_f64().unwrap(), g["value"].as_f64().unwrap());
        let bounded = !g["class"].as_str().unwrap().contains("unstable");
        assert_eq!(bounded, phi < 2.0 * ((1.0 + d * d).sqrt() - d), "({phi}, {d}): {}", g["class"]);
    }
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    // A method without D is refused with exit 2.
    let (code, _, err) = zcheck(&["map", "false_euler", "--phi", "0..3", "--param", "D=0..1"]);
    assert_eq!(code, 2, "{err}");
}

/// The damped built-ins are listed and analysed like the others.
#[test]
fn damped_builtins_are_listed_and_analysed() {
    let (code, out, _) = zcheck(&["methods"]);
    assert_eq!(code, 0);
    for name in poly::advanced::builtins::damped_builtin_names() {
        assert!(out.contains(name), "{name} not listed");
    }
    let (code, out, err) = zcheck(&["stability", "false_euler_damped", "--param", "D=1/2"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("sqrt(5) - 1"), "{out}");
}
