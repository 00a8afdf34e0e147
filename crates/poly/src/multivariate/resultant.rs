//! The Sylvester resultant of two polynomials in one symbol whose
//! coefficients are polynomials in the others: the projection that
//! eliminates a symbol (region boundaries, the w-plane's boundary locus,
//! moduli of roots).

use crate::multivariate::matrix::PolyMatrix;
use crate::multivariate::poly::Poly;

/// The Sylvester resultant of two polynomials given by their coefficients
/// (lowest power first), each coefficient a polynomial in the remaining
/// symbols; zero when either is zero.
pub fn resultant(f: &[Poly], g: &[Poly]) -> Poly {
    let trim = |c: &[Poly]| -> Vec<Poly> {
        let mut v = c.to_vec();
        while v.last().is_some_and(Poly::is_zero) {
            v.pop();
        }
        v
    };
    let (f, g) = (trim(f), trim(g));
    if f.is_empty() || g.is_empty() {
        return Poly::zero();
    }
    let (m, n) = (f.len() - 1, g.len() - 1);
    if m + n == 0 {
        return Poly::one();
    }
    let size = m + n;
    let mut rows = vec![vec![Poly::zero(); size]; size];
    for i in 0..n {
        for (k, c) in f.iter().rev().enumerate() {
            rows[i][i + k] = c.clone();
        }
    }
    for i in 0..m {
        for (k, c) in g.iter().rev().enumerate() {
            rows[n + i][i + k] = c.clone();
        }
    }
    PolyMatrix::from_rows(rows).det()
}

/// Where a root of χ(z) = Σ a_k z^k (coefficients lowest first, each a
/// polynomial in the other symbols; the top one nonzero) can reach or
/// cross the unit circle as the symbols move: the conditions the exact
/// regions and the design search draw their curves from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CircleConditions {
    /// a_n: a root from infinity.
    pub leading: Poly,
    /// a_0: a root through 0.
    pub constant: Poly,
    /// χ(1): a root through +1.
    pub at_one: Poly,
    /// χ(−1): a root through −1.
    pub at_minus_one: Poly,
    /// Two roots with z_i z_j = 1 (a pair on the circle): a₂ − a₀ for
    /// degree 2, else Res_z(χ, zⁿχ(1/z)).
    pub unit_circle: Poly,
}

/// The [`CircleConditions`] of χ's coefficients `a` (lowest first).
///
/// ```
/// use poly::advanced::circle_conditions;
/// let a: Vec<poly::Poly> = ["1", "-2 + Phi^2", "1"].iter().map(|s| poly::Poly::parse(s).unwrap()).collect();
/// let c = circle_conditions(&a);
/// assert_eq!(c.at_one.to_string(), "Phi^2");
/// assert_eq!(c.at_minus_one.to_string(), "4 - Phi^2");
/// assert!(c.unit_circle.is_zero()); // self-reciprocal: always a pair z, 1/z
/// ```
pub fn circle_conditions(a: &[Poly]) -> CircleConditions {
    let n = a.len() - 1;
    let (mut at_one, mut at_minus_one) = (Poly::zero(), Poly::zero());
    for (k, c) in a.iter().enumerate() {
        at_one += c;
        if k % 2 == 0 {
            at_minus_one += c;
        } else {
            at_minus_one -= c;
        }
    }
    let unit_circle = if n == 2 {
        &a[2] - &a[0]
    } else {
        // zⁿχ(1/z) has the coefficients of χ reversed.
        let rev: Vec<Poly> = a.iter().rev().cloned().collect();
        resultant(a, &rev)
    };
    CircleConditions {
        leading: a[n].clone(),
        constant: a[0].clone(),
        at_one,
        at_minus_one,
        unit_circle,
    }
}
