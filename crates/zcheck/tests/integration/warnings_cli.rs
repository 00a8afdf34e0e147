//! Warnings (issue 27): each fires on a file that has the mistake and
//! stays silent on one that does not; `--deny-warnings` turns them into an
//! exit-2 error before any output.

use crate::run::zcheck;
use std::path::{Path, PathBuf};

fn write(name: &str, text: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("warnings");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    path
}

/// The warnings `stability FILE` prints (it succeeds either way).
fn warnings(path: &Path) -> Vec<String> {
    let (code, stdout, stderr) = zcheck(&["stability", path.to_str().expect("utf-8")]);
    assert_eq!(code, 0, "{stderr}");
    assert!(!stdout.is_empty());
    stderr.lines().filter(|l| l.starts_with("warning: ")).map(str::to_owned).collect()
}

#[track_caller]
fn fires(name: &str, bad: &str, says: &[&str], good: &str) {
    let w = warnings(&write(&format!("bad_{name}"), bad));
    assert_eq!(w.len(), says.len(), "{name}: {w:#?}");
    for (w, s) in w.iter().zip(says) {
        assert!(w.contains(s), "{name}: {w:?} lacks {s:?}");
        assert!(w.contains(&format!("bad_{name}:")), "{name}: {w:?} is not located in its file");
    }
    let w = warnings(&write(&format!("good_{name}"), good));
    assert!(w.is_empty(), "{name}: fired on the good file: {w:#?}");
}

#[test]
fn program_warnings() {
    fires(
        "typo.zm",
        "method m\nstate y v\nyy = y + Phi*v\nv = v - Phi*y\n",
        &[
            ":2:7: state variable `y` is never assigned",
            ":3:1: `yy` is assigned but never read: did you mean the state variable `y`?",
        ],
        "method m\nstate y v\ny = y + Phi*v\nv = v - Phi*y\n",
    );
    fires(
        "decimal.zm",
        "method m\nstate y v\nv = v - 0.3333333333333333*Phi*y  # 0.5000000000000001 in a comment\ny = y + Phi*v\n",
        &[":3:9: 0.3333333333333333 is within 1e-12 of 1/3"],
        "method m\nstate y v\nv = v - 0.5*Phi*y\ny = y + 1e-3*v + Phi*v\n",
    );
    fires(
        "unread.zm",
        "method m\nstate y v\nk = Phi*y\nv = v - Phi*y\ny = y + Phi*v\n",
        &[":3:1: `k` is assigned but never read: no later line uses this value"],
        "method m\nstate y v\nk = Phi*y\nv = v - k\ny = y + Phi*v\n",
    );
}

#[test]
fn tableau_warnings() {
    fires(
        "weights.toml",
        "A = [[0, 0], [\"1/2\", 0]]\nb = [\"1/2\", \"1/3\"]\n",
        &[":2:5: b sums to 5/6, not 1: the method is not consistent"],
        "A = [[0, 0], [\"1/2\", 0]]\nb = [0, 1]\n",
    );
    fires(
        "c.toml",
        "A = [[0, 0], [\"1/2\", 0]]\nb = [0, 1]\nc = [0, \"1/3\"]\n",
        &[":3:9: c[2] differs from row 2 of A, which sums to 1/2"],
        "A = [[0, 0], [\"1/2\", 0]]\nb = [0, 1]\nc = [0, 0.5]\n",
    );
    fires(
        "decimal.toml",
        "A = [[0, 0], [0.6666666666666666, 0]]\nb = [0.25, 0.75]\n",
        &[":1:15: A[2][1] = 0.6666666666666666 is within 1e-12 of 2/3: write \"2/3\""],
        "A = [[0, 0], [0.5, 0]]\nb = [0, 1.0]\n",
    );
    fires(
        "surd.toml",
        "A = [[0.7886751345948129]]\nb = [1]\n",
        &[":1:7: A[1][1] = 0.7886751345948129 is within 1e-12 of (3 + sqrt(3))/6"],
        "A = [[\"(3 + sqrt(3))/6\"]]\nb = [1]\n",
    );
}

#[test]
fn multistep_warnings() {
    fires(
        "inconsistent.toml",
        "alpha = [-1, 1]\nbeta = [0.5, 0.6]\n",
        &[":1:9: ρ'(1) = Σjα_j = 1 but σ(1) = Σβ_j = 11/10, expected them equal"],
        "alpha = [-1, 1]\nbeta = [0.5, 0.5]\n",
    );
    fires(
        "not_zero_stable.toml",
        "alpha = [-5, 4, 1]\nbeta = [2, 4, 0]\n",
        &[":1:9: ρ(z) = Σα_j z^j has a root outside the unit circle"],
        "alpha = [0, -1, 1]\nbeta = [\"-1/2\", \"3/2\", 0]\n",
    );
}

/// `--deny-warnings` refuses before any output, wherever the flag stands;
/// without it the same run succeeds, and a clean file passes with it.
#[test]
fn deny_warnings() {
    let bad = write("deny.zm", "method m\nstate y v\nk = Phi*y\nv = v - Phi*y\ny = y + Phi*v\n");
    let bad = bad.to_str().expect("utf-8");
    for args in [["--deny-warnings", "stability", bad], ["stability", bad, "--deny-warnings"]] {
        let (code, stdout, stderr) = zcheck(&args);
        assert_eq!(code, 2, "{stderr}");
        assert!(stdout.is_empty(), "{stdout}");
        assert!(
            stderr.contains("1 warning above, and --deny-warnings makes them errors"),
            "{stderr}"
        );
    }
    let (code, stdout, _) = zcheck(&["stability", bad]);
    assert_eq!(code, 0);
    assert!(stdout.contains("chi(z)"));
    let (code, _, stderr) = zcheck(&["--deny-warnings", "stability", "false_euler"]);
    assert_eq!((code, stderr.as_str()), (0, ""));
}

/// Nowhere else: every exact catalogue file, tableau or multistep, is
/// warning-free (the float-only ones, marked INEXACT, do warn: their
/// weights sum to 1 ± 1e-17).
#[test]
fn exact_catalogue_is_warning_free() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/nodepy");
    let mut checked = 0;
    for kind in ["rk", "lmm"] {
        for e in std::fs::read_dir(root.join(kind)).expect("catalogue") {
            let path = e.expect("entry").path();
            if std::fs::read_to_string(&path).expect("read").contains("INEXACT") {
                continue;
            }
            assert!(warnings(&path).is_empty(), "{}", path.display());
            checked += 1;
        }
    }
    assert!(checked >= 60, "{checked}");
}
