//! Shared proptest strategies: small rationals, polynomials over a few
//! symbols, and polynomial matrices.

use std::collections::HashMap;

use poly::{q, Poly, PolyMatrix, Sym, Q};
use proptest::prelude::*;

/// The symbols random polynomials are built from.
pub const NAMES: [&str; 3] = ["Phi", "D", "z"];

pub fn sym(k: usize) -> Sym {
    Sym::new(NAMES[k])
}

/// A rational `n/d` with |n| ≤ 9 and 1 ≤ d ≤ 4.
pub fn small_q() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=4).prop_map(|(n, d)| q(n, d))
}

/// A nonzero rational `n/d` with 1 ≤ |n| ≤ 9 and 1 ≤ d ≤ 4.
pub fn nonzero_q() -> impl Strategy<Value = Q> {
    (1i64..=9, 1i64..=4, any::<bool>()).prop_map(|(n, d, neg)| q(if neg { -n } else { n }, d))
}

/// A monomial over the first `n_syms` of [`NAMES`], exponents up to 3.
fn monomial(n_syms: usize) -> impl Strategy<Value = Poly> {
    proptest::collection::vec((0..n_syms, 0u32..=3), 0..=3).prop_map(|factors| {
        factors.into_iter().fold(Poly::one(), |acc, (s, e)| acc * Poly::sym(sym(s)).pow(e))
    })
}

/// A sum of up to `max_terms` terms `c * monomial` with small rational `c`.
pub fn poly_in(n_syms: usize, max_terms: usize) -> impl Strategy<Value = Poly> {
    proptest::collection::vec((small_q(), monomial(n_syms)), 0..=max_terms)
        .prop_map(|terms| terms.into_iter().fold(Poly::zero(), |acc, (c, m)| acc + m.scale(&c)))
}

/// A random polynomial over Phi, D and z with up to four terms.
pub fn small_poly() -> impl Strategy<Value = Poly> {
    poly_in(3, 4)
}

/// A value for each of Phi, D and z.
pub fn point() -> impl Strategy<Value = HashMap<Sym, Q>> {
    proptest::collection::vec(small_q(), 3)
        .prop_map(|vs| vs.into_iter().enumerate().map(|(k, v)| (sym(k), v)).collect())
}

/// An n×n matrix whose entries are zero about a third of the time and
/// otherwise small polynomials in Phi and D (never z, so that z can serve as
/// the characteristic variable).
pub fn matrix(n: usize) -> impl Strategy<Value = PolyMatrix> {
    let entry = prop_oneof![1 => Just(Poly::zero()), 2 => poly_in(2, 3)];
    proptest::collection::vec(entry, n * n)
        .prop_map(move |data| PolyMatrix::from_rows(data.chunks(n).map(<[Poly]>::to_vec).collect()))
}

/// The transpose of a square matrix.
pub fn transpose(m: &PolyMatrix) -> PolyMatrix {
    let n = m.rows();
    PolyMatrix::from_rows((0..n).map(|j| (0..n).map(|i| m[(i, j)].clone()).collect()).collect())
}
