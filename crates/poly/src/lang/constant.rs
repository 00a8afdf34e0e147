//! `const` lines: exact constant expressions and their values.
//!
//! A constant is any expression in numbers, the radicals `sqrt(N)`,
//! `cbrt(N)` and `root(K, N)` of positive integers, and the constants
//! declared on earlier lines, with `+ - * /` and integer powers:
//! `const beta = 1/12`, `const g = (3 + sqrt(3))/6`. Its value is an element
//! of the number field the program's radicals span
//! (`multivariate::constants`), exact; dividing by a nonzero element is
//! exact too, through its inverse in the field.
//!
//! The field's generators depend on every radical of the program (√2 and
//! root(4, 2) share the generator 2^(1/4)), so all radicals are read first
//! and the constants are evaluated after, in the order they are declared.

use std::collections::{BTreeMap, HashMap};

use crate::error::{Error, ErrorKind, Span};
use crate::lang::syntax::{BinOp, Expr, ExprKind};
use crate::multivariate::constants::{self as field, Radical};
use crate::{Poly, Q};
use num_integer::Integer;

/// An exact constant `const NAME = expr` and its value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Constant {
    /// The name in the program.
    pub name: String,
    /// The value as an element of the field spanned by the program's
    /// radicals: a polynomial over Q in the generator symbols, reduced.
    pub value: Poly,
    /// The 1-based source line.
    pub line: u32,
}

impl Constant {
    /// The value as a radical in normal form (a rational times a product of
    /// prime roots, such as 2·√3), when it is one; `None` for a sum such
    /// as (3 + √3)/6 and for 0.
    pub fn radical(&self) -> Option<Radical> {
        if self.value.len() != 1 {
            return None;
        }
        let (mono, coeff) = self.value.terms().next()?;
        let mut parts = Vec::new();
        for &(sym, e) in mono.factors() {
            let (p, l) = field::generator_of(sym)?;
            let g = e.gcd(&l);
            parts.push((p, e / g, l / g));
        }
        parts.sort_unstable();
        Some(Radical { coeff: coeff.clone(), parts })
    }
}

/// One `const` line as parsed: its name, the name's span and the expression.
pub(crate) type ConstSource = (String, Span, Expr);

/// The values of the `const` lines, in order. `declared` gives the
/// declaration of every name of the program, and `what` says what a
/// declared name that is not a constant is ("a parameter", ...).
pub(crate) fn evaluate(
    consts: &[ConstSource],
    declared: &HashMap<String, Span>,
    what: impl Fn(&str) -> Option<&'static str>,
) -> Result<Vec<Constant>, Error> {
    let mut radicals = Vec::new();
    for (_, _, e) in consts {
        collect_radicals(e, &mut radicals)?;
    }
    let index = field::generator_indices(&radicals);
    let mut eval = Evaluator { index, values: HashMap::new(), declared, what: &what };
    let mut out = Vec::with_capacity(consts.len());
    for (name, span, e) in consts {
        let value = eval.value(e)?;
        eval.values.insert(name.clone(), value.clone());
        out.push(Constant { name: name.clone(), value, line: span.line });
    }
    Ok(out)
}

/// `p^n` in the field, reduced after every product so that no intermediate
/// result grows beyond the field's basis.
pub(crate) fn pow_reduced(p: &Poly, mut n: u32) -> Poly {
    let mut base = field::reduce(p);
    let mut acc = Poly::one();
    while n > 0 {
        if n & 1 == 1 {
            acc = field::reduce(&(&acc * &base));
        }
        n >>= 1;
        if n > 0 {
            base = field::reduce(&(&base * &base));
        }
    }
    acc
}

/// Every radical called in `e`, in order, each checked.
fn collect_radicals(e: &Expr, out: &mut Vec<Radical>) -> Result<(), Error> {
    match &e.kind {
        ExprKind::Call { func, args } => out.push(radical_of(func, args, e.span)?),
        ExprKind::Neg(x) | ExprKind::Pow(x, _) => collect_radicals(x, out)?,
        ExprKind::Bin(_, l, r) => {
            collect_radicals(l, out)?;
            collect_radicals(r, out)?;
        }
        ExprKind::Num(_) | ExprKind::Name(_) | ExprKind::Hist(..) | ExprKind::Primed(_) => {}
    }
    Ok(())
}

/// The radical a call `sqrt(N)`, `cbrt(N)` or `root(K, N)` denotes, or a
/// located error.
fn radical_of(func: &str, args: &[(Q, Span)], call: Span) -> Result<Radical, Error> {
    let bad = |s: Span, what: &str| {
        Error::new(ErrorKind::BadConstant, s, format!("{what}: expected `sqrt(N)`, `cbrt(N)` or `root(K, N)` with N a positive integer (at most {}) and K an integer from 2 to 64", field::MAX_RADICAND))
    };
    let (k, n) = match (func, args) {
        ("sqrt", [n]) => (2, n),
        ("cbrt", [n]) => (3, n),
        ("root", [(k, ks), n]) => {
            let k = field::radicand(k)
                .filter(|&k| (2..=64).contains(&k))
                .ok_or_else(|| bad(*ks, &format!("root index {k}")))?;
            (k as u32, n)
        }
        _ => return Err(bad(call, &format!("`{func}` with {} argument(s)", args.len()))),
    };
    let value = field::radicand(&n.0)
        .ok_or_else(|| bad(n.1, &format!("{} is not a positive integer", n.0)))?;
    Ok(Radical::root(k, value))
}

struct Evaluator<'a, F> {
    index: BTreeMap<u64, u32>,
    /// The constants evaluated so far.
    values: HashMap<String, Poly>,
    declared: &'a HashMap<String, Span>,
    what: &'a F,
}

impl<F: Fn(&str) -> Option<&'static str>> Evaluator<'_, F> {
    fn not_constant(span: Span, found: &str) -> Error {
        Error::new(
            ErrorKind::BadConstant,
            span,
            format!("{found}: expected an exact constant (numbers, `sqrt(N)`, `cbrt(N)`, `root(K, N)` and constants declared above)"),
        )
    }

    fn value(&self, e: &Expr) -> Result<Poly, Error> {
        Ok(match &e.kind {
            ExprKind::Num(q) => Poly::constant(q.clone()),
            ExprKind::Name(n) => {
                if let Some(v) = self.values.get(n) {
                    return Ok(v.clone());
                }
                if let Some(what) = (self.what)(n) {
                    return Err(Self::not_constant(e.span, &format!("`{n}` is {what}")));
                }
                return Err(match self.declared.get(n) {
                    Some(d) if d.line >= e.span.line => use_before_declaration(n, e.span, *d),
                    _ => Error::new(
                        ErrorKind::UnknownName,
                        e.span,
                        format!("unknown name `{n}`: expected a number, `sqrt(N)`, `cbrt(N)`, `root(K, N)` or a constant declared above"),
                    ),
                });
            }
            ExprKind::Hist(n, k) => {
                return Err(Self::not_constant(e.span, &format!("`{n}@{k}` is a past value")))
            }
            ExprKind::Primed(n) => {
                return Err(Self::not_constant(e.span, &format!("`{n}'` is an end-of-step value")))
            }
            ExprKind::Call { func, args } => {
                radical_of(func, args, e.span).map(|r| r.to_poly(&self.index))?
            }
            ExprKind::Neg(x) => -self.value(x)?,
            ExprKind::Pow(b, n) => pow_reduced(&self.value(b)?, *n),
            ExprKind::Bin(op, l, r) => {
                let (a, b) = (self.value(l)?, self.value(r)?);
                match op {
                    BinOp::Add => a + b,
                    BinOp::Sub => a - b,
                    BinOp::Mul => field::reduce(&(&a * &b)),
                    BinOp::Div => {
                        if b.is_zero() {
                            return Err(Error::new(
                                ErrorKind::BadDivision,
                                r.span,
                                "division by zero: expected a nonzero divisor",
                            ));
                        }
                        let inv = field::inverse(&b).expect("a nonzero element of the field");
                        field::reduce(&(&a * &inv))
                    }
                }
            }
        })
    }
}

/// The error for a declared name used on or before its declaration's line.
pub(crate) fn use_before_declaration(name: &str, used: Span, declared: Span) -> Error {
    let how = if declared.line == used.line {
        "in its own declaration".to_owned()
    } else {
        format!("before its declaration on line {}", declared.line)
    };
    Error::new(
        ErrorKind::Declaration,
        used,
        format!(
            "`{name}` is used {how}: expected every declaration before the first use of its name"
        ),
    )
}

/// (K, N) of a radical's constant name: `sqrt_5`, `cbrt_2`, `root_4_2`.
fn root_of_name(name: &str) -> Option<(u32, u64)> {
    let n = |s: &str| s.parse::<u64>().ok().filter(|&n| n > 0 && n <= field::MAX_RADICAND);
    if let Some(r) = name.strip_prefix("sqrt_") {
        return Some((2, n(r)?));
    }
    if let Some(r) = name.strip_prefix("cbrt_") {
        return Some((3, n(r)?));
    }
    let (k, r) = name.strip_prefix("root_")?.split_once('_')?;
    Some((k.parse().ok().filter(|k| (2..=64).contains(k))?, n(r)?))
}

/// The generator index L_p of each prime under the named radicals, as a
/// program declaring them all gets it; `None` for a name not of
/// the tableau reader's making (`lang::tableau`).
pub(crate) fn radical_indices(constants: &[(String, String)]) -> Option<BTreeMap<u64, u32>> {
    let radicals: Vec<field::Radical> = constants
        .iter()
        .map(|(name, _)| root_of_name(name).map(|(k, n)| field::Radical::root(k, n)))
        .collect::<Option<_>>()?;
    Some(field::generator_indices(&radicals))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The normal form of a monomial value is the radical it came from.
    #[test]
    fn a_single_term_value_is_a_radical() {
        let radicals = [Radical::root(2, 12), Radical::root(4, 2), Radical::root(2, 2)];
        let index = field::generator_indices(&radicals);
        for r in &radicals {
            let c = Constant { name: "c".into(), value: r.to_poly(&index), line: 1 };
            assert_eq!(c.radical().as_ref(), Some(r));
        }
        let sum = Constant {
            name: "g".into(),
            value: &Poly::one() + &radicals[0].to_poly(&index),
            line: 1,
        };
        assert_eq!(sum.radical(), None);
        let third = Constant { name: "b".into(), value: Poly::constant(crate::q(1, 3)), line: 1 };
        assert!(third.radical().is_some_and(|r| r.is_rational()));
    }
}
