//! `zcheck`: the command-line face of zcheck. The command line lives in the
//! library (`zcheck::cli`), arguments to exit code; this binary only runs it.

use std::process::ExitCode;

/// The exact engine allocates and frees many small big integers; mimalloc
/// serves them faster than glibc's allocator (DESIGN.md, "Why mimalloc as
/// the allocator?").
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    zcheck::cli::main()
}
