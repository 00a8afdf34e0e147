//! The application fuzz targets' committed corpora and crash regressions
//! (`fuzz/{corpus,regressions}/{scene_toml,tableau,order_toml}/`), replayed as ordinary
//! tests through the same functions the libFuzzer targets call, so CI checks
//! them without the nightly toolchain cargo-fuzz needs (FUZZING.md).

use testkit::fuzz as app;

use testkit::replay as replay_corpus;

use std::path::PathBuf;

fn replay(target: &str, body: fn(&[u8])) {
    let fuzz = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    replay_corpus::replay(&fuzz, target, body);
}

#[test]
fn scene_toml_corpus() {
    replay("scene_toml", app::scene_toml);
}

#[test]
fn tableau_corpus() {
    replay("tableau", app::tableau);
}

#[test]
fn order_toml_corpus() {
    replay("order_toml", app::order_toml);
}
