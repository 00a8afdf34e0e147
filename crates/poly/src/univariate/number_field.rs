//! Exact arithmetic in Q(α) for a real algebraic α, for decisions exactly
//! at an irrational critical Φ.
//!
//! Elements are polynomials in α reduced modulo a factor m of α's defining
//! polynomial. The defining polynomial is square-free but need not be
//! irreducible, so Q[x]/(m) may have zero divisors; every zero test is
//! instead decided exactly as the sign of the polynomial at α
//! ([`Algebraic::is_root_of`]), and an inverse first divides m by its gcd
//! with the element (a factor without α as a root), after which the
//! inverse solves the linear system of multiplication by the element (the
//! D5 principle, with the branch chosen by α itself).

use num_bigint::BigInt;
use num_traits::{One, Zero};

use crate::{Algebraic, UPoly, Q};

/// Q(α).
pub(crate) struct Field {
    alpha: Algebraic,
    m: UPoly,
}

/// A polynomial in z over Q(α), lowest power first, trimmed.
pub(crate) type FPoly = Vec<UPoly>;

impl Field {
    pub fn new(alpha: &Algebraic) -> Field {
        Field { alpha: alpha.clone(), m: alpha.defining_poly() }
    }

    pub fn reduce(&self, x: &UPoly) -> UPoly {
        if x.degree().unwrap_or(0) < self.m.degree().unwrap_or(0) {
            return x.clone();
        }
        x.div_rem(&self.m).1
    }

    pub fn is_zero(&self, x: &UPoly) -> bool {
        x.is_zero() || self.alpha.is_root_of(x)
    }

    pub fn mul(&self, x: &UPoly, y: &UPoly) -> UPoly {
        self.reduce(&(x * y))
    }

    /// 1/x for x(α) ≠ 0.
    pub fn inv(&mut self, x: &UPoly) -> UPoly {
        let x = self.reduce(x);
        let h = self.m.gcd(&x);
        if h.degree().unwrap_or(0) > 0 {
            // α is not a root of h (x(α) ≠ 0): drop that factor of m.
            self.m = self.m.div_rem(&h).0;
        }
        let x = self.reduce(&x);
        inverse_mod(&x, &self.m)
    }

    pub fn trim(&self, mut f: FPoly) -> FPoly {
        while f.last().is_some_and(|c| self.is_zero(c)) {
            f.pop();
        }
        f
    }

    fn monic(&mut self, f: FPoly) -> FPoly {
        let Some(lc) = f.last() else { return f };
        let inv = self.inv(lc);
        f.iter().map(|c| self.mul(c, &inv)).collect()
    }

    /// The remainder of f by a monic g.
    fn rem_monic(&self, f: &[UPoly], g: &[UPoly]) -> FPoly {
        let n = g.len() - 1;
        let mut r: FPoly = f.to_vec();
        while r.len() > n {
            let k = r.len() - 1 - n;
            let lr = r.pop().expect("non-empty");
            if !lr.is_zero() {
                for (j, gj) in g.iter().enumerate().take(n) {
                    r[k + j] = self.reduce(&(&r[k + j] - &(&lr * gj)));
                }
            }
            r = self.trim(r);
        }
        self.trim(r)
    }

    /// The monic gcd over Q(α).
    pub fn gcd(&mut self, f: &[UPoly], g: &[UPoly]) -> FPoly {
        let (mut a, mut b) = (self.trim(f.to_vec()), self.trim(g.to_vec()));
        if a.len() < b.len() {
            std::mem::swap(&mut a, &mut b);
        }
        while !b.is_empty() {
            let bm = self.monic(b);
            let r = self.rem_monic(&a, &bm);
            a = bm;
            b = r;
        }
        self.monic(a)
    }

    /// Exact quotient f / g (g divides f).
    pub fn div(&mut self, f: &[UPoly], g: &[UPoly]) -> FPoly {
        let g = self.monic(self.trim(g.to_vec()));
        let n = g.len() - 1;
        let mut r: FPoly = self.trim(f.to_vec());
        let mut q = vec![UPoly::zero(); r.len().saturating_sub(n).max(1)];
        while r.len() > n {
            let k = r.len() - 1 - n;
            let lr = r.pop().expect("non-empty");
            q[k] = lr.clone();
            for (j, gj) in g.iter().enumerate().take(n) {
                r[k + j] = self.reduce(&(&r[k + j] - &(&lr * gj)));
            }
        }
        self.trim(q)
    }

    pub fn derivative(&self, f: &[UPoly]) -> FPoly {
        self.trim(
            f.iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| c.scale(&Q::from_integer(k.into())))
                .collect(),
        )
    }

    /// The rank of a matrix over Q(α).
    pub fn rank(&mut self, mut m: Vec<Vec<UPoly>>) -> usize {
        let rows = m.len();
        let cols = m.first().map_or(0, Vec::len);
        let mut rank = 0;
        for c in 0..cols {
            let Some(p) = (rank..rows).find(|&r| !self.is_zero(&m[r][c])) else { continue };
            m.swap(rank, p);
            let inv = self.inv(&m[rank][c]);
            for r in rank + 1..rows {
                if self.is_zero(&m[r][c]) {
                    continue;
                }
                let f = self.mul(&m[r][c], &inv);
                let pivot_row = m[rank].clone();
                for (x, y) in m[r][c..cols].iter_mut().zip(&pivot_row[c..cols]) {
                    let v = self.mul(&f, y);
                    *x = self.reduce(&(&*x - &v));
                }
            }
            rank += 1;
        }
        rank
    }

    pub fn mat_mul(&self, a: &[Vec<UPoly>], b: &[Vec<UPoly>]) -> Vec<Vec<UPoly>> {
        let n = a.len();
        let k = b.len();
        let m = b.first().map_or(0, Vec::len);
        let mut out = vec![vec![UPoly::zero(); m]; n];
        for i in 0..n {
            for l in 0..k {
                if a[i][l].is_zero() {
                    continue;
                }
                for j in 0..m {
                    if !b[l][j].is_zero() {
                        out[i][j] = &out[i][j] + &(&a[i][l] * &b[l][j]);
                    }
                }
            }
            for e in out[i].iter_mut() {
                *e = self.reduce(e);
            }
        }
        out
    }

    /// q(P) for a polynomial q over Q(α) and a square matrix P over Q(α).
    pub fn poly_at_matrix(&self, q: &[UPoly], p: &[Vec<UPoly>]) -> Vec<Vec<UPoly>> {
        let n = p.len();
        let mut acc = vec![vec![UPoly::zero(); n]; n];
        for c in q.iter().rev() {
            acc = self.mat_mul(&acc, p);
            for (i, row) in acc.iter_mut().enumerate() {
                row[i] = self.reduce(&(&row[i] + c));
            }
        }
        acc
    }
}

/// s with s·x ≡ 1 (mod m) and deg s < deg m, for x coprime to m (and of
/// lower degree): the system of multiplication by x on Q[t]/(m), column j
/// the integer form of x·t^j mod m with its scale kept aside, solved by
/// Bareiss' fraction-free elimination. The extended Euclidean algorithm
/// over Q (the tests' oracle) let its cofactors' coefficients swell: close
/// to a minute on the critical points of some random 3-state programs.
pub(crate) fn inverse_mod(x: &UPoly, m: &UPoly) -> UPoly {
    use crate::univariate::upoly::{content, int_primitive};
    let n = m.degree().unwrap_or(0);
    if n == 0 || x.is_zero() {
        return UPoly::zero();
    }
    let mi = int_primitive(m);
    let lead = mi[n].clone();
    // Column j is scale[j] · cols[j] (integers, lowest power first).
    let mut col = int_primitive(x);
    col.resize(n, BigInt::zero());
    let k = x.coeffs().iter().position(|c| !c.is_zero()).expect("non-zero");
    let mut scale = &x.coeffs()[k] / Q::from_integer(col[k].clone());
    let mut cols = Vec::with_capacity(n);
    let mut scales = Vec::with_capacity(n);
    for j in 0..n {
        if j > 0 {
            // t·c mod m = (L·t·c − top·M)/L, made primitive.
            let top = col[n - 1].clone();
            let mut next: Vec<BigInt> = std::iter::once(BigInt::zero())
                .chain(col[..n - 1].iter().cloned())
                .map(|c| c * &lead)
                .collect();
            for (c, mc) in next.iter_mut().zip(&mi) {
                *c -= &top * mc;
            }
            let g = content(&next);
            if !g.is_zero() && !g.is_one() {
                next.iter_mut().for_each(|c| *c /= &g);
            }
            scale *= Q::new(g, lead.clone());
            col = next;
        }
        cols.push(col.clone());
        scales.push(scale.clone());
    }
    // Rows of [C | e₀]: row i holds coefficient i of every column.
    let rows: Vec<Vec<BigInt>> = (0..n)
        .map(|i| {
            let mut r: Vec<BigInt> = cols.iter().map(|c| c[i].clone()).collect();
            r.push(if i == 0 { BigInt::one() } else { BigInt::zero() });
            r
        })
        .collect();
    let (num, det) = bareiss_solve(rows);
    // s_j = u_j / scale_j with u = num / det.
    UPoly::new(num.into_iter().zip(&scales).map(|(v, sc)| Q::new(v, det.clone()) / sc).collect())
}

/// The solution of a non-singular integer system [A | b] (n rows of n + 1)
/// as integers over one denominator: (det·u, det), by Bareiss' fraction-
/// free elimination (every division exact) and fraction-free back
/// substitution (det·u is integral by Cramer's rule).
fn bareiss_solve(mut a: Vec<Vec<BigInt>>) -> (Vec<BigInt>, BigInt) {
    let n = a.len();
    let mut prev = BigInt::one();
    for k in 0..n {
        let p = (k..n).find(|&r| !a[r][k].is_zero()).expect("a non-singular system");
        a.swap(k, p);
        let pivot = a[k].clone();
        for row in a.iter_mut().skip(k + 1) {
            for j in k + 1..=n {
                row[j] = (&pivot[k] * &row[j] - &row[k] * &pivot[j]) / &prev;
            }
            row[k] = BigInt::zero();
        }
        prev = pivot[k].clone();
    }
    let det = a[n - 1][n - 1].clone();
    let mut num = vec![BigInt::zero(); n];
    for k in (0..n).rev() {
        let mut acc = &det * &a[k][n];
        for j in k + 1..n {
            acc -= &a[k][j] * &num[j];
        }
        num[k] = acc / &a[k][k];
    }
    (num, det)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The extended Euclidean algorithm over Q: the slow, obvious oracle.
    fn inverse_by_euclid(x: &UPoly, m: &UPoly) -> UPoly {
        let (mut r0, mut r1) = (m.clone(), x.clone());
        let (mut s0, mut s1) = (UPoly::zero(), UPoly::constant(Q::one()));
        while !r1.is_zero() {
            let (q, r) = r0.div_rem(&r1);
            let s = &s0 - &(&q * &s1);
            r0 = std::mem::replace(&mut r1, r);
            s0 = std::mem::replace(&mut s1, s);
        }
        let c = r0.coeff(0);
        s0.scale(&c.recip()).div_rem(m).1
    }

    proptest! {
        /// Bareiss' inverse is Euclid's, and x·s ≡ 1 (mod m), on random
        /// coprime pairs with rational coefficients.
        #[test]
        fn inverse_matches_extended_euclid(
            m in proptest::collection::vec((-40i64..40, 1i64..9), 2..9),
            x in proptest::collection::vec((-40i64..40, 1i64..9), 1..8),
        ) {
            let q = |v: &[(i64, i64)]| UPoly::new(v.iter().map(|&(a, b)| Q::new(a.into(), b.into())).collect());
            let (m, x) = (q(&m), q(&x));
            prop_assume!(m.degree().unwrap_or(0) >= 1 && !x.is_zero());
            let x = x.div_rem(&m).1;
            prop_assume!(!x.is_zero() && m.gcd(&x).degree() == Some(0));
            let s = inverse_mod(&x, &m);
            prop_assert_eq!(&s, &inverse_by_euclid(&x, &m));
            prop_assert_eq!((&s * &x).div_rem(&m).1, UPoly::constant(Q::one()));
        }
    }
}
