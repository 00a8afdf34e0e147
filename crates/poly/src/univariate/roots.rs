//! Real roots, the fast way first: Descartes' rule of signs and a replay of
//! Sturm's bisection (`isolate`), with the Sturm chain (`sturm`) as the
//! fallback and the definition of the intervals.

use num_traits::Zero;

use crate::univariate::isolate::{budget, descartes_isolate, isolate};
use crate::univariate::sturm::{isolate_squarefree_sturm, CmpZero};
use crate::univariate::upoly::int_primitive;
use crate::{UPoly, Q};

/// Whether `p` (p(0) ≠ 0) provably has no root in (0, ∞): Descartes' rule
/// of signs on (0, B) (B a power of two above every root's modulus) and on
/// the halves of any part where the rule counts two or more sign changes,
/// up to `budget` parts ([`crate::univariate::isolate`]'s bisection, stopped at the
/// first root). `false` means "not proven": a part with exactly one sign
/// change holds a root, and a root at a halving point is seen exactly.
pub(crate) fn no_positive_roots(p: &UPoly, budget: usize) -> bool {
    debug_assert!(!p.coeff(0).is_zero());
    if p.degree().unwrap_or(0) == 0 {
        return false;
    }
    // Descartes' rule on (0, ∞) itself: no sign change, no positive root;
    // exactly one, exactly one root. Read off the rational coefficients,
    // before any integer form is made.
    let mut changes = 0;
    let mut last = std::cmp::Ordering::Equal;
    for c in p.coeffs() {
        let s = c.numer().sign().cmp_zero();
        if s != std::cmp::Ordering::Equal {
            if last != std::cmp::Ordering::Equal && s != last {
                changes += 1;
            }
            last = s;
        }
    }
    match changes {
        0 => return true,
        1 => return false,
        _ => {}
    }
    // Descartes' bisection starts from Fujiwara's bound (no Cauchy bound).
    descartes_isolate(&int_primitive(p), u64::MAX, true, budget)
        .is_some_and(|roots| roots.is_empty())
}

/// Disjoint isolating intervals of the distinct real roots of `p`, sorted
/// increasingly. Each entry is either `(r, r)` for a rational root `r` met
/// by bisection, or `(lo, hi)` with `lo < hi`, exactly one root strictly
/// inside, and `p(lo)`, `p(hi)` non-zero of opposite signs.
pub fn isolate_real_roots(p: &UPoly) -> Vec<(Q, Q)> {
    if p.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    isolate_squarefree(&p.squarefree())
}

/// [`isolate_real_roots`] for a polynomial already square-free (its own
/// square-free part up to a constant factor): the same intervals, without
/// recomputing the square-free part. Computed by Descartes' rule and a
/// replay of the bisection ([`crate::univariate::isolate`]); by the Sturm chain only
/// when the rational roots elude p-adic lifting.
pub(crate) fn isolate_squarefree(sf: &UPoly) -> Vec<(Q, Q)> {
    if sf.degree().unwrap_or(0) == 0 {
        return Vec::new();
    }
    let budget = budget(sf.degree().unwrap_or(0));
    isolate(sf, false, budget).unwrap_or_else(|| isolate_squarefree_sturm(sf))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::univariate::isolate::shift_by_one;
    use crate::univariate::sturm::{count_real_roots, root_bound};
    use num_bigint::BigInt;
    use proptest::prelude::*;

    proptest! {
        /// The shift agrees with composing with x + 1, and Descartes' proof
        /// of "no positive root" agrees with the Sturm count.
        #[test]
        fn descartes_agrees_with_sturm(c in proptest::collection::vec(-30i64..30, 2..9)) {
            prop_assume!(c[0] != 0 && *c.last().unwrap() != 0);
            let p = UPoly::from_ints(&c);
            let mut shifted: Vec<BigInt> = c.iter().map(|&x| BigInt::from(x)).collect();
            shift_by_one(&mut shifted).expect("BigInt never overflows");
            let composed = p.compose(&UPoly::from_ints(&[1, 1]));
            prop_assert_eq!(UPoly::new(shifted.into_iter().map(Q::from_integer).collect()), composed);
            let sf = p.squarefree();
            let positive = count_real_roots(&sf, &Q::zero(), &root_bound(&sf));
            if no_positive_roots(&sf, 32) {
                prop_assert_eq!(positive, 0);
            }
        }
    }

    /// Every root negative or complex, with four sign changes: proven
    /// root-free after halvings; and a root exactly at a halving point is
    /// not mistaken for none.
    #[test]
    fn descartes_proves_and_refuses() {
        // (x² − x + 1)(x² − 2x + 5)(x + 3): no positive root, 4 sign changes.
        let p = &(&UPoly::from_ints(&[1, -1, 1]) * &UPoly::from_ints(&[5, -2, 1]))
            * &UPoly::from_ints(&[3, 1]);
        assert!(no_positive_roots(&p, 32));
        // (x − 1)(x² + 1)·(x² − x + 1): a root at 1 (B = 4, so 1 is a halving point).
        let q = &(&UPoly::from_ints(&[-1, 1]) * &UPoly::from_ints(&[1, 0, 1]))
            * &UPoly::from_ints(&[1, -1, 1]);
        assert!(!no_positive_roots(&q, 32));
    }
}
