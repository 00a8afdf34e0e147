//! Matrices of polynomials and their determinants.
//!
//! The determinant is computed by Berkowitz's algorithm, which uses only
//! ring operations (no division), so it works over `Q[Phi, D, z, ...]`
//! without fractions of polynomials. For an n×n matrix it costs O(n⁴) ring
//! operations and yields the whole characteristic polynomial
//!
//! $$\det(xI - A) = \sum_k c_k x^{n-k}, \qquad c_0 = 1,$$
//!
//! from which `det A = (-1)^n c_n`. [`PolyMatrix::det_laplace`] is the slow,
//! obvious oracle the tests hold it against.
//!
//! Most matrices zcheck meets are univariate: transition matrices in Phi
//! alone. For those, Berkowitz runs on dense integer polynomials (`i128`
//! coefficients, after clearing denominators: the coefficients of the scaled
//! matrix LA are `L^k c_k`), which is two orders of magnitude faster than the
//! sparse rational path. Every operation there is overflow-checked, and an
//! overflow falls back to the sparse path, so the result never changes.

use std::fmt;
use std::ops::{Index, IndexMut, Mul};

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, ToPrimitive};

use crate::{Monomial, Poly, Sym, Q};

/// A dense `rows × cols` matrix of [`Poly`] entries.
#[derive(Clone, PartialEq, Eq)]
pub struct PolyMatrix {
    rows: usize,
    cols: usize,
    data: Vec<Poly>,
}

impl PolyMatrix {
    /// The zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> PolyMatrix {
        PolyMatrix { rows, cols, data: vec![Poly::zero(); rows * cols] }
    }

    /// The identity matrix.
    pub fn identity(n: usize) -> PolyMatrix {
        let mut m = PolyMatrix::zeros(n, n);
        for i in 0..n {
            m[(i, i)] = Poly::one();
        }
        m
    }

    /// From rows; panics when the rows are ragged.
    #[track_caller]
    pub fn from_rows(rows: Vec<Vec<Poly>>) -> PolyMatrix {
        let r = rows.len();
        let c = rows.first().map_or(0, Vec::len);
        assert!(rows.iter().all(|row| row.len() == c), "ragged rows");
        PolyMatrix { rows: r, cols: c, data: rows.into_iter().flatten().collect() }
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Row `i` as a slice.
    pub fn row(&self, i: usize) -> &[Poly] {
        &self.data[i * self.cols..(i + 1) * self.cols]
    }

    /// Applies `f` to every entry.
    pub fn map(&self, f: impl Fn(&Poly) -> Poly) -> PolyMatrix {
        PolyMatrix { rows: self.rows, cols: self.cols, data: self.data.iter().map(f).collect() }
    }

    /// `x·I − self`, for a square matrix.
    #[track_caller]
    pub fn char_matrix(&self, x: &Poly) -> PolyMatrix {
        assert_eq!(self.rows, self.cols, "char_matrix of a non-square matrix");
        let mut m = self.map(|p| -p);
        for i in 0..self.rows {
            m[(i, i)] += x;
        }
        m
    }

    /// The characteristic polynomial's coefficients `[c_0 = 1, c_1, ..., c_n]`
    /// of `det(xI − A) = Σ c_k x^(n−k)`, by Berkowitz's division-free
    /// algorithm.
    #[track_caller]
    pub fn charpoly_berkowitz(&self) -> Vec<Poly> {
        assert_eq!(self.rows, self.cols, "charpoly of a non-square matrix");
        if let Some(c) = charpoly_univariate(self) {
            return c;
        }
        self.charpoly_berkowitz_sparse()
    }

    /// Berkowitz on the sparse multivariate representation: always
    /// applicable, and the reference the dense path must reproduce.
    fn charpoly_berkowitz_sparse(&self) -> Vec<Poly> {
        let a = self;
        let mut c = vec![Poly::one()];
        for r in 0..self.rows {
            // Leading principal block of size r+1 = [[M, S], [R, a_rr]].
            // The Toeplitz column is 1, -a_rr, -R S, -R M S, ..., -R M^(r-1) S.
            let mut col = Vec::with_capacity(r + 2);
            col.push(Poly::one());
            col.push(-&a[(r, r)]);
            let mut v: Vec<Poly> = (0..r).map(|i| a[(i, r)].clone()).collect();
            for k in 0..r {
                let mut dot = Poly::zero();
                for (j, vj) in v.iter().enumerate() {
                    if !vj.is_zero() && !a[(r, j)].is_zero() {
                        dot += &(&a[(r, j)] * vj);
                    }
                }
                col.push(-dot);
                if k + 1 < r {
                    v = (0..r)
                        .map(|i| {
                            let mut s = Poly::zero();
                            for (j, vj) in v.iter().enumerate() {
                                if !vj.is_zero() && !a[(i, j)].is_zero() {
                                    s += &(&a[(i, j)] * vj);
                                }
                            }
                            s
                        })
                        .collect();
                }
            }
            let mut next = Vec::with_capacity(r + 2);
            for i in 0..r + 2 {
                let mut s = Poly::zero();
                for (j, cj) in c.iter().enumerate().take(i + 1) {
                    if !cj.is_zero() && !col[i - j].is_zero() {
                        s += &(&col[i - j] * cj);
                    }
                }
                next.push(s);
            }
            c = next;
        }
        c
    }

    /// The determinant, by Berkowitz's algorithm.
    #[track_caller]
    pub fn det(&self) -> Poly {
        let c = self.charpoly_berkowitz();
        let det = c.last().cloned().unwrap_or_else(Poly::one);
        if self.rows % 2 == 1 {
            -det
        } else {
            det
        }
    }

    /// The determinant by cofactor expansion along the first row: O(n!),
    /// an oracle for tests and tiny matrices only.
    #[track_caller]
    pub fn det_laplace(&self) -> Poly {
        assert_eq!(self.rows, self.cols, "determinant of a non-square matrix");
        let idx: Vec<usize> = (0..self.cols).collect();
        self.laplace(0, &idx)
    }

    fn laplace(&self, row: usize, cols: &[usize]) -> Poly {
        if cols.is_empty() {
            return Poly::one();
        }
        let mut acc = Poly::zero();
        for (k, &c) in cols.iter().enumerate() {
            let e = &self[(row, c)];
            if e.is_zero() {
                continue;
            }
            let rest: Vec<usize> = cols.iter().copied().filter(|&x| x != c).collect();
            let minor = e * &self.laplace(row + 1, &rest);
            if k % 2 == 0 {
                acc += &minor;
            } else {
                acc -= &minor;
            }
        }
        acc
    }
}

/// A dense polynomial with integer coefficients, lowest power first, no
/// trailing zeros (zero is empty).
type Dense = Vec<i128>;

/// `acc += a * b`, or `None` on overflow.
fn mul_add(acc: &mut Dense, a: &[i128], b: &[i128]) -> Option<()> {
    if a.is_empty() || b.is_empty() {
        return Some(());
    }
    if acc.len() < a.len() + b.len() - 1 {
        acc.resize(a.len() + b.len() - 1, 0);
    }
    for (i, &x) in a.iter().enumerate() {
        if x == 0 {
            continue;
        }
        for (slot, &y) in acc[i..].iter_mut().zip(b) {
            *slot = slot.checked_add(x.checked_mul(y)?)?;
        }
    }
    while acc.last() == Some(&0) {
        acc.pop();
    }
    Some(())
}

fn negate(a: &[i128]) -> Option<Dense> {
    a.iter().map(|x| x.checked_neg()).collect()
}

/// The univariate fast path of [`PolyMatrix::charpoly_berkowitz`]: `None`
/// when the entries involve two or more symbols, or when a coefficient
/// overflows `i128` at any step.
fn charpoly_univariate(a: &PolyMatrix) -> Option<Vec<Poly>> {
    let mut sym: Option<Sym> = None;
    let mut lcm = BigInt::one();
    for e in &a.data {
        for (m, c) in e.terms() {
            for &(s, _) in m.factors() {
                match sym {
                    None => sym = Some(s),
                    Some(t) if t != s => return None,
                    Some(_) => {}
                }
            }
            lcm = lcm.lcm(c.denom());
        }
    }
    let scale = lcm.to_i128()?;
    let exponent = |m: &Monomial| sym.map_or(0, |s| m.exponent(s)) as usize;
    let mut dense = Vec::with_capacity(a.data.len());
    for e in &a.data {
        let mut d: Dense = Vec::new();
        for (m, c) in e.terms() {
            let k = exponent(m);
            if d.len() <= k {
                d.resize(k + 1, 0);
            }
            d[k] = (c.numer() * (&lcm / c.denom())).to_i128()?;
        }
        dense.push(d);
    }
    let c = berkowitz_dense(a.rows, &dense)?;
    // c_k(A) = c_k(LA) / L^k.
    let mut power = BigInt::one();
    let mut out = Vec::with_capacity(c.len());
    for ck in c {
        out.push(Poly::from_terms(ck.into_iter().enumerate().filter(|(_, x)| *x != 0).map(
            |(k, x)| {
                let m = sym.map_or_else(Monomial::one, |s| Monomial::power(s, k as u32));
                (Q::new(BigInt::from(x), power.clone()), m)
            },
        )));
        power *= scale;
    }
    Some(out)
}

/// Berkowitz on dense integer polynomials, row-major `n×n` entries; the same
/// recurrence as the sparse path.
fn berkowitz_dense(n: usize, a: &[Dense]) -> Option<Vec<Dense>> {
    let at = |i: usize, j: usize| &a[i * n + j];
    let mut c: Vec<Dense> = vec![vec![1]];
    for r in 0..n {
        let mut col: Vec<Dense> = Vec::with_capacity(r + 2);
        col.push(vec![1]);
        col.push(negate(at(r, r))?);
        let mut v: Vec<Dense> = (0..r).map(|i| at(i, r).clone()).collect();
        for k in 0..r {
            let mut dot = Dense::new();
            for (j, vj) in v.iter().enumerate() {
                mul_add(&mut dot, at(r, j), vj)?;
            }
            col.push(negate(&dot)?);
            if k + 1 < r {
                let mut next = Vec::with_capacity(r);
                for i in 0..r {
                    let mut s = Dense::new();
                    for (j, vj) in v.iter().enumerate() {
                        mul_add(&mut s, at(i, j), vj)?;
                    }
                    next.push(s);
                }
                v = next;
            }
        }
        let mut next = Vec::with_capacity(r + 2);
        for i in 0..r + 2 {
            let mut s = Dense::new();
            for (j, cj) in c.iter().enumerate().take(i + 1) {
                mul_add(&mut s, &col[i - j], cj)?;
            }
            next.push(s);
        }
        c = next;
    }
    Some(c)
}

impl Index<(usize, usize)> for PolyMatrix {
    type Output = Poly;
    #[track_caller]
    fn index(&self, (i, j): (usize, usize)) -> &Poly {
        assert!(i < self.rows && j < self.cols, "index ({i}, {j}) out of bounds");
        &self.data[i * self.cols + j]
    }
}

impl IndexMut<(usize, usize)> for PolyMatrix {
    #[track_caller]
    fn index_mut(&mut self, (i, j): (usize, usize)) -> &mut Poly {
        assert!(i < self.rows && j < self.cols, "index ({i}, {j}) out of bounds");
        &mut self.data[i * self.cols + j]
    }
}

impl Mul<&PolyMatrix> for &PolyMatrix {
    type Output = PolyMatrix;
    #[track_caller]
    fn mul(self, rhs: &PolyMatrix) -> PolyMatrix {
        assert_eq!(self.cols, rhs.rows, "matrix product dimensions");
        let mut out = PolyMatrix::zeros(self.rows, rhs.cols);
        for i in 0..self.rows {
            for j in 0..rhs.cols {
                let mut s = Poly::zero();
                for k in 0..self.cols {
                    s += &(&self[(i, k)] * &rhs[(k, j)]);
                }
                out[(i, j)] = s;
            }
        }
        out
    }
}

impl fmt::Display for PolyMatrix {
    /// One row per line, entries in brackets: `[1, -Phi]`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for i in 0..self.rows {
            let row: Vec<String> = self.row(i).iter().map(ToString::to_string).collect();
            writeln!(f, "[{}]", row.join(", "))?;
        }
        Ok(())
    }
}

impl fmt::Debug for PolyMatrix {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}
