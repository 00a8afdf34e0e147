//! The dense univariate path of [`PolyMatrix::charpoly_berkowitz`].
//!
//! Most matrices zcheck meets are univariate: transition matrices in Phi
//! alone. For those, Berkowitz runs on dense integer polynomials (`i128`
//! coefficients, after clearing denominators: the coefficients of the scaled
//! matrix LA are `L^k c_k`), which is two orders of magnitude faster than the
//! sparse rational path. Every operation there is overflow-checked, and an
//! overflow falls back to the next path, so the result never changes.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, ToPrimitive};

use super::polymatrix::PolyMatrix;
use crate::multivariate::poly::Monomial;
use crate::{Poly, Sym, Q};

/// Dense integer polynomials in one flat buffer. Slot `i` holds its
/// coefficients, lowest power first and without trailing zeros, in
/// `coeffs[i * stride..i * stride + len[i]]`, and `norm[i]` is their 1-norm
/// (the sum of absolute values, saturating). One buffer serves a whole
/// Berkowitz run, so the hot loop allocates nothing.
struct DenseBuffer {
    stride: usize,
    coeffs: Vec<i128>,
    len: Vec<usize>,
    norm: Vec<u128>,
}

impl DenseBuffer {
    fn new(slots: usize, stride: usize) -> DenseBuffer {
        DenseBuffer {
            stride,
            coeffs: vec![0; slots * stride],
            len: vec![0; slots],
            norm: vec![0; slots],
        }
    }

    fn get(&self, i: usize) -> &[i128] {
        &self.coeffs[i * self.stride..i * self.stride + self.len[i]]
    }

    fn set(&mut self, i: usize, value: &[i128]) {
        let base = i * self.stride;
        self.coeffs[base..base + value.len()].copy_from_slice(value);
        self.len[i] = value.len();
        self.finish(i);
    }

    /// Negates slot `i`; `None` when it holds `i128::MIN`.
    fn negate(&mut self, i: usize) -> Option<()> {
        let base = i * self.stride;
        for x in &mut self.coeffs[base..base + self.len[i]] {
            *x = x.checked_neg()?;
        }
        Some(())
    }

    /// Drops trailing zeros of slot `i` and recomputes its 1-norm.
    fn finish(&mut self, i: usize) {
        let base = i * self.stride;
        let mut len = self.len[i];
        while len > 0 && self.coeffs[base + len - 1] == 0 {
            len -= 1;
        }
        self.len[i] = len;
        self.norm[i] = self.coeffs[base..base + len]
            .iter()
            .fold(0u128, |s, x| s.saturating_add(x.unsigned_abs()));
    }
}

/// How the dense path did its arithmetic, so the tests can see which
/// branch ran.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Arithmetic {
    /// Every sum of products was proven in range beforehand.
    Bounded,
    /// At least one needed overflow-checked arithmetic (and none overflowed).
    Checked,
}

/// `out[slot] = Σ left[x]·right[y]` over the slot pairs `(x, y)` in
/// `pairs`, or `None` when a coefficient overflows `i128`.
///
/// Each coefficient of the result, and each partial sum on the way, is at
/// most `Σ ‖left[x]‖₁‖right[y]‖₁` in absolute value. When that bound fits in
/// `i64` every operand and partial sum does too, and a product is one
/// multiply; when it fits in `i128` the products run with plain wrapping
/// `i128` arithmetic, which is then exact (and several times faster than
/// checked `i128` multiplication); otherwise every step is checked.
/// `checked` records that the slow branch ran.
fn sum_of_products(
    out: &mut DenseBuffer,
    slot: usize,
    left: &DenseBuffer,
    right: &DenseBuffer,
    pairs: impl Iterator<Item = (usize, usize)> + Clone,
    checked: &mut bool,
) -> Option<()> {
    let bound = pairs
        .clone()
        .fold(0u128, |s, (x, y)| s.saturating_add(left.norm[x].saturating_mul(right.norm[y])));
    let in_range = bound <= i128::MAX as u128;
    *checked |= !in_range;
    let base = slot * out.stride;
    let mut len = 0;
    for (x, y) in pairs {
        let (a, b) = (left.get(x), right.get(y));
        if a.is_empty() || b.is_empty() {
            continue;
        }
        let need = a.len() + b.len() - 1;
        if need > len {
            out.coeffs[base + len..base + need].fill(0);
            len = need;
        }
        let acc = &mut out.coeffs[base..base + len];
        if bound <= i64::MAX as u128 {
            mul_add_narrow(acc, a, b);
        } else if in_range {
            mul_add_wrapping(acc, a, b);
        } else {
            mul_add_checked(acc, a, b)?;
        }
    }
    out.len[slot] = len;
    out.finish(slot);
    Some(())
}

/// `acc += a * b`, wrapping; exact when the caller has bounded the result.
#[inline]
fn mul_add_wrapping(acc: &mut [i128], a: &[i128], b: &[i128]) {
    for (i, &x) in a.iter().enumerate() {
        if x == 0 {
            continue;
        }
        for (slot, &y) in acc[i..].iter_mut().zip(b) {
            *slot = slot.wrapping_add(x.wrapping_mul(y));
        }
    }
}

/// `acc += a * b` for a sum the caller has bounded by `i64::MAX`: every
/// operand and partial sum fits in `i64`, where a product is one multiply
/// instead of three.
#[inline]
fn mul_add_narrow(acc: &mut [i128], a: &[i128], b: &[i128]) {
    for (i, &x) in a.iter().enumerate() {
        if x == 0 {
            continue;
        }
        let x = x as i64;
        for (slot, &y) in acc[i..].iter_mut().zip(b) {
            *slot = (*slot as i64).wrapping_add(x.wrapping_mul(y as i64)) as i128;
        }
    }
}

/// `acc += a * b`, or `None` on overflow.
fn mul_add_checked(acc: &mut [i128], a: &[i128], b: &[i128]) -> Option<()> {
    for (i, &x) in a.iter().enumerate() {
        if x == 0 {
            continue;
        }
        for (slot, &y) in acc[i..].iter_mut().zip(b) {
            *slot = slot.checked_add(x.checked_mul(y)?)?;
        }
    }
    Some(())
}

/// The univariate fast path of [`PolyMatrix::charpoly_berkowitz`]: `None`
/// when the entries involve two or more symbols, or when a coefficient
/// overflows `i128` at any step.
pub(super) fn charpoly_univariate(a: &PolyMatrix) -> Option<Vec<Poly>> {
    charpoly_univariate_with_route(a).map(|(c, _)| c)
}

/// Which branches the dense path took, so the tests can see them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Route {
    arithmetic: Arithmetic,
    /// Whether [`halve_degrees`] applied.
    halved: bool,
}

/// [`charpoly_univariate`], also saying which branches it took.
fn charpoly_univariate_with_route(a: &PolyMatrix) -> Option<(Vec<Poly>, Route)> {
    let mut sym: Option<Sym> = None;
    let mut degree = 0usize;
    // The lcm L of all denominators. A denominator or numerator beyond i128
    // would make some scaled coefficient overflow, so it ends the fast path.
    let mut scale: i128 = 1;
    for e in &a.data {
        for (m, c) in e.terms() {
            for &(s, k) in m.factors() {
                match sym {
                    None => sym = Some(s),
                    Some(t) if t != s => return None,
                    Some(_) => {}
                }
                degree = degree.max(k as usize);
            }
            let d = c.denom().to_i128()?;
            if scale % d != 0 {
                scale = scale.checked_mul(d / scale.gcd(&d))?;
            }
        }
    }
    let n = a.rows;
    let mut entries = DenseBuffer::new(n * n, degree + 1);
    let mut scratch = vec![0i128; degree + 1];
    for (slot, e) in a.data.iter().enumerate() {
        scratch.fill(0);
        let mut len = 0;
        for (m, c) in e.terms() {
            let k = sym.map_or(0, |s| m.exponent(s)) as usize;
            let numer = c.numer().to_i128()?;
            let denom = c.denom().to_i128()?;
            scratch[k] = numer.checked_mul(scale / denom)?;
            len = len.max(k + 1);
        }
        entries.set(slot, &scratch[..len]);
    }
    // With a parity structure, Berkowitz runs on C(u) with u = x², and
    // the coefficient of u^e is that of x^(2e).
    let (c, arithmetic, spread) = match halve_degrees(n, &entries) {
        Some((halved, halved_degree)) => {
            let (c, arithmetic) = berkowitz_dense(n, halved_degree, &halved)?;
            (c, arithmetic, 2)
        }
        None => {
            let (c, arithmetic) = berkowitz_dense(n, degree, &entries)?;
            (c, arithmetic, 1)
        }
    };
    // c_k(A) = c_k(LA) / L^k. While L^k fits in i128 the fraction is
    // reduced there; beyond, BigRational reduces it.
    let mut power = Some(1i128);
    let mut big_power = BigInt::one();
    let mut out = Vec::with_capacity(n + 1);
    for k in 0..=n {
        let terms = c.get(k).iter().enumerate().filter(|(_, x)| **x != 0).map(|(e, &x)| {
            let coefficient = match power {
                Some(1) => Q::from_integer(BigInt::from(x)),
                Some(p) => {
                    let g = x.unsigned_abs().gcd(&(p as u128)) as i128;
                    Q::new_raw(BigInt::from(x / g), BigInt::from(p / g))
                }
                None => Q::new(BigInt::from(x), big_power.clone()),
            };
            let m = sym.map_or_else(Monomial::one, |s| Monomial::power(s, (spread * e) as u32));
            (coefficient, m)
        });
        out.push(Poly::from_terms(terms));
        power = power.and_then(|p| p.checked_mul(scale));
        big_power *= scale;
    }
    Some((out, Route { arithmetic, halved: spread == 2 }))
}

/// The parity reduction of the dense path.
///
/// When a diagonal similarity `D = diag(x^s_i)`, `s_i ∈ {0, 1}`, turns `A`
/// into a matrix `B = D⁻¹AD` of even polynomials, then `B(x) = C(x²)` and
/// `det(yI − A) = det(yI − B) = det(yI − C)(x²)`: the same characteristic
/// polynomial from entries of half the degree, about a quarter of the
/// work. Such an `s` exists exactly when every entry's exponents share one
/// parity `p_ij` and `s_i + s_j ≡ p_ij (mod 2)` is solvable, which is the
/// shape of transition matrices of mechanical systems in Phi (positions
/// even, velocities odd). Returns `C` and its degree, or `None` when there
/// is no such `s` or nothing to gain (constant entries).
fn halve_degrees(n: usize, a: &DenseBuffer) -> Option<(DenseBuffer, usize)> {
    if a.stride == 1 {
        return None;
    }
    // The common parity of an entry's exponents; `None` for a zero entry.
    let mut parity = vec![None; n * n];
    for (slot, p) in parity.iter_mut().enumerate() {
        let mut exponents =
            a.get(slot).iter().enumerate().filter(|(_, x)| **x != 0).map(|(e, _)| e % 2);
        if let Some(first) = exponents.next() {
            if exponents.any(|e| e != first) {
                return None;
            }
            *p = Some(first);
        }
    }
    // Solve s_i + s_j ≡ p_ij over each connected component, from s = 0 at
    // its first index.
    let mut shift: Vec<Option<usize>> = vec![None; n];
    let mut stack = Vec::new();
    for root in 0..n {
        if shift[root].is_some() {
            continue;
        }
        shift[root] = Some(0);
        stack.push(root);
        while let Some(i) = stack.pop() {
            let si = shift[i]?;
            for j in 0..n {
                for p in [parity[i * n + j], parity[j * n + i]].into_iter().flatten() {
                    let want = (p + si) % 2;
                    match shift[j] {
                        None => {
                            shift[j] = Some(want);
                            stack.push(j);
                        }
                        Some(sj) if sj != want => return None,
                        Some(_) => {}
                    }
                }
            }
        }
    }
    let shift: Vec<usize> = shift.into_iter().collect::<Option<_>>()?;
    // Entry (i, j) of B is x^(s_j − s_i) A_ij; its exponents are even and
    // non-negative (s_i = 1, s_j = 0 forces odd exponents, so ≥ 1).
    let halved_exponent = |i: usize, j: usize, e: usize| (e + shift[j] - shift[i]) / 2;
    let mut degree = 0;
    for i in 0..n {
        for j in 0..n {
            // The last stored coefficient is nonzero.
            if let Some(top) = a.len[i * n + j].checked_sub(1) {
                degree = degree.max(halved_exponent(i, j, top));
            }
        }
    }
    let mut c = DenseBuffer::new(n * n, degree + 1);
    let mut scratch = vec![0i128; degree + 1];
    for i in 0..n {
        for j in 0..n {
            scratch.fill(0);
            let mut len = 0;
            for (e, &x) in a.get(i * n + j).iter().enumerate().filter(|(_, x)| **x != 0) {
                let k = halved_exponent(i, j, e);
                scratch[k] = x;
                len = k + 1;
            }
            c.set(i * n + j, &scratch[..len]);
        }
    }
    Some((c, degree))
}

/// Berkowitz on dense integer polynomials of degree at most `degree`,
/// row-major `n×n` entries in `a`; the same recurrence as the sparse path.
/// Returns the buffer whose slot `k` is `c_k`.
fn berkowitz_dense(n: usize, degree: usize, a: &DenseBuffer) -> Option<(DenseBuffer, Arithmetic)> {
    // Every polynomial below (M^k S, R M^k S, c_k) has degree at most
    // n·degree, so one stride fits all.
    let stride = n * degree + 1;
    let mut checked = false;
    let mut c = DenseBuffer::new(n + 2, stride);
    let mut next = DenseBuffer::new(n + 2, stride);
    let mut col = DenseBuffer::new(n + 2, stride);
    let mut v = DenseBuffer::new(n, stride);
    let mut w = DenseBuffer::new(n, stride);
    c.set(0, &[1]);
    for r in 0..n {
        // Leading principal block of size r+1 = [[M, S], [R, a_rr]].
        // The Toeplitz column is 1, -a_rr, -R S, -R M S, ..., -R M^(r-1) S.
        col.set(0, &[1]);
        col.set(1, a.get(r * n + r));
        col.negate(1)?;
        for i in 0..r {
            v.set(i, a.get(i * n + r));
        }
        for k in 0..r {
            sum_of_products(&mut col, k + 2, a, &v, (0..r).map(|j| (r * n + j, j)), &mut checked)?;
            col.negate(k + 2)?;
            if k + 1 < r {
                for i in 0..r {
                    sum_of_products(
                        &mut w,
                        i,
                        a,
                        &v,
                        (0..r).map(|j| (i * n + j, j)),
                        &mut checked,
                    )?;
                }
                std::mem::swap(&mut v, &mut w);
            }
        }
        for i in 0..r + 2 {
            sum_of_products(
                &mut next,
                i,
                &col,
                &c,
                (0..=i.min(r)).map(|j| (i - j, j)),
                &mut checked,
            )?;
        }
        std::mem::swap(&mut c, &mut next);
    }
    let arithmetic = if checked { Arithmetic::Checked } else { Arithmetic::Bounded };
    Some((c, arithmetic))
}

#[cfg(test)]
mod tests {
    //! The dense univariate path against the sparse reference, branch by
    //! branch: parity halving, bounded and checked arithmetic, and the
    //! fallback on overflow.

    use proptest::prelude::*;

    use super::*;

    fn phi() -> Poly {
        Poly::sym(Sym::phi())
    }

    /// `m · 2^shift` as a constant polynomial.
    fn big(m: i64, shift: u32) -> Poly {
        Poly::constant(Q::from_integer(BigInt::from(m) << shift))
    }

    /// The dense path gives the sparse path's coefficients, by the route
    /// expected.
    #[track_caller]
    fn check(a: &PolyMatrix, arithmetic: Arithmetic, halved: bool) {
        let (c, route) = charpoly_univariate_with_route(a).expect("the dense path applies");
        assert_eq!(c, a.charpoly_berkowitz_sparse());
        assert_eq!(route, Route { arithmetic, halved });
    }

    /// The dense path gives up, and the public result is still the sparse
    /// one (and the determinant agrees with Laplace).
    #[track_caller]
    fn check_fallback(a: &PolyMatrix) {
        assert!(charpoly_univariate(a).is_none(), "the dense path should overflow");
        assert_eq!(a.charpoly_berkowitz(), a.charpoly_berkowitz_sparse());
        assert_eq!(a.det(), a.det_laplace());
    }

    #[test]
    fn parity_structured_matrices_are_halved() {
        let p = phi();
        // False Euler's transition matrix: positions even, velocities odd.
        let one = Poly::one();
        check(
            &PolyMatrix::from_rows(vec![vec![one.clone(), -&p], vec![p.clone(), &one - &p.pow(2)]]),
            Arithmetic::Bounded,
            true,
        );
        // Rational entries and an even-only matrix (all shifts 0).
        let half = Poly::constant(Q::new(1.into(), 2.into()));
        check(
            &PolyMatrix::from_rows(vec![
                vec![&half * &p.pow(2), Poly::int(3), Poly::zero()],
                vec![Poly::int(-1), p.pow(4), &half - &p.pow(2)],
                vec![Poly::int(2), Poly::zero(), Poly::int(7)],
            ]),
            Arithmetic::Bounded,
            true,
        );
    }

    #[test]
    fn matrices_without_parity_structure_are_not_halved() {
        let p = phi();
        // Mixed parities within an entry.
        check(
            &PolyMatrix::from_rows(vec![
                vec![&Poly::one() + &p, Poly::int(2)],
                vec![p.pow(2), Poly::int(3)],
            ]),
            Arithmetic::Bounded,
            false,
        );
        // Pure parities whose shifts conflict: s0+s1, s1+s2 and s0+s2 all odd.
        let one = Poly::one();
        check(
            &PolyMatrix::from_rows(vec![
                vec![one.clone(), p.clone(), p.clone()],
                vec![p.clone(), one.clone(), p.clone()],
                vec![p.clone(), p.clone(), one.clone()],
            ]),
            Arithmetic::Bounded,
            false,
        );
        // Constant entries: nothing to halve.
        check(&PolyMatrix::from_rows(vec![vec![Poly::int(4)]]), Arithmetic::Bounded, false);
    }

    /// The 1-norm bound 2^63 · 2^64 passes i128, but the true coefficients
    /// (2^126) fit: checked arithmetic finishes on the dense path.
    #[test]
    fn a_loose_bound_falls_back_to_checked_arithmetic() {
        let b = &big(1, 63) * &(&Poly::one() + &phi());
        check(
            &PolyMatrix::from_rows(vec![vec![Poly::zero(), b], vec![big(1, 63), Poly::zero()]]),
            Arithmetic::Checked,
            false,
        );
    }

    #[test]
    fn overflow_falls_back_to_the_sparse_path() {
        // 2^100 · 2^100 overflows i128.
        check_fallback(&PolyMatrix::from_rows(vec![
            vec![Poly::zero(), &big(1, 100) * &phi()],
            vec![&big(-3, 100) * &phi(), Poly::one()],
        ]));
        // A coefficient beyond i128 from the start.
        check_fallback(&PolyMatrix::from_rows(vec![vec![big(1, 130)]]));
        // Denominators whose lcm passes i128.
        let tiny = |k: i64| Poly::constant(Q::new(1.into(), BigInt::from(k) << 70u32));
        check_fallback(&PolyMatrix::from_rows(vec![
            vec![tiny(3), Poly::one()],
            vec![Poly::one(), tiny(5)],
        ]));
    }

    /// A matrix with the parity structure for random shifts `s`: entry
    /// (i, j) has only exponents ≡ s_i + s_j, coefficients up to `2^bits`.
    fn parity_matrix(n: usize, bits: u32) -> impl Strategy<Value = PolyMatrix> {
        let entry = (any::<bool>(), proptest::collection::vec(-(1i64 << bits)..=(1i64 << bits), 3));
        (proptest::collection::vec(0usize..2, n), proptest::collection::vec(entry, n * n)).prop_map(
            move |(shift, entries)| {
                let rows = (0..n)
                    .map(|i| {
                        (0..n)
                            .map(|j| {
                                let (present, ref coeffs) = entries[i * n + j];
                                if !present {
                                    return Poly::zero();
                                }
                                let parity = (shift[i] + shift[j]) % 2;
                                coeffs.iter().enumerate().fold(Poly::zero(), |acc, (k, &c)| {
                                    &acc + &(&Poly::int(c) * &phi().pow((2 * k + parity) as u32))
                                })
                            })
                            .collect()
                    })
                    .collect();
                PolyMatrix::from_rows(rows)
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Halved, in every arithmetic (small, i128-sized and overflowing
        /// coefficients), the public result equals the sparse reference.
        #[test]
        fn parity_matrices_match_the_sparse_path(
            a in (1usize..=6, prop_oneof![Just(2u32), Just(20), Just(40)])
                .prop_flat_map(|(n, bits)| parity_matrix(n, bits))
        ) {
            prop_assert_eq!(a.charpoly_berkowitz(), a.charpoly_berkowitz_sparse());
            // Every nonconstant matrix of this shape takes the halved route.
            if let Some((_, route)) = charpoly_univariate_with_route(&a) {
                let constant = a.data.iter().all(|e| e.degree_in(Sym::phi()) == 0);
                prop_assert!(route.halved || constant);
            }
        }
    }
}
