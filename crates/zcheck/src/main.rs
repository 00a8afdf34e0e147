//! `zcheck`: the command-line face of zcheck.
//!
//! The subcommands live in the library (`zcheck::cli`); this file parses
//! the arguments, runs the command, and turns an error into a message on
//! stderr and exit code 2.

use std::io::Write as _;
use std::process::ExitCode;

use clap::{CommandFactory, FromArgMatches};
use zcheck::cli::Cli;

/// The most bytes of an error message printed: enough for any real error,
/// and a bound on what a hostile input can put on the terminal.
const MAX_ERROR_BYTES: usize = 4000;

fn main() -> ExitCode {
    // `--phi -1`, `--eps -0.5`: a negative number is a value, never a flag.
    let command = Cli::command().mut_subcommands(|s| s.allow_negative_numbers(true));
    let cli = match command.try_get_matches().and_then(|m| Cli::from_arg_matches(&m)) {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    match cli.run() {
        Ok(code) => code,
        // The reader closed stdout early: nothing is wrong.
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            print_error(&format!("error: {}", with_sources(&e)));
            ExitCode::from(2)
        }
    }
}

/// Help and version go to stdout with exit 0; usage errors to stderr, made
/// safe to print (the user's argument is echoed), with exit 2.
fn clap_exit(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    let text = e.render().to_string();
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            match zcheck::cli::output::emit(&text) {
                Ok(()) => ExitCode::SUCCESS,
                Err(_) => ExitCode::from(2),
            }
        }
        _ => {
            print_error(&text);
            ExitCode::from(2)
        }
    }
}

fn is_broken_pipe(e: &zcheck::Error) -> bool {
    e.io_error().is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
}

/// The error's message, then each of its sources after `: `.
fn with_sources(e: &zcheck::Error) -> String {
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
fn print_error(text: &str) {
    let lines: Vec<String> =
        text.trim_end().split('\n').map(|l| poly::show_invisible(l).into_owned()).collect();
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
