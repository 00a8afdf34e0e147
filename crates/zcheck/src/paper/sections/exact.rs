//! The exact helpers under every section and under the range analysis: a
//! transcription parsed as a polynomial, p and q of a second-order χ, and a
//! polynomial in Φ at a rational Φ.

use std::collections::HashMap;

use poly::{Derivation, Poly, Sym, Q};

/// One of our own transcriptions in `Poly::parse` syntax; a parse failure
/// is a programmer error.
#[track_caller]
pub(crate) fn paper(text: &str) -> Poly {
    Poly::parse(text).unwrap_or_else(|e| panic!("transcription {text:?}: {e}"))
}

/// The paper's second-order form: `chi = z^2 - 2 p z + q`.
#[track_caller]
pub(crate) fn p_q(d: &Derivation) -> (Poly, Poly) {
    d.p_q().unwrap_or_else(|| panic!("{} is not second order", d.method().name()))
}

/// `p` evaluated at Φ = `phi` (all other parameters must be absent).
pub(crate) fn at_phi(p: &Poly, phi: &Q) -> Q {
    let values = HashMap::from([(Sym::phi(), phi.clone())]);
    p.eval(&values).expect("a polynomial in Phi only")
}
