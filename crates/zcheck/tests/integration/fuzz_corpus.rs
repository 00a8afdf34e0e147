//! The application fuzz targets' committed corpora and crash regressions
//! (`fuzz/{corpus,regressions}/{scene_toml,tableau}/`), replayed as ordinary
//! tests through the same functions the libFuzzer targets call, so CI checks
//! them without the nightly toolchain cargo-fuzz needs (FUZZING.md).

#[path = "../../../../fuzz/src/app.rs"]
mod app;

use std::path::PathBuf;

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
fn scene_toml_corpus() {
    replay("scene_toml", app::scene_toml);
}

#[test]
fn tableau_corpus() {
    replay("tableau", app::tableau);
}
