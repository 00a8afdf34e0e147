//! A claim of the paper, what zcheck found about it, and the verdict.
//!
//! A claim never carries a verdict written in code: it carries a
//! [`Finding`], the computed inputs of the check, and [`Claim::new`] asks the
//! one verdict policy ([`super::policy::verdict`]) for the verdict. The
//! fields live in this module so that no section can set a verdict by hand.

use serde::Serialize;

use super::finding::Finding;
use super::policy;
use super::policy::Verdict;

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
    pub(crate) fn new(
        id: String,
        section: String,
        statement: String,
        derived: String,
        finding: Finding,
        evidence: String,
    ) -> Claim {
        let verdict = policy::verdict(&finding);
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
