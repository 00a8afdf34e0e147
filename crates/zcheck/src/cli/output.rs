//! Writing results to stdout, in one place.
//!
//! A reader that stops early (`zcheck derive x | head -1`, `| true`) closes
//! the pipe; that is the reader's choice, not an error, so a broken pipe ends
//! the output quietly instead of panicking as `print!` does.

use std::io::Write;

use clap::builder::TypedValueParser as _;

/// Writes `text` to stdout. A closed pipe is not an error: the rest of the
/// text is dropped. Any other write failure (a full disk) is.
pub fn emit(text: &str) -> std::io::Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// [`emit`] with a line feed after `text`.
pub fn emitln(text: &str) -> std::io::Result<()> {
    emit(&format!("{text}\n"))
}

/// An output format, one type for every command. Each command accepts the
/// formats it writes, through [`Format::parser`]; a format its parser
/// refuses never reaches it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Text for people (the default of most commands).
    Text,
    /// JSON, pretty-printed.
    Json,
    /// LaTeX source (`zcheck derive`).
    Latex,
    /// A Markdown document (`zcheck paper`, `zcheck overview`).
    Markdown,
}

/// The formats of most commands.
pub const TEXT_JSON: &[Format] = &[Format::Text, Format::Json];

/// The formats of the commands that write a document.
pub const MARKDOWN_JSON: &[Format] = &[Format::Markdown, Format::Json];

impl Format {
    const ALL: [Format; 4] = [Format::Text, Format::Json, Format::Latex, Format::Markdown];

    /// The name on the command line.
    fn name(self) -> &'static str {
        match self {
            Format::Text => "text",
            Format::Json => "json",
            Format::Latex => "latex",
            Format::Markdown => "markdown",
        }
    }

    /// A clap parser accepting `formats` only, listed in that order in the
    /// help and in the error for any other value.
    pub fn parser(
        formats: &'static [Format],
    ) -> impl clap::builder::TypedValueParser<Value = Format> {
        clap::builder::PossibleValuesParser::new(formats.iter().map(|f| f.name())).map(|name| {
            Format::ALL.into_iter().find(|f| f.name() == name).expect("a format's own name")
        })
    }
}
