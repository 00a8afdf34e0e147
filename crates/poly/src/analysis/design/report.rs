//! The answer types of the exact optimiser: the objective, the free
//! parameters with their ranges, the score (an exact number or +∞), the
//! optimum with where it is attained and why (the certificate), and the
//! exact grid check. Types only; `one.rs` and `two.rs` fill them in.

use std::cmp::Ordering;
use std::fmt;

use crate::error::{Error, ErrorKind};
use crate::{Algebraic, Q};

/// What is maximised.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Objective {
    /// Φ_max on the oscillator ([`Derivation::stability`](crate::Derivation::stability)).
    PhiMax,
    /// The stable length of the negative real axis of y' = λy.
    RealLimit,
    /// The stable half-length of the imaginary axis of y' = λy.
    ImagLimit,
    /// Kraaijevanger's radius of absolute monotonicity (a tableau).
    SspCoefficient,
}

impl Objective {
    /// `phi_max`, `real_limit`, `imag_limit` or `ssp_coefficient`.
    pub fn name(self) -> &'static str {
        match self {
            Objective::PhiMax => "phi_max",
            Objective::RealLimit => "real_limit",
            Objective::ImagLimit => "imag_limit",
            Objective::SspCoefficient => "ssp_coefficient",
        }
    }

    /// The objective of that name; the error lists the four.
    pub fn parse(name: &str) -> Result<Objective, Error> {
        [Objective::PhiMax, Objective::RealLimit, Objective::ImagLimit, Objective::SspCoefficient]
            .into_iter()
            .find(|o| o.name() == name)
            .ok_or_else(|| {
                Error::analysis(
                    ErrorKind::Unsupported,
                    format!(
                        "unknown objective {name:?}: expected phi_max, real_limit, imag_limit or \
                         ssp_coefficient"
                    ),
                )
            })
    }
}

impl fmt::Display for Objective {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A value of the objective: an exact real number, or +∞ (stable for every
/// step). A method stable for no step > 0 scores 0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Score {
    /// A finite value, exact.
    Finite(Algebraic),
    /// +∞.
    Infinite,
}

impl Score {
    /// 0.
    pub fn zero() -> Score {
        Score::Finite(Algebraic::zero())
    }

    /// The finite value, if it is one.
    pub fn finite(&self) -> Option<&Algebraic> {
        match self {
            Score::Finite(a) => Some(a),
            Score::Infinite => None,
        }
    }

    /// The closed form (`2*sqrt(5)`), `inf`, or the root description.
    pub fn describe(&self) -> String {
        match self {
            Score::Finite(a) => match a.closed_form() {
                Some(c) => c,
                None => {
                    let width = Q::new(1.into(), (1i64 << 40).into());
                    format!("{} (about {})", a.refine(&width).describe("x"), a.to_decimal(6))
                }
            },
            Score::Infinite => "inf".to_owned(),
        }
    }
}

impl PartialOrd for Score {
    fn partial_cmp(&self, other: &Score) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Score {
    fn cmp(&self, other: &Score) -> Ordering {
        match (self, other) {
            (Score::Finite(a), Score::Finite(b)) => a.cmp(b),
            (Score::Finite(_), Score::Infinite) => Ordering::Less,
            (Score::Infinite, Score::Finite(_)) => Ordering::Greater,
            (Score::Infinite, Score::Infinite) => Ordering::Equal,
        }
    }
}

impl fmt::Display for Score {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.describe())
    }
}

/// A free parameter and its exact range [lo, hi].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FreeParam {
    /// The parameter's name, as the method declares it.
    pub name: String,
    /// The lower end (included).
    pub lo: Q,
    /// The upper end (included).
    pub hi: Q,
}

impl FreeParam {
    /// `name ∈ [lo, hi]`; an empty range (lo > hi) is refused when the
    /// problem is solved.
    pub fn new(name: &str, lo: Q, hi: Q) -> FreeParam {
        FreeParam { name: name.to_owned(), lo, hi }
    }
}

/// The objective evaluated exactly on a grid of the allowed set.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GridCheck {
    /// How many points were evaluated.
    pub points: usize,
    /// The largest value found (never above the optimum).
    pub max: Score,
    /// The first grid point where it was found (a point of a finite
    /// allowed set may be irrational).
    pub at: Vec<(String, Algebraic)>,
}

/// The exact optimum of an objective over a box of parameters.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub struct Design {
    /// What was maximised.
    pub objective: Objective,
    /// The free parameters and their ranges.
    pub params: Vec<FreeParam>,
    /// The supremum over the allowed set, exact.
    pub optimum: Score,
    /// Whether some point attains it (false: it is approached only).
    pub attained: bool,
    /// Where: the lexicographically smallest maximiser, or the limit point.
    pub at: Vec<(String, Algebraic)>,
    /// Plain-language lines that make the optimum checkable.
    pub certificate: Vec<String>,
    /// The exact grid check.
    pub grid_check: GridCheck,
    /// How many candidate points the exact search evaluated.
    pub candidates: usize,
}

/// The most degree a breakpoint polynomial may have: past it the exact
/// search stops and says so.
pub const MAX_BREAKPOINT_DEGREE: usize = 400;

/// The largest degree (in the two parameters together) of an equation of
/// the two-parameter search whose common factors with its partner are
/// sought: past it the remainder sequence swells for minutes, so the search
/// stops and names this bound (the examples' systems stay at 30 or less).
pub const MAX_SYSTEM_DEGREE: usize = 32;

/// The grid's points along one parameter (one parameter: 201 points; two:
/// 50 × 50).
pub const GRID_ONE: usize = 201;
/// Points per side of the two-parameter grid.
pub const GRID_TWO: usize = 50;

/// The error of an exact search that cannot finish.
pub(crate) fn bound_error(what: String) -> Error {
    Error::analysis(ErrorKind::Unsupported, what)
}

/// An input the optimiser refuses.
pub(crate) fn input_error(what: String) -> Error {
    Error::analysis(ErrorKind::Unsupported, what)
}
