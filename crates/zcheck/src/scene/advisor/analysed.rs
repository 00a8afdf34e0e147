//! A candidate's analysis, built once and shared by every mode: the
//! method's χ as f64 polynomials in (Φ, D) (`BiPoly`: its coefficients in
//! z, and p, q − 1, q − p² of a monic quadratic) and its exact (Φ, D)
//! region with the per-ζ caches, plus the substep search every answer runs
//! ([`smallest_meeting`], up to [`MAX_SUBSTEPS`]). The methods of
//! [`Analysed`] live with their concern: `estimate.rs` (float), `exact.rs`
//! (exact region), `accuracy.rs` (the accuracy model).

use std::collections::HashMap;

use poly::advanced::region::{PhiLimit, Region};
use poly::{Poly, Sym};

use crate::error::Error;
use crate::load::LoadedMethod;

/// Largest number of substeps searched.
pub(super) const MAX_SUBSTEPS: u64 = 1 << 24;

/// A polynomial in (Φ, D) with f64 coefficients.
#[derive(Clone, Debug)]
pub(super) struct BiPoly(Vec<(f64, i32, i32)>);

impl BiPoly {
    fn new(p: &Poly, d: Sym) -> BiPoly {
        BiPoly(
            p.terms()
                .map(|(m, c)| {
                    (
                        check::numeric::q_to_f64(c),
                        m.exponent(Sym::phi()) as i32,
                        m.exponent(d) as i32,
                    )
                })
                .collect(),
        )
    }

    pub(super) fn eval(&self, phi: f64, d: f64) -> f64 {
        self.0.iter().map(|&(c, i, j)| c * phi.powi(i) * d.powi(j)).sum()
    }
}

/// Everything per candidate that does not depend on the mode.
pub(super) struct Analysed {
    pub(super) spec: LoadedMethod,
    pub(super) region: Region,
    /// χ's coefficients in z (lowest first), in (Φ, D).
    pub(super) coeffs: Vec<BiPoly>,
    /// p, q − 1 and q − p² when χ is monic of degree 2.
    pub(super) second: Option<[BiPoly; 3]>,
    pub(super) exact_limits: HashMap<u64, PhiLimit>,
    /// χ with D substituted and its exact stable intervals (None when the
    /// analysis failed), by the bits of D.
    pub(super) at_param: std::cell::RefCell<HashMap<u64, AtParam>>,
}

/// χ(·, D) at one D, and its exact stable Φ-intervals when analysed.
type AtParam = (Poly, Option<Vec<poly::advanced::stability::StableInterval>>);

impl Analysed {
    pub(super) fn new(spec: LoadedMethod) -> Result<Analysed, Error> {
        let d = Sym::new("D");
        if let Some(extra) =
            spec.method().params().iter().find(|s| s.name() != "Phi" && s.name() != "D")
        {
            return Err(Error::unsupported(format!(
                "method {}: parameter {extra} has no value in a scene: expected only Phi and D",
                spec.display()
            )));
        }
        let chi = &spec.derivation()?.charpoly();
        let region = spec
            .derivation()?
            .region(d)
            .map_err(|e| Error::from(e).context(format!("method {}", spec.display())))?;
        let zc = chi.coeffs_in(Sym::z());
        let coeffs = zc.iter().map(|c| BiPoly::new(c, d)).collect();
        let second = (zc.len() == 3 && zc[2].is_one()).then(|| {
            let p = &zc[1] * &Poly::constant(poly::q(-1, 2));
            let q = zc[0].clone();
            let disc = &q - &(&p * &p);
            [BiPoly::new(&p, d), BiPoly::new(&(&q - &Poly::one()), d), BiPoly::new(&disc, d)]
        });
        Ok(Analysed {
            spec,
            region,
            coeffs,
            second,
            exact_limits: HashMap::new(),
            at_param: Default::default(),
        })
    }
}

/// The smallest n ≥ `from` with `ok(n)`, by doubling then bisection
/// (assumes `ok` monotone), `None` past [`MAX_SUBSTEPS`].
pub(super) fn smallest_meeting(ok: impl Fn(u64) -> bool, from: u64) -> Option<u64> {
    if ok(from) {
        return Some(from);
    }
    let mut lo = from;
    let mut hi = from.max(1) * 2;
    while !ok(hi) {
        lo = hi;
        hi *= 2;
        if hi > MAX_SUBSTEPS {
            return None;
        }
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if ok(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}
