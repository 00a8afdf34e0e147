//! Everything past the front door, for callers who need the machinery
//! itself: the built-in registry, the two derivation routes one at a time,
//! the implicit system, the lowered program, the analysis of a bare χ, real
//! root isolation, series, the (Φ, parameter) region, equivalences and
//! conserved forms.
//!
//! A question that [`Derivation`](crate::Derivation) answers should be
//! asked of it: the routes here answer narrower questions. In particular
//! [`stability::analyze`] sees χ alone, so a repeated root on the unit
//! circle is undecided there, where
//! [`Derivation::stability`](crate::Derivation::stability) decides it from
//! the transition matrix.

pub use crate::analysis::{
    cost, design, equiv, invariant, order, plane, region, series, stability,
};
pub use crate::derive::routes::{
    charpoly, charpoly_state_route, charpoly_z_route, transition_matrix, w, z_matrix,
    ReducedZMatrix,
};
#[doc(hidden)]
pub use crate::derive::routes::{charpoly_z_route_dense, derive_both_routes};
pub use crate::error::{show_invisible, Warning};
pub use crate::lang::method::{
    Assign, Constant, EndValue, Equation, GaussSeidelRead, Operand, Target, Unknown,
};
pub use crate::lang::syntax::parse_number;
pub use crate::lang::system::{system as implicit_system, System as ImplicitSystem};
pub use crate::lang::{builtins, multistep, partitioned, tableau};
pub use crate::multivariate::constants as field;
pub use crate::multivariate::matrix::SparsePolyMatrix;
pub use crate::multivariate::poly::Monomial;
pub use crate::multivariate::resultant::{circle_conditions, resultant, CircleConditions};
/// Sturm sequences, root counts and real-root isolation over Q.
pub mod sturm {
    pub use crate::univariate::roots::isolate_real_roots;
    pub use crate::univariate::sturm::*;
}
