//! The exact algebra of the design search: polynomials made primitive and
//! stripped of a variable's power, resultants that eliminate one symbol
//! (the modular route over Z[p] when one symbol remains, else Sylvester's
//! determinant), real roots inside a closed range, rationals between
//! algebraic numbers, and the sign of a polynomial at a point whose
//! coordinates are algebraic numbers: one irrational coordinate by the
//! number's own sign test, two by rational interval arithmetic on refined
//! isolating boxes (which ends, because the callers ask only where the
//! polynomial does not vanish).

use std::cmp::Ordering;
use std::collections::HashMap;

use num_traits::{One, Zero};

use super::report::{bound_error, MAX_BREAKPOINT_DEGREE};
use crate::error::Error;
use crate::multivariate::resultant::resultant as sylvester;
use crate::{Algebraic, Poly, Sym, UPoly, Q};

/// `p` divided by its rational content (the one in `region`).
pub(crate) use crate::analysis::region::primitive;

/// `p` divided by the largest power of `x` that divides it.
pub(crate) fn strip_power(p: &Poly, x: Sym) -> Poly {
    let c = p.coeffs_in(x);
    let low = c.iter().position(|c| !c.is_zero()).unwrap_or(0);
    Poly::from_coeffs_in(x, &c[low..])
}

/// `p` split as content × primitive part with respect to `x`: the content
/// is the gcd of p's coefficients in x (a polynomial in the other symbols).
pub(crate) fn content_in(p: &Poly, x: Sym) -> (Poly, Poly) {
    let coeffs = p.coeffs_in(x);
    let g = coeffs.iter().filter(|c| !c.is_zero()).fold(Poly::zero(), |g, c| g.gcd(c));
    if g.is_zero() || g.as_constant().is_some() {
        return (Poly::one(), p.clone());
    }
    let rest = p.div_exact(&g).expect("the content divides");
    (g, rest)
}

/// A polynomial whose zero set is that of Res_x(f, g) (the resultant up to
/// a nonzero constant; f itself when g is a nonzero constant in x, and
/// so on): the elimination of `x`.
pub(crate) fn eliminate(f: &Poly, g: &Poly, x: Sym) -> Result<Poly, Error> {
    let (cf, cg) = (f.coeffs_in(x), g.coeffs_in(x));
    if f.is_zero() || g.is_zero() {
        return Ok(Poly::zero());
    }
    if cf.len() == 1 {
        return Ok(f.clone());
    }
    if cg.len() == 1 {
        return Ok(g.clone());
    }
    let mut others = f.symbols();
    others.extend(g.symbols());
    others.remove(&x);
    let r = if others.len() == 1 {
        let s = *others.iter().next().expect("one symbol");
        let scale = |c: &[Poly]| -> Vec<UPoly> {
            let lcm = c
                .iter()
                .flat_map(|p| p.terms().map(|(_, q)| q.denom().clone()))
                .fold(num_bigint::BigInt::one(), |l, d| num_integer::Integer::lcm(&l, &d));
            let k = Q::from_integer(lcm);
            c.iter().map(|p| p.scale(&k).to_upoly(s).expect("one symbol")).collect()
        };
        Poly::from_upoly(s, &crate::univariate::modular::resultant(&scale(&cf), &scale(&cg)))
    } else {
        sylvester(&cf, &cg)
    };
    check_size(&r)?;
    Ok(primitive(&r))
}

/// Refuses a breakpoint polynomial past [`MAX_BREAKPOINT_DEGREE`].
pub(crate) fn check_size(p: &Poly) -> Result<(), Error> {
    for s in p.symbols() {
        let d = p.degree_in(s) as usize;
        if d > MAX_BREAKPOINT_DEGREE {
            return Err(bound_error(format!(
                "a breakpoint polynomial has degree {d} in {s}, past the bound \
                 MAX_BREAKPOINT_DEGREE = {MAX_BREAKPOINT_DEGREE}: the exact search stops here \
                 rather than guess"
            )));
        }
    }
    Ok(())
}

/// The distinct real roots of `u` in the closed range [lo, hi], increasing.
pub(crate) fn roots_in(u: &UPoly, lo: &Q, hi: &Q) -> Vec<Algebraic> {
    if u.is_zero() || u.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    Algebraic::real_roots(u)
        .into_iter()
        .filter(|r| r.cmp_rational(lo) != Ordering::Less && r.cmp_rational(hi) != Ordering::Greater)
        .collect()
}

/// A rational strictly between `lo < hi`.
pub(crate) fn between(lo: &Algebraic, hi: &Algebraic) -> Q {
    Algebraic::rational_between(lo, hi)
}

/// A rational strictly above `a`.
pub(crate) fn above(a: &Algebraic) -> Q {
    a.interval().1 + Q::one()
}

/// `p` with the rational coordinates of `point` (by symbol) substituted.
pub(crate) fn substitute_rational(p: &Poly, point: &[(Sym, Algebraic)]) -> Poly {
    let values: HashMap<Sym, Q> =
        point.iter().filter_map(|(s, a)| a.as_rational().map(|q| (*s, q.clone()))).collect();
    if values.is_empty() {
        p.clone()
    } else {
        p.eval_partial(&values)
    }
}

/// The irrational coordinates of `point`.
pub(crate) fn irrational(point: &[(Sym, Algebraic)]) -> Vec<(Sym, Algebraic)> {
    point.iter().filter(|(_, a)| !a.is_rational()).cloned().collect()
}

/// A polynomial in `x` alone whose real roots include every real root of
/// `p(x, point)`: p itself once the coordinates are rational, else the
/// product over the conjugates, Res_s(m_α(s), p) for each irrational
/// coordinate α of symbol s (m_α monic: exactly ∏ p(x, α′)).
pub(crate) fn roots_cover(p: &Poly, point: &[(Sym, Algebraic)], x: Sym) -> Result<UPoly, Error> {
    let mut q = substitute_rational(p, point);
    for (s, a) in irrational(point) {
        let m = Poly::from_upoly(s, &a.defining_poly());
        q = eliminate(&m, &q, s)?;
    }
    Ok(q.to_upoly(x).unwrap_or_else(UPoly::zero))
}

/// The sign of `p` (a polynomial in the point's symbols only) at the point.
/// With two irrational coordinates the answer comes from interval
/// arithmetic on refined boxes: it ends only when p does not vanish there,
/// which the callers guarantee (`None` after the refinement budget).
pub(crate) fn sign_at(p: &Poly, point: &[(Sym, Algebraic)]) -> Option<Ordering> {
    let q = substitute_rational(p, point);
    if let Some(c) = q.as_constant() {
        return Some(c.cmp(&Q::zero()));
    }
    let irr = irrational(point);
    if irr.len() == 1 {
        let (s, a) = &irr[0];
        return Some(a.sign_of(&q.to_upoly(*s)?));
    }
    let mut boxes: Vec<(Sym, Algebraic)> = irr;
    for _ in 0..200 {
        let iv: HashMap<Sym, (Q, Q)> = boxes.iter().map(|(s, a)| (*s, a.interval())).collect();
        let (lo, hi) = interval_eval(&q, &iv);
        if lo > Q::zero() {
            return Some(Ordering::Greater);
        }
        if hi < Q::zero() {
            return Some(Ordering::Less);
        }
        for (_, a) in boxes.iter_mut() {
            let (l, h) = a.interval();
            *a = a.refine(&((&h - &l) / Q::from_integer(4.into())));
        }
    }
    None
}

/// The sign of `p` at the point from one interval evaluation on the
/// current isolating boxes; `None` when the enclosure holds 0 (and the
/// point is not rational).
pub(crate) fn interval_sign(p: &Poly, point: &[(Sym, Algebraic)]) -> Option<Ordering> {
    let q = substitute_rational(p, point);
    if let Some(c) = q.as_constant() {
        return Some(c.cmp(&Q::zero()));
    }
    let iv: HashMap<Sym, (Q, Q)> =
        irrational(point).iter().map(|(s, a)| (*s, a.interval())).collect();
    let (lo, hi) = interval_eval(&q, &iv);
    if lo > Q::zero() {
        Some(Ordering::Greater)
    } else if hi < Q::zero() {
        Some(Ordering::Less)
    } else {
        None
    }
}

fn iv_mul(a: &(Q, Q), b: &(Q, Q)) -> (Q, Q) {
    let c = [&a.0 * &b.0, &a.0 * &b.1, &a.1 * &b.0, &a.1 * &b.1];
    let lo = c.iter().min().expect("four").clone();
    let hi = c.iter().max().expect("four").clone();
    (lo, hi)
}

/// An enclosure of p over the box (rational interval arithmetic).
fn interval_eval(p: &Poly, iv: &HashMap<Sym, (Q, Q)>) -> (Q, Q) {
    let (mut lo, mut hi) = (Q::zero(), Q::zero());
    for (m, c) in p.terms() {
        let mut t = (c.clone(), c.clone());
        for &(s, e) in m.factors() {
            let x = iv.get(&s).cloned().unwrap_or((Q::zero(), Q::zero()));
            for _ in 0..e {
                t = iv_mul(&t, &x);
            }
        }
        lo += &t.0;
        hi += &t.1;
    }
    (lo, hi)
}
