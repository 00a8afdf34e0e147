//! `zcheck advise --scene` and `zcheck map` end to end: the acceptance
//! facts of the scene advisor against oracles computed here (ω_max of a
//! chain by nalgebra's dense symmetric eigensolver, the bound
//! 2(√(1 + ζ²) − ζ) in closed form), prediction against simulation on every
//! example scene, located errors for bad scene files, and the (Φ, D) map.

use crate::run::zcheck;
use nalgebra::DMatrix;
use serde_json::Value;
use testkit::scratch::{Scratch, ScratchFile};

#[track_caller]
fn json(args: &[&str]) -> Value {
    let (code, out, err) = zcheck(args);
    assert_eq!(code, 0, "zcheck {args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("zcheck {args:?}: {e}: {out}"))
}

fn write(name: &str, text: &str) -> ScratchFile {
    ScratchFile::new(&format!("{name}.toml"), text)
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
        let v = json(&["advise", "--scene", &example(name), "--format", "json", "--simulate-all"]);
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
        (
            "pos-mixed",
            format!("{head}pos = [0, 0]\n[[mass]]\nname = \"b\"\nkg = 1.0\npos = [1, 0, 0]\n"),
            ":9:7:",
            "pos has 3 coordinates",
        ),
        (
            "pos-some",
            format!("{head}pos = [0, 0]\n[[mass]]\nname = \"b\"\nkg = 1.0\n"),
            ":7:8:",
            "mass \"b\" has no pos",
        ),
        (
            "fixed-not-bool",
            format!("{head}fixed = \"yes\"\n"),
            ":5:9:",
            "boolean",
        ),
        (
            "same-position",
            format!("{head}pos = [2, 1]\n[[mass]]\nname = \"b\"\nkg = 1.0\npos = [2, 1]\n[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 1.0\n"),
            ":11:11:",
            "same position",
        ),
        (
            "max-hz",
            "tick_hz = 60\n[accuracy]\nmax_hz = 0\n[[mode]]\nhz = 3\n".to_owned(),
            ":3:10:",
            "max_hz = 0",
        ),
        (
            "max-hz-inf",
            "tick_hz = 60\n[accuracy]\nmax_hz = inf\n[[mode]]\nhz = 3\n".to_owned(),
            ":3:10:",
            "max_hz = inf",
        ),
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
    let scratch = Scratch::new("map");
    let svg = scratch.join("map.svg");
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

/// The particle examples (a 3D cloth, a 2D rope): the degrees of freedom
/// and zero modes counted from the geometry, and every candidate's
/// simulation agreeing with its prediction.
#[test]
fn particle_examples_agree_with_simulation() {
    // cloth8: 56 free particles × 3; nothing holds them out of the plane.
    // rope2d: 10 free particles × 2; every triple is a triangle.
    for (name, dof, rigid) in [("cloth8", 168u64, 56u64), ("rope2d", 20, 0)] {
        let start = std::time::Instant::now();
        let v = json(&["advise", "--scene", &example(name), "--format", "json", "--simulate-all"]);
        eprintln!("{name}: {:?}", start.elapsed());
        assert_eq!(v["dof"], dof, "{name}");
        assert_eq!(v["rigid_modes"], rigid, "{name}");
        assert_eq!(v["modes"].as_array().unwrap().len() as u64, dof - rigid, "{name}");
        assert!(v["recommended"]["substeps"].is_u64(), "{name}: {}", v["recommended"]);
        let mut checked = 0;
        for c in v["candidates"].as_array().unwrap() {
            if c["substeps_accurate"].is_u64() {
                let s = &c["simulated"];
                assert_eq!(s["agree"], true, "{name} {}: {c}", c["method"]);
                assert!(s["modes_checked"].as_u64().unwrap() > 0, "{name}: {c}");
                checked += 1;
            }
        }
        assert!(checked >= 3, "{name}: {checked} candidates checked");
        let (code, out, err) = zcheck(&["advise", "--scene", &example(name), "--no-simulate"]);
        assert_eq!(code, 0, "{err}");
        assert!(out.contains(&format!("{rigid} zero-frequency (rigid) left out")), "{out}");
    }
}

/// False Euler on an undamped mode: the principal root has |z| = 1 and
/// angle ψ with cos ψ = 1 − Φ²/2 (χ = z² − (2 − Φ²)z + 1), i.e.
/// ψ = 2·asin(Φ/2) (the acos form loses half the digits at small Φ), so
/// the phase drift over the duration is steps·(ψ − Φ), and it is stable
/// for Φ < 2.
fn false_euler_accurate(hz: f64, tick: f64, duration: f64, phase: f64) -> u64 {
    (1u64..)
        .find(|&n| {
            let phi = 2.0 * std::f64::consts::PI * hz / (tick * n as f64);
            phi < 2.0 && duration * tick * n as f64 * (2.0 * (phi / 2.0).asin() - phi) <= phase
        })
        .unwrap()
}

/// `max_hz` on two independent springs at 1 Hz and 200 Hz: with
/// `max_hz = 10` the substeps are the stability of the 200 Hz mode and
/// the accuracy of the 1 Hz one (closed forms for False Euler; for every
/// method, the advisor on each spring alone); without it, the 200 Hz
/// mode's accuracy sets them.
#[test]
fn max_hz_holds_only_the_band_to_the_target() {
    let (tick, duration, phase) = (60.0, 100.0, 1e-3);
    let k = |hz: f64| (2.0 * std::f64::consts::PI * hz).powi(2);
    let spring = |name: &str, hz: f64| {
        format!(
            "[[mass]]\nname = \"{name}\"\nkg = 1.0\n[[spring]]\nbetween = [\"{name}\", \"ground\"]\nstiffness = {}\n",
            k(hz)
        )
    };
    let head = |max_hz: &str| {
        format!(
            "tick_hz = {tick}\nduration_s = {duration}\n[accuracy]\nphase_rad = {phase}\n{max_hz}"
        )
    };
    let run = |name: &str, text: String| {
        let path = write(name, &text);
        json(&["advise", "--scene", path.to_str().unwrap(), "--format", "json", "--no-simulate"])
    };
    let both = format!("{}{}", spring("slow", 1.0), spring("fast", 200.0));
    let banded = run("two-scale-band", format!("{}{both}", head("max_hz = 10\n")));
    let all = run("two-scale-all", format!("{}{both}", head("")));
    let slow = run("two-scale-slow", format!("{}{}", head(""), spring("slow", 1.0)));
    let fast = run("two-scale-fast", format!("{}{}", head(""), spring("fast", 200.0)));
    // Closed forms, False Euler.
    let phi_fast = 2.0 * std::f64::consts::PI * 200.0 / tick;
    let stable_fast = (phi_fast / 2.0).floor() as u64 + 1;
    let accurate_slow = false_euler_accurate(1.0, tick, duration, phase);
    assert!(accurate_slow > stable_fast, "choose numbers where accuracy sets it");
    let fe = candidate(&banded, "false_euler");
    assert_eq!(fe["substeps_stable"], stable_fast);
    assert_eq!(fe["substeps_accurate"], accurate_slow);
    assert_eq!(
        candidate(&all, "false_euler")["substeps_accurate"],
        false_euler_accurate(200.0, tick, duration, phase)
    );
    assert_eq!(banded["max_hz"], 10.0);
    assert!(all["max_hz"].is_null());
    // Every method: the band's answer from each spring alone.
    for c in banded["candidates"].as_array().unwrap() {
        let m = c["method"].as_str().unwrap();
        let (s, f, a) = (candidate(&slow, m), candidate(&fast, m), candidate(&all, m));
        assert_eq!(c["substeps_stable"], f["substeps_stable"], "{m}");
        assert_eq!(a["substeps_stable"], f["substeps_stable"], "{m}");
        let expected = match (f["substeps_stable"].as_u64(), s["substeps_accurate"].as_u64()) {
            (Some(ns), Some(na)) => serde_json::json!(ns.max(na)),
            _ => Value::Null,
        };
        assert_eq!(c["substeps_accurate"], expected, "{m}");
        // Without the band the fast spring must be accurate too.
        if let (Some(x), Some(y)) =
            (a["substeps_accurate"].as_u64(), f["substeps_accurate"].as_u64())
        {
            assert_eq!(x, y.max(s["substeps_accurate"].as_u64().unwrap()), "{m}");
        }
    }
    // The text says where the targets apply.
    let path = write("two-scale-text", format!("{}{both}", head("max_hz = 10\n")).as_str());
    let (code, out, err) = zcheck(&["advise", "--scene", path.to_str().unwrap(), "--no-simulate"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("the modes at or below 10 Hz (every mode stable)"), "{out}");
}

/// A scene whose every mode has zero frequency (a free particle, springs
/// only between fixed ones): no crash, no division by zero; one substep is
/// stable, and the zero modes are counted.
#[test]
fn zero_frequency_modes_need_no_substeps() {
    let text = "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 1.0\npos = [0, 0, 0]\nfixed = true\n[[mass]]\nname = \"b\"\nkg = 1.0\npos = [1, 0, 0]\nfixed = true\n[[mass]]\nname = \"c\"\nkg = 2.0\npos = [0, 1, 0]\n[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 10.0\nratio = 0.1\n";
    let path = write("all-rigid", text);
    let v = json(&["advise", "--scene", path.to_str().unwrap(), "--format", "json"]);
    assert_eq!(v["dof"], 3);
    assert_eq!(v["rigid_modes"], 3);
    assert!(v["modes"].as_array().unwrap().is_empty());
    for c in v["candidates"].as_array().unwrap() {
        assert_eq!(c["substeps_stable"], 1, "{c}");
    }
    // Two particles joined by one spring, free in 2D: one mode at
    // ω² = k(1/m_a + 1/m_b) along the spring, three rigid.
    let text = "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 1.0\npos = [0, 0]\n[[mass]]\nname = \"b\"\nkg = 3.0\npos = [3, 4]\n[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 300.0\n";
    let path = write("free-pair", text);
    let v =
        json(&["advise", "--scene", path.to_str().unwrap(), "--format", "json", "--no-simulate"]);
    assert_eq!(v["rigid_modes"], 3);
    let modes = v["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 1);
    let hz = (300.0f64 * (1.0 + 1.0 / 3.0)).sqrt() / (2.0 * std::f64::consts::PI);
    assert!((modes[0]["hz"].as_f64().unwrap() - hz).abs() < 1e-9 * hz, "{}", modes[0]);
}

/// Non-proportional damping with rigid modes: a chain laid along x in 2D
/// (pinned mass, two springs, a damper on the second) moves along x as the
/// scalar chain does, and nothing holds it sideways (two zero modes). The
/// full-step analysis runs without the zero modes (a Jordan block at 1
/// otherwise), so every candidate's substeps equal the scalar chain's, and
/// its simulation agrees with its prediction.
#[test]
fn rigid_modes_with_non_proportional_damping_match_the_scalar_chain() {
    let springs = "[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 400.0\n[[spring]]\nbetween = [\"b\", \"c\"]\nstiffness = 900.0\ndamping = 4.0\n";
    let mass =
        |name: &str, kg: f64, pos: &str| format!("[[mass]]\nname = \"{name}\"\nkg = {kg}\n{pos}");
    let planar = format!(
        "tick_hz = 60\n{}{}{}{springs}",
        mass("a", 1.0, "pos = [0, 0]\nfixed = true\n"),
        mass("b", 1.0, "pos = [1, 0]\n"),
        mass("c", 2.0, "pos = [2, 0]\n")
    );
    let scalar = format!(
        "tick_hz = 60\n{}{}{}{springs}",
        mass("a", 1.0, "fixed = true\n"),
        mass("b", 1.0, ""),
        mass("c", 2.0, "")
    );
    let p = json(&[
        "advise",
        "--scene",
        write("np-planar", &planar).to_str().unwrap(),
        "--format",
        "json",
        "--simulate-all",
    ]);
    let s = json(&[
        "advise",
        "--scene",
        write("np-scalar", &scalar).to_str().unwrap(),
        "--format",
        "json",
        "--simulate-all",
    ]);
    assert_eq!(p["damping"]["kind"], "non_proportional");
    assert_eq!(s["damping"]["kind"], "non_proportional");
    assert_eq!((p["dof"].as_u64(), p["rigid_modes"].as_u64()), (Some(4), Some(2)));
    assert_eq!((s["dof"].as_u64(), s["rigid_modes"].as_u64()), (Some(2), Some(0)));
    let hz = |v: &Value| -> Vec<f64> {
        v["modes"].as_array().unwrap().iter().map(|m| m["hz"].as_f64().unwrap()).collect()
    };
    let (hp, hs) = (hz(&p), hz(&s));
    assert_eq!(hp.len(), hs.len());
    for (x, y) in hp.iter().zip(&hs) {
        assert!((x - y).abs() <= 1e-9 * y, "{hp:?} vs {hs:?}");
    }
    for c in p["candidates"].as_array().unwrap() {
        let m = c["method"].as_str().unwrap();
        let o = candidate(&s, m);
        assert_eq!(c["stability_from"], "full-step matrix (non-proportional damping)", "{m}");
        assert_eq!(c["substeps_stable"], o["substeps_stable"], "{m}");
        assert_eq!(c["substeps_accurate"], o["substeps_accurate"], "{m}");
        if c["substeps_accurate"].is_u64() {
            assert_eq!(c["simulated"]["agree"], true, "{m}: {c}");
        }
    }
}

/// By default the checking simulation is bounded: the recommended method
/// and every candidate within SIM_COST_FACTOR (4x) of its cost per tick
/// are simulated (and agree); every other candidate that meets the target
/// is named with its cost ratio, above 4, and not simulated. Together they
/// are every candidate that meets the target.
#[test]
fn the_default_simulation_checks_the_close_candidates_and_names_the_rest() {
    for name in [
        "chain10",
        "quarter_car",
        "cloth_strip",
        "building3",
        "spring_120hz",
        "cloth8",
        "rope2d",
        "cloth64",
    ] {
        let v = json(&["advise", "--scene", &example(name), "--format", "json"]);
        let rec = v["recommended"]["method"].as_str().unwrap();
        let left: Vec<&str> = v["simulation_left_out"]
            .as_array()
            .unwrap()
            .iter()
            .map(|l| {
                assert!(l["cost_ratio"].as_f64().unwrap() > 4.0, "{name}: {l}");
                l["method"].as_str().unwrap()
            })
            .collect();
        assert!(!left.contains(&rec), "{name}: the recommended {rec} left out");
        for c in v["candidates"].as_array().unwrap() {
            let m = c["method"].as_str().unwrap();
            if !c["substeps_accurate"].is_u64() {
                assert!(c["simulated"].is_null() && !left.contains(&m), "{name} {m}");
            } else if left.contains(&m) {
                assert!(c["simulated"].is_null(), "{name} {m}: simulated though left out");
            } else {
                assert_eq!(c["simulated"]["agree"], true, "{name} {m}: {c}");
            }
        }
        let (code, out, _) = zcheck(&["advise", "--scene", &example(name)]);
        assert_eq!(code, 0);
        for m in &left {
            assert!(out.contains("not simulated") && out.contains(m), "{name}: {out}");
        }
    }
}

/// Every example reports its highest mode below its certified bound, and on
/// an undamped scene every candidate's substeps at the bound are at least
/// the substeps the eigensolver's frequencies give (never fewer).
#[test]
fn the_certified_bound_covers_the_highest_mode_and_its_substeps() {
    let mut certified = 0;
    for name in
        ["chain10", "quarter_car", "cloth_strip", "building3", "cloth8", "rope2d", "cloth64"]
    {
        let v = json(&["advise", "--scene", &example(name), "--format", "json", "--no-simulate"]);
        let (h, b) = (v["highest_hz"].as_f64().unwrap(), v["highest_hz_bound"].as_f64().unwrap());
        assert!(h <= b * (1.0 + 1e-12), "{name}: {h} > {b}");
        for c in v["candidates"].as_array().unwrap() {
            if let Some(at_bound) = c["substeps_stable_certified"].as_u64() {
                assert!(at_bound >= c["substeps_stable"].as_u64().unwrap(), "{name}: {c}");
                certified += 1;
            }
        }
    }
    // rope2d is undamped: its five stable candidates.
    assert!(certified >= 5, "{certified}");
}

/// The recommendation is the cheapest candidate meeting the target by an
/// exact cost, operations per step × substeps × degrees of freedom, ties
/// broken by name: recomputed here from the candidates' own exact fields,
/// on every example scene, and the same on a second run. `--rank measured`
/// picks the least measured ns per tick instead, whatever it is.
#[test]
fn the_recommendation_is_the_least_exact_cost_ties_by_name() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes");
    for name in ["chain10", "cloth_strip", "building3", "quarter_car", "rope2d", "spring_120hz"] {
        let path = format!("{dir}/{name}.toml");
        let v = json(&["advise", "--scene", &path, "--no-simulate", "--format", "json"]);
        assert_eq!(v["rank"], "exact", "{name}");
        let dof = v["dof"].as_u64().unwrap();
        let mut best: Option<(u64, String, u64)> = None;
        for c in v["candidates"].as_array().unwrap() {
            let (Some(n), Some(per_step)) =
                (c["substeps_accurate"].as_u64(), c["ops_per_step"].as_u64())
            else {
                assert!(c["ops_per_tick"].is_null(), "{name}: {c}");
                continue;
            };
            let cost = per_step * n * dof;
            assert_eq!(c["ops_per_tick"].as_u64(), Some(cost), "{name}: {c}");
            let m = c["method"].as_str().unwrap().to_owned();
            if best.as_ref().is_none_or(|(b, bm, _)| (cost, &m) < (*b, bm)) {
                best = Some((cost, m, n));
            }
        }
        let rec = &v["recommended"];
        match best {
            Some((_, m, n)) => {
                assert_eq!(rec["method"], m.as_str(), "{name}");
                assert_eq!(rec["substeps"].as_u64(), Some(n), "{name}");
            }
            None => assert!(rec.is_null(), "{name}: {rec}"),
        }
        let again = json(&["advise", "--scene", &path, "--no-simulate", "--format", "json"]);
        assert_eq!(again["recommended"], v["recommended"], "{name}");
        let measured = json(&[
            "advise",
            "--scene",
            &path,
            "--no-simulate",
            "--rank",
            "measured",
            "--format",
            "json",
        ]);
        assert_eq!(measured["rank"], "measured", "{name}");
        let fastest = measured["candidates"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|c| c["ns_per_tick"].is_f64())
            .map(|c| c["ns_per_tick"].as_f64().unwrap())
            .fold(f64::INFINITY, f64::min);
        let chosen = measured["recommended"]["method"].as_str().map(|m| candidate(&measured, m));
        if let Some(c) = chosen {
            assert_eq!(c["ns_per_tick"].as_f64(), Some(fastest), "{name}");
        }
    }
}
