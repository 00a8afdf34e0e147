//! Fuzz target `tableau`: see `fuzz/src/app.rs` and FUZZING.md.
#![no_main]

#[path = "../src/app.rs"]
mod app;

libfuzzer_sys::fuzz_target!(|data: &[u8]| app::tableau(data));
