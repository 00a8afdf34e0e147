//! Fuzz target `scene_toml`: see `fuzz/src/app.rs` and FUZZING.md.
#![no_main]

#[path = "../src/app.rs"]
mod app;

libfuzzer_sys::fuzz_target!(|data: &[u8]| app::scene_toml(data));
