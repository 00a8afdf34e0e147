//! The fuzz targets' committed corpora and crash regressions, replayed as
//! ordinary tests: `cargo test` runs every input of `fuzz/corpus/<target>/`
//! and `fuzz/regressions/<target>/` through the same function the libFuzzer
//! target calls, so CI checks them without the nightly toolchain that
//! cargo-fuzz needs (see FUZZING.md).

use testkit::fuzz as targets;

use testkit::replay as replay_corpus;

use std::path::PathBuf;

fn replay(target: &str, body: fn(&[u8])) {
    let fuzz = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    replay_corpus::replay(&fuzz, target, body);
}

#[test]
fn parse_corpus() {
    replay("parse", targets::parse);
}

#[test]
fn parse_derive_corpus() {
    replay("parse_derive", targets::parse_derive);
}

#[test]
fn stability_corpus() {
    replay("stability", targets::stability);
}

/// Regression (fuzz target `stability`, 11 crashes, one cause): the exact
/// analysis indexed past the power sums for a first-order χ (one state
/// variable) and panicked. First-order methods are analysed now.
#[test]
fn first_order_methods_are_analysed() {
    for src in [
        "method m\nstate y\ny = y - Phi*y\n",
        "method m\nstate y\ny = y + Phi*y\n",
        "method m\nstate y\ny = y\n",
    ] {
        let chi = poly::advanced::charpoly(&poly::Method::parse("first.zm", src).unwrap()).unwrap();
        assert!(poly::advanced::stability::analyze(&chi).is_ok(), "{src}");
    }
}
