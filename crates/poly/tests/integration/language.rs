//! The language as users write it (issue 27): declarations anywhere before
//! the first use of their names, `const` lines with any exact constant
//! expression, and equations linear in the unknowns with unknowns on either
//! side. Each form derives what the form it replaces derives, and each
//! misuse is a located error.

use poly::advanced::builtins::builtin_source;
use poly::{ErrorKind, Method, Poly, Sym};

use crate::errors::check;

fn parse(src: &str) -> Method {
    Method::parse("test.zm", src).unwrap_or_else(|e| panic!("{e}\nfrom:\n{src}"))
}

fn derive(src: &str) -> poly::Derivation {
    poly::derive(&parse(src)).unwrap_or_else(|e| panic!("{e}\nfrom:\n{src}"))
}

/// `a` and `b` derive the same χ and the same P (over its denominator).
#[track_caller]
fn same_method(a: &str, b: &str) {
    let (da, db) = (derive(a), derive(b));
    assert_eq!(da.charpoly, db.charpoly, "\n{a}\nvs\n{b}");
    assert_eq!(da.p_denominator, db.p_denominator, "\n{a}\nvs\n{b}");
    assert_eq!(da.transition_matrix, db.transition_matrix, "\n{a}\nvs\n{b}");
}

// ---- Declarations anywhere before the first use ----

/// SDIRK2 with its scalar temporary `g` first and the `const` and
/// `unknown` lines after it, each just before its first use: the order
/// that "declaration after an assignment" used to refuse.
#[test]
fn a_temporary_may_come_before_the_unknown_and_const_lines() {
    let moved = "method sdirk2\nstate v y\n\
                 const r = sqrt(2)\n\
                 g = 1 - 1/r\n\
                 unknown k1v k1y\n\
                 k1v = -(y + Phi*g*k1y)\n\
                 k1y =   v + Phi*g*k1v\n\
                 unknown k2v k2y\n\
                 k2v = -(y + Phi*((1 - g)*k1y + g*k2y))\n\
                 k2y =   v + Phi*((1 - g)*k1v + g*k2v)\n\
                 v = v + Phi*((1 - g)*k1v + g*k2v)\n\
                 y = y + Phi*((1 - g)*k1y + g*k2y)\n";
    same_method(moved, builtin_source("sdirk2").unwrap());
    // A parameter declared last, after the lines that do not read it, and
    // the state line after a temporary that reads only Phi.
    let late = "method fe\nh = Phi/2\nstate v y\nv = v - 2*h*y\ny = y + Phi*v\nparam D\n";
    assert_eq!(derive(late).charpoly, derive(builtin_source("false_euler").unwrap()).charpoly);
    assert_eq!(parse(late).params().len(), 2);
}

/// A name used before its declaration is an error at the use, whatever
/// the declaration.
#[test]
#[rustfmt::skip]
fn a_name_used_before_its_declaration_is_located_at_the_use() {
    use ErrorKind::Declaration as K;
    check("method m\nt = v\nstate v y\nv = t\n", K, 2, 5, "`v` is used before its declaration on line 3");
    check("method m\nv = y\nstate v y\n", K, 2, 1, "`v` is used before its declaration on line 3");
    check("method m\nstate v y\nv = v - D*y\nparam D\n", K, 3, 9, "`D` is used before its declaration on line 4");
    check("method m\nstate v y\nv = v - c*y\nconst c = 1/2\n", K, 3, 9, "`c` is used before its declaration on line 4");
    check("method m\nstate v y\nk = y\nunknown k\nv = v + k\n", K, 3, 1, "`k` is used before its declaration on line 4");
    check("method m\nx = y@1\nstate v y\n", K, 2, 5, "`y` is used before its declaration on line 3");
    check("method m\nv' = v\nstate v y\n", K, 2, 1, "`v` is used before its declaration on line 3");
    check("method m\nstate v y\nconst a = b + 1\nconst b = 2\n", K, 3, 11, "`b` is used before its declaration on line 4");
    check("method m\nstate v y\nconst a = a + 1\n", K, 3, 11, "`a` is used in its own declaration");
    // The `method` line still comes first, and names are declared once.
    check("state v\nmethod m\n", K, 1, 1, "missing `method NAME` line: expected it before `state`");
    check("method m\nstate v y\nv = v\nparam v\n", K, 4, 7, "declared twice");
}

// ---- Constant expressions ----

/// `const` takes any exact constant expression, and a constant reads as
/// its value written inline.
#[test]
fn constants_are_exact_expressions() {
    let inline = "method m\nstate v y\nv = v - 1/12*Phi*y\ny = y + (3 + 2*(1/12))*Phi*v\n";
    let named = "method m\nstate v y\nconst beta = 1/12\nconst g = 3 + 2*beta\n\
                 v = v - beta*Phi*y\ny = y + g*Phi*v\n";
    same_method(inline, named);
    // (3 + √3)/6, the two-stage SDIRK's γ of order 3, is a root of
    // 6γ² − 6γ + 1.
    let m = parse("method m\nstate v y\nconst g = (3 + sqrt(3))/6\nv = v - g*Phi*y\n");
    let g = &m.constants()[0].value;
    let s3 = Poly::sym(poly::advanced::field::generator(3, 2));
    assert_eq!(*g, &Poly::constant(poly::q(1, 2)) + &s3.scale(&poly::q(1, 6)));
    let six = |p: &Poly| p.scale(&poly::q(6, 1));
    let zero = &(&six(&poly::advanced::field::reduce(&(g * g))) - &six(g)) + &Poly::one();
    assert!(poly::advanced::field::reduce(&zero).is_zero(), "{zero}");
    assert!(m.constants()[0].radical().is_none());
    // Forest–Ruth's θ = 1/(2 − ∛2) as a constant: θ·(2 − ∛2) = 1 exactly,
    // and the method is the built-in, which folds θ in a temporary.
    let fr = builtin_source("forest_ruth").unwrap().replace(
        "const c = cbrt(2)\nt = 1/(2 - c)                     # theta, exact in Q(cbrt(2))\n",
        "const c = cbrt(2)\nconst t = 1/(2 - c)\n",
    );
    assert!(fr.contains("const t = 1/(2 - c)"), "{fr}");
    same_method(&fr, builtin_source("forest_ruth").unwrap());
    let m = parse(&fr);
    let theta = &m.constants()[1].value;
    let c = Poly::sym(poly::advanced::field::generator(2, 3));
    assert!(poly::advanced::field::reduce(&(theta * &(&Poly::int(2) - &c))).is_one());
}

/// The lowered listing shows a rational constant as its value and a
/// radical with its minimal polynomial, as before.
#[test]
fn constants_in_the_lowered_listing() {
    let shown = parse(
        "method m\nstate v y\nconst b = 1/12\nconst r = 2*sqrt(3)\nconst n = -cbrt(2)\n\
         const g = (3 + sqrt(3))/6\nv = v - (b + r + n + g)*Phi*y\n",
    )
    .to_string();
    assert!(shown.contains("const b = 1/12\n"), "{shown}");
    assert!(shown.contains("const r = 2*sqrt(3) (minimal polynomial x^2 - 12)\n"), "{shown}");
    assert!(shown.contains("const n = -cbrt(2) (minimal polynomial x^3 + 2)\n"), "{shown}");
    assert!(shown.contains("const g = 1/2 + 1/6*sqrt(3)\n"), "{shown}");
}

#[test]
#[rustfmt::skip]
fn what_a_constant_may_not_be() {
    use ErrorKind::{BadConstant, BadDivision, UnknownName};
    let c = |rhs: &str| format!("method m\nstate v y\nconst c = {rhs}\nv = v - c*y\n");
    check(&c("Phi/2"), BadConstant, 3, 11, "`Phi` is a parameter: expected an exact constant");
    check(&c("v + 1"), BadConstant, 3, 11, "`v` is a state variable");
    check(&c("y@1"), BadConstant, 3, 11, "`y@1` is a past value");
    check(&c("2*y'"), BadConstant, 3, 13, "`y'` is an end-of-step value");
    check(&c("q + 1"), UnknownName, 3, 11, "unknown name `q`");
    check(&c("1/(sqrt(2) - sqrt(2))"), BadDivision, 3, 13, "division by zero");
    check(&c("1/(1 - 2*0.5)"), BadDivision, 3, 13, "division by zero");
    check(&c("exp(2) + 1"), BadConstant, 3, 11, "unknown function name `exp`");
    check(&c("1 + sqrt(0)"), BadConstant, 3, 20, "not a positive integer");
    // Root functions belong in `const` lines.
    check("method m\nstate v y\nv = v - sqrt(2)*Phi*y\n", BadConstant, 3, 9, "outside a `const` line");
}

// ---- Equations linear in the unknowns ----

/// The trapezoidal rule with every unknown moved to the left: the same
/// system, so the same χ, P and det A.
#[test]
fn unknowns_may_stand_on_either_side() {
    let moved = "method trapezoidal\nstate v y\n\
                 v' + Phi*y'/2 = v - Phi*y/2\n\
                 y' - Phi*v'/2 = y + Phi*v/2\n";
    same_method(moved, builtin_source("trapezoidal").unwrap());
    // Unknowns on both sides, and an equation written backwards: its row of
    // A is ∂(lhs − rhs)/∂u as written, here the negative of the rule's, so
    // det A and χ change sign and P does not.
    let both = "method trapezoidal\nstate v y\n\
                2*v' + Phi*y = v' + v - Phi*y'/2 - Phi*y/2 + Phi*y\n\
                y + Phi*(v + v')/2 = y'\n";
    let (d, trap) = (derive(both), derive(builtin_source("trapezoidal").unwrap()));
    assert_eq!(d.charpoly, -&trap.charpoly);
    assert_eq!(d.p_denominator, -&trap.p_denominator);
    assert_eq!(d.transition_matrix, trap.transition_matrix.map(|p| -p));
    // A declared unknown in a general equation.
    let k = "method be\nstate v y\nunknown k\n2*k = k - y - Phi*v\nv = v + Phi*k\ny = y + Phi*v\n";
    let solved = "method be\nstate v y\nunknown k\nk = -y - Phi*v\nv = v + Phi*k\ny = y + Phi*v\n";
    same_method(k, solved);
}

/// Generalized-α (Chung and Hulbert) on y'' = −y with ρ∞ = 4/5: the
/// acceleration equation (1 − α_m) a' + α_m a = −((1 − α_f) y' + α_f y)
/// as written, against the same method with a' solved by hand. The system
/// is the same up to that row's factor 1 − α_m, so χ is (1 − α_m) times
/// the hand-solved χ and P is the same; the method is unconditionally
/// stable.
#[test]
fn generalized_alpha_needs_no_solving_by_hand() {
    let consts = "const rho = 4/5\n\
                  const am = (2*rho - 1)/(rho + 1)\n\
                  const af = rho/(rho + 1)\n\
                  const gam = 1/2 - am + af\n\
                  const beta = (1 - am + af)^2/4\n";
    let updates = "y' = y + Phi*v + Phi^2*((1/2 - beta)*a + beta*a')\n\
                   v' = v + Phi*((1 - gam)*a + gam*a')\n";
    let written = format!(
        "method galpha\nstate y v a\n{consts}{updates}(1 - am)*a' + am*a = -((1 - af)*y' + af*y)\n"
    );
    let by_hand = format!(
        "method galpha\nstate y v a\n{consts}{updates}a' = -((1 - af)*y' + af*y + am*a)/(1 - am)\n"
    );
    let (w, h) = (derive(&written), derive(&by_hand));
    let factor = poly::q(2, 3); // 1 − α_m with α_m = 1/3
    assert_eq!(w.charpoly, h.charpoly.scale(&factor));
    assert_eq!(w.p_denominator, h.p_denominator.scale(&factor));
    // P = transition_matrix / p_denominator is the same.
    for i in 0..3 {
        for j in 0..3 {
            let (pw, ph) = (&w.transition_matrix[(i, j)], &h.transition_matrix[(i, j)]);
            assert_eq!(pw * &h.p_denominator, ph * &w.p_denominator, "P[{i}][{j}]");
        }
    }
    let report = w.stability(&poly::Params::new()).expect("analysed");
    assert!(report.bounded_for_all(), "{:?}", report.stability);
}

/// The k-th equation that does not name its unknown fills the row of the
/// k-th unknown by name, so reordering declarations keeps det A, and χ.
#[test]
fn general_equations_take_the_unknowns_by_name() {
    let system = "a + b = v\na - 2*b = y\nv = v + Phi*a\ny = y - Phi*b\n";
    let ab = derive(&format!("method m\nstate v y\nunknown a b\n{system}"));
    let ba = derive(&format!("method m\nstate v y\nunknown b a\n{system}"));
    assert_eq!(ab.charpoly, ba.charpoly);
    // det [[1, 1], [1, −2]] = −3: the first equation fills a's row.
    assert_eq!(ab.p_denominator, Poly::int(-3));
    let swapped = derive(&format!("method m\nstate y v\nunknown b\nunknown a\n{system}"));
    assert_eq!(swapped.charpoly, ab.charpoly);
    let z = Sym::z();
    assert_eq!(ab.charpoly.degree_in(z), 2);
}

#[test]
#[rustfmt::skip]
fn misused_equations_are_located() {
    use ErrorKind::{Affine, BadDivision, Equation, Nonlinear};
    const H: &str = "method m\nstate v y\n";
    check(&format!("{H}2*v = y\n"), Equation, 3, 1, "this equation holds no unknown");
    check(&format!("{H}v@1 = y\n"), Equation, 3, 1, "holds no unknown");
    check(&format!("{H}v' + y' = v\nv' - y' = y\nv' = v\n"), Equation, 5, 1, "one equation too many: the 2 unknown(s) (v', y') already have 2 equation(s) above (line(s) 3, 4)");
    check(&format!("{H}v' = v\ny' = y\nv' + y' = v + y\n"), Equation, 5, 1, "one equation too many: the 2 unknown(s) (v', y')");
    check(&format!("{H}v' + Phi*y' = v\n"), Equation, 3, 10, "`y'` is read but `y` has no equation");
    check(&format!("{H}unknown a b\na + b = v\nv = v + a\n"), Equation, 3, 11, "unknown `b` has no equation");
    check(&format!("{H}v' + y' = v + 1\ny' = y\n"), Affine, 3, 1, "term `1` does not depend on the state");
    check(&format!("{H}v'*y' = v\ny' = y\n"), Nonlinear, 3, 1, "nonlinear term");
    check(&format!("{H}v'/y' = v\ny' = y\n"), BadDivision, 3, 4, "state-dependent");
    check(&format!("{H}v' + y' = v\ny' = y\nv = y\n"), Equation, 5, 1, "`v` is assigned after its equation on line 3, which holds `v'`");
    check(&format!("{H}v' + y' v\n"), ErrorKind::Syntax, 3, 9, "`=` or an operator");
}
