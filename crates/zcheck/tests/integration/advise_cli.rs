//! `zcheck advise` agrees with `zcheck stability` and `zcheck verify` at the
//! same Φ, binary against binary: the methods advise calls stable at Φ are
//! exactly those with Φ < phi_max from `stability`, and exactly those whose
//! `verify` class at Φ is bounded; the stabilising substeps k are the fewest
//! for which `verify` finds Φ/k bounded. Also: the text output of the README
//! example, and bad input as an error with exit status 2.

use crate::run::zcheck;
use poly::RootClass;
use serde_json::Value;

#[track_caller]
fn json(args: &[&str]) -> Value {
    let (code, out, err) = zcheck(args);
    assert_eq!(code, 0, "zcheck {args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("zcheck {args:?}: {e}: {out}"))
}

/// The method argument and `--param` flags that name the method advise
/// used: the built-in itself, or (damped scene) its damped built-in.
fn method_args(method: &str, damping: Option<&str>) -> Vec<String> {
    let Some(d) = damping else { return vec![method.to_owned()] };
    let name = if method == "standard_euler" {
        return vec!["damped_euler_d".into(), "--param".into(), format!("D={d}")];
    } else {
        format!("{method}_damped")
    };
    assert!(poly::advanced::builtins::builtin_source(&name).is_some(), "damped built-in {name}");
    vec![name, "--param".into(), format!("D={d}")]
}

fn verify_bounded(margs: &[String], phis: &[f64]) -> Vec<bool> {
    let list: Vec<String> = phis.iter().map(|p| p.to_string()).collect();
    let list = list.join(",");
    let mut args: Vec<&str> = vec!["verify"];
    args.push(&margs[0]);
    args.extend(margs[1..].iter().map(String::as_str));
    args.extend(["--phi", &list, "--steps", "0", "--format", "json"]);
    let v = json(&args);
    let points = v[0]["points"].as_array().or_else(|| v["methods"][0]["points"].as_array());
    let points = points.unwrap_or_else(|| panic!("verify JSON without points: {v}"));
    points
        .iter()
        .map(|p| {
            RootClass::from_name(p["class"].as_str().unwrap()).expect("known class").bounded()
                == Some(true)
        })
        .collect()
}

#[track_caller]
fn check_scene(freq: &str, tick: &str, damping: Option<&str>) {
    let mut args = vec!["advise", "--freq", freq, "--tick", tick, "--format", "json"];
    if let Some(d) = damping {
        args.extend(["--damping", d]);
    }
    let advice = json(&args);
    let phi = advice["phi"].as_f64().unwrap();
    for m in advice["methods"].as_array().unwrap() {
        let name = m["method"].as_str().unwrap();
        let margs = method_args(name, damping);
        let mut sargs: Vec<&str> = vec!["stability"];
        sargs.extend(margs.iter().map(String::as_str));
        sargs.extend(["--format", "json"]);
        let stab = json(&sargs);
        let stable = m["stable_at_phi"].as_bool().unwrap();
        let below_max = stab["phi_max"].as_f64().is_some_and(|max| phi < max);
        assert_eq!(stable, below_max, "{name} at {phi}: advise vs stability {}", stab["phi_max"]);
        let mut phis = vec![phi];
        if let Some(k) = m["substeps_stable"].as_u64() {
            phis.push(phi / k as f64);
            if k > 1 {
                phis.push(phi / (k - 1) as f64);
            }
        }
        let bounded = verify_bounded(&margs, &phis);
        assert_eq!(stable, bounded[0], "{name} at {phi}: advise vs verify");
        if let Some(k) = m["substeps_stable"].as_u64() {
            assert!(bounded[1], "{name}: verify says {k} substeps are not enough");
            if k > 1 {
                assert!(!bounded[2], "{name}: verify says {} substeps suffice", k - 1);
            }
        } else {
            assert!(stab["phi_max"].is_null(), "{name}: never stable but stability has a limit");
        }
    }
}

/// Undamped scenes around every limit (Φ = 4π, 0.52, 1.99, 2.09) and damped ones.
#[test]
fn advise_agrees_with_stability_and_verify() {
    check_scene("120", "60", None);
    check_scene("5", "60", None);
    check_scene("19", "60", None);
    check_scene("10", "30", None);
    check_scene("9", "60", Some("0.25"));
}

/// The README example prints the stable set and the cheapest method.
#[test]
fn readme_example_text() {
    let (code, out, err) = zcheck(&["advise", "--freq", "120", "--tick", "60"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Phi = 2*pi*120/60 = 12.5664 rad per tick"), "{out}");
    assert!(out.contains("stable at Phi = 12.5664 with one step per tick: none"), "{out}");
    assert!(out.contains("cheapest meeting the tolerance: "), "{out}");
}

/// Bad input is an error naming the flag, with exit status 2.
#[test]
fn bad_input_is_an_error() {
    #[track_caller]
    fn check(args: &[&str], expected: &str) {
        let (code, _, err) = zcheck(args);
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains(expected), "{args:?}: {err}");
    }
    check(&["advise", "--freq", "120", "--tick", "0"], "--tick 0: expected a finite number > 0");
    check(
        &["advise", "--freq", "1", "--tick", "60", "--damping", "2"],
        "--damping 2: expected a damping ratio",
    );
    check(&["tradeoff", "--periods=-1"], "--periods -1: expected a finite number > 0");
}

/// `--freq/--tick/--damping` is a one-mode scene: the JSON carries the
/// scene advisor's `modes`, `candidates` and `recommended` for the same
/// spring, and the two independent computations agree on every method's
/// stabilising substeps (exact limit in the one-spring path, the (Φ, D)
/// region in the scene path). The recommendation's simulation agrees.
#[test]
fn one_spring_is_a_one_mode_scene() {
    // 1 Hz on a 10 Hz tick over the default 1 s: a duration shorter than
    // the simulation's fit needs (it once left every mode unchecked); and a
    // damping ratio of 1e-20, exact, whose limits are 1e-7 wide.
    for (freq, tick, damping) in [
        ("120", "60", None),
        ("19", "60", None),
        ("9", "60", Some("0.25")),
        ("1", "10", None),
        ("1", "10", Some("1e-20")),
    ] {
        let mut args = vec!["advise", "--freq", freq, "--tick", tick, "--format", "json"];
        if let Some(d) = damping {
            args.extend(["--damping", d]);
        }
        let v = json(&args);
        let modes = v["modes"].as_array().expect("modes");
        assert_eq!(modes.len(), 1, "{v}");
        let hz: f64 = freq.parse().unwrap();
        assert!((modes[0]["hz"].as_f64().unwrap() - hz).abs() <= 1e-9 * hz, "{v}");
        let candidates = v["candidates"].as_array().expect("candidates");
        for m in v["methods"].as_array().expect("methods") {
            let name = m["method"].as_str().unwrap();
            let c = candidates
                .iter()
                .find(|c| c["method"] == name)
                .unwrap_or_else(|| panic!("{name} not among the scene candidates: {v}"));
            assert_eq!(m["substeps_stable"], c["substeps_stable"], "{freq} Hz, {name}");
            if let Some(sim) = c["simulated"].as_object() {
                assert_eq!(sim["agree"], true, "{freq} Hz, {name}: {v}");
                assert!(sim["modes_checked"].as_u64() >= Some(1), "{freq} Hz, {name}: {v}");
            }
        }
        assert!(v["recommended"].is_object(), "{v}");
    }
}

/// `--methods` with `--freq/--tick` was silently ignored (the table showed
/// the seven direct methods): now it is refused with what to use instead.
#[test]
fn methods_without_a_scene_are_refused_not_ignored() {
    let (code, out, err) = zcheck(&["advise", "--freq", "5", "--tick", "60", "--methods", "rk4"]);
    assert_eq!(code, 2, "{out}");
    assert!(out.is_empty(), "{out}");
    assert!(err.contains("--methods rk4") && err.contains("--scene FILE"), "{err}");
    assert!(err.contains("zcheck tradeoff --method rk4"), "{err}");
}
