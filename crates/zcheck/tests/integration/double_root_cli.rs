//! Three substeps of False Euler (Φ/3 each) at Φ = 3: χ = (z + 1)² and
//! P = −I, bounded. `zcheck stability` decides it from P, and `zcheck
//! verify` agrees numerically: the eigenvalues −1, −1 and no growth.

use std::process::Command;

use serde_json::Value;

use testkit::programs::FALSE_EULER_3;
use testkit::scratch::ScratchFile;

fn json(args: &[&str]) -> Value {
    let file = ScratchFile::new("false_euler_3.zm", FALSE_EULER_3);
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(args)
        .arg(&*file)
        .args(["--format", "json"])
        .output()
        .expect("runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("json")
}

#[test]
fn stability_is_bounded_through_the_double_root_at_three() {
    let v = json(&["stability"]);
    assert_eq!(v["boundedness_from"], "transition_matrix");
    assert_eq!(v["charpoly"], "z^2 - 2*z + Phi^2*z - 2/27*Phi^4*z + 1/729*Phi^6*z + 1");
    assert_eq!(v["phi_max_exact"], "6");
    assert_eq!(v["bounded_at_phi_max"], false);
    let points = v["critical_points"].as_array().unwrap();
    let at = |exact: &str| points.iter().find(|p| p["phi_exact"] == exact).expect(exact);
    assert_eq!(at("3")["bounded"], true);
    assert_eq!(at("3*sqrt(3)")["bounded"], true);
    assert_eq!(at("6")["bounded"], false);
    let change = v["class_changes"].as_array().unwrap().iter().find(|c| c["phi_exact"] == "3");
    assert_eq!(change.unwrap()["at"], "double_root_on_circle");
}

#[test]
fn verify_agrees_numerically_at_three() {
    let v = json(&["verify", "--phi", "3"]);
    let m = &v[0];
    assert_eq!(m["agree"], true);
    let p = &m["points"][0];
    assert_eq!(p["phi"], 3.0);
    assert_eq!(p["class"], "double_root_on_circle");
    for z in p["eigenvalues"].as_array().unwrap() {
        assert!(
            (z[0].as_f64().unwrap() + 1.0).abs() < 1e-12 && z[1].as_f64().unwrap().abs() < 1e-12
        );
    }
    // P = −I: the state's norm does not grow.
    assert!(p["sim"]["norm_growth_per_step"].as_f64().unwrap().abs() < 1e-12);
}
