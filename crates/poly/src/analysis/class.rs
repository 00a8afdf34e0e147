//! The taxonomy of section 4: what the roots of χ(z) say about a sample
//! sequence.
//!
//! The class is decided by the dominant root(s), those of largest modulus ρ,
//! because they govern the long-run behaviour. The paper lists real roots in
//! (0, ∞) and complex pairs; the negative real axis (an alternating sequence,
//! Ψ = π) and repeated roots on the unit circle complete the picture. This
//! type is shared by the exact analysis (`poly`) and the numeric witnesses
//! (`check`), so both speak the same words.

use std::fmt;

/// The behaviour of a sample sequence, decided by its dominant root(s).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum RootClass {
    /// Every root is zero: the sequence vanishes after finitely many steps.
    Deadbeat,
    /// Dominant complex pair with |z| < 1.
    DampedOscillation,
    /// Dominant simple complex pair with |z| = 1.
    Harmonic,
    /// Dominant complex pair with |z| > 1.
    UnstableOscillation,
    /// Dominant real root 0 < z < 1.
    MonotonicStable,
    /// Dominant simple real root z = 1.
    Constant,
    /// Dominant real root z > 1.
    MonotonicUnstable,
    /// Dominant real root −1 < z < 0: sign flips every step, decaying.
    AlternatingStable,
    /// Dominant simple real root z = −1: sign flips every step, Ψ = π.
    Alternating,
    /// Dominant real root z < −1: sign flips every step, growing.
    AlternatingUnstable,
    /// A repeated root on the unit circle (z₁ = z₂ = ±1, or a repeated pair):
    /// polynomial growth when the root is defective in P, as section 4
    /// notes, bounded when P is semisimple there (P = −I). χ alone does
    /// not tell which ([`RootClass::bounded`] is `None`).
    DoubleRootOnCircle,
    /// The step is undefined: its implicit system is singular (det A = 0).
    Singular,
}

impl RootClass {
    /// Every class, in a fixed order.
    pub const ALL: [RootClass; 12] = [
        RootClass::Deadbeat,
        RootClass::DampedOscillation,
        RootClass::Harmonic,
        RootClass::UnstableOscillation,
        RootClass::MonotonicStable,
        RootClass::Constant,
        RootClass::MonotonicUnstable,
        RootClass::AlternatingStable,
        RootClass::Alternating,
        RootClass::AlternatingUnstable,
        RootClass::DoubleRootOnCircle,
        RootClass::Singular,
    ];

    /// The snake_case name used in JSON and reports.
    pub fn name(self) -> &'static str {
        match self {
            RootClass::Deadbeat => "deadbeat",
            RootClass::DampedOscillation => "damped_oscillation",
            RootClass::Harmonic => "harmonic",
            RootClass::UnstableOscillation => "unstable_oscillation",
            RootClass::MonotonicStable => "monotonic_stable",
            RootClass::Constant => "constant",
            RootClass::MonotonicUnstable => "monotonic_unstable",
            RootClass::AlternatingStable => "alternating_stable",
            RootClass::Alternating => "alternating",
            RootClass::AlternatingUnstable => "alternating_unstable",
            RootClass::DoubleRootOnCircle => "double_root_on_circle",
            RootClass::Singular => "singular",
        }
    }

    /// The class with this [`RootClass::name`].
    pub fn from_name(name: &str) -> Option<RootClass> {
        RootClass::ALL.into_iter().find(|c| c.name() == name)
    }

    /// Whether the sequence stays bounded, as far as the roots of χ tell:
    /// `Some(true)` when ρ < 1, or ρ = 1 with simple dominant roots;
    /// `Some(false)` when ρ > 1 or the step is singular; `None` for
    /// [`RootClass::DoubleRootOnCircle`], which χ alone cannot decide: a
    /// repeated root on the circle is bounded exactly when the transition
    /// matrix P is semisimple there (False Euler at Φ = 2 grows, P = −I
    /// does not). [`Derivation::class_at`](crate::Derivation::class_at)
    /// decides it from P.
    pub fn bounded(self) -> Option<bool> {
        match self {
            RootClass::Deadbeat
            | RootClass::DampedOscillation
            | RootClass::Harmonic
            | RootClass::MonotonicStable
            | RootClass::Constant
            | RootClass::AlternatingStable
            | RootClass::Alternating => Some(true),
            RootClass::UnstableOscillation
            | RootClass::MonotonicUnstable
            | RootClass::AlternatingUnstable
            | RootClass::Singular => Some(false),
            RootClass::DoubleRootOnCircle => None,
        }
    }
}

impl fmt::Display for RootClass {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
