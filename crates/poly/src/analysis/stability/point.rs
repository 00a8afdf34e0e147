//! Exact classification and counting at one Φ.
//!
//! At a rational Φ, χ is a polynomial in z over Q. [`circle_counts`] counts
//! its distinct roots inside, on and outside the unit circle: the factor
//! g = gcd(f, f*) holds every root on the circle and every reciprocal pair
//! (w, 1/w); its roots on the circle are the real roots of G in (−2, 2)
//! (g = z^m G(z + 1/z)) plus ±1, and its other roots split evenly. The
//! cofactor h has no root on the circle and no reciprocal pair: its roots
//! inside come from the signs of the Schur transforms' constants (O(n²),
//! `schur_transform_counts`), or, where one vanishes, from the inertia of
//! its Schur–Cohn matrix BᵀB − AᵀA (A, B lower triangular Toeplitz of
//! a_0 … a_{n−1} and a_n … a_1; non-singular for h): positive eigenvalues
//! inside, negative outside, by Jacobi's rule on Bareiss pivots or an exact
//! symmetric elimination over Q with 1×1 and 2×2 pivots.
//!
//! [`classify`] then finds the dominant roots: the real roots are isolated
//! (Sturm), the largest modulus R among them is bracketed by rationals
//! l < R < u, and the counts of roots of f(u z) outside and of f(l z) inside
//! the circle tell whether a complex root lies beyond R (oscillatory), or
//! only the real roots sit in the annulus l ≤ |z| ≤ u (real dominant). A
//! complex root of modulus exactly R (a tie) makes the bracket fail to
//! separate; after a bounded number of refinements the slow, obvious
//! classifier [`classify_roots_by_products`] decides.
//!
//! The second-order sign table ([`classify_pq`]) is shared with `check`.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

use crate::univariate::algebraic::Algebraic;
use crate::univariate::sturm::{count_real_roots, IntPoly};
use crate::{RootClass, UPoly, Q};

/// Distinct roots inside, on and outside the unit circle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Counts {
    /// Strictly inside.
    pub inside: usize,
    /// On the circle.
    pub on: usize,
    /// Strictly outside.
    pub outside: usize,
}

/// `f(s·z)`.
fn scaled(f: &UPoly, s: &Q) -> UPoly {
    let mut p = Q::one();
    let mut c = Vec::with_capacity(f.coeffs().len());
    for a in f.coeffs() {
        c.push(a * &p);
        p *= s;
    }
    UPoly::new(c)
}

/// The distinct roots of a non-zero `f` inside, on and outside the unit
/// circle, exactly.
pub fn circle_counts(f: &UPoly) -> Counts {
    counts_squarefree(&f.squarefree())
}

/// [`circle_counts`] of a f = a z² + b z + c (a ≠ 0) from signs: a complex
/// pair has |z|² = c/a; real roots are placed against ±1 by f(±1) and the
/// vertex −b/(2a).
pub(crate) fn quadratic_counts(f: &UPoly) -> Counts {
    debug_assert_eq!(f.degree(), Some(2));
    quadratic_counts_of(crate::univariate::upoly::int_primitive(f))
}

/// [`quadratic_counts`] of c + b z + a z² given by integers proportional
/// to its coefficients (a ≠ 0).
pub(crate) fn quadratic_counts_of(mut k: Vec<BigInt>) -> Counts {
    debug_assert_eq!(k.len(), 3);
    // Integer coefficients with a > 0 (the same roots).
    if k[2].is_negative() {
        k.iter_mut().for_each(|x| *x = -&*x);
    }
    let (c, b, a) = (&k[0], &k[1], &k[2]);
    let counts = |inside, on, outside| Counts { inside, on, outside };
    // |p/q| against 1, q ≠ 0.
    let place = |p: &BigInt, q: &BigInt| match p.abs().cmp(&q.abs()) {
        Ordering::Less => counts(1, 0, 0),
        Ordering::Equal => counts(0, 1, 0),
        Ordering::Greater => counts(0, 0, 1),
    };
    let disc = b * b - ((a * c) << 2u32);
    match disc.sign() {
        // A complex pair, |z|² = c/a.
        num_bigint::Sign::Minus => {
            return match c.cmp(a) {
                Ordering::Less => counts(2, 0, 0),
                Ordering::Equal => counts(0, 2, 0),
                Ordering::Greater => counts(0, 0, 2),
            }
        }
        // A double root −b/(2a).
        num_bigint::Sign::NoSign => return place(b, &(a << 1u32)),
        num_bigint::Sign::Plus => {}
    }
    let (at_one, at_minus_one) = (a + b + c, a - b + c);
    // A root at ±1: the other is c/a over it, the same modulus as c/a.
    if at_one.is_zero() || at_minus_one.is_zero() {
        let mut k = place(c, a);
        k.on += 1;
        return k;
    }
    match (at_one.is_positive(), at_minus_one.is_positive()) {
        // Opposite signs: one root in (−1, 1), one outside.
        (true, false) | (false, true) => counts(1, 0, 1),
        // Both positive: the roots on one side of ±1, inside when the
        // vertex −b/(2a) is.
        (true, true) if b.abs() < (a << 1u32) => counts(2, 0, 0),
        (true, true) => counts(0, 0, 2),
        // Both negative: −1 and 1 lie between the roots.
        (false, false) => counts(0, 0, 2),
    }
}

/// [`circle_counts`] of a square-free polynomial.
fn counts_squarefree(sf: &UPoly) -> Counts {
    let Some(n) = sf.degree() else { return Counts::default() };
    let lowest = sf.coeffs().iter().position(|c| !c.is_zero()).unwrap_or(n);
    let g0 = UPoly::new(sf.coeffs()[lowest..].to_vec());
    let mut counts = Counts { inside: lowest.min(1), ..Counts::default() };
    if g0.degree().unwrap_or(0) == 0 {
        return counts;
    }
    let g = g0.gcd(&g0.reversed());
    let (h, dg) = match g.degree().unwrap_or(0) {
        0 => (g0, 0),
        // g0 is itself self-reciprocal (g is g0 made monic).
        d if Some(d) == g0.degree() => (UPoly::constant(Q::one()), d),
        d => (g0.div_rem(&g).0, d),
    };
    let (hin, hout) = schur_cohn_inertia(&h);
    let on = if dg > 0 { on_circle_reciprocal(&g) } else { 0 };
    let off = (dg - on) / 2;
    counts.inside += hin + off;
    counts.on = on;
    counts.outside = hout + off;
    counts
}

/// Roots on the circle of a monic, square-free g whose roots are closed
/// under inversion.
fn on_circle_reciprocal(g: &UPoly) -> usize {
    let mut g = g.clone();
    let mut on = 0;
    for s in [Q::one(), -Q::one()] {
        if g.eval(&s).is_zero() {
            on += 1;
            g = g.div_rem(&UPoly::new(vec![-s, Q::one()])).0;
        }
    }
    let Some(d) = g.degree() else { return on };
    if d == 0 {
        return on;
    }
    debug_assert!(d % 2 == 0, "a palindrome of even degree remains");
    let big_g = crate::univariate::upoly::reciprocal_reduce(
        g.coeffs(),
        Q::zero(),
        |a, b| a + b,
        |a, k| a * Q::from_integer(k.into()),
    );
    let big_g = UPoly::new(big_g);
    let two = Q::from_integer(2.into());
    on + 2 * count_real_roots(&big_g, &-two.clone(), &two)
}

/// (inside, outside) for h with h(0) ≠ 0 and h, h* coprime, from the
/// inertia of the Schur–Cohn matrix.
fn schur_cohn_inertia(h: &UPoly) -> (usize, usize) {
    let Some(n) = h.degree() else { return (0, 0) };
    if n == 0 {
        return (0, 0);
    }
    let a = crate::univariate::upoly::int_primitive(h);
    if let Some(r) = schur_transform_counts(&a) {
        return r;
    }
    // C = BᵀB − AᵀA, A[i][j] = a_{i−j}, B[i][j] = a_{n−(i−j)} (i ≥ j).
    // (BᵀB)[j][k] = Σ_{i ≥ max(j,k)} B[i][j] B[i][k].
    let mut c = vec![vec![BigInt::zero(); n]; n];
    for j in 0..n {
        for k in j..n {
            let mut s = BigInt::zero();
            for i in k..n {
                s += &a[n - (i - j)] * &a[n - (i - k)];
                s -= &a[i - j] * &a[i - k];
            }
            c[j][k] = s.clone();
            c[k][j] = s;
        }
    }
    if let Some(r) = inertia_by_minors(c.clone()) {
        return r;
    }
    let cq: Vec<Vec<Q>> =
        c.into_iter().map(|row| row.into_iter().map(Q::from_integer).collect()).collect();
    let (pos, neg, zero) = inertia(cq);
    debug_assert_eq!(zero, 0, "h and h* are coprime");
    (pos, neg)
}

/// (inside, outside) in the regular case of the Schur–Cohn test, from the
/// Schur transforms f_{k} = T f_{k−1}, T f = f(0)·f − lc(f)·f* (f* the
/// reversal at the formal degree, so T f has formal degree one less): with
/// δ_k = f_k(0) ≠ 0 for k = 1..n, the roots inside the circle are the k
/// with δ_1⋯δ_k < 0 (Henrici, Applied and Computational Complex Analysis
/// I, thm. 6.8b). O(n²) operations where the minors of the n×n Schur–Cohn
/// matrix take O(n³).
///
/// T doubles the size of the coefficients, but from f_3 on T f_{k−1} is
/// divisible by δ_{k−2} (a Bareiss-like identity, checked at every step:
/// a remainder, which has not been seen, falls back to the minors), and
/// dividing by it keeps the sizes linear in k. The divided f_k is the true
/// one over s_k = s_{k−1}²·δ_{k−2}, so the sign of the true δ_k is that of
/// the computed one times sign δ_{k−2}. `None` when some δ_k vanishes or a
/// division is not exact.
fn schur_transform_counts(a: &[BigInt]) -> Option<(usize, usize)> {
    let n = a.len() - 1;
    let mut cur = a.to_vec();
    // consts[j] = f_j(0) as computed (after the division).
    let mut consts: Vec<BigInt> = vec![cur[0].clone()];
    let (mut product_negative, mut inside) = (false, 0);
    for k in 1..=n {
        let m = cur.len() - 1;
        let mut next: Vec<BigInt> =
            (0..m).map(|i| &cur[0] * &cur[i] - &cur[m] * &cur[m - i]).collect();
        let mut scale_negative = false;
        if k >= 3 {
            let d = &consts[k - 2];
            for c in &mut next {
                let (q, r) = c.div_rem(d);
                if !r.is_zero() {
                    return None;
                }
                *c = q;
            }
            scale_negative = d.sign() == num_bigint::Sign::Minus;
        }
        let delta_sign = next[0].sign();
        if delta_sign == num_bigint::Sign::NoSign {
            return None;
        }
        product_negative ^= (delta_sign == num_bigint::Sign::Minus) ^ scale_negative;
        if product_negative {
            inside += 1;
        }
        consts.push(next[0].clone());
        cur = next;
    }
    Some((inside, n - inside))
}

/// Jacobi's rule: when every leading principal minor D_k of the symmetric
/// integer matrix is non-zero, the negative eigenvalues are the sign changes
/// of 1, D_1, …, D_n. The minors are Bareiss's pivots (exact integer
/// elimination). `None` when some D_k vanishes.
fn inertia_by_minors(mut m: Vec<Vec<BigInt>>) -> Option<(usize, usize)> {
    let n = m.len();
    let mut prev = BigInt::one();
    let mut last_sign = Ordering::Greater;
    let mut neg = 0;
    for k in 0..n {
        let d = m[k][k].clone();
        let s = match d.sign() {
            num_bigint::Sign::Minus => Ordering::Less,
            num_bigint::Sign::NoSign => return None,
            num_bigint::Sign::Plus => Ordering::Greater,
        };
        if s != last_sign {
            neg += 1;
        }
        last_sign = s;
        // Each Bareiss step keeps the trailing block symmetric (it is a
        // Schur complement times a scalar): update the upper triangle only,
        // reading m[i][k] as m[k][i].
        for i in k + 1..n {
            for j in i..n {
                let v = (&d * &m[i][j] - &m[k][i] * &m[k][j]) / &prev;
                m[i][j] = v;
            }
        }
        prev = d;
    }
    Some((n - neg, neg))
}

/// (positive, negative, zero) eigenvalue counts of a symmetric matrix over
/// Q, by symmetric elimination with 1×1 and 2×2 pivots (Sylvester's law of
/// inertia).
pub(crate) fn inertia(mut m: Vec<Vec<Q>>) -> (usize, usize, usize) {
    let (mut pos, mut neg) = (0, 0);
    let mut idx: Vec<usize> = (0..m.len()).collect();
    while !idx.is_empty() {
        if let Some(p) = idx.iter().position(|&i| !m[i][i].is_zero()) {
            let i = idx.remove(p);
            let d = m[i][i].clone();
            if d > Q::zero() {
                pos += 1;
            } else {
                neg += 1;
            }
            let row: Vec<Q> = idx.iter().map(|&k| m[i][k].clone()).collect();
            for (a, &j) in idx.iter().enumerate() {
                if row[a].is_zero() {
                    continue;
                }
                let f = &row[a] / &d;
                for (b, &k) in idx.iter().enumerate() {
                    if !row[b].is_zero() {
                        let v = &f * &row[b];
                        m[j][k] -= v;
                    }
                }
            }
            continue;
        }
        // Zero diagonal: a 2×2 pivot [[0, b], [b, 0]] has one eigenvalue of
        // each sign.
        let found = idx.iter().enumerate().find_map(|(a, &i)| {
            idx.iter()
                .enumerate()
                .skip(a + 1)
                .find(|(_, &j)| !m[i][j].is_zero())
                .map(|(b, _)| (a, b))
        });
        let Some((a, b)) = found else { break };
        let (i, j) = (idx[a], idx[b]);
        idx.retain(|&k| k != i && k != j);
        pos += 1;
        neg += 1;
        // Schur complement with the block E = [[0, e], [e, 0]], E⁻¹ = [[0, 1/e], [1/e, 0]]:
        // m[k][l] −= (m[k][i] m[j][l] + m[k][j] m[i][l]) / e.
        let e = m[i][j].clone();
        let ci: Vec<Q> = idx.iter().map(|&k| m[k][i].clone()).collect();
        let cj: Vec<Q> = idx.iter().map(|&k| m[k][j].clone()).collect();
        for (x, &k) in idx.iter().enumerate() {
            for (y, &l) in idx.iter().enumerate() {
                let v = &(&(&ci[x] * &cj[y]) + &(&cj[x] * &ci[y])) / &e;
                if !v.is_zero() {
                    m[k][l] -= v;
                }
            }
        }
    }
    let zero = m.len() - pos - neg;
    (pos, neg, zero)
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Kind {
    Complex,
    Negative,
    Positive,
}

/// The root class of a polynomial in z with rational coefficients, exactly,
/// for any degree (see the module notes). Ties for the largest modulus are
/// resolved towards oscillation (a dominant complex pair wins), then
/// alternation (a dominant negative root wins); a repeated root on the
/// circle when the largest modulus is 1 gives
/// [`RootClass::DoubleRootOnCircle`].
pub fn classify(f: &UPoly) -> RootClass {
    classify_with_counts(f).0
}

/// [`classify`] and [`circle_counts`] together.
pub(crate) fn classify_with_counts(f: &UPoly) -> (RootClass, Counts) {
    classify_counts(f, true)
}

/// [`classify_with_counts`], through F for an even polynomial F(z²) when
/// `even_route` (the tests hold both routes equal).
fn classify_counts(f: &UPoly, even_route: bool) -> (RootClass, Counts) {
    let Some(n) = f.degree() else { return (RootClass::Deadbeat, Counts::default()) };
    let lowest = f.coeffs().iter().position(|c| !c.is_zero()).unwrap_or(n);
    let g = UPoly::new(f.coeffs()[lowest..].to_vec());
    let zero_counts = Counts { inside: lowest.min(1), ..Counts::default() };
    if g.degree().unwrap_or(0) == 0 {
        return (RootClass::Deadbeat, zero_counts);
    }
    // An even g = F(z²), F(0) ≠ 0 (so g(0) ≠ 0): the roots of g are the
    // ±√w for the roots w of F, |z|² = |w|, with w's multiplicity, so the
    // counts are F's doubled and a repeated root on the circle is one of
    // F's. The dominant roots: a complex or negative w gives complex z,
    // and a positive w the real pair ±√w of equal modulus (alternating:
    // the rule for a tie of z and −z below).
    let (base, kind, mut counts) = match g.even_part().filter(|_| even_route) {
        Some(big_f) => {
            let sf = big_f.squarefree();
            let c = match sf.degree() {
                Some(2) => quadratic_counts(&sf),
                _ => counts_squarefree(&sf),
            };
            let kind = dominant_kind(&sf).map(|k| {
                if k == Kind::Positive {
                    Kind::Negative
                } else {
                    Kind::Complex
                }
            });
            let counts = Counts { inside: 2 * c.inside, on: 2 * c.on, outside: 2 * c.outside };
            (big_f, kind, counts)
        }
        None => {
            let sf = g.squarefree();
            let counts = counts_squarefree(&sf);
            (g.clone(), dominant_kind(&sf), counts)
        }
    };
    counts.inside += zero_counts.inside;
    let rho = if counts.outside > 0 {
        Ordering::Greater
    } else if counts.on > 0 {
        Ordering::Equal
    } else {
        Ordering::Less
    };
    let kind = match kind {
        Some(k) => k,
        None => return (classify_roots_by_products(&g), counts),
    };
    let repeated_on = || {
        let d = base.gcd(&base.derivative());
        d.degree().unwrap_or(0) > 0 && circle_counts(&d).on > 0
    };
    let (stable, on, unstable) = match kind {
        Kind::Complex => {
            (RootClass::DampedOscillation, RootClass::Harmonic, RootClass::UnstableOscillation)
        }
        Kind::Negative => {
            (RootClass::AlternatingStable, RootClass::Alternating, RootClass::AlternatingUnstable)
        }
        Kind::Positive => {
            (RootClass::MonotonicStable, RootClass::Constant, RootClass::MonotonicUnstable)
        }
    };
    let class = match rho {
        Ordering::Less => stable,
        Ordering::Equal if repeated_on() => RootClass::DoubleRootOnCircle,
        Ordering::Equal => on,
        Ordering::Greater => unstable,
    };
    (class, counts)
}

/// Which kind of root has the largest modulus; `None` when a bracket does
/// not separate (a tie between a real root and a complex pair).
fn dominant_kind(sf: &UPoly) -> Option<Kind> {
    match sf.degree() {
        Some(1 | 2) => Some(small_dominant_kind(sf)),
        _ => dominant_kind_by_brackets(sf),
    }
}

/// [`dominant_kind`] of a square-free `sf` of degree 1 or 2 with sf(0) ≠ 0,
/// from signs: the root −c₀/c₁; no real root (complex); or real roots
/// r₁ < r₂ whose sum −c₁/c₂ says which is larger in modulus (a tie
/// r₁ = −r₂ counts as negative, as in the general route).
fn small_dominant_kind(sf: &UPoly) -> Kind {
    let c = crate::univariate::upoly::int_primitive(sf);
    let same_sign = |x: &BigInt, y: &BigInt| x.sign() == y.sign();
    if c.len() == 2 {
        return if same_sign(&c[0], &c[1]) { Kind::Negative } else { Kind::Positive };
    }
    let disc = &c[1] * &c[1] - ((&c[0] * &c[2]) << 2u32);
    if disc.is_negative() {
        return Kind::Complex;
    }
    // r₁ + r₂ = −c₁/c₂ > 0 exactly when c₁, c₂ differ in sign.
    if !c[1].is_zero() && !same_sign(&c[1], &c[2]) {
        Kind::Positive
    } else {
        Kind::Negative
    }
}

/// [`dominant_kind`] by isolating the real roots and bracketing the
/// largest modulus among them.
fn dominant_kind_by_brackets(sf: &UPoly) -> Option<Kind> {
    let n = sf.degree().expect("non-constant");
    let (reals, ends) = Algebraic::extreme_real_roots(sf);
    let Some((bottom, top)) = ends.as_ref() else {
        return Some(Kind::Complex);
    };
    let neg_mod = (bottom.sign() == Ordering::Less).then(|| bottom.neg());
    let (r, kind, n_dom) = match (&neg_mod, top.sign() == Ordering::Greater) {
        (Some(m), true) => match m.cmp(top) {
            Ordering::Less => (top.clone(), Kind::Positive, 1),
            Ordering::Equal => (top.clone(), Kind::Negative, 2),
            Ordering::Greater => (m.clone(), Kind::Negative, 1),
        },
        (Some(m), false) => (m.clone(), Kind::Negative, 1),
        (None, _) => (top.clone(), Kind::Positive, 1),
    };
    if reals.len() == n {
        return Some(kind);
    }
    if let Some(q) = r.as_rational() {
        let c = counts_squarefree(&scaled(sf, q));
        if c.outside > 0 || c.on > n_dom {
            return Some(Kind::Complex);
        }
        return Some(kind);
    }
    let mut width = {
        let (lo, hi) = r.interval();
        (hi - lo) / Q::from_integer(4.into())
    };
    let ip = IntPoly::new(sf);
    for _ in 0..24 {
        let (l, u) = r.refine(&width).interval();
        if l <= Q::zero() {
            width /= Q::from_integer(16.into());
            continue;
        }
        let cu = counts_squarefree(&scaled(sf, &u));
        if cu.outside > 0 {
            return Some(Kind::Complex);
        }
        let cl = counts_squarefree(&scaled(sf, &l));
        let annulus = n - cl.inside - cu.outside;
        let reals_in = reals.iter().filter(|iv| modulus_at_least(&ip, iv, &l)).count();
        if annulus == reals_in {
            return Some(kind);
        }
        width = (&u - &l) / Q::from_integer(64.into());
    }
    None
}

/// Whether the root of `ip` isolated by `(lo, hi)` (an interval of
/// [`crate::univariate::sturm::isolate_real_roots`]: `(r, r)` for a rational root, or
/// exactly one root strictly inside and `ip` non-zero of opposite signs at
/// the ends) has modulus at least `l > 0`.
fn modulus_at_least(ip: &IntPoly, (lo, hi): &(Q, Q), l: &Q) -> bool {
    // The root against a point x: `Less` when the root is below it.
    let cmp = |x: &Q| -> Ordering {
        if lo == hi || x <= lo || x >= hi {
            return lo.cmp(x).then(hi.cmp(x));
        }
        match ip.sign_at(x) {
            Ordering::Equal => Ordering::Equal,
            s if s == ip.sign_at(hi) => Ordering::Less,
            _ => Ordering::Greater,
        }
    };
    cmp(l) != Ordering::Less || cmp(&-l) != Ordering::Greater
}

/// The signs of the shifted polynomials of a second-order χ = z² − 2p·z + q
/// at one point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PqSigns {
    /// Sign of p² − q (the discriminant over four).
    pub disc: Ordering,
    /// Sign of p.
    pub p: Ordering,
    /// Sign of p − 1.
    pub p_minus_1: Ordering,
    /// Sign of p + 1.
    pub p_plus_1: Ordering,
    /// Sign of q − 1.
    pub q_minus_1: Ordering,
    /// Sign of q + 1.
    pub q_plus_1: Ordering,
    /// Sign of χ(1) = 1 − 2p + q.
    pub chi_1: Ordering,
    /// Sign of χ(−1) = 1 + 2p + q.
    pub chi_minus_1: Ordering,
}

/// The class of χ(z) = z² − 2p·z + q from the signs of its shifted
/// polynomials: the one sign table of second-order methods, used by the
/// exact analysis (at rational and algebraic Φ) and by `check`.
pub fn classify_pq(s: &PqSigns) -> RootClass {
    classify_pq_with(|f| match f {
        Pq::Disc => s.disc,
        Pq::P => s.p,
        Pq::PMinus1 => s.p_minus_1,
        Pq::PPlus1 => s.p_plus_1,
        Pq::QMinus1 => s.q_minus_1,
        Pq::QPlus1 => s.q_plus_1,
        Pq::Chi1 => s.chi_1,
        Pq::ChiMinus1 => s.chi_minus_1,
    })
}

/// A field of [`PqSigns`].
#[derive(Clone, Copy)]
enum Pq {
    Disc,
    P,
    PMinus1,
    PPlus1,
    QMinus1,
    QPlus1,
    Chi1,
    ChiMinus1,
}

/// [`classify_pq`] reading each sign through `s` when the table needs it:
/// at an algebraic point a sign is an exact evaluation, and most classes
/// need two or three of the eight.
fn classify_pq_with(s: impl Fn(Pq) -> Ordering) -> RootClass {
    use Ordering::{Equal, Greater, Less};
    use RootClass::*;
    match s(Pq::Disc) {
        Less => match s(Pq::QMinus1) {
            Equal => Harmonic,
            Less => DampedOscillation,
            Greater => UnstableOscillation,
        },
        // A double real root at z = p.
        Equal => match s(Pq::P) {
            Equal => Deadbeat,
            _ if s(Pq::PMinus1) == Equal || s(Pq::PPlus1) == Equal => DoubleRootOnCircle,
            Greater if s(Pq::PMinus1) == Less => MonotonicStable,
            Greater => MonotonicUnstable,
            _ if s(Pq::PPlus1) == Greater => AlternatingStable,
            _ => AlternatingUnstable,
        },
        // Two distinct real roots p ± √(p² − q); the dominant one has the
        // sign of p, and χ(±1) tells on which side of ±1 the roots lie.
        Greater => match s(Pq::P) {
            Equal => match s(Pq::QPlus1) {
                Equal => Alternating,
                Greater => AlternatingStable,
                Less => AlternatingUnstable,
            },
            Greater => match s(Pq::Chi1) {
                Equal if s(Pq::PMinus1) == Less => Constant,
                Equal | Less => MonotonicUnstable,
                Greater if s(Pq::PMinus1) == Greater => MonotonicUnstable,
                Greater => MonotonicStable,
            },
            Less => match s(Pq::ChiMinus1) {
                Equal if s(Pq::PPlus1) == Greater => Alternating,
                Equal | Less => AlternatingUnstable,
                Greater if s(Pq::PPlus1) == Less => AlternatingUnstable,
                Greater => AlternatingStable,
            },
        },
    }
}

/// The class of a real root r alone (a first-degree χ).
pub(crate) fn class_of_single_root(
    r_sign: Ordering,
    r_minus_one: Ordering,
    r_plus_one: Ordering,
) -> RootClass {
    match r_sign {
        Ordering::Equal => RootClass::Deadbeat,
        Ordering::Greater => match r_minus_one {
            Ordering::Less => RootClass::MonotonicStable,
            Ordering::Equal => RootClass::Constant,
            Ordering::Greater => RootClass::MonotonicUnstable,
        },
        Ordering::Less => match r_plus_one {
            Ordering::Greater => RootClass::AlternatingStable,
            Ordering::Equal => RootClass::Alternating,
            Ordering::Less => RootClass::AlternatingUnstable,
        },
    }
}

/// The thirteen expressions in c, b, a whose signs decide the class of
/// c + b z + a z², in the order [`classify_quadratic_by`] reads them (the
/// `Q_*` indices): over Q\[Φ\] for the rational engine, over F\[Φ\] for
/// χ with exact constants. The one root-class table is
/// [`classify_quadratic_by`] with [`classify_pq`].
pub(crate) fn quadratic_terms<T: Ring>(c: &T, b: &T, a: &T) -> Vec<T> {
    (0..QUADRATIC_TERMS).map(|k| quadratic_term(k, c, b, a)).collect()
}

/// The number of [`quadratic_terms`].
const QUADRATIC_TERMS: usize = 13;

/// The operations [`quadratic_terms`] takes its coefficients through:
/// those of a ring on references (Q\[Φ\], F\[Φ\], the integers).
pub(crate) trait Ring: Clone {
    fn plus(&self, other: &Self) -> Self;
    fn minus(&self, other: &Self) -> Self;
    fn times(&self, other: &Self) -> Self;
    fn negated(&self) -> Self;
}

impl<T: Clone> Ring for T
where
    for<'x> &'x T: std::ops::Add<&'x T, Output = T>
        + std::ops::Sub<&'x T, Output = T>
        + std::ops::Mul<&'x T, Output = T>
        + std::ops::Neg<Output = T>,
{
    fn plus(&self, other: &Self) -> Self {
        self + other
    }
    fn minus(&self, other: &Self) -> Self {
        self - other
    }
    fn times(&self, other: &Self) -> Self {
        self * other
    }
    fn negated(&self) -> Self {
        -self
    }
}

/// Entry `k` of [`quadratic_terms`] alone (made when a sign table asks).
fn quadratic_term<T: Ring>(k: usize, c: &T, b: &T, a: &T) -> T {
    let two_a = || a.plus(a);
    match k {
        Q_A => a.clone(),
        Q_B => b.clone(),
        Q_NEG_C => c.negated(),
        Q_NEG_C_PLUS_B => c.plus(b).negated(),
        Q_B_MINUS_C => b.minus(c),
        Q_DISC => {
            let ac = a.times(c);
            let two_ac = ac.plus(&ac);
            b.times(b).minus(&two_ac.plus(&two_ac))
        }
        Q_NEG_B => b.negated(),
        Q_NEG_B_PLUS_2A => b.plus(&two_a()).negated(),
        Q_2A_MINUS_B => two_a().minus(b),
        Q_C_MINUS_A => c.minus(a),
        Q_C_PLUS_A => c.plus(a),
        Q_CHI_1 => a.plus(b).plus(c),
        Q_CHI_MINUS_1 => a.minus(b).plus(c),
        _ => unreachable!("{k}: there are {QUADRATIC_TERMS} quadratic terms"),
    }
}

/// The polynomials in Φ whose signs decide a second-order χ = c + b z + a z²
/// (see [`classify_quadratic_by`]), each formed with its integer form when
/// a sign table first asks for it (most classes need three of the
/// thirteen), then kept for the next point.
#[derive(Clone, Debug)]
pub(crate) struct QuadPolys {
    /// c, b, a.
    coeffs: [UPoly; 3],
    entries: [std::sync::OnceLock<(UPoly, crate::univariate::sturm::IntPoly)>; QUADRATIC_TERMS],
}

const Q_A: usize = 0;
const Q_B: usize = 1;
const Q_NEG_C: usize = 2;
const Q_NEG_C_PLUS_B: usize = 3;
const Q_B_MINUS_C: usize = 4;
const Q_DISC: usize = 5;
const Q_NEG_B: usize = 6;
const Q_NEG_B_PLUS_2A: usize = 7;
const Q_2A_MINUS_B: usize = 8;
const Q_C_MINUS_A: usize = 9;
const Q_C_PLUS_A: usize = 10;
const Q_CHI_1: usize = 11;
const Q_CHI_MINUS_1: usize = 12;

impl QuadPolys {
    pub(crate) fn new(a: &[UPoly]) -> QuadPolys {
        QuadPolys {
            coeffs: [a[0].clone(), a[1].clone(), a[2].clone()],
            entries: Default::default(),
        }
    }

    /// Entry `k` of [`quadratic_terms`] and its integer form.
    pub(crate) fn entry(&self, k: usize) -> (&UPoly, &crate::univariate::sturm::IntPoly) {
        let (p, i) = self.entries[k].get_or_init(|| {
            let [c, b, a] = &self.coeffs;
            let p = quadratic_term(k, c, b, a);
            let i = crate::univariate::sturm::IntPoly::new(&p);
            (p, i)
        });
        (p, i)
    }
}

/// The class of a z² + b z + c (coefficients polynomials in Φ) from signs;
/// `sgn(k)` gives the sign of [`QuadPolys`]' entry k at the point of
/// interest, so this is exact at algebraic Φ too. With p = −b/(2a), q = c/a
/// each shifted value's sign is the sign of a polynomial times the sign of a.
pub(crate) fn classify_quadratic_by(sgn: impl Fn(usize) -> Ordering) -> RootClass {
    let sa = sgn(Q_A);
    if sa == Ordering::Equal {
        let sb = sgn(Q_B);
        if sb == Ordering::Equal {
            return RootClass::Deadbeat;
        }
        // The one root r = −c/b: r − 1 = −(c + b)/b, r + 1 = (b − c)/b.
        let by_b = |o: Ordering| if sb == Ordering::Greater { o } else { o.reverse() };
        return class_of_single_root(
            by_b(sgn(Q_NEG_C)),
            by_b(sgn(Q_NEG_C_PLUS_B)),
            by_b(sgn(Q_B_MINUS_C)),
        );
    }
    let by_a = |o: Ordering| if sa == Ordering::Greater { o } else { o.reverse() };
    // Each sign asked once, and only when the table reads it.
    let memo: [std::cell::Cell<Option<Ordering>>; QUADRATIC_TERMS] = Default::default();
    let sgn = |k: usize| {
        memo[k].get().unwrap_or_else(|| {
            let s = sgn(k);
            memo[k].set(Some(s));
            s
        })
    };
    classify_pq_with(|f| match f {
        Pq::Disc => sgn(Q_DISC),
        Pq::P => by_a(sgn(Q_NEG_B)),
        Pq::PMinus1 => by_a(sgn(Q_NEG_B_PLUS_2A)),
        Pq::PPlus1 => by_a(sgn(Q_2A_MINUS_B)),
        Pq::QMinus1 => by_a(sgn(Q_C_MINUS_A)),
        Pq::QPlus1 => by_a(sgn(Q_C_PLUS_A)),
        Pq::Chi1 => by_a(sgn(Q_CHI_1)),
        Pq::ChiMinus1 => by_a(sgn(Q_CHI_MINUS_1)),
    })
}

// ---------------------------------------------------------------------------
// The slow, obvious classifier: products of roots by Newton's identities.

/// The power sums p_k = Σ z_i^k, k = 0..=kmax, of the roots of `f` (with
/// multiplicity), by Newton's identities.
fn power_sums(f: &UPoly, kmax: usize) -> Vec<Q> {
    let n = f.degree().expect("non-zero polynomial");
    let an = f.leading();
    let a = |k: usize| f.coeff(k) / &an;
    let mut p = vec![Q::from_integer(n.into())];
    for k in 1..=kmax {
        let mut s = Q::zero();
        for i in 1..=k.min(n) {
            if i < k {
                s += a(n - i) * &p[k - i];
            } else {
                s += a(n - k) * Q::from_integer(k.into());
            }
        }
        p.push(-s);
    }
    p
}

/// The monic polynomial of degree `m` whose roots have power sums `s[1..=m]`.
fn from_power_sums(s: &[Q], m: usize) -> UPoly {
    let mut e = vec![Q::one()];
    for k in 1..=m {
        let mut acc = Q::zero();
        for i in 1..=k {
            let term = &e[k - i] * &s[i];
            if i % 2 == 1 {
                acc += term;
            } else {
                acc -= term;
            }
        }
        e.push(acc / Q::from_integer(k.into()));
    }
    let mut c = vec![Q::zero(); m + 1];
    for (k, ek) in e.iter().enumerate() {
        c[m - k] = if k % 2 == 0 { ek.clone() } else { -ek.clone() };
    }
    UPoly::new(c)
}

/// The polynomial whose roots are z_i z_j (i ≤ j) over the roots of `f`.
fn pair_products_with_squares(f: &UPoly) -> UPoly {
    let n = f.degree().expect("non-zero polynomial");
    let m = n * (n + 1) / 2;
    let p = power_sums(f, 2 * m);
    let half = Q::new(1.into(), 2.into());
    let s: Vec<Q> = (0..=m).map(|k| (&p[k] * &p[k] + &p[2 * k]) * &half).collect();
    from_power_sums(&s, m)
}

/// How many roots of the square-free `f` have modulus² equal to `rho_sq`:
/// (real ones, complex conjugate pairs).
fn count_on_circle(f: &UPoly, reals: &[Algebraic], rho_sq: &Algebraic) -> (usize, usize) {
    let real = reals.iter().filter(|r| r.square() == *rho_sq).count();
    let mult = rho_sq.multiplicity_in(&pair_products_with_squares(f));
    (real, mult.saturating_sub(real))
}

/// The root class of a polynomial in z over Q by the slow, obvious route:
/// the dominant modulus² is the largest positive root of the polynomial of
/// all products z_i z_j (i ≤ j), degree n(n+1)/2; real roots with r² = ρ²
/// and conjugate pairs with z z̄ = ρ² are counted exactly. Same tie rules as
/// [`classify`]; kept as its oracle (and its fallback at exact ties).
pub fn classify_roots_by_products(f: &UPoly) -> RootClass {
    let Some(n) = f.degree() else { return RootClass::Deadbeat };
    let lowest = f.coeffs().iter().position(|c| !c.is_zero()).unwrap_or(n);
    let g = UPoly::new(f.coeffs()[lowest..].to_vec());
    if g.degree().unwrap_or(0) == 0 {
        return RootClass::Deadbeat;
    }
    let sf = g.squarefree();
    let reals = Algebraic::real_roots(&sf);
    let products = pair_products_with_squares(&sf);
    let rho_sq = Algebraic::positive_roots(&products)
        .pop()
        .expect("a non-zero root gives a positive product z z̄");
    let (n_real, n_pairs) = count_on_circle(&sf, &reals, &rho_sq);
    let vs_one = rho_sq.cmp_rational(&Q::one());
    let repeated = || {
        let rep = g.gcd(&g.derivative());
        if rep.degree().unwrap_or(0) == 0 {
            return false;
        }
        let rep_reals = Algebraic::real_roots(&rep);
        let (r, c) = count_on_circle(&rep, &rep_reals, &rho_sq);
        r + c > 0
    };
    let pick = |stable, on_circle, unstable| match vs_one {
        Ordering::Less => stable,
        Ordering::Equal if repeated() => RootClass::DoubleRootOnCircle,
        Ordering::Equal => on_circle,
        Ordering::Greater => unstable,
    };
    if n_pairs > 0 {
        return pick(
            RootClass::DampedOscillation,
            RootClass::Harmonic,
            RootClass::UnstableOscillation,
        );
    }
    debug_assert!(n_real > 0, "the dominant modulus belongs to some root");
    let negative = reals.iter().any(|r| r.sign() == Ordering::Less && r.square() == rho_sq);
    if negative {
        pick(RootClass::AlternatingStable, RootClass::Alternating, RootClass::AlternatingUnstable)
    } else {
        pick(RootClass::MonotonicStable, RootClass::Constant, RootClass::MonotonicUnstable)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// (inside, outside) from the inertia of the Schur–Cohn matrix over Q:
    /// the O(n³) definition the transform counts stand in for.
    fn by_inertia(a: &[BigInt]) -> (usize, usize) {
        let n = a.len() - 1;
        let mut c = vec![vec![Q::zero(); n]; n];
        for j in 0..n {
            for k in 0..n {
                let mut s = BigInt::zero();
                for i in j.max(k)..n {
                    s += &a[n - (i - j)] * &a[n - (i - k)];
                    s -= &a[i - j] * &a[i - k];
                }
                c[j][k] = Q::from_integer(s);
            }
        }
        let (pos, neg, zero) = inertia(c);
        assert_eq!(zero, 0, "regular case");
        (pos, neg)
    }

    proptest! {
        /// The quadratic rules count as the general route does, on
        /// products of linear factors (roots at ±1, double roots, rational
        /// roots anywhere) and random quadratics (complex pairs, |z| = 1).
        #[test]
        fn quadratic_counts_match_the_general_route(
            roots in ((-6i64..=6, 1i64..=4), (-6i64..=6, 1i64..=4)),
            coeffs in (-9i64..=9, -9i64..=9, 1i64..=9),
            scale in -3i64..=3,
            use_roots in proptest::bool::ANY,
        ) {
            prop_assume!(scale != 0);
            let f = if use_roots {
                let ((p, q), (r, s)) = roots;
                &UPoly::from_ints(&[-p, q]) * &UPoly::from_ints(&[-r, s])
            } else {
                UPoly::from_ints(&[coeffs.0, coeffs.1, coeffs.2])
            };
            let f = f.scale(&Q::from_integer(scale.into()));
            prop_assert_eq!(quadratic_counts(&f), circle_counts(&f));
        }
    }

    proptest! {
        /// The dominant kind of a square-free linear or quadratic
        /// polynomial from signs agrees with the brackets' route.
        #[test]
        fn small_dominant_kind_matches_the_brackets(
            c in proptest::collection::vec(-9i64..=9, 2..4),
        ) {
            let f = UPoly::from_ints(&c);
            prop_assume!(f.degree().unwrap_or(0) > 0 && !f.coeff(0).is_zero());
            let sf = f.squarefree();
            prop_assume!(sf.degree() == f.degree());
            prop_assert_eq!(Some(small_dominant_kind(&sf)), dominant_kind_by_brackets(&sf));
        }
    }

    proptest! {
        /// The class and counts of an even z^k·F(z²) read from F agree
        /// with the general route on z, for products of small factors
        /// (roots at ±1 and ±i, on the circle, repeated, ties of moduli).
        #[test]
        fn even_route_matches_the_general_route(
            factors in proptest::collection::vec((-4i64..=4, -4i64..=4, 0i64..=2), 1..4),
            repeat in proptest::bool::ANY,
            shift in 0usize..3,
        ) {
            let mut big_f = UPoly::from_ints(&[1]);
            for &(c0, c1, c2) in &factors {
                big_f = &big_f * &UPoly::from_ints(&[c0, c1, c2]);
            }
            if repeat {
                let (c0, c1, c2) = factors[0];
                big_f = &big_f * &UPoly::from_ints(&[c0, c1, c2]);
            }
            prop_assume!(big_f.degree().unwrap_or(0) > 0);
            let mut c = vec![Q::zero(); shift];
            c.extend(big_f.spread().coeffs().iter().cloned());
            let f = UPoly::new(c);
            prop_assert_eq!(classify_counts(&f, true), classify_counts(&f, false));
        }
    }

    proptest! {
        /// |root| ≥ l read off an isolating interval with at most one sign
        /// agrees with the made number's |x| compared with l (the route it
        /// replaced in `dominant_kind`).
        #[test]
        fn modulus_from_the_interval_matches_the_number(
            c in proptest::collection::vec(-20i64..20, 2..8),
            ln in 1i64..60, ld in 1i64..8,
        ) {
            prop_assume!(*c.last().unwrap() != 0);
            let sf = UPoly::from_ints(&c).squarefree();
            prop_assume!(sf.degree().unwrap_or(0) > 0);
            let l = Q::new(ln.into(), ld.into());
            let ip = IntPoly::new(&sf);
            let intervals = crate::univariate::roots::isolate_real_roots(&sf);
            let numbers = Algebraic::real_roots(&sf);
            prop_assert_eq!(intervals.len(), numbers.len());
            for (iv, x) in intervals.iter().zip(&numbers) {
                prop_assert_eq!(
                    modulus_at_least(&ip, iv, &l),
                    x.abs().cmp_rational(&l) != Ordering::Less,
                    "{:?} {} {}", iv, x, l
                );
            }
        }
    }

    proptest! {
        /// Wherever the transform recursion answers, it agrees with the
        /// inertia of the Schur–Cohn matrix.
        #[test]
        fn schur_transform_counts_match_the_inertia(
            c in proptest::collection::vec(-40i64..40, 2..10),
        ) {
            prop_assume!(c[0] != 0 && *c.last().unwrap() != 0);
            let f = UPoly::from_ints(&c);
            // The matrix is singular exactly when f and f* share a root.
            prop_assume!(f.gcd(&f.reversed()).degree() == Some(0));
            let a: Vec<BigInt> = c.iter().map(|&x| BigInt::from(x)).collect();
            if let Some(r) = schur_transform_counts(&a) {
                prop_assert_eq!(r, by_inertia(&a));
            }
        }
    }

    /// The recursion answers (no vanishing δ_k, every division exact) on
    /// almost every polynomial, so the fallback is the exception: at least
    /// 95 of 100 random ones of degree 2–9 with h, h* coprime.
    #[test]
    fn schur_transform_counts_answer_on_most_inputs() {
        let mut next = crate::testing::xorshift(0x1234_5678_9abc_def1);
        let (mut tried, mut answered) = (0, 0);
        while tried < 100 {
            let seed = next();
            let n = 3 + (seed % 8) as usize;
            let c: Vec<i64> = (0..n).map(|k| ((seed >> (5 * k)) % 61) as i64 - 30).collect();
            let f = UPoly::from_ints(&c);
            if c[0] == 0 || c[n - 1] == 0 || f.gcd(&f.reversed()).degree() != Some(0) {
                continue;
            }
            tried += 1;
            let a: Vec<BigInt> = c.iter().map(|&x| BigInt::from(x)).collect();
            if let Some(r) = schur_transform_counts(&a) {
                assert_eq!(r, by_inertia(&a), "{c:?}");
                answered += 1;
            }
        }
        assert!(answered >= 95, "answered {answered} of {tried}");
    }

    /// Degree 9 with 30-bit coefficients: the divisions keep the sizes
    /// linear, and the counts match the inertia.
    #[test]
    fn schur_transform_counts_on_a_large_case() {
        let c: Vec<i64> = (0..10)
            .map(|k: i64| (k * 7919 + 104_729).pow(2) % 1_000_000_007 - 500_000_000)
            .collect();
        let a: Vec<BigInt> = c.iter().map(|&x| BigInt::from(x)).collect();
        let r = schur_transform_counts(&a).expect("regular");
        assert_eq!(r, by_inertia(&a));
    }
}
