//! The one helper for insta's snapshot path, shared by every test binary of
//! the workspace.
//!
//! Snapshots live at the top of the workspace, in `snapshots/<dir>/<name>.snap`,
//! named explicitly (never after the test module), so moving a test between
//! modules or binaries never renames a reviewed snapshot.

use std::path::{Path, PathBuf};

/// The workspace's `snapshots/<dir>` folder.
pub fn snapshot_dir(dir: &str) -> PathBuf {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let root = manifest
        .ancestors()
        .find(|p| p.join("snapshots").is_dir() && p.join("crates").is_dir())
        .expect("the workspace root holds snapshots/ and crates/");
    root.join("snapshots").join(dir)
}

/// insta settings that store snapshots in `snapshots/<dir>` under their
/// explicit names.
pub fn in_dir(dir: &str) -> insta::Settings {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path(snapshot_dir(dir));
    settings.set_prepend_module_to_snapshot(false);
    settings
}
