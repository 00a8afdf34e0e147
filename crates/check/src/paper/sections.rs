//! Claims of sections 4–12 and Appendices A–B (placeholder: filled by the proof issue).

use super::Claim;

/// The claims of sections 4–12 and Appendices A and B.
pub fn claims() -> Vec<Claim> {
    Vec::new()
}
