//! Ctrl-C on every long-running command (`verify`, `drift`, `advise`'s
//! checking simulation, `map`, `tradeoff`): a clean message, a partial
//! result where one makes sense, exit code 130; and where SIGINT was
//! ignored at start (a background job of a script), it stays ignored.
//!
//! No timing decides anything here. Each child is started with its SIGINT
//! disposition set by the test itself (whatever the harness inherited), and
//! with `ZCHECK_READY=wait`: it says `zcheck: ready` on stderr once its
//! handler is settled, then waits for a line on stdin. The test sends
//! SIGINT in between, then lets the run start. A hang is caught by a
//! one-minute guard, which only a hang misses.

#![cfg(unix)]

use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::process::CommandExt;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// How SIGINT is set in the child before zcheck starts.
#[derive(Clone, Copy)]
enum Sigint {
    Default,
    Ignored,
}

/// What a run gave: its status, stdout and stderr.
struct Ended {
    status: ExitStatus,
    stdout: String,
    stderr: String,
}

/// Starts zcheck with `args` and SIGINT as `sigint`, waits for its
/// readiness line, sends SIGINT, lets the run begin and waits for its end.
fn interrupted(args: &[&str], sigint: Sigint) -> Ended {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_zcheck"));
    cmd.args(args)
        .env("ZCHECK_READY", "wait")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let disposition = match sigint {
        Sigint::Default => libc::SIG_DFL,
        Sigint::Ignored => libc::SIG_IGN,
    };
    // SAFETY: between fork and exec only async-signal-safe calls are
    // allowed; signal(2) is one.
    unsafe {
        cmd.pre_exec(move || {
            libc::signal(libc::SIGINT, disposition);
            Ok(())
        });
    }
    let mut child = cmd.spawn().expect("zcheck starts");
    let mut stderr = BufReader::new(child.stderr.take().expect("stderr piped"));
    let mut head = String::new();
    loop {
        let mut line = String::new();
        let n = stderr.read_line(&mut line).expect("stderr readable");
        assert!(n > 0, "{args:?} ended before it was ready: {head}");
        head += &line;
        if line.trim_end() == "zcheck: ready" {
            break;
        }
    }
    // SAFETY: kill(2) on our own child's pid.
    let sent = unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGINT) };
    assert_eq!(sent, 0, "SIGINT sent");
    let mut stdin = child.stdin.take().expect("stdin piped");
    stdin.write_all(b"go\n").expect("the gate opens");
    drop(stdin);
    let mut stdout = child.stdout.take().expect("stdout piped");
    let out_reader = std::thread::spawn(move || {
        let mut s = String::new();
        stdout.read_to_string(&mut s).map(|_| s)
    });
    let err_reader = std::thread::spawn(move || {
        let mut s = String::new();
        stderr.read_to_string(&mut s).map(|_| s)
    });
    let status = wait_within(&mut child, Duration::from_secs(60), args);
    Ended {
        status,
        stdout: out_reader.join().expect("reader").expect("stdout utf-8"),
        stderr: head + &err_reader.join().expect("reader").expect("stderr utf-8"),
    }
}

/// Waits for `child`; a run still going after `limit` is a hang: killed,
/// and the test fails.
fn wait_within(child: &mut Child, limit: Duration, args: &[&str]) -> ExitStatus {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().expect("waits") {
            return status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{args:?} still running {limit:?} after SIGINT");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The run stopped on SIGINT: exit 130, a one-line `interrupted: ...`
/// message naming `what`, no panic.
#[track_caller]
fn assert_stopped(e: &Ended, what: &str) {
    assert_eq!(e.status.code(), Some(130), "stderr: {}", e.stderr);
    assert!(!e.stderr.contains("panicked"), "{}", e.stderr);
    let message: Vec<&str> = e.stderr.lines().filter(|l| l.starts_with("interrupted")).collect();
    assert_eq!(message.len(), 1, "{}", e.stderr);
    assert!(message[0].contains(what), "{message:?} should name {what}");
}

/// `verify` stops its long simulation, says how far it got, prints no
/// result: a verification cut short verifies nothing.
#[test]
fn verify_stops_on_ctrl_c() {
    let e = interrupted(
        &["verify", "false_euler", "--steps", "1000000000", "--budget", "1e11"],
        Sigint::Default,
    );
    assert_stopped(&e, "simulated steps");
    assert!(e.stdout.is_empty(), "{}", e.stdout);
}

/// Started with SIGINT ignored (a script's background job), `verify` keeps
/// it ignored and runs to the end: the same document as an undisturbed run.
#[test]
fn verify_keeps_an_ignored_sigint_ignored() {
    let args = ["verify", "false_euler", "--steps", "300000", "--format", "json"];
    let e = interrupted(&args, Sigint::Ignored);
    assert_eq!(e.status.code(), Some(0), "stderr: {}", e.stderr);
    let quiet = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("zcheck runs");
    assert_eq!(e.stdout, String::from_utf8_lossy(&quiet.stdout));
    assert!(e.stdout.contains("\"agree\""), "{}", e.stdout);
}

/// `drift` prints the partial result it has (the checkpoints done, marked
/// as interrupted), then exits 130.
#[test]
fn drift_prints_its_partial_result_on_ctrl_c() {
    let e = interrupted(
        &["drift", "false_euler", "--phi", "0.1", "--steps", "1000000000000", "--format", "json"],
        Sigint::Default,
    );
    assert_stopped(&e, "partial result");
    let v: serde_json::Value = serde_json::from_str(&e.stdout).expect("a JSON document");
    assert_eq!(v["runs"][0]["interrupted"], true, "{}", e.stdout);
}

/// With SIGINT ignored, `drift` runs to its end.
#[test]
fn drift_keeps_an_ignored_sigint_ignored() {
    let e = interrupted(
        &["drift", "false_euler", "--phi", "0.1", "--steps", "5000", "--format", "json"],
        Sigint::Ignored,
    );
    assert_eq!(e.status.code(), Some(0), "stderr: {}", e.stderr);
    let v: serde_json::Value = serde_json::from_str(&e.stdout).expect("a JSON document");
    assert_eq!(v["runs"][0]["interrupted"], false, "{}", e.stdout);
}

/// `map` stops its grid between points.
#[test]
fn map_stops_on_ctrl_c() {
    let e = interrupted(
        &["map", "false_euler_damped", "--phi", "0..3", "--param", "D=0..2", "--grid", "400"],
        Sigint::Default,
    );
    assert_stopped(&e, "grid");
    assert!(e.stdout.is_empty(), "{}", e.stdout);
}

/// `tradeoff` stops between the methods it times.
#[test]
fn tradeoff_stops_on_ctrl_c() {
    let e = interrupted(&["tradeoff"], Sigint::Default);
    assert_stopped(&e, "methods timed");
    assert!(e.stdout.is_empty(), "{}", e.stdout);
}

/// `advise --scene` stops its checking simulation and says how to skip it.
#[test]
fn advise_stops_its_simulation_on_ctrl_c() {
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/chain10.toml");
    let e = interrupted(&["advise", "--scene", scene], Sigint::Default);
    assert_stopped(&e, "--no-simulate");
    assert!(e.stdout.is_empty(), "{}", e.stdout);
}
