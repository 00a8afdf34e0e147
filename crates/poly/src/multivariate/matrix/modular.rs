//! Determinants and characteristic polynomials of polynomial matrices by
//! evaluation, interpolation and Chinese remaindering.
//!
//! The sparse multivariate Berkowitz of [`super`] multiplies canonical
//! polynomials with rational coefficients at every step; on a 16×16 matrix
//! in two symbols that is seconds. This path never forms an intermediate
//! polynomial:
//!
//! 1. **Clear denominators.** For a determinant, row `i` is multiplied by the
//!    lcm `L_i` of its denominators, so `det A = det B / ∏ L_i` with `B`
//!    integral. For a characteristic polynomial the whole matrix is scaled
//!    by one `L` (a similarity-invariant scaling): `c_k(A) = c_k(LA) / L^k`.
//! 2. **Bound the answer.** Every coefficient of `det B` is at most
//!    `∏_i H_i`, `H_i² = Σ_j ‖B_ij‖₁²` (Hadamard's inequality on the torus
//!    |x_v| = 1, where each entry is at most its coefficients' 1-norm, and a
//!    coefficient is at most the maximum of the polynomial on the torus). A
//!    coefficient of `c_k(B)`, a sum of `C(n, k) ≤ 2^n` principal minors, is
//!    at most `2^n ∏_i max(1, H_i)`. The degree in each symbol `v` is at most
//!    the sum over rows (or columns) of the largest degree in `v`.
//! 3. **Compute modulo primes.** For enough primes `p < 2^62` (their
//!    product above twice the bound), evaluate `B` on a grid of
//!    `deg_v + 1` points per symbol, take the determinant (Gaussian
//!    elimination) or the characteristic polynomial (Hessenberg reduction)
//!    of each scalar matrix over `F_p`, and interpolate the grid back to
//!    coefficients (Newton's divided differences, one symbol at a time).
//! 4. **Reconstruct.** Each integer coefficient is the symmetric residue of
//!    Garner's mixed-radix CRT; dividing by `∏ L_i` or `L^k` gives the
//!    rational coefficient.
//!
//! Every step is exact (a field is a field whichever prime), so no prime is
//! unlucky and the result is the sparse path's, which the tests check.

use std::collections::BTreeSet;
use std::sync::{Mutex, OnceLock};

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

use super::PolyMatrix;
use crate::{Monomial, Poly, Sym, Q};

/// The largest evaluation grid attempted (points per prime); beyond it the
/// caller falls back to the sparse path.
const MAX_GRID: usize = 1 << 22;

/// Arithmetic modulo an odd prime `p < 2^62`, on Montgomery residues
/// `a·2^64 mod p`.
#[derive(Clone, Copy)]
pub(crate) struct Field {
    p: u64,
    /// `-p⁻¹ mod 2^64`.
    neg_inv: u64,
    /// `2^128 mod p`, which maps an integer into Montgomery form.
    r2: u64,
}

impl Field {
    pub(crate) fn new(p: u64) -> Field {
        debug_assert!(p % 2 == 1 && p < 1 << 62);
        // Newton's iteration doubles the correct low bits of p⁻¹ mod 2^64;
        // p is its own inverse mod 8, so five steps reach 96 bits.
        let mut inv = p;
        for _ in 0..5 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(p.wrapping_mul(inv)));
        }
        let r = ((1u128 << 64) % u128::from(p)) as u64;
        let r2 = ((u128::from(r) * u128::from(r)) % u128::from(p)) as u64;
        Field { p, neg_inv: inv.wrapping_neg(), r2 }
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

    /// The Montgomery residue of an integer.
    pub(crate) fn lift(self, a: u64) -> u64 {
        self.mul(a % self.p, self.r2)
    }

    fn lift_big(self, x: &BigInt) -> u64 {
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

    fn pow(self, mut a: u64, mut e: u64) -> u64 {
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

/// Each prime contributes at least this many bits to the CRT modulus.
const BITS_PER_PRIME: u64 = 61;

/// An integral polynomial entry: `(exponent per symbol, coefficient)`.
type Entry = Vec<(Vec<u32>, BigInt)>;

/// A matrix with integer polynomial entries over `vars`, ready to be
/// evaluated modulo primes.
struct Integral {
    n: usize,
    vars: Vec<Sym>,
    /// Per symbol, 2 when the entries were rewritten in its square (see
    /// [`halve`]), else 1: exponent `e` of the result stands for `spread·e`.
    spread: Vec<u32>,
    entries: Vec<Entry>,
    /// Per symbol, the largest exponent in any entry.
    max_exp: Vec<u32>,
    /// Per symbol, a bound on the degree of the result.
    degree: Vec<usize>,
    /// Bits of a bound on the absolute value of every result coefficient.
    bits: u64,
}

/// The symbols of a matrix, the one of lowest entry degree last (it is
/// evaluated innermost, by Horner), or `last` when given.
fn symbols(a: &PolyMatrix, last: Option<Sym>) -> Vec<Sym> {
    let set: BTreeSet<Sym> = a.data.iter().flat_map(|e| e.symbols()).collect();
    let mut vars: Vec<Sym> = set.into_iter().filter(|&s| Some(s) != last).collect();
    let max_deg = |s: Sym| a.data.iter().map(|e| e.degree_in(s)).max().unwrap_or(0);
    vars.sort_by_key(|&s| std::cmp::Reverse(max_deg(s)));
    vars.extend(last);
    vars
}

/// `a` with row `i` scaled by `scale[i]`, as integer entries, and the
/// bounds of the module docs. `per_minor` adds the `2^n` of a sum over
/// principal minors. Every symbol but `keep` is halved where it can be.
fn integral(a: &PolyMatrix, scale: &[BigInt], per_minor: bool, keep: Option<Sym>) -> Integral {
    let n = a.rows;
    let vars = symbols(a, keep);
    let mut entries = Vec::with_capacity(n * n);
    let mut bits = 2u64;
    for i in 0..n {
        let mut h2 = BigInt::zero();
        for j in 0..n {
            let mut entry: Entry = Vec::new();
            let mut norm = BigInt::zero();
            for (m, c) in a[(i, j)].terms() {
                let exps: Vec<u32> = vars.iter().map(|&s| m.exponent(s)).collect();
                let x = c.numer() * (&scale[i] / c.denom());
                norm += x.abs();
                entry.push((exps, x));
            }
            h2 += &norm * &norm;
            entries.push(entry);
        }
        // H_i ≤ 2^ceil(bits(H_i²)/2); rows with H_i < 1 add nothing.
        bits += h2.bits().div_ceil(2);
    }
    if per_minor {
        bits += n as u64;
    }
    let spread = (0..vars.len())
        .map(|v| if Some(vars[v]) != keep && halve(n, &mut entries, v) { 2 } else { 1 })
        .collect();
    let mut max_exp = vec![0u32; vars.len()];
    let mut row_deg = vec![vec![0usize; n]; vars.len()];
    let mut col_deg = vec![vec![0usize; n]; vars.len()];
    for (slot, entry) in entries.iter().enumerate() {
        let (i, j) = (slot / n, slot % n);
        for (exps, _) in entry {
            for (v, &e) in exps.iter().enumerate() {
                max_exp[v] = max_exp[v].max(e);
                row_deg[v][i] = row_deg[v][i].max(e as usize);
                col_deg[v][j] = col_deg[v][j].max(e as usize);
            }
        }
    }
    let degree = (0..vars.len())
        .map(|v| row_deg[v].iter().sum::<usize>().min(col_deg[v].iter().sum()))
        .collect();
    Integral { n, vars, spread, entries, max_exp, degree, bits }
}

/// The parity reduction in symbol `v`, in place; false (and nothing
/// changed) when it does not apply or gains nothing.
///
/// When a diagonal similarity `D = diag(x^s_i)`, `s_i ∈ {0, 1}`, turns `A`
/// into `B = D⁻¹AD` with only even powers of `x`, then `B(x) = C(x²)`, and
/// `det A = det B` and `det(yI − A) = det(yI − B)` are those of `C` with
/// `x²` for its symbol: the same answer from entries of half the degree.
/// Such an `s` exists exactly when every entry's exponents of `x` share one
/// parity `p_ij` and `s_i + s_j ≡ p_ij (mod 2)` is solvable, which is the
/// shape of mechanical systems in Phi (positions even, velocities odd).
fn halve(n: usize, entries: &mut [Entry], v: usize) -> bool {
    let mut parity = vec![None; n * n];
    let mut top = 0;
    for (slot, entry) in entries.iter().enumerate() {
        let mut exps = entry.iter().map(|(e, _)| e[v]);
        if let Some(first) = exps.next() {
            top = top.max(first);
            for e in exps {
                if e % 2 != first % 2 {
                    return false;
                }
                top = top.max(e);
            }
            parity[slot] = Some(first % 2);
        }
    }
    if top < 2 {
        return false;
    }
    // Solve s_i + s_j ≡ p_ij over each connected component, from s = 0 at
    // its first index.
    let mut shift: Vec<Option<u32>> = vec![None; n];
    let mut stack = Vec::new();
    for root in 0..n {
        if shift[root].is_some() {
            continue;
        }
        shift[root] = Some(0);
        stack.push(root);
        while let Some(i) = stack.pop() {
            let si = shift[i].unwrap_or(0);
            for j in 0..n {
                for p in [parity[i * n + j], parity[j * n + i]].into_iter().flatten() {
                    let want = (p + si) % 2;
                    match shift[j] {
                        None => {
                            shift[j] = Some(want);
                            stack.push(j);
                        }
                        Some(sj) if sj != want => return false,
                        Some(_) => {}
                    }
                }
            }
        }
    }
    // Entry (i, j) of B is x^(s_j − s_i) A_ij, whose exponents are even and
    // non-negative (s_i = 1, s_j = 0 forces odd exponents, so ≥ 1).
    for (slot, entry) in entries.iter_mut().enumerate() {
        let (si, sj) = (shift[slot / n].unwrap_or(0), shift[slot % n].unwrap_or(0));
        for (exps, _) in entry {
            exps[v] = (exps[v] + sj - si) / 2;
        }
    }
    true
}

/// The lcm of the denominators of some polynomials.
fn denominator_lcm<'a>(polys: impl Iterator<Item = &'a Poly>) -> BigInt {
    let mut l = BigInt::one();
    for p in polys {
        for (_, c) in p.terms() {
            if !(&l % c.denom()).is_zero() {
                l = l.lcm(c.denom());
            }
        }
    }
    l
}

/// What is computed at each grid point.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Job {
    /// det B: one value per point.
    Det,
    /// det(xI − B): `n + 1` values per point, `c_0..c_n`.
    Charpoly,
    /// det B where B = B₀ + w·B₁ is linear in its innermost symbol w: at
    /// each point of the other symbols, the coefficients in w at once (see
    /// [`pencil_mod`]) instead of values at `deg_w + 1` points.
    Pencil,
}

/// Residues, per prime, of the result's integer coefficients: slot
/// `k * grid + idx` is coefficient `k` (0 for a determinant) of the
/// monomial with exponents given by the mixed-radix digits of `idx`.
fn residues(b: &Integral, job: Job, f: Field) -> Vec<u64> {
    let n = b.n;
    let nv = b.vars.len();
    let sizes: Vec<usize> = b.degree.iter().map(|d| d + 1).collect();
    let grid: usize = sizes.iter().product();
    let outputs = match job {
        Job::Det | Job::Pencil => 1,
        Job::Charpoly => n + 1,
    };
    let mut out = vec![0u64; outputs * grid];
    // The entries' coefficients modulo p.
    let coeffs: Vec<Vec<u64>> =
        b.entries.iter().map(|e| e.iter().map(|(_, c)| f.lift_big(c)).collect()).collect();
    // Powers of each grid coordinate: pow[v][(point, e)].
    let pow: Vec<Vec<u64>> = (0..nv)
        .map(|v| {
            let w = b.max_exp[v] as usize + 1;
            let mut t = vec![0u64; sizes[v] * w];
            for x in 0..sizes[v] {
                let xm = f.lift(x as u64);
                let mut acc = f.one();
                for e in 0..w {
                    t[x * w + e] = acc;
                    acc = f.mul(acc, xm);
                }
            }
            t
        })
        .collect();
    let inverses: Vec<u64> = (0..=sizes.iter().copied().max().unwrap_or(1))
        .map(|k| if k == 0 { 0 } else { f.inv(f.lift(k as u64)) })
        .collect();
    // The innermost symbol is evaluated by Horner on each entry's dense
    // coefficients in it; the others once per outer point.
    let inner = nv.checked_sub(1);
    let inner_width = inner.map_or(1, |v| b.max_exp[v] as usize + 1);
    let inner_size = inner.map_or(1, |v| sizes[v]);
    let mut dense = vec![0u64; n * n * inner_width];
    let mut mat = vec![0u64; n * n];
    let mut digits = vec![0usize; nv];
    let mut scratch = Scratch::new(n);
    for outer in 0..grid / inner_size {
        // Mixed-radix digits of the outer point (all symbols but the last).
        let mut rest = outer;
        for v in (0..nv.saturating_sub(1)).rev() {
            digits[v] = rest % sizes[v];
            rest /= sizes[v];
        }
        dense.fill(0);
        for (slot, entry) in b.entries.iter().enumerate() {
            for ((exps, _), &c) in entry.iter().zip(&coeffs[slot]) {
                let mut x = c;
                for v in 0..nv.saturating_sub(1) {
                    let w = b.max_exp[v] as usize + 1;
                    x = f.mul(x, pow[v][digits[v] * w + exps[v] as usize]);
                }
                let k = inner.map_or(0, |v| exps[v] as usize);
                let d = &mut dense[slot * inner_width + k];
                *d = f.add(*d, x);
            }
        }
        let base = outer * inner_size;
        if job == Job::Pencil {
            let (b0, b1) = split_pencil(&dense, inner_width, n);
            if let Some(c) = pencil_mod(f, b0, b1, n, &mut scratch) {
                for (k, &x) in c.iter().enumerate() {
                    if k < inner_size {
                        out[base + k] = x;
                    } else {
                        debug_assert_eq!(x, 0, "degree in w above its bound");
                    }
                }
                continue;
            }
        }
        for point in 0..inner_size {
            let xm = inner.map_or(0, |_| f.lift(point as u64));
            for (slot, m) in mat.iter_mut().enumerate() {
                let cs = &dense[slot * inner_width..(slot + 1) * inner_width];
                let mut acc = 0;
                for &c in cs.iter().rev() {
                    acc = f.add(f.mul(acc, xm), c);
                }
                *m = acc;
            }
            let idx = base + point;
            match job {
                Job::Det | Job::Pencil => out[idx] = det_mod(f, &mut mat, n),
                Job::Charpoly => {
                    let c = charpoly_mod(f, &mut mat, n, &mut scratch);
                    for (k, &x) in c.iter().enumerate() {
                        out[k * grid + idx] = x;
                    }
                }
            }
        }
        if job == Job::Pencil {
            // This outer point fell back to values in w: interpolate them
            // now, since the pass below skips the w axis.
            interpolate(f, &mut out[base..base + inner_size], &inverses);
        }
    }
    // Values on the grid to coefficients, one symbol at a time.
    let axes = match job {
        Job::Pencil => nv - 1,
        Job::Det | Job::Charpoly => nv,
    };
    let mut line = Vec::new();
    for block in out.chunks_mut(grid) {
        let mut stride = grid;
        for &size in &sizes[..axes] {
            stride /= size;
            // Lines along this symbol: `stride` apart, `size` long.
            for start in 0..grid {
                if !(start / stride).is_multiple_of(size) {
                    continue;
                }
                line.clear();
                line.extend((0..size).map(|t| block[start + t * stride]));
                interpolate(f, &mut line, &inverses);
                for (t, &x) in line.iter().enumerate() {
                    block[start + t * stride] = x;
                }
            }
        }
    }
    out
}

/// The coefficient matrices of w⁰ and w¹ of a pencil, from the dense
/// per-entry coefficients in w (`width` = 1 or 2 per entry).
fn split_pencil(dense: &[u64], width: usize, n: usize) -> (Vec<u64>, Vec<u64>) {
    let b0 = (0..n * n).map(|s| dense[s * width]).collect();
    let b1 = (0..n * n).map(|s| if width > 1 { dense[s * width + 1] } else { 0 }).collect();
    (b0, b1)
}

/// The coefficients in w, lowest first, of det(B₀ + w·B₁) over `F_p`, or
/// `None` when B₀ is singular. With C = −B₀⁻¹B₁,
/// det(B₀ + wB₁) = det B₀ · det(I − wC) = det B₀ · Σ_k c_k(C) w^k, where
/// det(xI − C) = Σ c_k x^(n−k): one elimination and one Hessenberg reduction
/// instead of `n + 1` eliminations at points in w.
fn pencil_mod(
    f: Field,
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
    let c = charpoly_mod(f, &mut b1, n, scratch);
    Some(c.into_iter().map(|x| f.mul(x, det)).collect())
}

/// Values at the points 0, 1, ..., len−1 to coefficients, lowest first, in
/// place: Newton's divided differences, then the Newton form expanded.
fn interpolate(f: Field, v: &mut [u64], inverses: &[u64]) {
    let d = v.len();
    for (j, &inv) in inverses.iter().enumerate().take(d).skip(1) {
        for i in (j..d).rev() {
            v[i] = f.mul(f.sub(v[i], v[i - 1]), inv);
        }
    }
    // p = c_{d-1}; p = p·(x − (i)) + c_i for i = d−2 down to 0.
    let newton: Vec<u64> = v.to_vec();
    v.fill(0);
    v[0] = newton[d - 1];
    for i in (0..d - 1).rev() {
        let xi = f.lift(i as u64);
        // p·x − xi·p + c_i, highest first so each slot reads the old value.
        for k in (1..d).rev() {
            v[k] = f.sub(v[k - 1], f.mul(xi, v[k]));
        }
        v[0] = f.sub(newton[i], f.mul(xi, v[0]));
    }
}

/// The determinant of an `n×n` matrix over `F_p` by Gaussian elimination
/// (destroys `a`).
fn det_mod(f: Field, a: &mut [u64], n: usize) -> u64 {
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

/// Buffers reused across the grid points of one characteristic polynomial.
struct Scratch {
    polys: Vec<Vec<u64>>,
}

impl Scratch {
    fn new(n: usize) -> Scratch {
        Scratch { polys: (0..=n).map(|m| vec![0; m + 1]).collect() }
    }
}

/// `[c_0 = 1, c_1, ..., c_n]` of `det(xI − A) = Σ c_k x^(n−k)` over `F_p`:
/// Hessenberg reduction by similarity, then the three-term-like recurrence
/// on the leading principal blocks (destroys `a`).
fn charpoly_mod(f: Field, h: &mut [u64], n: usize, scratch: &mut Scratch) -> Vec<u64> {
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

/// Garner's mixed-radix reconstruction of integers from residues modulo
/// `primes`, in the symmetric range.
struct Crt {
    fields: Vec<Field>,
    /// `(p_0 ⋯ p_{j−1})⁻¹ mod p_j`, Montgomery form in field j.
    inv_prefix: Vec<u64>,
    /// `p_i mod p_j` for i < j, Montgomery form in field j.
    p_mod: Vec<Vec<u64>>,
    primes: Vec<u64>,
    modulus: BigInt,
    half: BigInt,
}

impl Crt {
    fn new(primes: &[u64]) -> Crt {
        let fields: Vec<Field> = primes.iter().map(|&p| Field::new(p)).collect();
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
    fn reconstruct(&self, residues: &[u64]) -> BigInt {
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
}

/// Runs `job` on the integral matrix and returns the integer coefficients
/// per output and grid index (`None` entries are zero).
fn solve(b: &Integral, job: Job) -> Option<Vec<Option<BigInt>>> {
    let grid = b.degree.iter().try_fold(1usize, |g, &d| g.checked_mul(d + 1))?;
    if grid > MAX_GRID {
        return None;
    }
    let count = (b.bits + 1).div_ceil(BITS_PER_PRIME) as usize;
    let primes = primes(count);
    let crt = Crt::new(&primes);
    let per_prime: Vec<Vec<u64>> = crt.fields.iter().map(|&f| residues(b, job, f)).collect();
    let len = per_prime[0].len();
    let mut r = vec![0u64; primes.len()];
    Some(
        (0..len)
            .map(|slot| {
                for (x, res) in r.iter_mut().zip(&per_prime) {
                    *x = res[slot];
                }
                if r.iter().all(|&x| x == 0) {
                    None
                } else {
                    Some(crt.reconstruct(&r)).filter(|x| !x.is_zero())
                }
            })
            .collect(),
    )
}

/// The polynomial with integer coefficients `ints` on the grid of `b`,
/// each divided by `den`.
fn to_poly(b: &Integral, ints: &[Option<BigInt>], den: &BigInt) -> Poly {
    let sizes: Vec<usize> = b.degree.iter().map(|d| d + 1).collect();
    Poly::from_terms(ints.iter().enumerate().filter_map(|(idx, c)| {
        let c = c.as_ref()?;
        let mut rest = idx;
        let mut factors = Vec::with_capacity(b.vars.len());
        for v in (0..b.vars.len()).rev() {
            factors.push((b.vars[v], b.spread[v] * (rest % sizes[v]) as u32));
            rest /= sizes[v];
        }
        Some((Q::new(c.clone(), den.clone()), Monomial::from_factors(factors)))
    }))
}

/// `det a`, or `None` when the grid would be too large.
pub(crate) fn det(a: &PolyMatrix) -> Option<Poly> {
    let n = a.rows;
    if n == 0 {
        return Some(Poly::one());
    }
    let scale: Vec<BigInt> = (0..n).map(|i| denominator_lcm(a.row(i).iter())).collect();
    let b = integral(a, &scale, false, None);
    let ints = solve(&b, Job::Det)?;
    let den = scale.iter().fold(BigInt::one(), |acc, l| acc * l);
    Some(to_poly(&b, &ints, &den))
}

/// `det a` for a matrix whose entries have degree at most 1 in `w`, by
/// [`Job::Pencil`] (any degree falls back to [`det`]); `None` when the grid
/// would be too large.
pub(crate) fn det_linear_in(a: &PolyMatrix, w: Sym) -> Option<Poly> {
    let n = a.rows;
    if n == 0
        || a.data.iter().any(|e| e.degree_in(w) > 1)
        || a.data.iter().all(|e| e.degree_in(w) == 0)
    {
        return det(a);
    }
    let scale: Vec<BigInt> = (0..n).map(|i| denominator_lcm(a.row(i).iter())).collect();
    let b = integral(a, &scale, false, Some(w));
    let ints = solve(&b, Job::Pencil)?;
    let den = scale.iter().fold(BigInt::one(), |acc, l| acc * l);
    Some(to_poly(&b, &ints, &den))
}

/// `[c_0 = 1, ..., c_n]` of `det(xI − a)`, or `None` when the grid would be
/// too large.
pub(crate) fn charpoly(a: &PolyMatrix) -> Option<Vec<Poly>> {
    let n = a.rows;
    let l = denominator_lcm(a.data.iter());
    let b = integral(a, &vec![l.clone(); n], true, None);
    let ints = solve(&b, Job::Charpoly)?;
    let grid = ints.len() / (n + 1);
    let mut den = BigInt::one();
    let mut out = Vec::with_capacity(n + 1);
    for k in 0..=n {
        out.push(to_poly(&b, &ints[k * grid..(k + 1) * grid], &den));
        den *= &l;
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    //! The field, the primes and the interpolation on their own; the
    //! determinant and characteristic polynomial against the sparse path
    //! are in the integration tests.

    use super::*;

    #[test]
    fn montgomery_arithmetic_matches_u128_arithmetic() {
        for &p in &primes(3) {
            let f = Field::new(p);
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
        let f = Field::new(primes(1)[0]);
        let coeffs: Vec<u64> = [5u64, 0, 7, 1, 3].iter().map(|&c| f.lift(c)).collect();
        let mut values: Vec<u64> = (0..coeffs.len() as u64)
            .map(|x| {
                let xm = f.lift(x);
                coeffs.iter().rev().fold(0, |acc, &c| f.add(f.mul(acc, xm), c))
            })
            .collect();
        let inverses: Vec<u64> =
            (0..=5).map(|k| if k == 0 { 0 } else { f.inv(f.lift(k)) }).collect();
        interpolate(f, &mut values, &inverses);
        assert_eq!(values, coeffs);
    }
}
