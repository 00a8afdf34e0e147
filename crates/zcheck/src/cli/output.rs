//! Writing results to stdout and errors to stderr, in one place.
//!
//! A reader that stops early (`zcheck derive x | head -1`, `| true`) closes
//! the pipe; that is the reader's choice, not an error, so a broken pipe ends
//! the output quietly instead of panicking as `print!` does. An error is
//! printed made safe (invisible characters shown as `U+XXXX`) and bounded.

use std::io::Write;
use std::process::ExitCode;

use crate::error::Error;

/// The most bytes of an error message printed: enough for any real error,
/// and a bound on what a hostile input can put on the terminal.
const MAX_ERROR_BYTES: usize = 4000;

/// Writes `text` to stdout. A closed pipe is not an error: the rest of the
/// text is dropped. Any other write failure (a full disk) is.
pub(crate) fn emit(text: &str) -> std::io::Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// [`emit`] with a line feed after `text`.
pub(crate) fn emitln(text: &str) -> std::io::Result<()> {
    emit(&format!("{text}\n"))
}

/// Help and version go to stdout with exit 0; usage errors to stderr, made
/// safe to print (the user's argument is echoed), with exit 2.
pub(crate) fn clap_exit(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    let text = e.render().to_string();
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => match emit(&text) {
            Ok(()) => ExitCode::SUCCESS,
            Err(_) => ExitCode::from(2),
        },
        _ => {
            print_error(&text);
            ExitCode::from(2)
        }
    }
}

pub(crate) fn is_broken_pipe(e: &Error) -> bool {
    e.io_error().is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
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

/// Prints an error on stderr: control and invisible characters (other than
/// line feeds) as `U+XXXX`, and at most [`MAX_ERROR_BYTES`]. A failure to
/// write stderr is ignored: there is nowhere left to report it.
pub(crate) fn print_error(text: &str) {
    let lines: Vec<String> = text
        .trim_end()
        .split('\n')
        .map(|l| poly::advanced::show_invisible(l).into_owned())
        .collect();
    let mut shown = lines.join("\n");
    if shown.len() > MAX_ERROR_BYTES {
        let mut cut = MAX_ERROR_BYTES;
        while !shown.is_char_boundary(cut) {
            cut -= 1;
        }
        let more = shown.len() - cut;
        shown.truncate(cut);
        shown.push_str(&format!("… ({more} more bytes)"));
    }
    let _ = writeln!(std::io::stderr().lock(), "{shown}");
}
