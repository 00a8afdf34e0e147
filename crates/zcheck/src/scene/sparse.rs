//! Symmetric sparse matrices, compressed by rows with faer: the scene's K
//! and C, and the scaled K̃ = M^{-1/2} K M^{-1/2} the eigensolvers read.

use faer::sparse::{SparseRowMat, SparseRowMatRef, Triplet};

/// A symmetric sparse matrix, compressed by rows (faer's `SparseRowMat`):
/// K, C, and the scaled K̃ = M^{-1/2} K M^{-1/2}. Built by [`Assembly`]
/// from (row, column, value) triplets, duplicates summed.
#[derive(Clone, Debug)]
pub(crate) struct Sparse {
    mat: SparseRowMat<usize, f64>,
}

impl PartialEq for Sparse {
    fn eq(&self, other: &Sparse) -> bool {
        self.n() == other.n() && (0..self.n()).all(|i| self.row(i).eq(other.row(i)))
    }
}

/// Triplets of a symmetric matrix being assembled.
#[derive(Clone, Debug)]
pub(crate) struct Assembly {
    n: usize,
    triplets: Vec<Triplet<usize, usize, f64>>,
}

impl Assembly {
    /// An n×n matrix with no entries yet.
    pub(crate) fn new(n: usize) -> Assembly {
        Assembly { n, triplets: Vec::new() }
    }

    /// Adds x at (i, j).
    pub(crate) fn add(&mut self, i: usize, j: usize, x: f64) {
        self.triplets.push(Triplet::new(i, j, x));
    }

    /// Adds a two-ended element of coefficient `x` and `dim`×`dim` block
    /// B (row-major) between the degrees of freedom starting at `a` and
    /// `b` (`None`: the end is ground or fixed): x·B on each free end's
    /// diagonal block, −x·B between them. Exact zeros are not stored.
    pub(crate) fn add_block(
        &mut self,
        a: Option<usize>,
        b: Option<usize>,
        dim: usize,
        block: &[f64],
        x: f64,
    ) {
        for (r, c, sign) in [(a, a, 1.0), (b, b, 1.0), (a, b, -1.0), (b, a, -1.0)] {
            if let (Some(r), Some(c)) = (r, c) {
                for p in 0..dim {
                    for q in 0..dim {
                        let v = sign * x * block[p * dim + q];
                        if v != 0.0 {
                            self.add(r + p, c + q, v);
                        }
                    }
                }
            }
        }
    }

    /// The compressed matrix, duplicates summed. The matrix is symmetric
    /// and every entry is added on both sides of the diagonal: the upper
    /// triangle's sums are kept and mirrored, so it is symmetric to the last
    /// bit whatever the order of the sums.
    pub(crate) fn finish(self) -> Sparse {
        let upper: Vec<Triplet<usize, usize, f64>> =
            self.triplets.iter().filter(|t| t.row <= t.col).copied().collect();
        let upper = SparseRowMat::try_new_from_triplets(self.n, self.n, &upper)
            .expect("indices are in range by construction");
        let mut full = Vec::with_capacity(2 * upper.compute_nnz());
        for i in 0..self.n {
            let m = upper.as_ref();
            for (&j, &v) in m.symbolic().col_idx_of_row_raw(i).iter().zip(m.val_of_row(i)) {
                full.push(Triplet::new(i, j, v));
                if j != i {
                    full.push(Triplet::new(j, i, v));
                }
            }
        }
        let mat = SparseRowMat::try_new_from_triplets(self.n, self.n, &full)
            .expect("indices are in range by construction");
        Sparse { mat }
    }
}

impl Sparse {
    /// The n×n zero matrix.
    #[cfg(test)]
    pub(crate) fn zeros(n: usize) -> Sparse {
        Assembly::new(n).finish()
    }

    /// diag(d).
    pub(crate) fn diagonal(d: &[f64]) -> Sparse {
        let mut a = Assembly::new(d.len());
        for (i, &x) in d.iter().enumerate() {
            a.add(i, i, x);
        }
        a.finish()
    }

    /// The size.
    pub(crate) fn n(&self) -> usize {
        self.mat.nrows()
    }

    /// Row i's `(column, value)` entries, increasing column.
    pub(crate) fn row(&self, i: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let m = self.mat.as_ref();
        m.symbolic().col_idx_of_row_raw(i).iter().copied().zip(m.val_of_row(i).iter().copied())
    }

    /// Entry (i, j).
    pub(crate) fn get(&self, i: usize, j: usize) -> f64 {
        let m = self.mat.as_ref();
        let cols = m.symbolic().col_idx_of_row_raw(i);
        cols.binary_search(&j).map_or(0.0, |p| m.val_of_row(i)[p])
    }

    /// faer's view, compressed by rows.
    pub(crate) fn as_faer(&self) -> SparseRowMatRef<'_, usize, f64> {
        self.mat.as_ref()
    }

    /// Whether every entry is zero.
    pub(crate) fn is_zero(&self) -> bool {
        self.mat.as_ref().val().iter().all(|&x| x == 0.0)
    }

    /// Whether row i has no non-zero entry.
    pub(crate) fn row_is_zero(&self, i: usize) -> bool {
        self.mat.as_ref().val_of_row(i).iter().all(|&x| x == 0.0)
    }

    /// (D A D) for the diagonal D = diag(d).
    pub(crate) fn scaled(&self, d: &[f64]) -> Sparse {
        let mut a = Assembly::new(self.n());
        for i in 0..self.n() {
            for (j, x) in self.row(i) {
                a.add(i, j, d[i] * x * d[j]);
            }
        }
        a.finish()
    }

    /// The principal submatrix on the indices `keep` (increasing).
    pub(crate) fn restricted(&self, keep: &[usize]) -> Sparse {
        let mut at = vec![usize::MAX; self.n()];
        for (new, &old) in keep.iter().enumerate() {
            at[old] = new;
        }
        let mut a = Assembly::new(keep.len());
        for (new, &old) in keep.iter().enumerate() {
            for (j, x) in self.row(old) {
                if at[j] != usize::MAX {
                    a.add(new, at[j], x);
                }
            }
        }
        a.finish()
    }

    /// y = A x, rows in parallel (rayon) on large matrices.
    pub(crate) fn mul_vec(&self, x: &[f64], y: &mut [f64]) {
        use rayon::prelude::*;
        let m = self.mat.as_ref();
        let (ptr, cols, vals) = (m.symbolic().row_ptr(), m.symbolic().col_idx(), m.val());
        let row = |i: usize| -> f64 {
            let (a, b) = (ptr[i], ptr[i + 1]);
            cols[a..b].iter().zip(&vals[a..b]).map(|(&j, &v)| v * x[j]).sum()
        };
        if y.len() < 1 << 15 {
            y.iter_mut().enumerate().for_each(|(i, yi)| *yi = row(i));
        } else {
            y.par_chunks_mut(1 << 13).enumerate().for_each(|(c, ys)| {
                for (k, yi) in ys.iter_mut().enumerate() {
                    *yi = row((c << 13) + k);
                }
            });
        }
    }

    /// A certified upper bound on the largest eigenvalue of this symmetric
    /// matrix: Gershgorin's max_i Σ_j |a_ij|, each row sum rounded up by
    /// its length times ε (the error of a sum of that many non-negative
    /// terms), so no rounding brings it below the exact bound.
    pub(crate) fn gershgorin_upper(&self) -> f64 {
        (0..self.n())
            .map(|i| {
                let r = self.mat.as_ref().val_of_row(i);
                let sum: f64 = r.iter().map(|x| x.abs()).sum();
                sum * (1.0 + (r.len() as f64 + 2.0) * f64::EPSILON)
            })
            .fold(0.0, f64::max)
    }

    /// The largest absolute entry.
    pub(crate) fn max_abs(&self) -> f64 {
        self.mat.as_ref().val().iter().fold(0.0, |m, &x| m.max(x.abs()))
    }

    /// xᵀ A x.
    pub(crate) fn quad(&self, x: &[f64]) -> f64 {
        (0..self.n()).map(|i| x[i] * self.row(i).map(|(j, a)| a * x[j]).sum::<f64>()).sum()
    }

    /// Whether A B is symmetric (A, B symmetric: whether they commute), to
    /// `tol` relative to the largest entry of the product.
    pub(crate) fn commutes_with(&self, b: &Sparse, tol: f64) -> bool {
        let n = self.n();
        let mut prod: Vec<std::collections::HashMap<usize, f64>> = vec![Default::default(); n];
        for (i, row) in prod.iter_mut().enumerate() {
            for (k, a) in self.row(i) {
                for (j, x) in b.row(k) {
                    *row.entry(j).or_insert(0.0) += a * x;
                }
            }
        }
        let scale = prod.iter().flat_map(|r| r.values()).fold(0.0f64, |m, x| m.max(x.abs()));
        prod.iter().enumerate().all(|(i, r)| {
            r.iter().all(|(&j, &x)| {
                let y = prod[j].get(&i).copied().unwrap_or(0.0);
                (x - y).abs() <= tol * scale.max(f64::MIN_POSITIVE)
            })
        })
    }
}
