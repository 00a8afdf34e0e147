//! Fuzz target `order_toml`: see `testkit::fuzz` and FUZZING.md.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| zcheck_fuzz::order_toml(data));
