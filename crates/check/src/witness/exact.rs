//! The reference: the exact χ(z) from `poly`, evaluated exactly at the
//! rational value of the `f64` parameters and rounded once.

use crate::numeric::ParamsF64;
use std::collections::HashMap;

use nalgebra::DMatrix;
use num_bigint::BigInt;
use num_traits::{Signed, Zero};
use poly::{Method, Poly, RootClass, Sym, Q};

use super::eigen::{eigenvalues_nalgebra, C64};
use super::tolerance::poly_tolerances;
use crate::classify::{classify_pq, classify_roots, psi_of, PqSigns};
use crate::error::Error;
use crate::numeric::{q_to_f64, Params};

/// The shifted polynomials of a second-order χ = z² − 2p·z + q, exact in
/// the parameters (see [`crate::classify`]).
#[derive(Clone, Debug)]
pub struct PqPolys {
    /// p.
    pub p: Poly,
    /// q.
    pub q: Poly,
    /// p² − q.
    pub disc: Poly,
    /// p − 1.
    pub p_minus_1: Poly,
    /// p + 1.
    pub p_plus_1: Poly,
    /// q − 1.
    pub q_minus_1: Poly,
    /// q + 1.
    pub q_plus_1: Poly,
    /// χ(1) = 1 − 2p + q.
    pub chi_1: Poly,
    /// χ(−1) = 1 + 2p + q.
    pub chi_minus_1: Poly,
}

impl PqPolys {
    /// The shifted polynomials of z² − 2p·z + q.
    pub fn new(p: Poly, q: Poly) -> PqPolys {
        let one = Poly::one();
        let two_p = &p + &p;
        PqPolys {
            disc: &(&p * &p) - &q,
            p_minus_1: &p - &one,
            p_plus_1: &p + &one,
            q_minus_1: &q - &one,
            q_plus_1: &q + &one,
            chi_1: &(&one - &two_p) + &q,
            chi_minus_1: &(&one + &two_p) + &q,
            p,
            q,
        }
    }

    /// The polynomials in [`PqSigns`] order after `p` and `q`: disc, p, p − 1,
    /// p + 1, q − 1, q + 1, χ(1), χ(−1).
    pub fn sign_polys(&self) -> [&Poly; 8] {
        [
            &self.disc,
            &self.p,
            &self.p_minus_1,
            &self.p_plus_1,
            &self.q_minus_1,
            &self.q_plus_1,
            &self.chi_1,
            &self.chi_minus_1,
        ]
    }
}

/// Signs from eight values in [`PqPolys::sign_polys`] order.
pub fn pq_signs(v: [std::cmp::Ordering; 8]) -> PqSigns {
    PqSigns {
        disc: v[0],
        p: v[1],
        p_minus_1: v[2],
        p_plus_1: v[3],
        q_minus_1: v[4],
        q_plus_1: v[5],
        chi_1: v[6],
        chi_minus_1: v[7],
    }
}

/// The exact χ(z) of a method, ready to be evaluated at numeric parameters.
#[derive(Clone, Debug)]
pub struct ExactCharpoly {
    method: String,
    params: Vec<Sym>,
    charpoly: Poly,
    coeffs: Vec<Poly>,
    pq: Option<PqPolys>,
}

/// What the exact χ says at one point.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactForm {
    /// χ's coefficients, highest power first, each exact-then-rounded.
    pub coeffs: Vec<f64>,
    /// The roots, largest modulus first (Im ≥ 0 first among a pair).
    pub roots: Vec<C64>,
    /// ρ = max |z|.
    pub spectral_radius: f64,
    /// ln ρ, without cancellation for degree 2 (see the module docs).
    pub growth_per_step: f64,
    /// Ψ of the dominant root, in [0, π].
    pub psi: f64,
    /// The section-4 class (exact for degree 2, tolerance-based beyond).
    pub class: RootClass,
}

impl ExactCharpoly {
    /// Derives `method` (both exact routes) and prepares χ.
    pub fn new(method: &Method) -> Result<ExactCharpoly, Error> {
        let d = poly::derive(method)?;
        Ok(ExactCharpoly::from_derivation(&d))
    }

    /// Prepares χ from a derivation.
    pub fn from_derivation(d: &poly::Derivation) -> ExactCharpoly {
        ExactCharpoly {
            method: d.method().name().to_owned(),
            params: d.method().params().to_vec(),
            charpoly: d.charpoly().clone(),
            coeffs: d.coeffs().iter().map(with_constants_approximated).collect(),
            // The exact p, q path needs rational coefficients; a χ with
            // exact constants (Forest–Ruth's cbrt(2)) takes the general path.
            pq: d
                .p_q()
                .filter(|(p, q)| {
                    !poly::advanced::field::has_generators(p)
                        && !poly::advanced::field::has_generators(q)
                })
                .map(|(p, q)| PqPolys::new(p, q)),
        }
    }

    /// χ as a polynomial in z and the parameters.
    pub fn charpoly(&self) -> &Poly {
        &self.charpoly
    }

    /// The degree N.
    pub fn degree(&self) -> usize {
        self.coeffs.len() - 1
    }

    /// The shifted polynomials, for a second-order method.
    pub fn pq(&self) -> Option<&PqPolys> {
        self.pq.as_ref()
    }

    /// The parameters as exact rationals.
    pub fn exact_params(&self, params: &Params) -> Result<HashMap<Sym, Q>, Error> {
        params.exact_values(&self.method, &self.params)
    }

    /// The coefficients at `params`, highest power first, each evaluated
    /// exactly and rounded once.
    pub fn coeffs_at(&self, params: &Params) -> Result<Vec<f64>, Error> {
        let map = self.exact_params(params)?;
        Ok(self.coeffs.iter().map(|c| q_to_f64(&exact_eval(c, &map))).collect())
    }

    /// Roots, growth, Ψ and class at `params`.
    pub fn at(&self, params: &Params) -> Result<ExactForm, Error> {
        let map = self.exact_params(params)?;
        let coeffs: Vec<f64> = self.coeffs.iter().map(|c| q_to_f64(&exact_eval(c, &map))).collect();
        match &self.pq {
            Some(pq) => Ok(second_order_form(pq, &map, coeffs)),
            // An implicit second-order χ = a z² + b z + c (a = det A): p and
            // q taken exactly at this point, then the same cancellation-free
            // forms as for z² − 2p z + q.
            None if self.coeffs.len() == 3 => {
                let v: Vec<Q> = self.coeffs.iter().map(|c| exact_eval(c, &map)).collect();
                if v[0].is_zero() {
                    return Err(Error::singular(&self.method, params.phi_value()));
                }
                let two = Q::from_integer(2.into());
                let p = -(&v[1] / (&two * &v[0]));
                let q = &v[2] / &v[0];
                let pq = PqPolys::new(Poly::constant(p), Poly::constant(q));
                Ok(second_order_form(&pq, &HashMap::new(), coeffs))
            }
            None => {
                let mut roots = polynomial_roots(&coeffs)?;
                let exact: Vec<Q> = self.coeffs.iter().map(|c| exact_eval(c, &map)).collect();
                polish_roots(&exact, &mut roots);
                sort_roots(&mut roots);
                let tol = poly_tolerances(&coeffs, &roots);
                let class = classify_roots(&roots, &tol);
                let rho = roots.iter().map(|z| z.norm()).fold(0.0, f64::max);
                let dom = roots.first().copied().unwrap_or_default();
                Ok(ExactForm {
                    coeffs,
                    psi: psi_of(dom),
                    spectral_radius: rho,
                    growth_per_step: rho.ln(),
                    class,
                    roots,
                })
            }
        }
    }
}

/// `p` with each exact constant (sqrt(2), cbrt(2)) replaced by a rational
/// within 2^-256 of it, once, so that evaluating a coefficient at a point is
/// rational arithmetic only: the error this leaves in a coefficient's value
/// is about 2^-250 of its terms' size, far below f64 resolution.
fn with_constants_approximated(p: &Poly) -> Poly {
    let width = num_traits::pow(Q::new(1.into(), 2.into()), 256);
    let values: HashMap<Sym, Q> = p
        .symbols()
        .into_iter()
        .filter(|&s| poly::advanced::field::generator_of(s).is_some())
        .map(|s| (s, poly::advanced::field::approx(&Poly::sym(s), &width)))
        .collect();
    if values.is_empty() {
        p.clone()
    } else {
        p.eval_partial(&values)
    }
}

/// χ and χ′ at the complex point z (its f64 parts read as the rationals
/// they are), exactly, with the coefficients highest power first; each
/// part rounded once to f64 at the end. `None` when z is not finite.
///
/// ```
/// use check::witness::{exact_value_and_slope, C64};
/// let chi = [poly::q(1, 1), poly::q(-2, 1), poly::q(5, 4)]; // z² − 2z + 5/4
/// let (v, d) = exact_value_and_slope(&chi, C64::new(1.0, 0.5)).unwrap();
/// assert_eq!((v, d), (C64::new(0.0, 0.0), C64::new(0.0, 1.0))); // a root; χ′ = 2z − 2
/// ```
pub fn exact_value_and_slope(coeffs: &[Q], z: C64) -> Option<(C64, C64)> {
    // On integers: the coefficients over one denominator D (a = A/D,
    // highest degree first) and z = (X + iY)/E over one power of two E,
    // so p(z) = H/(D·E^n) and p′(z) = H′/(D·E^(n−1)) with H, H′ from a
    // homogeneous Horner scheme, one reduction at the end instead of one
    // per operation. The values are the same rationals as term by term.
    let (x, y) = (crate::numeric::f64_to_q(z.re)?, crate::numeric::f64_to_q(z.im)?);
    let n = coeffs.len().checked_sub(1)?;
    if n == 0 {
        return Some((C64::new(q_to_f64(&coeffs[0]), 0.0), C64::new(0.0, 0.0)));
    }
    let e = if x.denom() > y.denom() { x.denom().clone() } else { y.denom().clone() };
    let big_x = x.numer() * (&e / x.denom());
    let big_y = y.numer() * (&e / y.denom());
    let d = coeffs.iter().fold(BigInt::from(1), |l, a| num_integer::Integer::lcm(&l, a.denom()));
    let ints: Vec<BigInt> = coeffs.iter().map(|a| a.numer() * (&d / a.denom())).collect();
    // H ← H·(X + iY) + A_j·E^k at the k-th step, p's and p′'s together
    // (p′'s coefficients are j·A_j, one degree lower).
    let (mut pr, mut pi) = (BigInt::zero(), BigInt::zero());
    let (mut dr, mut di) = (BigInt::zero(), BigInt::zero());
    let mut e_pow = BigInt::from(1);
    for (k, a) in ints.iter().enumerate() {
        let j = n - k;
        let (npr, npi) = (&pr * &big_x - &pi * &big_y + a * &e_pow, &pr * &big_y + &pi * &big_x);
        // p′ = Σ j·a_j z^(j−1): its scheme adds j·A_j·E^k at the same k,
        // for j ≥ 1 only (one step fewer).
        if j > 0 {
            if k > 0 {
                let (ndr, ndi) = (&dr * &big_x - &di * &big_y, &dr * &big_y + &di * &big_x);
                (dr, di) = (ndr, ndi);
            }
            dr += a * BigInt::from(j) * &e_pow;
        }
        (pr, pi) = (npr, npi);
        e_pow *= &e;
    }
    // e_pow = E^(n+1) now.
    let den_p = &d * (&e_pow / &e);
    let den_d = &d * (&e_pow / &e / &e);
    let f = |num: BigInt, den: &BigInt| q_to_f64(&Q::new(num, den.clone()));
    Some((C64::new(f(pr, &den_p), f(pi, &den_p)), C64::new(f(dr, &den_d), f(di, &den_d))))
}

/// Newton steps on each root with χ and χ′ evaluated exactly: roots taken
/// from rounded coefficients lose accuracy where roots crowd (a multistep
/// method's principal pair 1 ± iΦ at small Φ: relative error 10⁻⁵ in Ψ at
/// Φ = 10⁻⁶), the exact values do not. A step is taken only while it stays
/// within a quarter of the distance to the nearest other root, so a root
/// never jumps to a neighbour (and an exactly multiple root stays put).
fn polish_roots(exact: &[Q], roots: &mut [C64]) {
    for k in 0..roots.len() {
        let gap = (0..roots.len())
            .filter(|&j| j != k)
            .map(|j| (roots[j] - roots[k]).norm())
            .fold(f64::INFINITY, f64::min);
        for _ in 0..4 {
            let Some((v, d)) = exact_value_and_slope(exact, roots[k]) else { break };
            let step = v / d;
            if !step.re.is_finite() || !step.im.is_finite() || step.norm() > 0.25 * gap {
                break;
            }
            let next = roots[k] - step;
            if next == roots[k] {
                break;
            }
            roots[k] = next;
        }
    }
}

/// A coefficient's value at the parameters: rational, since its exact
/// constants were approximated when χ was prepared
/// ([`with_constants_approximated`]) and `map` gives every parameter.
fn exact_eval(p: &Poly, map: &HashMap<Sym, Q>) -> Q {
    let v = p.eval_partial(map);
    v.as_constant().unwrap_or_else(|| panic!("every parameter has a value: {v}"))
}

fn sign(x: &Q) -> std::cmp::Ordering {
    if x.is_zero() {
        std::cmp::Ordering::Equal
    } else if x.is_positive() {
        std::cmp::Ordering::Greater
    } else {
        std::cmp::Ordering::Less
    }
}

/// The class of a second-order χ exactly at the rational values `map`.
pub fn exact_pq_class(pq: &PqPolys, map: &HashMap<Sym, Q>) -> RootClass {
    let s = pq.sign_polys().map(|p| sign(&exact_eval(p, map)));
    classify_pq(&pq_signs(s))
}

fn second_order_form(pq: &PqPolys, map: &HashMap<Sym, Q>, coeffs: Vec<f64>) -> ExactForm {
    let e = |p: &Poly| q_to_f64(&exact_eval(p, map));
    let (p, q, disc) = (e(&pq.p), e(&pq.q), e(&pq.disc));
    let class = exact_pq_class(pq, map);
    let (roots, radius, growth, psi);
    if disc < 0.0 {
        // Complex pair p ± j√(q − p²); |z|² = q.
        let s = (-disc).sqrt();
        roots = vec![C64::new(p, s), C64::new(p, -s)];
        radius = q.sqrt();
        growth = 0.5 * e(&pq.q_minus_1).ln_1p();
        psi = s.atan2(p);
    } else if disc == 0.0 {
        roots = vec![C64::new(p, 0.0); 2];
        radius = p.abs();
        growth = if p > 0.0 { e(&pq.p_minus_1).ln_1p() } else { (-e(&pq.p_plus_1)).ln_1p() };
        psi = if p < 0.0 { std::f64::consts::PI } else { 0.0 };
    } else {
        let s = disc.sqrt();
        // The root with the sign of p is the larger one; the other follows
        // from the product q, never from a cancelling difference.
        let big = if p >= 0.0 { p + s } else { p - s };
        let small = if big != 0.0 { q / big } else { -s };
        roots = vec![C64::new(big, 0.0), C64::new(small, 0.0)];
        radius = big.abs();
        growth = if p == 0.0 {
            s.ln()
        } else if p > 0.0 {
            // |z| − 1 = (p − 1) + s, or −χ(1)/(1 − z_other) when that cancels.
            let (pm1, direct) = (e(&pq.p_minus_1), e(&pq.p_minus_1) + s);
            let t = if direct.abs() >= 0.5 * pm1.abs().max(s) {
                direct
            } else {
                -e(&pq.chi_1) / (1.0 - small)
            };
            t.ln_1p()
        } else {
            let (pp1, direct) = (e(&pq.p_plus_1), s - e(&pq.p_plus_1));
            let t = if direct.abs() >= 0.5 * pp1.abs().max(s) {
                direct
            } else {
                -e(&pq.chi_minus_1) / (1.0 + small)
            };
            t.ln_1p()
        };
        psi = if big < 0.0 { std::f64::consts::PI } else { 0.0 };
    }
    let mut roots = roots;
    sort_roots(&mut roots);
    // Two real roots of one modulus (p = 0: ±√−q) are both dominant, and
    // q/big may round above |big|: Ψ is that of the root sorted first, the
    // one the simulation witness follows.
    let psi = if disc > 0.0 { psi_of(roots[0]) } else { psi };
    ExactForm { coeffs, roots, spectral_radius: radius, growth_per_step: growth, psi, class }
}

/// Sorts roots by decreasing modulus, Im ≥ 0 first within a pair, then by
/// decreasing real part.
pub fn sort_roots(roots: &mut [C64]) {
    roots.sort_by(|a, b| {
        b.norm()
            .partial_cmp(&a.norm())
            .unwrap_or(std::cmp::Ordering::Equal)
            .then((a.im < 0.0).cmp(&(b.im < 0.0)))
            .then(b.re.partial_cmp(&a.re).unwrap_or(std::cmp::Ordering::Equal))
    });
}

/// Roots of a monic polynomial (coefficients highest first, the first 1):
/// directly for degree 1, as companion-matrix eigenvalues beyond.
pub fn polynomial_roots(coeffs: &[f64]) -> Result<Vec<C64>, Error> {
    let n = coeffs.len().saturating_sub(1);
    match n {
        0 => Ok(Vec::new()),
        1 => Ok(vec![C64::new(-coeffs[1] / coeffs[0], 0.0)]),
        _ => {
            let mut c = DMatrix::<f64>::zeros(n, n);
            for j in 0..n {
                c[(0, j)] = -coeffs[j + 1] / coeffs[0];
            }
            for i in 1..n {
                c[(i, i - 1)] = 1.0;
            }
            eigenvalues_nalgebra(&c)
        }
    }
}
