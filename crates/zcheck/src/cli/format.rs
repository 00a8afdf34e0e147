//! The one output format type, [`Format`]: each command accepts the formats
//! it writes (text, JSON, LaTeX, Markdown), through [`Format::parser`].

use clap::builder::TypedValueParser as _;

/// An output format, one type for every command. Each command accepts the
/// formats it writes, through [`Format::parser`]; a format its parser
/// refuses never reaches it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Format {
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
pub(crate) const TEXT_JSON: &[Format] = &[Format::Text, Format::Json];

/// The formats of the commands that write a document.
pub(crate) const MARKDOWN_JSON: &[Format] = &[Format::Markdown, Format::Json];

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
    pub(crate) fn parser(
        formats: &'static [Format],
    ) -> impl clap::builder::TypedValueParser<Value = Format> {
        clap::builder::PossibleValuesParser::new(formats.iter().map(|f| f.name())).map(|name| {
            Format::ALL.into_iter().find(|f| f.name() == name).expect("a format's own name")
        })
    }
}
