//! What zcheck computed about a claim ([`Finding`]): an object against its
//! transcription, a statement case by case, or a slip. The policy draws the
//! verdict from it.

use serde::Serialize;

/// Where a case lies relative to what the paper asserts.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Scope {
    /// Inside the range the paper states for the claim (or under the
    /// condition its text implies). When the paper states no narrower range,
    /// every case the wording covers is stated.
    Stated,
    /// Covered only by the wording ("always", "for all systems") beyond the
    /// range the paper states elsewhere. A case is never put here without
    /// the reason, which the report prints with the claim's evidence.
    Wording {
        /// Why the paper's statement does not reach the case: the range it
        /// states, computed, or the reading its words leave open.
        reason: String,
    },
}

impl Scope {
    /// Covered only by the wording, for `reason`.
    pub(crate) fn wording(reason: impl Into<String>) -> Scope {
        Scope::Wording { reason: reason.into() }
    }

    /// Whether the paper states the case.
    pub fn is_stated(&self) -> bool {
        matches!(self, Scope::Stated)
    }
}

/// One case of a statement checked case by case: a piece of the Φ axis, a
/// run, a reading.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Case {
    /// The case in words ("0 < Φ < 2", "Cf = 0.3, 100,000 steps").
    pub case: String,
    /// Whether the statement holds there (computed).
    pub holds: bool,
    /// Whether the paper states it there or only its wording covers it.
    pub scope: Scope,
}

/// The computed inputs from which the policy derives a verdict.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Finding {
    /// An object the paper prints (a polynomial, a matrix, a number) against
    /// the one zcheck derived, both in canonical form: equal or not.
    Same {
        /// The paper's object, parsed and written canonically.
        printed: String,
        /// zcheck's object, written the same way.
        derived: String,
    },
    /// A statement checked case by case.
    Cases {
        /// Every case, with where the statement holds.
        cases: Vec<Case>,
    },
    /// A printed text against what it evidently means, and whether the
    /// difference reaches the mathematics (the computed program, the
    /// numbers).
    Slip {
        /// As printed.
        printed: String,
        /// What the context shows was meant.
        intended: String,
        /// Whether the slip changes what the program computes.
        changes_math: bool,
    },
}

impl Finding {
    /// Two objects in canonical form (their `Display`).
    pub(crate) fn same(
        printed: impl std::fmt::Display,
        derived: impl std::fmt::Display,
    ) -> Finding {
        Finding::Same { printed: printed.to_string(), derived: derived.to_string() }
    }

    /// A statement that must hold in every listed case, all stated.
    pub(crate) fn all<S: Into<String>>(cases: impl IntoIterator<Item = (S, bool)>) -> Finding {
        Finding::Cases {
            cases: cases
                .into_iter()
                .map(|(case, holds)| Case { case: case.into(), holds, scope: Scope::Stated })
                .collect(),
        }
    }

    /// Stated cases and cases only the wording covers.
    pub(crate) fn scoped<S: Into<String>>(
        cases: impl IntoIterator<Item = (S, bool, Scope)>,
    ) -> Finding {
        Finding::Cases {
            cases: cases
                .into_iter()
                .map(|(case, holds, scope)| Case { case: case.into(), holds, scope })
                .collect(),
        }
    }
}
