//! The one error type of `check`.
//!
//! In the style of jiff: an opaque [`Error`] with a [`kind`](Error::kind), a
//! lower-case message, and a [`source`](std::error::Error::source) chain. A
//! parse error keeps `poly`'s located error (file:line:column) as its
//! source and shows it unchanged; an I/O error carries the path it failed on.

use std::fmt;
use std::path::{Path, PathBuf};

/// What kind of failure an [`Error`] reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A parameter the method declares has no value.
    MissingParam,
    /// The method did not parse, or its exact derivation failed (see the
    /// source, a located [`poly::Error`]).
    Poly,
    /// An eigenvalue solver did not converge within its iteration bound.
    NoConvergence,
    /// A value that must be finite was not.
    NotFinite,
    /// A file could not be read (see [`Error::path`]), or is no `.zm`
    /// file (a directory, empty, too large).
    Io,
    /// A value is finite but beyond what the `f64` witnesses can work with
    /// (they square magnitudes): `f64` cannot represent the question.
    OutOfRange,
    /// The native compiler (feature `jit`) could not compile a step.
    Jit,
    /// The caller stopped a long run (a Ctrl-C) before it ended.
    Interrupted,
}

/// Why numeric work on a method, or loading it, failed.
pub struct Error {
    inner: Box<Inner>,
}

struct Inner {
    kind: ErrorKind,
    message: String,
    path: Option<PathBuf>,
    source: Option<Source>,
}

enum Source {
    Poly(poly::Error),
    Io(std::io::Error),
}

impl Error {
    fn new(kind: ErrorKind, message: String) -> Error {
        Error { inner: Box::new(Inner { kind, message, path: None, source: None }) }
    }

    pub(crate) fn missing_param(method: &str, param: &str) -> Error {
        Error::new(
            ErrorKind::MissingParam,
            format!(
                "method `{method}` needs a value for parameter `{param}`: \
                 expected it among the given parameters"
            ),
        )
    }

    pub(crate) fn no_convergence(solver: &'static str) -> Error {
        Error::new(
            ErrorKind::NoConvergence,
            format!("{solver}: eigenvalues did not converge within the iteration bound"),
        )
    }

    pub(crate) fn singular(method: &str, phi: f64) -> Error {
        Error::new(
            ErrorKind::NotFinite,
            format!("method `{method}`: the step's linear system is singular at Phi = {phi}: expected a Phi where it has a unique solution"),
        )
    }

    pub(crate) fn not_finite(what: &str) -> Error {
        Error::new(ErrorKind::NotFinite, format!("{what} is not finite: expected a finite number"))
    }

    pub(crate) fn interrupted(done: u64, asked: u64) -> Error {
        Error::new(
            ErrorKind::Interrupted,
            format!("interrupted after {done} of {asked} simulated steps"),
        )
    }

    pub(crate) fn out_of_range(what: &str) -> Error {
        Error::new(
            ErrorKind::OutOfRange,
            format!("{what}: f64 cannot represent this question (expected magnitudes below 1e100)"),
        )
    }

    #[cfg(feature = "jit")]
    pub(crate) fn jit(method: &str, what: &str) -> Error {
        Error::new(ErrorKind::Jit, format!("method `{method}`: the native compiler failed: {what}"))
    }

    /// A path that is no readable `.zm` file: `what` says why.
    pub(crate) fn not_a_method_file(path: &Path, what: &str) -> Error {
        let shown = poly::advanced::show_invisible(&path.display().to_string()).into_owned();
        // A location (`1:1: ...`) follows the path without a space.
        let sep = if what.starts_with(|c: char| c.is_ascii_digit()) { ":" } else { ": " };
        let mut e = Error::new(ErrorKind::Io, format!("{shown}{sep}{what}"));
        e.inner.path = Some(path.to_owned());
        e
    }

    pub(crate) fn io(path: &Path, source: std::io::Error) -> Error {
        let shown = poly::advanced::show_invisible(&path.display().to_string()).into_owned();
        let mut e = Error::new(ErrorKind::Io, format!("{shown}: cannot read"));
        e.inner.path = Some(path.to_owned());
        e.inner.source = Some(Source::Io(source));
        e
    }

    /// What kind of failure this is.
    pub fn kind(&self) -> ErrorKind {
        self.inner.kind
    }

    /// The file involved, for I/O and parse errors.
    pub fn path(&self) -> Option<&Path> {
        self.inner.path.as_deref()
    }

    /// The located `poly` error underneath, for parse and derivation errors.
    pub fn poly_error(&self) -> Option<&poly::Error> {
        match &self.inner.source {
            Some(Source::Poly(e)) => Some(e),
            _ => None,
        }
    }
}

impl From<poly::Error> for Error {
    fn from(e: poly::Error) -> Error {
        let mut err = Error::new(ErrorKind::Poly, String::new());
        err.inner.source = Some(Source::Poly(e));
        err
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.inner.source {
            // Transparent: poly's message already says file:line:column.
            Some(Source::Poly(e)) => fmt::Display::fmt(e, f),
            _ => f.write_str(&self.inner.message),
        }
    }
}

impl fmt::Debug for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Error")
            .field("kind", &self.inner.kind)
            .field("message", &self.to_string())
            .field("path", &self.inner.path)
            .finish()
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.inner.source {
            // Transparent for poly: its own source, if any.
            Some(Source::Poly(e)) => std::error::Error::source(e),
            Some(Source::Io(e)) => Some(e),
            None => None,
        }
    }
}
