//! Φ_max on the oscillator as a function of the parameters. Boundedness is
//! the root condition of χ(z; Φ, p), decided at a rational point by
//! [`Derivation::stability`] (with the transition matrix where a root on
//! the circle is repeated). The class can change only on the zero sets of
//! χ's critical conditions in (Φ, p): the leading and constant
//! coefficients, χ(1), χ(−1), the unit-circle condition (two roots with
//! z_i z_j = 1: a₂ − a₀ for degree 2, else Res_z(χ, zⁿχ(1/z))) and the
//! discriminant in z. Between the parameter values where their arrangement
//! in Φ changes (`system::arrangement`), Φ_max is one continuous, monotone
//! branch of their roots, and its limit at an end of a piece is decided
//! exactly (`limit`): the root of the conditions at the end inside the
//! separating interval where the branch stays.
//!
//! The root condition is not a closed one (a repeated root on the circle
//! may be unbounded), so Φ_max may jump at a breakpoint: the search reads
//! both the value at every breakpoint and the limits on each side, and says
//! when the supremum is only approached.

use std::cmp::Ordering;
use std::collections::HashMap;

use super::algebra::{above, between, content_in, primitive, roots_in, strip_power};
use super::report::{input_error, Score};
use super::system::{Eval, Factor};
use super::tableau::ParamTableau;
use crate::analysis::stability::Stability;
use crate::error::Error;
use crate::multivariate::resultant::{circle_conditions, resultant};
use crate::{Algebraic, Derivation, Params, Poly, Sym, UPoly, Q};

/// Where the values at rational points come from.
#[derive(Clone, Debug)]
pub(crate) enum Source<'a> {
    /// A program, with the other parameters bound.
    Program(&'a Derivation, Params),
    /// A tableau with parameters.
    Tableau(&'a ParamTableau),
}

/// Φ_max as a function of the free parameters.
#[derive(Clone, Debug)]
pub(crate) struct Oscillator<'a> {
    pub source: Source<'a>,
    /// The critical conditions, in Φ and the free parameters.
    pub factors: Vec<Factor>,
    /// Parameters fixed as polynomials in the free ones (a search along a
    /// line of the box, `order_set.rs`): each is given its value at a
    /// point before the source reads it.
    pub along: Vec<(Sym, Poly)>,
    /// χ(z; Φ, free parameters) itself (`disk.rs` reads its coefficients).
    pub chi: Poly,
}

impl<'a> Oscillator<'a> {
    /// From χ(z; Φ, free parameters).
    pub(crate) fn new(source: Source<'a>, chi: &Poly) -> Oscillator<'a> {
        let (z, phi) = (Sym::z(), Sym::phi());
        let a = chi.coeffs_in(z);
        let c = circle_conditions(&a);
        let disc = resultant(&a, &chi.derivative(z).coeffs_in(z));
        let mut factors: Vec<Factor> = Vec::new();
        for (poly, label) in [
            (c.leading, "the leading coefficient of chi (a root from infinity)"),
            (c.constant, "the constant coefficient of chi (a root through 0)"),
            (c.at_one, "chi(1) (a root through +1)"),
            (c.at_minus_one, "chi(-1) (a root through -1)"),
            (c.unit_circle, "the unit-circle condition (two roots with z_i z_j = 1)"),
            (disc, "the discriminant of chi in z (a repeated root)"),
        ] {
            let p = strip_power(&poly, phi);
            if p.is_zero() || p.as_constant().is_some() {
                continue;
            }
            let p = primitive(&p);
            if !factors.iter().any(|f| f.poly == p) {
                factors.push(Factor { poly: p, label: label.to_owned() });
            }
        }
        Oscillator { source, factors, along: Vec::new(), chi: chi.clone() }
    }

    /// Φ_max at a rational point.
    pub(crate) fn at(&self, point: &[(Sym, Q)]) -> Result<Score, Error> {
        let mut full = point.to_vec();
        let map: HashMap<Sym, Q> = point.iter().cloned().collect();
        for (s, expr) in &self.along {
            let v = expr.eval(&map).ok_or_else(|| {
                input_error(format!("{s} = {expr} needs a value of every free parameter"))
            })?;
            full.push((*s, v));
        }
        let point = &full[..];
        let report = match &self.source {
            Source::Program(d, bound) => {
                let mut params = bound.clone();
                for (s, v) in point {
                    params.insert(s.name(), v.clone());
                }
                d.stability(&params)?
            }
            Source::Tableau(t) => {
                crate::derive(&t.at(point)?.method(false)?)?.stability(&Params::new())?
            }
        };
        Ok(match report.stability {
            Stability::Limited { phi_max, .. } => Score::Finite(phi_max),
            Stability::UndecidedAt { at, .. } => Score::Finite(at),
            Stability::BoundedForAllPhi => Score::Infinite,
            Stability::UnboundedForAllPhi | Stability::UnstableNearZero => Score::zero(),
        })
    }

    /// Φ_max at a point of the search: rational coordinates only.
    pub(crate) fn evaluate(&self, point: &[(Sym, Algebraic)]) -> Result<Eval, Error> {
        let q: Vec<(Sym, Q)> = point
            .iter()
            .map(|(s, a)| {
                a.as_rational().map(|q| (*s, q.clone())).ok_or_else(|| {
                    input_error(format!(
                        "phi_max is evaluated exactly at rational parameter values; the \
                         breakpoint {s} = {} is irrational, where Phi_max may jump: the exact \
                         search stops here rather than guess",
                        a.describe(s.name())
                    ))
                })
            })
            .collect::<Result<_, _>>()?;
        let score = self.at(&q)?;
        let vanishing = match &score {
            Score::Finite(v) if !v.sign().is_eq() => self.vanishing(&q, v),
            _ => Vec::new(),
        };
        Ok(Eval { score, exit: None, vanishing })
    }

    fn at_point(&self, k: usize, point: &[(Sym, Q)]) -> Option<UPoly> {
        let map: HashMap<Sym, Q> = point.iter().cloned().collect();
        self.factors[k].poly.eval_partial(&map).to_upoly(Sym::phi())
    }

    fn vanishing(&self, point: &[(Sym, Q)], v: &Algebraic) -> Vec<usize> {
        (0..self.factors.len())
            .filter(|&k| self.at_point(k, point).is_some_and(|u| !u.is_zero() && v.is_root_of(&u)))
            .collect()
    }

    /// The limit of Φ_max as the one free parameter `p` tends to the
    /// rational `c` from inside the piece whose other end is `other`.
    /// Returns the limit and the rational sample whose value located it.
    pub(crate) fn limit(&self, p: Sym, c: &Q, other: &Algebraic) -> Result<(Score, Q), Error> {
        let phi = Sym::phi();
        let at_c: Vec<UPoly> = (0..self.factors.len())
            .map(|k| self.at_point(k, &[(p, c.clone())]).unwrap_or_else(UPoly::zero))
            .collect();
        if let Some(k) = at_c.iter().position(UPoly::is_zero) {
            return Err(input_error(format!(
                "{} vanishes for every Phi at {p} = {c}: the limit of Phi_max there is not \
                 decided by the exact search",
                self.factors[k].label
            )));
        }
        let mut roots: Vec<Algebraic> = at_c.iter().flat_map(Algebraic::positive_roots).collect();
        roots.sort();
        roots.dedup();
        // Separators: one rational in each gap, and one above the last root.
        let mut seps: Vec<Q> = Vec::new();
        let mut lo = Algebraic::zero();
        for r in &roots {
            seps.push(between(&lo, r));
            lo = r.clone();
        }
        seps.push(above(&lo));
        // A sample close enough to c: no condition vanishes at a separator
        // between the sample and c.
        let c_alg = Algebraic::from_rational(c.clone());
        let (a, b) = if *other > c_alg {
            (c_alg.clone(), other.clone())
        } else {
            (other.clone(), c_alg.clone())
        };
        let mut near = other.clone();
        for s in &seps {
            for f in &self.factors {
                let g = f.poly.subs(phi, &Poly::constant(s.clone()));
                let Some(u) = g.to_upoly(p) else { continue };
                for r in roots_in(&u, &a.interval().0, &b.interval().1) {
                    let inside = r > a && r < b;
                    let closer = if *other > c_alg { r < near } else { r > near };
                    if inside && closer {
                        near = r;
                    }
                }
            }
        }
        let sample = if near > c_alg { between(&c_alg, &near) } else { between(&near, &c_alg) };
        let value = self.at(&[(p, sample.clone())])?;
        let limit = match &value {
            Score::Infinite => Score::Infinite,
            Score::Finite(v) => {
                let j = seps.iter().position(|s| v.cmp_rational(s) == Ordering::Less);
                match j {
                    Some(0) => Score::zero(),
                    Some(j) => Score::Finite(roots[j - 1].clone()),
                    None => Score::Infinite,
                }
            }
        };
        Ok((limit, sample))
    }
}

/// χ(z; Φ, p) of a tableau on the oscillator y' = ωv, v' = −ωy: with
/// u = y + iv the step is R(−iΦ) on u, so χ = (Q(−iΦ)z − P(−iΦ))·conjugate
/// = |Q|²z² − 2 Re(P Q̄) z + |P|² along w = −iΦ.
pub(crate) fn tableau_chi(t: &ParamTableau) -> Poly {
    let (p, q) = t.p_q();
    let (w, phi, z) = (Sym::w(), Sym::phi(), Sym::z());
    let split = |f: &Poly| -> (Poly, Poly) {
        let (mut re, mut im) = (Poly::zero(), Poly::zero());
        for (k, c) in f.coeffs_in(w).iter().enumerate() {
            // (−iΦ)^k = (−i)^k Φ^k.
            let t = c * &Poly::sym(phi).pow(k as u32);
            match k % 4 {
                0 => re += &t,
                1 => im -= &t,
                2 => re -= &t,
                _ => im += &t,
            }
        }
        (re, im)
    };
    let ((pr, pi), (qr, qi)) = (split(&p), split(&q));
    let q2 = &(&qr * &qr) + &(&qi * &qi);
    let p2 = &(&pr * &pr) + &(&pi * &pi);
    let re_pq = &(&pr * &qr) + &(&pi * &qi);
    let zz = Poly::sym(z);
    let chi = &(&(&q2 * &zz.pow(2)) - &(&re_pq.scale(&Q::from_integer(2.into())) * &zz)) + &p2;
    let (_, part) = content_in(&chi, z);
    part
}
