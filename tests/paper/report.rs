//! The proof report of `zcheck paper`: its summary counts agree with the
//! claims, its JSON has the documented shape, and the Markdown report is
//! snapshotted (rounded numbers only) in snapshots/paper/.

use zcheck::paper::{all_claims, report, Verdict};

/// The summary counts are the claims' verdicts, per section and in total,
/// and every section 4–12, A–E appears in the JSON summary.
#[test]
fn summary_counts_the_claims() {
    let claims = all_claims();
    let json = report::to_json(&claims);
    let summary = &json["summary"];
    assert_eq!(summary["total"], claims.len());
    for (v, key) in [
        (Verdict::Confirmed, "confirmed"),
        (Verdict::Refined, "refined"),
        (Verdict::Errata, "errata"),
        (Verdict::Typo, "typo"),
    ] {
        assert_eq!(summary[key], claims.iter().filter(|c| c.verdict() == v).count(), "{key}");
    }
    for s in ["4", "5", "6", "7", "8", "9", "10", "11", "12", "A", "B", "C", "D", "E"] {
        let n = claims.iter().filter(|c| c.section == s).count();
        assert_eq!(summary["by_section"][s]["claims"], n, "section {s}");
    }
    let first = &json["claims"][0];
    for key in ["id", "section", "statement", "derived", "verdict", "evidence"] {
        assert!(first.get(key).is_some(), "claims[0] lacks {key}");
    }
    let ids: std::collections::HashSet<&str> = claims.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(ids.len(), claims.len(), "claim ids are unique");
}

/// The Markdown report of sections 4–12 and Appendices A–B (the scenes of
/// C–E have their own snapshot tests), for a person to read.
#[test]
fn markdown_report_snapshot() {
    let claims = zcheck::paper::sections::claims();
    let text = report::to_markdown(&claims);
    crate::snapshot::in_dir("paper")
        .bind(|| insta::assert_snapshot!("paper_report_sections", text));
}
