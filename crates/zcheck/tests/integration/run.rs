//! Running the `zcheck` binary, as every command-line test here does.

use std::process::Command;

/// `zcheck ARGS`: its exit code (−1 for a signal), stdout and stderr.
pub(crate) fn zcheck(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck")).args(args).output().expect("zcheck runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
