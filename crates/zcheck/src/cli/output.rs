//! Writing results to stdout, in one place.
//!
//! A reader that stops early (`zcheck derive x | head -1`, `| true`) closes
//! the pipe; that is the reader's choice, not an error, so a broken pipe ends
//! the output quietly instead of panicking as `print!` does.

use std::io::Write;

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
