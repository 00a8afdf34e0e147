//! Slow, obvious answers that the fast paths are held to in the tests.

use num_traits::ToPrimitive;
use poly::{Algebraic, Q};

/// The f64 nearest a real algebraic number, the obvious way: halve its
/// isolating interval until both ends convert (num-rational's conversion
/// rounds correctly) to the same f64. It ends for an irrational number,
/// which is never the midpoint of two floats, and at once for a rational.
pub fn nearest_f64(a: &Algebraic) -> f64 {
    if let Some(q) = a.as_rational() {
        return q.to_f64().expect("a finite rational");
    }
    let mut b = a.clone();
    loop {
        let (lo, hi) = b.interval();
        let (l, h) = (lo.to_f64().expect("finite"), hi.to_f64().expect("finite"));
        if l == h {
            return l;
        }
        b = b.refine(&((&hi - &lo) / Q::from_integer(2.into())));
    }
}
