//! The exact route: the substep map over Q, its characteristic polynomial,
//! and stability decided with `poly`'s root classes; and the exact null
//! space of the constraint Jacobian J, the rigid modes.
//!
//! The scene's typed numbers (masses, stiffness, damping, tick rate) enter
//! as the decimals they print as (a typed 0.01 kg is 1/100), the computed
//! unit directions as their exact binary values: the map decided is the
//! map of the scene as read. χ of the substep map P comes from an exact
//! Hessenberg reduction over Q. Every x, v in null(J) is a rigid motion:
//! (x, 0) is fixed and (0, v) drifts, a Jordan block at 1, so
//! χ_P = (z − 1)^{2r}·χ_D with r = dim null(J) and D the map on the
//! non-rigid modes; the division is exact or an error. χ_D is classified by
//! [`poly::advanced::stability::classify`]: its dominant modulus against 1,
//! and where a root on the unit circle is repeated, whether P is semisimple
//! there, by exact ranks: rank q(P) = rank q(P)² for the square-free q of
//! the roots on the circle (undecided when 1 is among them, which the rigid
//! block shares). Since ρ(P^S) = ρ(P)^S and P^S has a growing block
//! exactly when P has, the tick map's verdict is the substep map's.

use std::cmp::Ordering;

use check::numeric::{f64_to_decimal_q, f64_to_q};
use num_traits::{One, Zero};
use poly::{RootClass, UPoly, Q};

use super::kernel::{Convert, Substep};
use super::model::{Config, Model};

/// The substep over Q.
pub(crate) fn substep_q(model: &Model, config: &Config, tick_hz: f64) -> Substep<Q> {
    let physical = |x: f64| f64_to_decimal_q(x).unwrap_or_else(Q::zero);
    let geometric = |x: f64| f64_to_q(x).unwrap_or_else(Q::zero);
    Substep::new(model, config, tick_hz, &Convert { physical: &physical, geometric: &geometric })
}

/// A basis of null(J) over Q, J the constraint Jacobian (a row ∇C_j per
/// constraint over the free degrees of freedom), by sparse elimination:
/// each row scaled by its first entry (a diagonal spring's (c, c) becomes
/// (1, 1) exactly), reduced by the pivot rows found so far; then one
/// vector per free column by back substitution.
pub(crate) fn null_basis(model: &Model) -> Vec<Vec<Q>> {
    let n = model.n();
    let mut pivots: Vec<Option<Vec<(usize, Q)>>> = vec![None; n];
    for c in &model.constraints {
        let mut row: Vec<(usize, Q)> = c
            .grad
            .iter()
            .filter_map(|&(i, g)| Some((i, f64_to_q(g)?)))
            .filter(|(_, g)| !g.is_zero())
            .collect();
        row.sort_by_key(|e| e.0);
        while let Some((lead, a)) = row.first().cloned() {
            let Some(p) = &pivots[lead] else {
                let inv = a.recip();
                row.iter_mut().for_each(|(_, x)| *x = &*x * &inv);
                pivots[lead] = Some(row);
                break;
            };
            // row −= a · p (p's lead is 1).
            row = axpy(&row, &-a, p);
        }
    }
    let free: Vec<usize> = (0..n).filter(|&i| pivots[i].is_none()).collect();
    let mut basis = Vec::with_capacity(free.len());
    for &f in &free {
        let mut x = vec![Q::zero(); n];
        x[f] = Q::one();
        for col in (0..n).rev() {
            if let Some(p) = &pivots[col] {
                let mut s = Q::zero();
                for (j, a) in &p[1..] {
                    if !x[*j].is_zero() {
                        s += a * &x[*j];
                    }
                }
                x[col] = -s;
            }
        }
        basis.push(x);
    }
    basis
}

/// `u + s·v` of sorted sparse rows.
fn axpy(u: &[(usize, Q)], s: &Q, v: &[(usize, Q)]) -> Vec<(usize, Q)> {
    let mut out = Vec::with_capacity(u.len() + v.len());
    let (mut i, mut j) = (0, 0);
    while i < u.len() || j < v.len() {
        let take_u = j >= v.len() || (i < u.len() && u[i].0 < v[j].0);
        let take_v = i >= u.len() || (j < v.len() && v[j].0 < u[i].0);
        if take_u {
            out.push(u[i].clone());
            i += 1;
        } else if take_v {
            out.push((v[j].0, s * &v[j].1));
            j += 1;
        } else {
            let x = &u[i].1 + &(s * &v[j].1);
            if !x.is_zero() {
                out.push((u[i].0, x));
            }
            i += 1;
            j += 1;
        }
    }
    out
}

/// χ(z) = det(zI − A) over Q, lowest coefficient first, by a similarity
/// reduction to upper Hessenberg form and its three-term recurrence.
pub(crate) fn charpoly(a: &[Vec<Q>]) -> Vec<Q> {
    let n = a.len();
    let mut h: Vec<Vec<Q>> = a.to_vec();
    for j in 0..n.saturating_sub(2) {
        let Some(piv) = (j + 1..n).find(|&i| !h[i][j].is_zero()) else { continue };
        if piv != j + 1 {
            h.swap(piv, j + 1);
            for row in h.iter_mut() {
                row.swap(piv, j + 1);
            }
        }
        let inv = h[j + 1][j].recip();
        for r in j + 2..n {
            if h[r][j].is_zero() {
                continue;
            }
            let f = &h[r][j] * &inv;
            // row r −= f · row j+1; column j+1 += f · column r.
            let pivot_row = h[j + 1].clone();
            for (target, x) in h[r].iter_mut().zip(&pivot_row) {
                if !x.is_zero() {
                    *target -= &f * x;
                }
            }
            for row in h.iter_mut() {
                if !row[r].is_zero() {
                    let t = &f * &row[r];
                    row[j + 1] += t;
                }
            }
        }
    }
    // p_0 = 1; p_m = (z − h_{m−1,m−1}) p_{m−1}
    //   − Σ_{i=1}^{m−1} h_{m−1−i,m−1} (Π_{t=m−i}^{m−1} h_{t,t−1}) p_{m−1−i}.
    let mut p: Vec<Vec<Q>> = vec![vec![Q::one()]];
    for m in 1..=n {
        let prev = &p[m - 1];
        let mut next = vec![Q::zero(); m + 1];
        for (k, c) in prev.iter().enumerate() {
            next[k + 1] += c;
            next[k] -= &h[m - 1][m - 1] * c;
        }
        let mut prod = Q::one();
        for i in 1..m {
            prod *= &h[m - i][m - i - 1];
            if prod.is_zero() {
                break;
            }
            let coef = &h[m - 1 - i][m - 1] * &prod;
            if coef.is_zero() {
                continue;
            }
            for (k, c) in p[m - 1 - i].iter().enumerate() {
                next[k] -= &coef * c;
            }
        }
        p.push(next);
    }
    p.pop().unwrap_or_default()
}

/// `f / (z − 1)^k`, or `None` when (z − 1)^k does not divide f.
pub(crate) fn divide_by_z_minus_one(f: &[Q], k: usize) -> Option<Vec<Q>> {
    let mut f = f.to_vec();
    for _ in 0..k {
        // Synthetic division by (z − 1), highest coefficient first.
        let d = f.len().checked_sub(1)?;
        let mut q = vec![Q::zero(); d];
        let mut carry = Q::zero();
        for i in (1..=d).rev() {
            carry = &f[i] + &carry;
            q[i - 1] = carry.clone();
        }
        if !(&f[0] + &carry).is_zero() {
            return None;
        }
        f = q;
    }
    Some(f)
}

/// The exact verdict on a substep map.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Verdict {
    /// The dominant modulus of the non-rigid part against 1.
    pub rho: Ordering,
    /// Whether the non-rigid part stays bounded (`None`: undecided).
    pub bounded: Option<bool>,
    /// The root class of χ_D.
    pub class: RootClass,
    /// Degree of χ_D.
    pub degree: usize,
}

/// The exact verdict on the substep map `p` (over Q) with `rigid` = 2r
/// eigenvalues of its rigid block, or `None` when (z − 1)^{2r} does not
/// divide χ_P (a contradiction with the deflation: never silent).
pub(crate) fn verdict(p: &[Vec<Q>], rigid: usize) -> Option<Verdict> {
    let chi = charpoly(p);
    let chi_d = divide_by_z_minus_one(&chi, rigid)?;
    let degree = chi_d.len().saturating_sub(1);
    let f = UPoly::new(chi_d);
    let class = poly::advanced::stability::classify(&f);
    let rho = match class {
        RootClass::Deadbeat
        | RootClass::DampedOscillation
        | RootClass::MonotonicStable
        | RootClass::AlternatingStable => Ordering::Less,
        RootClass::Harmonic
        | RootClass::Constant
        | RootClass::Alternating
        | RootClass::DoubleRootOnCircle => Ordering::Equal,
        RootClass::UnstableOscillation
        | RootClass::MonotonicUnstable
        | RootClass::AlternatingUnstable
        | RootClass::Singular => Ordering::Greater,
    };
    let bounded = match class.bounded() {
        Some(b) => Some(b),
        None => semisimple_on_circle(p, &f),
    };
    Some(Verdict { rho, bounded, class, degree })
}

/// Whether P is semisimple at the roots of f on the unit circle (f has
/// none outside): rank q(P) = rank q(P)² for q the square-free part of
/// gcd(f, z^n f(1/z)); `None` when 1 is among them.
fn semisimple_on_circle(p: &[Vec<Q>], f: &UPoly) -> Option<bool> {
    let q = f.gcd(&f.reversed()).squarefree();
    if q.eval(&Q::one()).is_zero() {
        return None;
    }
    let qp = poly_at(&q, p);
    let qp2 = mat_mul(&qp, &qp);
    Some(rank(qp) == rank(qp2))
}

/// q(A) by Horner.
fn poly_at(q: &UPoly, a: &[Vec<Q>]) -> Vec<Vec<Q>> {
    let n = a.len();
    let mut acc = vec![vec![Q::zero(); n]; n];
    for c in q.coeffs().iter().rev() {
        acc = mat_mul(&acc, a);
        for (i, row) in acc.iter_mut().enumerate() {
            row[i] += c;
        }
    }
    acc
}

fn mat_mul(a: &[Vec<Q>], b: &[Vec<Q>]) -> Vec<Vec<Q>> {
    let n = a.len();
    let m = b.first().map_or(0, Vec::len);
    let mut out = vec![vec![Q::zero(); m]; n];
    for i in 0..n {
        for (k, bk) in b.iter().enumerate() {
            if a[i][k].is_zero() {
                continue;
            }
            for j in 0..m {
                if !bk[j].is_zero() {
                    out[i][j] += &a[i][k] * &bk[j];
                }
            }
        }
    }
    out
}

/// The rank over Q, by Gaussian elimination.
pub(crate) fn rank(mut a: Vec<Vec<Q>>) -> usize {
    let rows = a.len();
    let cols = a.first().map_or(0, Vec::len);
    let mut r = 0;
    for c in 0..cols {
        let Some(piv) = (r..rows).find(|&i| !a[i][c].is_zero()) else { continue };
        a.swap(r, piv);
        let inv = a[r][c].recip();
        for i in r + 1..rows {
            if a[i][c].is_zero() {
                continue;
            }
            let f = &a[i][c] * &inv;
            let pivot_row = a[r].clone();
            for (target, x) in a[i][c..cols].iter_mut().zip(&pivot_row[c..cols]) {
                if !x.is_zero() {
                    *target -= &f * x;
                }
            }
        }
        r += 1;
        if r == rows {
            break;
        }
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use poly::q;

    /// χ of a companion matrix is its polynomial; of a rotation-like block
    /// z² − tz + d.
    #[test]
    fn charpoly_is_exact() {
        // Companion of z³ − 2z² + 3z − 5 (lowest first: −5, 3, −2, 1).
        let a = vec![
            vec![q(0, 1), q(0, 1), q(5, 1)],
            vec![q(1, 1), q(0, 1), q(-3, 1)],
            vec![q(0, 1), q(1, 1), q(2, 1)],
        ];
        assert_eq!(charpoly(&a), vec![q(-5, 1), q(3, 1), q(-2, 1), q(1, 1)]);
        // A dense 3×3 against the Laplace expansion by hand:
        // [[1,2,3],[4,5,6],[7,8,10]]: z³ − 16z² − 12z + 3... det = -3.
        let b = vec![
            vec![q(1, 1), q(2, 1), q(3, 1)],
            vec![q(4, 1), q(5, 1), q(6, 1)],
            vec![q(7, 1), q(8, 1), q(10, 1)],
        ];
        let c = charpoly(&b);
        assert_eq!(c[3], q(1, 1));
        assert_eq!(c[2], q(-16, 1));
        // Sum of principal 2×2 minors: (5−8) + (10−21) + (50−48) = −12.
        assert_eq!(c[1], q(-12, 1));
        assert_eq!(c[0], q(3, 1)); // −det, det = −3.
        assert_eq!(divide_by_z_minus_one(&[q(1, 1), q(-2, 1), q(1, 1)], 2), Some(vec![q(1, 1)]));
        assert_eq!(divide_by_z_minus_one(&[q(1, 1), q(-2, 1), q(2, 1)], 1), None);
    }

    /// A Jordan block at −1 grows; −I does not (both have χ = (z + 1)²).
    #[test]
    fn repeated_roots_on_the_circle_are_decided_from_the_matrix() {
        let jordan = vec![vec![q(-1, 1), q(1, 1)], vec![q(0, 1), q(-1, 1)]];
        let minus_i = vec![vec![q(-1, 1), q(0, 1)], vec![q(0, 1), q(-1, 1)]];
        let v = verdict(&jordan, 0).unwrap();
        assert_eq!((v.rho, v.bounded), (Ordering::Equal, Some(false)));
        let v = verdict(&minus_i, 0).unwrap();
        assert_eq!((v.rho, v.bounded), (Ordering::Equal, Some(true)));
        assert_eq!(rank(minus_i), 2);
    }
}
