//! `zcheck equiv A B`: the strongest identity between two methods, run as a
//! user runs it, and `poly::advanced::equiv` over every pair of built-ins checked
//! against the slow oracle (rebuilding one transition matrix from the other
//! with the permutation and scaling found, multiplying out T·P_a and P_b·T
//! for a change of variables; comparing χ directly).

use std::path::Path;
use std::process::{Command, Output};

use poly::advanced::equiv::{self, Relation};
use poly::PolyMatrix;
use serde_json::Value;

/// A file of this crate: `methods/…` or `tests/data/…`.
fn file(rel: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel).to_str().expect("utf-8 path").to_owned()
}

fn zcheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("zcheck runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).expect("utf-8")
}

/// Damped Euler (D = Φ/2) is False Euler with v and y exchanged and one sign
/// flipped; Verlet is False Euler through a change of variables T(Φ);
/// Standard Euler shares nothing.
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
        ("verlet", "change_of_variables", true),
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

/// Verlet and False Euler: the text prints T, T⁻¹ and the two sets of
/// equations, the JSON the same, and T·P_a = P_b·T holds when the printed
/// matrices are parsed back and multiplied here.
#[test]
fn verlet_and_false_euler_through_t_of_phi() {
    let out = zcheck(&["equiv", "verlet", "false_euler"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    for line in [
        "verlet and false_euler: similar by a change of variables T(Phi), not by a permutation or scaling",
        "  v = (y - y@1)/Phi",
        "  y@1 = y - Phi*v",
        "T = [[1, -1], [Phi, 0]] / Phi",
        "T^-1 = [[0, 1], [-Phi, 1]]",
        "T and T^-1 exist wherever Phi != 0",
        "the samples of y are identical: y_n of false_euler from T x0 equals y_n of verlet from x0",
    ] {
        assert!(stdout.contains(line), "missing {line:?} in\n{stdout}");
    }
    let out = zcheck(&["equiv", "verlet", "false_euler", "--format", "json"]);
    let v: Value = serde_json::from_str(&text(&out.stdout)).expect("json");
    let change = &v["change"];
    assert_eq!(change["observed"], "y");
    assert_eq!(change["t_denominator"], "Phi");
    assert_eq!(change["b_from_a"][0], "v = (y - y@1)/Phi");
    let matrix = |m: &Value| {
        PolyMatrix::from_rows(
            m.as_array()
                .expect("rows")
                .iter()
                .map(|r| {
                    r.as_array()
                        .expect("entries")
                        .iter()
                        .map(|e| {
                            poly::Poly::parse(e.as_str().expect("text")).expect("a polynomial")
                        })
                        .collect()
                })
                .collect(),
        )
    };
    let (t, inverse) = (matrix(&change["t"]), matrix(&change["inverse"]));
    let derive = |n: &str| poly::derive(&poly::builtin(n).expect("built-in")).expect("derives");
    let (pa, pb) = (
        derive("verlet").transition_matrix().clone(),
        derive("false_euler").transition_matrix().clone(),
    );
    assert_eq!(&t * &pa, &pb * &t, "T P_a = P_b T");
    let phi = poly::Poly::var("Phi");
    assert_eq!(&t * &inverse, PolyMatrix::identity(2).map(|e| e * &phi), "T T^-1 = I");
}

/// The y-first symplectic Euler (`methods/symplectic_euler_y_first.zm`) is
/// Damped Euler with D = Φ/2 exactly, and False Euler up to a signed
/// permutation; Damped Euler and False Euler stay a signed permutation (the
/// stronger relation), not a change of variables.
#[test]
fn damped_euler_is_the_y_first_symplectic_euler() {
    let y_first = file("methods/symplectic_euler_y_first.zm");
    for (a, b, relation) in [
        (y_first.as_str(), "damped_euler", "equal"),
        (y_first.as_str(), "false_euler", "permutation_and_scaling"),
        ("damped_euler", "false_euler", "permutation_and_scaling"),
        ("damped_euler_d", "false_euler", "different"),
    ] {
        let out = zcheck(&["equiv", a, b, "--format", "json"]);
        assert!(out.status.success(), "{a} {b}: {}", text(&out.stderr));
        let v: Value = serde_json::from_str(&text(&out.stdout)).expect("json");
        assert_eq!(v["relation"], relation, "{a} {b}");
        assert_eq!(v["change"], Value::Null, "{a} {b}");
    }
}

/// Two steps with the same χ = (z − c)², c = 1 − Φ²/2, that no change of
/// variables relates: c·I against a Jordan block. The weaker relation is
/// the truth there, and is what `equiv` says.
#[test]
fn same_charpoly_only_where_that_is_the_truth() {
    let (scalar, jordan) =
        (file("tests/data/equiv/scalar_step.zm"), file("tests/data/equiv/jordan_step.zm"));
    for (a, b) in [(&scalar, &jordan), (&jordan, &scalar)] {
        let out = zcheck(&["equiv", a, b]);
        assert!(out.status.success(), "{}", text(&out.stderr));
        let stdout = text(&out.stdout);
        assert!(stdout.contains("the same characteristic polynomial, not similar"), "{stdout}");
        assert!(!stdout.contains("T ="), "{stdout}");
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
    let mut changes = 0;
    for a in &names {
        for b in &names {
            let (da, db) = (derive(a), derive(b));
            let r = equiv::relate(&da, &db);
            let (dena, denb) = (da.p_denominator(), db.p_denominator());
            let same_chi = da.charpoly() * denb == db.charpoly() * dena;
            assert_eq!(r.shares_charpoly(), same_chi, "{a} {b}");
            assert_eq!(r.name(), equiv::relate(&db, &da).name(), "{a} {b}: not symmetric");
            let (pa, pb) = (
                &da.transition_matrix().map(|e| e * denb),
                &db.transition_matrix().map(|e| e * dena),
            );
            let n = pa.rows();
            let one = poly::q(1, 1);
            let (perm, scale): (Vec<usize>, Vec<poly::Q>) = match &r {
                Relation::Equal => ((0..n).collect(), vec![one.clone(); n]),
                Relation::Permutation { perm } => (perm.clone(), vec![one.clone(); n]),
                Relation::Scaling { scale } => ((0..n).collect(), scale.clone()),
                Relation::PermutationAndScaling { perm, scale } => (perm.clone(), scale.clone()),
                Relation::ChangeOfVariables(change) => {
                    // T·P_a = P_b·T, multiplied out; T invertible.
                    assert_eq!(&change.t * pa, pb * &change.t, "{a} -> {b}: T P_a != P_b T");
                    let scale = &change.t_denominator * &change.inverse_denominator;
                    assert_eq!(
                        &change.t * &change.inverse,
                        PolyMatrix::identity(n).map(|e| e * &scale),
                        "{a} -> {b}: T T^-1 != I"
                    );
                    changes += 1;
                    continue;
                }
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
    // Verlet with False Euler, Damped Euler and the matrix twins of both
    // (4 pairs, both ways).
    assert!(changes >= 8, "{changes}");
}

/// Backward Euler's P is (numerator)/(1 + Φ²): never equal to Standard
/// Euler's, whose P is its numerator's shape without the denominator.
#[test]
fn implicit_p_is_compared_as_a_fraction() {
    let derive = |n: &str| poly::derive(&poly::builtin(n).expect("built-in")).expect("derives");
    let (be, se) = (derive("backward_euler"), derive("standard_euler"));
    assert!(!be.p_denominator().is_one());
    assert!(
        !matches!(equiv::relate(&be, &se), Relation::Equal),
        "{}",
        equiv::relate(&be, &se).name()
    );
    // Trapezoidal and implicit midpoint share χ on the oscillator.
    let (tr, mp) = (derive("trapezoidal"), derive("implicit_midpoint"));
    assert!(equiv::relate(&tr, &mp).shares_charpoly());
}
