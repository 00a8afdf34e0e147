//! Resolving a method argument: a built-in name or a path to a `.zm` file.

use std::io::Read;
use std::path::Path;

use poly::Method;

use crate::error::Error;

/// The largest `.zm` file read, in bytes: far beyond any method, and a bound
/// on the work when the path names something endless such as `/dev/zero`.
pub const MAX_FILE_BYTES: u64 = 4 << 20;

/// Whether `arg` names a file rather than a built-in: it ends in `.zm`,
/// contains a path separator, or names something that exists.
pub fn is_path(arg: &str) -> bool {
    arg.ends_with(".zm")
        || arg.contains('/')
        || arg.contains(std::path::MAIN_SEPARATOR)
        || Path::new(arg).exists()
}

/// Loads `arg`: a file when [`is_path`] says so, otherwise a built-in name.
///
/// A file is read up to [`MAX_FILE_BYTES`]; a directory, an empty file and
/// a larger one are errors that say so, and bytes that are not UTF-8 are an
/// error located at their line and column.
pub fn load_method(arg: &str) -> Result<Method, Error> {
    if !is_path(arg) {
        return poly::builtin(arg).map_err(Error::from);
    }
    let path = Path::new(arg);
    let meta = std::fs::metadata(path).map_err(|e| Error::io(path, e))?;
    if meta.is_dir() {
        return Err(Error::not_a_method_file(path, "is a directory: expected a .zm file"));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| Error::io(path, e))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        let limit = format!("file too large: expected at most {} MiB", MAX_FILE_BYTES >> 20);
        return Err(Error::not_a_method_file(path, &limit));
    }
    if bytes.is_empty() {
        return Err(Error::not_a_method_file(
            path,
            "1:1: the file is empty: expected a .zm method",
        ));
    }
    Method::parse_bytes(arg, &bytes).map_err(Error::from)
}
