//! [`PolyMatrix`]: a dense matrix of polynomials, its arithmetic, and the
//! two reference algorithms the fast paths are held against: Berkowitz's
//! division-free characteristic polynomial on sparse polynomials, and
//! Laplace expansion.

use std::fmt;
use std::ops::{Index, IndexMut, Mul};

use crate::Poly;

/// A dense `rows × cols` matrix of [`Poly`] entries.
#[derive(Clone, PartialEq, Eq)]
pub struct PolyMatrix {
    pub(crate) rows: usize,
    pub(crate) cols: usize,
    pub(crate) data: Vec<Poly>,
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
