//! Replays a fuzz target's committed corpus and crash regressions as an
//! ordinary test: every file under `fuzz/{corpus,regressions}/<target>/`
//! through the same function the libFuzzer target calls, from the
//! integration tests of `poly` and of `zcheck`.

use std::path::{Path, PathBuf};

/// Runs `body` on every file of `<fuzz>/{corpus,regressions}/<target>/`
/// (`fuzz` is the `fuzz/` directory); a panic names the file. At least ten
/// files must be found, so a moved corpus cannot pass silently.
pub fn replay(fuzz: &Path, target: &str, body: fn(&[u8])) {
    let mut n = 0;
    for kind in ["corpus", "regressions"] {
        let dir = fuzz.join(kind).join(target);
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
    assert!(n >= 10, "{target}: only {n} corpus files found under {}", fuzz.display());
}
