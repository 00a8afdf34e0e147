//! The exact region checks: membership of (Φ, D) in the method's stable
//! region (the f64 spectral radius decides only where it clears 1 by
//! [`FLOAT_MARGIN`], else poly's `Region` and the exact stable intervals of
//! χ(·, D)), the exact Φ_max at ζ, and a mode's exact fewest stable
//! substeps from a guess (the certified substeps of an undamped scene
//! included).

use check::numeric::{f64_to_decimal_q, f64_to_q};
use poly::advanced::region::PhiLimit;

use super::analysed::{Analysed, MAX_SUBSTEPS};

/// How far the f64 spectral radius must clear 1 for the float to decide
/// membership of the stable region (see [`Analysed::inside`]).
const FLOAT_MARGIN: f64 = 1e-6;

impl Analysed {
    /// Is (Φ, D) inside the stable region? Decided by the f64 spectral
    /// radius only where it clears 1 by [`FLOAT_MARGIN`] (10⁹ times the
    /// rounding error of a simple root, 10² times that of a double one);
    /// otherwise exactly, against the stable intervals of χ(·, D), computed
    /// once per D (a scene's undamped modes share one analysis), or by the
    /// exact class at Φ when that analysis fails.
    pub(super) fn inside(&self, phi: f64, d: f64) -> bool {
        let rho = self.rho(phi, d);
        if rho < 1.0 - FLOAT_MARGIN {
            return true;
        }
        if rho > 1.0 + FLOAT_MARGIN && rho.is_finite() {
            return false;
        }
        self.inside_exact(phi, d)
    }

    /// Exact membership of (Φ, D), with no float deciding. D is read as
    /// the decimal it prints as (a typed `--damping 0.1` or `ratio = 0.1`
    /// is 1/10, as everywhere else); Φ, a computed ωT/n, as its exact
    /// binary value.
    fn inside_exact(&self, phi: f64, d: f64) -> bool {
        let (Some(p), Some(dq)) = (f64_to_q(phi), f64_to_decimal_q(d)) else { return false };
        let mut cache = self.at_param.borrow_mut();
        let (_, intervals) = cache.entry(d.to_bits()).or_insert_with(|| {
            let chi = self.region.at_param(&dq);
            let intervals = self.region.stability_at(&dq).ok().map(|r| r.stable_intervals);
            (chi, intervals)
        });
        match intervals {
            Some(intervals) => intervals.iter().any(|iv| {
                let above_lo = match iv.lo.cmp_rational(&p) {
                    std::cmp::Ordering::Less => true,
                    std::cmp::Ordering::Equal => iv.lo_closed,
                    std::cmp::Ordering::Greater => false,
                };
                let below_hi = match &iv.hi {
                    None => true,
                    Some(hi) => match hi.cmp_rational(&p) {
                        std::cmp::Ordering::Greater => true,
                        std::cmp::Ordering::Equal => iv.hi_closed,
                        std::cmp::Ordering::Less => false,
                    },
                };
                above_lo && below_hi
            }),
            None => self.region.contains(&p, &dq).unwrap_or(false),
        }
    }

    /// The exact Φ_max at ζ (cached by the bits of ζ).
    pub(super) fn limit(&mut self, d: f64) -> Option<PhiLimit> {
        if let Some(l) = self.exact_limits.get(&d.to_bits()) {
            return Some(l.clone());
        }
        let l = self.region.phi_max(&f64_to_decimal_q(d)?).ok()?;
        self.exact_limits.insert(d.to_bits(), l.clone());
        Some(l)
    }

    /// The exact smallest n (given the interval assumption) starting from a
    /// guess: up while outside, down while n − 1 is inside.
    pub(super) fn exact_stable(&self, phi1: f64, d: f64, guess: u64) -> Option<u64> {
        let mut n = guess.max(1);
        let mut tries = 0;
        while !self.inside(phi1 / n as f64, d) {
            n = if tries < 16 { n + 1 } else { n * 2 };
            tries += 1;
            if n > MAX_SUBSTEPS {
                return None;
            }
        }
        while n > 1 && self.inside(phi1 / (n - 1) as f64, d) {
            n -= 1;
        }
        Some(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::load::LoadedMethod;

    /// The float filter of `inside` never contradicts the exact decision:
    /// every damped built-in on a grid of (Φ, D) across its boundary,
    /// including points within 10⁻⁹ of the exact limit.
    #[test]
    fn the_float_filter_agrees_with_the_exact_membership() {
        for spec in LoadedMethod::damped_builtins().unwrap() {
            let a = Analysed::new(spec).unwrap();
            for d in [0.0, 0.05, 0.3, 0.9] {
                let mut phis: Vec<f64> = (1..=40).map(|k| k as f64 * 0.1).collect();
                if let Ok(PhiLimit::Below(m)) = a.region.phi_max(&f64_to_decimal_q(d).unwrap()) {
                    let m: f64 = m.to_decimal(17).parse().unwrap();
                    phis.extend([m * (1.0 - 1e-9), m * (1.0 + 1e-9), m * 0.999, m * 1.001]);
                }
                for phi in phis {
                    assert_eq!(
                        a.inside(phi, d),
                        a.inside_exact(phi, d),
                        "{} at Phi = {phi}, D = {d}",
                        a.spec.display()
                    );
                }
            }
        }
    }
}
