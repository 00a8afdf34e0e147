//! Integration tests of the `poly` crate, built as one test binary.
//!
//! - `algebra`: ring laws of [`poly::Poly`] and the [`poly::UPoly`] toolkit;
//! - `design`: the exact optimiser's known optima, against the front
//!   door's values and bisection (issue 37);
//! - `det`: Berkowitz against the Laplace oracle, det(AB) = det(A)·det(B);
//! - `routes`: the two derivations agree on random step programs, and the
//!   transition matrix matches an independent exact interpreter;
//! - `large`: RK4 on spring chains and 100,000 temporaries, fast paths
//!   against slow ones;
//! - `errors`: every kind of bad `.zm` input gives a located error, and the
//!   parser never panics;
//! - `fuzz_corpus`: the fuzz targets' corpora and crash regressions, replayed;
//! - `parser`: details of the expression language; `language`: declarations
//!   anywhere, constant expressions and equations in the unknowns (issue 27);
//! - `region`: the exact (Φ, D) region against closed forms;
//! - `snapshots`: each built-in's derivation, reviewed against the paper;
//! - `cost`: operation counts; `series`: exact Ψ and |z|² series;
//! - `stability`: the exact stability analysis; `sturm`: Sturm sequences and
//!   real algebraic numbers against brute-force oracles;
//! - `tableau`: Butcher tableaux derive their built-ins' χ;
//! - `order`: order conditions by trees, SSP, PSD, partitioned methods,
//!   splittings and modified equations against their oracles (issue 35).

mod algebra;
mod common;
mod cost;
mod design;
mod det;
mod double_root;
mod errors;
mod front_door;
mod fuzz_corpus;
mod implicit;
mod invariant;
mod language;
mod large;
mod multistep;
mod order;
mod parser;
mod plane;
mod random_programs;
mod region;
mod routes;
mod series;
use testkit::snapshot;
mod snapshots;
mod stability;
mod sturm;
mod tableau;
