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
