//! The generator of issue 10's property tests, shared by `poly`'s exact
//! half (`random_programs.rs`, Jury's test at rational samples) and
//! `check`'s numeric half (`stability_scan.rs`, an eigenvalue scan).

use proptest::prelude::*;

/// A random linear program as `.zm` text.
pub fn program() -> impl Strategy<Value = String> {
    (
        1usize..=3,
        prop::collection::vec(0usize..=2, 3),
        prop::collection::vec(prop::collection::vec((0usize..16, 0usize..8, 0u32..=3), 1..4), 3),
    )
        .prop_map(|(n, hist, terms)| {
            const COEFS: [&str; 8] = ["1", "-1", "1/2", "-1/2", "2", "-3/2", "1/3", "3/4"];
            // Keep the degree of χ at most 6: history only while it fits.
            let mut hist = hist;
            let mut total = n;
            for h in hist.iter_mut().take(n) {
                *h = (*h).min(6 - total);
                total += *h;
            }
            let vars: Vec<String> = (0..n).map(|i| format!("x{i}")).collect();
            let mut operands: Vec<String> = vars.clone();
            for (i, v) in vars.iter().enumerate() {
                for k in 1..=hist[i] {
                    operands.push(format!("{v}@{k}"));
                }
            }
            let mut src = format!("method gen\nstate {}\n", vars.join(" "));
            for (i, v) in vars.iter().enumerate() {
                let sum: Vec<String> = terms[i]
                    .iter()
                    .map(|&(o, c, k)| {
                        let phi = match k {
                            0 => String::new(),
                            1 => "Phi*".to_owned(),
                            k => format!("Phi^{k}*"),
                        };
                        format!("{}*{phi}{}", COEFS[c], operands[o % operands.len()])
                    })
                    .collect();
                src += &format!("{v} = {v} + {}\n", sum.join(" + "));
            }
            src
        })
}
