//! The proof report: every claim with its verdict, rendered as Markdown for
//! a person or as JSON for a program, with a summary of verdicts per section
//! at the top.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::Serialize;
use serde_json::json;

use crate::paper::claim::Claim;

use crate::paper::policy::Verdict;

/// The paper's sections that carry claims, in the paper's order, with their
/// titles as the table of contents prints them.
pub(crate) const SECTIONS: [(&str, &str); 14] = [
    ("4", "z-Transformation"),
    ("5", "Standard Euler"),
    ("6", "Damped Euler"),
    ("7", "False Euler"),
    ("8", "Verlet Integration"),
    ("9", "Standard Heun"),
    ("10", "False Heun"),
    ("11", "Semi-False Heun"),
    ("12", "Conclusions"),
    ("A", "Appendix A (Taylor)"),
    ("B", "Appendix B (Source code)"),
    ("C", "Appendix C (3 bodies, False Euler)"),
    ("D", "Appendix D (3 bodies, Stand. Euler)"),
    ("E", "Appendix E (Aircraft)"),
];

/// Verdict counts.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub(crate) struct Counts {
    /// All claims.
    pub claims: usize,
    /// Claims that hold as printed.
    pub confirmed: usize,
    /// Claims true only on a smaller range or with a missing condition.
    pub refined: usize,
    /// Misprints that change the mathematics, and false claims.
    pub errata: usize,
    /// Slips that change nothing (counted apart from the errata).
    pub typo: usize,
}

impl Counts {
    fn add(&mut self, v: Verdict) {
        self.claims += 1;
        match v {
            Verdict::Confirmed => self.confirmed += 1,
            Verdict::Refined => self.refined += 1,
            Verdict::Errata => self.errata += 1,
            Verdict::Typo => self.typo += 1,
        }
    }

    fn get(&self, v: Verdict) -> usize {
        match v {
            Verdict::Confirmed => self.confirmed,
            Verdict::Refined => self.refined,
            Verdict::Errata => self.errata,
            Verdict::Typo => self.typo,
        }
    }
}

/// Counts over all claims and per section (every section of [`SECTIONS`],
/// in order, including those without claims).
pub(crate) fn summary(claims: &[Claim]) -> (Counts, Vec<(&'static str, Counts)>) {
    let mut total = Counts::default();
    let mut per: BTreeMap<&str, Counts> = BTreeMap::new();
    for c in claims {
        total.add(c.verdict());
        per.entry(c.section.as_str()).or_default().add(c.verdict());
    }
    let sections =
        SECTIONS.iter().map(|(s, _)| (*s, per.get(s).cloned().unwrap_or_default())).collect();
    (total, sections)
}

/// The JSON document: `{"claims": [...], "summary": {...}}`.
pub fn to_json(claims: &[Claim]) -> serde_json::Value {
    let (total, sections) = summary(claims);
    let by_section: serde_json::Map<String, serde_json::Value> = sections
        .iter()
        .map(|(s, c)| ((*s).to_owned(), serde_json::to_value(c).expect("plain counts")))
        .collect();
    json!({
        "claims": claims,
        "summary": {
            "total": total.claims,
            "confirmed": total.confirmed,
            "refined": total.refined,
            "errata": total.errata,
            "typo": total.typo,
            "by_section": by_section,
        },
    })
}

fn title(section: &str) -> &'static str {
    SECTIONS.iter().find(|(s, _)| *s == section).map(|(_, t)| *t).unwrap_or("")
}

fn heading(section: &str) -> String {
    if section.chars().all(|c| c.is_ascii_digit()) {
        format!("Section {section}: {}", title(section))
    } else {
        title(section).to_owned()
    }
}

/// The Markdown report: summary table, the list of differences from the
/// paper, then every claim section by section.
pub fn to_markdown(claims: &[Claim]) -> String {
    let (total, sections) = summary(claims);
    let mut out = String::new();
    let _ =
        writeln!(out, "# The executable proof of Hoffmann, \"Simple Integration Algorithms\"\n");
    let _ = writeln!(
        out,
        "{} claims: {} confirmed, {} refined (true on the range the paper states or under a condition it \
         leaves implicit), {} errata (false within what the paper asserts, or a misprint that changes the \
         mathematics), {} typo (a slip that changes nothing).\n",
        total.claims, total.confirmed, total.refined, total.errata, total.typo
    );
    let _ = writeln!(out, "## Summary\n");
    let _ = writeln!(out, "| section | title | claims | confirmed | refined | errata | typo |");
    let _ = writeln!(out, "|---|---|---:|---:|---:|---:|---:|");
    for (s, c) in &sections {
        let _ = writeln!(
            out,
            "| {s} | {} | {} | {} | {} | {} | {} |",
            title(s),
            c.claims,
            c.confirmed,
            c.refined,
            c.errata,
            c.typo
        );
    }
    let _ = writeln!(
        out,
        "| all | | {} | {} | {} | {} | {} |\n",
        total.claims, total.confirmed, total.refined, total.errata, total.typo
    );
    let _ = writeln!(out, "## Differences from the paper\n");
    for v in [Verdict::Errata, Verdict::Refined, Verdict::Typo] {
        if total.get(v) == 0 {
            continue;
        }
        for c in claims.iter().filter(|c| c.verdict() == v) {
            let _ = writeln!(
                out,
                "- **{}** `{}` ({}): {}",
                v.name(),
                c.id,
                heading(&c.section),
                c.derived
            );
        }
    }
    let _ = writeln!(out);
    for (s, _) in SECTIONS {
        let here: Vec<&Claim> = claims.iter().filter(|c| c.section == s).collect();
        if here.is_empty() {
            continue;
        }
        let _ = writeln!(out, "## {}\n", heading(s));
        for c in here {
            let _ = writeln!(out, "### `{}`: {}\n", c.id, c.verdict().name());
            let _ = writeln!(out, "- **Paper:** {}", c.statement);
            let _ = writeln!(out, "- **Derived:** {}", c.derived);
            let _ = writeln!(out, "- **Evidence:** {}\n", c.evidence);
        }
    }
    out
}
