//! The answers of the stability analysis: the verdict over Φ > 0, the
//! critical points and their conditions, the class on every interval, the
//! stable intervals. Types only; the engines in `rational.rs` and
//! `constants.rs` fill them in.

use std::cmp::Ordering;
use std::fmt;

use super::point::Counts;
use crate::univariate::algebraic::Algebraic;
use crate::{RootClass, Q};

/// A critical condition: a polynomial in Φ whose roots may change the class.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Condition {
    /// The leading coefficient a_n vanishes: a root arrives from infinity.
    LeadingCoefficient,
    /// The constant coefficient a_0 vanishes: a root passes through zero.
    ConstantCoefficient,
    /// χ(1) = 0: a real root at +1.
    ChiAtOne,
    /// χ(−1) = 0: a real root at −1.
    ChiAtMinusOne,
    /// Two roots with product 1 (|z|² = 1 for a complex pair).
    UnitCircle,
    /// Two roots of the self-reciprocal factor meet (on the circle, or
    /// leaving it).
    ReciprocalDiscriminant,
    /// Two roots coincide (discriminant of χ in z).
    Discriminant,
    /// Two roots of different kind have the same modulus.
    ModulusTie,
}

impl Condition {
    /// The name used in JSON and reports.
    pub fn name(self) -> &'static str {
        match self {
            Condition::LeadingCoefficient => "leading coefficient",
            Condition::ConstantCoefficient => "constant coefficient",
            Condition::ChiAtOne => "chi(1)",
            Condition::ChiAtMinusOne => "chi(-1)",
            Condition::UnitCircle => "z_i z_j = 1",
            Condition::ReciprocalDiscriminant => "reciprocal discriminant",
            Condition::Discriminant => "discriminant",
            Condition::ModulusTie => "modulus tie",
        }
    }
}

impl fmt::Display for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What happens at the stability limit Φ_max.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Boundary {
    /// Two roots meet at z = −1 (False Euler at Φ = 2).
    DoubleRootAtMinusOne,
    /// Two roots meet at z = +1.
    DoubleRootAtPlusOne,
    /// A real root passes through z = +1.
    RootThroughPlusOne,
    /// A real root passes through z = −1.
    RootThroughMinusOne,
    /// A complex pair crosses the unit circle.
    ComplexPairLeavesCircle,
    /// A complex pair on the unit circle becomes a repeated pair.
    RepeatedPairOnCircle,
    /// The leading coefficient vanishes: a root arrives from infinity.
    RootFromInfinity,
    /// The step's implicit system is singular there: the step is undefined.
    SingularStep,
    /// None of the above was recognised.
    Other,
}

impl Boundary {
    /// The snake_case name used in JSON and reports.
    pub fn name(self) -> &'static str {
        match self {
            Boundary::DoubleRootAtMinusOne => "double_root_at_minus_one",
            Boundary::DoubleRootAtPlusOne => "double_root_at_plus_one",
            Boundary::RootThroughPlusOne => "root_through_plus_one",
            Boundary::RootThroughMinusOne => "root_through_minus_one",
            Boundary::ComplexPairLeavesCircle => "complex_pair_leaves_circle",
            Boundary::RepeatedPairOnCircle => "repeated_pair_on_circle",
            Boundary::RootFromInfinity => "root_from_infinity",
            Boundary::SingularStep => "singular_step",
            Boundary::Other => "other",
        }
    }
}

impl fmt::Display for Boundary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The verdict over Φ > 0 near zero: one of five exclusive states (the
/// last, `UndecidedAt`, only from χ alone).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Stability {
    /// Every 0 < Φ < `phi_max` gives a bounded sequence, and Φ just above
    /// `phi_max` does not.
    Limited {
        /// The stability limit.
        phi_max: Algebraic,
        /// Whether Φ = Φ_max itself is bounded (decided exactly; from the
        /// Jordan structure of P when the analysis was given P).
        bounded_at_phi_max: bool,
        /// What happens at the limit.
        boundary: Boundary,
    },
    /// No Φ > 0 is bounded: every Φ > 0 grows.
    UnboundedForAllPhi,
    /// Every small Φ > 0 grows, but Φ is bounded further out: on the
    /// intervals of [`StabilityReport::stable_intervals`] (a method unstable
    /// near zero, or singular there, that a larger step stabilises).
    UnstableNearZero,
    /// Every Φ > 0 gives a bounded sequence.
    BoundedForAllPhi,
    /// χ alone cannot decide: every 0 < Φ < `at` is bounded, and at `at` a
    /// root on the unit circle is repeated, which is bounded exactly when
    /// the transition matrix P is semisimple there. An analysis given P
    /// ([`Derivation::stability`](crate::Derivation::stability)) decides it
    /// for χ over Q; for χ with exact constants it decides it whenever the
    /// norm of an entry of P − (tr P/2)·I does not vanish there, and else
    /// returns this variant rather than guess (no built-in does).
    UndecidedAt {
        /// The first Φ whose boundedness χ does not decide.
        at: Algebraic,
        /// What happens there.
        boundary: Boundary,
    },
}

impl Stability {
    /// `limited`, `unbounded_for_all_phi`, `unstable_near_zero`,
    /// `bounded_for_all_phi` or `undecided_without_transition_matrix`.
    pub fn name(&self) -> &'static str {
        match self {
            Stability::Limited { .. } => "limited",
            Stability::UndecidedAt { .. } => "undecided_without_transition_matrix",
            Stability::UnboundedForAllPhi => "unbounded_for_all_phi",
            Stability::UnstableNearZero => "unstable_near_zero",
            Stability::BoundedForAllPhi => "bounded_for_all_phi",
        }
    }
}

/// The answer at one rational Φ of an analysis that has the transition
/// matrix P ([`Derivation::class_at`](crate::Derivation::class_at)): the
/// root class of χ, and whether the sequence stays bounded there, decided
/// from P where χ alone cannot (a repeated root on the unit circle is
/// bounded exactly when P is semisimple there).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ClassAt {
    /// The root class of χ.
    pub class: RootClass,
    /// Whether the sequence stays bounded.
    pub bounded: bool,
}

/// A Φ where the root class changes.
#[derive(Clone, Debug)]
pub struct ClassChange {
    /// The critical Φ.
    pub at: Algebraic,
    /// The class just below.
    pub from: RootClass,
    /// The class just above.
    pub to: RootClass,
    /// The class exactly at `at` (`None` when not computed: degree ≥ 3 at an
    /// irrational point).
    pub at_class: Option<RootClass>,
}

/// A maximal open Φ-interval of one class.
#[derive(Clone, Debug)]
pub struct ClassInterval {
    /// Lower end (zero for the first interval).
    pub lo: Algebraic,
    /// Upper end; `None` for ∞.
    pub hi: Option<Algebraic>,
    /// The class everywhere strictly inside.
    pub class: RootClass,
    /// The rational Φ at which the class was decided.
    pub sample: Q,
    /// Distinct roots inside, on and outside the unit circle at the sample.
    pub counts: Counts,
}

/// A critical Φ and the conditions that vanish there.
#[derive(Clone, Debug)]
pub struct CriticalPoint {
    /// The critical Φ.
    pub at: Algebraic,
    /// The vanishing conditions.
    pub conditions: Vec<Condition>,
    /// Whether the sequence is bounded exactly at this Φ; decided at every
    /// point next to a bounded interval, `None` elsewhere, and `None` from χ
    /// alone where a root on the circle is repeated (undecided).
    pub bounded: Option<bool>,
}

/// A maximal Φ-interval on which every step size gives a bounded sequence.
#[derive(Clone, Debug)]
pub struct StableInterval {
    /// Lower end (zero for an interval starting at zero).
    pub lo: Algebraic,
    /// Whether `lo` itself is bounded (false for zero, which is excluded).
    pub lo_closed: bool,
    /// Upper end; `None` for ∞.
    pub hi: Option<Algebraic>,
    /// Whether `hi` itself is bounded.
    pub hi_closed: bool,
}

/// Where the verdict hangs on a term too small to be meaningful.
#[derive(Clone, Debug)]
pub struct Marginal {
    /// c in |z|² − 1 = c·Φ^k + … (exact; 0 < |c| < 10⁻¹²).
    pub coefficient: Q,
    /// k.
    pub power: usize,
    /// The stated growth threshold ε: growth per step at most 1 + ε.
    pub threshold: Q,
    /// The largest Φ with every root |z| ≤ 1 + ε on (0, Φ]; `None` when no
    /// such limit exists (within ε for every Φ).
    pub practical_phi_max: Option<Algebraic>,
}

/// The exact stability analysis over Φ > 0, from
/// [`Derivation::stability`](crate::Derivation::stability).
#[derive(Clone, Debug)]
pub struct StabilityReport {
    /// Degree of χ in z.
    pub degree: usize,
    /// The verdict near Φ = 0.
    pub stability: Stability,
    /// Whether boundedness at multiple roots on the circle was decided from
    /// the transition matrix P (true) or not (false: χ alone, where a
    /// repeated root on the circle is undecided, see
    /// [`Stability::UndecidedAt`]).
    pub from_transition_matrix: bool,
    /// Every class change over Φ > 0, increasing.
    pub class_changes: Vec<ClassChange>,
    /// The classes between the changes, covering (0, ∞).
    pub intervals: Vec<ClassInterval>,
    /// Every maximal interval of bounded Φ, increasing (disjoint).
    pub stable_intervals: Vec<StableInterval>,
    /// Every critical Φ > 0 examined, with its vanishing conditions.
    pub critical_points: Vec<CriticalPoint>,
    /// Set when the verdict near zero hangs on a tiny term.
    pub marginal: Option<Marginal>,
}

impl StabilityReport {
    /// Φ_max when the verdict is [`Stability::Limited`].
    pub fn phi_max(&self) -> Option<&Algebraic> {
        match &self.stability {
            Stability::Limited { phi_max, .. } => Some(phi_max),
            _ => None,
        }
    }

    /// Whether Φ_max itself is bounded, when there is a limit.
    pub fn bounded_at_phi_max(&self) -> Option<bool> {
        match &self.stability {
            Stability::Limited { bounded_at_phi_max, .. } => Some(*bounded_at_phi_max),
            _ => None,
        }
    }

    /// The boundary kind, when there is a limit (or a point χ alone leaves
    /// undecided).
    pub fn boundary(&self) -> Option<Boundary> {
        match &self.stability {
            Stability::Limited { boundary, .. } | Stability::UndecidedAt { boundary, .. } => {
                Some(*boundary)
            }
            _ => None,
        }
    }

    /// The point where an analysis of χ alone stops, when the verdict is
    /// [`Stability::UndecidedAt`].
    pub fn undecided_at(&self) -> Option<&Algebraic> {
        match &self.stability {
            Stability::UndecidedAt { at, .. } => Some(at),
            _ => None,
        }
    }

    /// Bounded for every Φ > 0.
    pub fn bounded_for_all(&self) -> bool {
        self.stability == Stability::BoundedForAllPhi
    }

    /// The class exactly at each change point, in the order of
    /// [`StabilityReport::class_changes`].
    pub fn class_at_changes(&self) -> Vec<Option<RootClass>> {
        self.class_changes.iter().map(|c| c.at_class).collect()
    }

    /// Whether every 0 < Φ < `phi` is bounded (exact).
    pub fn is_stable_below(&self, phi: &Q) -> bool {
        match &self.stability {
            Stability::BoundedForAllPhi => true,
            Stability::UnboundedForAllPhi | Stability::UnstableNearZero => false,
            Stability::Limited { phi_max, .. } => phi_max.cmp_rational(phi) != Ordering::Less,
            Stability::UndecidedAt { at, .. } => at.cmp_rational(phi) != Ordering::Less,
        }
    }
}
