//! A tableau's derivation on the oscillator from its stability function
//! R(w) = P(w)/Q(w) (`routes::derive_runge_kutta`): u = y + iv obeys
//! u' = −iωu, so a step multiplies u by R(−iΦ); with α + iβ = d·R(−iΦ),
//! d·P = [[α, β], [−β, α]] and χ = d·z² − 2α·z + |P(iΦ)|². In general over
//! polynomials in w, Φ and z, and in machine words for rational P and Q.

use crate::lang::method::Method;
use crate::multivariate::poly::Monomial;
use crate::{Poly, PolyMatrix, Sym};

/// The oscillator's fields of `derive_runge_kutta` in general (P and Q
/// may hold the method's radicals), over polynomials in w, Φ and z.
pub(super) fn general(method: &Method, p: &Poly, q: &Poly) -> (PolyMatrix, Poly, Poly) {
    let fix = |x: Poly| crate::lang::system::fix(method, x);
    let z = Poly::sym(Sym::z());
    let phi = Poly::sym(Sym::phi());
    // (re, im) of c(−iΦ), (−i)^k cycling 1, −i, −1, i.
    let split = |c: &Poly| {
        let (mut re, mut im) = (Poly::zero(), Poly::zero());
        let mut power = Poly::one();
        for (k, ck) in c.coeffs_in(Sym::w()).iter().enumerate() {
            if !ck.is_zero() {
                let t = ck * &power;
                match k % 4 {
                    0 => re += &t,
                    1 => im -= &t,
                    2 => re -= &t,
                    _ => im += &t,
                }
            }
            power = &power * &phi;
        }
        (re, im)
    };
    let ((pr, pi), (qr, qi)) = (split(p), split(q));
    let d = fix(&(&qr * &qr) + &(&qi * &qi));
    let alpha = fix(&(&pr * &qr) + &(&pi * &qi));
    let beta = fix(&(&pi * &qr) - &(&pr * &qi));
    let modulus = fix(&(&pr * &pr) + &(&pi * &pi));
    let two_alpha = alpha.scale(&crate::Q::from_integer(2.into()));
    let chi = fix(&(&(&d * &(&z * &z)) - &(&two_alpha * &z)) + &modulus);
    let dp = PolyMatrix::from_rows(vec![vec![alpha.clone(), beta.clone()], vec![-&beta, alpha]]);
    (dp, d, chi)
}

/// The oscillator's fields of `derive_runge_kutta` for P and Q with
/// rational coefficients (a tableau without radicals), in `i128`: the
/// same formulas over P̂/D_P and Q̂/D_Q with integer P̂, Q̂, one reduction
/// per coefficient of the results, and no polynomial in several symbols
/// formed until then. `None` at the first overflow (the general route
/// then); a unit test holds it to the general route.
pub(super) fn in_words(p: &crate::UPoly, q: &crate::UPoly) -> Option<(PolyMatrix, Poly, Poly)> {
    use num_integer::Integer;
    use num_traits::ToPrimitive;
    type Words = Vec<i128>;
    // The numerators over the least common denominator.
    let words = |u: &crate::UPoly| -> Option<(Words, i128)> {
        let d = u.coeffs().iter().try_fold(1i128, |l, c| {
            let d = c.denom().to_i128()?;
            (l / l.gcd(&d)).checked_mul(d)
        })?;
        let n = u
            .coeffs()
            .iter()
            .map(|c| c.numer().to_i128()?.checked_mul(d / c.denom().to_i128()?))
            .collect::<Option<Words>>()?;
        Some((n, d))
    };
    // (re, im) of c(−iΦ): (−i)^k cycles 1, −i, −1, i.
    let split = |c: &[i128]| -> (Words, Words) {
        let (mut re, mut im) = (vec![0; c.len()], vec![0; c.len()]);
        for (k, &ck) in c.iter().enumerate() {
            match k % 4 {
                0 => re[k] = ck,
                1 => im[k] = -ck,
                2 => re[k] = -ck,
                _ => im[k] = ck,
            }
        }
        (re, im)
    };
    // x·y ± u·v, coefficientwise in Φ.
    let products = |x: &[i128], y: &[i128], u: &[i128], v: &[i128], minus: bool| {
        let mut out = vec![0i128; (x.len() + y.len()).max(u.len() + v.len()).saturating_sub(1)];
        for (i, a) in x.iter().enumerate() {
            for (j, b) in y.iter().enumerate() {
                out[i + j] = out[i + j].checked_add(a.checked_mul(*b)?)?;
            }
        }
        for (i, a) in u.iter().enumerate() {
            for (j, b) in v.iter().enumerate() {
                let t = a.checked_mul(*b)?;
                out[i + j] =
                    if minus { out[i + j].checked_sub(t)? } else { out[i + j].checked_add(t)? };
            }
        }
        Some(out)
    };
    let ((pn, dp), (qn, dq)) = (words(p)?, words(q)?);
    let ((pr, pi), (qr, qi)) = (split(&pn), split(&qn));
    let (dd, dm, dpq) = (dq.checked_mul(dq)?, dp.checked_mul(dp)?, dp.checked_mul(dq)?);
    // n_k/den Φ^k z^zk, each reduced once; `scale` ±1 or ±2.
    let phi = Sym::phi();
    let terms =
        |n: &[i128], den: i128, scale: i128, zk: u32| -> Option<Vec<(crate::Q, Monomial)>> {
            n.iter()
                .enumerate()
                .filter(|(_, x)| **x != 0)
                .map(|(k, x)| {
                    let x = x.checked_mul(scale)?;
                    let g = x.gcd(&den);
                    let c = crate::Q::new_raw((x / g).into(), (den / g).into());
                    Some((c, Monomial::from_factors(vec![(phi, k as u32), (Sym::z(), zk)])))
                })
                .collect()
        };
    let d = products(&qr, &qr, &qi, &qi, false)?;
    let alpha = products(&pr, &qr, &pi, &qi, false)?;
    let beta = products(&pi, &qr, &pr, &qi, true)?;
    let modulus = products(&pr, &pr, &pi, &pi, false)?;
    // χ = d·z² − 2α·z + |P(iΦ)|².
    let chi = Poly::from_terms(
        terms(&d, dd, 1, 2)?
            .into_iter()
            .chain(terms(&alpha, dpq, -2, 1)?)
            .chain(terms(&modulus, dm, 1, 0)?),
    );
    let alpha = Poly::from_terms(terms(&alpha, dpq, 1, 0)?);
    let (beta, minus_beta) =
        (Poly::from_terms(terms(&beta, dpq, 1, 0)?), Poly::from_terms(terms(&beta, dpq, -1, 0)?));
    let dp = PolyMatrix::from_rows(vec![vec![alpha.clone(), beta], vec![minus_beta, alpha]]);
    Some((dp, Poly::from_terms(terms(&d, dd, 1, 0)?), chi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{UPoly, Q};
    use proptest::prelude::*;

    fn upoly(c: &[(i64, i64)]) -> UPoly {
        UPoly::new(c.iter().map(|&(n, d)| Q::new(n.into(), d.into())).collect())
    }

    proptest! {
        /// The oscillator's fields over Q in one variable are the general
        /// route's, over polynomials in w, Φ and z, for random P and Q
        /// with rational coefficients (zeros, gaps, degrees 0 to 6).
        #[test]
        fn in_words_is_the_general_route(
            p in proptest::collection::vec((-9i64..=9, 1i64..=7), 1..7),
            q in proptest::collection::vec((-9i64..=9, 1i64..=7), 1..5),
            huge in prop::sample::select(vec![1i64, 1, 1, 1 << 61]),
        ) {
            // A coefficient near 2^61 makes the products overflow `i128`.
            let (p, q) = (upoly(&p), upoly(&q));
            let p = UPoly::new(p.coeffs().iter().map(|c| c * Q::from_integer(huge.into())).collect());
            prop_assume!(!q.is_zero());
            let method = crate::builtin("rk4").expect("a built-in without radicals");
            prop_assert!(method.constants().is_empty());
            let (pw, qw) = (Poly::from_upoly(Sym::w(), &p), Poly::from_upoly(Sym::w(), &q));
            let general = general(&method, &pw, &qw);
            let Some(fast) = in_words(&p, &q) else {
                prop_assert!(p.coeffs().iter().chain(q.coeffs()).any(|c| c.numer().bits() > 40));
                return Ok(());
            };
            prop_assert_eq!(fast.1, general.1, "d");
            prop_assert_eq!(fast.2, general.2, "chi");
            prop_assert_eq!(fast.0, general.0, "d·P");
        }
    }
}
