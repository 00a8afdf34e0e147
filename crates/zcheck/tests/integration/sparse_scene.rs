//! The sparse route of `zcheck advise --scene` (the certified highest mode,
//! the lowest or in-band modes by shift and invert, samples between)
//! against the dense one (every mode, faer's dense eigensolver) on every
//! example scene and on scenes built here.

use std::process::Command;

use serde_json::Value;
use testkit::scratch::ScratchFile;

fn example(name: &str) -> String {
    format!("{}/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"))
}

#[track_caller]
fn advise(path: &str, route: &str) -> Value {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(["advise", "--scene", path, "--spectrum", route, "--no-simulate", "--format", "json"])
        .output()
        .expect("zcheck runs");
    assert!(out.status.success(), "{path} {route}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("json")
}

fn write(name: &str, text: &str) -> ScratchFile {
    ScratchFile::new(&format!("{name}.toml"), text)
}

/// An n×n cloth like the examples' (top row fixed, structural and shear
/// springs, C = K/10000), with a band.
fn cloth(n: usize, band: &str) -> String {
    let mut s = format!(
        "tick_hz = 60\nduration_s = 1\n[accuracy]\nphase_rad = 0.5\namplitude = 0.05\n{band}"
    );
    for i in 0..n {
        for j in 0..n {
            s += &format!(
                "[[mass]]\nname = \"p{i}_{j}\"\nkg = 0.005\npos = [{}, {}, 0.0]\n{}",
                0.02 * j as f64,
                -0.02 * i as f64,
                if i == 0 { "fixed = true\n" } else { "" }
            );
        }
    }
    let mut spring = |a: (usize, usize), b: (usize, usize), k: f64| {
        s += &format!(
            "[[spring]]\nbetween = [\"p{}_{}\", \"p{}_{}\"]\nstiffness = {k}\ndamping = {}\n",
            a.0,
            a.1,
            b.0,
            b.1,
            k / 1e4
        );
    };
    for i in 0..n {
        for j in 0..n {
            if j + 1 < n {
                spring((i, j), (i, j + 1), 50.0);
            }
            if i + 1 < n {
                spring((i, j), (i + 1, j), 50.0);
                if j + 1 < n {
                    spring((i, j), (i + 1, j + 1), 25.0);
                }
                if j > 0 {
                    spring((i, j), (i + 1, j - 1), 25.0);
                }
            }
        }
    }
    s
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

/// The distinct values of a sorted list (merged within 1e-9).
fn distinct(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| close(*a, *b, 1e-9));
    v
}

/// Both routes give every candidate the same substeps; every mode the
/// sparse route computes is a dense mode to 1e-9, and so is its highest
/// (Lanczos) frequency; the certified bound is at or above the dense
/// highest mode; with a complete band, the sparse route found every
/// distinct dense frequency in it.
#[track_caller]
fn routes_agree(name: &str, path: &str) {
    let (d, s) = (advise(path, "dense"), advise(path, "sparse"));
    assert_eq!(s["spectrum"]["route"], "sparse", "{name}");
    assert_eq!(d["spectrum"]["route"], "dense", "{name}");
    for (a, b) in
        d["candidates"].as_array().unwrap().iter().zip(s["candidates"].as_array().unwrap())
    {
        assert_eq!(a["method"], b["method"]);
        assert_eq!(a["substeps_stable"], b["substeps_stable"], "{name} {}", a["method"]);
        assert_eq!(a["substeps_accurate"], b["substeps_accurate"], "{name} {}", a["method"]);
    }
    assert_eq!(d["recommended"], s["recommended"], "{name}");
    // Frequencies compare where the dense modes are the undamped ones
    // (under non-proportional damping they are the damped |λ|).
    if d["damping"]["kind"] == "non_proportional" {
        return;
    }
    let hz = |v: &Value, sampled: bool| -> Vec<f64> {
        v["modes"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|m| m["sampled"].as_bool().unwrap_or(false) == sampled)
            .map(|m| m["hz"].as_f64().unwrap())
            .collect()
    };
    let dense = distinct(hz(&d, false));
    let top = *dense.last().unwrap();
    for f in hz(&s, false) {
        assert!(dense.iter().any(|&g| close(f, g, 1e-9)), "{name}: sparse mode {f} Hz not dense");
    }
    let ritz = s["highest_hz"].as_f64().unwrap();
    assert!(close(ritz, top, 1e-9), "{name}: highest {ritz} vs dense {top}");
    let bound = s["highest_hz_bound"].as_f64().unwrap();
    assert!(bound >= top, "{name}: bound {bound} below {top}");
    if s["spectrum"]["band_complete"] == true {
        let f = s["max_hz"].as_f64().unwrap();
        let want: Vec<f64> = dense.iter().copied().filter(|&g| g <= f).collect();
        let got = distinct(hz(&s, false));
        assert_eq!(got.len(), want.len(), "{name}: band modes {got:?} vs {want:?}");
    }
}

#[test]
fn sparse_and_dense_routes_agree_on_every_example_scene() {
    // spring_120hz is a scene of modes: there is no eigenproblem.
    for name in ["chain10", "quarter_car", "cloth_strip", "building3", "cloth8", "rope2d"] {
        routes_agree(name, &example(name));
    }
}

#[test]
fn sparse_and_dense_routes_agree_on_a_cloth_with_a_band() {
    let path = write("cloth20", &cloth(20, "max_hz = 8\n"));
    routes_agree("cloth20 band", path.to_str().unwrap());
    // The band is complete there, so the count of band modes was compared.
    assert_eq!(advise(path.to_str().unwrap(), "sparse")["spectrum"]["band_complete"], true);
    let path = write("cloth12-all", &cloth(12, ""));
    routes_agree("cloth12 every mode", path.to_str().unwrap());
}

/// The two-scale scene (a slow and a stiff oscillator): with the band at
/// 10 Hz, the sparse route's answer is the dense route's.
#[test]
fn max_hz_on_the_sparse_route() {
    let text = "tick_hz = 60\nduration_s = 2\n[accuracy]\nmax_hz = 10\n\
        [[mass]]\nname = \"slow\"\nkg = 1.0\n[[mass]]\nname = \"fast\"\nkg = 1.0\n\
        [[spring]]\nbetween = [\"ground\", \"slow\"]\nstiffness = 39.47841760435743\n\
        [[spring]]\nbetween = [\"ground\", \"fast\"]\nstiffness = 1579136.704174297\n";
    let path = write("two-scale", text);
    routes_agree("two-scale", path.to_str().unwrap());
    let s = advise(path.to_str().unwrap(), "sparse");
    assert_eq!(s["spectrum"]["band_complete"], true);
    assert_eq!(s["spectrum"]["computed"], 1, "{}", s["spectrum"]);
}

/// The 64×64 cloth takes the sparse route by default, and the checking
/// simulation (whole scene, physical coordinates) agrees with the
/// prediction for every candidate it simulates.
#[test]
fn the_large_cloth_takes_the_sparse_route_and_its_simulation_agrees() {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(["advise", "--scene", &example("cloth64"), "--format", "json"])
        .output()
        .expect("zcheck runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["spectrum"]["route"], "sparse");
    assert_eq!(v["spectrum"]["certificate"], "cholesky");
    assert_eq!(v["spectrum"]["untouched_dofs"], 4032);
    assert_eq!(v["spectrum"]["band_complete"], true);
    let mut simulated = 0;
    for c in v["candidates"].as_array().unwrap() {
        if !c["simulated"].is_null() {
            assert_eq!(c["simulated"]["agree"], true, "{c}");
            assert!(c["simulated"]["modes_checked"].as_u64().unwrap() >= 4, "{c}");
            simulated += 1;
        }
    }
    assert!(simulated >= 1);
}
