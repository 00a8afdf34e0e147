//! The executable proof of the paper, as data: every claim the paper makes,
//! what zcheck derived, and a verdict.
//!
//! `zcheck paper` prints these claims; the tests in `tests/paper/` assert
//! them. A claim's `statement` transcribes the paper exactly as printed; its
//! `derived` field says what zcheck found; its `evidence` says how.

use serde::Serialize;

/// How a claim of the paper fares against the derivation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The claim holds as printed.
    Confirmed,
    /// The claim is a misprint or false.
    Errata,
    /// The claim is true but incomplete: it holds on a smaller range than
    /// stated, or needs a condition the paper omits.
    Refined,
}

impl Verdict {
    /// The lower-case name used in reports.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Confirmed => "confirmed",
            Verdict::Errata => "errata",
            Verdict::Refined => "refined",
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
    /// The verdict.
    pub verdict: Verdict,
    /// How the verdict was reached (exact derivation, numbers, runs).
    pub evidence: String,
}

pub mod appendix;
pub mod report;
pub mod sections;

/// Every claim of the paper, in the paper's order: sections 4–12 and
/// Appendices A–B, then the appendix scenes C–E.
pub fn all_claims() -> Vec<Claim> {
    // The appendix scenes simulate while the sections compute exactly: run
    // them side by side (the report must stay under 0.3 s).
    std::thread::scope(|scope| {
        let scenes = scope.spawn(appendix::claims);
        let mut v = sections::claims();
        v.extend(scenes.join().expect("appendix claims do not panic"));
        v
    })
}
