//! The README's two commands share one build. Every library the main job
//! (`cargo run --release --bin zcheck -- paper`) compiles gets the features
//! the test command (`cargo test --workspace --release`) unifies, so the
//! tests reuse it instead of compiling serde, clap, poly, check and zcheck a
//! second time. crates/zcheck/Cargo.toml pins those features (DESIGN.md, "Why
//! are the tests built in release mode?"); this test finds the pin a dependency
//! update makes stale, by asking cargo for both feature sets.

use std::collections::{BTreeMap, BTreeSet};
use std::process::Command;

/// Each package of `cargo tree ARGS` (name, version and, for a path
/// package, its path), with the feature lists it is built with: two lists
/// where the host side (build scripts, proc macros) differs from the target.
fn features(args: &[&str]) -> BTreeMap<String, BTreeSet<String>> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_owned());
    let out = Command::new(cargo)
        .args(["tree", "--offline", "--locked", "--prefix", "none", "--format", "{p}|{f}"])
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("run cargo tree");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "cargo tree {args:?} failed: {stderr}");
    let mut map = BTreeMap::<String, BTreeSet<String>>::new();
    for line in String::from_utf8(out.stdout).expect("utf-8").lines() {
        let line = line.trim_end_matches(" (*)");
        if line.is_empty() {
            continue;
        }
        let (package, features) = line.split_once('|').expect("{p}|{f}");
        map.entry(package.to_owned()).or_default().insert(features.to_owned());
    }
    map
}

#[test]
fn the_tests_reuse_every_library_the_main_job_builds() {
    let main_job = features(&["-p", "zcheck", "-e", "no-dev"]);
    let tests = features(&["--workspace"]);
    assert!(main_job.len() > 50, "too few packages in the main job: {main_job:?}");
    let differ: Vec<String> = main_job
        .iter()
        .filter(|&(package, f)| tests.get(package) != Some(f))
        .map(|(package, f)| format!("{package}: main job {f:?}, tests {:?}", tests.get(package)))
        .collect();
    assert!(
        differ.is_empty(),
        "the README's test command would compile these again: pin their features in \
         crates/zcheck/Cargo.toml:\n{}",
        differ.join("\n")
    );
}
