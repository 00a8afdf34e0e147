//! Layer 4, the method language: the `.zm` syntax, [`Method`](method::Method)
//! and its lowering to a linear step, the one registry of built-ins,
//! [`Params`](params::Params), Butcher-tableau and linear multistep input.
//!
//! Imports only from the layers below (`arith`, `univariate`,
//! `multivariate`).

pub mod builtins;
pub(crate) mod constant;
pub(crate) mod generated;
pub(crate) mod load;
pub(crate) mod lower;
pub(crate) mod method;
pub mod multistep;
pub(crate) mod params;
pub mod partitioned;
pub(crate) mod syntax;
pub(crate) mod system;
pub mod tableau;
