//! Exact arithmetic in Q(α) for a real algebraic α, for decisions exactly
//! at an irrational critical Φ.
//!
//! Elements are polynomials in α reduced modulo a factor m of α's defining
//! polynomial. The defining polynomial is square-free but need not be
//! irreducible, so Q[x]/(m) may have zero divisors; every zero test is
//! instead decided exactly as the sign of the polynomial at α
//! ([`Algebraic::is_root_of`]), and an inverse first divides m by its gcd
//! with the element (a factor without α as a root), after which the
//! extended Euclidean algorithm gives the inverse (the D5 principle, with
//! the branch chosen by α itself).

use num_traits::One;

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
        // Extended Euclid: s·x + t·m = 1.
        let (mut r0, mut r1) = (self.m.clone(), x);
        let (mut s0, mut s1) = (UPoly::zero(), UPoly::constant(Q::one()));
        while !r1.is_zero() {
            let (q, r) = r0.div_rem(&r1);
            let s = &s0 - &(&q * &s1);
            r0 = std::mem::replace(&mut r1, r);
            s0 = std::mem::replace(&mut s1, s);
        }
        // r0 is a non-zero constant.
        let c = r0.coeff(0);
        self.reduce(&s0.scale(&c.recip()))
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
