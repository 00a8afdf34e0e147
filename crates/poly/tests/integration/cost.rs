//! Operations per step (`poly::advanced::cost`): the paper's "two multiplications and
//! two additions" and the counting model's rules, one concern per checker.
//!
//! Expected counts are read off the `.zm` sources line by line (the comment
//! beside each row says how), not copied from the program's output.

use poly::advanced::builtins::builtin_names;
use poly::advanced::builtins::direct_twin;
use poly::advanced::cost::step_cost;
use poly::advanced::cost::{combination_cost, matrix_cost};
use poly::{builtin, Method, OpCount, Poly};

fn ops(mul: u32, add: u32, copy: u32) -> OpCount {
    OpCount { mul, add, copy }
}

#[track_caller]
fn check_program(name: &str, expected: OpCount) {
    let m = builtin(name).expect("built-in");
    assert_eq!(step_cost(&m).program, expected, "{name}: program cost");
}

#[track_caller]
fn check_matrix_form(name: &str, expected: OpCount) {
    let m = builtin(name).expect("built-in");
    assert_eq!(step_cost(&m).matrix_form, expected, "{name}: transition-matrix form cost");
}

#[track_caller]
fn check_source(src: &str, expected: OpCount) {
    let m = Method::parse("t.zm", src).expect("valid method");
    assert_eq!(step_cost(&m).program, expected, "{src}");
}

/// Section 8: "both methods need two multiplications and two additions per
/// step". False Euler does; Verlet's folded step needs only one of each.
#[test]
fn paper_section_8_claim() {
    // v = v - Phi*y; y = y + Phi*v: one product and one sum per line.
    check_program("false_euler", ops(2, 2, 0));
    // y = 2*y - y@1 - Phi^2*y folds to (2 - Phi^2)*y - y@1, plus the shift y@1 <- y.
    check_program("verlet", ops(1, 1, 1));
}

/// The direct programs of Appendix B, counted line by line.
#[test]
fn direct_programs() {
    // v1 = v - Phi*y (1m 1a); y = y + Phi*v (1m 1a); v = v1 (copy).
    check_program("standard_euler", ops(2, 2, 1));
    // v1 = (1 - Phi^2)*v - Phi*y (2m 1a) once D = Phi/2 folds; y = y + Phi*v; v = v1.
    check_program("damped_euler", ops(3, 2, 1));
    // dv1, dy1, dv2, dy2: 4m; v11, y11: 2a; v, y = x + 0.5*(a + b): 1m 2a each.
    check_program("standard_heun", ops(6, 6, 0));
    // As Standard Heun plus v12 = v + dv2 (1a).
    check_program("false_heun", ops(6, 7, 0));
    // As False Heun, but v11 = v + dv1 is never read (dy1 reads the old v): dead.
    check_program("semi_false_heun", ops(6, 6, 0));
    // The transition-matrix branches: each row a*v + b*y with a, b not +-1.
    check_program("false_euler_matrix", ops(3, 2, 1));
    check_program("standard_heun_matrix", ops(4, 2, 1));
    check_program("false_heun_matrix", ops(4, 2, 1));
    check_program("semi_false_heun_matrix", ops(4, 2, 1));
}

/// The transition matrix applied directly: P's rows, one combination each.
#[test]
fn matrix_forms() {
    // P = [1, -Phi; Phi, 1 - Phi^2].
    check_matrix_form("false_euler", ops(3, 2, 0));
    // P = [2 - Phi^2, -1; 1, 0]: the second row is the shift.
    check_matrix_form("verlet", ops(1, 1, 1));
    // P = [1 - Phi^2/2, -Phi; Phi, 1 - Phi^2/2].
    check_matrix_form("standard_heun", ops(4, 2, 0));
}

/// Appendix B writes each method twice; the hand-written "Transition matrix"
/// branch costs what `matrix_cost` computes from the derived P (copies
/// aside: the branch writes through a temporary).
#[test]
fn matrix_twins_cost_what_the_derived_matrix_costs() {
    for name in builtin_names() {
        let Some(direct) = direct_twin(name) else { continue };
        let twin = step_cost(&builtin(name).unwrap()).program;
        let derived = step_cost(&builtin(direct).unwrap()).matrix_form;
        assert_eq!((twin.mul, twin.add), (derived.mul, derived.add), "{name} vs {direct}");
    }
}

/// The model's rules: what is free and what is shared.
#[test]
fn folding_rules() {
    let head = "method t\nstate v y\n";
    // Multiplication by +-1 is free, written or not.
    check_source(&format!("{head}v = 1*v - 1*Phi*y\ny = y + Phi*v\n"), ops(2, 2, 0));
    // Equal coefficients up to sign share one multiplication.
    check_source(&format!("{head}v = 0.5*v + 0.5*y\n"), ops(1, 1, 0));
    check_source(&format!("{head}v = 0.5*v - 0.5*y\n"), ops(1, 1, 0));
    check_source(&format!("{head}v = 0.5*(v + y)\n"), ops(1, 1, 0));
    // Powers of Phi are precomputed: Phi^3*y is one multiplication.
    check_source(&format!("{head}v = v - Phi^3*y\n"), ops(1, 1, 0));
    // Parameter-only temporaries fold away.
    check_source(&format!("{head}k = Phi*Phi/2\nv = v - k*y\n"), ops(1, 1, 0));
    // A negation cannot hide in a register; a plain copy is no arithmetic.
    check_source(&format!("{head}v = -y\n"), ops(0, 1, 0));
    check_source(&format!("{head}v = -y - v\n"), ops(0, 2, 0));
    check_source(&format!("{head}t = y\nv = t\n"), ops(0, 0, 2));
    // Dead code costs nothing: the temporary t is never read.
    check_source(&format!("{head}t = Phi*y + v\nv = v - Phi*y\n"), ops(1, 1, 0));
    // 2*y and Phi*y@2 are products; each history slot read costs one shift per step.
    check_source("method t\nstate y\ny = 2*y - y@1 + Phi*y@2\n", ops(2, 2, 2));
}

/// `combination_cost` and `matrix_cost` directly, on hand-built input.
#[test]
fn combinations() {
    let p = |s: &str| Poly::parse(s).unwrap();
    let phi = p("Phi");
    assert_eq!(combination_cost([]), ops(0, 0, 0));
    assert_eq!(combination_cost([&p("1"), &p("-Phi"), &p("Phi")]), ops(1, 2, 0));
    assert_eq!(combination_cost([&phi, &p("Phi^2")]), ops(2, 1, 0));
    let identity = poly::PolyMatrix::identity(3);
    assert_eq!(matrix_cost(&identity), ops(0, 0, 0));
}

/// The display is what `zcheck tradeoff` prints.
#[test]
fn display() {
    assert_eq!(ops(2, 2, 0).to_string(), "2 mul + 2 add");
    assert_eq!(ops(1, 1, 1).to_string(), "1 mul + 1 add + 1 copy");
    assert_eq!(ops(0, 0, 3).to_string(), "0 mul + 0 add + 3 copies");
}
