//! The extremes of the numbers, end to end: Φ from subnormal to 1e300 in
//! every subcommand that takes a Φ, and parameters from 1e-12 to 1e6. Each
//! gives the exact answer, checked against an independent oracle, or a
//! clean error (exit 2) saying that f64 cannot represent the question.

use std::process::Command;

use num_traits::Signed;
use poly::{RootClass, Q};
use serde_json::Value;

#[track_caller]
fn zcheck(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("runs");
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    (out.status.code().unwrap_or(-1), String::from_utf8_lossy(&out.stdout).into_owned(), err)
}

/// `verify` at tiny Φ (down to the smallest subnormal) reports, for every
/// point, the class the exact analysis in `poly` gives at the same Φ (the
/// f64's exact value), and the witnesses agree.
#[test]
fn verify_tiny_phi_gives_the_exact_class() {
    let phis = ["1e-300", "2.2250738585072014e-308", "5e-324", "1e-12"];
    for name in ["false_euler", "standard_euler", "standard_heun", "false_heun", "verlet"] {
        let (code, out, err) = zcheck(&[
            "verify",
            name,
            "--phi",
            &phis.join(","),
            "--steps",
            "100",
            "--format",
            "json",
        ]);
        assert_eq!(code, 0, "{name}: {err}");
        let v: Value = serde_json::from_str(&out).expect("json");
        let chi = poly::advanced::charpoly(&poly::builtin(name).unwrap()).unwrap();
        for p in v[0]["points"].as_array().unwrap() {
            let phi = p["phi"].as_f64().unwrap();
            let exact =
                poly::advanced::stability::class_at(&chi, &Q::from_float(phi).unwrap()).unwrap();
            let shown = RootClass::from_name(p["class"].as_str().unwrap()).unwrap();
            assert_eq!(shown, exact, "{name} at {phi:e}");
        }
    }
}

/// Where f64 cannot hold Φ, or the witnesses would overflow, the answer is
/// a clean error naming the problem.
#[test]
fn verify_beyond_f64_is_a_clean_error() {
    for (phi, says) in [
        ("1e-400", "below the smallest positive f64"),
        ("1e309", "beyond the range of f64"),
        ("-1e309", "beyond the range of f64"),
        ("1e300", "f64 cannot represent"),
        ("1e150", "f64 cannot represent"),
        ("1e60", "f64 cannot represent"),
    ] {
        let (code, _, err) = zcheck(&["verify", "false_euler", "--phi", phi, "--steps", "10"]);
        assert_eq!(code, 2, "{phi}: {err}");
        assert!(err.contains(says), "{phi}: {err}");
        assert!(err.len() < 400, "{phi}: {err}");
    }
}

/// `plot` and `advise` take Φ (or make one) at both ends without panicking.
#[test]
fn plot_and_advise_at_both_ends() {
    let out = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("extremes_plot");
    let out = out.to_str().unwrap();
    for (args, code) in [
        (vec!["plot", "yt", "--out", out, "--phi", "1e-300", "--methods", "false_euler"], 2),
        (vec!["plot", "yt", "--out", out, "--phi", "5e-324", "--methods", "false_euler"], 2),
        (vec!["plot", "yt", "--out", out, "--phi", "1e300", "--methods", "false_euler"], 0),
        (vec!["plot", "zplane", "--out", out, "--phi-max", "1e300", "--methods", "verlet"], 0),
        (vec!["advise", "--freq", "1e-300", "--tick", "60"], 0),
        (vec!["advise", "--freq", "5e-324", "--tick", "1"], 0),
        (vec!["advise", "--freq", "1e300", "--tick", "60"], 0),
        (vec!["advise", "--freq", "1", "--tick", "1e-300"], 0),
    ] {
        let (c, stdout, err) = zcheck(&args);
        assert_eq!(c, code, "{args:?}: {err}");
        assert!(!stdout.contains("000000000000000000000000"), "{args:?}: {stdout}");
    }
}

/// `stability` decides damped Euler exactly at D = 1e-12 and D = 1e6.
/// Oracles from the closed form of its roots, z = 1 − DΦ ± Φ·sqrt(D² − 1):
/// for D < 1 the roots are complex while stable and Φ_max = 2D exactly; for
/// D > 1 the smaller root reaches −1 at the smaller root of
/// x² − 4D·x + 4 = 0, which must lie in the reported isolating interval.
#[test]
fn stability_at_tiny_and_huge_damping() {
    let json = |d: &str| -> Value {
        let (code, out, err) = zcheck(&[
            "stability",
            "damped_euler_d",
            "--param",
            &format!("D={d}"),
            "--format",
            "json",
        ]);
        assert_eq!(code, 0, "{err}");
        serde_json::from_str(&out).expect("json")
    };
    let q = |s: &Value| -> Q { s.as_str().unwrap().parse().unwrap() };
    let v = json("1e-12");
    assert_eq!(v["params"]["D"], "1/1000000000000");
    assert_eq!(q(&v["phi_max_exact"]), poly::q(1, 500_000_000_000));

    let v = json("1e6");
    assert_eq!(v["params"]["D"], "1000000");
    let d = poly::q(1_000_000, 1);
    let g = |x: &Q| x * x - poly::q(4, 1) * &d * x + poly::q(4, 1);
    let interval = &v["phi_max_detail"]["interval"];
    let (lo, hi) = (q(&interval[0]), q(&interval[1]));
    assert!(g(&lo).is_positive() && g(&hi).is_negative(), "[{lo}, {hi}]");
    assert!(&hi - &lo <= poly::q(1, 1_000_000_000_000_000));
}
