//! Matrices of polynomials and their determinants ([`routes`] chooses the
//! path).
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
//! - the sparse multivariate Berkowitz ([`polymatrix`]), always applicable, the
//!   reference the others are tested against.
//!
//! [`echelon`] is fraction-free Gauss–Jordan elimination (ranks, null spaces
//! and solutions over the rational functions, without fractions).
//!
//! [`sparse`] holds [`SparsePolyMatrix`], the storage for matrices with one
//! row per program line (the z-domain matrix M), which are mostly zero.

mod dense;
pub(crate) mod echelon;
pub(crate) mod modular;
pub(crate) mod polymatrix;
mod routes;
mod sparse;

pub use polymatrix::PolyMatrix;
pub use sparse::SparsePolyMatrix;
