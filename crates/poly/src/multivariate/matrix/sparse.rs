//! A polynomial matrix that stores only its nonzero entries.
//!
//! The z-domain matrix M has one row and column per assignment of the step,
//! and each row has as many nonzeros as its assignment has operands (plus
//! the diagonal). A program of 100,000 lines thus has a matrix of 10^10
//! entries of which a few hundred thousand are nonzero: stored densely it
//! would be quadratic in the program's length, stored by rows it is linear.

use std::fmt;
use std::ops::Index;

use super::polymatrix::PolyMatrix;
use crate::Poly;

/// A `rows × cols` matrix of [`Poly`] entries, each row a list of its
/// nonzero entries in increasing column order.
#[derive(Clone, PartialEq, Eq)]
pub struct SparsePolyMatrix {
    rows: usize,
    cols: usize,
    entries: Vec<Vec<(usize, Poly)>>,
}

/// What every absent entry reads as.
static ZERO: Poly = Poly::ZERO;

impl SparsePolyMatrix {
    /// The zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> SparsePolyMatrix {
        SparsePolyMatrix { rows, cols, entries: vec![Vec::new(); rows] }
    }

    /// The identity matrix.
    pub fn identity(n: usize) -> SparsePolyMatrix {
        SparsePolyMatrix {
            rows: n,
            cols: n,
            entries: (0..n).map(|i| vec![(i, Poly::one())]).collect(),
        }
    }

    /// From each row's `(column, entry)` pairs in any order; entries of one
    /// column are summed and zeros dropped.
    #[track_caller]
    pub fn from_row_entries(cols: usize, rows: Vec<Vec<(usize, Poly)>>) -> SparsePolyMatrix {
        let entries = rows
            .into_iter()
            .map(|mut row| {
                assert!(row.iter().all(|(j, _)| *j < cols), "column out of bounds");
                row.sort_by_key(|(j, _)| *j);
                let mut out: Vec<(usize, Poly)> = Vec::with_capacity(row.len());
                for (j, p) in row {
                    match out.last_mut() {
                        Some((k, q)) if *k == j => *q += &p,
                        _ => out.push((j, p)),
                    }
                }
                out.retain(|(_, p)| !p.is_zero());
                out
            })
            .collect::<Vec<_>>();
        SparsePolyMatrix { rows: entries.len(), cols, entries }
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Row `i` written out densely (for printing small matrices).
    #[track_caller]
    pub fn row(&self, i: usize) -> Vec<Poly> {
        let mut out = vec![Poly::zero(); self.cols];
        for (j, p) in &self.entries[i] {
            out[*j] = p.clone();
        }
        out
    }

    /// The nonzero entries of row `i`, `(column, entry)` by increasing column.
    pub fn row_entries(&self, i: usize) -> &[(usize, Poly)] {
        &self.entries[i]
    }

    /// The number of nonzero entries.
    pub fn nonzeros(&self) -> usize {
        self.entries.iter().map(Vec::len).sum()
    }

    /// Adds `x` to entry `(i, j)`, dropping the entry if it cancels.
    #[track_caller]
    pub fn add_to(&mut self, i: usize, j: usize, x: &Poly) {
        assert!(i < self.rows && j < self.cols, "index ({i}, {j}) out of bounds");
        let row = &mut self.entries[i];
        match row.binary_search_by_key(&j, |(c, _)| *c) {
            Ok(k) => {
                row[k].1 += x;
                if row[k].1.is_zero() {
                    row.remove(k);
                }
            }
            Err(k) => {
                if !x.is_zero() {
                    row.insert(k, (j, x.clone()));
                }
            }
        }
    }

    /// The same matrix stored densely.
    pub fn to_dense(&self) -> PolyMatrix {
        let mut m = PolyMatrix::zeros(self.rows, self.cols);
        for (i, row) in self.entries.iter().enumerate() {
            for (j, p) in row {
                m[(i, *j)] = p.clone();
            }
        }
        m
    }
}

impl Index<(usize, usize)> for SparsePolyMatrix {
    type Output = Poly;
    #[track_caller]
    fn index(&self, (i, j): (usize, usize)) -> &Poly {
        assert!(i < self.rows && j < self.cols, "index ({i}, {j}) out of bounds");
        let row = &self.entries[i];
        match row.binary_search_by_key(&j, |(c, _)| *c) {
            Ok(k) => &row[k].1,
            Err(_) => &ZERO,
        }
    }
}

impl From<&PolyMatrix> for SparsePolyMatrix {
    fn from(m: &PolyMatrix) -> SparsePolyMatrix {
        SparsePolyMatrix {
            rows: m.rows(),
            cols: m.cols(),
            entries: (0..m.rows())
                .map(|i| {
                    m.row(i)
                        .iter()
                        .enumerate()
                        .filter(|(_, p)| !p.is_zero())
                        .map(|(j, p)| (j, p.clone()))
                        .collect()
                })
                .collect(),
        }
    }
}

impl fmt::Display for SparsePolyMatrix {
    /// As [`PolyMatrix`] prints: one row per line, entries in brackets.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for i in 0..self.rows {
            let row: Vec<String> = self.row(i).iter().map(ToString::to_string).collect();
            writeln!(f, "[{}]", row.join(", "))?;
        }
        Ok(())
    }
}

impl fmt::Debug for SparsePolyMatrix {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}
