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
//! Three exact paths compute the same coefficients, fastest first:
//!
//! - [`dense`]: matrices in one symbol, Berkowitz on dense `i128`
//!   polynomials, given up on any overflow;
//! - [`modular`]: any number of symbols, by evaluation at points modulo
//!   word-sized primes, interpolation and Chinese remaindering under a
//!   proven coefficient bound;
//! - the sparse multivariate Berkowitz here, always applicable, the
//!   reference the others are tested against.
//!
//! [`sparse`] holds [`SparsePolyMatrix`], the storage for matrices with one
//! row per program line (the z-domain matrix M), which are mostly zero.

use std::fmt;
use std::ops::{Index, IndexMut, Mul};

mod dense;
pub(crate) mod modular;
mod sparse;

pub use sparse::SparsePolyMatrix;

use crate::{Poly, Sym};

/// Up to this size the sparse Berkowitz beats the modular path's setup
/// (primes, CRT constants, a grid), so multivariate matrices this small stay
/// on it (measured on the built-ins, whose z-route matrices are 1×1 to 4×4).
const SMALL: usize = 4;

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
        if let Some(c) = dense::charpoly_univariate(self) {
            return c;
        }
        if self.rows > SMALL {
            if let Some(c) = modular::charpoly(self) {
                return c;
            }
        }
        self.charpoly_berkowitz_sparse()
    }

    /// The characteristic polynomial's coefficients by the modular path
    /// alone (see the module docs), `None` when its grid would be too
    /// large. Exposed for the tests that hold it against the sparse path.
    #[doc(hidden)]
    #[track_caller]
    pub fn charpoly_modular(&self) -> Option<Vec<Poly>> {
        assert_eq!(self.rows, self.cols, "charpoly of a non-square matrix");
        modular::charpoly(self)
    }

    /// The determinant of a matrix whose entries have degree at most 1 in
    /// `w` (a pencil B₀ + w·B₁), by the modular path's pencil job: per point
    /// of the other symbols, one elimination and one Hessenberg reduction
    /// give every coefficient in `w`. Falls back to [`PolyMatrix::det`].
    #[track_caller]
    pub fn det_pencil(&self, w: Sym) -> Poly {
        assert_eq!(self.rows, self.cols, "determinant of a non-square matrix");
        if self.rows <= SMALL {
            return self.det();
        }
        modular::det_linear_in(self, w).unwrap_or_else(|| self.det())
    }

    /// [`PolyMatrix::det_pencil`] by the modular pencil job alone, whatever
    /// the size. Exposed for the tests.
    #[doc(hidden)]
    #[track_caller]
    pub fn det_pencil_modular(&self, w: Sym) -> Option<Poly> {
        assert_eq!(self.rows, self.cols, "determinant of a non-square matrix");
        modular::det_linear_in(self, w)
    }

    /// The determinant by the modular path alone, `None` when its grid
    /// would be too large. Exposed for the tests.
    #[doc(hidden)]
    #[track_caller]
    pub fn det_modular(&self) -> Option<Poly> {
        assert_eq!(self.rows, self.cols, "determinant of a non-square matrix");
        modular::det(self)
    }

    /// Berkowitz on the sparse multivariate representation: always
    /// applicable, and the reference the faster paths must reproduce.
    #[doc(hidden)]
    #[track_caller]
    pub fn charpoly_berkowitz_sparse(&self) -> Vec<Poly> {
        assert_eq!(self.rows, self.cols, "charpoly of a non-square matrix");
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

    /// The determinant: Berkowitz on the dense path for a matrix in one
    /// symbol, else the modular path, else Berkowitz on the sparse path.
    #[track_caller]
    pub fn det(&self) -> Poly {
        assert_eq!(self.rows, self.cols, "determinant of a non-square matrix");
        let c = match dense::charpoly_univariate(self) {
            Some(c) => c,
            None if self.rows <= SMALL => self.charpoly_berkowitz_sparse(),
            None => match modular::det(self) {
                Some(d) => return d,
                None => self.charpoly_berkowitz_sparse(),
            },
        };
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
