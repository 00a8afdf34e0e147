//! Exact stability regions in two parameters: the step Φ and one more, the
//! damping ratio D of the test equation v' = −2Dv − y, y' = v.
//!
//! χ(z; Φ, D) = Σ a_k(Φ, D) z^k. The boundedness of the sample sequence can
//! change only where a root meets the unit circle or comes from infinity,
//! that is on the zero sets of four polynomials in (Φ, D), the *critical
//! curves*:
//!
//! - the leading coefficient a_n (a root arrives from infinity);
//! - χ(1) = Σ a_k (a real root through +1);
//! - χ(−1) = Σ (−1)^k a_k (a real root through −1);
//! - the unit-circle condition: two roots with z_i z_j = 1, which for a
//!   complex pair is |z|² = 1. For n = 2 it is a_2 − a_0 (= a_2·(1 − z_1 z_2));
//!   for higher degree the reciprocal resultant Res_z(χ, z^n χ(1/z)), which
//!   vanishes on the same set together with χ(±1).
//!
//! Each curve is kept primitive, with its monomial factors Φ^i D^j split off
//! (they only say that Φ = 0 or D = 0 is critical). Between the curves the
//! stable/unstable split is constant.
//!
//! **Membership** of a rational (Φ, D) is the exact class of χ there, with
//! boundedness at a repeated root on the unit circle decided from P
//! ([`Derivation::class_at`] with D bound). **Φ_max(D)** at a
//! rational D is the one-variable analysis of χ(z; Φ, D) in Φ.
//!
//! **Unconditional stability** (every Φ > 0 and D ≥ 0 bounded, the analogue
//! of A-stability) is decided by a cylindrical decomposition along D: the
//! structure of the curves over the D axis can change only at the positive
//! real roots of each curve's leading coefficient in Φ, its value at Φ = 0,
//! its discriminant in Φ (Res_Φ(f, ∂f/∂Φ)), and the pairwise resultants in
//! Φ. Between consecutive such D the curves' Φ-roots move continuously
//! without meeting, so the one-variable analysis at one rational D per cell
//! decides the whole cell; D = 0 and every rational critical D are analysed
//! too. At an irrational critical D only a non-open failure could hide (a
//! repeated root on the unit circle, since |z| > 1 is an open condition and
//! would show in a neighbouring cell): [`Unconditional::Stable`] records how
//! many such lines there were.

use std::cmp::Ordering;
use std::collections::HashMap;
use std::fmt;

use num_traits::{One, Signed, Zero};

use crate::analysis::stability::{self, ClassAt, Stability};
use crate::multivariate::resultant::{circle_conditions, resultant};
use crate::Error as StabilityError;
use crate::{Algebraic, Poly, Sym, UPoly, Q};
use crate::{Derivation, Params};

/// Which condition a critical curve expresses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum CurveKind {
    /// The leading coefficient of χ in z vanishes.
    Leading,
    /// χ(1) = 0.
    ChiAtOne,
    /// χ(−1) = 0.
    ChiAtMinusOne,
    /// Two roots with z_i z_j = 1 (a complex pair on the unit circle).
    UnitCircle,
}

impl CurveKind {
    /// The snake_case name used in JSON and reports.
    pub fn name(self) -> &'static str {
        match self {
            CurveKind::Leading => "leading",
            CurveKind::ChiAtOne => "chi(1)",
            CurveKind::ChiAtMinusOne => "chi(-1)",
            CurveKind::UnitCircle => "unit_circle",
        }
    }
}

impl fmt::Display for CurveKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One critical curve: the zero set of a polynomial in Φ and the parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    /// The condition it expresses.
    pub kind: CurveKind,
    /// The condition with monomial factors and rational content removed;
    /// zero only where the condition is identically zero.
    pub poly: Poly,
    /// The monomial factor Φ^i D^j that was split off (a polynomial with
    /// one term).
    pub monomial: Poly,
}

/// Φ_max at one value of the parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum PhiLimit {
    /// Every 0 < Φ < Φ_max is bounded, Φ_max exact.
    Below(Algebraic),
    /// Every Φ > 0 is bounded.
    Every,
    /// Unbounded for every small Φ > 0.
    Never,
}

/// The verdict on stability over the whole quadrant Φ > 0, D ≥ 0.
#[derive(Clone, Debug, PartialEq)]
pub enum Unconditional {
    /// Bounded at every Φ > 0 and every D ≥ 0 examined: every cell of the
    /// decomposition and every rational critical D. `irrational_lines`
    /// counts the irrational critical D not analysed themselves (see the
    /// module notes).
    Stable {
        /// Irrational critical D (lines not analysed on themselves).
        irrational_lines: usize,
    },
    /// An exact counterexample: a rational D with its Φ limit.
    Unstable {
        /// The damping ratio at which some Φ > 0 is unbounded.
        d: Q,
        /// What the one-variable analysis found there.
        limit: Box<PhiLimit>,
    },
}

/// The exact (Φ, D) stability region of one characteristic polynomial.
#[derive(Clone, Debug)]
pub struct Region {
    derivation: Derivation,
    chi: Poly,
    param: Sym,
    /// The method's other parameters, bound ([`Derivation::region_with`]).
    bound: Params,
    curves: Vec<Curve>,
}

impl Derivation {
    /// The exact stability region over (Φ, `param`) of a method whose only
    /// parameters are Φ and `param`. Errs when χ, with the parameter given a
    /// value, is not a polynomial in z and Φ with roots.
    ///
    /// ```
    /// let d = poly::derive(&poly::builtin("false_euler_damped")?)?;
    /// let r = d.region(poly::Sym::new("D"))?;
    /// assert!(r.contains(&poly::q(1, 1), &poly::q(1, 10))?);
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn region(&self, param: Sym) -> Result<Region, StabilityError> {
        region(self, param, &Params::new())
    }

    /// [`Derivation::region`] of a method with further parameters, each
    /// bound in `bound` (Newmark's (Φ, β) region with γ = 1/2): χ and every
    /// analysis of the region read them at those values.
    ///
    /// ```
    /// let src = "method nm\nparam beta\nparam gamma\nstate v y\n\
    ///     y' = y + Phi*v + Phi^2*((1/2 - beta)*(-y) + beta*(-y'))\n\
    ///     v' = v + Phi*((1 - gamma)*(-y) + gamma*(-y'))\n";
    /// let d = poly::derive_source("nm.zm", src)?;
    /// let half = poly::Params::new().bind("gamma", poly::q(1, 2));
    /// let r = d.region_with(poly::Sym::new("beta"), &half)?;
    /// assert!(r.contains(&poly::q(100, 1), &poly::q(1, 4))?);
    /// assert!(!r.contains(&poly::q(3, 1), &poly::q(0, 1))?);
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn region_with(&self, param: Sym, bound: &Params) -> Result<Region, StabilityError> {
        region(self, param, bound)
    }
}

fn region(derivation: &Derivation, param: Sym, bound: &Params) -> Result<Region, StabilityError> {
    let values: HashMap<Sym, Q> = bound.iter().map(|(n, v)| (Sym::new(n), v.clone())).collect();
    let chi = &derivation.charpoly().eval_partial(&values);
    // The one-variable engine validates the symbols: any symbol other than
    // z, Φ and `param` is reported by it.
    stability::class_at(&substitute(chi, param, &Q::one()), &Q::one())?;
    let (z, phi) = (Sym::z(), Sym::phi());
    let c = circle_conditions(&chi.coeffs_in(z));
    let mut curves = Vec::new();
    for (kind, p) in [
        (CurveKind::Leading, c.leading),
        (CurveKind::ChiAtOne, c.at_one),
        (CurveKind::ChiAtMinusOne, c.at_minus_one),
        (CurveKind::UnitCircle, c.unit_circle),
    ] {
        let (monomial, poly) = split_monomial(&p, &[phi, param]);
        curves.push(Curve { kind, poly: primitive(&poly), monomial });
    }
    Ok(Region {
        derivation: derivation.clone(),
        chi: chi.clone(),
        param,
        bound: bound.clone(),
        curves,
    })
}

impl Region {
    /// χ(z; Φ, D).
    pub fn charpoly(&self) -> &Poly {
        &self.chi
    }

    /// The second parameter (D).
    pub fn param(&self) -> Sym {
        self.param
    }

    /// The four critical curves, in the order of [`CurveKind`].
    pub fn curves(&self) -> &[Curve] {
        &self.curves
    }

    /// The curves that can bound the region: those that are neither
    /// constant nor identically zero.
    pub fn boundary_curves(&self) -> impl Iterator<Item = &Curve> {
        self.curves.iter().filter(|c| !c.poly.is_zero() && c.poly.as_constant().is_none())
    }

    /// χ with the parameter set to `d`: a polynomial in z and Φ.
    pub fn at_param(&self, d: &Q) -> Poly {
        substitute(&self.chi, self.param, d)
    }

    /// The exact root class at a rational (Φ, D), and whether the sequence
    /// stays bounded there, from the derivation (so with P: a repeated root
    /// on the unit circle is bounded exactly when P is semisimple there).
    pub fn class_at(&self, phi: &Q, d: &Q) -> Result<ClassAt, StabilityError> {
        self.derivation.class_at(&self.bound.clone().bind(self.param.name(), d.clone()), phi)
    }

    /// Whether the rational (Φ, D) is in the stable region: the sequence
    /// stays bounded there, decided with P ([`Region::class_at`]).
    pub fn contains(&self, phi: &Q, d: &Q) -> Result<bool, StabilityError> {
        Ok(self.class_at(phi, d)?.bounded)
    }

    /// The whole stability analysis over Φ at a rational value of the
    /// parameter, from the derivation (so with P).
    pub fn stability_at(&self, d: &Q) -> Result<crate::StabilityReport, StabilityError> {
        self.derivation.stability(&self.bound.clone().bind(self.param.name(), d.clone()))
    }

    /// Φ_max at a rational D, exactly (boundedness at a repeated root on
    /// the unit circle decided from the transition matrix).
    pub fn phi_max(&self, d: &Q) -> Result<PhiLimit, StabilityError> {
        let r = self.stability_at(d)?;
        Ok(match r.stability {
            Stability::BoundedForAllPhi => PhiLimit::Every,
            Stability::Limited { phi_max, .. } => PhiLimit::Below(phi_max),
            // Bounded below `at`; only χ with exact constants can leave it
            // undecided, and then `at` is where the proof stops.
            Stability::UndecidedAt { at, .. } => PhiLimit::Below(at),
            Stability::UnboundedForAllPhi | Stability::UnstableNearZero => PhiLimit::Never,
        })
    }

    /// The positive D where the arrangement of the curves over the D axis
    /// can change (see the module notes), increasing and distinct.
    pub fn critical_params(&self) -> Vec<Algebraic> {
        let (phi, d) = (Sym::phi(), self.param);
        let curves: Vec<&Poly> = self.boundary_curves().map(|c| &c.poly).collect();
        let mut projections: Vec<Poly> = Vec::new();
        for f in &curves {
            let c = f.coeffs_in(phi);
            if c.len() == 1 {
                projections.push(c[0].clone());
                continue;
            }
            projections.push(c[c.len() - 1].clone());
            projections.push(c[0].clone());
            projections.push(resultant(&c, &f.derivative(phi).coeffs_in(phi)));
        }
        for (i, f) in curves.iter().enumerate() {
            for g in &curves[i + 1..] {
                let (cf, cg) = (f.coeffs_in(phi), g.coeffs_in(phi));
                if cf.len() > 1 && cg.len() > 1 {
                    projections.push(resultant(&cf, &cg));
                }
            }
        }
        let mut roots: Vec<Algebraic> = Vec::new();
        for p in projections {
            let Some(u) = p.to_upoly(d) else { continue };
            if u.is_zero() || u.degree().unwrap_or(0) == 0 {
                continue;
            }
            for r in Algebraic::positive_roots(&u) {
                if !roots.contains(&r) {
                    roots.push(r);
                }
            }
        }
        roots.sort();
        roots
    }

    /// Decides stability for every Φ > 0 and D ≥ 0 (see the module notes).
    pub fn unconditional(&self) -> Result<Unconditional, StabilityError> {
        let critical = self.critical_params();
        let mut samples: Vec<Q> = vec![Q::zero()];
        let mut irrational_lines = 0;
        let mut below = Algebraic::zero();
        for c in &critical {
            samples.push(rational_between(&below, c));
            match c.as_rational() {
                Some(q) => samples.push(q.clone()),
                None => irrational_lines += 1,
            }
            below = c.clone();
        }
        samples.push(below.interval().1.floor() + Q::one() + Q::one());
        for d in samples {
            let limit = self.phi_max(&d)?;
            if limit != PhiLimit::Every {
                return Ok(Unconditional::Unstable { d, limit: Box::new(limit) });
            }
        }
        Ok(Unconditional::Stable { irrational_lines })
    }

    /// The Φ in (lo, hi) where `curve` meets the line D = `d`, exactly,
    /// increasing.
    pub fn curve_phis(&self, curve: &Curve, d: &Q, lo: &Q, hi: &Q) -> Vec<Algebraic> {
        let f = substitute(&curve.poly, self.param, d);
        let Some(u) = f.to_upoly(Sym::phi()) else { return Vec::new() };
        roots_inside(&u, lo, hi)
    }

    /// The D in (lo, hi) where `curve` meets the line Φ = `phi`, exactly,
    /// increasing.
    pub fn curve_params(&self, curve: &Curve, phi: &Q, lo: &Q, hi: &Q) -> Vec<Algebraic> {
        let f = substitute(&curve.poly, Sym::phi(), phi);
        let Some(u) = f.to_upoly(self.param) else { return Vec::new() };
        roots_inside(&u, lo, hi)
    }
}

fn roots_inside(u: &UPoly, lo: &Q, hi: &Q) -> Vec<Algebraic> {
    if u.is_zero() || u.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    Algebraic::real_roots(u)
        .into_iter()
        .filter(|r| r.cmp_rational(lo) == Ordering::Greater && r.cmp_rational(hi) == Ordering::Less)
        .collect()
}

/// `p` with `sym` set to the rational `value`.
fn substitute(p: &Poly, sym: Sym, value: &Q) -> Poly {
    let values: HashMap<Sym, Q> = [(sym, value.clone())].into_iter().collect();
    p.eval_partial(&values)
}

/// Splits off the largest monomial Φ^i D^j dividing `p`: `(monomial, rest)`,
/// the monomial as a polynomial.
fn split_monomial(p: &Poly, syms: &[Sym]) -> (Poly, Poly) {
    if p.is_zero() {
        return (Poly::one(), Poly::zero());
    }
    let lowest: Vec<(Sym, u32)> = syms
        .iter()
        .map(|&s| (s, p.terms().map(|(m, _)| m.exponent(s)).min().unwrap_or(0)))
        .collect();
    let power =
        |f: &[(Sym, u32)]| f.iter().fold(Poly::one(), |acc, &(s, e)| &acc * &Poly::sym(s).pow(e));
    let mut rest = Poly::zero();
    for (m, c) in p.terms() {
        let f: Vec<(Sym, u32)> = m
            .factors()
            .iter()
            .map(|&(s, e)| {
                let low = lowest.iter().find(|(t, _)| *t == s).map_or(0, |&(_, l)| l);
                (s, e - low)
            })
            .collect();
        rest += &power(&f).scale(c);
    }
    (power(&lowest), rest)
}

/// `p` divided by its rational content, with a positive leading term (in
/// the canonical order): the same zero set, smaller numbers.
pub(crate) fn primitive(p: &Poly) -> Poly {
    let Some((_, first)) = p.terms().last() else { return Poly::zero() };
    // The gcd of numerators over the lcm of denominators.
    let mut num = num_bigint::BigInt::zero();
    let mut den = num_bigint::BigInt::one();
    for (_, c) in p.terms() {
        num = num_integer::Integer::gcd(&num, c.numer());
        den = num_integer::Integer::lcm(&den, c.denom());
    }
    let mut content = Q::new(num, den);
    if first.is_negative() {
        content = -content;
    }
    p.scale(&content.recip())
}

/// A rational strictly between two distinct algebraic numbers `lo < hi`.
fn rational_between(lo: &Algebraic, hi: &Algebraic) -> Q {
    let (mut a, mut b) = (lo.clone(), hi.clone());
    let four = Q::from_integer(4.into());
    loop {
        let ((_, ahi), (blo, _)) = (a.interval(), b.interval());
        if ahi < blo {
            return (ahi + blo) / Q::from_integer(2.into());
        }
        let (alo, ahi) = a.interval();
        let (blo, bhi) = b.interval();
        a = a.refine(&((&ahi - &alo) / &four));
        b = b.refine(&((&bhi - &blo) / &four));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Sylvester resultant equals the product of g over the roots of f
    /// for polynomials with known rational roots (the obvious oracle).
    #[test]
    fn resultant_of_known_roots() {
        // f = (x − 1)(x − 2), g = (x − 3): Res = g(1) g(2) = (−2)(−1) = 2.
        let f = [Poly::int(2), Poly::int(-3), Poly::int(1)];
        let g = [Poly::int(-3), Poly::int(1)];
        assert_eq!(resultant(&f, &g), Poly::int(2));
        // A common root: zero.
        let g = [Poly::int(-2), Poly::int(1)];
        assert_eq!(resultant(&f, &g), Poly::zero());
    }

    /// False Euler on the damped spring: χ(−1) is Φ² + 4DΦ − 4, whose
    /// positive root is 2(√(1 + D²) − D); χ(1) is Φ² alone.
    #[test]
    fn false_euler_curves() {
        let r = crate::derive(&crate::builtin("false_euler_damped").unwrap())
            .unwrap()
            .region(Sym::new("D"))
            .unwrap();
        let minus_one = r.curves().iter().find(|c| c.kind == CurveKind::ChiAtMinusOne).unwrap();
        assert_eq!(minus_one.poly, Poly::parse("Phi^2 + 4*D*Phi - 4").unwrap());
        let one = r.curves().iter().find(|c| c.kind == CurveKind::ChiAtOne).unwrap();
        assert_eq!(one.poly, Poly::one());
        assert_eq!(one.monomial, Poly::parse("Phi^2").unwrap());
    }
}
