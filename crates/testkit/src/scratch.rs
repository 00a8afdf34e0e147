//! Scratch files for tests that hand a path to the CLI: a fresh directory
//! under the system's temporary directory (tempfile's), removed with
//! everything in it when the value is dropped. A failing test still cleans
//! up, since unwinding drops it, and two test processes never share one.

use std::ops::Deref;
use std::path::{Path, PathBuf};

/// A fresh directory, removed when dropped.
pub struct Scratch(tempfile::TempDir);

impl Scratch {
    /// A new directory named `zcheck-LABEL-` and a random suffix.
    pub fn new(label: &str) -> Scratch {
        let dir = tempfile::Builder::new()
            .prefix(&format!("zcheck-{label}-"))
            .tempdir()
            .unwrap_or_else(|e| panic!("a scratch directory for {label}: {e}"));
        Scratch(dir)
    }

    /// The directory.
    pub fn path(&self) -> &Path {
        self.0.path()
    }

    /// The path of `name` in the directory (nothing is written).
    pub fn join(&self, name: &str) -> PathBuf {
        self.0.path().join(name)
    }

    /// `text` written to `name` in the directory; its path.
    pub fn file(&self, name: &str, text: &str) -> PathBuf {
        let path = self.join(name);
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        path
    }
}

/// One file, named as given (the CLI reads a method's name from its file's
/// stem), alone in a [`Scratch`] directory, removed with it when dropped.
/// It dereferences to its path.
pub struct ScratchFile {
    path: PathBuf,
    _dir: Scratch,
}

impl ScratchFile {
    /// `text` written to a file `name` in a new scratch directory.
    pub fn new(name: &str, text: &str) -> ScratchFile {
        let dir = Scratch::new(name.split('.').next().unwrap_or("file"));
        ScratchFile { path: dir.file(name, text), _dir: dir }
    }
}

impl Deref for ScratchFile {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.path
    }
}

impl AsRef<Path> for ScratchFile {
    fn as_ref(&self) -> &Path {
        &self.path
    }
}
