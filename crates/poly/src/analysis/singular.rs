//! Where a step is undefined: the Φ > 0 at which an implicit step's linear
//! system is singular.

use crate::multivariate::constants as field;
use crate::{Algebraic, Derivation, Poly, Sym, Q};

impl Derivation {
    /// The Φ > 0 at which an implicit step's system is singular: the positive
    /// real zeros of d = det A (as a polynomial in Φ alone). For a d holding
    /// constants, the zeros of its norm over Q at which d itself changes sign.
    /// Empty for an explicit method or when d holds other parameters.
    pub fn singular_points(&self) -> Vec<Algebraic> {
        let den = self.p_denominator();
        let n = field::norm(den);
        let Some(u) = n.to_upoly(Sym::phi()) else { return Vec::new() };
        if u.degree().unwrap_or(0) == 0 {
            return Vec::new();
        }
        let roots = Algebraic::positive_roots(&u);
        if !field::has_generators(den) {
            return roots;
        }
        let at =
            |x: &Q| field::sign(&field::reduce(&den.subs(Sym::phi(), &Poly::constant(x.clone()))));
        roots
            .into_iter()
            .filter(|r| {
                let r = r.refine(&Q::new(1.into(), 1_000_000.into()));
                let (lo, hi) = r.interval();
                at(&lo) != at(&hi)
            })
            .collect()
    }
}
