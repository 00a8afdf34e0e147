//! Commands over any parameters. `zcheck map`: a (Phi, NAME) map for a
//! parameter not named D, and the map over Newmark's (beta, gamma), held to
//! Hughes' closed forms: unconditionally stable exactly when
//! 2 beta >= gamma >= 1/2, and otherwise (gamma >= 1/2)
//! Phi_max = (gamma/2 - beta)^(-1/2); Newmark's (Phi, beta) map with gamma
//! bound. `zcheck overview --param`.

use crate::run::zcheck;
use serde_json::Value;
use testkit::scratch::Scratch;

const NEWMARK: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/methods/newmark.zm");

#[track_caller]
fn json(args: &[&str]) -> Value {
    let (code, out, err) = zcheck(args);
    assert_eq!(code, 0, "zcheck {args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("zcheck {args:?}: {e}: {out}"))
}

/// Newmark over (beta, gamma): every grid point's exact verdict is Hughes'
/// closed form, the witnesses agree everywhere, and the exact curves that
/// bound the unconditional region are 2 beta = gamma and gamma = 1/2.
#[test]
fn newmark_over_beta_and_gamma() {
    let scratch_svg = Scratch::new("map2");
    let svg = scratch_svg.join("map2.svg");
    let v = json(&[
        "map",
        NEWMARK,
        "--param",
        "beta=-1/8..1/2",
        "--param",
        "gamma=0..1",
        "--grid",
        "16",
        "--samples",
        "40",
        "--svg",
        svg.to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert_eq!(v["axes"], serde_json::json!(["beta", "gamma"]));
    assert_eq!(v["disagreements"], 0);
    let grid = v["grid"].as_array().unwrap();
    assert_eq!(grid.len(), 256);
    let (mut unconditional, mut finite) = (0, 0);
    for g in grid {
        let (b, c) = (g["values"][0].as_f64().unwrap(), g["values"][1].as_f64().unwrap());
        let inside = 2.0 * b >= c && c >= 0.5;
        assert_eq!(g["unconditional"], inside, "({b}, {c}): {g}");
        assert_eq!(g["stability"] == "bounded_for_all_phi", inside, "({b}, {c}): {g}");
        if c > 0.5 && 2.0 * b < c {
            let want = 1.0 / (c / 2.0 - b).sqrt();
            let got = g["phi_max"].as_f64().unwrap();
            assert!((got - want).abs() < 1e-9 * want, "({b}, {c}): {got} vs {want}");
            finite += 1;
        }
        if c < 0.5 {
            assert!(g["phi_max"].is_null(), "({b}, {c}): {g}");
        }
        unconditional += usize::from(inside);
        assert_eq!(g["witness_phis"].as_array().unwrap().len(), 2);
    }
    assert!(unconditional > 10 && finite > 10, "{unconditional} {finite}");
    // The bounding curves, checked through their traced points.
    let curves = v["curves"].as_array().unwrap();
    let bounding: Vec<&Value> = curves.iter().filter(|c| c["bounds_region"] == true).collect();
    assert_eq!(bounding.len(), 2, "{curves:?}");
    for c in &bounding {
        let points = c["points"].as_array().unwrap();
        assert!(points.len() > 10, "{c}");
        let on = |f: &dyn Fn(f64, f64) -> f64| {
            points.iter().all(|p| f(p[0].as_f64().unwrap(), p[1].as_f64().unwrap()).abs() < 1e-9)
        };
        match c["kind"].as_str().unwrap() {
            "chi(-1)" => assert!(on(&|b, g| 2.0 * b - g), "{c}"),
            "unit_circle" => assert!(on(&|_, g| g - 0.5), "{c}"),
            k => panic!("unexpected bounding curve {k}: {c}"),
        }
        assert!(c["inequality"].is_string(), "{c}");
    }
    assert_eq!(v["region_matches_grid"], true);
    assert!(v["class_edges"].as_u64().unwrap() > 0);
    assert_eq!(v["class_edges"], v["edges_on_curves"]);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg"));
    for label in ["Phi_max = infinity", "bounds the region", "no Phi_max"] {
        assert!(text.contains(label), "{label} missing from the SVG");
    }
}

/// The text output states the region as the two inequalities.
#[test]
fn newmark_text_states_the_region() {
    let (code, out, err) =
        zcheck(&["map", NEWMARK, "--param", "beta=0..1/2", "--param", "gamma=0..1", "--grid", "8"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Phi_max = infinity exactly where"), "{out}");
    assert!(out.contains("-gamma + 2*beta >= 0") && out.contains("-1 + 2*gamma >= 0"), "{out}");
    assert!(out.contains("agree with the exact roots and verdict at 64 of 64"), "{out}");
}

/// One range over a parameter not named D: the (Phi, beta) map of Newmark
/// with gamma = 1/2, whose limit is Phi_max = (1/4 - beta)^(-1/2) and none
/// from beta = 1/4 on.
#[test]
fn phi_beta_map() {
    let src = std::fs::read_to_string(NEWMARK)
        .unwrap()
        .replace("param gamma\n", "")
        .replace("gamma", "(1/2)")
        .replace("method newmark", "method newmark_half");
    let scratch_path = Scratch::new("newmark-half");
    let path = scratch_path.join("newmark-half.zm");
    std::fs::write(&path, src).unwrap();
    let v = json(&[
        "map",
        path.to_str().unwrap(),
        "--phi",
        "0..6",
        "--param",
        "beta=0..1/2",
        "--grid",
        "12",
        "--samples",
        "20",
        "--format",
        "json",
    ]);
    assert_eq!(v["axes"], serde_json::json!(["Phi", "beta"]));
    assert_eq!(v["disagreements"], 0);
    for g in v["grid"].as_array().unwrap() {
        let (phi, b) = (g["phi"].as_f64().unwrap(), g["value"].as_f64().unwrap());
        let bounded = !g["class"].as_str().unwrap().contains("unstable");
        let want = b >= 0.25 || phi < 1.0 / (0.25 - b).sqrt();
        assert_eq!(bounded, want, "({phi}, {b}): {}", g["class"]);
    }
    let limits = v["limits"].as_array().unwrap();
    assert_eq!(limits.last().unwrap()["phi_max"], "every", "{limits:?}");
    assert_eq!(limits[0]["phi_max"], "2.000000000000", "{limits:?}");
}

/// Bad input: located (the flag and the text typed), exit 2, no panic.
#[test]
fn bad_ranges_are_refused() {
    for (args, wanted) in [
        (
            &["map", NEWMARK, "--param", "beta=1..0", "--param", "gamma=0..1"][..],
            "--param beta 1..0: expected LO < HI",
        ),
        (
            &["map", "false_euler_damped", "--param", "D=0..1", "--param", "E=0..1"][..],
            "--param E=0..1: two ranges given, but method false_euler_damped has 1 parameter (D)",
        ),
        (
            &["map", NEWMARK, "--param", "beta=0..1", "--param", "delta=0..1"][..],
            "--param delta: method newmark has no parameter delta (declared: beta, gamma)",
        ),
        (
            &["map", NEWMARK, "--param", "beta=0..1"][..],
            "--param beta=0..1: a map over (Phi, beta) needs --phi",
        ),
        (
            &["map", NEWMARK, "--phi", "0..1", "--param", "beta=0..1", "--param", "gamma=0..1"][..],
            "--phi 0..1: a map over two parameters covers every Phi > 0",
        ),
        (
            &["map", NEWMARK, "--phi", "0..1", "--param", "beta=0..1"][..],
            "further parameters (gamma)",
        ),
        (&["map", NEWMARK][..], "expected one or two ranges"),
        (
            &[
                "map",
                NEWMARK,
                "--param",
                "beta=0..1",
                "--param",
                "gamma=0..1",
                "--param",
                "gamma=1",
            ][..],
            "--param gamma: given twice",
        ),
    ] {
        let (code, _, err) = zcheck(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(wanted), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

/// `overview --param` binds each method's own parameters: Newmark at
/// (1/4, 1/2) is the built-in newmark_average, row for row, and at
/// (1/4, 3/5) its limit is Hughes' (gamma/2 - beta)^(-1/2) = 2 sqrt(5).
#[test]
fn overview_binds_params() {
    let v = json(&[
        "overview",
        NEWMARK,
        "newmark_average",
        "--param",
        "beta=1/4",
        "--param",
        "gamma=0.5",
        "--format",
        "json",
    ]);
    let rows = v.as_array().unwrap();
    assert_eq!(rows[0]["method"], "newmark (beta = 1/4, gamma = 1/2)");
    assert_eq!(rows[1]["method"], "newmark_average");
    for key in ["charpoly", "phi_max_exact", "psi_series", "modulus_sq_series", "phase_error"] {
        assert_eq!(rows[0][key], rows[1][key], "{key}");
    }
    let v = json(&[
        "overview",
        NEWMARK,
        "--param",
        "beta=1/4",
        "--param",
        "gamma=3/5",
        "--format",
        "json",
    ]);
    assert_eq!(v[0]["phi_max_exact"], "2*sqrt(5)");
    let want = 1.0 / (0.3f64 - 0.25).sqrt();
    assert!((v[0]["phi_max"].as_f64().unwrap() - want).abs() < 1e-12, "{}", v[0]);
    // A parameter left without a value, or one no method declares.
    for (args, wanted) in [
        (&["overview", NEWMARK, "--param", "beta=1/4"][..], "give gamma a value"),
        (&["overview", NEWMARK, "--param", "delta=1"][..], "method newmark has no parameter delta"),
        (&["overview", "--param", "D=1/2"][..], "none of the methods declares a parameter D"),
    ] {
        let (code, _, err) = zcheck(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(wanted) && !err.contains("panicked"), "{args:?}: {err}");
    }
}

/// `zcheck map` binds Newmark's gamma for the (Phi, beta) map Hughes draws:
/// Phi_max = 2/sqrt(1 - 4 beta) below beta = 1/4, every Phi from there.
#[test]
fn map_binds_other_parameters() {
    let d = json(&[
        "map",
        NEWMARK,
        "--phi",
        "0..5",
        "--param",
        "beta=0..1/2",
        "--param",
        "gamma=1/2",
        "--grid",
        "8",
        "--samples",
        "20",
        "--format",
        "json",
    ]);
    assert_eq!(d["axes"], serde_json::json!(["Phi", "beta"]));
    assert_eq!(d["bound"], serde_json::json!([["gamma", "1/2"]]));
    assert_eq!(d["disagreements"], 0);
    let limits = d["limits"].as_array().unwrap();
    assert_eq!(limits[0]["exact"], "2", "{limits:?}");
    assert_eq!(limits[1]["exact"], "2*sqrt(2)", "{limits:?}");
    assert!(limits[2..].iter().all(|l| l["phi_max"] == "every"), "{limits:?}");
    for g in d["grid"].as_array().unwrap() {
        let (phi, beta) = (g["phi"].as_f64().unwrap(), g["value"].as_f64().unwrap());
        let stable = beta >= 0.25 || phi * phi * (1.0 - 4.0 * beta) < 4.0;
        assert_eq!(g["class"] != "alternating_unstable", stable, "({phi}, {beta}): {g}");
    }
}
