//! The float estimates: the f64 spectral radius of χ at (Φ, D), from the
//! per-mode polynomials in (Φ, D) with f64 coefficients, and from it a
//! guess of a mode's fewest stable substeps, which picks the limiting
//! modes for the exact checks (`exact.rs`).

use super::analysed::{Analysed, MAX_SUBSTEPS};

impl Analysed {
    /// Spectral radius of χ at (Φ, D) in f64.
    pub(super) fn rho(&self, phi: f64, d: f64) -> f64 {
        let c: Vec<f64> = self.coeffs.iter().map(|p| p.eval(phi, d)).collect();
        if c.len() == 3 {
            let (a, b, cc) = (c[2], c[1], c[0]);
            let disc = b * b - 4.0 * a * cc;
            if disc < 0.0 {
                return (cc / a).abs().sqrt();
            }
            let s = disc.sqrt();
            let r1 = (-b - b.signum() * s) / (2.0 * a);
            let r2 = if r1 != 0.0 { cc / (a * r1) } else { 0.0 };
            return r1.abs().max(r2.abs());
        }
        match check::witness::polynomial_roots(&c) {
            Ok(r) => r.iter().map(|z| z.norm()).fold(0.0, f64::max),
            Err(_) => f64::INFINITY,
        }
    }

    /// A float estimate of the smallest stable n for a mode with per-tick
    /// step `phi1` (None: runs away).
    pub(super) fn estimate_stable(&self, phi1: f64, d: f64) -> Option<u64> {
        let ok = |phi: f64| self.rho(phi, d) <= 1.0 + 1e-12;
        if ok(phi1) {
            return Some(1);
        }
        let mut lo = phi1 / MAX_SUBSTEPS as f64;
        if !ok(lo) {
            return None;
        }
        let mut hi = phi1;
        for _ in 0..60 {
            let mid = (lo * hi).sqrt();
            if ok(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(((phi1 / lo).ceil() as u64).max(1))
    }
}
