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

use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

use crate::arith::zp::{
    det_frac, eval, interpolate, inverse_table, primes, reduce, res_frac, Crt, Frac, Zp,
};
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

/// Combines residue vectors (one per prime, plain) into integers in the
/// symmetric range (Garner's CRT), as a polynomial over Q.
fn crt(residues: &[(u64, Vec<u64>)]) -> UPoly {
    let primes: Vec<u64> = residues.iter().map(|r| r.0).collect();
    let crt = Crt::new(&primes);
    let len = residues.first().map_or(0, |r| r.1.len());
    let mut column = vec![0u64; primes.len()];
    UPoly::new(
        (0..len)
            .map(|k| {
                for (x, r) in column.iter_mut().zip(residues) {
                    *x = r.1[k];
                }
                Q::from_integer(crt.reconstruct_plain(&column))
            })
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
    // Orders 1 and 2 (Jury's inners of a second- and third-order χ) by
    // their formulas: fewer products than any evaluation at points.
    match m.len() {
        1 => return m[0][0].clone(),
        2 => return &(&m[0][0] * &m[1][1]) - &(&m[0][1] * &m[1][0]),
        _ => {}
    }
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
        let mont = Zp::new(p);
        let red: Vec<Vec<Vec<u64>>> =
            entries.iter().map(|row| row.iter().map(|e| reduce(e, p)).collect()).collect();
        let mut points = b.points(mont);
        while !points.done() {
            let x = points.next_x();
            let mut a: Vec<Vec<u64>> =
                red.iter().map(|row| row.iter().map(|e| eval(e, x, mont)).collect()).collect();
            points.push(x, det_frac(&mut a, mont));
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
    fn points(&self, mont: Zp) -> Points {
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
struct Points {
    mont: Zp,
    ord: usize,
    needed: usize,
    next: u64,
    xs: Vec<u64>,
    /// s(x) = value/x^ord as a fraction (Montgomery form), divided out
    /// all at once by [`Points::interpolate`].
    fracs: Vec<Frac>,
}

impl Points {
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
            m.mul(value.den, m.pow(m.form(x), self.ord as u64))
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
        let mut inv = m.inv(acc);
        let mut ys = vec![0; self.fracs.len()];
        for i in (0..self.fracs.len()).rev() {
            let inv_i = if i == 0 { inv } else { m.mul(inv, prefix[i - 1]) };
            inv = m.mul(inv, self.fracs[i].den);
            ys[i] = m.mul(m.mul(self.fracs[i].num, inv_i), 1);
        }
        let mut c = vec![0; self.ord];
        let max = self.xs.last().copied().unwrap_or(0) as usize;
        interpolate(m, &mut ys, |i| self.xs[i], &inverse_table(m, max));
        c.extend(ys);
        c
    }
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
        let mont = Zp::new(p);
        let fr: Vec<Vec<u64>> = fi.iter().map(|e| reduce(e, p)).collect();
        let gr: Vec<Vec<u64>> = gi.iter().map(|e| reduce(e, p)).collect();
        let mut points = b.points(mont);
        while !points.done() {
            let x = points.next_x();
            let fx: Vec<u64> = fr.iter().map(|c| eval(c, x, mont)).collect();
            let gx: Vec<u64> = gr.iter().map(|c| eval(c, x, mont)).collect();
            // Skip points where a formal leading coefficient vanishes: there
            // the actual resultant is not the formal one.
            if fx[m] != 0 && gx[n] != 0 {
                points.push(x, res_frac(fx, gx, mont));
            }
        }
        residues.push((p, points.interpolate()));
    }
    crt(&residues)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::ToPrimitive;

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
            let proven = crate::arith::zp::coprime_mod_p(&ints(&a), &ints(&b));
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
