//! Writing results to stdout and errors to stderr, in one place.
//!
//! A reader that stops early (`zcheck derive x | head -1`, `| true`) closes
//! the pipe; that is the reader's choice, not an error, so a broken pipe ends
//! the output quietly instead of panicking as `print!` does. An error is
//! printed made safe (invisible characters shown as `U+XXXX`) and bounded.

use std::io::Write;
use std::process::ExitCode;

use crate::error::Error;

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

pub(crate) use crate::error::with_sources;
pub(crate) use crate::warn::print_error;
