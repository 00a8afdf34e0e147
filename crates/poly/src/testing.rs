//! Helpers shared by the unit tests.

/// Marsaglia's xorshift64: a reproducible stream for the randomised tests.
pub(crate) fn xorshift(mut seed: u64) -> impl FnMut() -> u64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    }
}
