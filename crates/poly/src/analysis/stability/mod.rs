//! Exact stability analysis of a characteristic polynomial χ(z; Φ) over all
//! step sizes Φ > 0, in time polynomial in the degree of χ.
//!
//! The root class of χ (section 4's taxonomy, [`RootClass`]) can change only
//! at finitely many *critical* Φ, the positive roots of the polynomials in
//! Φ listed in `conditions`: the leading and constant coefficients, χ(1),
//! χ(−1), the unit-circle condition ∏_{i<j}(1 − z_i z_j) (Jury's inners
//! determinant, of degree ≤ (n − 1)·deg_Φ; for a self-reciprocal factor the
//! discriminant of G with g(z) = z^m G(z + 1/z)), the discriminant in z, and
//! ties for the largest modulus. Each is computed over Z\[Φ\] by modular
//! evaluation and interpolation, made square-free, and its positive real
//! roots are isolated with Sturm sequences as exact [`Algebraic`] numbers.
//!
//! Between consecutive critical points the counts of roots inside, on and
//! outside the unit circle, and the class, are constant; one exact
//! computation at a rational sample decides them ([`point`]: Schur–Cohn
//! inertia over Q, real-root isolation, rational brackets of the dominant
//! modulus). At each critical point the class is exact for rational points
//! and for second-order χ (signs of polynomials at an algebraic number);
//! boundedness at a critical point next to a bounded interval is decided
//! for any degree in Q(α): a repeated root on the circle (gcds over Q(α))
//! makes χ alone unbounded, and with the transition matrix P
//! ([`analyze_derivation`]) the root is bounded exactly when it is
//! semisimple: rank q(P) = rank q(P)² for the square-free q of the repeated
//! roots on the circle.
//!
//! No float decides anything.
//!
//! Limitations (stated, not hidden): for degree ≥ 5, ties for the largest
//! modulus between a real root and a complex pair are not among the critical
//! conditions, so a class change (monotonic ↔ oscillatory) from such a tie
//! inside an interval could go unlisted; for degree ≥ 3 the class exactly at
//! an irrational critical point is not computed (`at_class` is `None`),
//! while boundedness there is. The stability limit and the bounded/unbounded
//! split are exact for every degree, because boundedness changes only where
//! a root meets the unit circle.

mod conditions;
pub mod constants;
pub mod point;
mod rational;

use std::cmp::Ordering;
use std::collections::HashMap;
use std::fmt;

pub use point::{
    circle_counts, classify, classify_pq, classify_roots_by_products, Counts, PqSigns,
};
pub use rational::{analyze, analyze_derivation};

use crate::error::Error;
use crate::univariate::algebraic::Algebraic;
use crate::{Poly, RootClass, Sym, Q};

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
            Boundary::Other => "other",
        }
    }
}

impl fmt::Display for Boundary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The verdict over Φ > 0 near zero: one of three exclusive states.
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
    /// No Φ > 0 is bounded near zero: every small Φ > 0 grows. (Bounded
    /// intervals further out, if any, are in
    /// [`StabilityReport::stable_intervals`].)
    UnboundedForAllPhi,
    /// Every Φ > 0 gives a bounded sequence.
    BoundedForAllPhi,
}

impl Stability {
    /// `limited`, `unbounded_for_all_phi` or `bounded_for_all_phi`.
    pub fn name(&self) -> &'static str {
        match self {
            Stability::Limited { .. } => "limited",
            Stability::UnboundedForAllPhi => "unbounded_for_all_phi",
            Stability::BoundedForAllPhi => "bounded_for_all_phi",
        }
    }
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
    /// point next to a bounded interval, `None` elsewhere.
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

/// The result of [`analyze`].
#[derive(Clone, Debug)]
pub struct StabilityReport {
    /// Degree of χ in z.
    pub degree: usize,
    /// The verdict near Φ = 0.
    pub stability: Stability,
    /// Whether boundedness at multiple roots on the circle was decided from
    /// the transition matrix P (true) or from χ alone (false: a repeated
    /// root on the circle counts as unbounded).
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

    /// The boundary kind, when there is a limit.
    pub fn boundary(&self) -> Option<Boundary> {
        match &self.stability {
            Stability::Limited { boundary, .. } => Some(*boundary),
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
            Stability::UnboundedForAllPhi => false,
            Stability::Limited { phi_max, .. } => phi_max.cmp_rational(phi) != Ordering::Less,
        }
    }
}

/// The root class of χ at a rational Φ, exactly.
pub fn class_at(charpoly: &Poly, phi: &Q) -> Result<RootClass, Error> {
    // Exact constants (sqrt(3), cbrt(2)): the norm-based layer.
    if crate::multivariate::constants::has_generators(charpoly) {
        return crate::analysis::stability::constants::class_at(charpoly, phi);
    }
    let chi = conditions::Charpoly::new(charpoly)?;
    Ok(rational::class_at_rational(&chi, phi).0)
}

/// The root class of χ exactly at an algebraic Φ; `Ok(None)` when χ has
/// degree ≥ 3 and Φ is irrational (not computed, see the module notes).
pub fn class_at_algebraic(charpoly: &Poly, phi: &Algebraic) -> Result<Option<RootClass>, Error> {
    let chi = conditions::Charpoly::new(charpoly)?;
    Ok(rational::class_at_point(&chi, phi))
}

/// Substitutes rational values for every parameter except Φ (and z).
pub fn substitute_params(charpoly: &Poly, values: &HashMap<Sym, Q>) -> Poly {
    charpoly.eval_partial(values)
}
