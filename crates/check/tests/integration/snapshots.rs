//! Rounded summaries of sweeps and witness tables, snapshotted so a change
//! in any class boundary or verdict shows up in review.

use check::numeric::ParamsF64;
use std::fmt::Write;

use check::numeric::Params;
use check::sweep::{default_grid, sweep};
use check::witness::Witnesses;

fn params() -> Params {
    Params::default().with("D", 0.3)
}

/// Class boundaries of every built-in along Φ in [1e-8, 4] (D = 0.3),
/// rounded to 6 significant digits.
#[test]
fn sweep_boundaries_of_every_builtin() {
    let mut s = String::new();
    for name in poly::advanced::builtins::paper_builtin_names() {
        let sw = sweep(&poly::builtin(name).unwrap(), &params(), &default_grid()).unwrap();
        write!(s, "{name}: {}", sw.first.1).unwrap();
        for b in &sw.boundaries {
            write!(s, " | {:.6} | {}", b.above, b.class_above).unwrap();
        }
        writeln!(s).unwrap();
    }
    crate::snapshot::in_dir("check")
        .bind(|| insta::assert_snapshot!("sweep_boundaries_of_every_builtin", s));
}

/// The verify table of `names` at `phis`: class, ρ and Ψ to 6 digits, and
/// whether the four witnesses agree (5000 simulated steps).
fn verify_summary<'a>(names: impl IntoIterator<Item = &'a str>, phis: &[f64]) -> String {
    let mut s = String::new();
    for name in names {
        let w = Witnesses::new(&poly::builtin(name).unwrap()).unwrap();
        writeln!(s, "{name}").unwrap();
        for &phi in phis {
            let r = w.at(&params().with("Phi", phi), 5000).unwrap();
            writeln!(
                s,
                "  phi {phi:<8} {:<22} rho {:.6} psi {:.6} agree {}",
                r.exact.class.name(),
                r.exact.spectral_radius,
                r.exact.psi,
                r.agree()
            )
            .unwrap();
        }
    }
    s
}

/// The verify table at the default Φ list.
#[test]
fn verify_summary_of_every_builtin() {
    let s = verify_summary(
        poly::advanced::builtins::paper_builtin_names(),
        &[1e-6, 0.1, 0.5, 1.0, 1.5, 1.9],
    );
    crate::snapshot::in_dir("check")
        .bind(|| insta::assert_snapshot!("verify_summary_of_every_builtin", s));
}

/// The verify table of the implicit and algebraic built-ins, up to Φ = 3.
#[test]
fn verify_summary_of_the_implicit_builtins() {
    let s = verify_summary(
        poly::advanced::builtins::IMPLICIT_METHODS,
        &[1e-6, 0.1, 0.5, 1.0, 1.5, 1.9, 3.0],
    );
    crate::snapshot::in_dir("check")
        .bind(|| insta::assert_snapshot!("verify_summary_of_the_implicit_builtins", s));
}
