//! `zcheck`: the command-line face of zcheck. The command line lives in the
//! library (`zcheck::cli`), arguments to exit code; this binary only runs it.

use std::process::ExitCode;

fn main() -> ExitCode {
    zcheck::cli::main()
}
