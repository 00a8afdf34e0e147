//! Butcher tableaux as input (`zcheck from-tableau`, `zcheck::tableau`):
//! each tableau's program gives exactly the χ of the hand-written program
//! of the same method (the oracle), explicit tableaux give explicit
//! programs, and every mistake in a tableau file is located.

use std::path::{Path, PathBuf};
use std::process::Command;

use zcheck::tableau::Tableau;

fn tableau_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tableaux")
}

fn load(name: &str) -> Tableau {
    Tableau::load(&tableau_dir().join(format!("{name}.toml"))).expect("tableau loads")
}

fn chi_of(src: &str) -> poly::Poly {
    poly::derive_source("generated.zm", src).expect("derives").charpoly().clone()
}

/// RK4's tableau gives the χ of the hand-written RK4 program (state in the
/// other order, stages written out by hand), and an explicit program.
#[test]
fn rk4_tableau_matches_the_hand_written_program() {
    let t = load("rk4");
    assert!(t.is_explicit());
    let src = t.to_zm(false);
    assert!(!src.contains("unknown"), "{src}");
    let hand = include_str!("../../../poly/methods/rk4.zm");
    assert_eq!(chi_of(&src), chi_of(hand));
}

/// Each implicit tableau gives the χ of the implicit built-in of the same
/// name, written by hand in issue 11's language.
#[test]
fn implicit_tableaux_match_the_builtins() {
    for name in ["gauss_legendre_2", "radau_iia_2", "sdirk2"] {
        let t = load(name);
        assert!(!t.is_explicit(), "{name}");
        let src = t.to_zm(false);
        let builtin = poly::advanced::builtins::builtin_source(name).expect("built-in");
        assert_eq!(chi_of(&src), chi_of(builtin), "{name}:\n{src}");
    }
}

/// The damped program is the undamped one at D = 0, and reads D otherwise.
#[test]
fn damped_programs_reduce_to_the_oscillator_at_zero_damping() {
    for name in ["rk4", "gauss_legendre_2", "sdirk2"] {
        let t = load(name);
        let damped = chi_of(&t.to_zm(true));
        let d = poly::Sym::new("D");
        assert!(damped.symbols().contains(&d), "{name}");
        let at_zero = damped.eval_partial(&[(d, poly::q(0, 1))].into_iter().collect());
        assert_eq!(at_zero, chi_of(&t.to_zm(false)), "{name}");
    }
}

/// The damped RK4 program agrees with the hand-written damped Heun's
/// structure where they must: its χ at Φ → the stability function of RK4
/// applied to the damped test matrix. Checked against the explicit series
/// R(w) = 1 + w + w²/2 + w³/6 + w⁴/24 evaluated on the damped oscillator's
/// matrix J = [[-2D, -1], [1, 0]]: χ(z) = det(zI − R(ΦJ)).
#[test]
fn damped_rk4_is_the_taylor_polynomial_of_the_damped_matrix() {
    use poly::{Poly, PolyMatrix};
    let t = load("rk4");
    let chi = chi_of(&t.to_zm(true));
    let (phi, d) = (Poly::sym(poly::Sym::phi()), Poly::sym(poly::Sym::new("D")));
    let zero = Poly::int(0);
    let j = PolyMatrix::from_rows(vec![
        vec![&(&Poly::int(-2) * &d) * &phi, &Poly::int(-1) * &phi],
        vec![phi.clone(), zero.clone()],
    ]);
    let id = PolyMatrix::from_rows(vec![
        vec![Poly::int(1), zero.clone()],
        vec![zero.clone(), Poly::int(1)],
    ]);
    // R(ΦJ) by Horner: ((((ΦJ/4 + I)ΦJ/3 + I)ΦJ/2 + I)ΦJ + I).
    let mut r = id.clone();
    for k in [4, 3, 2, 1] {
        let scaled = (&r * &j).map(|e| e.scale(&poly::q(1, k)));
        r = PolyMatrix::from_rows(
            (0..2).map(|a| (0..2).map(|b| &scaled[(a, b)] + &id[(a, b)]).collect()).collect(),
        );
    }
    let z = Poly::sym(poly::Sym::z());
    let m = |a: usize, b: usize| if a == b { &z - &r[(a, b)] } else { &zero - &r[(a, b)] };
    let expected = &(&m(0, 0) * &m(1, 1)) - &(&m(0, 1) * &m(1, 0));
    assert_eq!(chi, expected);
}

fn zcheck(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("run zcheck");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `from-tableau` prints a program that `derive` reads back; `derive` and
/// `stability` also read the tableau directly.
#[test]
fn the_commands_read_tableaux() {
    let rk4 = tableau_dir().join("rk4.toml");
    let rk4 = rk4.to_str().expect("utf-8");
    let (code, zm, err) = zcheck(&["from-tableau", rk4]);
    assert_eq!(code, 0, "{err}");
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("tableau");
    std::fs::create_dir_all(&dir).expect("dir");
    let file = dir.join("rk4_generated.zm");
    std::fs::write(&file, &zm).expect("write");
    let (code, from_zm, err) = zcheck(&["derive", file.to_str().expect("utf-8")]);
    assert_eq!(code, 0, "{err}");
    let (code, from_toml, err) = zcheck(&["derive", rk4]);
    assert_eq!(code, 0, "{err}");
    let chi = |s: &str| s.lines().find(|l| l.starts_with("chi(z) =")).map(str::to_owned);
    assert!(chi(&from_zm).is_some(), "{from_zm}");
    assert_eq!(chi(&from_zm), chi(&from_toml));
    let (code, out, err) = zcheck(&["stability", rk4, "--format", "json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("json");
    assert_eq!(v["stability"], "limited", "{out}");
}

/// Every mistake in a tableau file: exit 2, the file's line and column, and
/// what was expected. One line per case: file text, location, fragment.
#[test]
#[rustfmt::skip]
fn mistakes_are_located() {
    let cases: &[(&str, &str, &str)] = &[
        ("A = [[inf]]\nb = [1]\n", ":1:7:", "not a finite number"),
        ("A = [[nan]]\nb = [1]\n", ":1:7:", "NaN is not a finite number"),
        ("A = [[0, 0], [1]]\nb = [1, 0]\n", ":1:14:", "row 2 of A has 1 entries: expected 2"),
        ("A = [[0]]\nb = [1, 2]\n", ":2:5:", "b has 2 entries: expected 1"),
        ("A = [[0]]\nb = [\"1/(1 - 1)\"]\n", ":2:6:", "b[1]"),
        ("A = [[\"x\"]]\nb = [1]\n", ":1:7:", "unexpected name `x`"),
        ("A = [[\"Phi\"]]\nb = [1]\n", ":1:7:", "unexpected name `Phi`"),
        ("A = [[\"sqrt(0)\"]]\nb = [1]\n", ":1:7:", "expected a positive integer literal"),
        ("A = [[\"sqrt(2.5)\"]]\nb = [1]\n", ":1:7:", "expected a positive integer literal"),
        ("A = [[\"root(1, 5)\"]]\nb = [1]\n", ":1:7:", "K >= 2"),
        ("A = [[\"sqrt(2\"]]\nb = [1]\n", ":1:7:", "not closed"),
        ("A = [[\"1/2 \u{2212} 1\"]]\nb = [1]\n", ":1:7:", "U+2212"),
        ("A = [[true]]\nb = [1]\n", ":1:7:", "found a boolean"),
        ("A = [[\"\"]]\nb = [1]\n", ":1:7:", "the entry is empty"),
        ("A = [[0]]\n", ":1:1:", "missing field `b`"),
        ("A = [[0]]\nb = [1]\nd = 3\n", ":3:1:", "unknown field `d`"),
        ("A = []\nb = []\n", ":1:5:", "A has 0 rows"),
        ("name = \"my method\"\nA = [[0]]\nb = [1]\n", ":1:8:", "expected letters, digits and `_`"),
        ("A = [[0, 0], [\"1/2\", 0]]\nb = [0, 1]\nc = [0, \"1/3\"]\n", "", ""),
    ];
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("tableau");
    std::fs::create_dir_all(&dir).expect("dir");
    let mut failures = Vec::new();
    for (k, (text, at, says)) in cases.iter().enumerate() {
        let file = dir.join(format!("case_{k}.toml"));
        std::fs::write(&file, text).expect("write");
        let path = file.to_str().expect("utf-8");
        let (code, out, err) = zcheck(&["from-tableau", path]);
        assert!(!err.contains("panicked"), "{err}");
        if at.is_empty() {
            // c that is not A's row sums is allowed (an autonomous equation
            // never reads c), and said in the program.
            if code != 0 || !out.contains("c differs from A's row sums in row(s) [2]") {
                failures.push(format!("{text:?}: exit {code}: {out}{err}"));
            }
            continue;
        }
        if code != 2 || !err.contains(&format!("{path}{at}")) || !err.contains(says) {
            failures.push(format!("{text:?}: expected exit 2 at {at} saying {says:?}: exit {code}: {err}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A TOML float is the decimal written: `0.1` is 1/10, so a tableau in
/// floats derives the same χ as the one in fractions.
#[test]
fn toml_floats_are_the_decimals_written() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("tableau-floats");
    std::fs::create_dir_all(&dir).expect("dir");
    let floats = dir.join("heun_floats.toml");
    let exact = dir.join("heun_exact.toml");
    std::fs::write(&floats, "A = [[0, 0], [1.0, 0]]\nb = [0.5, 0.5]\n").unwrap();
    std::fs::write(&exact, "A = [[0, 0], [1, 0]]\nb = [\"1/2\", \"1/2\"]\n").unwrap();
    let chi = |p: &PathBuf| {
        let (code, out, err) = zcheck(&["stability", p.to_str().unwrap(), "--format", "json"]);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        v["charpoly"].as_str().unwrap().to_owned()
    };
    assert_eq!(chi(&floats), chi(&exact));
    // 0.1 is 1/10, not 3602879701896397/36028797018963968.
    std::fs::write(&floats, "A = [[0.1]]\nb = [1]\n").unwrap();
    let (code, out, _) = zcheck(&["from-tableau", floats.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(out.contains("1/10"), "{out}");
}

/// A tableau's programs are derived from its stability function R = P/Q;
/// on every tableau of NodePy's catalogue and of `tableaux/`, that gives
/// exactly what solving the stages' system by both routes gives (the
/// oracle): χ, d·P, d, M, and so the same stability and w-plane reports.
#[test]
fn stability_function_route_matches_both_routes_on_the_catalogues() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<PathBuf> = Vec::new();
    for dir in [root.join("tests/data/nodepy/rk"), tableau_dir()] {
        for e in std::fs::read_dir(dir).expect("catalogue") {
            let p = e.expect("entry").path();
            if p.extension().is_some_and(|x| x == "toml")
                && !std::fs::read_to_string(&p).expect("text").contains("alpha")
            {
                files.push(p);
            }
        }
    }
    files.sort();
    assert!(files.len() > 50, "{}", files.len());
    let params = poly::Params::new();
    for f in &files {
        let arg = f.display().to_string();
        let oscillator = zcheck::api::load(&arg).expect("loads");
        let scalar = zcheck::load::LoadedMethod::load_for_plane(&arg).expect("loads");
        for m in [oscillator.method(), scalar.method()] {
            let fast = poly::derive(m).expect("derives");
            let slow = poly::advanced::derive_both_routes(m).expect("derives");
            assert_eq!(fast.charpoly(), slow.charpoly(), "{arg}");
            assert_eq!(fast.transition_matrix(), slow.transition_matrix(), "{arg}");
            assert_eq!(fast.p_denominator(), slow.p_denominator(), "{arg}");
            assert_eq!(fast.z_matrix(), slow.z_matrix(), "{arg}");
            if m.is_scalar() {
                assert_eq!(fast.plane(&params).ok(), slow.plane(&params).ok(), "{arg}");
            } else {
                let report = |d: &poly::Derivation| format!("{:?}", d.stability(&params).ok());
                assert_eq!(report(&fast), report(&slow), "{arg}");
            }
        }
    }
}
