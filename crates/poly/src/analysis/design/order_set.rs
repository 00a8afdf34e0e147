//! The allowed set of a two-parameter problem under `min_order`: where the
//! order conditions (polynomials in the free parameters a, b) all vanish.
//!
//! The conditions that are affine in (a, b) are solved exactly: they cut
//! the plane to a line (one of them, or several proportional ones) or to a
//! point (two independent ones), or show the set empty. On a line one
//! parameter is written as an affine function of the other, t, and every
//! polynomial of the search is restricted to it ([`restrict`]): the
//! two-parameter problem becomes a one-parameter one in t, over the range
//! of t that keeps both parameters in the box. The conditions that are not
//! affine become polynomials in t there, whose common roots are the allowed
//! points. Without an affine condition the set is a curve that is not a
//! line, which the exact search does not follow: the error says so.
//!
//! The linear order conditions of a scalar program are affine in its
//! coefficients; a tableau's classical conditions are usually not, and are
//! solved only when they are.

use std::collections::HashMap;

use num_traits::Zero;

use super::problem::{Engine, Setup};
use super::report::input_error;
use super::system::SignSystem;
use crate::error::{Error, ErrorKind};
use crate::{Algebraic, Poly, Sym, Q};

/// The allowed set, solved.
#[derive(Clone, Debug)]
pub(crate) enum OrderSet {
    /// One point of the box, each free symbol with its value.
    Point(Vec<(Sym, Q)>),
    /// A line, or the points of a line where the remaining conditions hold.
    Line(Line),
}

/// A line of the plane, `dependent = expr(t)`, inside the box.
#[derive(Clone, Debug)]
pub(crate) struct Line {
    /// The parameter left free along the line.
    pub t: Sym,
    /// The parameter fixed by the line.
    pub dependent: Sym,
    /// `dependent` as an affine polynomial in `t` (constant when the line
    /// is parallel to t's axis).
    pub expr: Poly,
    /// The range of t that keeps both parameters in the box.
    pub lo: Q,
    pub hi: Q,
    /// The conditions that are not affine, restricted to the line
    /// (polynomials in t, none identically zero).
    pub remainder: Vec<Poly>,
}

impl Line {
    /// The point of the plane at `t = v`, in the order of `syms`.
    pub(crate) fn point(&self, syms: &[Sym], v: &Algebraic) -> Vec<(Sym, Algebraic)> {
        syms.iter()
            .map(|&s| if s == self.t { (s, v.clone()) } else { (s, self.dependent_at(v)) })
            .collect()
    }

    /// The value of the dependent parameter at `t = v`.
    pub(crate) fn dependent_at(&self, v: &Algebraic) -> Algebraic {
        let c = self.expr.coeffs_in(self.t);
        let alpha = c.first().and_then(Poly::as_constant).unwrap_or_default();
        let beta = c.get(1).and_then(Poly::as_constant).unwrap_or_default();
        affine_image(v, &alpha, &beta)
    }

    /// The line in words: `a2 = 1/2 with a3 in [0, 1/6]`.
    pub(crate) fn describe(&self) -> String {
        format!("{} = {} with {} in [{}, {}]", self.dependent, self.expr, self.t, self.lo, self.hi)
    }
}

/// α + β·v, exactly: the image of v's isolating interval under the affine
/// map isolates the root of its defining polynomial's image.
fn affine_image(v: &Algebraic, alpha: &Q, beta: &Q) -> Algebraic {
    if beta.is_zero() {
        return Algebraic::from_rational(alpha.clone());
    }
    if let Some(q) = v.as_rational() {
        return Algebraic::from_rational(alpha + beta * q);
    }
    let x = Sym::new("x_design");
    let d = Poly::from_upoly(x, &v.defining_poly());
    // d((x − α)/β) vanishes at α + βv.
    let back = (&Poly::sym(x) - &Poly::constant(alpha.clone())).scale(&beta.recip());
    let image = d.subs(x, &back).to_upoly(x).expect("a polynomial in x alone");
    let (lo, hi) = v.interval();
    let (a, b) = (alpha + beta * &lo, alpha + beta * &hi);
    let (a, b) = if a <= b { (a, b) } else { (b, a) };
    Algebraic::from_isolating(&image, &a, &b)
        .expect("an affine map keeps an isolating interval isolating")
}

/// An affine condition `ka·a + kb·b + k0 = 0`, or `None` when `c` is not
/// affine in (a, b).
fn affine(c: &Poly, a: Sym, b: Sym) -> Option<(Q, Q, Q)> {
    if c.total_degree() > 1 {
        return None;
    }
    let zero: HashMap<Sym, Q> = [(a, Q::zero()), (b, Q::zero())].into_iter().collect();
    let k0 = c.eval(&zero)?;
    let ka = c.coeffs_in(a).get(1).map_or(Some(Q::zero()), Poly::as_constant)?;
    let kb = c.coeffs_in(b).get(1).map_or(Some(Q::zero()), Poly::as_constant)?;
    Some((ka, kb, k0))
}

fn empty(what: String) -> Error {
    Error::analysis(ErrorKind::NoRoots, what)
}

/// Solves the order conditions of a two-parameter problem over the box
/// `ranges` (lo, hi of each free symbol, in `s.syms`' order).
pub(crate) fn solve(s: &Setup, ranges: &[(Q, Q)], order: usize) -> Result<OrderSet, Error> {
    let (a, b) = (s.syms[0], s.syms[1]);
    let (mut lines, mut rest): (Vec<(Q, Q, Q)>, Vec<Poly>) = (Vec::new(), Vec::new());
    for c in &s.order_conditions {
        match affine(c, a, b) {
            Some(l) => lines.push(l),
            None => rest.push(c.clone()),
        }
    }
    let none = || {
        empty(format!(
            "no ({a}, {b}) in the box has order {order}: the order conditions have no common \
             solution there"
        ))
    };
    let Some(first) = lines.iter().find(|(ka, kb, _)| !ka.is_zero() || !kb.is_zero()).cloned()
    else {
        if lines.is_empty() {
            return Err(input_error(format!(
                "min_order {order} with two free parameters: no order condition is affine in \
                 ({a}, {b}) (the first is {} = 0), so the allowed set is a curve that is not a \
                 line, which the exact search does not follow; bind one parameter with a value",
                rest[0]
            )));
        }
        // Every affine condition is a nonzero constant.
        return Err(none());
    };
    let (ka, kb, k0) = &first;
    let mut point: Option<(Q, Q)> = None;
    for (la, lb, l0) in &lines {
        let det = ka * lb - kb * la;
        if !det.is_zero() {
            // Cramer's rule on the two independent conditions.
            let pa = (kb * l0 - k0 * lb) / &det;
            let pb = (k0 * la - ka * l0) / &det;
            point = Some((pa, pb));
            break;
        }
    }
    let in_range = |v: &Q, (lo, hi): &(Q, Q)| lo <= v && v <= hi;
    if let Some((pa, pb)) = point {
        let values: HashMap<Sym, Q> = [(a, pa.clone()), (b, pb.clone())].into_iter().collect();
        let holds = s.order_conditions.iter().all(|c| c.eval(&values).is_some_and(|v| v.is_zero()));
        if !holds || !in_range(&pa, &ranges[0]) || !in_range(&pb, &ranges[1]) {
            return Err(none());
        }
        return Ok(OrderSet::Point(vec![(a, pa), (b, pb)]));
    }
    // Every affine condition is a multiple of the first: one line, unless
    // one of them contradicts it.
    for (la, lb, l0) in &lines {
        if !(ka * l0 - k0 * la).is_zero() || !(kb * l0 - k0 * lb).is_zero() {
            return Err(none());
        }
    }
    // dependent = α + β t, with t the other parameter.
    let (t, dependent, kt, kd, t_range, d_range) = if !kb.is_zero() {
        (a, b, ka, kb, &ranges[0], &ranges[1])
    } else {
        (b, a, kb, ka, &ranges[1], &ranges[0])
    };
    let alpha = -(k0 / kd);
    let beta = -(kt / kd);
    let (mut lo, mut hi) = t_range.clone();
    if beta.is_zero() {
        if !in_range(&alpha, d_range) {
            return Err(none());
        }
    } else {
        let ends = [(&d_range.0 - &alpha) / &beta, (&d_range.1 - &alpha) / &beta];
        let (l, h) = if ends[0] <= ends[1] { (&ends[0], &ends[1]) } else { (&ends[1], &ends[0]) };
        lo = lo.max(l.clone());
        hi = hi.min(h.clone());
        if lo > hi {
            return Err(none());
        }
    }
    let expr = &Poly::constant(alpha) + &Poly::sym(t).scale(&beta);
    let remainder: Vec<Poly> =
        rest.iter().map(|c| c.subs(dependent, &expr)).filter(|c| !c.is_zero()).collect();
    Ok(OrderSet::Line(Line { t, dependent, expr, lo, hi, remainder }))
}

/// The setup restricted to the line: every polynomial of the engine with
/// the dependent parameter replaced, t the one free parameter, and the
/// remaining conditions as its order conditions.
pub(crate) fn restrict<'a>(s: &Setup<'a>, line: &Line) -> Setup<'a> {
    let on = |p: &Poly| p.subs(line.dependent, &line.expr);
    let engine = match &s.engine {
        Engine::Signs(sys) => {
            let mut r = SignSystem { x: sys.x, factors: Vec::new(), conditions: Vec::new() };
            for f in &sys.factors {
                r.factor(on(&f.poly), &f.label);
            }
            r.conditions = sys.conditions.clone();
            Engine::Signs(r)
        }
        Engine::Oscillator(o) => {
            let mut r = o.clone();
            for f in &mut r.factors {
                f.poly = on(&f.poly);
            }
            r.along.push((line.dependent, line.expr.clone()));
            Engine::Oscillator(r)
        }
    };
    Setup { engine, syms: vec![line.t], order_conditions: line.remainder.clone() }
}
