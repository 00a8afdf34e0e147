//! Resolving a method argument: a built-in name or a path to a `.zm` file.

use std::fmt;
use std::path::Path;

use poly::Method;

/// Why a method could not be loaded.
#[derive(Debug)]
pub enum LoadError {
    /// The file could not be read.
    Io {
        /// The path as given.
        path: String,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The file (or built-in) did not parse.
    Parse(poly::Error),
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadError::Io { path, source } => write!(f, "{path}: cannot read: {source}"),
            LoadError::Parse(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for LoadError {}

/// Loads `arg`: a path when it ends in `.zm` or names an existing file,
/// otherwise a built-in method name.
pub fn load_method(arg: &str) -> Result<Method, LoadError> {
    if arg.ends_with(".zm") || Path::new(arg).is_file() {
        let src = std::fs::read_to_string(arg)
            .map_err(|source| LoadError::Io { path: arg.to_owned(), source })?;
        Method::parse(arg, &src).map_err(LoadError::Parse)
    } else {
        poly::builtin(arg).map_err(LoadError::Parse)
    }
}
