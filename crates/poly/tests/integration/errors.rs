//! Every kind of bad `.zm` input gives an `Err` located at file:line:column,
//! with its kind and a message saying what was expected; and no input, valid
//! or not, makes the parser or the derivation panic.

use poly::{ErrorKind, Method};
use proptest::prelude::*;

/// The declarations most cases start from (lines 1–3).
const HEAD: &str = "method m\nstate v y\nparam D\n";

/// Parses `src` (as file `bad.zm`) and checks the error's kind, line, column,
/// that its message contains `says` and states what was expected, and that
/// the rendered error starts with `bad.zm:line:col:` and puts a caret under
/// the column.
#[track_caller]
pub(crate) fn check(src: &str, kind: ErrorKind, line: u32, col: u32, says: &str) {
    let err = match Method::parse("bad.zm", src) {
        Ok(m) => panic!("expected an error, parsed:\n{m}\nfrom:\n{src}"),
        Err(e) => e,
    };
    let shown = err.to_string();
    assert_eq!(err.kind(), kind, "{shown}");
    assert_eq!((err.span().line, err.span().col), (line, col), "{shown}");
    assert_eq!(err.file(), "bad.zm");
    assert!(err.message().contains(says), "message lacks {says:?}:\n{shown}");
    assert!(err.message().contains("expected"), "message does not say what was expected:\n{shown}");
    assert!(shown.starts_with(&format!("bad.zm:{line}:{col}: ")), "{shown}");
    let lines: Vec<&str> = shown.lines().collect();
    // The empty file has no line 1 to echo.
    let source_line = src.lines().nth(line as usize - 1).unwrap_or("");
    assert!(line == 1 || src.lines().nth(line as usize - 1).is_some(), "no line {line}");
    // Lines longer than the snippet are cut (`long_lines_and_names_are_cut`).
    if !source_line.trim().is_empty() && source_line.chars().count() <= 100 {
        // `N | text` then `  | ^^^` with the caret under column `col`.
        let text_row = lines.iter().position(|l| l.ends_with(source_line)).expect("source echoed");
        let caret_row = lines[text_row + 1];
        let bar = lines[text_row].find(" | ").expect("gutter") + 3;
        assert_eq!(caret_row.find('^'), Some(bar + col as usize - 1), "caret misplaced:\n{shown}");
    }
}

#[test]
fn unknown_names() {
    check(&format!("{HEAD}v = v - Phi*q\n"), ErrorKind::UnknownName, 4, 13, "unknown name `q`");
    check(&format!("{HEAD}v = v - u@1\n"), ErrorKind::UnknownName, 4, 9, "`u@1`");
    // `omega` is not Phi: the message lists what is defined.
    check(&format!("{HEAD}v = v - omega*y\n"), ErrorKind::UnknownName, 4, 9, "Phi, D");
}

#[test]
fn reading_a_temporary_before_it_is_assigned() {
    check(
        &format!("{HEAD}v = v - Phi*t\nt = y\n"),
        ErrorKind::ReadBeforeAssign,
        4,
        13,
        "`t` is read before it is assigned",
    );
    // Its own right-hand side does not count as an earlier assignment.
    check(&format!("{HEAD}t = t + v\n"), ErrorKind::ReadBeforeAssign, 4, 5, "`t`");
}

#[test]
fn nonlinear_terms() {
    check(&format!("{HEAD}v = v*y\n"), ErrorKind::Nonlinear, 4, 5, "nonlinear");
    check(&format!("{HEAD}v = v^2\n"), ErrorKind::Nonlinear, 4, 5, "power 2");
    check(&format!("{HEAD}v = (v + Phi*y)*(y - v)\n"), ErrorKind::Nonlinear, 4, 5, "nonlinear");
    // Through a temporary, and through history.
    check(&format!("{HEAD}t = Phi*v\n\ny = t*y@1\n"), ErrorKind::Nonlinear, 6, 5, "nonlinear");
}

#[test]
fn bad_divisions() {
    check(&format!("{HEAD}v = v/y\n"), ErrorKind::BadDivision, 4, 7, "state-dependent");
    check(&format!("{HEAD}v = v - y/Phi\n"), ErrorKind::BadDivision, 4, 11, "parameter");
    check(&format!("{HEAD}v = v - y/(1 + D)\n"), ErrorKind::BadDivision, 4, 11, "parameter");
    check(&format!("{HEAD}v = v/0\n"), ErrorKind::BadDivision, 4, 7, "division by zero");
    check(&format!("{HEAD}v = v/(2 - 4*0.5)\n"), ErrorKind::BadDivision, 4, 7, "division by zero");
}

#[test]
fn bad_powers() {
    check(&format!("{HEAD}v = Phi^0.5*v\n"), ErrorKind::BadPower, 4, 9, "integer exponent");
    check(&format!("{HEAD}v = Phi^y*v\n"), ErrorKind::BadPower, 4, 9, "integer exponent");
    check(&format!("{HEAD}v = Phi^-1*v\n"), ErrorKind::BadPower, 4, 9, "integer exponent");
    check(&format!("{HEAD}v = v*Phi^\n"), ErrorKind::BadPower, 4, 10, "integer exponent");
    check(&format!("{HEAD}v = Phi^65*v\n"), ErrorKind::BadPower, 4, 9, "too large");
}

#[test]
fn affine_terms() {
    check(&format!("{HEAD}v = v + 1\n"), ErrorKind::Affine, 4, 5, "does not depend on the state");
    check(&format!("{HEAD}y = y + Phi*v - D\n"), ErrorKind::Affine, 4, 5, "`-D`");
    // A state variable set to a parameter-only value is affine too.
    check(&format!("{HEAD}v = Phi\n"), ErrorKind::Affine, 4, 5, "does not depend on the state");
}

#[test]
fn declaration_errors() {
    use ErrorKind::Declaration as K;
    check("state v\nv = v\n", K, 1, 1, "missing `method NAME`");
    check("# nothing but a comment\n", K, 1, 1, "missing `method NAME`");
    check("method m\nv = v\n", K, 2, 1, "missing `state` line");
    check("method m\nparam D\n", K, 2, 1, "missing `state` line");
    check("method m\nstate v v\n", K, 2, 9, "declared twice");
    check("method m\nstate v\nparam v\n", K, 3, 7, "declared twice");
    check("method m\nmethod n\nstate v\n", K, 2, 8, "a second `method`");
    check("method m\nstate v\nstate y\n", K, 3, 1, "a second `state`");
    check(
        "method m\nstate v\nv = D*v\nparam D\n",
        K,
        3,
        5,
        "`D` is used before its declaration on line 4",
    );
    check("method m\nstate v\nPhi = v\n", K, 3, 1, "`Phi` is a parameter");
    check(&format!("{HEAD}D = v\n"), K, 4, 1, "`D` is a parameter");
    check("method m\nstate v\nparam Phi\n", K, 3, 7, "`Phi` is always a parameter");
    check("method m\nstate v z\n", K, 2, 9, "`z` is reserved");
    check("method m\nstate v\nz = v\n", K, 3, 1, "`z` is reserved");
}

#[test]
fn syntax_errors() {
    use ErrorKind::Syntax as K;
    check(&format!("{HEAD}v = v -\n"), K, 4, 8, "a number, a name or `(`");
    check(&format!("{HEAD}v = v * * y\n"), K, 4, 9, "a number, a name or `(`");
    check(&format!("{HEAD}v = (v - Phi*y\n"), K, 4, 15, "`)`");
    check(&format!("{HEAD}v = v - Phi*y)\n"), K, 4, 14, "the end of the line");
    check(&format!("{HEAD}v = v $ y\n"), K, 4, 7, "unexpected character `$`");
    check(&format!("{HEAD}v = v - Phi*y@\n"), K, 4, 15, "history depth");
    check(&format!("{HEAD}v = v - Phi*y@x\n"), K, 4, 15, "history depth");
    check(&format!("{HEAD}v = v - Phi*y@33\n"), K, 4, 15, "too deep");
    check(&format!("{HEAD}v = v - Phi@1*y\n"), K, 4, 9, "not a state variable");
    check(&format!("{HEAD}v v\n"), K, 4, 3, "`=`");
    check(&format!("{HEAD}= v\n"), K, 4, 1, "an assignment");
    check("method\nstate v\n", K, 1, 7, "the method's name");
    check("method m\nstate\n", K, 2, 6, "state variable names");
    check(&format!("{HEAD}v = 2.5e\n"), K, 4, 5, "digits after the exponent");
    check(&format!("{HEAD}v = 2Phi*v\n"), K, 4, 5, "runs into a name");
    check(&format!("{HEAD}v = state*v\n"), K, 4, 5, "keywords");
    let long = format!("{HEAD}v = v{}\n", " + v".repeat(600));
    check(&long, K, 4, 1, "line too long");
}

/// An error on a later line after blank lines and comments still points at
/// the right place.
#[test]
fn locations_count_blank_lines_and_comments() {
    let src = "# header\n\nmethod m   # name\nstate v y\n\n# the step\nv = v - Phi*y\ny = y + Phi*v*y   # oops\n";
    check(src, ErrorKind::Nonlinear, 8, 9, "nonlinear");
}

/// `Poly::parse` reports its errors with the same location scheme.
#[test]
fn polynomial_parse_errors_are_located() {
    let e = poly::Poly::parse("z^2 - 2*p*z + ").expect_err("dangling operator");
    assert_eq!(e.kind(), ErrorKind::Syntax);
    // Right after the trailing operator, not after the blank that follows.
    assert_eq!((e.span().line, e.span().col), (1, 14));
    assert!(e.to_string().starts_with("<expression>:1:14: expected"), "{e}");
    let e = poly::Poly::parse("1/(Phi - 1)").expect_err("division by a polynomial");
    assert_eq!(e.kind(), ErrorKind::BadDivision);
}

/// Random text over the language's alphabet and random edits of the
/// built-in sources: parsing returns Ok or Err and never panics, and every
/// program that parses derives with both routes agreeing.
mod fuzz {
    use super::*;

    const PIECES: &[&str] = &[
        "method",
        "state",
        "param",
        "m",
        "v",
        "y",
        "t",
        "D",
        "Phi",
        "z",
        "@",
        "@1",
        "@2",
        "0",
        "1",
        "2",
        "0.5",
        "1e3",
        ".25",
        "+",
        "-",
        "*",
        "/",
        "^",
        "^2",
        "(",
        ")",
        "=",
        "#",
        " ",
        " ",
        "\n",
        "\n",
        "$",
        "é",
        "\t",
        "\r\n",
        "99999999999",
    ];

    /// Parsing never panics, every error it returns has a line and a
    /// column (issue 27), and every program that parses derives.
    fn no_panic(src: &str) {
        match Method::parse("fuzz.zm", src) {
            Ok(m) => {
                poly::derive(&m).unwrap_or_else(|e| panic!("{e}\nfrom:\n{src:?}"));
            }
            Err(e) => {
                let (line, col) = (e.span().line, e.span().col);
                assert!(line >= 1 && col >= 1, "{line}:{col}: {e}\nfrom:\n{src:?}");
                assert!(line as usize <= src.lines().count().max(1), "{e}\nfrom:\n{src:?}");
            }
        }
        let _ = poly::Poly::parse(src);
    }

    fn edited_builtin() -> impl Strategy<Value = String> {
        let names: Vec<&'static str> = poly::advanced::builtins::builtin_names().collect();
        let edit = (any::<prop::sample::Index>(), 0usize..4, prop::sample::select(PIECES));
        (prop::sample::select(names), proptest::collection::vec(edit, 1..=4)).prop_map(
            |(name, edits)| {
                let mut chars: Vec<char> = poly::advanced::builtins::builtin_source(name)
                    .expect("built-in")
                    .chars()
                    .collect();
                for (at, what, piece) in edits {
                    let i = at.index(chars.len() + 1);
                    match what {
                        0 if i < chars.len() => {
                            chars.remove(i);
                        }
                        1 if i < chars.len() => chars[i] = piece.chars().next().unwrap_or(' '),
                        _ => {
                            for (k, c) in piece.chars().enumerate() {
                                chars.insert(i + k, c);
                            }
                        }
                    }
                }
                chars.into_iter().collect()
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(512))]

        #[test]
        fn random_token_soup_never_panics(
            pieces in proptest::collection::vec(prop::sample::select(PIECES), 0..40)
        ) {
            no_panic(&pieces.concat());
        }

        #[test]
        fn a_method_head_then_random_tokens_never_panics(
            pieces in proptest::collection::vec(prop::sample::select(PIECES), 0..30)
        ) {
            no_panic(&format!("{HEAD}v = {}\n", pieces.concat()));
        }

        #[test]
        fn arbitrary_strings_never_panic(s in "\\PC{0,80}") {
            no_panic(&s);
        }

        #[test]
        fn edited_builtins_never_panic(src in edited_builtin()) {
            no_panic(&src);
        }
    }
}

/// Hostile text gets a located error that says what was meant (issue 14).
#[test]
#[rustfmt::skip]
fn hostile_text() {
    use ErrorKind::{BadPower, Declaration, Singular, Syntax};
    check(&format!("{HEAD}v = v - 1.2.3*Phi*y\n"), Syntax, 4, 9, "malformed number `1.2.3`");
    // The empty file, and files of nothing but blanks or a comment, at 1:1.
    check("", Declaration, 1, 1, "missing `method NAME` line");
    check("\n\n", Declaration, 1, 1, "missing `method NAME` line");
    check("  \t ", Declaration, 1, 1, "missing `method NAME` line");
    // A trailing operator before a comment or blanks: the column is right
    // after the operator, where the missing operand goes (issue 27).
    check(&format!("{HEAD}v = v - Phi*y*  # the step\n"), Syntax, 4, 15, "a number, a name or `(`");
    check(&format!("{HEAD}v = v - Phi*y*    \n"), Syntax, 4, 15, "a number, a name or `(`");
    check(&format!("{HEAD}v = (v - Phi*y   # unclosed\n"), Syntax, 4, 15, "`)`");
    // A system singular for every Φ is located on the equation that makes
    // it singular (the second), not the first (more in `implicit.rs`).
    check("method m\nstate v y\nunknown a b\na = 2*b + v\nb = a/2 + Phi*y\nv = v + a\n", Singular, 5, 1, "singular for every Phi");
    // Chains of 10,000 temporaries derive in tens of milliseconds: see
    // `large::chains_of_10_000_temporaries_derive_their_short_programs` and
    // the bench `chain/temporaries_10000` (no timed tests).
    check("method   # no name\nstate v\n", Syntax, 1, 7, "the method's name");
    check(&format!("{HEAD}v = v - Phi^99999999999999999999*y\n"), BadPower, 4, 13, "exponent 99999999999999999999 is too large");
    check(&format!("{HEAD}v = v - Phi^(1/2)*y\n"), Syntax, 4, 15, "exponents are integer literals");
    check(&format!("{HEAD}v = v - Phi^0.5*y\n"), BadPower, 4, 13, "exponents are integer literals");
    check(&format!("{HEAD}v = v \u{2212} Phi*y\n"), Syntax, 4, 7, "U+2212 (a dash");
    check(&format!("{HEAD}v = v - {}*y\n", "1".repeat(1001)), Syntax, 4, 9, "number too long");
    check(&format!("{HEAD}v = v - 1e99999999999999999999*y\n"), Syntax, 4, 9, "exponent too large");
    check(&format!("{HEAD}v = v - 1e1001*y\n"), Syntax, 4, 9, "exponent too large");
}

/// Invisible and control characters: located, named by code point, and
/// shown as `U+XXXX` in the echoed line too, with the caret under them.
#[track_caller]
fn check_invisible(src: &str, line: u32, col: u32, says: &str, echoed: &str) {
    let err = Method::parse("bad.zm", src).expect_err("an error");
    let shown = err.to_string();
    assert_eq!((err.span().line, err.span().col), (line, col), "{shown}");
    assert!(err.message().contains(says), "{shown}");
    assert!(!shown.chars().any(|c| c.is_control() && c != '\n'), "{shown:?}");
    let lines: Vec<&str> = shown.lines().collect();
    let text_row = lines.iter().position(|l| l.ends_with(echoed)).expect("line echoed");
    let caret = lines[text_row + 1].find('^').expect("caret");
    let bar = lines[text_row].find(" | ").expect("gutter") + 3;
    let upto = &lines[text_row][bar..];
    let target = upto.find("U+").map_or(col as usize - 1, |k| upto[..k].chars().count());
    assert_eq!(caret - bar, target, "caret:\n{shown}");
}

#[test]
#[rustfmt::skip]
fn invisible_characters() {
    check_invisible(&format!("{HEAD}v = v - Phi*y\0\n"), 4, 14, "U+0000", "v = v - Phi*yU+0000");
    check_invisible(&format!("{HEAD}v = v\u{1b}[2J\n"), 4, 6, "U+001B", "v = vU+001B[2J");
    check_invisible(&format!("{HEAD}v = v -\u{200b} Phi*y\n"), 4, 8, "U+200B (a zero-width space)", "v = v -U+200B Phi*y");
    check_invisible(&format!("{HEAD}v = \u{feff}v\n"), 4, 5, "U+FEFF (a byte-order mark)", "v = U+FEFFv");
    check_invisible(&format!("{HEAD}v = v\u{202e} - y\n"), 4, 6, "U+202E", "v = vU+202E - y");
    check_invisible("method m\rstate v y\rv = v\r", 1, 9, "carriage return U+000D", "method mU+000Dstate v yU+000Dv = vU+000D");
}

/// A byte-order mark first in the file and CRLF line endings are accepted.
#[test]
fn bom_and_crlf_are_accepted() {
    let src = poly::advanced::builtins::builtin_source("false_euler").unwrap();
    let with_bom = format!("\u{feff}{src}");
    let crlf = src.replace('\n', "\r\n");
    for text in [with_bom, crlf] {
        let m = Method::parse("ok.zm", &text).expect("parses");
        assert_eq!(
            poly::advanced::charpoly(&m).unwrap(),
            poly::advanced::charpoly(&poly::builtin("false_euler").unwrap()).unwrap()
        );
    }
}

/// Bytes that are not UTF-8 are located at the first bad byte.
#[test]
fn invalid_utf8_is_located() {
    for (bytes, line, col) in [
        (b"method m\nstate v y\nv = v - Phi*\xff y\n".as_slice(), 3, 13),
        (b"\xc3".as_slice(), 1, 1),
        (b"method \xe2\x82\n".as_slice(), 1, 8),
        (b"method m\n\n\nstate v\xf0\x9f\x98 y\n".as_slice(), 4, 8),
    ] {
        let e = Method::parse_bytes("bad.zm", bytes).expect_err("not UTF-8");
        assert_eq!(e.kind(), ErrorKind::Encoding);
        assert_eq!((e.span().line, e.span().col), (line, col), "{e}");
        assert!(e.to_string().starts_with(&format!("bad.zm:{line}:{col}: invalid UTF-8")), "{e}");
    }
}

/// A very long line is cut to about 100 characters around the column, and
/// a very long message (a 1 MB name) to 1000 characters: the whole error
/// stays under 4 KB.
#[test]
fn long_lines_and_names_are_cut() {
    let long = format!("{HEAD}v = v{} $ {}\n", " + v".repeat(200), "+ v".repeat(300_000));
    let e = Method::parse("bad.zm", &long).expect_err("bad character");
    assert_eq!((e.span().line, e.span().col), (4, 807));
    let shown = e.to_string();
    assert!(shown.len() < 600, "{} bytes", shown.len());
    assert!(shown.contains("… $ +") || shown.contains(" $ +"), "{shown}");
    let name = format!("{HEAD}v = v - Phi*{}\n", "q".repeat(1_000_000));
    let e = Method::parse("bad.zm", &name).expect_err("unknown name");
    assert!(e.to_string().len() < 4000, "{} bytes", e.to_string().len());
}

/// An unknown built-in says so, without a `:0:0:` location.
#[test]
fn unknown_builtin_has_no_fake_location() {
    let e = poly::builtin("no_such").expect_err("unknown");
    assert_eq!(e.kind(), ErrorKind::UnknownBuiltin);
    let shown = e.to_string();
    assert!(shown.starts_with("no built-in method named `no_such`: expected one of"), "{shown}");
    assert!(shown.contains("false_euler") && shown.ends_with("or a path to a .zm file"), "{shown}");
}

/// The command-line number reader is the `.zm` lexer's: exact decimals,
/// fractions and signs; everything else a located error.
#[test]
fn numbers_typed_on_the_command_line() {
    let ok = |s: &str, n: i64, d: i64| {
        assert_eq!(poly::advanced::parse_number(s).unwrap(), poly::q(n, d), "{s}")
    };
    ok("0.1", 1, 10);
    ok(".5", 1, 2);
    ok("-1/2", -1, 2);
    ok("+3", 3, 1);
    ok("2.5e-3", 1, 400);
    ok("1e6", 1_000_000, 1);
    ok("1.5/0.5", 3, 1);
    assert_eq!(
        poly::advanced::parse_number("1e-300").unwrap(),
        poly::Q::new(1.into(), num_traits::pow(num_bigint::BigInt::from(10), 300))
    );
    let bad = |s: &str, col: u32, says: &str| {
        let e = poly::advanced::parse_number(s).expect_err(s);
        assert_eq!(e.span().col, col, "{s}: {e}");
        assert!(e.message().contains(says), "{s}: {e}");
    };
    bad("1.2.3", 1, "malformed number `1.2.3`");
    bad("", 1, "expected a number");
    bad("-", 2, "expected a number");
    bad("abc", 1, "expected a number");
    bad("1/0", 3, "division by zero");
    bad("1/", 3, "expected a number");
    bad("1x", 1, "runs into a name");
    bad("1 2", 2, "expected nothing more");
    bad("1e", 1, "digits after the exponent");
    bad("0x10", 1, "runs into a name");
    bad("\u{2212}1", 1, "U+2212");
    bad("inf", 1, "expected a number");
    bad("NaN", 1, "expected a number");
}
