//! Claims of sections 4–12 and Appendices A–B, computed: each section module
//! transcribes what the paper prints and compares it with what `poly`
//! derives (exact polynomials, exact stability limits, exact series) and,
//! where only numbers can say it, with rounded floating-point values.

mod advice;
mod app_a;
mod app_b;
mod common;
mod exact;
mod frequency;
pub(crate) mod pascal;
pub(crate) mod ranges;
mod sec04;
mod sec05;
mod sec06;
mod sec07;
mod sec08;
mod sec09;
mod sec10;
mod sec11;
mod sec12;

use crate::paper::claim::Claim;

/// The claims of sections 4–12 and Appendices A and B, in the paper's order.
pub fn claims() -> Vec<Claim> {
    let mut v = Vec::new();
    for section in [
        sec04::claims,
        sec05::claims,
        sec06::claims,
        sec07::claims,
        sec08::claims,
        sec09::claims,
        sec10::claims,
        sec11::claims,
        sec12::claims,
        app_a::claims,
        app_b::claims,
    ] {
        v.extend(section());
    }
    v
}
