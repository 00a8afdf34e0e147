//! The verdict policy: the verdicts, and the one function that turns what
//! zcheck computed about a claim into a verdict (DESIGN.md, "the verdict
//! policy").
//!
//! - `Same`: the printed object equals the derived one: confirmed; else
//!   errata (a misprint that changes the mathematics).
//! - `Cases`: every case holds: confirmed; every stated case holds but a
//!   case only the wording covers fails: refined; a stated case fails (or
//!   nothing was checked): errata.
//! - `Slip`: the text is what was meant: confirmed; it is not, but the
//!   program computes the same: typo; it computes something else: errata.

use serde::Serialize;

use super::finding::Finding;

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
    pub(crate) fn name(self) -> &'static str {
        match self {
            Verdict::Confirmed => "confirmed",
            Verdict::Refined => "refined",
            Verdict::Errata => "errata",
            Verdict::Typo => "typo",
        }
    }
}

/// The verdict of a finding.
pub fn verdict(finding: &Finding) -> Verdict {
    match finding {
        Finding::Same { printed, derived } => {
            if printed == derived {
                Verdict::Confirmed
            } else {
                Verdict::Errata
            }
        }
        Finding::Cases { cases } => {
            let stated_fail = cases.iter().any(|c| c.scope.is_stated() && !c.holds);
            let stated_any = cases.iter().any(|c| c.scope.is_stated());
            if cases.is_empty() || !stated_any || stated_fail {
                Verdict::Errata
            } else if cases.iter().all(|c| c.holds) {
                Verdict::Confirmed
            } else {
                Verdict::Refined
            }
        }
        Finding::Slip { printed, intended, changes_math } => {
            if printed == intended {
                Verdict::Confirmed
            } else if *changes_math {
                Verdict::Errata
            } else {
                Verdict::Typo
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paper::finding::{Case, Scope};

    fn case(holds: bool, scope: Scope) -> Case {
        Case { case: String::new(), holds, scope }
    }

    /// Every branch of the policy, once.
    #[test]
    fn policy_table() {
        let check = |f: Finding, v: Verdict| assert_eq!(verdict(&f), v, "{f:?}");
        check(Finding::same("1", "1"), Verdict::Confirmed);
        check(Finding::same("1", "2"), Verdict::Errata);
        let (stated, wording) = (Scope::Stated, Scope::wording("a reason"));
        let cases = |c: Vec<Case>| Finding::Cases { cases: c };
        check(
            cases(vec![case(true, stated.clone()), case(true, wording.clone())]),
            Verdict::Confirmed,
        );
        check(
            cases(vec![case(true, stated.clone()), case(false, wording.clone())]),
            Verdict::Refined,
        );
        check(cases(vec![case(false, stated), case(true, wording.clone())]), Verdict::Errata);
        check(cases(vec![case(true, wording)]), Verdict::Errata);
        check(cases(vec![]), Verdict::Errata);
        let slip = |p: &str, i: &str, m: bool| Finding::Slip {
            printed: p.into(),
            intended: i.into(),
            changes_math: m,
        };
        check(slip("a", "a", false), Verdict::Confirmed);
        check(slip("a", "b", false), Verdict::Typo);
        check(slip("a", "b", true), Verdict::Errata);
    }
}
