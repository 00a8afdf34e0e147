//! The determinant and characteristic polynomial of a [`PolyMatrix`], by
//! the fastest exact path that applies: dense `i128` Berkowitz in one
//! symbol, then the modular path, then sparse Berkowitz (the reference).

use super::polymatrix::PolyMatrix;
use super::{dense, modular};
use crate::{Poly, Sym};

/// Up to this size the sparse Berkowitz beats the modular path's setup
/// (primes, CRT constants, a grid), so multivariate matrices this small stay
/// on it (measured on the built-ins, whose z-route matrices are 1×1 to 4×4).
const SMALL: usize = 4;

impl PolyMatrix {
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

    /// The determinant: Berkowitz on the dense path for a matrix in one
    /// symbol, else the modular path, else Berkowitz on the sparse path.
    #[track_caller]
    pub fn det(&self) -> Poly {
        assert_eq!(self.rows, self.cols, "determinant of a non-square matrix");
        // Triangular (a diagonally implicit Runge–Kutta step's system, an
        // explicit one's): the product of the diagonal.
        let n = self.rows;
        let zero_above = (0..n).all(|i| (i + 1..n).all(|j| self[(i, j)].is_zero()));
        if zero_above || (0..n).all(|i| (0..i).all(|j| self[(i, j)].is_zero())) {
            return (0..n).fold(Poly::one(), |acc, i| &acc * &self[(i, i)]);
        }
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
}
