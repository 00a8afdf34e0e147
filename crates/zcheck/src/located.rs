//! A mistake in one of the application's TOML files (a scene, a Butcher
//! tableau), located at its line and column.

use std::fmt;

/// A mistake in a file, with its 1-based line and column (in characters).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileError {
    pub(crate) path: String,
    pub(crate) line: usize,
    pub(crate) col: usize,
    pub(crate) message: String,
}

impl FileError {
    /// The 1-based line.
    pub fn line(&self) -> usize {
        self.line
    }

    /// The 1-based column.
    pub fn col(&self) -> usize {
        self.col
    }

    /// The message alone.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for FileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}: {}", self.path, self.line, self.col, self.message)
    }
}

impl std::error::Error for FileError {}

/// The 1-based line and column (in characters) of a byte offset.
pub(crate) fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}
