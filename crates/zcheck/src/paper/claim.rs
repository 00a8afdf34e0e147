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
    /// The printed line as it should read, where the claim is an erratum or
    /// a slip and the section computed it; the report falls back on the
    /// finding's derived object or intended text.
    pub corrected: Option<String>,
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
        Claim { id, section, statement, derived, corrected: None, verdict, evidence, finding }
    }

    /// The verdict.
    pub fn verdict(&self) -> Verdict {
        self.verdict
    }

    /// The computed inputs of the verdict.
    pub fn finding(&self) -> &Finding {
        &self.finding
    }

    /// The corrected line: the one the section computed, else the finding's
    /// derived object (an object against its transcription) or intended
    /// text (a slip); `None` for a statement checked case by case without
    /// a computed correction.
    pub fn correction(&self) -> Option<&str> {
        self.corrected.as_deref().or(match &self.finding {
            Finding::Same { derived, .. } => Some(derived.as_str()),
            Finding::Slip { intended, .. } => Some(intended.as_str()),
            Finding::Cases { .. } => None,
        })
    }

    /// The cases where the statement fails, each with the reason it lies
    /// beyond what the paper states (`None` for a stated case).
    pub fn failing_cases(&self) -> Vec<(&str, Option<&str>)> {
        match &self.finding {
            Finding::Cases { cases } => cases
                .iter()
                .filter(|c| !c.holds)
                .map(|c| {
                    let reason = match &c.scope {
                        super::finding::Scope::Wording { reason } => Some(reason.as_str()),
                        super::finding::Scope::Stated => None,
                    };
                    (c.case.as_str(), reason)
                })
                .collect(),
            _ => Vec::new(),
        }
    }

    /// The same claim judged on another finding (for tests that perturb a
    /// claim's computed inputs and watch its verdict move).
    pub fn with_finding(&self, finding: Finding) -> Claim {
        let mut c = Claim::new(
            self.id.clone(),
            self.section.clone(),
            self.statement.clone(),
            self.derived.clone(),
            finding,
            self.evidence.clone(),
        );
        c.corrected = self.corrected.clone();
        c
    }
}
