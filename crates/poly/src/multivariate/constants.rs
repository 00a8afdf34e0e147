//! Exact real algebraic constants: the radicals `sqrt(N)`, `cbrt(N)` and
//! `root(K, N)` of positive integers, and the number field they span.
//!
//! Every radical of a positive integer is a rational times a product of
//! prime radicals p^(r/L). A program's constants therefore live in the field
//!
//! $$ F = \mathbb{Q}(\beta_{p_1}, \dots, \beta_{p_k}), \qquad \beta_p = p^{1/L_p} > 0, $$
//!
//! with one *generator* β_p per prime p and L_p the least common multiple of
//! the denominators that p's exponents need. Each β_p has minimal polynomial
//! x^(L_p) − p (irreducible by Eisenstein's criterion at p), and by
//! Besicovitch's theorem on radicals of distinct primes the degrees multiply:
//! [F : Q] = ∏ L_p, with basis the monomials ∏ β_p^(j_p), 0 ≤ j_p < L_p. So an
//! element of F is a [`Poly`] in the generator symbols with every exponent
//! below its L_p, and that representation is canonical: `==` is equality of
//! real numbers, and a nonzero representative is a nonzero real number.
//!
//! The generators are ordinary [`Sym`]s named `sqrt(p)`, `cbrt(p)` or
//! `root(L,p)`; no `.zm` name can contain parentheses, so they never clash.
//! Polynomials over F are then polynomials over Q in the extra symbols,
//! reduced by [`reduce`] (x^L → p, a monomial rewrite since every minimal
//! polynomial is a binomial). The common rational case never meets a
//! generator and pays nothing.
//!
//! Decisions over F are exact: [`inverse`] solves the multiplication matrix
//! over Q, [`norm`] is its determinant (the product of all conjugates, a
//! polynomial over Q), and [`sign`] encloses each generator in rational
//! intervals (bisection on x^L − p) and narrows them until the enclosure of
//! the element excludes 0, which terminates because the element is nonzero.

use std::cmp::Ordering;
use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::multivariate::poly::Monomial;
use crate::{Poly, PolyMatrix, Sym, Q};

/// The largest radicand accepted (factored by trial division).
pub const MAX_RADICAND: u64 = 1_000_000_000_000;

/// A radical of a positive integer in normal form: `coeff · ∏ p^(num/den)`
/// with p prime, 0 < num < den and gcd(num, den) = 1.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Radical {
    /// The rational factor pulled out of the root (√12 = 2·√3 has 2).
    pub coeff: Q,
    /// `(p, num, den)`: the prime power p^(num/den) left under the root.
    pub parts: Vec<(u64, u32, u32)>,
}

impl Radical {
    /// root(k, n) = n^(1/k) for integers n ≥ 1, k ≥ 1, in normal form.
    pub fn root(k: u32, n: u64) -> Radical {
        let mut coeff = Q::one();
        let mut parts = Vec::new();
        for (p, e) in factor(n) {
            let g = e.gcd(&k);
            let (num, den) = (e / g, k / g);
            let whole = num / den;
            if whole > 0 {
                coeff *= Q::from_integer(BigInt::from(p).pow(whole));
            }
            let r = num % den;
            if r > 0 {
                parts.push((p, r, den));
            }
        }
        Radical { coeff, parts }
    }

    /// Whether the radical is rational (every prime came out of the root).
    pub fn is_rational(&self) -> bool {
        self.parts.is_empty()
    }

    /// The minimal polynomial over Q, as `(K, N)` for x^K − N: K is the
    /// least common multiple of the denominators (the degree, by
    /// Besicovitch's theorem) and N = value^K.
    pub fn minimal_polynomial(&self) -> (u32, Q) {
        let k = self.parts.iter().fold(1u32, |acc, &(_, _, d)| acc.lcm(&d));
        let mut n = num_traits::pow(self.coeff.clone(), k as usize);
        for &(p, num, den) in &self.parts {
            n *= Q::from_integer(BigInt::from(p).pow(num * (k / den)));
        }
        (k, n)
    }

    /// The value as an element of F, given each prime's generator index.
    pub fn to_poly(&self, index: &BTreeMap<u64, u32>) -> Poly {
        let mut m = Monomial::one();
        for &(p, num, den) in &self.parts {
            let l = index[&p];
            m = monomial_mul(&m, &Monomial::power(generator(p, l), num * (l / den)));
        }
        Poly::term(self.coeff.clone(), m)
    }
}

fn monomial_mul(a: &Monomial, b: &Monomial) -> Monomial {
    let p = &Poly::term(Q::one(), a.clone()) * &Poly::term(Q::one(), b.clone());
    let m = p.terms().next().map(|(m, _)| m.clone()).unwrap_or_default();
    m
}

/// The prime factorisation of `n ≥ 1` by trial division.
fn factor(mut n: u64) -> Vec<(u64, u32)> {
    let mut out = Vec::new();
    let mut p = 2u64;
    while p.saturating_mul(p) <= n {
        if n.is_multiple_of(p) {
            let mut e = 0;
            while n.is_multiple_of(p) {
                n /= p;
                e += 1;
            }
            out.push((p, e));
        }
        p += if p == 2 { 1 } else { 2 };
    }
    if n > 1 {
        out.push((n, 1));
    }
    out
}

/// For every prime under some radical, the least common multiple of its
/// denominators: the index L_p of its generator.
pub fn generator_indices<'a>(
    radicals: impl IntoIterator<Item = &'a Radical>,
) -> BTreeMap<u64, u32> {
    let mut index = BTreeMap::new();
    for r in radicals {
        for &(p, _, den) in &r.parts {
            let l = index.entry(p).or_insert(1u32);
            *l = l.lcm(&den);
        }
    }
    index
}

/// The generator symbol p^(1/L): `sqrt(p)`, `cbrt(p)` or `root(L,p)`.
pub fn generator(p: u64, l: u32) -> Sym {
    Sym::new(&match l {
        2 => format!("sqrt({p})"),
        3 => format!("cbrt({p})"),
        _ => format!("root({l},{p})"),
    })
}

/// `(p, L)` when `sym` is a generator p^(1/L), `None` for any other symbol.
pub fn generator_of(sym: Sym) -> Option<(u64, u32)> {
    let name = sym.name();
    if !name.ends_with(')') {
        return None;
    }
    let inner = |pre: &str| name.strip_prefix(pre).map(|s| &s[..s.len() - 1]);
    if let Some(p) = inner("sqrt(") {
        return Some((p.parse().ok()?, 2));
    }
    if let Some(p) = inner("cbrt(") {
        return Some((p.parse().ok()?, 3));
    }
    let (l, p) = inner("root(")?.split_once(',')?;
    Some((p.parse().ok()?, l.parse().ok()?))
}

/// Whether `p` holds any generator symbol.
pub fn has_generators(p: &Poly) -> bool {
    p.symbols().into_iter().any(|s| generator_of(s).is_some())
}

/// `p` reduced modulo every generator's minimal polynomial: each β^e with
/// e ≥ L becomes p^(e div L)·β^(e mod L). A ring homomorphism, so reducing
/// once at the end of a computation equals reducing at every step.
pub fn reduce(p: &Poly) -> Poly {
    if !has_generators(p) {
        return p.clone();
    }
    Poly::from_terms(p.terms().map(|(m, c)| {
        let mut c = c.clone();
        let mut out = Monomial::one();
        for &(s, e) in m.factors() {
            let e = match generator_of(s) {
                Some((prime, l)) if e >= l => {
                    c *= Q::from_integer(BigInt::from(prime).pow(e / l));
                    e % l
                }
                _ => e,
            };
            out = monomial_mul(&out, &Monomial::power(s, e));
        }
        (c, out)
    }))
}

/// The generators in `p`, with their indices, in symbol order.
fn generators_in(p: &Poly) -> Vec<(Sym, u64, u32)> {
    p.symbols().into_iter().filter_map(|s| generator_of(s).map(|(q, l)| (s, q, l))).collect()
}

/// The basis monomials ∏ β^(j), 0 ≤ j < L, of the field the generators span.
fn basis(gens: &[(Sym, u64, u32)]) -> Vec<Monomial> {
    let mut out = vec![Monomial::one()];
    for &(s, _, l) in gens {
        out = out
            .iter()
            .flat_map(|m| (0..l).map(move |j| monomial_mul(m, &Monomial::power(s, j))))
            .collect();
    }
    out
}

/// The generator part of a monomial and the rest.
fn split(m: &Monomial) -> (Monomial, Monomial) {
    let (mut g, mut r) = (Monomial::one(), Monomial::one());
    for &(s, e) in m.factors() {
        if generator_of(s).is_some() {
            g = monomial_mul(&g, &Monomial::power(s, e));
        } else {
            r = monomial_mul(&r, &Monomial::power(s, e));
        }
    }
    (g, r)
}

/// The matrix of multiplication by `p` on the basis of the field spanned by
/// `gens`: entry (i, j) is the coefficient of basis_i in p·basis_j, a
/// polynomial in `p`'s other symbols.
fn multiplication_matrix(p: &Poly, gens: &[(Sym, u64, u32)]) -> PolyMatrix {
    let b = basis(gens);
    let pos: BTreeMap<&Monomial, usize> = b.iter().enumerate().map(|(i, m)| (m, i)).collect();
    let mut mat = PolyMatrix::zeros(b.len(), b.len());
    for (j, bj) in b.iter().enumerate() {
        let prod = reduce(&(p * &Poly::term(Q::one(), bj.clone())));
        for (m, c) in prod.terms() {
            let (g, rest) = split(m);
            let i = pos[&g];
            mat[(i, j)] += &Poly::term(c.clone(), rest);
        }
    }
    mat
}

/// The norm of `p` from F to Q (over its other symbols): the product of its
/// conjugates, det of multiplication by `p`. A polynomial over Q whose
/// roots (in any of the other symbols) include every root of `p`.
pub fn norm(p: &Poly) -> Poly {
    let gens = generators_in(p);
    if gens.is_empty() {
        return p.clone();
    }
    multiplication_matrix(p, &gens).det()
}

/// The inverse of a nonzero element of F (a polynomial in generator symbols
/// only); `None` for zero or for an argument with other symbols.
pub fn inverse(a: &Poly) -> Option<Poly> {
    if a.is_zero() {
        return None;
    }
    let gens = generators_in(a);
    if a.symbols().len() != gens.len() {
        return None;
    }
    if gens.is_empty() {
        return Some(Poly::constant(a.as_constant()?.recip()));
    }
    let mat = multiplication_matrix(a, &gens);
    let n = mat.rows();
    // Gauss–Jordan over Q on [M | e_0]; basis_0 is 1.
    let mut rows: Vec<Vec<Q>> = (0..n)
        .map(|i| {
            let mut r: Vec<Q> =
                (0..n).map(|j| mat[(i, j)].as_constant().unwrap_or_else(Q::zero)).collect();
            r.push(if i == 0 { Q::one() } else { Q::zero() });
            r
        })
        .collect();
    for col in 0..n {
        let piv = (col..n).find(|&r| !rows[r][col].is_zero())?;
        rows.swap(col, piv);
        let inv = rows[col][col].recip();
        for x in rows[col].iter_mut() {
            *x *= inv.clone();
        }
        for r in 0..n {
            if r != col && !rows[r][col].is_zero() {
                let f = rows[r][col].clone();
                let pivot_row = rows[col].clone();
                for (x, p) in rows[r].iter_mut().zip(&pivot_row).skip(col) {
                    *x -= p.clone() * f.clone();
                }
            }
        }
    }
    let b = basis(&gens);
    Some(Poly::from_terms(b.into_iter().zip(rows).map(|(m, r)| (r[n].clone(), m))))
}

/// A rational interval of width below `width` around p^(1/L): with
/// 2^-k < width, r = ⌊(p·2^(kL))^(1/L)⌋ = ⌊p^(1/L)·2^k⌋ by one integer root,
/// so r/2^k ≤ p^(1/L) < (r + 1)/2^k.
fn enclose(p: u64, l: u32, width: &Q) -> (Q, Q) {
    // 2^-k < width ⇔ 2^k·numer > denom (width > 0).
    let (n, d) = (width.numer().magnitude(), width.denom().magnitude());
    let mut k = d.bits().saturating_sub(n.bits());
    while (n << k) <= *d {
        k += 1;
    }
    let scaled = num_bigint::BigUint::from(p) << (k * u64::from(l));
    let r = BigInt::from(scaled.nth_root(l));
    let unit = BigInt::one() << k;
    (Q::new(r.clone(), unit.clone()), Q::new(r + 1, unit))
}

/// A rational interval holding the real value of `a`, a polynomial in
/// generator symbols only, with each generator enclosed to `width`.
fn value_interval(a: &Poly, width: &Q) -> (Q, Q) {
    let mut boxes: BTreeMap<Sym, (Q, Q)> = BTreeMap::new();
    for (s, p, l) in generators_in(a) {
        boxes.insert(s, enclose(p, l, width));
    }
    let (mut lo, mut hi) = (Q::zero(), Q::zero());
    for (m, c) in a.terms() {
        let (mut mlo, mut mhi) = (Q::one(), Q::one());
        for &(s, e) in m.factors() {
            let (l, h) = &boxes[&s];
            mlo *= num_traits::pow(l.clone(), e as usize);
            mhi *= num_traits::pow(h.clone(), e as usize);
        }
        if c.is_positive() {
            lo += c * mlo;
            hi += c * mhi;
        } else {
            lo += c * mhi;
            hi += c * mlo;
        }
    }
    (lo, hi)
}

/// The exact sign of an element of F (a polynomial in generator symbols
/// only). Panics when `a` holds another symbol (a programmer error).
pub fn sign(a: &Poly) -> Ordering {
    assert!(
        a.symbols().into_iter().all(|s| generator_of(s).is_some()),
        "sign of a non-constant {a}"
    );
    if let Some(c) = a.as_constant() {
        return c.cmp(&Q::zero());
    }
    let mut width = Q::new(1.into(), 1024.into());
    loop {
        let (lo, hi) = value_interval(a, &width);
        if lo.is_positive() {
            return Ordering::Greater;
        }
        if hi.is_negative() {
            return Ordering::Less;
        }
        width /= Q::from_integer(1u64.wrapping_shl(16).into());
    }
}

/// A rational within `width` of the real value of `a` (generators only).
pub fn approx(a: &Poly, width: &Q) -> Q {
    // A rational is its own value (the interval would be the point).
    if let Some(q) = a.as_constant() {
        return q;
    }
    let mut w = width.clone();
    loop {
        let (lo, hi) = value_interval(a, &w);
        if &hi - &lo <= *width {
            return (lo + hi) / Q::from_integer(2.into());
        }
        w /= Q::from_integer(1024.into());
    }
}

/// The value of generator p^(1/L) to within about 2^-60, as a rational; the
/// numeric crate rounds it once to f64.
pub fn generator_value(sym: Sym) -> Option<Q> {
    let (p, l) = generator_of(sym)?;
    let (lo, hi) = enclose(p, l, &Q::new(1.into(), BigInt::from(1u64 << 62)));
    Some((lo + hi) / Q::from_integer(2.into()))
}

/// `n` as a u64, for radicands.
pub(crate) fn radicand(n: &Q) -> Option<u64> {
    if !n.is_integer() || !n.is_positive() {
        return None;
    }
    n.numer().to_u64().filter(|&v| v <= MAX_RADICAND)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The integer-root enclosure holds the root (checked by raising the
    /// ends to the L-th power exactly) and is narrower than asked.
    #[test]
    fn enclosures_hold_the_root() {
        for (p, l) in [(2u64, 2u32), (3, 2), (2, 3), (5, 5), (7, 2), (1, 2), (4, 2), (1_000_003, 3)]
        {
            for bits in [1u32, 7, 52, 100, 300] {
                let width = Q::new(3.into(), BigInt::one() << bits);
                let (lo, hi) = enclose(p, l, &width);
                let target = Q::from_integer(p.into());
                assert!(num_traits::pow(lo.clone(), l as usize) <= target, "{p}^(1/{l})");
                assert!(num_traits::pow(hi.clone(), l as usize) > target, "{p}^(1/{l})");
                assert!(&hi - &lo < width, "{p}^(1/{l}) at 2^-{bits}");
            }
        }
    }

    #[test]
    fn radicals_normalise() {
        let r = Radical::root(2, 12);
        assert_eq!(r.coeff, Q::from_integer(2.into()));
        assert_eq!(r.parts, vec![(3, 1, 2)]);
        assert_eq!(r.minimal_polynomial(), (2, Q::from_integer(12.into())));
        assert!(Radical::root(3, 8).is_rational());
        assert_eq!(Radical::root(4, 4).parts, vec![(2, 1, 2)]);
        assert_eq!(Radical::root(2, 6).minimal_polynomial(), (2, Q::from_integer(6.into())));
    }

    #[test]
    fn arithmetic_in_the_field() {
        let idx = generator_indices(&[Radical::root(2, 2), Radical::root(3, 2)]);
        assert_eq!(idx[&2], 6);
        let s = Radical::root(2, 2).to_poly(&idx);
        let c = Radical::root(3, 2).to_poly(&idx);
        assert_eq!(reduce(&(&s * &s)), Poly::int(2));
        assert_eq!(reduce(&c.pow(3)), Poly::int(2));
        let a = &Poly::int(2) - &c;
        let inv = inverse(&a).unwrap();
        assert_eq!(reduce(&(&a * &inv)), Poly::one());
        assert_eq!(sign(&a), Ordering::Greater);
        assert_eq!(sign(&(&Poly::int(1) - &s)), Ordering::Less);
        // N(2 - cbrt 2) = 8 - 2 = 6.
        let idx3 = generator_indices(&[Radical::root(3, 2)]);
        let c3 = Radical::root(3, 2).to_poly(&idx3);
        assert_eq!(norm(&(&Poly::int(2) - &c3)), Poly::int(6));
    }
}
