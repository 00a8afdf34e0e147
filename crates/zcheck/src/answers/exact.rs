//! Exact numbers as JSON, one shape for the documents that share it
//! (`zcheck region`, `zcheck order`): `{"exact", "value"}`, the exact text
//! and the nearest f64 (`null` where there is none, as for +∞), and for a
//! real algebraic number its defining polynomial and an isolating interval.

use num_traits::ToPrimitive;
use poly::{Algebraic, Poly, Q};
use serde_json::{json, Value};

/// Width to which exact numbers are narrowed before they become floats:
/// 1e-20, made once.
pub(crate) fn fine() -> Q {
    static FINE: std::sync::LazyLock<Q> =
        std::sync::LazyLock::new(|| Q::new(1.into(), num_traits::pow(10.into(), 20)));
    FINE.clone()
}

/// The f64 nearest an algebraic number, from its 17-digit expansion.
pub(crate) fn to_f64(a: &Algebraic) -> f64 {
    a.to_decimal(17).parse().expect("a decimal expansion parses as f64")
}

/// A real algebraic number as JSON: its exact form (the closed form, else
/// the defining polynomial in `var` and an interval), its value, its
/// defining polynomial and an isolating interval narrower than 1e-20.
pub(crate) fn number(a: &Algebraic, var: &str) -> Value {
    // Refined once: the interval and the description read the same number.
    let fine_a = a.refine(&fine());
    let (lo, hi) = fine_a.interval();
    json!({
        "exact": fine_a.describe(var),
        "value": to_f64(a),
        "defining_poly": a.defining_poly().to_string_in(var),
        "interval": [lo.to_string(), hi.to_string()],
    })
}

/// A constant of the method's field (rational, or with radicals) as JSON.
pub(crate) fn constant(c: &Poly) -> Value {
    if let Some(q) = c.as_constant() {
        return json!({ "exact": c.to_string(), "value": q.to_f64() });
    }
    let v = poly::advanced::field::approx(c, &fine());
    json!({ "exact": c.to_string(), "value": v.to_f64() })
}

/// +∞ as JSON: exact text `inf`, no f64 value.
pub(crate) fn infinity() -> Value {
    json!({ "exact": "inf", "value": null })
}
