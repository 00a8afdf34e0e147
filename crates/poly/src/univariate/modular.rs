//! Determinants and resultants over Z\[Φ\] by multi-modular evaluation and
//! interpolation.
//!
//! A determinant whose entries are integer polynomials in Φ is itself an
//! integer polynomial of known degree bound D (the sum over rows of the
//! largest entry degree). Modulo a 62-bit prime p it is evaluated at D + 1
//! points by Gaussian elimination (or, for a resultant, by Euclid's algorithm
//! over F_p), interpolated, and the residues are combined by the Chinese
//! remainder theorem in the symmetric range. Enough primes are taken that
//! their product exceeds twice a proven bound on every coefficient:
//! |coefficient| ≤ max_{|t| = 1} |det M(t)| ≤ ∏_i (Σ_j ‖m_ij‖₁²)^{1/2}
//! (Hadamard's inequality at each point of the unit circle, with the 1-norm
//! bounding an entry's modulus there). Nothing is guessed: the answer is the
//! exact integer polynomial.

use std::sync::OnceLock;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::{UPoly, Q};

/// The integer coefficients of `p`; panics when one is not an integer (a
/// programmer error: callers clear denominators first).
#[track_caller]
pub(crate) fn ints(p: &UPoly) -> Vec<BigInt> {
    p.coeffs()
        .iter()
        .map(|c| {
            assert!(c.is_integer(), "modular kernels take integer polynomials");
            c.to_integer()
        })
        .collect()
}

/// Σ |c_k|.
fn norm1(c: &[BigInt]) -> BigInt {
    c.iter().fold(BigInt::zero(), |acc, x| acc + x.abs())
}

fn mulmod(a: u64, b: u64, p: u64) -> u64 {
    ((a as u128 * b as u128) % p as u128) as u64
}

fn powmod(mut a: u64, mut e: u64, p: u64) -> u64 {
    let mut r = 1 % p;
    while e > 0 {
        if e & 1 == 1 {
            r = mulmod(r, a, p);
        }
        a = mulmod(a, a, p);
        e >>= 1;
    }
    r
}

/// 1/a mod p by the extended Euclidean algorithm (a ≢ 0, p prime).
fn inv(a: u64, p: u64) -> u64 {
    let (mut r0, mut r1) = (p as i128, (a % p) as i128);
    let (mut t0, mut t1) = (0i128, 1i128);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    debug_assert_eq!(r0, 1, "invertible");
    t0.rem_euclid(p as i128) as u64
}

fn addmod(a: u64, b: u64, p: u64) -> u64 {
    let s = a + b;
    if s >= p {
        s - p
    } else {
        s
    }
}

fn submod(a: u64, b: u64, p: u64) -> u64 {
    if a >= b {
        a - b
    } else {
        a + p - b
    }
}

/// Montgomery multiplication modulo an odd p < 2^62 with R = 2^64, used
/// one-sided: `mul(a, b·R mod p) = a·b mod p` with a plain a, so a factor
/// reused across a loop is converted once ([`Mont::form`]) and every product
/// in the loop avoids a 128-bit division.
struct Mont {
    p: u64,
    /// −p⁻¹ mod 2^64.
    neg_inv: u64,
    /// R² mod p: [`Mont::form`] is one product with it, no division.
    r2: u64,
}

impl Mont {
    fn new(p: u64) -> Mont {
        // Newton's iteration for p⁻¹ mod 2^64 (p odd: p·p ≡ 1 mod 8).
        let mut x = p;
        for _ in 0..5 {
            x = x.wrapping_mul(2u64.wrapping_sub(p.wrapping_mul(x)));
        }
        let r1 = ((1u128 << 64) % p as u128) as u64;
        Mont { p, neg_inv: x.wrapping_neg(), r2: mulmod(r1, r1, p) }
    }

    /// b·R mod p.
    fn form(&self, b: u64) -> u64 {
        self.mul(b, self.r2)
    }

    /// a·b·R⁻¹ mod p, for a, b < p.
    fn mul(&self, a: u64, b: u64) -> u64 {
        let t = a as u128 * b as u128;
        let m = (t as u64).wrapping_mul(self.neg_inv);
        let u = ((t + m as u128 * self.p as u128) >> 64) as u64;
        if u >= self.p {
            u - self.p
        } else {
            u
        }
    }

    /// a^e mod p for a plain a < p (square and multiply in Montgomery form).
    fn pow(&self, a: u64, e: u64) -> u64 {
        self.mul(self.pow_form(self.form(a), e), 1)
    }

    /// (a^e)·R for a in Montgomery form (a·R).
    fn pow_form(&self, mut base: u64, mut e: u64) -> u64 {
        let mut acc = self.form(1);
        while e > 0 {
            if e & 1 == 1 {
                acc = self.mul(acc, base);
            }
            base = self.mul(base, base);
            e >>= 1;
        }
        acc
    }

    /// 1/a mod p (a ≢ 0, p prime), by Fermat: a^(p−2). About 90 products,
    /// where the extended Euclidean algorithm on 62-bit numbers spends ~36
    /// divisions.
    fn inv(&self, a: u64) -> u64 {
        self.pow(a, self.p - 2)
    }
}

/// Deterministic Miller–Rabin for 64-bit integers.
fn is_prime(n: u64) -> bool {
    if n < 2 {
        return false;
    }
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    for &b in &BASES {
        if n.is_multiple_of(b) {
            return n == b;
        }
    }
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'next: for &a in &BASES {
        let mut x = powmod(a, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mulmod(x, x, n);
            if x == n - 1 {
                continue 'next;
            }
        }
        return false;
    }
    true
}

/// The first `count` primes below 2^62, decreasing (computed once, cached).
fn primes(count: usize) -> Vec<u64> {
    static CACHE: OnceLock<std::sync::Mutex<Vec<u64>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| std::sync::Mutex::new(Vec::new()));
    let mut list = cache.lock().unwrap_or_else(|e| e.into_inner());
    let mut n = list.last().map_or(1u64 << 62, |&p| p - 2) | 1;
    while list.len() < count {
        if is_prime(n) {
            list.push(n);
        }
        n -= 2;
    }
    list[..count].to_vec()
}

fn reduce(c: &[BigInt], p: u64) -> Vec<u64> {
    let pb = BigInt::from(p);
    c.iter().map(|x| x.mod_floor(&pb).to_u64().expect("reduced below p")).collect()
}

fn eval_mod(c: &[u64], x: u64, mont: &Mont) -> u64 {
    let xm = mont.form(x % mont.p);
    c.iter().rev().fold(0, |acc, &a| addmod(mont.mul(acc, xm), a, mont.p))
}

/// Newton interpolation over F_p; coefficients lowest power first. The
/// points are small distinct integers, so the inverses of their differences
/// come from one table.
fn interpolate(xs: &[u64], ys: &[u64], p: u64) -> Vec<u64> {
    let n = xs.len();
    let max = xs.iter().copied().max().unwrap_or(0) as usize;
    // inv_table[d] = 1/d mod p for d = 1..=max, by the recurrence
    // 1/d = −(p div d)·1/(p mod d).
    let mut inv_table = vec![0u64; max + 1];
    if max >= 1 {
        inv_table[1] = 1;
    }
    for d in 2..=max {
        let q = p / d as u64;
        let r = (p % d as u64) as usize;
        inv_table[d] = (p - mulmod(q, inv_table[r], p)) % p;
    }
    let mont = Mont::new(p);
    let inv_table: Vec<u64> = inv_table.into_iter().map(|v| mont.form(v)).collect();
    let mut dd = ys.to_vec();
    for j in 1..n {
        for i in (j..n).rev() {
            let num = submod(dd[i], dd[i - 1], p);
            dd[i] = mont.mul(num, inv_table[(xs[i] - xs[i - j]) as usize]);
        }
    }
    // Horner on the Newton form: c ← c·(x − x_k) + dd[k].
    let mut c: Vec<u64> = Vec::with_capacity(n);
    for k in (0..n).rev() {
        let xk = mont.form(xs[k] % p);
        c.push(0);
        for i in (1..c.len()).rev() {
            c[i] = submod(c[i - 1], mont.mul(c[i], xk), p);
        }
        c[0] = submod(0, mont.mul(c[0], xk), p);
        c[0] = addmod(c[0], dd[k], p);
    }
    c
}

/// Combines residue vectors (one per prime) into integers in the symmetric
/// range, as a polynomial over Q.
fn crt(residues: &[(u64, Vec<u64>)]) -> UPoly {
    let len = residues.first().map_or(0, |r| r.1.len());
    let mut value = vec![BigInt::zero(); len];
    let mut modulus = BigInt::one();
    for (p, r) in residues {
        let pb = BigInt::from(*p);
        // x ≡ value (mod modulus), x ≡ r (mod p): x = value + modulus·t,
        // t = (r − value)·modulus⁻¹ mod p.
        let m_mod = modulus.mod_floor(&pb).to_u64().expect("below p");
        let m_inv = inv(m_mod, *p);
        for (v, &ri) in value.iter_mut().zip(r) {
            let v_mod = v.mod_floor(&pb).to_u64().expect("below p");
            let t = mulmod((ri + p - v_mod) % p, m_inv, *p);
            *v += &modulus * BigInt::from(t);
        }
        modulus *= pb;
    }
    let half = &modulus >> 1;
    UPoly::new(
        value
            .into_iter()
            .map(|v| Q::from_integer(if v > half { v - &modulus } else { v }))
            .collect(),
    )
}

/// How many primes make a product above 2·2^bits.
fn primes_for(bound_sq: &BigInt) -> Vec<u64> {
    // |c| ≤ √bound_sq < 2^(bits(bound_sq)/2 + 1); need ∏p > 2|c|.
    let bits = bound_sq.bits() / 2 + 3;
    let count = (bits as usize).div_ceil(61);
    primes(count.max(1))
}

/// Whether every polynomial is even (no odd power of Φ).
fn all_even<'a>(mut ps: impl Iterator<Item = &'a UPoly>) -> bool {
    ps.all(|p| p.coeffs().iter().skip(1).step_by(2).all(Zero::is_zero))
}

/// c(Φ) = h(Φ²) ↦ h, for an even c.
fn halve(p: &UPoly) -> UPoly {
    UPoly::new(p.coeffs().iter().step_by(2).cloned().collect())
}

/// h ↦ h(Φ²).
fn unhalve(h: &UPoly) -> UPoly {
    let mut c = vec![Q::zero(); (2 * h.coeffs().len()).saturating_sub(1)];
    for (k, v) in h.coeffs().iter().enumerate() {
        c[2 * k] = v.clone();
    }
    UPoly::new(c)
}

/// The determinant of a square matrix of integer polynomials in Φ. When
/// every entry is even in Φ (the oscillator's χ usually is: P(−Φ) is P(Φ)
/// conjugated by diag(1, −1)), so is the determinant: it is computed in
/// u = Φ², with half the interpolation points, each evaluation half as long.
pub(crate) fn det(m: &[Vec<UPoly>]) -> UPoly {
    if all_even(m.iter().flatten()) && m.iter().flatten().any(|e| e.degree().unwrap_or(0) > 0) {
        let half: Vec<Vec<UPoly>> = m.iter().map(|row| row.iter().map(halve).collect()).collect();
        return unhalve(&det_direct(&half));
    }
    det_direct(m)
}

fn det_direct(m: &[Vec<UPoly>]) -> UPoly {
    let n = m.len();
    if n == 0 {
        return UPoly::constant(Q::one());
    }
    let entries: Vec<Vec<Vec<BigInt>>> =
        m.iter().map(|row| row.iter().map(ints).collect()).collect();
    let shapes: Vec<Vec<Option<Shape>>> =
        entries.iter().map(|row| row.iter().map(|e| Shape::of(e)).collect()).collect();
    let Some(b) = Bounds::of(&shapes) else { return UPoly::zero() };
    let mut residues = Vec::new();
    for p in primes_for(&b.coeff_sq) {
        let mont = Mont::new(p);
        let red: Vec<Vec<Vec<u64>>> =
            entries.iter().map(|row| row.iter().map(|e| reduce(e, p)).collect()).collect();
        let mut points = b.points(&mont);
        while !points.done() {
            let x = points.next_x();
            let mut a: Vec<Vec<u64>> =
                red.iter().map(|row| row.iter().map(|e| eval_mod(e, x, &mont)).collect()).collect();
            points.push(x, det_mod(&mut a, &mont));
        }
        residues.push((p, points.interpolate()));
    }
    crt(&residues)
}

/// Of one polynomial entry of a matrix, what the bounds on its determinant
/// need: the order at Φ = 0, the degree, and ‖e‖₁.
struct Shape {
    ord: usize,
    deg: usize,
    norm: BigInt,
}

impl Shape {
    /// `None` for the zero polynomial.
    fn of(e: &[BigInt]) -> Option<Shape> {
        let ord = e.iter().position(|c| !c.is_zero())?;
        let deg = e.iter().rposition(|c| !c.is_zero())?;
        Some(Shape { ord, deg, norm: norm1(e) })
    }
}

/// What is known of det M, M a square matrix of integer polynomials in
/// Φ, before computing it: every term of det M = Σ_σ ±∏ m_{i,σ(i)} has
/// order at least Σ ord and degree at most Σ deg along its permutation, so
/// the least weight of a perfect matching (weights ord) bounds the order
/// of det M below and the greatest (weights deg) bounds its degree above:
/// tropical determinants, found by the Hungarian algorithm. They are often
/// far tighter than the sum of row degrees: for AB8's discriminant in Φ²
/// (order 14, degree 22) they give order ≥ 13 and degree ≤ 29, where the
/// row sums allow 0 and 31, so 17 interpolation points per prime do
/// instead of 32.
struct Bounds {
    ord: usize,
    deg: usize,
    /// A bound on the square of every coefficient: Hadamard's inequality
    /// with entries replaced by their 1-norms (Goldstein–Graham), on the
    /// rows or on the columns, whichever is smaller.
    coeff_sq: BigInt,
}

impl Bounds {
    /// `None` when no permutation avoids the zero entries: then every term
    /// vanishes and det M = 0.
    fn of(shapes: &[Vec<Option<Shape>>]) -> Option<Bounds> {
        use pathfinding::kuhn_munkres::{kuhn_munkres, kuhn_munkres_min};
        use pathfinding::matrix::Matrix;
        let n = shapes.len();
        // A zero entry weighs more than any matching of non-zero entries can.
        let big = 1i64 << 40;
        let weights = |f: &dyn Fn(&Shape) -> i64, absent: i64| {
            let cells = shapes
                .iter()
                .flat_map(|row| row.iter().map(|e| e.as_ref().map_or(absent, f)))
                .collect::<Vec<i64>>();
            Matrix::from_vec(n, n, cells).expect("square")
        };
        let (deg, _) = kuhn_munkres(&weights(&|s| s.deg as i64, -big));
        if deg < 0 {
            return None;
        }
        let (ord, _) = kuhn_munkres_min(&weights(&|s| s.ord as i64, big));
        let sq = |e: &Option<Shape>| e.as_ref().map_or(BigInt::zero(), |s| &s.norm * &s.norm);
        let rows = shapes.iter().map(|row| row.iter().map(sq).sum::<BigInt>()).product::<BigInt>();
        let cols = (0..n)
            .map(|j| shapes.iter().map(|row| sq(&row[j])).sum::<BigInt>())
            .product::<BigInt>();
        let ord = usize::try_from(ord).expect("non-negative");
        let deg = usize::try_from(deg).expect("non-negative");
        debug_assert!(ord <= deg);
        Some(Bounds { ord, deg, coeff_sq: rows.min(cols) })
    }

    /// The interpolation of det M = Φ^ord·s(Φ), deg s ≤ deg − ord, from
    /// values at deg − ord + 1 points (not 0 when ord > 0).
    fn points<'a>(&self, mont: &'a Mont) -> Points<'a> {
        Points {
            mont,
            ord: self.ord,
            needed: self.deg - self.ord + 1,
            next: u64::from(self.ord > 0),
            xs: Vec::new(),
            fracs: Vec::new(),
        }
    }
}

/// Values of det M (or of a resultant) modulo p, gathered for [`Bounds`].
struct Points<'a> {
    mont: &'a Mont,
    ord: usize,
    needed: usize,
    next: u64,
    xs: Vec<u64>,
    /// s(x) = value/x^ord as a fraction (Montgomery form), divided out
    /// all at once by [`Points::interpolate`].
    fracs: Vec<Frac>,
}

impl Points<'_> {
    fn done(&self) -> bool {
        self.xs.len() >= self.needed
    }

    /// The next point to try (the caller may skip it by not pushing).
    fn next_x(&mut self) -> u64 {
        self.next += 1;
        self.next - 1
    }

    /// The value at x, stored as s(x) = value / x^ord.
    fn push(&mut self, x: u64, value: Frac) {
        let m = self.mont;
        let den = if self.ord == 0 {
            value.den
        } else {
            m.mul(value.den, m.pow_form(m.form(x), self.ord as u64))
        };
        self.xs.push(x);
        self.fracs.push(Frac { num: value.num, den });
    }

    /// The coefficients of det M modulo p, lowest first: s interpolated,
    /// shifted up by ord.
    fn interpolate(&self) -> Vec<u64> {
        let m = self.mont;
        // Montgomery's trick: prefix products of the denominators, one
        // inversion of the last, then each inverse from its neighbours.
        let mut prefix = Vec::with_capacity(self.fracs.len());
        let mut acc = m.form(1);
        for f in &self.fracs {
            acc = m.mul(acc, f.den);
            prefix.push(acc);
        }
        let mut inv = m.form(m.inv(m.mul(acc, 1)));
        let mut ys = vec![0; self.fracs.len()];
        for i in (0..self.fracs.len()).rev() {
            let inv_i = if i == 0 { inv } else { m.mul(inv, prefix[i - 1]) };
            inv = m.mul(inv, self.fracs[i].den);
            ys[i] = m.mul(m.mul(self.fracs[i].num, inv_i), 1);
        }
        let mut c = vec![0; self.ord];
        c.extend(interpolate(&self.xs, &ys, m.p));
        c
    }
}

/// A value num/den modulo p, both parts in Montgomery form (den ≠ 0): a
/// kernel's result before its one division, so that all the values of one
/// prime share a single inversion (Montgomery's trick, [`Points`]).
#[derive(Clone, Copy)]
struct Frac {
    num: u64,
    den: u64,
}

impl Frac {
    fn zero(mont: &Mont) -> Frac {
        Frac { num: 0, den: mont.form(1) }
    }
}

/// det(a) over F_p by fraction-free elimination: row_i ← a_kk·row_i −
/// a_ik·row_k scales the determinant by a_kk, gathered in a denominator
/// and returned with it (no inverse here: [`Points`] divides all the values
/// of a prime at once). Values in Montgomery form.
fn det_mod(a: &mut [Vec<u64>], mont: &Mont) -> Frac {
    let (n, p) = (a.len(), mont.p);
    for x in a.iter_mut().flatten() {
        *x = mont.form(*x);
    }
    let one = mont.form(1);
    let (mut num, mut den) = (one, one);
    for k in 0..n {
        let Some(piv) = (k..n).find(|&i| a[i][k] != 0) else { return Frac::zero(mont) };
        if piv != k {
            a.swap(piv, k);
            num = submod(0, num, p);
        }
        let akk = a[k][k];
        num = mont.mul(num, akk);
        for i in k + 1..n {
            let f = a[i][k];
            if f == 0 {
                continue;
            }
            let (top, bottom) = a.split_at_mut(i);
            for (x, &y) in bottom[0][k + 1..].iter_mut().zip(&top[k][k + 1..]) {
                *x = submod(mont.mul(*x, akk), mont.mul(y, f), p);
            }
            bottom[0][k] = 0;
            den = mont.mul(den, akk);
        }
    }
    Frac { num, den }
}

fn trim(v: &mut Vec<u64>) {
    while v.last() == Some(&0) {
        v.pop();
    }
}

/// Res(f, g) over F_p by Euclid's algorithm (actual degrees), with
/// pseudo-remainders: R = lc(g)^e·(f mod g) needs no inverse, and
/// Res(g, R) = lc(g)^{e·deg g}·Res(g, f mod g), so the scale factors are
/// gathered in a denominator and returned with it (an inverse costs about
/// as much as the whole elimination of a step; [`Points`] does one per
/// prime). Values are kept in Montgomery form throughout.
fn res_mod(mut f: Vec<u64>, mut g: Vec<u64>, mont: &Mont) -> Frac {
    let p = mont.p;
    trim(&mut f);
    trim(&mut g);
    if f.is_empty() || g.is_empty() {
        return Frac::zero(mont);
    }
    for x in f.iter_mut().chain(g.iter_mut()) {
        *x = mont.form(*x);
    }
    let one = mont.form(1);
    let (mut num, mut den) = (one, one);
    loop {
        let (m, n) = (f.len() - 1, g.len() - 1);
        if n == 0 {
            num = mont.mul(num, mont.pow_form(g[0], m as u64));
            break;
        }
        if m == 0 {
            num = mont.mul(num, mont.pow_form(f[0], n as u64));
            break;
        }
        let lg = g[n];
        let mut r = std::mem::take(&mut f);
        let mut e = 0u64;
        if r.len() > n {
            for k in (0..r.len() - n).rev() {
                let c = r[k + n];
                if c == 0 {
                    continue;
                }
                // r ← lc(g)·r − c·z^k·g: the top term cancels.
                for x in &mut r[..k + n] {
                    *x = mont.mul(*x, lg);
                }
                for (j, &gj) in g[..n].iter().enumerate() {
                    r[k + j] = submod(r[k + j], mont.mul(gj, c), p);
                }
                r[k + n] = 0;
                e += 1;
            }
            r.truncate(n);
        }
        trim(&mut r);
        if r.is_empty() {
            return Frac::zero(mont);
        }
        let k = r.len() - 1;
        if (m * n) % 2 == 1 {
            num = submod(0, num, p);
        }
        num = mont.mul(num, mont.pow_form(lg, (m - k) as u64));
        den = mont.mul(den, mont.pow_form(lg, e * n as u64));
        f = std::mem::replace(&mut g, r);
    }
    Frac { num, den }
}

/// Whether two integer polynomials (lowest power first, non-zero leading
/// coefficients) are coprime over Q, proven by their resultant modulo a
/// prime dividing neither leading coefficient being non-zero (their gcd
/// there has degree 0; a common factor over Q would survive reduction).
/// `false` means "not proven" (they may still be coprime).
pub(crate) fn coprime_mod_p(a: &[BigInt], b: &[BigInt]) -> bool {
    let (la, lb) = (a.last().expect("non-zero"), b.last().expect("non-zero"));
    for p in primes(4) {
        let pb = BigInt::from(p);
        if (la % &pb).is_zero() || (lb % &pb).is_zero() {
            continue;
        }
        // With both leading coefficients non-zero mod p, the resultant
        // vanishes exactly when the two share a root over F̄_p.
        let mont = Mont::new(p);
        return res_mod(reduce(a, p), reduce(b, p), &mont).num != 0;
    }
    false
}

/// Six primes below 2^20 (decreasing): a product of two residues is below
/// 2^40, so a u64 sums 2^24 of them before one reduction, and x^p needs 20
/// squarings. (The expected number of roots modulo p of a polynomial without
/// rational roots does not shrink with a larger p, so nothing is lost.)
const SMALL_PRIMES: [u64; 6] = [1_048_573, 1_048_571, 1_048_559, 1_048_549, 1_048_517, 1_048_507];

/// Polynomial arithmetic over F_p for p < 2^20 (coefficients lowest first).
mod small {
    pub(super) fn trim(v: &mut Vec<u64>) {
        while v.last() == Some(&0) {
            v.pop();
        }
    }

    pub(super) fn inv(a: u64, p: u64) -> u64 {
        let (mut r, mut b, mut e) = (1u64, a % p, p - 2);
        while e > 0 {
            if e & 1 == 1 {
                r = r * b % p;
            }
            b = b * b % p;
            e >>= 1;
        }
        r
    }

    pub(super) fn rem(mut a: Vec<u64>, b: &[u64], p: u64) -> Vec<u64> {
        trim(&mut a);
        let n = b.len() - 1;
        let li = inv(b[n], p);
        while a.len() > n {
            let c = a[a.len() - 1] * li % p;
            let s = a.len() - 1 - n;
            for (j, &bj) in b.iter().enumerate() {
                a[s + j] = (a[s + j] + p - bj * c % p) % p;
            }
            trim(&mut a);
        }
        a
    }

    pub(super) fn gcd(mut a: Vec<u64>, mut b: Vec<u64>, p: u64) -> Vec<u64> {
        trim(&mut a);
        trim(&mut b);
        while !b.is_empty() {
            let r = rem(a, &b, p);
            a = b;
            b = r;
        }
        a
    }

    /// The number of distinct roots in F_p of f (degree ≥ 1, lowest
    /// coefficient first, p < 2^20): deg gcd(x^p − x, f), x^p mod f by
    /// squaring from the top bit of p, a set bit being one multiplication by
    /// x (a shift and one reduction step).
    /// gcd(x^p − x, f) over F_p (the product of x − r over f's distinct
    /// roots r in F_p, up to a constant), for f of degree ≥ 1, p < 2^20.
    pub(super) fn roots_part(f: &[u64], p: u64) -> Vec<u64> {
        debug_assert!(p < 1 << 20);
        let d = f.len() - 1;
        // −f / lc(f), so that reducing a top term c·x^(d+s) adds c·neg[j]·x^(s+j).
        let li = inv(f[d], p);
        let neg: Vec<u64> = f[..d].iter().map(|&c| (p - c * li % p) % p).collect();
        let mut acc = vec![0u64; d];
        if d == 1 {
            acc[0] = neg[0];
        } else {
            acc[1] = 1;
        }
        for bit in (0..63 - p.leading_zeros()).rev() {
            acc = square_rem(&acc, &neg, p);
            if (p >> bit) & 1 == 1 {
                acc = times_x_rem(acc, &neg, p);
            }
        }
        // x^p − x
        if d == 1 {
            acc[0] = (acc[0] + p - neg[0]) % p;
        } else {
            acc[1] = (acc[1] + p - 1) % p;
        }
        trim(&mut acc);
        gcd(acc, f.to_vec(), p)
    }

    /// The roots in F_p of g, a product of distinct linear factors, when
    /// they can be read off: degree 0 or 1, or 2 with p ≡ 3 (mod 4) (a
    /// square root is then a power).
    pub(super) fn read_roots(g: &[u64], p: u64) -> Option<Vec<u64>> {
        match g.len() {
            1 => Some(Vec::new()),
            2 => Some(vec![(p - g[0] * inv(g[1], p) % p) % p]),
            3 if p % 4 == 3 => {
                let li = inv(g[2], p);
                let (b, c) = (g[1] * li % p, g[0] * li % p);
                // x = (−b ± √Δ)/2, Δ = b² − 4c a non-zero square.
                let disc = (b * b % p + p - 4 * c % p) % p;
                let root = super::powmod(disc, (p + 1) / 4, p);
                debug_assert_eq!(root * root % p, disc, "g splits");
                let half = inv(2, p);
                let minus_b = (p - b) % p;
                Some(vec![(minus_b + root) % p * half % p, (minus_b + p - root) % p * half % p])
            }
            _ => None,
        }
    }

    /// a² mod f for a of degree below d = deg f, f given as `neg` = −f/lc(f)
    /// without its leading 1. Products are summed unreduced (each below
    /// 2^40) and reduced once per coefficient.
    fn square_rem(a: &[u64], neg: &[u64], p: u64) -> Vec<u64> {
        let d = neg.len();
        let mut c = vec![0u64; 2 * d - 1];
        for (i, &x) in a.iter().enumerate() {
            if x == 0 {
                continue;
            }
            for (j, &y) in a.iter().enumerate() {
                c[i + j] += x * y;
            }
        }
        reduce_top(c, neg, p)
    }

    /// x·a mod f for a of degree below d = deg f.
    fn times_x_rem(a: Vec<u64>, neg: &[u64], p: u64) -> Vec<u64> {
        let mut c = Vec::with_capacity(a.len() + 1);
        c.push(0);
        c.extend(a);
        reduce_top(c, neg, p)
    }

    /// c mod f for c with unreduced coefficients (each below 2^63 − 2^40·d)
    /// of degree below 2d: the top terms are reduced one at a time, each
    /// adding d products below 2^40 to lower coefficients.
    fn reduce_top(mut c: Vec<u64>, neg: &[u64], p: u64) -> Vec<u64> {
        let d = neg.len();
        for t in (d..c.len()).rev() {
            let top = c[t] % p;
            if top != 0 {
                for (j, &nj) in neg.iter().enumerate() {
                    c[t - d + j] += top * nj;
                }
            }
        }
        c.truncate(d);
        for x in &mut c {
            *x %= p;
        }
        c
    }
}

/// What the primes near 2^20 tell about the rational roots of the integer
/// polynomial f (square-free over Q, f(0) ≠ 0), from those dividing neither
/// its leading coefficient nor its discriminant (f mod p square-free, so
/// distinct rational roots stay distinct mod p).
pub(crate) struct ModRoots {
    /// The least number of roots in F_p over the primes tried, an upper
    /// bound on the number of distinct rational roots (`None`: no prime
    /// suited). The primes are tried until one has no root.
    pub bound: Option<usize>,
    /// The first prime at which the roots can be read off from
    /// gcd(x^p − x, f) (one root, or two with p ≡ 3 mod 4), with them:
    /// simple roots, ready to be lifted.
    pub readable: Option<(u64, Vec<u64>)>,
}

/// [`ModRoots`] of `f`; with `stop_at_readable`, the primes are tried only
/// until the roots at one can be read off (then `bound` may be above the
/// least count).
pub(crate) fn mod_roots(f: &[BigInt], stop_at_readable: bool) -> ModRoots {
    let mut out = ModRoots { bound: None, readable: None };
    let Some(lead) = f.last() else { return out };
    for p in SMALL_PRIMES {
        if (lead % BigInt::from(p)).is_zero() {
            continue;
        }
        let fp = reduce(f, p);
        let d: Vec<u64> =
            fp.iter().enumerate().skip(1).map(|(k, &c)| c * (k as u64 % p) % p).collect();
        if small::gcd(fp.clone(), d, p).len() != 1 {
            continue;
        }
        let part = small::roots_part(&fp, p);
        let count = part.len().saturating_sub(1);
        out.bound = Some(out.bound.map_or(count, |b| b.min(count)));
        if count == 0 {
            break;
        }
        if out.readable.is_none() {
            out.readable = small::read_roots(&part, p).map(|roots| (p, roots));
            if stop_at_readable && out.readable.is_some() {
                break;
            }
        }
    }
    out
}

/// An upper bound on the number of distinct rational roots of the integer
/// polynomial `f` (square-free over Q, f(0) ≠ 0): [`ModRoots::bound`].
pub(crate) fn rational_root_bound(f: &[BigInt]) -> Option<usize> {
    mod_roots(f, false).bound
}

/// Res_z(f, g) for f, g in Z[Φ][z] given by their coefficients in z (lowest
/// first, each an integer polynomial in Φ, the last one non-zero). Computed
/// in u = Φ² when every coefficient is even in Φ (see [`det`]).
pub(crate) fn resultant(f: &[UPoly], g: &[UPoly]) -> UPoly {
    if g.len() == 2 {
        return resultant_with_linear(f, g);
    }
    if f.len() == 2 {
        // Res(f, g) = (−1)^(deg f·deg g) Res(g, f).
        let r = resultant_with_linear(g, f);
        return if g.len().is_multiple_of(2) { r.scale(&-Q::one()) } else { r };
    }
    if all_even(f.iter().chain(g)) && f.iter().chain(g).any(|e| e.degree().unwrap_or(0) > 0) {
        let (fh, gh): (Vec<UPoly>, Vec<UPoly>) =
            (f.iter().map(halve).collect(), g.iter().map(halve).collect());
        return unhalve(&resultant_direct(&fh, &gh));
    }
    resultant_direct(f, g)
}

/// Res(f, g) for a linear g = g₀ + g₁z, Sylvester's determinant expanded
/// along its one row of g per column: (−1)^m Σ_k f_k·(−g₀)^k·g₁^(m−k)
/// (m = deg f; f_m·∏ g(α_i) when f_m ≠ 0), by a homogeneous Horner scheme:
/// no primes, no bounds.
fn resultant_with_linear(f: &[UPoly], g: &[UPoly]) -> UPoly {
    let m = f.len() - 1;
    let neg_g0 = -&g[0];
    let mut acc = f[m].clone();
    let mut g1_power = UPoly::constant(Q::one());
    for k in (0..m).rev() {
        g1_power = &g1_power * &g[1];
        acc = &(&acc * &neg_g0) + &(&f[k] * &g1_power);
    }
    if m % 2 == 1 {
        acc.scale(&-Q::one())
    } else {
        acc
    }
}

fn resultant_direct(f: &[UPoly], g: &[UPoly]) -> UPoly {
    let (m, n) = (f.len() - 1, g.len() - 1);
    let fi: Vec<Vec<BigInt>> = f.iter().map(ints).collect();
    let gi: Vec<Vec<BigInt>> = g.iter().map(ints).collect();
    // The Sylvester matrix's shape: n rows of f's coefficients, m of g's,
    // each shifted one column right of the last.
    let shape = |c: &[Vec<BigInt>], rows: usize| -> Vec<Vec<Option<Shape>>> {
        let k = c.len() - 1;
        (0..rows)
            .map(|i| {
                (0..m + n)
                    .map(|j| {
                        j.checked_sub(i).filter(|&t| t <= k).and_then(|t| Shape::of(&c[k - t]))
                    })
                    .collect()
            })
            .collect()
    };
    let mut shapes = shape(&fi, n);
    shapes.extend(shape(&gi, m));
    let Some(b) = Bounds::of(&shapes) else { return UPoly::zero() };
    let mut residues = Vec::new();
    for p in primes_for(&b.coeff_sq) {
        let mont = Mont::new(p);
        let fr: Vec<Vec<u64>> = fi.iter().map(|e| reduce(e, p)).collect();
        let gr: Vec<Vec<u64>> = gi.iter().map(|e| reduce(e, p)).collect();
        let mut points = b.points(&mont);
        while !points.done() {
            let x = points.next_x();
            let fx: Vec<u64> = fr.iter().map(|c| eval_mod(c, x, &mont)).collect();
            let gx: Vec<u64> = gr.iter().map(|c| eval_mod(c, x, &mont)).collect();
            // Skip points where a formal leading coefficient vanishes: there
            // the actual resultant is not the formal one.
            if fx[m] != 0 && gx[n] != 0 {
                points.push(x, res_mod(fx, gx, &mont));
            }
        }
        residues.push((p, points.interpolate()));
    }
    crt(&residues)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn up(c: &[i64]) -> UPoly {
        UPoly::from_ints(c)
    }

    /// Laplace expansion along the first row: the slow, obvious oracle.
    fn laplace(m: &[Vec<UPoly>]) -> UPoly {
        if m.len() == 1 {
            return m[0][0].clone();
        }
        let mut acc = UPoly::zero();
        for (j, e) in m[0].iter().enumerate() {
            let minor: Vec<Vec<UPoly>> = m[1..]
                .iter()
                .map(|row| {
                    row.iter()
                        .enumerate()
                        .filter(|(c, _)| *c != j)
                        .map(|(_, x)| x.clone())
                        .collect()
                })
                .collect();
            let t = e * &laplace(&minor);
            acc = if j % 2 == 0 { &acc + &t } else { &acc - &t };
        }
        acc
    }

    /// An n×n matrix of integer polynomials: a third of the entries zero,
    /// the others Φ^k·(1 to 3 coefficients in [−m, m]), k < `powers`.
    fn random_matrix(
        n: usize,
        next: &mut impl FnMut() -> u64,
        powers: u64,
        m: u64,
    ) -> Vec<Vec<UPoly>> {
        (0..n)
            .map(|_| {
                (0..n)
                    .map(|_| {
                        if next().is_multiple_of(3) {
                            return UPoly::zero();
                        }
                        let k = if powers > 1 { (next() % powers) as usize } else { 0 };
                        let len = 1 + (next() % 3) as usize;
                        let mut c = vec![0i64; k];
                        c.extend((0..len).map(|_| (next() % (2 * m + 1)) as i64 - m as i64));
                        up(&c)
                    })
                    .collect()
            })
            .collect()
    }

    /// Random 1×1 … 5×5 matrices of integer polynomials (many zero entries,
    /// so pivots vanish at some points and rows are swapped) against Laplace.
    #[test]
    fn det_matches_laplace_expansion() {
        let mut next = crate::testing::xorshift(0x2545_f491_4f6c_dd1d);
        for trial in 0..60 {
            let m = random_matrix(1 + trial % 5, &mut next, 1, 1000);
            assert_eq!(det(&m), laplace(&m), "{m:?}");
        }
    }

    /// Entries Φ^k·(random), zeros among them: the tropical bounds on the
    /// order and the degree decide how many points are interpolated, so a
    /// bound too tight would show here against Laplace's expansion.
    #[test]
    fn det_with_powers_of_phi_matches_laplace_expansion() {
        let mut next = crate::testing::xorshift(0x9e37_79b9_7f4a_7c15);
        for trial in 0..80 {
            let m = random_matrix(1 + trial % 5, &mut next, 4, 20);
            assert_eq!(det(&m), laplace(&m), "{m:?}");
        }
    }

    /// The bounds themselves: order and degree of det M are within them
    /// (exactly met on these), and a matrix without a permutation of
    /// non-zero entries is singular.
    #[test]
    fn tropical_bounds_hold() {
        let shapes = |m: &[Vec<UPoly>]| -> Vec<Vec<Option<Shape>>> {
            m.iter().map(|row| row.iter().map(|e| Shape::of(&ints(e))).collect()).collect()
        };
        // [[Φ², Φ], [Φ, Φ³]]: det Φ⁵ − Φ², order 2, degree 5.
        let m = vec![vec![up(&[0, 0, 1]), up(&[0, 1])], vec![up(&[0, 1]), up(&[0, 0, 0, 1])]];
        let b = Bounds::of(&shapes(&m)).expect("a permutation");
        assert_eq!((b.ord, b.deg), (2, 5));
        assert_eq!(det(&m), up(&[0, 0, -1, 0, 0, 1]));
        // [[Φ, 0], [1, 0]]: no permutation avoids a zero.
        let m = vec![vec![up(&[0, 1]), UPoly::zero()], vec![up(&[1]), UPoly::zero()]];
        assert!(Bounds::of(&shapes(&m)).is_none());
        assert!(det(&m).is_zero());
    }

    /// Resultants whose coefficients carry powers of Φ (as the
    /// discriminants of χ do): checked against Sylvester's determinant at
    /// more points than the result's degree, so the whole polynomial is.
    #[test]
    fn resultant_with_powers_of_phi_matches_sylvester() {
        let mut next = crate::testing::xorshift(0xd1b5_4a32_d192_ed03);
        let mut small = |m: u64| (next() % (2 * m + 1)) as i64 - m as i64;
        for _ in 0..30 {
            let (m, n) =
                (2 + small(1).unsigned_abs() as usize, 1 + small(1).unsigned_abs() as usize);
            let mut coeffs = |deg: usize| -> Vec<UPoly> {
                let mut c: Vec<UPoly> = (0..deg)
                    .map(|_| {
                        let k = small(1).unsigned_abs() as usize + 1;
                        let mut c = vec![0i64; k];
                        c.extend([small(4), small(3)]);
                        up(&c)
                    })
                    .collect();
                c.push(up(&[if small(1) >= 0 { 2 } else { -1 }]));
                c
            };
            let (f, g) = (coeffs(m), coeffs(n));
            // Degree ≤ n·4 + m·4 ≤ 20 here: 27 points decide it.
            resultant_matches_at(&f, &g, -13..=13);
        }
    }

    /// "Coprime mod p" is a proof: whenever it answers, the gcd over Q is
    /// constant, and a shared factor is never missed; on random pairs it
    /// answers for nearly all coprime ones.
    #[test]
    fn coprime_mod_p_agrees_with_the_gcd() {
        let mut next = crate::testing::xorshift(0x1234_5678_9abc_def1);
        let mut small = |m: u64| (next() % (2 * m + 1)) as i64 - m as i64;
        let (mut coprime, mut answered) = (0, 0);
        for trial in 0..200 {
            let mut poly = |len: usize| {
                let mut c: Vec<i64> = (0..len).map(|_| small(9)).collect();
                if *c.last().unwrap() == 0 {
                    *c.last_mut().unwrap() = 1;
                }
                up(&c)
            };
            let (mut a, mut b) = (poly(2 + trial % 5), poly(1 + trial % 4));
            if trial % 3 == 0 {
                let common = poly(2);
                a = &a * &common;
                b = &b * &common;
            }
            let proven = coprime_mod_p(&ints(&a), &ints(&b));
            let truly = a.gcd(&b).degree() == Some(0);
            assert!(!proven || truly, "{a:?}, {b:?}");
            coprime += usize::from(truly);
            answered += usize::from(proven);
        }
        assert!(answered * 100 >= coprime * 95, "{answered} of {coprime}");
    }

    #[test]
    fn det_of_polynomial_matrix() {
        // [[x, 1], [2, x]] → x² − 2
        let m = vec![vec![up(&[0, 1]), up(&[1])], vec![up(&[2]), up(&[0, 1])]];
        assert_eq!(det(&m), up(&[-2, 0, 1]));
    }

    /// The root count over F_p by x^p − x equals counting by trying every
    /// element, for small primes and random polynomials.
    #[test]
    fn root_count_mod_p_matches_trying_every_element() {
        let mut next = crate::testing::xorshift(0x9e37_79b9_7f4a_7c15);
        for p in [2u64, 3, 101, 103, 1009, SMALL_PRIMES[0], SMALL_PRIMES[5]] {
            let trials = if p > 10_000 { 3 } else { 40 };
            for _ in 0..trials {
                let deg = 1 + (next() % 7) as usize;
                let mut f: Vec<u64> = (0..deg).map(|_| next() % p).collect();
                f.push(1 + next() % (p - 1));
                if p > 10_000 {
                    // Plant a few roots, so that the count is not always 0 or 1.
                    for _ in 0..next() % 3 {
                        let r = next() % p;
                        f.insert(0, 0);
                        for k in 0..f.len() - 1 {
                            f[k] = (f[k] + p - r * f[k + 1] % p) % p;
                        }
                    }
                }
                let brute = (0..p)
                    .filter(|&x| f.iter().rev().fold(0u64, |acc, &c| (acc * x + c) % p) == 0)
                    .count();
                assert_eq!(super::small::roots_part(&f, p).len() - 1, brute, "{f:?} mod {p}");
            }
        }
    }

    #[test]
    fn fast_field_operations_match_the_obvious_ones() {
        // Oracles: Fermat's inverse a^(p−2) and the 128-bit remainder.
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for p in primes(3) {
            let mont = Mont::new(p);
            for _ in 0..200 {
                x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                let a = x % p;
                let b = x.rotate_left(17) % p;
                assert_eq!(mont.mul(a, mont.form(b)), mulmod(a, b, p));
                if a != 0 {
                    assert_eq!(inv(a, p), powmod(a, p - 2, p));
                    // Fermat in Montgomery form against the extended Euclid.
                    assert_eq!(mont.inv(a), inv(a, p));
                    assert_eq!(mulmod(mont.inv(a), a, p), 1);
                }
                assert_eq!(mont.pow(a, b % 1000), powmod(a, b % 1000, p));
                assert_eq!(addmod(a, b, p), ((a as u128 + b as u128) % p as u128) as u64);
                assert_eq!(
                    submod(a, b, p),
                    ((a as u128 + p as u128 - b as u128) % p as u128) as u64
                );
            }
        }
    }

    /// The Sylvester determinant over Z by Bareiss' fraction-free
    /// elimination: the textbook resultant, the oracle.
    /// The modular resultant of f, g ∈ Z[Φ][z] at each Φ = t equals
    /// Sylvester's determinant of f(t), g(t).
    fn resultant_matches_at(f: &[UPoly], g: &[UPoly], ts: std::ops::RangeInclusive<i64>) {
        let r = resultant(f, g);
        for t in ts {
            let tq = Q::from_integer(t.into());
            let at = |v: &[UPoly]| -> Vec<i64> {
                v.iter().map(|c| c.eval(&tq).to_integer().to_i64().unwrap()).collect()
            };
            let expected = sylvester_resultant(&at(f), &at(g));
            assert_eq!(r.eval(&tq), Q::from_integer(expected), "f = {f:?}, g = {g:?}, t = {t}");
        }
    }

    fn sylvester_resultant(f: &[i64], g: &[i64]) -> BigInt {
        let (m, n) = (f.len() - 1, g.len() - 1);
        let size = m + n;
        let mut a = vec![vec![BigInt::zero(); size]; size];
        for i in 0..n {
            for (j, &c) in f.iter().rev().enumerate() {
                a[i][i + j] = BigInt::from(c);
            }
        }
        for i in 0..m {
            for (j, &c) in g.iter().rev().enumerate() {
                a[n + i][i + j] = BigInt::from(c);
            }
        }
        let mut sign = BigInt::one();
        let mut prev = BigInt::one();
        for k in 0..size {
            let Some(piv) = (k..size).find(|&i| !a[i][k].is_zero()) else { return BigInt::zero() };
            if piv != k {
                a.swap(piv, k);
                sign = -sign;
            }
            for i in k + 1..size {
                for j in k + 1..size {
                    let v = &a[i][j] * &a[k][k] - &a[i][k] * &a[k][j];
                    a[i][j] = v / &prev;
                }
                a[i][k] = BigInt::zero();
            }
            prev = a[k][k].clone();
        }
        sign * &a[size - 1][size - 1]
    }

    #[test]
    fn resultant_matches_sylvester_at_points() {
        // Random f, g in Z[Φ][z] with constant leading coefficients; the
        // modular resultant at Φ = t equals Sylvester's determinant of f(t),
        // g(t).
        let mut x = 12345u64;
        let mut next = |m: i64| {
            x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((x >> 33) as i64).rem_euclid(2 * m + 1) - m
        };
        for round in 0..24 {
            // Every other round even in Φ: the halved path (u = Φ²).
            let even = round % 2 == 1;
            let (m, n) = (2 + next(1).unsigned_abs() as usize, 1 + next(1).unsigned_abs() as usize);
            let mut coeffs = |deg: usize| -> Vec<UPoly> {
                let mut c: Vec<UPoly> = (0..deg)
                    .map(|_| {
                        if even {
                            up(&[next(5), 0, next(5), 0, next(3)])
                        } else {
                            up(&[next(5), next(5), next(3)])
                        }
                    })
                    .collect();
                let mut lead = next(4);
                if lead == 0 {
                    lead = 3;
                }
                c.push(up(&[lead]));
                c
            };
            let (f, g) = (coeffs(m), coeffs(n));
            resultant_matches_at(&f, &g, -3..=3);
        }
    }

    /// An even matrix's determinant, computed in Φ², equals the direct one.
    #[test]
    fn even_determinant_equals_the_direct_one() {
        let m = vec![
            vec![up(&[1, 0, -2]), up(&[3]), up(&[0, 0, 0, 0, 1])],
            vec![up(&[0, 0, 5]), up(&[-1, 0, 1]), up(&[2])],
            vec![up(&[7]), up(&[0, 0, -3]), up(&[1, 0, 1, 0, 1])],
        ];
        assert!(all_even(m.iter().flatten()));
        let d = det(&m);
        assert_eq!(d, det_direct(&m));
        assert!(d.degree().unwrap_or(0) >= 4, "{d:?}");
    }

    proptest::proptest! {
        /// The roots read off a product of distinct linear factors over
        /// F_p are its roots: one, or two at a prime p ≡ 3 (mod 4); none
        /// read at p ≡ 1 (mod 4) for two.
        #[test]
        fn roots_read_off_are_the_roots(
            r1 in 0u64..1_048_507, r2 in 0u64..1_048_507, scale in 1u64..1000, two in proptest::bool::ANY,
        ) {
            for p in SMALL_PRIMES {
                let (r1, r2) = (r1 % p, r2 % p);
                let linear = vec![(p - r1) * scale % p, scale];
                let g = if two {
                    proptest::prop_assume!(r1 != r2);
                    // scale·(x − r1)(x − r2)
                    vec![r1 * r2 % p * scale % p, (2 * p - r1 - r2) % p * scale % p, scale]
                } else {
                    linear
                };
                let read = small::read_roots(&g, p);
                if two && p % 4 == 1 {
                    proptest::prop_assert_eq!(read, None);
                    continue;
                }
                let mut read = read.expect("readable");
                read.sort_unstable();
                let mut expected = if two { vec![r1, r2] } else { vec![r1] };
                expected.sort_unstable();
                proptest::prop_assert_eq!(read, expected, "p = {}", p);
            }
        }
    }

    proptest::proptest! {
        /// The closed form with a linear factor equals the modular
        /// Sylvester determinant, either side linear, even or not in Φ.
        #[test]
        fn linear_resultant_matches_the_modular_one(
            f in proptest::collection::vec(proptest::collection::vec(-6i64..=6, 1..4), 1..6),
            g in proptest::collection::vec(-6i64..=6, 1..4),
            g1 in proptest::collection::vec(-6i64..=6, 1..4),
            flip in proptest::bool::ANY,
        ) {
            let mut f: Vec<UPoly> = f.iter().map(|c| up(c)).collect();
            f.push(up(&[2, 0, 1]));
            let g = vec![up(&g), up(&g1)];
            proptest::prop_assume!(!g[1].is_zero());
            let (a, b) = if flip { (g, f) } else { (f, g) };
            proptest::prop_assert_eq!(resultant(&a, &b), resultant_direct(&a, &b));
        }
    }

    #[test]
    fn resultant_matches_sylvester() {
        // Res_z(z² − x, z − 1) = 1 − x.
        let f = vec![up(&[0, -1]), up(&[]), up(&[1])];
        let g = vec![up(&[-1]), up(&[1])];
        assert_eq!(resultant(&f, &g), up(&[1, -1]));
        // Res_z(x z + 1, z² + x) : roots z = −1/x: x·(1/x² + x)·... = 1 + x³.
        let f = vec![up(&[1]), up(&[0, 1])];
        let g = vec![up(&[0, 1]), up(&[]), up(&[1])];
        assert_eq!(resultant(&f, &g), up(&[1, 0, 0, 1]));
    }
}
