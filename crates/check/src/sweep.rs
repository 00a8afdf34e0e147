//! Sweeping Φ: the class at every point of a grid, and each Φ where the
//! class changes, bracketed by adjacent `f64` values.
//!
//! A [`Classifier`] fixes a method and its other parameters (D, ...) and
//! answers the class and spectral radius at any Φ:
//!
//! * **second order** (χ = z² − 2p·z + q): the shifted polynomials of
//!   [`crate::classify`] are made univariate in Φ (other parameters
//!   substituted exactly), their coefficients rounded to `f64`, and evaluated
//!   by Horner together with a running error bound
//!   `(2d + 2)·ε·Σ|a_k||Φ|^k`. When a bound does not settle a sign (within
//!   a few ulps of a class boundary) the classifier evaluates exactly in
//!   rationals at the `f64` Φ instead, so every answer is the exact class of
//!   that Φ. This path runs tens of millions of points per second.
//! * **any order**: the exact χ evaluated at Φ, its roots, and the
//!   tolerance classifier [`crate::classify::classify_roots`].
//!
//! [`find_boundaries`] classifies a grid and bisects every interval whose
//! ends differ down to two adjacent `f64` values, reporting the class on
//! each side; thin classes (a single harmonic point, a deadbeat point) come
//! out as two boundaries in a row.
//!
//! ```
//! use check::{numeric::Params, sweep};
//! let m = poly::builtin("false_euler")?;
//! let s = sweep::sweep(&m, &Params::default(), &sweep::default_grid())?;
//! assert_eq!(s.boundaries.len(), 2); // harmonic | double root at Φ = 2 | alternating unstable
//! assert_eq!(s.boundaries[0].above, 2.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::numeric::ParamsF64;
use std::cmp::Ordering;
use std::collections::HashMap;

use poly::{Method, Poly, RootClass, Sym, Q};

use crate::classify::classify_pq;
use crate::error::Error;
use crate::numeric::{f64_to_q, q_to_f64, Params};
use crate::witness::{exact_pq_class, pq_signs, ExactCharpoly, PqPolys};

/// A univariate polynomial in Φ with `f64` coefficients, evaluated with an
/// error bound.
#[derive(Clone, Debug)]
pub struct HornerPoly {
    /// Coefficients, lowest power first.
    coeffs: Vec<f64>,
    abs: Vec<f64>,
    gamma: f64,
}

impl HornerPoly {
    /// Rounds the exact univariate polynomial `p` (in `phi` only). An
    /// exact constant in a coefficient (`sqrt(2)`, `cbrt(2)`) is evaluated
    /// there, once; any other symbol gives `None`.
    pub fn new(p: &Poly, phi: Sym) -> Option<HornerPoly> {
        let coeffs: Vec<f64> = match p.to_upoly(phi) {
            Some(u) => u.coeffs().iter().map(q_to_f64).collect(),
            None => {
                let mut out = Vec::new();
                for c in p.coeffs_in(phi) {
                    if c.symbols().iter().any(|&s| poly::advanced::field::generator_of(s).is_none())
                    {
                        return None;
                    }
                    out.push(crate::numeric::eval_poly(&c, &Params::default()).ok()?);
                }
                out
            }
        };
        let abs = coeffs.iter().map(|c| c.abs()).collect();
        let d = coeffs.len().max(1) as f64;
        Some(HornerPoly { coeffs, abs, gamma: (2.0 * d + 2.0) * f64::EPSILON })
    }

    /// The value at `x` and a bound on its error (rounded coefficients and
    /// Horner's arithmetic). The bound is 0 for the zero polynomial.
    #[inline]
    pub fn eval(&self, x: f64) -> (f64, f64) {
        let ax = x.abs();
        let (mut v, mut a) = (0.0, 0.0);
        for (c, ca) in self.coeffs.iter().zip(&self.abs).rev() {
            v = v * x + c;
            a = a * ax + ca;
        }
        (v, self.gamma * a)
    }

    /// The value at `x` alone.
    #[inline]
    pub fn value(&self, x: f64) -> f64 {
        self.coeffs.iter().rev().fold(0.0, |acc, c| acc * x + c)
    }
}

#[derive(Clone, Debug)]
enum Kind {
    SecondOrder { p: HornerPoly, q: HornerPoly, signs: Box<[HornerPoly; 8]>, exact: Box<PqPolys> },
    General { charpoly: Box<ExactCharpoly>, params: Params },
}

/// Class and spectral radius of one method at any Φ (other parameters fixed).
#[derive(Clone, Debug)]
pub struct Classifier {
    method: String,
    kind: Kind,
}

impl Classifier {
    /// Prepares `method` with `params` for its parameters other than Φ (a
    /// value for Φ in `params` is ignored).
    pub fn new(method: &Method, params: &Params) -> Result<Classifier, Error> {
        Classifier::from_derivation(&poly::derive(method)?, params)
    }

    /// As [`Classifier::new`], from an existing derivation (no second
    /// derivation).
    pub fn from_derivation(
        derivation: &poly::Derivation,
        params: &Params,
    ) -> Result<Classifier, Error> {
        let method = derivation.method();
        let charpoly = ExactCharpoly::from_derivation(derivation);
        let phi = Sym::phi();
        let syms: Vec<Sym> = method.params().iter().copied().filter(|&s| s != phi).collect();
        let others = params.exact_values(method.name(), &syms)?;
        let kind = match charpoly.pq() {
            Some(pq) => {
                let sub = |p: &Poly| p.eval_partial(&others);
                let exact = PqPolys::new(sub(&pq.p), sub(&pq.q));
                let h = |p: &Poly| {
                    HornerPoly::new(p, phi).expect("univariate in Phi after substitution")
                };
                let signs = Box::new(exact.sign_polys().map(h));
                Kind::SecondOrder { p: h(&exact.p), q: h(&exact.q), signs, exact: Box::new(exact) }
            }
            None => {
                let mut all = params.clone();
                all.set("Phi", 0.0);
                Kind::General { charpoly: Box::new(charpoly), params: all }
            }
        };
        Ok(Classifier { method: method.name().to_owned(), kind })
    }

    /// The method's name.
    pub fn method(&self) -> &str {
        &self.method
    }

    /// Whether the fast second-order path is used.
    pub fn is_second_order(&self) -> bool {
        matches!(self.kind, Kind::SecondOrder { .. })
    }

    /// The class at `phi`.
    pub fn classify(&self, phi: f64) -> RootClass {
        self.radius_and_class(phi).1
    }

    /// The spectral radius ρ and the class at `phi`.
    pub fn radius_and_class(&self, phi: f64) -> (f64, RootClass) {
        match &self.kind {
            Kind::SecondOrder { p, q, signs, exact } => {
                let (pv, _) = p.eval(phi);
                let (qv, _) = q.eval(phi);
                let disc = pv * pv - qv;
                // The common case, a complex pair away from the unit circle's
                // edge, needs two signs only.
                let (d, db) = signs[0].eval(phi);
                if d < -db {
                    let (m, mb) = signs[4].eval(phi);
                    if m.abs() > mb || (m == 0.0 && mb == 0.0) {
                        let class = match m.partial_cmp(&0.0) {
                            Some(Ordering::Less) => RootClass::DampedOscillation,
                            Some(Ordering::Greater) => RootClass::UnstableOscillation,
                            _ => RootClass::Harmonic,
                        };
                        return (qv.sqrt(), class);
                    }
                }
                let mut certain = true;
                let s = signs.each_ref().map(|h| {
                    let (v, b) = h.eval(phi);
                    if v.abs() > b {
                        v.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
                    } else {
                        if !(v == 0.0 && b == 0.0) {
                            certain = false;
                        }
                        Ordering::Equal
                    }
                });
                let class = if certain {
                    classify_pq(&pq_signs(s))
                } else {
                    let map: HashMap<Sym, Q> =
                        [(Sym::phi(), f64_to_q(phi).unwrap_or_default())].into();
                    exact_pq_class(exact, &map)
                };
                let radius = if disc < 0.0 { qv.sqrt() } else { pv.abs() + disc.sqrt() };
                (radius, class)
            }
            Kind::General { charpoly, params } => {
                let at = params.clone().with("Phi", phi);
                match charpoly.at(&at) {
                    Ok(f) => (f.spectral_radius, f.class),
                    Err(_) => (f64::NAN, RootClass::MonotonicUnstable),
                }
            }
        }
    }
}

/// A change of class between two adjacent `f64` values of Φ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Boundary {
    /// The largest Φ with the lower class.
    pub below: f64,
    /// The smallest Φ with the upper class (the next `f64` after `below`).
    pub above: f64,
    /// The class at `below`.
    pub class_below: RootClass,
    /// The class at `above`.
    pub class_above: RootClass,
}

/// A sweep of one method.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    /// The method's name.
    pub method: String,
    /// The first grid point and its class.
    pub first: (f64, RootClass),
    /// The last grid point and its class.
    pub last: (f64, RootClass),
    /// Every class change, by increasing Φ.
    pub boundaries: Vec<Boundary>,
}

/// `points` values from `from` to `to`, equally spaced in log Φ.
pub fn log_grid(from: f64, to: f64, points: usize) -> Vec<f64> {
    let (a, b) = (from.ln(), to.ln());
    let n = points.max(2) - 1;
    (0..=n).map(|i| if i == n { to } else { (a + (b - a) * i as f64 / n as f64).exp() }).collect()
}

/// `points` values from `from` to `to`, equally spaced.
pub fn linear_grid(from: f64, to: f64, points: usize) -> Vec<f64> {
    let n = points.max(2) - 1;
    (0..=n).map(|i| if i == n { to } else { from + (to - from) * i as f64 / n as f64 }).collect()
}

/// Φ from 1e-8 to 4: 1601 points on a log grid merged with 4001 on a linear
/// grid, sorted.
pub fn default_grid() -> Vec<f64> {
    let mut g = log_grid(1e-8, 4.0, 1601);
    g.extend(linear_grid(1e-8, 4.0, 4001));
    g.sort_by(f64::total_cmp);
    g.dedup();
    g
}

/// Bisects `[lo, hi]` (class `class_lo` at `lo`, another at `hi`) down to
/// adjacent `f64` values.
fn bisect(c: &Classifier, mut lo: f64, mut hi: f64, class_lo: RootClass) -> Boundary {
    loop {
        let mid = lo + (hi - lo) / 2.0;
        if mid <= lo || mid >= hi {
            break;
        }
        if c.classify(mid) == class_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Boundary { below: lo, above: hi, class_below: class_lo, class_above: c.classify(hi) }
}

/// Every class change along `grid` (sorted ascending), each bisected to
/// adjacent `f64` values.
pub fn find_boundaries(c: &Classifier, grid: &[f64]) -> Vec<Boundary> {
    let mut out = Vec::new();
    let classes: Vec<RootClass> = grid.iter().map(|&x| c.classify(x)).collect();
    for i in 1..grid.len() {
        if classes[i] == classes[i - 1] {
            continue;
        }
        let (mut lo, mut class_lo) = (grid[i - 1], classes[i - 1]);
        loop {
            let b = bisect(c, lo, grid[i], class_lo);
            out.push(b);
            if b.class_above == classes[i] || b.above >= grid[i] {
                break;
            }
            lo = b.above;
            class_lo = b.class_above;
        }
    }
    out
}

/// Sweeps `method` (other parameters from `params`) along `grid`.
pub fn sweep(method: &Method, params: &Params, grid: &[f64]) -> Result<Sweep, Error> {
    sweep_derivation(&poly::derive(method)?, params, grid)
}

/// [`sweep`] of an existing derivation (no second derivation).
pub fn sweep_derivation(
    derivation: &poly::Derivation,
    params: &Params,
    grid: &[f64],
) -> Result<Sweep, Error> {
    let method = derivation.method();
    let c = Classifier::from_derivation(derivation, params)?;
    let first = grid.first().copied().unwrap_or(0.0);
    let last = grid.last().copied().unwrap_or(0.0);
    Ok(Sweep {
        method: method.name().to_owned(),
        first: (first, c.classify(first)),
        last: (last, c.classify(last)),
        boundaries: find_boundaries(&c, grid),
    })
}
