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
    /// A name declared twice, used before its declaration, assigned where
    /// it may not be, or a missing `method`/`state` line.
    Declaration,
    /// The z-domain and state-space derivations disagree (an internal fault,
    /// reported rather than hidden).
    RoutesDisagree,
    /// The bytes are not UTF-8 text.
    Encoding,
    /// A method name that is no built-in.
    UnknownBuiltin,
    /// Stability analysis: a symbol other than `z` and `Phi` remains (give
    /// it a value first).
    ExtraSymbol,
    /// Stability analysis: the polynomial does not depend on `z` (no roots
    /// to classify).
    NoRoots,
    /// An unknown (`unknown a` or a primed state `x'`) without an equation,
    /// with two, an equation for a name that is not an unknown, one equation
    /// more than there are unknowns, or an equation that holds no unknown.
    Equation,
    /// A prime on a name that has no end-of-step value: a temporary, a
    /// parameter, a constant or a history read (`y'@1`).
    BadPrime,
    /// The implicit system is singular for every Φ.
    Singular,
    /// A `const` whose expression is not an exact constant (it reads a
    /// parameter, a state variable or an unknown, calls a function other
    /// than `sqrt`, `cbrt` or `root`, or takes a root of something other
    /// than a positive integer), or a root function outside a `const` line.
    BadConstant,
    /// A series of Ψ or |z| that does not exist for this χ (not second
    /// order, no complex pair near Φ = 0, or Ψ not a series over Q).
    NoSeries,
    /// The frequency series (Ψ, |z|²) of a characteristic polynomial that
    /// is not second order in z.
    NotSecondOrder,
    /// The frequency series of a χ with no complex pair for small Φ > 0
    /// (or one near Ψ = π).
    NotOscillatory,
    /// Ψ or |z| is not a series over Q (its value at Φ = 0 is not a
    /// rational square); `advanced::series::psi_series_scaled` gives the
    /// scaled form.
    IrrationalSeries,
    /// Boundedness that χ alone does not decide: a repeated root on the
    /// unit circle, bounded exactly when the transition matrix P is
    /// semisimple there (ask the `Derivation`, which has P).
    Undecided,
    /// The analysis needs the other test equation: a scalar program (it
    /// reads `w`) given to an oscillator analysis, or an oscillator program
    /// with no scalar form (a partitioned method) given to the w-plane.
    TestEquation,
    /// Order conditions: a tree order (or a modified equation's power)
    /// beyond the supported maximum.
    TreeOrder,
    /// Order analysis: a question not decided for this input (the SSP
    /// coefficient of an implicit method with irrational entries).
    Unsupported,
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

/// The most characters of the offending line an error shows, around the column.
const SNIPPET_CHARS: usize = 100;

/// The most characters of a message or file name an error shows.
const MESSAGE_CHARS: usize = 1000;

impl fmt::Display for Error {
    /// `file:line:col: message`, then the line with a caret under the span.
    ///
    /// What comes from the user is made safe to print: control and invisible
    /// characters are shown as `U+XXXX`, the line is cut to about 100
    /// characters around the column, and the message and file name are cut
    /// to 1000 characters, so a hostile file cannot flood or drive the
    /// terminal.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let file = clip(&show_invisible(&self.file), MESSAGE_CHARS);
        let message = clip(&show_invisible(&self.message), MESSAGE_CHARS);
        match (self.span.line, file.is_empty()) {
            (0, true) => return write!(f, "{message}"),
            (0, false) => return write!(f, "{file}: {message}"),
            _ => write!(f, "{file}:{}:{}: {message}", self.span.line, self.span.col)?,
        }
        if !self.source_line.is_empty() {
            let (text, caret_at, caret_len) = snippet(&self.source_line, self.span);
            let n = self.span.line.to_string();
            let pad = " ".repeat(n.len());
            write!(f, "\n{pad} |\n{n} | {text}\n{pad} | ")?;
            write!(f, "{}{}", " ".repeat(caret_at), "^".repeat(caret_len))?;
        }
        Ok(())
    }
}

/// Whether `c` would be invisible, or would act on the terminal, if printed
/// raw: control characters (NUL, ESC, CR, ...), format characters (zero-width
/// spaces and joiners, bidirectional overrides, the byte-order mark) and
/// spaces other than the ASCII space.
pub(crate) fn is_invisible(c: char) -> bool {
    c.is_control()
        || (c.is_whitespace() && c != ' ')
        || matches!(c,
            '\u{00AD}' | '\u{034F}' | '\u{061C}' | '\u{115F}' | '\u{1160}' | '\u{17B4}'
            | '\u{17B5}' | '\u{180B}'..='\u{180F}' | '\u{200B}'..='\u{200F}'
            | '\u{202A}'..='\u{202E}' | '\u{2060}'..='\u{206F}' | '\u{3164}'
            | '\u{FE00}'..='\u{FE0F}' | '\u{FEFF}' | '\u{FFA0}' | '\u{FFF0}'..='\u{FFFB}'
            | '\u{E0000}'..='\u{E0FFF}')
}

/// `s` with every control or invisible character written as `U+XXXX` (tabs
/// and line feeds too), so the text is safe to print on a terminal.
///
/// ```
/// assert_eq!(poly::advanced::show_invisible("a\u{1b}[2Jb\u{200b}"), "aU+001B[2JbU+200B");
/// ```
pub fn show_invisible(s: &str) -> std::borrow::Cow<'_, str> {
    if !s.chars().any(is_invisible) {
        return std::borrow::Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if is_invisible(c) {
            out.push_str(&format!("U+{:04X}", c as u32));
        } else {
            out.push(c);
        }
    }
    std::borrow::Cow::Owned(out)
}

/// At most `max` characters of `s`, the cut marked with `…`.
fn clip(s: &str, max: usize) -> String {
    match s.char_indices().nth(max) {
        None => s.to_owned(),
        Some((at, _)) => format!("{}… ({} more characters)", &s[..at], s[at..].chars().count()),
    }
}

/// The part of `line` shown under an error: about [`SNIPPET_CHARS`]
/// characters around the span's column, invisible characters as `U+XXXX`
/// (tabs as one space, so the caret stays aligned), `…` where cut. Returns
/// the text, the caret's offset in it and the caret's length.
fn snippet(line: &str, span: Span) -> (String, usize, usize) {
    let chars: Vec<char> = line.chars().collect();
    let col = (span.col.max(1) as usize - 1).min(chars.len());
    let start = col.saturating_sub(SNIPPET_CHARS / 2);
    let end = (start + SNIPPET_CHARS).min(chars.len());
    let start = end.saturating_sub(SNIPPET_CHARS).min(start);
    let mut text = String::new();
    let mut width = 0;
    let mut caret_at = 0;
    let mut caret_end = None;
    if start > 0 {
        text.push('…');
        width += 1;
    }
    let span_end = col + span.len.max(1) as usize;
    for (k, &c) in chars.iter().enumerate().take(end).skip(start) {
        if k == col {
            caret_at = width;
        }
        if k == span_end {
            caret_end = Some(width);
        }
        let shown = match c {
            '\t' => " ".to_owned(),
            c if is_invisible(c) => format!("U+{:04X}", c as u32),
            c => c.to_string(),
        };
        width += shown.chars().count();
        text.push_str(&shown);
    }
    if col >= end {
        caret_at = width;
    }
    let caret_len = caret_end.unwrap_or(width + 1).saturating_sub(caret_at).max(1);
    if end < chars.len() {
        text.push('…');
    }
    (text, caret_at, caret_len)
}

impl std::error::Error for Error {}

impl Error {
    /// An analysis error: no source location.
    pub(crate) fn analysis(kind: ErrorKind, message: impl Into<String>) -> Error {
        Error::new(kind, Span::default(), message)
    }

    /// No built-in is called `name`; `names` are the ones there are.
    pub(crate) fn unknown_builtin(name: &str, names: &[&str]) -> Error {
        Error::new(
            ErrorKind::UnknownBuiltin,
            Span::default(),
            format!(
                "no built-in method named `{name}`: expected one of {}, or a path to a .zm file",
                names.join(", ")
            ),
        )
    }

    /// The error for bytes that are not UTF-8, located at the first bad byte.
    pub(crate) fn not_utf8(file: &str, bytes: &[u8], e: std::str::Utf8Error) -> Error {
        let good = &bytes[..e.valid_up_to()];
        let line = good.iter().filter(|&&b| b == b'\n').count();
        let line_start = good.iter().rposition(|&b| b == b'\n').map_or(0, |p| p + 1);
        let prefix = String::from_utf8_lossy(&good[line_start..]);
        let col = prefix.chars().count() + 1;
        let lossy = String::from_utf8_lossy(bytes);
        Error::new(
            ErrorKind::Encoding,
            Span { line: line as u32 + 1, col: col as u32, len: 1 },
            format!(
                "invalid UTF-8 (byte 0x{:02X} at offset {}): expected UTF-8 text",
                bytes.get(e.valid_up_to()).copied().unwrap_or(0),
                e.valid_up_to()
            ),
        )
        .located(file, &lossy)
    }
}

/// Something a program says that it probably does not mean, located as an
/// [`Error`] is but never fatal: a value assigned and never read, a state
/// variable the step never assigns, a tableau whose weights do not sum to
/// 1. The caller decides whether to show it or to refuse the input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Warning {
    /// Where: the name or the entry the warning is about.
    pub span: Span,
    /// What is wrong and what was probably meant.
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.span.line, self.span.col, self.message)
    }
}
