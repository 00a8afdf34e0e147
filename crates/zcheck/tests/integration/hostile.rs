//! Hostile input, as a new user or an attacker would type it: every fault
//! kind of issue 14, one table line per case (arguments, a file's bytes,
//! the expected exit code, a fragment of the message and its location), and
//! the error contract checked on every line: exit 2 for bad input, 1 for a
//! disagreement, 0 otherwise; no panic; at most 4 KB of error; no control
//! character on the terminal but line feeds.

use std::io::Read;
use std::path::PathBuf;
use std::process::{Command, Stdio};

/// The declarations most `.zm` cases start from (lines 1–2).
const HEAD: &str = "method m\nstate v y\n";

/// One case: `args` with `{file}` standing for a file holding `file`'s bytes
/// (and `{dir}` for an existing directory); the expected exit `code`; a
/// fragment `says` of stderr (or of stdout when `code` is 0); and `at`, the
/// location that must follow the file name (`:3:13:`), empty when none.
struct Case<'a> {
    args: &'a [&'a str],
    file: &'a [u8],
    code: i32,
    says: &'a str,
    at: &'a str,
}

const fn case<'a>(
    args: &'a [&'a str],
    file: &'a [u8],
    code: i32,
    says: &'a str,
    at: &'a str,
) -> Case<'a> {
    Case { args, file, code, says, at }
}

fn dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("hostile");
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Runs `zcheck` and checks the contract; returns (stdout, stderr).
#[track_caller]
fn run(args: &[String], code: i32) -> (String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("zcheck runs");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(code), "{args:?}\nstderr: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?} panicked: {stderr}");
    assert!(out.stderr.len() <= 4096, "{args:?}: {} bytes of error", out.stderr.len());
    assert!(
        !stderr.chars().any(|c| c.is_control() && c != '\n'),
        "{args:?}: control character on stderr: {stderr:?}"
    );
    (stdout, stderr)
}

#[track_caller]
fn check(cases: &[Case]) {
    for (k, c) in cases.iter().enumerate() {
        let path = dir().join(format!(
            "case_{}_{k}.zm",
            std::thread::current().name().unwrap_or("t").replace("::", "_")
        ));
        std::fs::write(&path, c.file).expect("write case file");
        let path = path.to_str().expect("utf-8 path").to_owned();
        let args: Vec<String> = c
            .args
            .iter()
            .map(|a| a.replace("{file}", &path).replace("{dir}", dir().to_str().expect("utf-8")))
            .collect();
        let (stdout, stderr) = run(&args, c.code);
        let shown = if c.code == 0 { &stdout } else { &stderr };
        assert!(shown.contains(c.says), "{args:?}: lacks {:?}:\n{shown}", c.says);
        if !c.at.is_empty() {
            assert!(
                stderr.contains(&format!("{path}{}", c.at)),
                "{args:?}: not at {}:\n{stderr}",
                c.at
            );
        }
        if c.code == 2 {
            assert!(!stderr.contains(":0:0:"), "{args:?}: no location:\n{stderr}");
            assert!(stderr.starts_with("error:"), "{args:?}:\n{stderr}");
        }
    }
}

fn zm(body: &str) -> Vec<u8> {
    format!("{HEAD}{body}\n").into_bytes()
}

/// Runs that would take too long are refused up front, with the estimate
/// and the flag that allows them; `--steps 0` and `--steps 1` work.
#[test]
#[rustfmt::skip]
fn bounded_work() {
    check(&[
        case(&["verify", "false_euler", "--steps", "1000000000000"], b"", 2, "pass --budget 6000000000000", ""),
        case(&["verify", "false_euler", "--steps", "1000000000000"], b"", 2, "pass --budget 6000000000000", ""),
        case(&["verify", "false_euler", "--steps", "1000", "--budget", "5999"], b"", 2, "budget is 5999", ""),
        case(&["verify", "false_euler", "--steps", "1000", "--budget", "6000"], b"", 0, "witnesses agree", ""),
        case(&["verify", "false_euler", "--steps", "0"], b"", 0, "witnesses agree", ""),
        case(&["verify", "false_euler", "standard_euler", "--steps", "1"], b"", 0, "witnesses agree", ""),
        case(&["verify", "false_euler", "--steps", "-1"], b"", 2, "non-negative whole number", ""),
        case(&["verify", "false_euler", "--steps", "2.5"], b"", 2, "non-negative whole number", ""),
        case(&["verify", "false_euler", "--steps", "1e30"], b"", 2, "too large", ""),
        case(&["scene", "aircraft", "--steps", "100000000000"], b"", 2, "--budget", ""),
    ]);
}

/// Undeclared parameters are refused by every subcommand that takes
/// `--param`, and every one accepts fractions and exact decimals.
#[test]
#[rustfmt::skip]
fn parameters() {
    check(&[
        case(&["verify", "false_euler", "--param", "X=1", "--steps", "10"], b"", 2, "method false_euler has no parameter X (declared: none)", ""),
        case(&["verify", "false_euler", "damped_euler_d", "--param", "X=1"], b"", 2, "none of the methods declares a parameter X (declared: D)", ""),
        case(&["stability", "damped_euler_d", "--param", "X=1"], b"", 2, "has no parameter X (declared: D)", ""),
        case(&["verify", "damped_euler_d", "--param", "D=1/2", "--steps", "10"], b"", 0, "witnesses agree", ""),
        case(&["verify", "damped_euler_d", "--param", "D=0.1", "--steps", "10"], b"", 0, "witnesses agree", ""),
        case(&["stability", "damped_euler_d", "--param", "D=1/2"], b"", 0, "(D = 1/2)", ""),
        case(&["stability", "damped_euler_d", "--param", "D=0.1"], b"", 0, "(D = 1/10)", ""),
        case(&["stability", "damped_euler_d", "--param", "D=0.1.2"], b"", 2, "malformed number `0.1.2`", ""),
        case(&["verify", "damped_euler_d", "--param", "D=1/0"], b"", 2, "division by zero", ""),
        case(&["verify", "damped_euler_d", "--param", "D=1", "--param", "D=2"], b"", 2, "given twice", ""),
        case(&["verify", "damped_euler_d", "--param", "Phi=1"], b"", 2, "Phi is the step size", ""),
        case(&["stability", "damped_euler_d", "--param", "D=-1"], b"", 0, "(D = -1)", ""),
        case(&["verify", "false_euler", "--phi", "-1", "--steps", "10"], b"", 0, "witnesses agree", ""),
        case(&["verify", "false_euler", "--phi", "-1,0.5", "--steps", "10"], b"", 0, "witnesses agree", ""),
        case(&["advise", "--freq", "2", "--tick", "60", "--damping", "-1"], b"", 2, "0 <= D < 1", ""),
        case(&["advise", "--freq", "-2", "--tick", "60"], b"", 2, "--freq -2: expected a finite number > 0", ""),
        case(&["plot", "yt", "--out", "{dir}", "--phi", "-1"], b"", 2, "--phi -1: expected a positive number", ""),
        case(&["scene", "three_body_euler", "--eps", "-0.01", "--steps", "10"], b"", 0, "radius", ""),
        case(&["tradeoff", "--periods", "-1"], b"", 2, "--periods -1: expected a finite number > 0", ""),
        case(&["emit", "false_euler", "--lang", "rust", "--phi", "1/10"], b"", 0, "Phi = 1/10", ""),
        case(&["emit", "false_euler", "--lang", "c", "--phi", "-0.5"], b"", 0, "Phi = -1/2", ""),
        case(&["emit", "false_euler", "--lang", "rust", "--phi", "0.1.2"], b"", 2, "malformed number `0.1.2`", ""),
        case(&["emit", "damped_euler_d", "--lang", "rust", "--phi", "1"], b"", 2, "needs --param D=VALUE", ""),
        case(&["emit", "backward_euler", "--lang", "rust"], b"", 2, "backward_euler is implicit", ""),
        case(&["emit", "backward_euler", "--lang", "rust", "--phi", "1/10"], b"", 0, "let v_next = ", ""),
    ]);
}

/// Errors name the file and the place, or say clearly what the argument
/// is: no `:0:0:`, and a path is never looked up as a built-in.
#[test]
#[rustfmt::skip]
fn locations() {
    check(&[
        case(&["derive", "{file}"], b"method m\nstate v y\nv = v - Phi*\xff y\n", 2, "invalid UTF-8", ":3:13:"),
        case(&["derive", "{file}"], b"\xfe", 2, "invalid UTF-8", ":1:1:"),
        case(&["derive", "no_such_method"], b"", 2, "no built-in method named `no_such_method`", ""),
        case(&["verify", "no_such_method"], b"", 2, "or a path to a .zm file", ""),
        case(&["derive", "/dev/null"], b"", 2, "/dev/null:1:1: the file is empty", ""),
        case(&["derive", "{dir}"], b"", 2, "is a directory: expected a .zm file", ""),
        case(&["derive", "./false_euler"], b"", 2, "./false_euler: cannot read: No such file", ""),
        case(&["stability", "sub/false_euler"], b"", 2, "sub/false_euler: cannot read", ""),
        case(&["derive", "{file}"], b"", 2, "the file is empty", ":1:1:"),
        case(&["equiv", "false_euler", "{file}"], b"\xfe", 2, "invalid UTF-8", ":1:1:"),
        case(&["equiv", "no_such_method", "false_euler"], b"", 2, "no built-in method named `no_such_method`", ""),
    ]);
}

/// A hostile line neither floods the terminal nor drives it.
#[test]
#[rustfmt::skip]
fn flooding_and_control_characters() {
    let long = zm(&format!("v = v - Phi*y{} $ {}", " + 0*v".repeat(200), "+ v".repeat(300_000)));
    let name = zm(&format!("v = v - Phi*{}", "q".repeat(1_000_000)));
    let nul = zm("v = v - Phi*y\0\x1b[2J");
    check(&[
        case(&["derive", "{file}"], &long, 2, "unexpected character `$`", ":3:1215:"),
        case(&["derive", "{file}"], &long, 2, "…", ""),
        case(&["derive", "{file}"], &name, 2, "more characters", ":3:13:"),
        case(&["derive", "{file}"], &nul, 2, "unexpected character U+0000", ":3:14:"),
        case(&["derive", "{file}"], &nul, 2, "U+001B[2J", ""),
        case(&["derive", "{file}"], b"method m\nstate v y\nv = v\x1b]0;pwned\x07\n", 2, "U+001B", ":3:6:"),
    ]);
    let huge_arg = format!("D{}=1", "\u{1b}".repeat(100_000));
    let (_, err) = run(&["verify".into(), "false_euler".into(), "--param".into(), huge_arg], 2);
    assert!(err.contains("U+001B"), "{err}");
}

/// The messages of issue 14 say what was meant.
#[test]
#[rustfmt::skip]
fn clear_messages() {
    let bom_first = [b"\xef\xbb\xbf".as_slice(), poly::advanced::builtins::builtin_source("false_euler").unwrap().as_bytes()].concat();
    check(&[
        case(&["derive", "{file}"], &zm("v = v - 1.2.3*Phi*y"), 2, "malformed number `1.2.3`: expected at most one decimal point", ":3:9:"),
        case(&["derive", "{file}"], &zm("v = v - Phi^99999999999999999999*y"), 2, "exponent 99999999999999999999 is too large: expected at most 64", ":3:13:"),
        case(&["derive", "{file}"], &zm("v = v - Phi^(1/2)*y"), 2, "exponents are integer literals", ":3:15:"),
        case(&["derive", "{file}"], &zm("v = v - Phi^0.5*y"), 2, "exponents are integer literals", ":3:13:"),
        case(&["derive", "{file}"], &zm("v = v \u{2212} Phi*y"), 2, "U+2212 (a dash: write the ASCII minus `-`)", ":3:7:"),
        case(&["derive", "{file}"], &zm("v = v -\u{200b} Phi*y"), 2, "U+200B (a zero-width space)", ":3:8:"),
        case(&["derive", "{file}"], &zm("v = v - \u{feff}Phi*y"), 2, "U+FEFF (a byte-order mark)", ":3:9:"),
        case(&["derive", "{file}"], &bom_first, 0, "routes agree", ""),
        case(&["derive", "{file}"], b"method m\rstate v y\rv = v - Phi*y\r", 2, "carriage return U+000D", ":1:9:"),
        case(&["derive", "{file}"], b"method m\r\nstate v y\r\nv = v - Phi*y\r\ny = y + Phi*v\r\n", 0, "routes agree", ""),
        case(&["verify", "false_euler", "--phi", "1e308", "--steps", "10"], b"", 2, "Phi = 1e308", ""),
    ]);
}

/// A decimal typed on the command line is that decimal: D = 0.1 is 1/10,
/// so Φ_max of the damped standard Euler is 2D = 1/5 exactly, not a ratio
/// of 2^54-sized integers.
#[test]
fn command_line_decimals_are_exact() {
    let (out, _) =
        run(&["advise", "--freq", "2", "--tick", "60", "--damping", "0.1"].map(String::from), 0);
    assert!(!out.contains("18014398509481984"), "{out}");
    let euler = out.lines().find(|l| l.starts_with("standard_euler")).expect("row");
    assert!(euler.split_whitespace().nth(1) == Some("1/5"), "{euler}");
}

/// Writes to a closed pipe end the output quietly: no panic, and the exit
/// code the run would have had.
#[test]
fn closed_stdout() {
    let phis: Vec<String> = (1..=400).map(|k| format!("{}", f64::from(k) / 200.0)).collect();
    let phis = phis.join(",");
    for args in [
        vec!["derive", "false_euler"],
        vec!["methods"],
        vec!["overview", "false_euler"],
        vec!["stability", "false_heun", "--format", "json"],
        vec!["verify", "false_euler", "--steps", "0", "--format", "json", "--phi", &phis],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_zcheck"))
            .args(&args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("spawns");
        drop(child.stdout.take());
        let mut err = String::new();
        child.stderr.take().expect("stderr").read_to_string(&mut err).expect("reads");
        let status = child.wait().expect("waits");
        assert_eq!(status.code(), Some(0), "{args:?}: {err}");
        assert!(err.is_empty(), "{args:?}: {err}");
    }
}

/// A program of 10,000 chained temporaries derives to a document the size
/// of its program: M(z) is printed over the state (2 × 2 here), and the
/// full 10,002 × 10,002 matrix is refused with its size, while a small
/// program still prints it on request.
#[test]
fn derive_output_is_bounded() {
    let mut src = String::from("method chain\nstate y v\nt0 = y + Phi*v\n");
    for k in 1..10_000 {
        src += &format!("t{k} = t{}\n", k - 1);
    }
    src += "y = t9999\nv = v - Phi*y\n";
    let path = dir().join("chain_10000.zm");
    std::fs::write(&path, &src).expect("write chain");
    let path = path.to_str().expect("utf-8 path").to_owned();
    let (json, _) = run(&["derive".into(), path.clone(), "--format".into(), "json".into()], 0);
    // The program itself is ~200 KB; the old document was 1.1 GB.
    assert!(json.len() < 2 * src.len() + 4096, "{} bytes of JSON", json.len());
    let v: serde_json::Value = serde_json::from_str(&json).expect("derive JSON");
    assert_eq!(v["z_matrix_labels"], serde_json::json!(["y", "v"]));
    assert_eq!(v["z_matrix"].as_array().map(Vec::len), Some(2));
    assert_eq!(v["charpoly"], "z^2 - 2*z + Phi^2*z + 1");
    assert!(v.get("z_matrix_full").is_none());
    let (_, err) = run(&["derive".into(), path, "--full-z-matrix".into()], 2);
    assert!(err.contains("10002 rows, and prints at most 256"), "{err}");
    let (full, _) = run(
        &[
            "derive".into(),
            "standard_heun".into(),
            "--full-z-matrix".into(),
            "--format".into(),
            "json".into(),
        ],
        0,
    );
    let v: serde_json::Value = serde_json::from_str(&full).expect("derive JSON");
    assert_eq!(v["z_matrix_full"].as_array().map(Vec::len), Some(8));
    assert_eq!(v["z_matrix"].as_array().map(Vec::len), Some(2));
}
