//! Resolving a method argument: a built-in name or a path to a `.zm` file.

use std::path::Path;

use poly::Method;

use crate::error::Error;

/// Loads `arg`: a path when it ends in `.zm` or names an existing file,
/// otherwise a built-in method name.
pub fn load_method(arg: &str) -> Result<Method, Error> {
    if arg.ends_with(".zm") || Path::new(arg).is_file() {
        let src =
            std::fs::read_to_string(arg).map_err(|source| Error::io(Path::new(arg), source))?;
        Method::parse(arg, &src).map_err(Error::from)
    } else {
        poly::builtin(arg).map_err(Error::from)
    }
}
