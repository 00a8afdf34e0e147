//! Fuzz target `parse`: see `testkit::fuzz::parse` and FUZZING.md.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| zcheck_fuzz::parse(data));
