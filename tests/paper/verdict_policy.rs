//! The verdicts are computed: every claim carries a finding (the computed
//! inputs of its check) and its verdict is the one policy's output on that
//! finding (DESIGN.md, "the verdict policy"). Perturbing a claim's finding
//! moves its verdict; no source file of the proof attaches a verdict by
//! hand.

use zcheck::paper::{policy, Case, Claim, Finding, Scope, Verdict};

fn all() -> Vec<Claim> {
    let mut v = crate::common::claims().to_vec();
    v.extend(crate::app_c_three_body::appendix_claims().iter().cloned());
    v
}

/// Every claim's verdict is the policy applied to its finding, and every
/// finding checked something: a case list is never empty and always has a
/// stated case.
#[test]
fn every_verdict_is_the_policy_of_its_finding() {
    for c in all() {
        assert_eq!(c.verdict(), policy::verdict(c.finding()), "{}", c.id);
        if let Finding::Cases { cases } = c.finding() {
            assert!(!cases.is_empty(), "{}: no case checked", c.id);
            assert!(cases.iter().any(|k| k.scope.is_stated()), "{}: no stated case", c.id);
        }
    }
}

/// Each claim's verdict flips when its computed inputs change: a printed
/// object that no longer matches (or now matches) what zcheck derived, a
/// stated case that fails, a case the wording covers that fails, a slip
/// that reaches (or no longer reaches) the program.
#[test]
fn every_verdict_moves_with_its_inputs() {
    for c in all() {
        let moved = |f: Finding, want: Verdict| {
            let judged = c.with_finding(f.clone());
            assert_eq!(judged.verdict(), want, "{}: perturbed to {f:?}", c.id);
        };
        match c.finding().clone() {
            Finding::Same { printed, derived } => {
                if printed == derived {
                    moved(
                        Finding::Same { printed: format!("{printed} + 1"), derived },
                        Verdict::Errata,
                    );
                } else {
                    moved(Finding::Same { printed: derived.clone(), derived }, Verdict::Confirmed);
                }
            }
            Finding::Cases { cases } => {
                let with = |f: &dyn Fn(&Case, usize) -> bool| Finding::Cases {
                    cases: cases
                        .iter()
                        .enumerate()
                        .map(|(k, x)| Case { holds: f(x, k), ..x.clone() })
                        .collect(),
                };
                moved(with(&|_, _| true), Verdict::Confirmed);
                let stated =
                    cases.iter().position(|x| x.scope == Scope::Stated).expect("a stated case");
                moved(with(&|_, k| k != stated), Verdict::Errata);
                if let Some(wording) = cases.iter().position(|x| !x.scope.is_stated()) {
                    moved(with(&|_, k| k != wording), Verdict::Refined);
                }
            }
            Finding::Slip { printed, intended, changes_math } => {
                moved(
                    Finding::Slip {
                        printed: intended.clone(),
                        intended: intended.clone(),
                        changes_math,
                    },
                    Verdict::Confirmed,
                );
                if printed != intended {
                    let flipped = if changes_math { Verdict::Typo } else { Verdict::Errata };
                    moved(
                        Finding::Slip { printed, intended, changes_math: !changes_math },
                        flipped,
                    );
                }
            }
        }
    }
}

/// No source file of the proof attaches a verdict, a case's outcome or a
/// slip's reach as a literal: only the policy names verdicts (and the report
/// counts them).
#[test]
fn no_verdict_is_a_literal_in_the_proof_sources() {
    fn walk(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for entry in std::fs::read_dir(dir).expect("readable source dir") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/zcheck/src/paper");
    let mut files = Vec::new();
    walk(&root, &mut files);
    assert!(files.len() > 10, "found only {files:?}");
    let allowed = ["claim.rs", "policy.rs", "report.rs"];
    for file in files {
        let name = file.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_owned();
        let text = std::fs::read_to_string(&file).expect("readable");
        // Test modules may name verdicts: they assert them.
        let code_part = text.split("#[cfg(test)]").next().unwrap_or_default();
        for (k, line) in code_part.lines().enumerate() {
            let code = line.split("//").next().unwrap_or_default();
            let compact: String = code.split_whitespace().collect();
            for literal in ["holds:true", "holds:false", "changes_math:true", "changes_math:false"]
            {
                assert!(!compact.contains(literal), "{name}:{}: literal {literal}", k + 1);
            }
            if !allowed.contains(&name.as_str()) {
                assert!(
                    !code.contains("Verdict::"),
                    "{name}:{}: a verdict named outside the policy",
                    k + 1
                );
            }
        }
    }
}
