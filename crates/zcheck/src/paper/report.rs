//! The proof report: every claim with its verdict, rendered as Markdown for
//! a person or as JSON for a program, with a summary of verdicts per section
//! at the top.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::Serialize;
use serde_json::json;

use crate::paper::claim::Claim;
use crate::paper::finding::{Finding, Scope};
use crate::paper::notation;
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

/// A text in the report's notation, as the Markdown prints it (Φ for
/// `Phi`, powers as superscripts; code spans untouched).
pub fn in_notation(text: &str) -> String {
    notation::math(text)
}

/// Bullets longer than this are split into one sub-bullet per clause.
pub(crate) const BULLET: usize = 300;

/// A text's clauses: split at `; ` outside parentheses, brackets and code
/// spans, and a
/// clause still about as long as a [`BULLET`] at its sentences.
pub(crate) fn clauses(text: &str) -> Vec<String> {
    let split = |text: &str, at: &dyn Fn(&[char], usize) -> bool, skip: usize| {
        let chars: Vec<char> = text.chars().collect();
        let (mut out, mut start, mut depth, mut code) = (Vec::new(), 0, 0i32, false);
        for k in 0..chars.len() {
            match chars[k] {
                '(' | '[' => depth += 1,
                ')' | ']' => depth -= 1,
                '`' => code = !code,
                _ => {}
            }
            if depth == 0 && !code && at(&chars, k) {
                out.push(
                    chars[start..=k]
                        .iter()
                        .collect::<String>()
                        .trim_end_matches(';')
                        .trim()
                        .to_owned(),
                );
                start = k + 1 + skip;
            }
        }
        out.push(chars[start.min(chars.len())..].iter().collect::<String>().trim().to_owned());
        out.retain(|c| !c.is_empty());
        out
    };
    let semicolon = |c: &[char], k: usize| c[k] == ';' && c.get(k + 1) == Some(&' ');
    // A sentence ends at ". " before a letter, not after "e.g" or "i.e".
    let sentence = |c: &[char], k: usize| {
        let abbreviation = k >= 3 && matches!(c[k - 3..k], ['e', '.', 'g'] | ['i', '.', 'e']);
        c[k] == '.'
            && c.get(k + 1) == Some(&' ')
            && c.get(k + 2).is_some_and(|x| x.is_alphabetic())
            && !abbreviation
    };
    // Split a little below the limit: the bullet's dash and indent count too.
    split(text, &semicolon, 1)
        .into_iter()
        .flat_map(
            |c| if c.chars().count() > BULLET - 10 { split(&c, &sentence, 1) } else { vec![c] },
        )
        .collect()
}

/// One labelled bullet, `- **Label:** text`, or, past [`BULLET`]
/// characters, the label with one sub-bullet per clause.
fn bullet(out: &mut String, indent: &str, label: &str, text: &str) {
    let text = notation::math(text);
    if text.chars().count() + label.len() + 8 <= BULLET {
        let _ = writeln!(out, "{indent}- **{label}:** {text}");
    } else {
        let _ = writeln!(out, "{indent}- **{label}:**");
        for c in clauses(&text) {
            let _ = writeln!(out, "{indent}  - {c}");
        }
    }
}

/// A statement as printed: a Pascal listing line (it opens with `name:=`
/// or `Var`) is code.
fn printed(statement: &str) -> String {
    let name: String = statement.chars().take_while(|c| c.is_ascii_alphanumeric()).collect();
    let rest = statement[name.len()..].trim_start();
    if !name.is_empty() && (rest.starts_with(":=") || name == "Var") {
        format!("`{statement}`")
    } else {
        statement.to_owned()
    }
}

/// The failing cases of a claim; cases beyond what the paper states are
/// followed by the reason, once for a run of cases that share it.
fn failing(c: &Claim) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let cases = c.failing_cases();
    let mut run = 0;
    for (k, (case, reason)) in cases.iter().enumerate() {
        run += 1;
        let next_shares = cases.get(k + 1).is_some_and(|(_, r)| r == reason);
        match reason {
            Some(r) if !next_shares => {
                let which = match run {
                    1 => "",
                    2 => "both ",
                    _ => "all ",
                };
                out.push(format!("{case} ({which}beyond what the paper states: {r})"));
                run = 0;
            }
            Some(_) => out.push((*case).to_owned()),
            None => {
                out.push((*case).to_owned());
                run = 0;
            }
        }
    }
    out
}

/// The Markdown report: summary table, the list of differences from the
/// paper (each erratum and slip printed against corrected, each refined
/// claim with the case where it fails), then every claim section by
/// section. Mathematics is written in the paper's notation (Φ); `Phi`
/// appears only in code.
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
    for (v, heading_text) in
        [(Verdict::Errata, "Errata"), (Verdict::Refined, "Refined"), (Verdict::Typo, "Typos")]
    {
        if total.get(v) == 0 {
            continue;
        }
        let _ = writeln!(out, "### {heading_text}\n");
        for c in claims.iter().filter(|c| c.verdict() == v) {
            let _ = writeln!(out, "- `{}` ({})", c.id, heading(&c.section));
            match v {
                Verdict::Refined => {
                    bullet(&mut out, "  ", "Fails where", &failing(c).join("; "));
                }
                _ => {
                    bullet(&mut out, "  ", "Printed", &printed(&c.statement));
                    match c.correction() {
                        Some(k) => bullet(&mut out, "  ", "Corrected", &printed(k)),
                        None => bullet(&mut out, "  ", "Fails where", &failing(c).join("; ")),
                    }
                    let first = clauses(&c.evidence).into_iter().next().unwrap_or_default();
                    bullet(&mut out, "  ", "Evidence", &first);
                }
            }
        }
        let _ = writeln!(out);
    }
    for (s, _) in SECTIONS {
        let here: Vec<&Claim> = claims.iter().filter(|c| c.section == s).collect();
        if here.is_empty() {
            continue;
        }
        let _ = writeln!(out, "## {}\n", heading(s));
        for c in here {
            let v = c.verdict();
            let _ = writeln!(out, "### `{}`: {}\n", c.id, v.name());
            let differs = matches!(v, Verdict::Errata | Verdict::Typo);
            bullet(&mut out, "", if differs { "Printed" } else { "Paper" }, &printed(&c.statement));
            if differs {
                if let Some(k) = c.correction() {
                    bullet(&mut out, "", "Corrected", &printed(k));
                }
            }
            bullet(&mut out, "", "Derived", &c.derived);
            let fails = failing(c);
            if !fails.is_empty() {
                bullet(&mut out, "", "Fails where", &fails.join("; "));
            }
            bullet(&mut out, "", "Evidence", &c.evidence);
            if let Finding::Cases { cases } = c.finding() {
                for case in cases.iter().filter(|k| k.holds) {
                    if let Scope::Wording { reason } = &case.scope {
                        bullet(
                            &mut out,
                            "  ",
                            "Beyond what the paper states",
                            &format!("{} (holds): {reason}", case.case),
                        );
                    }
                }
            }
            let _ = writeln!(out);
        }
    }
    out
}
