#![deny(missing_docs)]
//! Exact characteristic polynomials of linear time integrators.
//!
//! `poly` is the exact half of zcheck. It reads a method written in the
//! `.zm` language, lowers it to a linear step program, and derives the
//! method's characteristic polynomial χ(z) twice, by the z-domain
//! polynomial-matrix determinant and by det(zI − P), refusing to answer when
//! the two disagree. Everything is exact: rationals ([`Q`]), canonical sparse
//! polynomials over named symbols ([`Poly`]), dense univariate polynomials
//! ([`UPoly`]) and polynomial matrices ([`PolyMatrix`]).
//!
//! # The front door
//!
//! A [`Method`] comes from `.zm` text ([`Method::parse`]), a Butcher tableau
//! ([`Method::from_tableau`]) or a built-in's name ([`builtin`]);
//! [`derive()`] gives its [`Derivation`], which answers every question:
//! [`Derivation::charpoly`], [`Derivation::transition_matrix`],
//! [`Derivation::stability`] (exact limits and classes over Φ, boundedness
//! at a repeated root on the unit circle decided from P),
//! [`Derivation::psi_series`], [`Derivation::cost`], [`Derivation::region`],
//! [`Derivation::relate`], [`Derivation::conserved_form`]. Parameters other
//! than Φ are bound with [`Params`]. What lies past the front door is in
//! [`advanced`].
//!
//! ```
//! let d = poly::derive(&poly::Method::builtin("gauss_legendre_2")?)?;
//! let report = d.stability(&poly::Params::new())?;
//! assert_eq!(report.stability, poly::Stability::BoundedForAllPhi); // A-stable
//! # Ok::<(), poly::Error>(())
//! ```
//!
//! # Layers
//!
//! Inside, the crate is six layers, each importing only from those below:
//! `arith` (Q, integer gcds, Z/p), `univariate` (UPoly, real roots,
//! algebraic numbers), `multivariate` (Poly, polynomial matrices, exact
//! constants), `lang` (the `.zm` language, built-ins, tableaux), `derive`
//! (the two routes) and `analysis` (stability, series, region, equivalence,
//! invariants, cost).
//!
//! This crate never touches `f64` and never does I/O; numeric work lives in
//! the `check` crate.
//!
//! ```
//! let m = poly::builtin("standard_heun")?;
//! let d = poly::derive(&m)?;
//! let (p, q) = d.p_q().expect("second order");
//! assert_eq!(p.to_string(), "1 - 1/2*Phi^2");
//! assert_eq!(q.to_string(), "1 + 1/4*Phi^4");
//! # Ok::<(), poly::Error>(())
//! ```
//!
//! # Input safety
//!
//! `.zm` text is untrusted input. The parser is a recursive-descent parser
//! with limits on tokens per line (which bounds expression nesting),
//! exponents and history depth, so no input makes it recurse or allocate
//! without bound, and none makes it panic (property-tested). Every
//! analysis is exact: no tolerance decides anything, and fast paths (dense
//! integer determinants) fall back to the exact path on overflow.
//!
//! # Error reporting
//!
//! [`Error`] is the crate's one error type: [`Error::kind`] to branch on, and
//! a message that starts with `file:line:column:` and says what was
//! expected, followed by the offending line and a caret:
//!
//! ```
//! let e = poly::Method::parse("bad.zm", "method m\nstate v y\nv = v*y\n").unwrap_err();
//! assert_eq!(e.kind(), poly::ErrorKind::Nonlinear);
//! assert!(e.to_string().starts_with("bad.zm:3:5: nonlinear term"));
//! ```

pub mod advanced;
mod analysis;
mod arith;
mod derive;
mod error;
mod lang;
mod multivariate;
#[cfg(test)]
mod testing;
mod univariate;

pub use crate::analysis::class::RootClass;
pub use crate::analysis::cost::{OpCount, StepCost};
pub use crate::analysis::equiv::Relation;
pub use crate::analysis::plane::{PlaneReport, Sector};
pub use crate::analysis::stability::{
    Boundary, ClassChange, ClassInterval, Condition, CriticalPoint, Stability, StabilityReport,
    StableInterval,
};
pub use crate::arith::rational::{q, Q};
pub use crate::derive::routes::{derive, derive_source, Derivation};
pub use crate::error::{Error, ErrorKind, Span};
pub use crate::lang::builtins::builtin;
pub use crate::lang::method::Method;
pub use crate::lang::params::Params;
pub use crate::multivariate::matrix::PolyMatrix;
pub use crate::multivariate::poly::Poly;
pub use crate::multivariate::sym::Sym;
pub use crate::univariate::algebraic::Algebraic;
pub use crate::univariate::upoly::UPoly;
