//! The one error type of the zcheck application.
//!
//! In the style of `poly` and `check` (after jiff): an opaque [`Error`] with
//! a [`kind`](Error::kind) to branch on, a lower-case message that says what
//! was expected, the [`location`](Error::location) of a mistake in an input
//! file, and a [`source`](std::error::Error::source) chain. An error of
//! `poly` or `check` is carried unchanged and shows its own message (a parse
//! error keeps its `file:line:column:` and caret); an error with context
//! shows the context, then its source. The binary prints the message and
//! every source after it, each after `: `.

use std::fmt;
use std::sync::Arc;

/// What kind of failure an [`Error`] reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A command-line argument is malformed or out of range, or two
    /// arguments conflict.
    Usage,
    /// An input file (a `.zm` method, a Butcher tableau, a scene) could not
    /// be read or is malformed; see [`Error::location`].
    File,
    /// A method did not parse or derive (the source is a `poly::Error`).
    Method,
    /// The question does not apply to the method: a parameter without a
    /// value, no `param D` for a damped question, no conserved form.
    Unsupported,
    /// Numeric work failed: a `check::Error`, a reference integration, a
    /// scene's Newton iteration or its modal reduction.
    Numeric,
    /// Writing the output or a file failed.
    Io,
    /// A figure could not be drawn.
    Figure,
    /// The user stopped a long run (Ctrl-C): exit code 130.
    Interrupted,
}

/// Where in an input file a mistake is: 1-based line and column (in
/// characters).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Location {
    /// The line, from 1.
    pub line: usize,
    /// The column, from 1.
    pub col: usize,
}

/// Why a command of the application failed.
#[derive(Clone)]
pub struct Error {
    inner: Box<Inner>,
}

#[derive(Clone)]
struct Inner {
    kind: ErrorKind,
    /// `None`: the error shows its source's message (`poly`'s, `check`'s,
    /// an I/O error's), and its chain continues with the source's source.
    message: Option<String>,
    location: Option<Location>,
    source: Option<Arc<dyn std::error::Error + Send + Sync>>,
}

impl Error {
    fn new(kind: ErrorKind, message: impl Into<String>) -> Error {
        Error {
            inner: Box::new(Inner {
                kind,
                message: Some(message.into()),
                location: None,
                source: None,
            }),
        }
    }

    fn transparent(
        kind: ErrorKind,
        location: Option<Location>,
        source: impl std::error::Error + Send + Sync + 'static,
    ) -> Error {
        Error {
            inner: Box::new(Inner {
                kind,
                message: None,
                location,
                source: Some(Arc::new(source)),
            }),
        }
    }

    /// A bad command-line argument.
    pub(crate) fn usage(message: impl Into<String>) -> Error {
        Error::new(ErrorKind::Usage, message)
    }

    /// A method that does not parse or derive, said in `message` (which
    /// quotes the `poly` error it comes from).
    pub(crate) fn method(message: impl Into<String>) -> Error {
        Error::new(ErrorKind::Method, message)
    }

    /// A question that does not apply to the method.
    pub(crate) fn unsupported(message: impl Into<String>) -> Error {
        Error::new(ErrorKind::Unsupported, message)
    }

    /// Numeric work that failed.
    pub(crate) fn numeric(message: impl Into<String>) -> Error {
        Error::new(ErrorKind::Numeric, message)
    }

    /// A long run the user stopped (Ctrl-C); `message` says how far it got.
    pub(crate) fn interrupted(message: impl Into<String>) -> Error {
        Error::new(ErrorKind::Interrupted, message)
    }

    /// A figure that could not be drawn.
    pub(crate) fn figure(message: impl Into<String>) -> Error {
        Error::new(ErrorKind::Figure, message)
    }

    /// A mistake in the file `path` at a 1-based line and column, shown as
    /// `path:line:col: message`. Line 0 (a file that could not be read at
    /// all) has no location.
    pub(crate) fn file(path: &str, line: usize, col: usize, message: &str) -> Error {
        let mut e = Error::new(ErrorKind::File, format!("{path}:{line}:{col}: {message}"));
        e.inner.location = (line > 0).then_some(Location { line, col });
        e
    }

    /// An I/O failure: `message` (which names the file), then the I/O
    /// error as its source.
    pub(crate) fn io(message: impl Into<String>, source: std::io::Error) -> Error {
        let mut e = Error::new(ErrorKind::Io, message);
        e.inner.source = Some(Arc::new(source));
        e
    }

    /// This error under `context`: the context is shown first, then this
    /// error; the kind and location stay.
    pub(crate) fn context(self, context: impl Into<String>) -> Error {
        let (kind, location) = (self.inner.kind, self.inner.location);
        let mut e = Error::new(kind, context);
        e.inner.location = location;
        e.inner.source = Some(Arc::new(self));
        e
    }

    /// What kind of failure this is.
    pub(crate) fn kind(&self) -> ErrorKind {
        self.inner.kind
    }

    /// Where in an input file the mistake is, when it is in one.
    pub fn location(&self) -> Option<Location> {
        self.inner.location
    }

    /// The I/O error underneath, if any (a closed pipe, a full disk).
    pub(crate) fn io_error(&self) -> Option<&std::io::Error> {
        let mut next: Option<&(dyn std::error::Error + 'static)> = match &self.inner.source {
            Some(s) => Some(s.as_ref()),
            None => None,
        };
        while let Some(e) = next {
            if let Some(io) = e.downcast_ref::<std::io::Error>() {
                return Some(io);
            }
            if let Some(inner) = e.downcast_ref::<Error>() {
                return inner.io_error();
            }
            next = e.source();
        }
        None
    }
}

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

impl From<poly::Error> for Error {
    fn from(e: poly::Error) -> Error {
        let span = e.span();
        let location = (span.line > 0)
            .then_some(Location { line: span.line as usize, col: span.col as usize });
        Error::transparent(ErrorKind::Method, location, e)
    }
}

impl From<check::Error> for Error {
    fn from(e: check::Error) -> Error {
        let kind = match e.kind() {
            check::ErrorKind::Poly => ErrorKind::Method,
            check::ErrorKind::Io => ErrorKind::File,
            check::ErrorKind::MissingParam => ErrorKind::Usage,
            check::ErrorKind::Interrupted => ErrorKind::Interrupted,
            _ => ErrorKind::Numeric,
        };
        let location = e.poly_error().map(poly::Error::span).filter(|s| s.line > 0);
        let location = location.map(|s| Location { line: s.line as usize, col: s.col as usize });
        Error::transparent(kind, location, e)
    }
}

impl From<std::io::Error> for Error {
    fn from(e: std::io::Error) -> Error {
        Error::transparent(ErrorKind::Io, None, e)
    }
}

impl From<serde_json::Error> for Error {
    fn from(e: serde_json::Error) -> Error {
        Error::transparent(ErrorKind::Io, None, e)
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.inner.message, &self.inner.source) {
            (Some(message), _) => f.write_str(message),
            (None, Some(source)) => fmt::Display::fmt(source, f),
            (None, None) => Ok(()),
        }
    }
}

impl fmt::Debug for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Error")
            .field("kind", &self.inner.kind)
            .field("message", &self.to_string())
            .field("location", &self.inner.location)
            .finish()
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        let source = self.inner.source.as_deref()?;
        match self.inner.message {
            Some(_) => Some(source),
            // Transparent: the source's message is this error's.
            None => source.source(),
        }
    }
}

/// The error's message, then each of its sources after `: `.
pub(crate) fn with_sources(e: &Error) -> String {
    let mut text = e.to_string();
    let mut next = std::error::Error::source(e);
    while let Some(source) = next {
        text.push_str(&format!(": {source}"));
        next = source.source();
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Context comes first and keeps the kind; a transparent error shows
    /// its source's message once; the I/O error is found under context.
    #[test]
    fn chain_and_kind() {
        let io = std::io::Error::new(std::io::ErrorKind::BrokenPipe, "pipe closed");
        let e = Error::from(io).context("writing");
        assert_eq!(e.to_string(), "writing");
        assert_eq!(e.kind(), ErrorKind::Io);
        let chain: Vec<String> =
            std::iter::successors(std::error::Error::source(&e), |s| s.source())
                .map(ToString::to_string)
                .collect();
        assert_eq!(chain, ["pipe closed"]);
        assert_eq!(e.io_error().map(std::io::Error::kind), Some(std::io::ErrorKind::BrokenPipe));
        let f = Error::file("a.toml", 2, 3, "bad");
        assert_eq!(f.to_string(), "a.toml:2:3: bad");
        assert_eq!(f.location(), Some(Location { line: 2, col: 3 }));
        assert_eq!(Error::file("a.toml", 0, 0, "cannot read").location(), None);
    }
}
