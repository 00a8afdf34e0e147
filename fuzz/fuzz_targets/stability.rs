//! Fuzz target `stability`: see `testkit::fuzz::stability` and FUZZING.md.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| zcheck_fuzz::stability(data));
