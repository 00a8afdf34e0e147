//! `zcheck equiv A B`: the strongest identity between two methods, run as a
//! user runs it, and `poly::advanced::equiv` over every pair of built-ins checked
//! against the slow oracle (rebuilding one transition matrix from the other
//! with the permutation and scaling found; comparing χ directly).

use std::process::{Command, Output};

use poly::advanced::equiv::{self, Relation};
use serde_json::Value;

fn zcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("zcheck runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).expect("utf-8")
}

/// Damped Euler (D = Φ/2) is False Euler with v and y exchanged and one sign
/// flipped; Verlet shares only χ; Standard Euler shares nothing.
#[test]
fn text_and_json_name_the_relation() {
    let out = zcheck(&["equiv", "false_euler", "damped_euler"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("similar by a permutation and a diagonal scaling"),
        "{}",
        text(&out.stdout)
    );
    for (b, relation, shares) in [
        ("verlet", "same_charpoly", true),
        ("standard_euler", "different", false),
        ("false_euler_matrix", "equal", true),
    ] {
        let out = zcheck(&["equiv", "false_euler", b, "--format", "json"]);
        assert!(out.status.success(), "{b}: {}", text(&out.stderr));
        let v: Value = serde_json::from_str(&text(&out.stdout)).expect("json");
        assert_eq!(v["relation"], relation, "{b}");
        assert_eq!(v["shares_charpoly"], shares, "{b}");
        assert_eq!(v["charpoly_a"] == v["charpoly_b"], shares, "{b}");
    }
}

/// A `.zm` file: False Euler with its two updates swapped is recognised as
/// a reordering of the built-in's updates, and its P is the built-in's up to
/// a signed permutation.
#[test]
fn zm_files_and_reordered_updates() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("equiv_cli");
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join("swapped.zm");
    std::fs::write(&path, "method swapped\nstate v y\ny = y + Phi*v\nv = v - Phi*y\n")
        .expect("write");
    let out =
        zcheck(&["equiv", "false_euler", path.to_str().expect("utf-8 path"), "--format", "json"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let v: Value = serde_json::from_str(&text(&out.stdout)).expect("json");
    assert_eq!(v["reordered_updates"], true);
    assert_eq!(v["relation"], "permutation_and_scaling");
}

/// Bad input: an unknown name and a broken file are errors with exit code 2.
#[test]
fn bad_input_exits_2() {
    let out = zcheck(&["equiv", "false_euler", "no_such_method"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("no_such_method"), "{}", text(&out.stderr));
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("equiv_cli");
    std::fs::create_dir_all(&dir).expect("dir");
    let path = dir.join("broken.zm");
    std::fs::write(&path, "method broken\nstate v y\nv = v*y\n").expect("write");
    let out = zcheck(&["equiv", path.to_str().expect("utf-8 path"), "false_euler"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("broken.zm:3:"), "{}", text(&out.stderr));
}

/// Every pair of built-ins: the relation found is true (P_b rebuilt from P_a
/// exactly), symmetric in kind, and "shares χ" is exactly χ_a = χ_b.
#[test]
fn every_pair_of_builtins_against_the_oracle() {
    // Every built-in, implicit ones included: their P is (d·P)/d, so the
    // oracle compares fractions by cross-multiplying the denominators.
    let names: Vec<&str> = poly::advanced::builtins::builtin_names().collect();
    let derive = |n: &str| poly::derive(&poly::builtin(n).expect("built-in")).expect("derives");
    let mut identities = 0;
    for a in &names {
        for b in &names {
            let (da, db) = (derive(a), derive(b));
            let r = equiv::relate(&da, &db);
            let (dena, denb) = (&da.p_denominator, &db.p_denominator);
            let same_chi = &da.charpoly * denb == &db.charpoly * dena;
            assert_eq!(r.shares_charpoly(), same_chi, "{a} {b}");
            assert_eq!(r.name(), equiv::relate(&db, &da).name(), "{a} {b}: not symmetric");
            let (pa, pb) =
                (&da.transition_matrix.map(|e| e * denb), &db.transition_matrix.map(|e| e * dena));
            let n = pa.rows();
            let one = poly::q(1, 1);
            let (perm, scale): (Vec<usize>, Vec<poly::Q>) = match &r {
                Relation::Equal => ((0..n).collect(), vec![one.clone(); n]),
                Relation::Permutation { perm } => (perm.clone(), vec![one.clone(); n]),
                Relation::Scaling { scale } => ((0..n).collect(), scale.clone()),
                Relation::PermutationAndScaling { perm, scale } => (perm.clone(), scale.clone()),
                Relation::SameCharpoly | Relation::Different => continue,
            };
            identities += 1;
            for i in 0..n {
                for j in 0..n {
                    let rebuilt = pa[(perm[i], perm[j])].scale(&(&scale[i] / &scale[j]));
                    assert_eq!(rebuilt, pb[(i, j)], "{a} -> {b} at ({i}, {j})");
                }
            }
        }
    }
    // The twins (6 pairs, both ways), each method with itself (14), and
    // Damped Euler with False Euler and its twin (4 pairs, both ways).
    assert!(identities >= names.len() + 12 + 8, "{identities}");
}

/// Backward Euler's P is (numerator)/(1 + Φ²): never equal to Standard
/// Euler's, whose P is its numerator's shape without the denominator.
#[test]
fn implicit_p_is_compared_as_a_fraction() {
    let derive = |n: &str| poly::derive(&poly::builtin(n).expect("built-in")).expect("derives");
    let (be, se) = (derive("backward_euler"), derive("standard_euler"));
    assert!(!be.p_denominator.is_one());
    assert!(
        !matches!(equiv::relate(&be, &se), Relation::Equal),
        "{}",
        equiv::relate(&be, &se).name()
    );
    // Trapezoidal and implicit midpoint share χ on the oscillator.
    let (tr, mp) = (derive("trapezoidal"), derive("implicit_midpoint"));
    assert!(equiv::relate(&tr, &mp).shares_charpoly());
}
