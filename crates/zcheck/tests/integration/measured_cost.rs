//! Any method is ranked by measured cost: `zcheck tradeoff --method FILE`
//! times a user's `.zm` file's compiled step (finite ns), with no hand
//! kernel beside it, while every built-in has both columns.

use std::process::Command;

use serde_json::Value;
use testkit::scratch::Scratch;

#[test]
fn tradeoff_ranks_a_user_method_by_measured_cost() {
    let scratch_path = Scratch::new("user");
    let path = scratch_path.join("user.zm");
    // A False Euler written another way: a user's own method.
    std::fs::write(&path, "method my_false_euler\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n")
        .unwrap();
    let p = path.display().to_string();
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(["tradeoff", "--method", &p, "--budget-ms", "1", "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let rows = v["methods"].as_array().unwrap();
    let user = rows.iter().find(|r| r["method"] == p.as_str()).expect("user row");
    assert!(user["ns_per_step"].as_f64().is_some_and(|x| x.is_finite() && x > 0.0), "{user}");
    assert!(user["ns_per_step_hand"].is_null());
    assert!(user["rank"].as_u64().is_some(), "a stable method is ranked: {user}");
    for r in rows.iter().filter(|r| r["method"] != p.as_str()) {
        assert!(r["ns_per_step"].as_f64().is_some_and(|x| x > 0.0), "{r}");
        assert!(r["ns_per_step_hand"].as_f64().is_some_and(|x| x > 0.0), "{r}");
    }
}
