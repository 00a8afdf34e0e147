//! Section 5, Standard Euler: update, z-domain rows, characteristic
//! equation, eigenvalues, r² and "always an unstable oscillation".

use super::common::*;
use crate::paper::claim::Claim;

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("5", "sec05");
    ode_claim(
        &mut s,
        "standard_euler",
        "v̇ = −ω0 y, ẏ = ω0 v;  dv = −ω0 T y = −Φy, dy = ω0 T v = Φv",
        OSCILLATOR,
        Scheme::Euler,
    );
    stages_claim(
        &mut s,
        "update",
        "standard_euler",
        "v = v + dv = v − Φy;  y = y + dy = y + Φv",
        &[
            ("v", Printed { printed: "v = v − Φy", parse: "v - Phi*y" }),
            ("y", Printed { printed: "y = y + Φv", parse: "y + Phi*v" }),
        ],
    );
    z_rows_claim(
        &mut s,
        "standard_euler",
        "v = v z⁻¹ − Φ y z⁻¹;  y = Φ v z⁻¹ + y z⁻¹",
        &[
            ZRow { printed: "v = v z⁻¹ − Φ y z⁻¹", v: "1", y: "-Phi" },
            ZRow { printed: "y = Φ v z⁻¹ + y z⁻¹", v: "Phi", y: "1" },
        ],
    );
    charpoly_claim(
        &mut s,
        "charpoly",
        "standard_euler",
        "z² − 2z + (1 + Φ²) = 0",
        "z^2 - 2*z + (1 + Phi^2)",
    );
    eigen_claim(&mut s, "eigenvalues", "standard_euler", "z1/2 = 1 ± jΦ", "1", "Phi^2");
    r_squared_claim(&mut s, "standard_euler", "r1² = 1 + Φ²", "1 + Phi^2");
    always_unstable_claim(&mut s, "standard_euler");
    s.finish()
}
