//! The tolerance model (see the module docs of [`crate::witness`]).

use nalgebra::DMatrix;
use num_traits::Zero;

use super::eigen::{eigen_condition, C64};

/// Multiplier of N·ε for an isolated root.
pub const C_ISOLATED: f64 = 16.0;
/// Multiplier of N·ε^(1/m) for a cluster of m roots.
pub const C_CLUSTER: f64 = 8.0;

pub(super) fn scale_of(p: &DMatrix<f64>) -> f64 {
    p.norm().max(1.0)
}

fn poly_condition(coeffs: &[f64], z: C64) -> f64 {
    let n = coeffs.len() - 1;
    let mut abs_sum = 0.0;
    let mut deriv = C64::zero();
    for (k, &c) in coeffs.iter().enumerate() {
        let power = (n - k) as i32;
        abs_sum += c.abs() * z.norm().powi(power);
        if power > 0 {
            deriv += C64::new(c * power as f64, 0.0) * z.powi(power - 1);
        }
    }
    let d = deriv.norm();
    if d == 0.0 {
        f64::INFINITY
    } else {
        abs_sum / d
    }
}

/// Cluster sizes: how many roots lie within the cluster radius of each.
fn cluster_sizes(roots: &[C64], scale: f64) -> Vec<usize> {
    let n = roots.len().max(1) as f64;
    let radius = 2.0 * C_CLUSTER * n * f64::EPSILON.sqrt() * scale;
    roots.iter().map(|a| roots.iter().filter(|b| (*a - **b).norm() <= radius).count()).collect()
}

fn combine(isolated: f64, m: usize, n: usize, scale: f64) -> f64 {
    if m >= 2 {
        let cluster = C_CLUSTER * n as f64 * f64::EPSILON.powf(1.0 / m as f64) * scale;
        isolated.min(cluster)
    } else {
        isolated
    }
}

/// Agreement radii from the polynomial alone (no P): used to classify roots
/// of orders beyond 2.
pub fn poly_tolerances(coeffs: &[f64], roots: &[C64]) -> Vec<f64> {
    let n = roots.len();
    let scale = coeffs.iter().fold(1.0f64, |a, c| a.max(c.abs()));
    let sizes = cluster_sizes(roots, scale);
    roots
        .iter()
        .zip(&sizes)
        .map(|(&z, &m)| {
            let iso = C_ISOLATED * n as f64 * f64::EPSILON * poly_condition(coeffs, z).max(scale);
            combine(iso, m, n, scale)
        })
        .collect()
}

/// Agreement radii of the reference roots for P (see the module docs), with
/// each root's condition number κ and cluster size.
pub fn tolerances(
    p: &DMatrix<f64>,
    coeffs: &[f64],
    roots: &[C64],
) -> (Vec<f64>, Vec<f64>, Vec<usize>) {
    let n = roots.len();
    let scale = scale_of(p);
    let sizes = cluster_sizes(roots, scale);
    let mut tol = Vec::with_capacity(n);
    let mut kappa = Vec::with_capacity(n);
    for (&z, &m) in roots.iter().zip(&sizes) {
        let (k, _) = eigen_condition(p, z);
        // The degree-2 closed form is exact up to rounding; companion roots
        // carry the coefficients' sensitivity.
        let kappa_poly = if n == 2 { 0.0 } else { poly_condition(coeffs, z) };
        let iso = C_ISOLATED * n as f64 * f64::EPSILON * (scale * k).max(kappa_poly);
        tol.push(combine(iso, m, n, scale));
        kappa.push(k);
    }
    (tol, kappa, sizes)
}
