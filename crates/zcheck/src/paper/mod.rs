//! The executable proof of the paper, as data: every claim the paper makes,
//! what zcheck derived, and a verdict.
//!
//! `zcheck paper` prints these claims; the tests in `tests/paper/` assert
//! them. A claim's `statement` transcribes the paper exactly as printed; its
//! `derived` field says what zcheck found; its `evidence` says how.

mod claim;
mod finding;
pub(crate) mod notation;
pub mod policy;

pub use claim::Claim;
pub use finding::{Case, Finding, Scope};
pub use policy::Verdict;

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

/// The highest power of Φ shown in the overview's series.
pub(crate) const OVERVIEW_ORDER: usize = 5;

/// The document of `zcheck paper --format json`: the claims, the summary
/// and the overview.
pub(crate) fn json_document() -> Result<serde_json::Value, crate::Error> {
    let mut doc = report::to_json(&all_claims());
    doc["overview"] = serde_json::to_value(crate::overview::paper_overview(OVERVIEW_ORDER)?)?;
    Ok(doc)
}
