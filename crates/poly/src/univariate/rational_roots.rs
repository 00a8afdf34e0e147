//! Every rational root of an integer polynomial, by p-adic lifting.
//!
//! A rational root a/b (lowest terms) of f = Σ f_k x^k ∈ Z[x] has b | f_n
//! and a | f_0. For a prime p dividing neither f_n nor the discriminant of
//! f at a root, a/b reduces to a simple root of f mod p; Newton's iteration
//! lifts that root uniquely to Z/p^k, and once p^k > 2·|f_0|·|f_n| the lift
//! determines a/b by rational reconstruction (the half-extended Euclidean
//! algorithm). Each candidate is then checked by exact evaluation, so the
//! answer is complete and exact; only the choice of prime is heuristic, and
//! a prime at which some root is multiple is skipped.
//!
//! The roots modulo p come from gcd(x^p − x, f) at primes near 2^20: no root
//! there means no rational root; one root, or two when p ≡ 3 (mod 4), are
//! read off that gcd. Otherwise every residue modulo primes near 1000 is
//! tried. When the coefficients are large, where a prime without roots is
//! the cheaper answer than a lift, every prime near 2^20 is tried before
//! anything is lifted. Degrees 1 and 2 are solved in closed form.
//!
//! This replaces, for the stability analysis, an upper bound on the number
//! of rational roots (roots counted modulo primes) followed, whenever the
//! bound did not vanish, by a search in each isolating interval narrowed to
//! the width 1/(2·f_n): conditions with several irreducible factors rarely
//! have a prime without roots, so the search ran on most of them.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::Q;

/// Primes near 1000: roots modulo p are found by trying every residue.
const PRIMES: [u64; 12] = [1009, 1013, 1019, 1021, 1031, 1033, 1039, 1049, 1051, 1061, 1063, 1069];

/// The distinct rational roots of the integer polynomial `f` (lowest
/// coefficient first, f(0) ≠ 0, degree ≥ 1), increasing. `None` when no
/// prime tried has every root of f mod p simple (then the caller falls back
/// to a search).
pub(crate) fn rational_roots(f: &[BigInt]) -> Option<Vec<Q>> {
    let (lead, c0) = (f.last()?, &f[0]);
    debug_assert!(!c0.is_zero() && !lead.is_zero());
    // Degrees 1 and 2 in closed form: −f₀/f₁; (−f₁ ± √Δ)/(2f₂) when the
    // discriminant Δ is a square.
    match f.len() {
        2 => return Some(vec![Q::new(-c0, lead.clone())]),
        3 => {
            let disc = &f[1] * &f[1] - ((lead * c0) << 2u32);
            if disc.is_negative() {
                return Some(Vec::new());
            }
            let root = disc.sqrt();
            if &root * &root != disc {
                return Some(Vec::new());
            }
            let two_a = lead << 1u32;
            let mut out = vec![Q::new(-&f[1] - &root, two_a.clone()), Q::new(-&f[1] + root, two_a)];
            out.sort();
            out.dedup();
            return Some(out);
        }
        _ => {}
    }
    // p^k > 2·|f_0|·|f_n| lets reconstruction find a/b with |a| ≤ |f_0|,
    // 0 < b ≤ |f_n|.
    let bound: BigInt = (c0.abs() * lead.abs()) << 1;
    // No root modulo some prime near 2^20 (the usual case for a condition
    // without rational roots): none over Q. Else, where one or two roots
    // can be read off from gcd(x^p − x, f), they are lifted at once, with
    // no search over residues.
    // Lifting is cheap for small coefficients (a few Newton steps): the
    // first prime with readable roots is lifted from at once. With large
    // ones each step inverts modulo a large power: every prime is tried for
    // one without roots, then the roots read off, or residues modulo primes
    // near 1000 (below).
    let small = bound.bits() <= 160;
    let m = crate::arith::zp::mod_roots(f, small);
    if m.bound == Some(0) {
        return Some(Vec::new());
    }
    // With large coefficients every prime near 2^20 was tried for one
    // without roots, and each had some: a lift is due, and one or two roots
    // read off modulo such a prime are fewer to lift (and from twice the
    // bits) than the residues modulo a prime near 1000 (SDIRK34's A(α)
    // candidates: 1 root against 3).
    if let Some((p, roots)) = m.readable {
        // Small bounds are reached in a few Newton steps: no early stops.
        let p = BigInt::from(p);
        return Some(if small {
            lift(f, p, roots, &bound)
        } else {
            lift_early(f, p, roots, &bound)
        });
    }
    // Else roots modulo primes near 1000, found by trying every residue.
    'prime: for p in PRIMES {
        let pb = BigInt::from(p);
        if (lead % &pb).is_zero() {
            continue;
        }
        let fp: Vec<u64> = f.iter().map(|c| c.mod_floor(&pb).to_u64().expect("below p")).collect();
        let dp: Vec<u64> =
            fp.iter().enumerate().skip(1).map(|(k, &c)| c * (k as u64 % p) % p).collect();
        let eval = |c: &[u64], x: u64| c.iter().rev().fold(0u64, |acc, &a| (acc * x + a) % p);
        let mut roots = Vec::new();
        for x in 0..p {
            if eval(&fp, x) == 0 {
                if eval(&dp, x) == 0 {
                    continue 'prime;
                }
                roots.push(x);
            }
        }
        return Some(lift(f, pb, roots, &bound));
    }
    None
}

/// [`lift`], watching for roots of small height on the way up: once a
/// lifted root reconstructs, at the modulus reached, to some a/b that is a
/// root of f, that residue's root is found (the lift of a simple root is
/// unique), and the rest are the rational roots of f/(bx − a), asked anew
/// (usually a prime without roots then proves there are none, where the
/// other residues would have been lifted to the full bound). SDIRK34's
/// A(α) candidates: y = −1 found at the first step (modulus near 2^40),
/// not lifted to 2^5120.
/// The answer is [`lift`]'s, the complete set of rational roots either way
/// (a property test compares them).
fn lift_early(f: &[BigInt], p: BigInt, roots: Vec<u64>, bound: &BigInt) -> Vec<Q> {
    let (lead, c0) = (f.last().expect("degree ≥ 1"), &f[0]);
    let ip = crate::univariate::sturm::IntPoly::from_ints(f.to_vec());
    let mut modulus = p.clone();
    let mut lifted = start(f, &roots, &modulus);
    while modulus <= *bound {
        modulus = &modulus * &modulus;
        for (r, inv) in &mut lifted {
            (*r, *inv) = newton_step(f, r, inv, &modulus);
        }
        // Heights up to √m/2 reconstruct uniquely at m; the rational root
        // theorem (b | f_n, a | f_0) filters before the exact check.
        let half = (&modulus >> 2u32).sqrt();
        let small = lifted.iter().find_map(|(r, _)| {
            let (a, b) = reconstruct(r, &modulus, &half, &half)?;
            let divides = !a.is_zero() && (lead % &b).is_zero() && (c0 % &a).is_zero();
            // In lowest terms with b > 0 already (`reconstruct`).
            let x = Q::new_raw(a, b);
            (divides && ip.sign_at(&x).is_eq()).then_some(x)
        });
        if let Some(x) = small {
            let rest = crate::univariate::upoly::divide_linear(f, &x);
            let others = if rest.len() <= 1 { Some(Vec::new()) } else { rational_roots(&rest) };
            if let Some(mut others) = others {
                others.push(x);
                others.sort();
                others.dedup();
                return others;
            }
            break;
        }
    }
    lift(f, p, roots, bound)
}

/// Each root with 1/f′(root) modulo the prime.
fn start(f: &[BigInt], roots: &[u64], modulus: &BigInt) -> Vec<(BigInt, BigInt)> {
    roots
        .iter()
        .map(|&r| {
            let r = BigInt::from(r);
            let (_, d) = value_and_slope(f, &r, modulus);
            let inv = d.modinv(modulus).expect("a simple root: f′(r) is a unit");
            (r, inv)
        })
        .collect()
}

/// The rational roots of f among the lifts of `roots`, simple roots of f
/// modulo the prime p: Newton's iteration to a modulus above `bound`
/// (2·|f_0|·|f_n|), rational reconstruction, and an exact check of each.
fn lift(f: &[BigInt], p: BigInt, roots: Vec<u64>, bound: &BigInt) -> Vec<Q> {
    let (lead, c0) = (f.last().expect("degree ≥ 1"), &f[0]);
    let ip = crate::univariate::sturm::IntPoly::from_ints(f.to_vec());
    let mut modulus = p;
    // Each root with 1/f′(root) modulo the current modulus, carried along
    // by Newton's iteration for the inverse (no inversion modulo a large
    // power: on coefficients of thousands of bits that was most of a lift).
    let mut lifted = start(f, &roots, &modulus);
    while modulus <= *bound {
        modulus = &modulus * &modulus;
        for (r, inv) in &mut lifted {
            (*r, *inv) = newton_step(f, r, inv, &modulus);
        }
    }
    let mut out: Vec<Q> = lifted
        .iter()
        .filter_map(|(r, _)| reconstruct(r, &modulus, &c0.abs(), &lead.abs()))
        // In lowest terms with b > 0 already (`reconstruct`).
        .map(|(a, b)| Q::new_raw(a, b))
        .filter(|x| ip.sign_at(x).is_eq())
        .collect();
    out.sort();
    out.dedup();
    out
}

/// f(r) and f′(r) modulo m, by Horner.
fn value_and_slope(f: &[BigInt], r: &BigInt, m: &BigInt) -> (BigInt, BigInt) {
    let (mut v, mut d) = (BigInt::zero(), BigInt::zero());
    for c in f.iter().rev() {
        d = (d * r + &v).mod_floor(m);
        v = (v * r + c).mod_floor(m);
    }
    (v, d)
}

/// One step of Newton's iteration modulo m, for r a simple root of f
/// modulo √m and `inv` ≡ 1/f′(r) modulo √m: the root r − f(r)·inv modulo m
/// (f(r) and the error of `inv` are both multiples of √m, so their product
/// vanishes modulo m), and 1/f′ at it modulo m, by inv·(2 − f′·inv).
fn newton_step(f: &[BigInt], r: &BigInt, inv: &BigInt, m: &BigInt) -> (BigInt, BigInt) {
    let (v, _) = value_and_slope(f, r, m);
    let r = (r - v * inv).mod_floor(m);
    let (_, d) = value_and_slope(f, &r, m);
    let inv = (inv * (BigInt::from(2) - (d * inv).mod_floor(m))).mod_floor(m);
    (r, inv)
}

/// The a/b (b > 0, |a| ≤ n_max, b ≤ d_max) with a ≡ b·r (mod m), if any,
/// by the half-extended Euclidean algorithm (unique when 2·n_max·d_max < m).
fn reconstruct(r: &BigInt, m: &BigInt, n_max: &BigInt, d_max: &BigInt) -> Option<(BigInt, BigInt)> {
    let (mut r0, mut r1) = (m.clone(), r.mod_floor(m));
    let (mut t0, mut t1) = (BigInt::zero(), BigInt::one());
    while r1 > *n_max {
        let (q, r) = r0.div_rem(&r1);
        r0 = std::mem::replace(&mut r1, r);
        let t = &t0 - &q * &t1;
        t0 = std::mem::replace(&mut t1, t);
    }
    let (a, b) = if t1.is_negative() { (-r1, -t1) } else { (r1, t1) };
    (!b.is_zero() && b <= *d_max && crate::arith::intgcd::gcd(&a, &b).is_one()).then_some((a, b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The rational root theorem, tried candidate by candidate: the slow,
    /// obvious oracle (coefficients kept small so the divisors are few).
    fn by_candidates(f: &[i64]) -> Vec<Q> {
        let divisors = |n: i64| (1..=n.abs()).filter(move |d| n % d == 0).collect::<Vec<_>>();
        let mut out = Vec::new();
        for a in divisors(f[0]) {
            for b in divisors(*f.last().unwrap()) {
                for s in [-1, 1] {
                    let x = Q::new((s * a).into(), b.into());
                    let v = f
                        .iter()
                        .rev()
                        .fold(Q::zero(), |acc, &c| acc * &x + Q::from(BigInt::from(c)));
                    if v.is_zero() {
                        out.push(x);
                    }
                }
            }
        }
        out.sort();
        out.dedup();
        out
    }

    fn mul(a: &[i64], b: &[i64]) -> Vec<i64> {
        let mut c = vec![0; a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                c[i + j] += x * y;
            }
        }
        c
    }

    proptest! {
        /// Products of linear factors b·x − a and a random cofactor: the
        /// same roots as trying every candidate, whenever a prime is found.
        #[test]
        fn lifted_roots_are_the_candidates_that_vanish(
            linear in proptest::collection::vec((-9i64..=9, 1i64..=6), 0..4),
            cofactor in proptest::collection::vec(-5i64..=5, 1..4),
        ) {
            let mut f = cofactor.clone();
            prop_assume!(f[0] != 0 && *f.last().unwrap() != 0);
            for (a, b) in &linear {
                prop_assume!(*a != 0);
                f = mul(&f, &[-a, *b]);
            }
            prop_assume!(f.len() >= 2);
            let big: Vec<BigInt> = f.iter().map(|&c| BigInt::from(c)).collect();
            let expected = by_candidates(&f);
            match rational_roots(&big) {
                Some(got) => prop_assert_eq!(got, expected),
                // Every prime tried had a multiple root: f has a square factor.
                None => {
                    let u = crate::UPoly::from_ints(&f);
                    prop_assert!(u.gcd(&u.derivative()).degree().unwrap_or(0) > 0);
                }
            }
        }
    }

    proptest! {
        /// Lifting with an early stop at a root of small height finds what
        /// lifting every residue to the full bound finds: products of small
        /// linear factors and a cofactor with coefficients of 100-400 bits
        /// (no root modulo the prime is then rare, so both lift).
        #[test]
        fn early_lift_finds_what_the_full_lift_finds(
            linear in proptest::collection::vec((-9i64..=9, 1i64..=6), 0..3),
            cofactor in proptest::collection::vec(any::<i64>(), 2..6),
            bits in 1u32..6,
        ) {
            let scale = BigInt::one() << (64 * bits);
            let mut f: Vec<BigInt> =
                cofactor.iter().map(|&c| BigInt::from(c) * &scale + BigInt::from(c % 97)).collect();
            prop_assume!(!f[0].is_zero() && !f.last().unwrap().is_zero());
            for (a, b) in &linear {
                prop_assume!(*a != 0);
                let mut g = vec![BigInt::zero(); f.len() + 1];
                for (k, c) in f.iter().enumerate() {
                    g[k] -= c * a;
                    g[k + 1] += c * b;
                }
                f = g;
            }
            let m = crate::arith::zp::mod_roots(&f, false);
            if let Some((p, roots)) = m.readable {
                let bound: BigInt = (f[0].abs() * f.last().unwrap().abs()) << 1;
                let early = lift_early(&f, BigInt::from(p), roots.clone(), &bound);
                prop_assert_eq!(early, lift(&f, BigInt::from(p), roots, &bound));
            }
        }
    }

    /// Roots with large numerators and denominators (lifting far beyond p).
    #[test]
    fn large_rational_roots() {
        let a = BigInt::parse_bytes(b"123456789012345678901", 10).unwrap();
        let b = BigInt::parse_bytes(b"98765432109876543", 10).unwrap();
        // (b x − a)(x² + x + 7)
        let f = vec![-&a * 7, &b * 7 - &a, &b - &a, b.clone()];
        assert_eq!(rational_roots(&f), Some(vec![Q::new(a, b)]));
    }
}
