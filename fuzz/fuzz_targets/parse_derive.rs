//! Fuzz target `parse_derive`: see `testkit::fuzz::parse_derive` and FUZZING.md.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| zcheck_fuzz::parse_derive(data));
