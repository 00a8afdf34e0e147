//! The search over a box of two parameters (to come).

use super::problem::{Problem, Setup};
use super::report::{input_error, Score};
use super::system::Breakpoints;
use crate::error::Error;
use crate::Algebraic;

pub(crate) type Found = (Score, bool, Vec<Algebraic>, Vec<String>, usize);

pub(crate) fn search_box(
    _problem: &Problem,
    _s: &Setup,
    _polys: &[Breakpoints],
) -> Result<Found, Error> {
    Err(input_error("two parameters: not yet".into()))
}
