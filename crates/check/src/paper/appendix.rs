//! Claims of Appendices C–E, the scenes (placeholder: filled by the scenes issue).

use super::Claim;

/// The claims of Appendices C, D and E.
pub fn claims() -> Vec<Claim> {
    Vec::new()
}
