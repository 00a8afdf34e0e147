//! A claim of the paper, what zcheck found about it, and the verdict.
//!
//! A claim never carries a verdict written in code: it carries a
//! [`Finding`], the computed inputs of the check, and [`Claim::new`] asks the
//! one verdict policy ([`super::policy::verdict`]) for the verdict. The
//! fields live in this module so that no section can set a verdict by hand.

use serde::Serialize;

/// How a claim of the paper fares against the derivation (DESIGN.md, "the
/// verdict policy").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The claim holds as printed.
    Confirmed,
    /// True on the range the paper states, or under a condition it leaves
    /// implicit, but not as worded.
    Refined,
    /// False somewhere within what the paper asserts, or a misprint that
    /// changes the mathematics.
    Errata,
    /// A slip that changes nothing (a comment, a name); counted apart from
    /// the errata.
    Typo,
}

impl Verdict {
    /// The lower-case name used in reports.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Confirmed => "confirmed",
            Verdict::Refined => "refined",
            Verdict::Errata => "errata",
            Verdict::Typo => "typo",
        }
    }
}

/// Where a case lies relative to what the paper asserts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Scope {
    /// Inside the range the paper states for the claim (or under the
    /// condition its text implies). When the paper states no narrower range,
    /// every case the wording covers is stated.
    Stated,
    /// Covered only by the wording ("always", "for all systems") beyond the
    /// range the paper states elsewhere.
    Wording,
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
    pub fn same(printed: impl std::fmt::Display, derived: impl std::fmt::Display) -> Finding {
        Finding::Same { printed: printed.to_string(), derived: derived.to_string() }
    }

    /// A statement that must hold in every listed case, all stated.
    pub fn all<S: Into<String>>(cases: impl IntoIterator<Item = (S, bool)>) -> Finding {
        Finding::Cases {
            cases: cases
                .into_iter()
                .map(|(case, holds)| Case { case: case.into(), holds, scope: Scope::Stated })
                .collect(),
        }
    }

    /// Stated cases and cases only the wording covers.
    pub fn scoped<S: Into<String>>(cases: impl IntoIterator<Item = (S, bool, Scope)>) -> Finding {
        Finding::Cases {
            cases: cases
                .into_iter()
                .map(|(case, holds, scope)| Case { case: case.into(), holds, scope })
                .collect(),
        }
    }
}

/// One claim of the paper and zcheck's verdict on it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Claim {
    /// A stable identifier, `sec07.stability_limit` style.
    pub id: String,
    /// The paper's numbering: "4" to "12", or "A" to "E".
    pub section: String,
    /// What the paper says, transcribed as printed.
    pub statement: String,
    /// What zcheck derived.
    pub derived: String,
    /// The verdict: always `policy::verdict(&finding)`.
    verdict: Verdict,
    /// How the verdict was reached (exact derivation, numbers, runs).
    pub evidence: String,
    /// The computed inputs the verdict is derived from.
    finding: Finding,
}

impl Claim {
    /// A claim whose verdict the policy derives from `finding`.
    pub fn new(
        id: String,
        section: String,
        statement: String,
        derived: String,
        finding: Finding,
        evidence: String,
    ) -> Claim {
        let verdict = super::policy::verdict(&finding);
        Claim { id, section, statement, derived, verdict, evidence, finding }
    }

    /// The verdict.
    pub fn verdict(&self) -> Verdict {
        self.verdict
    }

    /// The computed inputs of the verdict.
    pub fn finding(&self) -> &Finding {
        &self.finding
    }

    /// The same claim judged on another finding (for tests that perturb a
    /// claim's computed inputs and watch its verdict move).
    pub fn with_finding(&self, finding: Finding) -> Claim {
        Claim::new(
            self.id.clone(),
            self.section.clone(),
            self.statement.clone(),
            self.derived.clone(),
            finding,
            self.evidence.clone(),
        )
    }
}
