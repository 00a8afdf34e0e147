//! The SSP coefficient: Kraaijevanger's radius of absolute monotonicity,
//! exact.
//!
//! With K = [[A, 0], [bᵀ, 0]], the method is absolutely monotonic at r ≥ 0
//! when I + rK is invertible, K(I + rK)⁻¹ ≥ 0 and (I + rK)⁻¹e ≥ 0
//! entrywise; the radius R is the supremum of the r for which this holds on
//! all of [0, r] (0 when it holds at no r > 0, unbounded when at every r).
//!
//! (I + rK)⁻¹ = [[X, 0], [−r bᵀX, 1]] with X = (I + rA)⁻¹ = adj/D,
//! D = det(I + rA), D(0) = 1. On [0, ρ_D), ρ_D the least positive root of
//! D, D > 0, so the conditions are that the polynomials A·adj, bᵀadj,
//! adj·e and D − r bᵀadj·e are ≥ 0, and R = min(ρ_D, each polynomial's
//! first point where it turns negative). A polynomial's sign is constant
//! between its consecutive positive roots (isolated exactly, as algebraic
//! numbers) and is read at one rational point of each gap; over a field
//! with radicals, the candidate roots are those of its norm, a polynomial
//! over Q whose roots include every conjugate's.
//!
//! Explicit methods have X = Σ_k (−rA)^k and D = 1. Methods with rational
//! entries get adj and D on integers, by Faddeev–LeVerrier (explicit ones
//! as the special case D = 1); implicit methods with radicals are decided
//! only when some entry of K is negative (R = 0), else the answer is
//! [`ErrorKind::Unsupported`]. The oracle, [`absolutely_monotone_at`],
//! inverts I + rK at one rational r.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use super::report::Ssp;
use super::rk::{dot, mat_vec};
use super::value::{read_matrix, Matrix, Value};
use crate::error::{Error, ErrorKind};
use crate::lang::tableau::Tableau;
use crate::multivariate::constants as field;
use crate::{Algebraic, Poly, Sym, UPoly, Q};

/// A polynomial in r with exact coefficients, lowest degree first.
type RPoly = Vec<Value>;

fn radius_of(tableau: &Tableau) -> Result<(Matrix, Vec<Value>), Error> {
    let (a_e, b_e, _) = tableau.entries();
    let (a, rest) = read_matrix(a_e, &[("b", b_e)])?;
    Ok((a, rest[0].clone()))
}

/// The SSP coefficient of a tableau (Kraaijevanger's radius of absolute
/// monotonicity), exact.
///
/// ```
/// use poly::advanced::tableau::{Exact, Tableau};
/// use poly::advanced::order::{ssp_coefficient, Ssp};
/// let e = |s: &str| Exact::parse(s).unwrap();
/// let a = vec![vec![e("0"), e("0"), e("0")], vec![e("1"), e("0"), e("0")], vec![e("1/4"), e("1/4"), e("0")]];
/// let t = Tableau::new("ssprk33", a, vec![e("1/6"), e("1/6"), e("2/3")], None)?;
/// assert_eq!(ssp_coefficient(&t)?, Ssp::Radius(poly::Algebraic::from_rational(poly::q(1, 1))));
/// # Ok::<(), poly::Error>(())
/// ```
pub fn ssp_coefficient(tableau: &Tableau) -> Result<Ssp, Error> {
    let (a, b) = radius_of(tableau)?;
    coefficient(&a, &b)
}

/// Whether the tableau is absolutely monotonic at the one point r ≥ 0:
/// I + rK invertible, K(I + rK)⁻¹ ≥ 0 and (I + rK)⁻¹e ≥ 0, by exact
/// Gauss–Jordan inversion. The slow, obvious oracle of
/// [`ssp_coefficient`] (which asks it of all of [0, r]).
pub fn absolutely_monotone_at(tableau: &Tableau, r: &Q) -> Result<bool, Error> {
    let (a, b) = radius_of(tableau)?;
    let s = b.len();
    let n = s + 1;
    let k = |i: usize, j: usize| -> Value {
        match (i < s, j < s) {
            (true, true) => a[i][j].clone(),
            (false, true) => b[j].clone(),
            _ => Value::zero(),
        }
    };
    let rv = Value::from(r.clone());
    let mut m: Matrix = (0..n)
        .map(|i| {
            (0..2 * n)
                .map(|j| match j < n {
                    true => {
                        let x = rv.mul(&k(i, j));
                        if i == j {
                            x.add(&Value::one())
                        } else {
                            x
                        }
                    }
                    false if j - n == i => Value::one(),
                    false => Value::zero(),
                })
                .collect()
        })
        .collect();
    for col in 0..n {
        let Some(p) = (col..n).find(|&i| !m[i][col].is_zero()) else {
            return Ok(false);
        };
        m.swap(col, p);
        let inv = m[col][col].inverse().expect("nonzero pivot");
        m[col] = m[col].iter().map(|x| x.mul(&inv)).collect();
        for i in 0..n {
            if i != col && !m[i][col].is_zero() {
                let f = m[i][col].clone();
                let pivot = m[col].clone();
                m[i] = m[i].iter().zip(&pivot).map(|(x, y)| x.sub(&f.mul(y))).collect();
            }
        }
    }
    let inv: Matrix = m.into_iter().map(|row| row[n..].to_vec()).collect();
    let nonneg = |v: &Value| v.sign() != Ordering::Less;
    for (i, row) in inv.iter().enumerate() {
        if !nonneg(&Value::sum(row)) {
            return Ok(false);
        }
        for j in 0..n {
            let kij = inv
                .iter()
                .enumerate()
                .fold(Value::zero(), |acc, (l, r)| acc.add(&k(i, l).mul(&r[j])));
            if !nonneg(&kij) {
                return Ok(false);
            }
        }
    }
    Ok(true)
}

/// The radius for A and b.
pub(crate) fn coefficient(a: &Matrix, b: &[Value]) -> Result<Ssp, Error> {
    let s = b.len();
    let explicit = (0..s).all(|i| (i..s).all(|j| a[i][j].is_zero()));
    let rational = super::value::all_rational(a.iter().flatten().chain(b));
    // Entries of K below zero: R = 0, whatever the rest.
    if a.iter().flatten().chain(b).any(|x| x.sign() == Ordering::Less) {
        return Ok(Ssp::Radius(Algebraic::zero()));
    }
    if rational {
        return Ok(self::rational(a, b));
    }
    if !explicit {
        return Err(Error::analysis(
            ErrorKind::Unsupported,
            "the SSP coefficient of an implicit tableau with irrational entries and K ≥ 0 is not \
             decided (only rational or explicit tableaux are)",
        ));
    }
    let polys = explicit_conditions(a, b);
    let mut best: Option<Algebraic> = None;
    for p in &polys {
        if let Some(r) = first_negative(p) {
            if best.as_ref().is_none_or(|b| r < *b) {
                best = Some(r);
            }
            if best.as_ref().is_some_and(|b| b.sign() == Ordering::Equal) {
                break;
            }
        }
    }
    Ok(best.map_or(Ssp::Unbounded, Ssp::Radius))
}

/// A tableau over Q, explicit or implicit, on integers. With A = Â/d and
/// b = b̂/d_b, Faddeev–LeVerrier on B̂ = −Â gives integer matrices N̂_k and
/// integers ĉ_k (ĉ_k = −tr(B̂N̂_(k−1))/k divides exactly: the ĉ_k are the
/// characteristic polynomial's coefficients of an integer matrix) with
/// adj(I + rA) = Σ_k N̂_k (r/d)^k and D = det(I + rA) = Σ_k ĉ_k (r/d)^k.
/// An explicit tableau has ĉ_k = 0 and N̂_k = (−Â)^k, so D = 1. Every
/// condition polynomial is then a positive multiple of one with integer
/// coefficients (no rational is reduced), and the radius is bounded by D's
/// least positive root.
fn rational(a: &Matrix, b: &[Value]) -> Ssp {
    let s = b.len();
    let q = |v: &Value| v.as_rational().expect("rational").clone();
    let d = crate::arith::intgcd::lcm_all(
        a.iter().flatten().map(|x| x.as_rational().expect("rational").denom()),
    );
    let db =
        crate::arith::intgcd::lcm_all(b.iter().map(|x| x.as_rational().expect("rational").denom()));
    let bm: Vec<Vec<BigInt>> =
        a.iter().map(|r| r.iter().map(|x| -scaled(&q(x), &d)).collect()).collect();
    let bi: Vec<BigInt> = b.iter().map(|x| scaled(&q(x), &db)).collect();
    let (ns, cs) = faddeev_leverrier(&bm);
    let m = ns.len();
    // The polynomial kept of numerators n_k over base·d^k is
    // Σ n_k d^(deg−k) r^k, base·d^deg times the condition.
    let mut numerators: Vec<Vec<BigInt>> = Vec::new();
    for i in 0..s {
        for j in 0..s {
            // (A·adj)_ij = Σ_k r^k (ÂN̂_k)_ij / d^(k+1): base d, with
            // ÂN̂_k = ĉ_(k+1) I − N̂_(k+1) (no product: N̂_(k+1) = B̂N̂_k + ĉ_(k+1) I).
            numerators.push(
                (0..m)
                    .map(|k| {
                        let c = match (i == j, cs.get(k + 1)) {
                            (true, Some(c)) => c.clone(),
                            _ => BigInt::zero(),
                        };
                        match ns.get(k + 1) {
                            Some(n) => c - &n[i][j],
                            None => c,
                        }
                    })
                    .collect(),
            );
        }
    }
    let bn: Vec<Vec<BigInt>> = ns
        .iter()
        .map(|n| (0..s).map(|j| (0..s).map(|l| &bi[l] * &n[l][j]).sum()).collect())
        .collect();
    // (bᵀadj)_j = Σ_k r^k (b̂ᵀN̂_k)_j / (d_b d^k): base d_b.
    numerators.extend((0..s).map(|j| bn.iter().map(|row| row[j].clone()).collect()));
    let ne: Vec<Vec<BigInt>> =
        ns.iter().map(|n| n.iter().map(|r| r.iter().sum()).collect()).collect();
    // (adj·e)_i = Σ_k r^k (N̂_k e)_i / d^k: base 1.
    numerators.extend((0..s).map(|i| ne.iter().map(|v| v[i].clone()).collect()));
    // D − r bᵀadj e, times d_b: the coefficient of r^k over d^k is
    // d_b ĉ_k − d·b̂ᵀN̂_(k−1)e.
    let mut last: Vec<BigInt> = cs.iter().map(|c| &db * c).collect();
    last.resize(last.len().max(m + 1), BigInt::zero());
    for (k, row) in bn.iter().enumerate() {
        last[k + 1] -= &d * row.iter().sum::<BigInt>();
    }
    numerators.push(last);
    let over = |n: Vec<BigInt>| -> Option<Vec<BigInt>> {
        let deg = n.iter().rposition(|x| !x.is_zero())?;
        Some((0..=deg).map(|k| &n[k] * num_traits::pow(d.clone(), deg - k)).collect())
    };
    let bound = over(cs.clone()).filter(|c| c.len() > 1).and_then(|c| {
        Algebraic::positive_roots(&UPoly::new(c.into_iter().map(Q::from_integer).collect()))
            .into_iter()
            .next()
    });
    let polys: Vec<Vec<BigInt>> = numerators.into_iter().filter_map(over).collect();
    least_first_negative(polys, bound).map_or(Ssp::Unbounded, Ssp::Radius)
}

/// Faddeev–LeVerrier on an integer matrix B: N_0 = I, c_k = −tr(BN_(k−1))/k
/// and N_k = BN_(k−1) + c_k I, so that det(λI − B) = Σ_k c_k λ^(s−k) and
/// adj(λI − B) = Σ_k λ^(s−1−k) N_k. Returns the N_k up to the last nonzero
/// one (an explicit tableau's B is nilpotent: its N_k = B^k end early) and
/// c_0..c_s up to the last nonzero one.
fn faddeev_leverrier(bm: &[Vec<BigInt>]) -> (Vec<Vec<Vec<BigInt>>>, Vec<BigInt>) {
    let s = bm.len();
    let identity = (0..s)
        .map(|i| (0..s).map(|j| BigInt::from(u8::from(i == j))).collect())
        .collect::<Vec<Vec<BigInt>>>();
    let mut ns = vec![identity];
    let mut cs = vec![BigInt::one()];
    for k in 1..=s {
        let last = ns.last().expect("one");
        let mut next: Vec<Vec<BigInt>> = (0..s)
            .map(|i| {
                (0..s)
                    .map(|j| {
                        let mut acc = BigInt::zero();
                        for l in 0..s {
                            if !bm[i][l].is_zero() && !last[l][j].is_zero() {
                                acc += &bm[i][l] * &last[l][j];
                            }
                        }
                        acc
                    })
                    .collect()
            })
            .collect();
        let trace: BigInt = (0..s).map(|i| &next[i][i]).sum();
        let c = -trace / BigInt::from(k);
        for (i, row) in next.iter_mut().enumerate() {
            row[i] += &c;
        }
        cs.push(c);
        if next.iter().flatten().all(Zero::is_zero) {
            break;
        }
        ns.push(next);
    }
    // Past the last N_k, every later c is 0 (N = 0 stays 0).
    while cs.len() > 1 && cs.last().is_some_and(Zero::is_zero) {
        cs.pop();
    }
    (ns, cs)
}

/// The least point after which one of the integer polynomials (lowest
/// degree first) is negative, at most `bound` (the least positive root of
/// D, for an implicit method): 0 when one is negative just after 0, `None`
/// when none ever is and there is no bound. Each polynomial is taken once
/// (duplicates dropped); one whose coefficients never change sign, or whose
/// Descartes count on (0, u) is 0 for u above the least point found so
/// far, is passed over: it cannot lower it.
fn least_first_negative(
    mut polys: Vec<Vec<BigInt>>,
    bound: Option<Algebraic>,
) -> Option<Algebraic> {
    polys.retain(|p| p.iter().any(|x| !x.is_zero()));
    polys.sort();
    polys.dedup();
    for p in &polys {
        let low = p.iter().find(|x| !x.is_zero()).expect("nonzero");
        if low.is_negative() {
            return Some(Algebraic::zero());
        }
    }
    // A polynomial with no negative coefficient is positive on r > 0.
    polys.retain(|p| p.iter().any(|x| x.is_negative()));
    // The ones already negative at the first trial point 8^k/8 (k = 0..4)
    // where any is go first: one of them sets the radius, which is then
    // below that point, and Descartes' test passes over most of the rest.
    for k in 0..5u32 {
        let x = Q::new(BigInt::one() << (3 * k), BigInt::from(8u8));
        let later: Vec<bool> = polys.iter().map(|p| sign_at(p, &x) != Ordering::Less).collect();
        if later.contains(&false) {
            let mut keyed: Vec<(bool, Vec<BigInt>)> = later.into_iter().zip(polys).collect();
            keyed.sort_by_key(|(later, _)| *later);
            polys = keyed.into_iter().map(|(_, p)| p).collect();
            break;
        }
    }
    let (mut best, mut below) = match bound {
        Some(r) => {
            let (r, u) = narrowed(r);
            (Some(r), Some(u))
        }
        None => (None, None),
    };
    for p in &polys {
        if below.as_ref().is_some_and(|u| variations_below(p, u) == 0) {
            continue;
        }
        let up = UPoly::new(p.iter().cloned().map(Q::from_integer).collect());
        if let Some(r) = first_negative_int(p, &up) {
            if best.as_ref().is_none_or(|b| r < *b) {
                let (r, u) = narrowed(r);
                (best, below) = (Some(r), Some(u));
            }
        }
    }
    best
}

/// The point with its interval narrowed to a 2⁻³⁰ part of it, and the end
/// of the Descartes tests that pass over what cannot lower it: the point
/// itself when rational (on (0, R) open, a polynomial whose root is R
/// itself is passed over), else a short dyadic just above it.
fn narrowed(r: Algebraic) -> (Algebraic, Q) {
    let hi = r.interval().1;
    let r = r.refine(&(hi.abs() / Q::from_integer(BigInt::one() << 30u32)));
    let u = match r.as_rational() {
        Some(q) => q.clone(),
        None => dyadic_above(&r.interval().1),
    };
    (r, u)
}

/// A dyadic rational at or above x ≥ 0 within about 2⁻³⁴·x, so that the
/// Descartes tests on (0, x) run on short numbers.
fn dyadic_above(x: &Q) -> Q {
    let bits = x.numer().bits() as i64 - x.denom().bits() as i64;
    let k = (34 - bits).max(0) as u32;
    let scaled = num_integer::Integer::div_ceil(&(x.numer() << k), x.denom());
    Q::new(scaled, BigInt::one() << k)
}

/// x·den for a rational x whose denominator divides den.
fn scaled(x: &Q, den: &BigInt) -> BigInt {
    x.numer() * (den / x.denom())
}

/// The sign variations of (1 + x)^n P(u/(1 + x)), Descartes' bound on P's
/// roots in (0, u) (0 means none).
fn variations_below(p: &[BigInt], u: &Q) -> usize {
    let n = p.len() - 1;
    let (un, ud) = (u.numer(), u.denom());
    // q^n P(p/(q(1+x)))(1+x)^n = Σ_k n_k p^k q^(n−k) (1+x)^(n−k).
    let mut out = vec![BigInt::zero(); n + 1];
    let mut pk = BigInt::one();
    for (k, c) in p.iter().enumerate() {
        if !c.is_zero() {
            let w = c * &pk * num_traits::pow(ud.clone(), n - k);
            // (1+x)^(n−k): binomial coefficients.
            let mut binom = BigInt::one();
            for (i, o) in out.iter_mut().enumerate().take(n - k + 1) {
                *o += &w * &binom;
                binom = binom * BigInt::from(n - k - i) / BigInt::from(i + 1);
            }
        }
        pk *= un;
    }
    let signs: Vec<bool> = out.iter().filter(|x| !x.is_zero()).map(|x| x.is_negative()).collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// The sign of an integer polynomial at a rational point.
fn sign_at(p: &[BigInt], x: &Q) -> Ordering {
    let (xn, xd) = (x.numer(), x.denom());
    // Σ c_k xn^k xd^(n−k), Horner in (xn, xd).
    let mut acc = BigInt::zero();
    let mut dpow = BigInt::one();
    for c in p.iter().rev() {
        acc = acc * xn + c * &dpow;
        dpow *= xd;
    }
    acc.cmp(&BigInt::zero())
}

/// [`first_negative`] for an integer polynomial.
fn first_negative_int(p: &[BigInt], up: &UPoly) -> Option<Algebraic> {
    first_sign_change(&Algebraic::positive_roots(up), |x| sign_at(p, x) == Ordering::Less)
}

/// Given a polynomial's positive roots in order (`candidates`) and its
/// sign test at a rational point, the first root after which it is
/// negative (0 when it is negative just after 0); `None` when it never is.
fn first_sign_change(
    candidates: &[Algebraic],
    negative_at: impl Fn(&Q) -> bool,
) -> Option<Algebraic> {
    let first = match candidates.first() {
        Some(c) => Algebraic::rational_between(&Algebraic::zero(), c),
        None => Q::one(),
    };
    if negative_at(&first) {
        return Some(Algebraic::zero());
    }
    for (k, c) in candidates.iter().enumerate() {
        let x = match candidates.get(k + 1) {
            Some(next) => Algebraic::rational_between(c, next),
            None => c.interval().1 + Q::one(),
        };
        if negative_at(&x) {
            return Some(c.clone());
        }
    }
    None
}

/// Explicit: X = Σ_k (−r)^k A^k; the polynomials A·X, bᵀX, X·e and
/// 1 − r bᵀX e, as coefficient lists in r.
fn explicit_conditions(a: &Matrix, b: &[Value]) -> Vec<RPoly> {
    let s = b.len();
    // powers[k] = (−A)^k.
    let mut powers: Vec<Matrix> = vec![(0..s)
        .map(|i| (0..s).map(|j| if i == j { Value::one() } else { Value::zero() }).collect())
        .collect()];
    for _ in 1..s {
        let last = powers.last().expect("one");
        let next: Matrix = (0..s)
            .map(|i| {
                (0..s)
                    .map(|j| {
                        (0..s).fold(Value::zero(), |acc, l| {
                            if a[i][l].is_zero() || last[l][j].is_zero() {
                                acc
                            } else {
                                acc.sub(&a[i][l].mul(&last[l][j]))
                            }
                        })
                    })
                    .collect()
            })
            .collect();
        if next.iter().flatten().all(Value::is_zero) {
            break;
        }
        powers.push(next);
    }
    let col = |m: &Matrix, j: usize| -> Vec<Value> { m.iter().map(|r| r[j].clone()).collect() };
    let mut out = Vec::new();
    for row in a {
        for j in 0..s {
            // (A X)_ij = Σ_k r^k (A (−A)^k)_ij
            out.push(powers.iter().map(|p| dot(row, &col(p, j))).collect());
        }
    }
    for j in 0..s {
        out.push(powers.iter().map(|p| dot(b, &col(p, j))).collect());
    }
    let e = vec![Value::one(); s];
    let xe: Vec<Vec<Value>> = powers.iter().map(|p| mat_vec(p, &e)).collect();
    for i in 0..s {
        out.push(xe.iter().map(|v| v[i].clone()).collect());
    }
    let mut last = vec![Value::one()];
    for v in &xe {
        last.push(dot(b, v).neg());
    }
    out.push(last);
    out
}

/// P(x) at a rational x.
fn eval(p: &RPoly, x: &Q) -> Value {
    let xv = Value::from(x.clone());
    p.iter().rev().fold(Value::zero(), |acc, c| acc.mul(&xv).add(c))
}

/// The supremum of the r with P ≥ 0 on [0, r]; `None` when P ≥ 0 on all of
/// [0, ∞).
fn first_negative(p: &RPoly) -> Option<Algebraic> {
    if p.iter().all(Value::is_zero) {
        return None;
    }
    let candidates = if super::value::all_rational(p) {
        Algebraic::positive_roots(&UPoly::new(
            p.iter().map(|x| x.as_rational().expect("rational").clone()).collect(),
        ))
    } else {
        let r = Sym::new("r");
        let mut poly = Poly::zero();
        for (k, c) in p.iter().enumerate() {
            poly += &(&c.to_poly() * &Poly::sym(r).pow(k as u32));
        }
        let norm = field::norm(&poly).to_upoly(r).expect("a polynomial in r");
        Algebraic::positive_roots(&norm)
    };
    first_sign_change(&candidates, |x| eval(p, x).sign() == Ordering::Less)
}
