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

/// The whole Markdown report, as `zcheck paper` prints it (the appendix
/// claims included).
fn markdown() -> &'static str {
    static TEXT: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    TEXT.get_or_init(|| report::to_markdown(&all_claims()))
}

/// The lines of the report that list claim `id`: its entry in the
/// differences (a bullet and its sub-bullets) and its own section (from its
/// heading to the next).
fn blocks(id: &str) -> (String, String) {
    let text = markdown();
    let lines: Vec<&str> = text.lines().collect();
    let entry = format!("- `{id}` (");
    let difference = match lines.iter().position(|l| l.starts_with(&entry)) {
        Some(k) => lines[k..]
            .iter()
            .enumerate()
            .take_while(|(j, l)| *j == 0 || l.starts_with("  "))
            .map(|(_, l)| *l)
            .collect::<Vec<_>>()
            .join("\n"),
        None => String::new(),
    };
    let heading = format!("### `{id}`:");
    let own = match lines.iter().position(|l| l.starts_with(&heading)) {
        Some(k) => lines[k..]
            .iter()
            .enumerate()
            .take_while(|(j, l)| *j == 0 || !l.starts_with("#"))
            .map(|(_, l)| *l)
            .collect::<Vec<_>>()
            .join("\n"),
        None => String::new(),
    };
    (difference, own)
}

/// Every erratum and slip is listed with the printed line, the corrected
/// line right under it, and the evidence; a refined claim with the cases
/// where it fails. Its own section says the same.
#[test]
fn differences_show_printed_against_corrected_and_the_failing_cases() {
    let claims = all_claims();
    let mut seen = [0usize; 3];
    for c in &claims {
        let (difference, own) = blocks(&c.id);
        match c.verdict() {
            Verdict::Errata | Verdict::Typo => {
                seen[0] += 1;
                let lines: Vec<&str> = difference.lines().collect();
                let printed = lines.iter().position(|l| l.starts_with("  - **Printed:**"));
                let next = printed.and_then(|k| lines.get(k + 1)).copied().unwrap_or_default();
                assert!(
                    next.starts_with("  - **Corrected:**")
                        || next.starts_with("  - **Fails where:**"),
                    "{}: printed and corrected are not side by side:\n{difference}",
                    c.id
                );
                if c.correction().is_some() {
                    assert!(next.starts_with("  - **Corrected:**"), "{}:\n{difference}", c.id);
                    assert!(own.contains("- **Corrected:**"), "{}:\n{own}", c.id);
                }
                assert!(difference.contains("  - **Evidence:**"), "{}:\n{difference}", c.id);
                assert!(own.contains("- **Printed:**"), "{}:\n{own}", c.id);
            }
            Verdict::Refined => {
                seen[1] += 1;
                let failing = c.failing_cases();
                assert!(!failing.is_empty(), "{}: refined without a failing case", c.id);
                for (case, reason) in failing {
                    let case = report::in_notation(case);
                    assert!(
                        difference.contains(&case),
                        "{}: {case:?} missing in\n{difference}",
                        c.id
                    );
                    assert!(own.contains(&case), "{}: {case:?} missing in\n{own}", c.id);
                    let reason = report::in_notation(
                        reason.expect("a refined claim fails beyond the stated"),
                    );
                    assert!(own.contains(&reason), "{}: the reason is missing in\n{own}", c.id);
                }
            }
            Verdict::Confirmed => {
                seen[2] += 1;
                assert!(difference.is_empty(), "{}: a confirmed claim among the differences", c.id);
            }
        }
    }
    assert!(seen.iter().all(|&n| n > 0), "{seen:?}");
}

/// Every case only the wording covers carries its reason, and the report
/// prints it with the claim, whether the case holds or fails.
#[test]
fn every_wording_scope_carries_its_reason() {
    let mut reasons = 0;
    for c in all_claims() {
        let zcheck::paper::Finding::Cases { cases } = c.finding() else { continue };
        for case in cases {
            if let zcheck::paper::Scope::Wording { reason } = &case.scope {
                reasons += 1;
                assert!(reason.len() > 30, "{}: a reason in a few words: {reason:?}", c.id);
                let (_, own) = blocks(&c.id);
                assert!(
                    own.contains(&report::in_notation(reason)),
                    "{}: {reason:?} not in\n{own}",
                    c.id
                );
            }
        }
    }
    assert!(reasons >= 15, "{reasons}");
}

/// Bullets stay within 300 characters, repeat no number ("1.8100 and
/// 1.8100"), and write Φ: `Phi` appears only in code spans.
#[test]
fn bullets_are_short_say_each_number_once_and_write_phi() {
    let text = format!(
        "{}\n{}",
        markdown(),
        zcheck::overview::to_markdown(&zcheck::overview::paper_overview(5).expect("overview"))
    );
    for line in text.lines() {
        if line.trim_start().starts_with("- ") {
            assert!(line.chars().count() <= 300, "{} characters: {line}", line.chars().count());
        }
        let prose: String = line.split('`').step_by(2).collect();
        assert!(
            !prose.split(|c: char| !c.is_alphanumeric() && c != '_').any(|w| w == "Phi"),
            "Phi outside code: {line}"
        );
        assert_eq!(repeated_number(line), None, "{line}");
    }
    assert_eq!(repeated_number("limits 1.8100 and 1.8100"), Some("1.8100".to_owned()));
    assert_eq!(repeated_number("errors 5.44e-4 and 5.44e-4, then"), Some("5.44e-4".to_owned()));
    assert_eq!(
        repeated_number("√101/5 − 1/5 ≈ 1.8100 and √101/5 − 1/5 ≈ 1.8100"),
        Some("√101/5 − 1/5 ≈ 1.8100".to_owned())
    );
    assert_eq!(repeated_number("2 + 2 against 1 + 1, x1 and x2"), None);
    assert_eq!(repeated_number("dispersion orders Φ³ vs Φ³"), Some("Φ³".to_owned()));
    assert_eq!(repeated_number("right sides = Φ + 3Φ³/8, Φ + 3Φ³/8"), Some("Φ + 3Φ³/8".to_owned()));
}

/// The longest `X` with a digit in `X and X`, `X vs X` or `X, X` (X a
/// whole word run).
fn repeated_number(line: &str) -> Option<String> {
    let chars: Vec<char> = line.chars().collect();
    let mut found: Option<String> = None;
    // A list may repeat a short entry ([[1, 1], ...]); a repeated value of
    // four characters or more is a repeat.
    for (joint, shortest) in [(" and ", 1), (" vs ", 1), (", ", 4)] {
        let and: Vec<char> = joint.chars().collect();
        for k in 0..chars.len().saturating_sub(and.len()) {
            if chars[k..k + and.len()] != and[..] {
                continue;
            }
            for n in shortest..=40.min(k) {
                let (left, right) = (&chars[k - n..k], chars.get(k + and.len()..k + and.len() + n));
                let bounded = (k == n || !chars[k - n - 1].is_alphanumeric())
                    && chars.get(k + and.len() + n).is_none_or(|c| !c.is_alphanumeric());
                if right == Some(left)
                    && bounded
                    && left.iter().any(|c| c.is_ascii_digit() || "⁰¹²³⁴⁵⁶⁷⁸⁹".contains(*c))
                {
                    let x: String = left.iter().collect();
                    if found.as_ref().is_none_or(|f| f.chars().count() < n) {
                        found = Some(x);
                    }
                }
            }
        }
    }
    found
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
