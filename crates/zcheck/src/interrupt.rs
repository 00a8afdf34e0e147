//! Ctrl-C for long runs (`verify`, `drift`, `advise`'s checking simulation,
//! `map`, `tradeoff`): one flag that their loops poll, set by a SIGINT
//! handler that only the command line installs ([`install`]). A library
//! caller (the Python module, a test) never gets a handler: the flag then
//! stays clear and nothing stops early.
//!
//! Where SIGINT was ignored when the process started (a background job of a
//! non-interactive shell, `nohup`), it stays ignored, as Python does: the
//! user who started the run that way asked not to be interrupted by it.
//!
//! A script that must know when the handler is in place (a test that sends
//! SIGINT) sets `ZCHECK_READY=1`: [`install`] then writes `zcheck: ready` on
//! stderr once the disposition is settled. With `ZCHECK_READY=wait` it also
//! waits for one line (or the end) on stdin before the run starts, so the
//! script decides when the run begins, and no timing decides anything.

use std::io::{BufRead, Write};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Once;

use crate::error::Error;

static REQUESTED: AtomicBool = AtomicBool::new(false);
static INSTALL: Once = Once::new();

/// The exit code of a run stopped by Ctrl-C (128 + SIGINT), as shells use.
pub(crate) const EXIT_CODE: u8 = 130;

/// Whether the user asked the run to stop.
pub(crate) fn requested() -> bool {
    REQUESTED.load(Ordering::Relaxed)
}

/// The flag itself, for loops that take an `AtomicBool` (check's drift).
pub(crate) fn flag() -> &'static AtomicBool {
    &REQUESTED
}

/// `Err` (kind `Interrupted`, with `what` as its message) once the user
/// asked the run to stop.
pub(crate) fn check(what: impl FnOnce() -> String) -> Result<(), Error> {
    if requested() {
        Err(Error::interrupted(what()))
    } else {
        Ok(())
    }
}

/// Installs the SIGINT handler, once per process, unless SIGINT was ignored
/// at start; then the readiness signal of `ZCHECK_READY` (module docs).
pub(crate) fn install() {
    INSTALL.call_once(|| {
        if !ignored_at_start() {
            // A handler set before (an embedding) is no error: the run then
            // cannot be stopped early, and ends as it would have.
            let _ = ctrlc::set_handler(|| REQUESTED.store(true, Ordering::SeqCst));
        }
        if let Ok(mode) = std::env::var("ZCHECK_READY") {
            let mut err = std::io::stderr().lock();
            let _ = writeln!(err, "zcheck: ready");
            let _ = err.flush();
            drop(err);
            if mode == "wait" {
                let _ = std::io::stdin().lock().read_line(&mut String::new());
            }
        }
    });
}

/// Whether SIGINT's disposition is "ignore" now, before any handler of
/// ours: the state the process was started in.
#[cfg(unix)]
fn ignored_at_start() -> bool {
    // SAFETY: sigaction with a null new action only reads the current
    // disposition into `old`, which is a plain C struct we own.
    unsafe {
        let mut old: libc::sigaction = std::mem::zeroed();
        libc::sigaction(libc::SIGINT, std::ptr::null(), &mut old) == 0
            && old.sa_sigaction == libc::SIG_IGN
    }
}

#[cfg(not(unix))]
fn ignored_at_start() -> bool {
    false
}
