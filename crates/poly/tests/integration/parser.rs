//! Details of the expression language: exact decimals, comments, powers,
//! the precedence of unary minus, and history reads.

use poly::advanced::Operand;
use poly::{Method, Poly};

/// `text` (a polynomial expression) parses to the same polynomial as
/// `same_as`.
#[track_caller]
fn check(text: &str, same_as: &str) {
    let got = Poly::parse(text).unwrap_or_else(|e| panic!("{e}"));
    let want = Poly::parse(same_as).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(got, want, "{text} vs {same_as}");
}

#[test]
fn decimals_are_exact() {
    check("0.5", "1/2");
    check("0.1 + 0.2", "3/10");
    check("2.5e-3", "1/400");
    check("2.5E+2", "250");
    check(".25*Phi", "Phi/4");
    check("1e3", "1000");
    check("0.333", "333/1000");
    check("1.", "1");
}

#[test]
fn powers() {
    check("Phi^(2)", "Phi*Phi");
    check("(1 - Phi)^3", "1 - 3*Phi + 3*Phi^2 - Phi^3");
    check("Phi^0", "1");
    check("2^10", "1024");
}

#[test]
fn unary_minus_binds_looser_than_power() {
    check("-Phi^2", "-(Phi^2)");
    check("-2^2", "-4");
    check("--Phi", "Phi");
    check("-Phi*D", "-(Phi*D)");
    check("2*-Phi", "-2*Phi");
    check("+Phi - -D", "Phi + D");
}

#[test]
fn operators_associate_to_the_left() {
    check("8/2/2", "2");
    check("1 - 2 - 3", "-4");
    check("Phi/2*D", "(Phi*D)/2");
}

#[test]
fn comments_blank_lines_and_whitespace_are_ignored() {
    let plain = Method::parse("a.zm", "method m\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n");
    let noisy = Method::parse(
        "b.zm",
        "# leading comment\n\n  method m # trailing\n\tstate  v   y\r\n\n   v=v-Phi *y#no space\ny = y + Phi*v   \n# end",
    );
    assert_eq!(plain.map(|m| m.to_string()), noisy.map(|m| m.to_string()));
}

/// `y@0` is the start value even after `y` has been updated in this step,
/// while a bare `y` then reads the new value.
#[test]
fn history_zero_is_the_start_value() {
    let m = Method::parse("h.zm", "method h\nstate y\ny = 2*y\ny = y + y@0\n").expect("parses");
    let last = &m.assigns()[1];
    let ops: Vec<Operand> = last.terms.iter().map(|(op, _)| *op).collect();
    assert!(ops.contains(&Operand::Stmt(0)), "bare y reads the new value: {m}");
    assert!(ops.contains(&Operand::Start { var: 0, lag: 0 }), "y@0 reads the start value: {m}");
    assert_eq!(m.history(), &[0]);
    assert_eq!(m.state_size(), 1);
    // y_next = 2y + y = 3y.
    let d = poly::derive(&m).expect("derives");
    assert_eq!(*d.charpoly(), Poly::parse("z - 3").expect("parses"));
}

/// A temporary that depends on the parameters only is folded into the
/// coefficients that read it (Appendix B's `D:=0.5*woT`).
#[test]
fn parameter_only_temporaries_fold() {
    let folded =
        Method::parse("a.zm", "method m\nstate v y\nk = 0.5*Phi\nv = v - k*y\n").expect("parses");
    let direct = Method::parse("b.zm", "method m\nstate v y\nv = v - Phi/2*y\n").expect("parses");
    let lowered = |m: &Method| -> Vec<_> {
        m.assigns().iter().map(|a| (a.target.clone(), a.terms.clone())).collect()
    };
    assert_eq!(lowered(&folded), lowered(&direct));
}

/// The lowered listing shows operands by name and subtraction as such.
#[test]
fn lowered_listing() {
    let m = poly::builtin("verlet").expect("built-in");
    insta::assert_snapshot!(m.to_string(), @r"
    method verlet
    state y
    param Phi
    %0 (y) = (2 - Phi^2)*y - y@1
    ");
}
