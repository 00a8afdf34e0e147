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

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

use super::polymatrix::PolyMatrix;
use crate::arith::zp::{self, interpolate, inverse_table, primes, split_pencil, Crt, Scratch, Zp};
use crate::multivariate::poly::Monomial;
use crate::{Poly, Sym, Q};

/// The largest evaluation grid attempted (points per prime); beyond it the
/// caller falls back to the sparse path.
const MAX_GRID: usize = 1 << 22;

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
fn residues(b: &Integral, job: Job, f: Zp) -> Vec<u64> {
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
    let inverses = inverse_table(f, sizes.iter().copied().max().unwrap_or(1));
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
            if let Some(c) = zp::pencil(f, b0, b1, n, &mut scratch) {
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
                Job::Det | Job::Pencil => out[idx] = zp::det(f, &mut mat, n),
                Job::Charpoly => {
                    let c = zp::charpoly(f, &mut mat, n, &mut scratch);
                    for (k, &x) in c.iter().enumerate() {
                        out[k * grid + idx] = x;
                    }
                }
            }
        }
        if job == Job::Pencil {
            // This outer point fell back to values in w: interpolate them
            // now, since the pass below skips the w axis.
            interpolate(f, &mut out[base..base + inner_size], |i| i as u64, &inverses);
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
                interpolate(f, &mut line, |i| i as u64, &inverses);
                for (t, &x) in line.iter().enumerate() {
                    block[start + t * stride] = x;
                }
            }
        }
    }
    out
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
