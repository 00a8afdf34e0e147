//! All of Z/p: Montgomery arithmetic modulo a prime below 2^62, the one
//! table of 62-bit primes (deterministic Miller–Rabin), Newton
//! interpolation, Garner's CRT, determinants, characteristic polynomials
//! and resultants of matrices and polynomials over F_p, and polynomial
//! arithmetic modulo primes near 2^20 (roots of x^p − x, coprimality). The
//! kernels of the modular routes in `univariate::modular` and
//! `multivariate::matrix::modular` (SymPy's `galoistools` plays this part
//! there).
//!
//! Values in Montgomery form (`a·2^64 mod p`) are marked as such; plain
//! residues are integers in `0..p`.

use std::sync::{Mutex, OnceLock};

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Arithmetic modulo an odd prime `p < 2^62`, on Montgomery residues
/// `a·2^64 mod p`.
#[derive(Clone, Copy)]
pub(crate) struct Zp {
    /// The prime.
    pub(crate) p: u64,
    /// `-p⁻¹ mod 2^64`.
    neg_inv: u64,
    /// `2^128 mod p`, which maps an integer into Montgomery form.
    r2: u64,
}

impl Zp {
    pub(crate) fn new(p: u64) -> Zp {
        debug_assert!(p % 2 == 1 && p < 1 << 62);
        // Newton's iteration doubles the correct low bits of p⁻¹ mod 2^64;
        // p is its own inverse mod 8, so five steps reach 96 bits.
        let mut inv = p;
        for _ in 0..5 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(p.wrapping_mul(inv)));
        }
        let r = ((1u128 << 64) % u128::from(p)) as u64;
        let r2 = ((u128::from(r) * u128::from(r)) % u128::from(p)) as u64;
        Zp { p, neg_inv: inv.wrapping_neg(), r2 }
    }

    /// `a·b·2^-64 mod p`: with `a, b < p < 2^62` the sum below stays under
    /// 2^127 and the result under 2p.
    #[inline]
    pub(crate) fn mul(self, a: u64, b: u64) -> u64 {
        let t = u128::from(a) * u128::from(b);
        let m = (t as u64).wrapping_mul(self.neg_inv);
        let u = ((t + u128::from(m) * u128::from(self.p)) >> 64) as u64;
        if u >= self.p {
            u - self.p
        } else {
            u
        }
    }

    #[inline]
    pub(crate) fn add(self, a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= self.p {
            s - self.p
        } else {
            s
        }
    }

    #[inline]
    pub(crate) fn sub(self, a: u64, b: u64) -> u64 {
        if a >= b {
            a - b
        } else {
            a + self.p - b
        }
    }

    pub(crate) fn neg(self, a: u64) -> u64 {
        if a == 0 {
            0
        } else {
            self.p - a
        }
    }

    /// The Montgomery form of a residue `a < p` (no reduction).
    #[inline]
    pub(crate) fn form(self, a: u64) -> u64 {
        self.mul(a, self.r2)
    }

    /// The Montgomery residue of an integer.
    pub(crate) fn lift(self, a: u64) -> u64 {
        self.mul(a % self.p, self.r2)
    }

    pub(crate) fn lift_big(self, x: &BigInt) -> u64 {
        let r = match x.to_i128() {
            Some(v) => v.rem_euclid(i128::from(self.p)) as u64,
            None => x.mod_floor(&BigInt::from(self.p)).to_u64().expect("a residue fits"),
        };
        self.lift(r)
    }

    /// The integer in `0..p` of a Montgomery residue.
    pub(crate) fn to_u64(self, a: u64) -> u64 {
        self.mul(a, 1)
    }

    pub(crate) fn one(self) -> u64 {
        self.lift(1)
    }

    /// `a^e` in Montgomery form, for `a` in Montgomery form.
    pub(crate) fn pow(self, mut a: u64, mut e: u64) -> u64 {
        let mut r = self.one();
        while e > 0 {
            if e & 1 == 1 {
                r = self.mul(r, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        r
    }

    /// The inverse of a nonzero residue (Fermat).
    pub(crate) fn inv(self, a: u64) -> u64 {
        debug_assert!(a != 0);
        self.pow(a, self.p - 2)
    }
}

/// `a·b mod p`, by one 128-bit remainder.
pub(crate) fn mulmod(a: u64, b: u64, p: u64) -> u64 {
    ((a as u128 * b as u128) % p as u128) as u64
}

/// `a^e mod p`, plain.
pub(crate) fn powmod(mut a: u64, mut e: u64, p: u64) -> u64 {
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

/// `a + b mod p` for `a, b < p`.
pub(crate) fn addmod(a: u64, b: u64, p: u64) -> u64 {
    let s = a + b;
    if s >= p {
        s - p
    } else {
        s
    }
}

/// `a − b mod p` for `a, b < p`.
pub(crate) fn submod(a: u64, b: u64, p: u64) -> u64 {
    if a >= b {
        a - b
    } else {
        a + p - b
    }
}

/// Deterministic Miller–Rabin for 64-bit integers (these bases suffice
/// below 3.3·10^24).
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
    let mulmod = |a: u64, b: u64| ((u128::from(a) * u128::from(b)) % u128::from(n)) as u64;
    let powmod = |mut a: u64, mut e: u64| {
        let mut r = 1u64;
        while e > 0 {
            if e & 1 == 1 {
                r = mulmod(r, a);
            }
            a = mulmod(a, a);
            e >>= 1;
        }
        r
    };
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'bases: for &b in &BASES {
        let mut x = powmod(b, d);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mulmod(x, x);
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// The first `count` primes below 2^62, largest first (cached: found once
/// per process).
pub(crate) fn primes(count: usize) -> Vec<u64> {
    static PRIMES: OnceLock<Mutex<Vec<u64>>> = OnceLock::new();
    let mut list =
        PRIMES.get_or_init(|| Mutex::new(Vec::new())).lock().unwrap_or_else(|e| e.into_inner());
    let mut candidate = list.last().map_or((1u64 << 62) - 1, |&p| p - 2);
    while list.len() < count {
        if is_prime(candidate) {
            list.push(candidate);
        }
        candidate -= 2;
    }
    list[..count].to_vec()
}

/// The residues of integer coefficients modulo `p`.
pub(crate) fn reduce(c: &[BigInt], p: u64) -> Vec<u64> {
    let pb = BigInt::from(p);
    c.iter().map(|x| x.mod_floor(&pb).to_u64().expect("reduced below p")).collect()
}

/// The value at `x` of a polynomial with plain residue coefficients,
/// lowest first: plain.
pub(crate) fn eval(c: &[u64], x: u64, mont: Zp) -> u64 {
    let xm = mont.form(x % mont.p);
    c.iter().rev().fold(0, |acc, &a| addmod(mont.mul(acc, xm), a, mont.p))
}

/// `1/d` in Montgomery form for `d = 0..=max` (0 at `d = 0`), by the
/// recurrence `1/d = −(p div d)·1/(p mod d)`: one table for every
/// difference of interpolation points.
pub(crate) fn inverse_table(f: Zp, max: usize) -> Vec<u64> {
    let p = f.p;
    let mut plain = vec![0u64; max + 1];
    if max >= 1 {
        plain[1] = 1;
    }
    for d in 2..=max {
        let q = p / d as u64;
        let r = (p % d as u64) as usize;
        plain[d] = (p - mulmod(q, plain[r], p)) % p;
    }
    plain.into_iter().map(|v| f.form(v)).collect()
}

/// Values at increasing small points `x(0) < x(1) < …` to the coefficients
/// of the interpolating polynomial, lowest first, in place: Newton's
/// divided differences, then the Newton form expanded. The values may be
/// plain residues or Montgomery forms; the coefficients come out in the same
/// representation. `inv` is [`inverse_table`] up to the largest difference
/// of two points.
pub(crate) fn interpolate(f: Zp, v: &mut [u64], x: impl Fn(usize) -> u64, inv: &[u64]) {
    let d = v.len();
    if d == 0 {
        return;
    }
    for j in 1..d {
        for i in (j..d).rev() {
            v[i] = f.mul(f.sub(v[i], v[i - 1]), inv[(x(i) - x(i - j)) as usize]);
        }
    }
    // p = c_{d-1}; p = p·(x − x_i) + c_i for i = d−2 down to 0.
    let newton: Vec<u64> = v.to_vec();
    v.fill(0);
    v[0] = newton[d - 1];
    for i in (0..d - 1).rev() {
        let xi = f.form(x(i) % f.p);
        // p·x − xi·p + c_i, highest first so each slot reads the old value.
        for k in (1..d).rev() {
            v[k] = f.sub(v[k - 1], f.mul(xi, v[k]));
        }
        v[0] = f.sub(newton[i], f.mul(xi, v[0]));
    }
}

/// Garner's mixed-radix reconstruction of integers from residues modulo
/// `primes`, in the symmetric range.
pub(crate) struct Crt {
    pub(crate) fields: Vec<Zp>,
    /// `(p_0 ⋯ p_{j−1})⁻¹ mod p_j`, Montgomery form in field j.
    inv_prefix: Vec<u64>,
    /// `p_i mod p_j` for i < j, Montgomery form in field j.
    p_mod: Vec<Vec<u64>>,
    primes: Vec<u64>,
    modulus: BigInt,
    half: BigInt,
}

impl Crt {
    pub(crate) fn new(primes: &[u64]) -> Crt {
        let fields: Vec<Zp> = primes.iter().map(|&p| Zp::new(p)).collect();
        let mut inv_prefix = Vec::new();
        let mut p_mod = Vec::new();
        for (j, &f) in fields.iter().enumerate() {
            let row: Vec<u64> = primes[..j].iter().map(|&p| f.lift(p)).collect();
            let prod = row.iter().fold(f.one(), |acc, &x| f.mul(acc, x));
            inv_prefix.push(f.inv(prod));
            p_mod.push(row);
        }
        let modulus = primes.iter().fold(BigInt::one(), |acc, &p| acc * p);
        let half = &modulus >> 1u32;
        Crt { fields, inv_prefix, p_mod, primes: primes.to_vec(), modulus, half }
    }

    /// The integer in `(-M/2, M/2]` with the given Montgomery residues.
    pub(crate) fn reconstruct(&self, residues: &[u64]) -> BigInt {
        let m = self.primes.len();
        let mut digits = Vec::with_capacity(m);
        for (j, &residue) in residues.iter().enumerate().take(m) {
            let f = self.fields[j];
            // (v_0 + v_1 p_0 + ... ) mod p_j, by Horner from the top digit.
            let mut acc = 0u64;
            for i in (0..j).rev() {
                acc = f.add(f.mul(acc, self.p_mod[j][i]), f.lift(digits[i]));
            }
            let v = f.mul(f.sub(residue, acc), self.inv_prefix[j]);
            digits.push(f.to_u64(v));
        }
        let mut x = BigInt::zero();
        for j in (0..m).rev() {
            x = x * self.primes[j] + digits[j];
        }
        if x > self.half {
            x -= &self.modulus;
        }
        x
    }

    /// The integer in `(-M/2, M/2]` with the given plain residues.
    pub(crate) fn reconstruct_plain(&self, residues: &[u64]) -> BigInt {
        let forms: Vec<u64> = residues.iter().zip(&self.fields).map(|(&r, f)| f.form(r)).collect();
        self.reconstruct(&forms)
    }
}

/// A value num/den modulo p, both parts in Montgomery form (den ≠ 0): a
/// kernel's result before its one division, so that all the values of one
/// prime share a single inversion (Montgomery's trick, [`Points`]).
#[derive(Clone, Copy)]
pub(crate) struct Frac {
    pub(crate) num: u64,
    pub(crate) den: u64,
}

impl Frac {
    pub(crate) fn zero(mont: Zp) -> Frac {
        Frac { num: 0, den: mont.form(1) }
    }
}

/// The determinant of an `n×n` matrix over `F_p` by Gaussian elimination
/// (destroys `a`).
pub(crate) fn det(f: Zp, a: &mut [u64], n: usize) -> u64 {
    let mut det = f.one();
    for c in 0..n {
        let Some(r) = (c..n).find(|&r| a[r * n + c] != 0) else {
            return 0;
        };
        if r != c {
            for j in c..n {
                a.swap(r * n + j, c * n + j);
            }
            det = f.neg(det);
        }
        let pivot = a[c * n + c];
        det = f.mul(det, pivot);
        let inv = f.inv(pivot);
        for r in c + 1..n {
            let x = a[r * n + c];
            if x == 0 {
                continue;
            }
            let factor = f.mul(x, inv);
            let (top, bottom) = a.split_at_mut(r * n);
            let pivot_row = &top[c * n + c + 1..c * n + n];
            for (y, &p) in bottom[c + 1..n].iter_mut().zip(pivot_row) {
                *y = f.sub(*y, f.mul(factor, p));
            }
        }
    }
    det
}

/// det(a) over F_p by fraction-free elimination: row_i ← a_kk·row_i −
/// a_ik·row_k scales the determinant by a_kk, gathered in a denominator
/// and returned with it (no inverse here: the caller divides all the values
/// of a prime at once). Values in Montgomery form.
pub(crate) fn det_frac(a: &mut [Vec<u64>], mont: Zp) -> Frac {
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

/// Buffers reused across the grid points of one characteristic polynomial.
pub(crate) struct Scratch {
    polys: Vec<Vec<u64>>,
}

impl Scratch {
    pub(crate) fn new(n: usize) -> Scratch {
        Scratch { polys: (0..=n).map(|m| vec![0; m + 1]).collect() }
    }
}

/// `[c_0 = 1, c_1, ..., c_n]` of `det(xI − A) = Σ c_k x^(n−k)` over `F_p`:
/// Hessenberg reduction by similarity, then the three-term-like recurrence
/// on the leading principal blocks (destroys `a`).
pub(crate) fn charpoly(f: Zp, h: &mut [u64], n: usize, scratch: &mut Scratch) -> Vec<u64> {
    for m in 1..n.saturating_sub(1) {
        let Some(i) = (m..n).find(|&i| h[i * n + m - 1] != 0) else {
            continue;
        };
        if i != m {
            for j in 0..n {
                h.swap(i * n + j, m * n + j);
            }
            for j in 0..n {
                h.swap(j * n + i, j * n + m);
            }
        }
        let inv = f.inv(h[m * n + m - 1]);
        for i in m + 1..n {
            let u = f.mul(h[i * n + m - 1], inv);
            if u == 0 {
                continue;
            }
            // Row i −= u·row m, then column m += u·column i.
            for j in m - 1..n {
                h[i * n + j] = f.sub(h[i * n + j], f.mul(u, h[m * n + j]));
            }
            for j in 0..n {
                h[j * n + m] = f.add(h[j * n + m], f.mul(u, h[j * n + i]));
            }
        }
    }
    // p_m = (x − h_mm) p_{m−1} − Σ_{i<m} h_im (∏_{j=i+1}^{m} h_{j,j−1}) p_{i−1},
    // 1-based; p_m is stored lowest power first.
    let p = &mut scratch.polys;
    p[0][0] = f.one();
    for m in 1..=n {
        let (done, rest) = p.split_at_mut(m);
        let pm = &mut rest[0];
        let prev = &done[m - 1];
        let d = h[(m - 1) * n + m - 1];
        pm[0] = f.neg(f.mul(d, prev[0]));
        for k in 1..m {
            pm[k] = f.sub(prev[k - 1], f.mul(d, prev[k]));
        }
        pm[m] = prev[m - 1];
        let mut t = f.one();
        for i in (1..m).rev() {
            t = f.mul(t, h[i * n + i - 1]);
            if t == 0 {
                break;
            }
            let coef = f.mul(h[(i - 1) * n + m - 1], t);
            if coef == 0 {
                continue;
            }
            for (k, &x) in done[i - 1].iter().enumerate() {
                pm[k] = f.sub(pm[k], f.mul(coef, x));
            }
        }
    }
    // c_k is the coefficient of x^(n−k).
    p[n].iter().rev().copied().collect()
}

/// The coefficient matrices of w⁰ and w¹ of a pencil, from the dense
/// per-entry coefficients in w (`width` = 1 or 2 per entry).
pub(crate) fn split_pencil(dense: &[u64], width: usize, n: usize) -> (Vec<u64>, Vec<u64>) {
    let b0 = (0..n * n).map(|s| dense[s * width]).collect();
    let b1 = (0..n * n).map(|s| if width > 1 { dense[s * width + 1] } else { 0 }).collect();
    (b0, b1)
}

/// The coefficients in w, lowest first, of det(B₀ + w·B₁) over `F_p`, or
/// `None` when B₀ is singular. With C = −B₀⁻¹B₁,
/// det(B₀ + wB₁) = det B₀ · det(I − wC) = det B₀ · Σ_k c_k(C) w^k, where
/// det(xI − C) = Σ c_k x^(n−k): one elimination and one Hessenberg reduction
/// instead of `n + 1` eliminations at points in w.
pub(crate) fn pencil(
    f: Zp,
    mut b0: Vec<u64>,
    mut b1: Vec<u64>,
    n: usize,
    scratch: &mut Scratch,
) -> Option<Vec<u64>> {
    // Gauss–Jordan on [B₀ | B₁]: B₀ to I, B₁ to B₀⁻¹B₁.
    let mut det = f.one();
    for c in 0..n {
        let r = (c..n).find(|&r| b0[r * n + c] != 0)?;
        if r != c {
            for j in 0..n {
                b0.swap(r * n + j, c * n + j);
                b1.swap(r * n + j, c * n + j);
            }
            det = f.neg(det);
        }
        let pivot = b0[c * n + c];
        det = f.mul(det, pivot);
        let inv = f.inv(pivot);
        for j in 0..n {
            b0[c * n + j] = f.mul(b0[c * n + j], inv);
            b1[c * n + j] = f.mul(b1[c * n + j], inv);
        }
        for r in 0..n {
            let x = b0[r * n + c];
            if r == c || x == 0 {
                continue;
            }
            for j in c..n {
                b0[r * n + j] = f.sub(b0[r * n + j], f.mul(x, b0[c * n + j]));
            }
            for j in 0..n {
                b1[r * n + j] = f.sub(b1[r * n + j], f.mul(x, b1[c * n + j]));
            }
        }
    }
    for x in &mut b1 {
        *x = f.neg(*x);
    }
    let c = charpoly(f, &mut b1, n, scratch);
    Some(c.into_iter().map(|x| f.mul(x, det)).collect())
}

/// Drops trailing zero coefficients.
pub(crate) fn trim(v: &mut Vec<u64>) {
    while v.last() == Some(&0) {
        v.pop();
    }
}

/// Res(f, g) over F_p by Euclid's algorithm (actual degrees), with
/// pseudo-remainders: R = lc(g)^e·(f mod g) needs no inverse, and
/// Res(g, R) = lc(g)^{e·deg g}·Res(g, f mod g), so the scale factors are
/// gathered in a denominator and returned with it (an inverse costs about
/// as much as the whole elimination of a step; the caller does one per
/// prime). Values are kept in Montgomery form throughout.
pub(crate) fn res_frac(mut f: Vec<u64>, mut g: Vec<u64>, mont: Zp) -> Frac {
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
            num = mont.mul(num, mont.pow(g[0], m as u64));
            break;
        }
        if m == 0 {
            num = mont.mul(num, mont.pow(f[0], n as u64));
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
        num = mont.mul(num, mont.pow(lg, (m - k) as u64));
        den = mont.mul(den, mont.pow(lg, e * n as u64));
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
        let mont = Zp::new(p);
        return res_frac(reduce(a, p), reduce(b, p), mont).num != 0;
    }
    false
}

/// The monic gcd over F_p of two polynomials of plain residues (lowest
/// first), as plain residues; empty when both are zero.
fn gcd_mod(a: &[u64], b: &[u64], f: Zp) -> Vec<u64> {
    let mut a: Vec<u64> = a.iter().map(|&x| f.form(x)).collect();
    let mut b: Vec<u64> = b.iter().map(|&x| f.form(x)).collect();
    trim(&mut a);
    trim(&mut b);
    while !b.is_empty() {
        // a ← a mod b.
        let n = b.len() - 1;
        let inv = f.inv(b[n]);
        while a.len() > n {
            let k = a.len() - 1 - n;
            let c = f.mul(a[a.len() - 1], inv);
            if c != 0 {
                for (j, &bj) in b.iter().enumerate() {
                    a[k + j] = f.sub(a[k + j], f.mul(c, bj));
                }
            }
            a.pop();
            trim(&mut a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    if let Some(&lead) = a.last() {
        let inv = f.inv(lead);
        for x in &mut a {
            *x = f.to_u64(f.mul(*x, inv));
        }
    }
    a
}

/// Whether `g` divides `a` in Z[x] (both lowest first, non-zero leading
/// coefficients), by long division that fails at the first inexact
/// quotient.
fn divides_int(a: &[BigInt], g: &[BigInt]) -> bool {
    let n = g.len() - 1;
    let lg = &g[n];
    let mut r = a.to_vec();
    while r.len() > n {
        let top = r.len() - 1;
        let (c, rem) = r[top].div_rem(lg);
        if !rem.is_zero() {
            return false;
        }
        let k = top - n;
        for (j, gj) in g.iter().enumerate() {
            r[k + j] -= &c * gj;
        }
        debug_assert!(r[top].is_zero());
        r.pop();
        while r.last().is_some_and(Zero::is_zero) {
            r.pop();
        }
    }
    r.is_empty()
}

/// The gcd in Z[x] of two non-zero integer polynomials (lowest first,
/// non-zero leading coefficients), primitive with a positive leading
/// coefficient, by Brown's modular algorithm: the monic gcd modulo primes
/// dividing neither leading coefficient, the smallest degree kept (a larger
/// one is an unlucky prime), scaled by gcd(lc(a), lc(b)) and joined by CRT
/// until two reconstructions agree; the primitive part is then proven by
/// dividing both. `None` when 200 primes do not settle it (the caller runs
/// its remainder sequence). The primitive remainder sequence of big
/// coefficients costs a pass over numbers of thousands of bits per step;
/// here each prime costs a Euclid over machine words.
pub(crate) fn gcd_int(a: &[BigInt], b: &[BigInt]) -> Option<Vec<BigInt>> {
    let (la, lb) = (a.last()?, b.last()?);
    if la.is_zero() || lb.is_zero() {
        return None;
    }
    let scale = crate::arith::intgcd::gcd(la, lb);
    let mut deg = usize::MAX;
    let mut used: Vec<u64> = Vec::new();
    let mut residues: Vec<Vec<u64>> = Vec::new();
    let mut previous: Option<Vec<BigInt>> = None;
    // Primes in batches: most gcds settle within a few.
    let batches = [8usize, 32, 200];
    let mut tried = 0;
    for p in batches.iter().flat_map(|&k| {
        let batch = primes(k)[tried..].to_vec();
        tried = k;
        batch
    }) {
        let pb = BigInt::from(p);
        if (la % &pb).is_zero() || (lb % &pb).is_zero() {
            continue;
        }
        let f = Zp::new(p);
        let h = gcd_mod(&reduce(a, p), &reduce(b, p), f);
        let d = h.len() - 1;
        if d == 0 {
            return Some(vec![BigInt::one()]);
        }
        if d > deg {
            continue;
        }
        if d < deg {
            deg = d;
            used.clear();
            residues.clear();
            previous = None;
        }
        let s = f.lift_big(&scale);
        used.push(p);
        residues.push(h.iter().map(|&x| f.to_u64(f.mul(f.form(x), s))).collect());
        let crt = Crt::new(&used);
        let candidate: Vec<BigInt> = (0..=d)
            .map(|i| crt.reconstruct_plain(&residues.iter().map(|r| r[i]).collect::<Vec<_>>()))
            .collect();
        if previous.as_ref() == Some(&candidate) {
            let content = candidate
                .iter()
                .filter(|x| !x.is_zero())
                .fold(BigInt::zero(), |g, x| crate::arith::intgcd::gcd(&g, x));
            let mut g: Vec<BigInt> = candidate.iter().map(|x| x / &content).collect();
            if g[d].is_negative() {
                g = g.into_iter().map(|x| -x).collect();
            }
            if divides_int(a, &g) && divides_int(b, &g) {
                return Some(g);
            }
        }
        previous = Some(candidate);
    }
    None
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

#[cfg(test)]
mod tests {
    //! The field, the primes, interpolation and the small-prime polynomial
    //! kernels on their own, against obvious oracles; the determinants and
    //! resultants against Laplace and Sylvester are tested where they are
    //! lifted to polynomials.

    use super::*;

    #[test]
    fn montgomery_arithmetic_matches_u128_arithmetic() {
        for &p in &primes(3) {
            let f = Zp::new(p);
            for (a, b) in
                [(0u64, 5u64), (1, 1), (p - 1, p - 1), (123_456_789, p - 2), (p / 3, p / 2)]
            {
                let want = ((u128::from(a) * u128::from(b)) % u128::from(p)) as u64;
                assert_eq!(f.to_u64(f.mul(f.lift(a), f.lift(b))), want);
                assert_eq!(
                    f.to_u64(f.add(f.lift(a), f.lift(b))),
                    ((u128::from(a) + u128::from(b)) % u128::from(p)) as u64
                );
            }
            let x = f.lift(987_654_321);
            assert_eq!(f.to_u64(f.mul(x, f.inv(x))), 1);
        }
    }

    #[test]
    fn primes_are_prime_and_descending() {
        let ps = primes(4);
        assert!(ps.windows(2).all(|w| w[0] > w[1]));
        for &p in &ps {
            assert!(p < 1 << 62 && p > 1 << 61);
            // Trial division by small odd numbers as a sanity oracle.
            assert!((3..2000u64).step_by(2).all(|d| p % d != 0));
        }
        assert!(is_prime(2_305_843_009_213_693_951)); // 2^61 − 1
        assert!(!is_prime(2_305_843_009_213_693_953));
        assert!(!is_prime(3_215_031_751)); // a strong pseudoprime to 2, 3, 5, 7
    }

    #[test]
    fn interpolation_inverts_evaluation() {
        let f = Zp::new(primes(1)[0]);
        let coeffs: Vec<u64> = [5u64, 0, 7, 1, 3].iter().map(|&c| f.lift(c)).collect();
        let mut values: Vec<u64> = (0..coeffs.len() as u64)
            .map(|x| {
                let xm = f.lift(x);
                coeffs.iter().rev().fold(0, |acc, &c| f.add(f.mul(acc, xm), c))
            })
            .collect();
        interpolate(f, &mut values, |i| i as u64, &inverse_table(f, 5));
        assert_eq!(values, coeffs);
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
                assert_eq!(small::roots_part(&f, p).len() - 1, brute, "{f:?} mod {p}");
            }
        }
    }

    #[test]
    fn fast_field_operations_match_the_obvious_ones() {
        // Oracles: Fermat's inverse a^(p−2) and the 128-bit remainder.
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for p in primes(3) {
            let mont = Zp::new(p);
            for _ in 0..200 {
                x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                let a = x % p;
                let b = x.rotate_left(17) % p;
                assert_eq!(mont.mul(a, mont.form(b)), mulmod(a, b, p));
                if a != 0 {
                    assert_eq!(mulmod(mont.to_u64(mont.inv(mont.form(a))), a, p), 1);
                }
                assert_eq!(mont.to_u64(mont.pow(mont.form(a), b % 1000)), powmod(a, b % 1000, p));
                assert_eq!(addmod(a, b, p), ((a as u128 + b as u128) % p as u128) as u64);
                assert_eq!(
                    submod(a, b, p),
                    ((a as u128 + p as u128 - b as u128) % p as u128) as u64
                );
            }
        }
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
}
