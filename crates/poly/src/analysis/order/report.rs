//! The answers of the order analysis, typed: [`OrderReport`] and its
//! parts ([`Order`], [`FailedCondition`], [`ModifiedTerm`], [`Ssp`], …),
//! the [`Options`] that ask for more, and the small helpers every kind of
//! method shares (an order capped by its forest, with the note that says
//! so).

use super::conditions::Weights;
use super::value::Value;
use crate::error::{Error, ErrorKind};
use crate::{Algebraic, Q};

/// What kind of method a report is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// A Butcher tableau.
    RungeKutta,
    /// A Butcher tableau with an embedded `bhat`.
    EmbeddedPair,
    /// A partitioned Runge–Kutta pair, `[q]` and `[p]`.
    Partitioned,
    /// A splitting: drift and kick coefficients.
    Splitting,
    /// A linear multistep method.
    Multistep,
}

impl Kind {
    /// The snake-case name: `runge_kutta`, `embedded_pair`, `partitioned`,
    /// `splitting`, `multistep`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::RungeKutta => "runge_kutta",
            Kind::EmbeddedPair => "embedded_pair",
            Kind::Partitioned => "partitioned",
            Kind::Splitting => "splitting",
            Kind::Multistep => "multistep",
        }
    }
}

/// An order: exact, or a lower bound past the trees checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Order {
    /// Every condition up to this order holds and one of the next fails.
    Exact(usize),
    /// Every condition checked (up to this order) holds; higher ones were
    /// not checked (the report's notes say why).
    AtLeast(usize),
}

impl Order {
    /// The number: the order, or its lower bound.
    pub fn value(self) -> usize {
        match self {
            Order::Exact(p) | Order::AtLeast(p) => p,
        }
    }

    /// Whether the order is exact (not a lower bound).
    pub fn is_exact(self) -> bool {
        matches!(self, Order::Exact(_))
    }
}

/// A tree of order `order` + 1 whose condition fails.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FailedCondition {
    /// The tree's notation, `[[][]]`.
    pub tree: String,
    /// Its elementary differential, `f''(f,f)`.
    pub differential: String,
    /// Φ(t) − 1/γ(t), exactly.
    pub residual: Value,
}

/// One term of the modified equation ỹ' = f(ỹ) + Σ_k h^k Σ_{|t|=k+1}
/// coefficient(t)·F(t)(ỹ), F(t) the bare elementary differential.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModifiedTerm {
    /// The power k of h.
    pub power: usize,
    /// The tree's notation (order k + 1).
    pub tree: String,
    /// F(t), readable.
    pub differential: String,
    /// The coefficient of h^k F(t)(ỹ).
    pub coefficient: Value,
}

/// The order whose conditions hold to within a tolerance.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ToleranceOrder {
    /// The tolerance T: |Φ(t) − 1/γ(t)| ≤ T counts as holding.
    pub tolerance: Q,
    /// The order with that reading.
    pub order: Order,
}

/// The SSP coefficient: Kraaijevanger's radius of absolute monotonicity.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Ssp {
    /// A finite radius, exact (0 when there is none).
    Radius(Algebraic),
    /// Absolutely monotonic for every r ≥ 0.
    Unbounded,
}

/// What a report computes beyond the defaults.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// The modified equation up to h^N (Runge–Kutta kinds), N ≤
    /// [`MAX_TREE_ORDER`](super::MAX_TREE_ORDER) − 1.
    pub modified: Option<usize>,
    /// The tolerance of [`OrderReport::order_within_tolerance`]; the caller
    /// decides when it applies (decimal input).
    pub tolerance: Option<Q>,
}

/// The answers of the order analysis; a field that does not apply to the
/// kind of method is `None`.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct OrderReport {
    /// The kind of method.
    pub kind: Kind,
    /// The classical order: every tree condition holds up to it (bicolored
    /// trees for partitioned methods, the alternating ones for splittings;
    /// C_q = 0 for multistep methods).
    pub order: Order,
    /// The order on linear problems: R(z) against e^z for Runge–Kutta
    /// kinds; the alternating chains (the oscillator q' = p, p' = −q and
    /// every linear separable system) for partitioned methods and
    /// splittings; the order for multistep methods.
    pub linear_order: Order,
    /// The largest q with b·c^(k−1) = 1/k and A c^(k−1) = c^k/k for k ≤ q
    /// (Runge–Kutta kinds; c as given, else A's row sums).
    pub stage_order: Option<usize>,
    /// b ≥ 0 and M = BA + AᵀB − bbᵀ positive semidefinite (Runge–Kutta
    /// kinds), decided exactly.
    pub algebraically_stable: Option<bool>,
    /// Runge–Kutta kinds: M = 0 for the reduced tableau; partitioned:
    /// b_i â_ij + b̂_j a_ji = b_i b̂_j and b = b̂; splittings: always.
    pub symplectic: Option<bool>,
    /// Runge–Kutta kinds: whether the tableau is DJ- or S-reducible (M = 0
    /// is then sufficient for symplecticity, not necessary, so the reduced
    /// tableau was asked).
    pub reducible: Option<bool>,
    /// The method equals its adjoint up to a permutation of stages (the
    /// reduced tableau, for Runge–Kutta kinds); a splitting's flow sequence
    /// is a palindrome once zero flows are dropped and neighbours of one
    /// kind merged.
    pub symmetric: Option<bool>,
    /// The SSP coefficient (Runge–Kutta kinds); `None` also when it is not
    /// decided (the notes say why).
    pub ssp_coefficient: Option<Ssp>,
    /// The classical order of (A, bhat), for an embedded pair.
    pub embedded_order: Option<Order>,
    /// The linear order of (A, bhat), for an embedded pair.
    pub embedded_linear_order: Option<Order>,
    /// The trees of order `order` + 1 whose conditions fail (Runge–Kutta
    /// kinds; empty when the order is a lower bound).
    pub failed_conditions: Option<Vec<FailedCondition>>,
    /// The modified equation, when asked for (Runge–Kutta kinds).
    pub modified_equation: Option<Vec<ModifiedTerm>>,
    /// The order within the tolerance, when one was given.
    pub order_within_tolerance: Option<ToleranceOrder>,
    /// The embedded estimator's order within the tolerance, for an
    /// embedded pair when one was given.
    pub embedded_order_within_tolerance: Option<ToleranceOrder>,
    /// What the numbers mean where it is not obvious: caps, reducibility,
    /// c differing from the row sums, undecided questions.
    pub notes: Vec<String>,
}

impl OrderReport {
    pub(crate) fn new(kind: Kind, order: Order, linear_order: Order) -> OrderReport {
        OrderReport {
            kind,
            order,
            linear_order,
            stage_order: None,
            algebraically_stable: None,
            symplectic: None,
            reducible: None,
            symmetric: None,
            ssp_coefficient: None,
            embedded_order: None,
            embedded_linear_order: None,
            failed_conditions: None,
            modified_equation: None,
            order_within_tolerance: None,
            embedded_order_within_tolerance: None,
            notes: Vec::new(),
        }
    }
}

/// An order from a forest's answer, with the note when it is a bound.
pub(crate) fn bounded(p: usize, failing: &[usize], what: &str, notes: &mut Vec<String>) -> Order {
    if failing.is_empty() {
        notes.push(format!(
            "every {what} condition up to order {p} holds; higher orders are not checked \
             (trees up to order {p} are generated), so the order is at least {p}"
        ));
        Order::AtLeast(p)
    } else {
        Order::Exact(p)
    }
}

pub(crate) fn shape(message: String) -> Error {
    Error::analysis(ErrorKind::Syntax, message)
}

/// The order within `options.tolerance`, when one is given.
pub(crate) fn within(w: &mut Weights, options: &Options, what: &str) -> Option<ToleranceOrder> {
    let t = options.tolerance.as_ref()?;
    let (p, failing) = w.order_within(t);
    let mut ignored = Vec::new();
    let order = bounded(p, &failing, what, &mut ignored);
    Some(ToleranceOrder { tolerance: t.clone(), order })
}
