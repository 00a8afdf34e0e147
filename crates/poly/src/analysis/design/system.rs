//! Objectives read from signs: the step x > 0 is admissible while every
//! condition, a product of polynomial factors in x and the parameters, is
//! ≥ 0 on all of (0, x]; the objective is the first x after which some
//! condition turns negative (0 when one is negative from the start, +∞
//! when none ever is). The axes of y' = λy for a one-step method are one
//! condition, the margin |Q|² − |P|² along the axis (R = P/Q), and the SSP
//! coefficient is Kraaijevanger's conditions, one per entry.
//!
//! Every condition is a closed one in (x, parameters), so the objective is
//! upper semicontinuous in the parameters: its maximum over a box is
//! attained, at one of the points where the arrangement of the factors'
//! roots in x changes (the search in `one.rs` and `two.rs`).
//!
//! At a point with algebraic coordinates the objective is still exact: the
//! roots of a factor are among those of its product over the conjugates
//! (`algebra::roots_cover`), and the sign of a factor at a rational x
//! between those roots is decided at the point (`algebra::sign_at`); it
//! never vanishes there, so the sign is never undecided.

use std::cmp::Ordering;

use super::algebra::{above, substitute_rational};
use super::algebra::{between, content_in, eliminate, irrational, primitive, roots_cover, sign_at};
use super::report::{bound_error, Score};
use crate::error::Error;
use crate::{Algebraic, Poly, Sym, Q};

/// One polynomial factor of the conditions.
#[derive(Clone, Debug)]
pub(crate) struct Factor {
    /// In x and the free parameters, without a power of x (positive for
    /// x > 0, so the sign is unchanged).
    pub poly: Poly,
    /// What its vanishing means, for the certificate.
    pub label: String,
}

/// One condition: the product of its factors must be ≥ 0.
#[derive(Clone, Debug)]
pub(crate) struct SignCondition {
    /// Indices into [`SignSystem::factors`].
    pub factors: Vec<usize>,
    /// What it says, for the certificate.
    pub label: String,
}

/// An objective read from signs.
#[derive(Clone, Debug)]
pub(crate) struct SignSystem {
    /// The objective's variable.
    pub x: Sym,
    /// The distinct factors.
    pub factors: Vec<Factor>,
    /// The conditions.
    pub conditions: Vec<SignCondition>,
}

/// The objective at one point, with what ends the admissible steps.
#[derive(Clone, Debug)]
pub(crate) struct Eval {
    /// The value.
    pub score: Score,
    /// The condition that turns negative there.
    pub exit: Option<usize>,
    /// The factors that vanish at the value (x itself a root of each).
    pub vanishing: Vec<usize>,
}

/// A labelled polynomial in the parameters whose roots may be breakpoints.
#[derive(Clone, Debug)]
pub(crate) struct Breakpoints {
    pub poly: Poly,
    pub label: String,
}

impl SignSystem {
    /// Adds a factor (stripped of x's power) and returns its index.
    pub(crate) fn factor(&mut self, poly: Poly, label: &str) -> usize {
        let poly = super::algebra::strip_power(&poly, self.x);
        self.factors.push(Factor { poly, label: label.to_owned() });
        self.factors.len() - 1
    }

    /// The objective at a point (each free symbol with its exact value).
    pub(crate) fn evaluate(&self, point: &[(Sym, Algebraic)]) -> Result<Eval, Error> {
        let x = self.x;
        let two_irrational = irrational(point).len() >= 2;
        let mut zero = vec![false; self.factors.len()];
        let mut roots: Vec<(Algebraic, usize)> = Vec::new();
        for (k, f) in self.factors.iter().enumerate() {
            let q = substitute_rational(&f.poly, point);
            if q.is_zero() {
                zero[k] = true;
                continue;
            }
            let coeffs = q.coeffs_in(x);
            let irr = irrational(point);
            if irr.len() == 1 {
                let (s, a) = &irr[0];
                if coeffs.iter().all(|c| c.to_upoly(*s).is_some_and(|u| a.is_root_of(&u))) {
                    zero[k] = true;
                    continue;
                }
            }
            let cover = roots_cover(&f.poly, point, x)?;
            if cover.is_zero() {
                if two_irrational {
                    return Err(bound_error(format!(
                        "the factor {} may vanish identically at a point with two irrational \
                         coordinates, which the exact search does not decide",
                        f.poly
                    )));
                }
                zero[k] = true;
                continue;
            }
            for r in Algebraic::positive_roots(&cover) {
                roots.push((r, k));
            }
        }
        roots.sort_by(|a, b| a.0.cmp(&b.0));
        // Distinct values, each with the factors that have it as a root
        // (some only for a conjugate point: decided below by the sign).
        let mut distinct: Vec<Algebraic> = Vec::new();
        for (r, _) in &roots {
            if distinct.last() != Some(r) {
                distinct.push(r.clone());
            }
        }
        let sign = |k: usize, at: &Q| -> Result<Ordering, Error> {
            let p = self.factors[k].poly.subs(x, &Poly::constant(at.clone()));
            sign_at(&p, point).ok_or_else(|| {
                bound_error(format!(
                    "the sign of {} at a point with two irrational coordinates was not \
                     separated from 0 within the refinement budget",
                    self.factors[k].poly
                ))
            })
        };
        let negative = |at: &Q| -> Result<Option<usize>, Error> {
            for (i, c) in self.conditions.iter().enumerate() {
                if c.factors.iter().any(|&k| zero[k]) {
                    continue;
                }
                let mut s = Ordering::Greater;
                for &k in &c.factors {
                    s = match (s, sign(k, at)?) {
                        (_, Ordering::Equal) => Ordering::Equal,
                        (a, Ordering::Greater) => a,
                        (a, Ordering::Less) => a.reverse(),
                    };
                }
                if s == Ordering::Less {
                    return Ok(Some(i));
                }
            }
            Ok(None)
        };
        let mut lo = Algebraic::zero();
        for i in 0..=distinct.len() {
            let sample = match distinct.get(i) {
                Some(r) => between(&lo, r),
                None => above(&lo),
            };
            if let Some(c) = negative(&sample)? {
                let vanishing = self.vanishing_at(&lo, point, &zero);
                return Ok(Eval { score: Score::Finite(lo), exit: Some(c), vanishing });
            }
            if let Some(r) = distinct.get(i) {
                lo = r.clone();
            }
        }
        Ok(Eval { score: Score::Infinite, exit: None, vanishing: Vec::new() })
    }

    /// The factors with a root at `x0` (> 0) at the point, decided by the
    /// sign change or, for an even root, by the factor's roots at a rational
    /// point; a best effort for the certificate only.
    fn vanishing_at(
        &self,
        x0: &Algebraic,
        point: &[(Sym, Algebraic)],
        zero: &[bool],
    ) -> Vec<usize> {
        if x0.sign().is_eq() {
            return Vec::new();
        }
        let mut out = Vec::new();
        for (k, f) in self.factors.iter().enumerate() {
            if zero[k] {
                continue;
            }
            let q = substitute_rational(&f.poly, point);
            if irrational(point).is_empty() {
                if let Some(u) = q.to_upoly(self.x) {
                    if x0.is_root_of(&u) {
                        out.push(k);
                    }
                }
            } else if let Ok(cover) = roots_cover(&f.poly, point, self.x) {
                if x0.is_root_of(&cover) {
                    out.push(k);
                }
            }
        }
        out
    }

    /// The breakpoint polynomials of the factors ([`arrangement`]).
    pub(crate) fn breakpoints(&self, params: &[Sym]) -> Result<Vec<Breakpoints>, Error> {
        arrangement(&self.factors, self.x, params)
    }
}

/// The polynomials in the parameters whose roots are where the
/// arrangement of the factors' roots in x can change: each factor's
/// content, leading coefficient, value at x = 0 and discriminant, each
/// pair's resultant, and, for each parameter p, Res_x(F, ∂F/∂p) (where
/// a root's derivative in p can vanish: the critical points of the
/// objective along a piece).
pub(crate) fn arrangement(
    factors: &[Factor],
    x: Sym,
    params: &[Sym],
) -> Result<Vec<Breakpoints>, Error> {
    let mut out = Vec::new();
    let mut parts: Vec<(Poly, &str)> = Vec::new();
    let mut push = |poly: Poly, label: String| {
        if !poly.is_zero() && poly.as_constant().is_none() {
            out.push(Breakpoints { poly: primitive(&poly), label });
        }
    };
    for f in factors {
        if f.poly.degree_in(x) == 0 {
            push(f.poly.clone(), format!("{} vanishes for every step", f.label));
            continue;
        }
        let (content, part) = content_in(&f.poly, x);
        push(content, format!("{} vanishes for every step", f.label));
        let c = part.coeffs_in(x);
        push(c[c.len() - 1].clone(), format!("{}: a root arrives from infinity", f.label));
        push(c[0].clone(), format!("{}: a root passes through 0", f.label));
        push(
            eliminate(&part, &part.derivative(x), x)?,
            format!("{}: a double root (tangency) in {}", f.label, x),
        );
        for &p in params {
            push(
                eliminate(&part, &part.derivative(p), x)?,
                format!("{}: a root stationary in {}", f.label, p),
            );
        }
        parts.push((part, &f.label));
    }
    for i in 0..parts.len() {
        for j in i + 1..parts.len() {
            let (f, g) = (&parts[i], &parts[j]);
            if f.0 == g.0 {
                continue;
            }
            push(eliminate(&f.0, &g.0, x)?, format!("{} and {} vanish at one step", f.1, g.1));
        }
    }
    Ok(out)
}
