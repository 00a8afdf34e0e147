//! Errors with a source location.
//!
//! Every error a user can cause (a bad `.zm` file) is an [`Error`] carrying
//! the file name, line and column, and a message that says what was expected.
//! The struct is opaque; [`Error::kind`] tells callers what went wrong.

use std::fmt;

/// What kind of mistake an [`Error`] reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The text does not follow the grammar.
    Syntax,
    /// A name that is not a state variable, parameter or assigned temporary.
    UnknownName,
    /// A temporary read before any assignment to it.
    ReadBeforeAssign,
    /// A product (or power) of two state-dependent values.
    Nonlinear,
    /// Division by a state variable, a parameter, or zero.
    BadDivision,
    /// A power whose exponent is not a non-negative integer literal.
    BadPower,
    /// A state-independent term in an assignment: the step must be linear.
    Affine,
    /// A name declared twice, assigned where it may not be, or a missing
    /// `method`/`state` line.
    Declaration,
    /// The z-domain and state-space derivations disagree (an internal fault,
    /// reported rather than hidden).
    RoutesDisagree,
}

/// A position in a source file, 1-based.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Span {
    /// Line number, from 1.
    pub line: u32,
    /// Column number in characters, from 1.
    pub col: u32,
    /// Length in characters (at least 1 when printing a caret).
    pub len: u32,
}

/// An error with its location and the offending line of source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    kind: ErrorKind,
    file: String,
    span: Span,
    message: String,
    source_line: String,
}

impl Error {
    pub(crate) fn new(kind: ErrorKind, span: Span, message: impl Into<String>) -> Error {
        Error {
            kind,
            file: String::new(),
            span,
            message: message.into(),
            source_line: String::new(),
        }
    }

    /// Attaches the file name and the text of the offending line.
    pub(crate) fn located(mut self, file: &str, src: &str) -> Error {
        self.file = file.to_owned();
        if self.span.line > 0 {
            self.source_line =
                src.lines().nth(self.span.line as usize - 1).unwrap_or("").to_owned();
        }
        self
    }

    /// What went wrong.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// Where it went wrong.
    pub fn span(&self) -> Span {
        self.span
    }

    /// The file name given to the parser.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// The message alone, without location.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for Error {
    /// `file:line:col: message`, then the line with a caret under the span.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}: {}", self.file, self.span.line, self.span.col, self.message)?;
        if !self.source_line.is_empty() {
            let n = self.span.line.to_string();
            let pad = " ".repeat(n.len());
            write!(f, "\n{pad} |\n{n} | {}\n{pad} | ", self.source_line)?;
            let col = self.span.col.max(1) as usize - 1;
            write!(f, "{}{}", " ".repeat(col), "^".repeat(self.span.len.max(1) as usize))?;
        }
        Ok(())
    }
}

impl std::error::Error for Error {}

impl Error {
    pub(crate) fn unknown_builtin(name: &str) -> Error {
        let names: Vec<&str> = crate::builtin_names().collect();
        Error::new(
            ErrorKind::Declaration,
            Span::default(),
            format!("no built-in method named `{name}`: expected one of {}", names.join(", ")),
        )
    }
}
