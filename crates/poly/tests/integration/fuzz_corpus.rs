//! The fuzz targets' committed corpora and crash regressions, replayed as
//! ordinary tests: `cargo test` runs every input of `fuzz/corpus/<target>/`
//! and `fuzz/regressions/<target>/` through the same function the libFuzzer
//! target calls, so CI checks them without the nightly toolchain that
//! cargo-fuzz needs (see FUZZING.md).

#[path = "../../../../fuzz/src/lib.rs"]
mod targets;

use std::path::PathBuf;

/// Every file under `fuzz/{corpus,regressions}/<target>/`, run through
/// `body`; a panic names the file.
fn replay(target: &str, body: fn(&[u8])) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let mut n = 0;
    for kind in ["corpus", "regressions"] {
        let dir = root.join(kind).join(target);
        let Ok(entries) = std::fs::read_dir(&dir) else { continue };
        let mut files: Vec<PathBuf> = entries.filter_map(|e| Some(e.ok()?.path())).collect();
        files.sort();
        for file in files {
            if file.file_name().is_some_and(|n| n.to_string_lossy().starts_with('.')) {
                continue;
            }
            let data = std::fs::read(&file).expect("readable corpus file");
            if let Err(panic) = std::panic::catch_unwind(|| body(&data)) {
                let why = panic
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                panic!("{target}: {} fails: {why}", file.display());
            }
            n += 1;
        }
    }
    assert!(n >= 10, "{target}: only {n} corpus files found under {}", root.display());
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
        let chi = poly::charpoly(&poly::Method::parse("first.zm", src).unwrap()).unwrap();
        assert!(poly::stability::analyze(&chi).is_ok(), "{src}");
    }
}
