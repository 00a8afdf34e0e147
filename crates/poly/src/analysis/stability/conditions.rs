//! The critical conditions of χ(z; Φ): polynomials in Φ whose positive
//! roots are the only places where the root class can change.
//!
//! χ = Σ a_k(Φ) z^k is first scaled to integer coefficients (the roots do not
//! change). A root meets the unit circle only where
//! - χ(1) = 0 or χ(−1) = 0 (a real root passes ±1), or
//! - two roots have product 1: ∏_{i<j}(1 − z_i z_j) = 0, which for a complex
//!   pair is |z|² = 1. Times a_n^{n−1} this product is the determinant of the
//!   (n−1)×(n−1) matrix X − Y of Jury's inners (X upper triangular Toeplitz of
//!   a_n … a_2, Y the lower-right triangular Toeplitz of a_0 … a_{n−2}); it is
//!   the square root of Res_z(χ, z^n χ(1/z)) / (χ(1) χ(−1)), so it carries the
//!   same roots at half the degree. It is computed by modular evaluation and
//!   interpolation ([`crate::univariate::modular`]).
//!
//! When that product vanishes identically (a self-reciprocal factor:
//! symplectic methods keep roots on the circle for a whole Φ-interval), the
//! factor g = gcd(χ, z^n χ(1/z)) over Q(Φ) is split off: its roots on the
//! circle are the real roots x ∈ (−2, 2) of G(x) with g = z^m G(z + 1/z), so
//! they change only where G(±2) = g(±1) = 0 (in χ(±1)), where G's leading
//! coefficient vanishes (in a_n) or where the discriminant of G vanishes.
//! The cofactor h = χ/g is handled like χ.
//!
//! The class of the dominant roots also changes where roots collide (the
//! discriminant of χ in z, Res_z(χ, χ′)/a_n), where a root comes from
//! infinity (a_n = 0), and where roots of different kind tie for the largest
//! modulus: r = −s (Res_y(E, O) with χ(z) = E(z²) + z·O(z²)) and, for
//! degree ≤ 4, a real root against a complex pair (r² = z z̄, from the
//! polynomials of squares and of pair products). Ties of a real root and a
//! complex pair at degree ≥ 5 are not among the conditions: such a change
//! inside an interval would go unlisted (see the module notes).

use num_bigint::BigInt;
use num_traits::One;

use crate::error::{Error, ErrorKind};
use crate::{Poly, Sym, UPoly, Q};

use super::report::{Condition, CriticalPoint};
use crate::univariate::algebraic::Algebraic;
use crate::univariate::modular;
use crate::univariate::upoly::reciprocal_reduce;

/// χ split into its coefficients in z, each an integer polynomial in Φ.
#[derive(Clone, Debug)]
pub(crate) struct Charpoly {
    /// a[k] multiplies z^k; the last is non-zero.
    pub a: Vec<UPoly>,
    /// For degree 2: the sign polynomials of the quadratic rules, formed on
    /// first use and reused at every sample and point.
    quad: std::sync::OnceLock<super::point::QuadPolys>,
}

impl Charpoly {
    pub fn new(chi: &Poly) -> Result<Charpoly, Error> {
        let (z, phi) = (Sym::z(), Sym::phi());
        if let Some(s) = chi.symbols().into_iter().find(|&s| s != z && s != phi) {
            return Err(Error::analysis(
                ErrorKind::ExtraSymbol,
                format!(
                    "characteristic polynomial {chi} still contains the parameter {s}; \
                     expected a polynomial in z and Phi only (give {s} a value)"
                ),
            ));
        }
        let a: Vec<UPoly> =
            chi.coeffs_in(z).iter().map(|c| c.to_upoly(phi).expect("only Phi remains")).collect();
        if a.len() < 2 {
            return Err(Error::analysis(
                ErrorKind::NoRoots,
                format!("characteristic polynomial {chi} does not depend on z"),
            ));
        }
        Ok(Charpoly::from_coeffs(a))
    }

    /// From coefficients in z (lowest first), scaled to integers, trailing
    /// zeros dropped.
    pub fn from_coeffs(mut a: Vec<UPoly>) -> Charpoly {
        while a.last().is_some_and(UPoly::is_zero) {
            a.pop();
        }
        Charpoly { a: integer_scaled(&a), quad: std::sync::OnceLock::new() }
    }

    pub fn degree(&self) -> usize {
        self.a.len() - 1
    }

    /// The sign polynomials of a second-order χ (degree 2 only).
    pub fn quad(&self) -> &super::point::QuadPolys {
        self.quad.get_or_init(|| super::point::QuadPolys::new(&self.a))
    }

    /// χ at a rational Φ, as a polynomial in z.
    pub fn at(&self, phi: &Q) -> UPoly {
        UPoly::new(self.a.iter().map(|c| c.eval(phi)).collect())
    }

    /// χ(x) as a polynomial in Φ, for a rational x.
    pub fn value_at_z(&self, x: &Q) -> UPoly {
        let mut acc = UPoly::zero();
        for c in self.a.iter().rev() {
            acc = &acc.scale(x) + c;
        }
        acc
    }

    /// χ′(x) as a polynomial in Φ.
    pub fn derivative_at_z(&self, x: &Q) -> UPoly {
        let d: Vec<UPoly> = self
            .a
            .iter()
            .enumerate()
            .skip(1)
            .map(|(k, c)| c.scale(&Q::from_integer(k.into())))
            .collect();
        let mut acc = UPoly::zero();
        for c in d.iter().rev() {
            acc = &acc.scale(x) + c;
        }
        acc
    }
}

/// The coefficients times the least common multiple of their denominators.
pub(crate) fn integer_scaled(a: &[UPoly]) -> Vec<UPoly> {
    let mut den = BigInt::one();
    for c in a {
        for q in c.coeffs() {
            den = crate::arith::intgcd::lcm(&den, q.denom());
        }
    }
    let s = Q::from_integer(den);
    a.iter().map(|c| c.scale(&s)).collect()
}

/// Jury's inners determinant det(X − Y) = a_n^{n−1} ∏_{i<j}(1 − z_i z_j).
pub(crate) fn unit_circle_condition(a: &[UPoly]) -> UPoly {
    let n = a.len() - 1;
    if n < 2 {
        return UPoly::constant(Q::one());
    }
    let m = n - 1;
    let mut rows = vec![vec![UPoly::zero(); m]; m];
    for (i, row) in rows.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            // X: upper triangular Toeplitz, X[i][j] = a_{n − (j − i)} for j ≥ i.
            let x = if j >= i { a[n - (j - i)].clone() } else { UPoly::zero() };
            // Y: Y[i][j] = a_{i + j − (m − 1)} when i + j ≥ m − 1.
            let y = if i + j + 1 >= m { a[i + j + 1 - m].clone() } else { UPoly::zero() };
            *e = &x - &y;
        }
    }
    modular::det(&rows)
}

/// The discriminant of χ in z, up to a non-zero constant; for an even χ
/// with a constant a_n, a polynomial with the same roots in Φ (see
/// [`even_discriminant`]).
pub(crate) fn discriminant(a: &[UPoly]) -> UPoly {
    let n = a.len() - 1;
    if n < 2 {
        return UPoly::constant(Q::one());
    }
    if let Some(d) = even_discriminant(a) {
        return d;
    }
    if n == 2 {
        let (c, b, a) = (&a[0], &a[1], &a[2]);
        return &(b * b) - &(a * c).scale(&Q::from_integer(4.into()));
    }
    let d: Vec<UPoly> =
        a.iter().enumerate().skip(1).map(|(k, c)| c.scale(&Q::from_integer(k.into()))).collect();
    let res = modular::resultant(a, &d);
    if a[n].degree() == Some(0) {
        return res.scale(&a[n].coeff(0).recip());
    }
    res.div_rem(&a[n]).0
}

/// For an even χ(z) = F(z²) of degree n ≥ 4 with a constant a_n: the
/// roots ±√w_i give Disc_z χ = c·F(0)·(Disc F)² (the pairs ±√w_i differ by
/// 2√w_i, and each pair i < j contributes (w_i − w_j)² twice), so
/// a₀·Disc F has its roots in Φ, at half the degree in z. Only the roots
/// matter: the discriminant is a condition (its positive roots) and a test
/// of vanishing at a point.
fn even_discriminant(a: &[UPoly]) -> Option<UPoly> {
    let n = a.len() - 1;
    if n < 4 || !even_in_z(a) || a[n].degree() != Some(0) {
        return None;
    }
    let big_f: Vec<UPoly> = a.iter().step_by(2).cloned().collect();
    Some(integer_scaled(&[&a[0] * &discriminant(&big_f)]).remove(0))
}

/// Whether χ has only even powers of z and even degree: χ = F(z²).
fn even_in_z(a: &[UPoly]) -> bool {
    a.len() % 2 == 1 && a.iter().skip(1).step_by(2).all(UPoly::is_zero)
}

/// Ties r = −s between roots: Res_y(E, O) with χ(z) = E(z²) + z·O(z²).
/// `None` when O or E vanishes identically (χ even or odd: every root ties
/// with its negative for all Φ).
pub(crate) fn opposite_tie(a: &[UPoly]) -> Option<UPoly> {
    let mut e: Vec<UPoly> = a.iter().step_by(2).cloned().collect();
    let mut o: Vec<UPoly> = a.iter().skip(1).step_by(2).cloned().collect();
    for v in [&mut e, &mut o] {
        while v.last().is_some_and(UPoly::is_zero) {
            v.pop();
        }
    }
    if e.is_empty() || o.is_empty() {
        return None;
    }
    if o.len() == 1 {
        // Res(E, c) = c^{deg E}: the roots of c.
        return Some(o[0].clone());
    }
    if e.len() == 1 {
        return Some(e[0].clone());
    }
    Some(modular::resultant(&e, &o))
}

/// For degree 3 and 4: r² = z_i z_j, a real root against a complex pair, as
/// the resultant of the polynomial of squares and that of pair products,
/// both in closed form (see [`squares_poly`], [`pair_products_poly`]).
pub(crate) fn pair_tie(a: &[UPoly]) -> Option<UPoly> {
    let n = a.len() - 1;
    if !(3..=4).contains(&n) {
        return None;
    }
    if let Some(r) = even_quartic_pair_tie(a) {
        return (!r.is_zero()).then_some(r);
    }
    let products = integer_scaled(&pair_products_poly(a));
    let squares = integer_scaled(&squares_poly(a));
    if products.last().is_none_or(UPoly::is_zero) || squares.last().is_none_or(UPoly::is_zero) {
        return None;
    }
    let r = modular::resultant(&squares, &products);
    (!r.is_zero()).then_some(r)
}

/// The pair tie of an even quartic χ = a₄z⁴ + a₂z² + a₀ with a constant a₄,
/// in closed form: its roots are ±√y₁, ±√y₂, the squares y₁, y₁, y₂, y₂ and
/// the pair products −y₁, −y₂, ±√(y₁y₂) (twice), so Res(squares, products)
/// is a constant times (y₁y₂)⁶(y₁ + y₂)⁴(y₁ − y₂)⁸, that is
/// a₀⁶·a₂⁴·(a₂² − 4a₀a₄)⁴. Only its roots matter (the condition's positive
/// roots and where it vanishes), so a₀·a₂·(a₂² − 4a₀a₄) is returned: the
/// same roots without the multiplicities.
fn even_quartic_pair_tie(a: &[UPoly]) -> Option<UPoly> {
    if a.len() != 5 || !even_in_z(a) || a[4].degree() != Some(0) {
        return None;
    }
    let d = &(&a[2] * &a[2]) - &(&a[0] * &a[4]).scale(&Q::from_integer(4.into()));
    Some(integer_scaled(&[&(&a[0] * &a[2]) * &d]).remove(0))
}

/// a_n^{2n}·∏(y − z_i²), by Graeffe's step: with χ(z) = E(z²) + z·O(z²),
/// χ(z)·χ(−z) = E(z²)² − z²·O(z²)² = (−1)^n a_n² ∏(z² − z_i²).
fn squares_poly(a: &[UPoly]) -> ZPoly {
    let n = a.len() - 1;
    let e: ZPoly = a.iter().step_by(2).cloned().collect();
    let o: ZPoly = a.iter().skip(1).step_by(2).cloned().collect();
    let mut g = zmul(&e, &e);
    let oo = zmul(&o, &o);
    for (k, c) in oo.iter().enumerate() {
        if g.len() <= k + 1 {
            g.resize(k + 2, UPoly::zero());
        }
        g[k + 1] = &g[k + 1] - c;
    }
    let sign = Q::from_integer(if n.is_multiple_of(2) { 1 } else { -1 }.into());
    if a[n].degree() == Some(0) {
        // A constant a_n: one rational factor.
        let factor = sign * num_traits::pow(a[n].coeff(0), 2 * n - 2);
        return trim(g.iter().map(|c| c.scale(&factor)).collect());
    }
    let mut factor = UPoly::constant(sign);
    for _ in 0..2 * n - 2 {
        factor = &factor * &a[n];
    }
    trim(g.iter().map(|c| c * &factor).collect())
}

/// a_n^{2m}·∏_{i<j}(x − z_i z_j), m = n(n − 1)/2, for n = 3 or 4, in closed
/// form. With A = a_n:
/// - n = 3: the products are e₃/z_k, so the polynomial is
///   A⁶x³ − Σ_{k≥1} a_k (−a₀)^{k−1} A^{6−k} x^{3−k};
/// - n = 4: complementary pairs u·v = e₄ with u + v = t a root of the
///   resolvent cubic R(t) = t³ − e₂t² + (e₁e₃ − 4e₄)t − (e₁²e₄ − 4e₂e₄ + e₃²),
///   so ∏(x − z_i z_j) = ∏_t (x² − t x + e₄) = x³ R((x² + e₄)/x), which
///   times A¹² is A⁹ Σ_k R̂_k (A x² + a₀)^k x^{3−k} with R̂₃ = 1, R̂₂ = −a₂,
///   R̂₁ = a₃a₁ − 4A a₀, R̂₀ = −(a₃² a₀ − 4A a₂ a₀ + A a₁²).
fn pair_products_poly(a: &[UPoly]) -> ZPoly {
    let n = a.len() - 1;
    let big_a = &a[n];
    let pow = |x: &UPoly, k: usize| match x.degree() {
        // A constant (explicit methods): one rational power.
        Some(0) => UPoly::constant(num_traits::pow(x.coeff(0), k)),
        _ => (0..k).fold(UPoly::constant(Q::one()), |acc, _| &acc * x),
    };
    let int = |k: i64| Q::from_integer(k.into());
    if n == 3 {
        let minus_a0 = -&a[0];
        let mut out = vec![UPoly::zero(); 4];
        out[3] = pow(big_a, 6);
        for k in 1..=3 {
            out[3 - k] = -&(&(&a[k] * &pow(&minus_a0, k - 1)) * &pow(big_a, 6 - k));
        }
        return trim(out);
    }
    debug_assert_eq!(n, 4);
    let (a0, a1, a2, a3) = (&a[0], &a[1], &a[2], &a[3]);
    let r_hat = [
        -&(&(&(a3 * a3) * a0) - &(&(&(big_a * a2) * a0).scale(&int(4)) - &(big_a * &(a1 * a1)))),
        &(a3 * a1) - &(big_a * a0).scale(&int(4)),
        -a2,
        UPoly::constant(Q::one()),
    ];
    // s = A x² + a₀ as a polynomial in x.
    let s: ZPoly = vec![a0.clone(), UPoly::zero(), big_a.clone()];
    let mut s_pow: ZPoly = vec![UPoly::constant(Q::one())];
    let mut out: ZPoly = vec![UPoly::zero(); 7];
    for (k, r) in r_hat.iter().enumerate() {
        // R̂_k·s^k·x^{3−k}
        for (j, c) in s_pow.iter().enumerate() {
            out[j + 3 - k] = &out[j + 3 - k] + &(r * c);
        }
        s_pow = zmul(&s_pow, &s);
    }
    let a9 = pow(big_a, 9);
    trim(out.iter().map(|c| c * &a9).collect())
}

/// The product of two polynomials in x over Q[Φ].
fn zmul(f: &[UPoly], g: &[UPoly]) -> ZPoly {
    if f.is_empty() || g.is_empty() {
        return Vec::new();
    }
    let mut out = vec![UPoly::zero(); f.len() + g.len() - 1];
    for (i, x) in f.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (j, y) in g.iter().enumerate() {
            out[i + j] = &out[i + j] + &(x * y);
        }
    }
    out
}

/// Polynomials in z over Q[Φ] (coefficients lowest first).
type ZPoly = Vec<UPoly>;

fn trim(mut v: ZPoly) -> ZPoly {
    while v.last().is_some_and(UPoly::is_zero) {
        v.pop();
    }
    v
}

/// The content (monic gcd of the coefficients over Q[Φ]).
fn content(f: &[UPoly]) -> UPoly {
    f.iter().fold(UPoly::zero(), |g, c| g.gcd(c))
}

fn primitive(f: ZPoly) -> ZPoly {
    let c = content(&f);
    if c.degree().unwrap_or(0) == 0 {
        return integer_scaled(&f);
    }
    integer_scaled(&f.iter().map(|x| x.div_rem(&c).0).collect::<Vec<_>>())
}

/// lc(g)^e·f = q·g + r in Q[Φ][z]: (q, r).
fn pseudo_div(f: &[UPoly], g: &[UPoly]) -> (ZPoly, ZPoly) {
    let n = g.len() - 1;
    let lg = &g[n];
    let mut r: ZPoly = f.to_vec();
    let mut q: ZPoly = vec![UPoly::zero(); f.len().saturating_sub(n).max(1)];
    while r.len() > n && !r.is_empty() {
        let k = r.len() - 1 - n;
        let lr = r.last().expect("non-empty").clone();
        // r ← lg·r − lr·z^k·g ; q ← lg·q + lr·z^k
        for c in q.iter_mut() {
            *c = &*c * lg;
        }
        q[k] = &q[k] + &lr;
        for c in r.iter_mut() {
            *c = &*c * lg;
        }
        for (j, gj) in g.iter().enumerate() {
            r[k + j] = &r[k + j] - &(&lr * gj);
        }
        r = trim(r);
    }
    (trim(q), r)
}

/// The primitive gcd of two polynomials in Q[Φ][z] (primitive PRS).
pub(crate) fn gcd_z(f: &[UPoly], g: &[UPoly]) -> ZPoly {
    let (a, b) = (primitive(trim(f.to_vec())), primitive(trim(g.to_vec())));
    // f = ±g up to content (χ and a palindromic reverse): the sequence
    // below would stop after one remainder with b.
    if a.len() == b.len() && (a == b || a.iter().zip(&b).all(|(x, y)| *x == -y)) {
        return b;
    }
    gcd_prs(a, b)
}

/// The primitive remainder sequence of two primitive polynomials.
fn gcd_prs(mut a: ZPoly, mut b: ZPoly) -> ZPoly {
    if a.len() < b.len() {
        std::mem::swap(&mut a, &mut b);
    }
    while !b.is_empty() {
        let (_, r) = pseudo_div(&a, &b);
        a = b;
        b = if r.is_empty() { r } else { primitive(r) };
    }
    a
}

/// f / g in Q[Φ][z] when g divides f (up to a factor in Q[Φ], removed).
pub(crate) fn exact_div_z(f: &[UPoly], g: &[UPoly]) -> ZPoly {
    let (q, r) = pseudo_div(f, g);
    debug_assert!(r.is_empty(), "exact division");
    primitive(q)
}

/// The critical conditions of χ, each a polynomial in Φ.
///
/// With `circle_only`, only those under which a root meets the unit circle
/// or arrives from infinity (no discriminant, no modulus ties).
pub(crate) fn conditions_of(chi: &Charpoly, circle_only: bool) -> Vec<(Condition, UPoly)> {
    let a = &chi.a;
    let n = chi.degree();
    let one = Q::one();
    let mut out = vec![
        (Condition::LeadingCoefficient, a[n].clone()),
        (Condition::ConstantCoefficient, a[0].clone()),
        (Condition::ChiAtOne, deflated_value_at_z(a, &one)),
        (Condition::ChiAtMinusOne, deflated_value_at_z(a, &-one.clone())),
    ];
    if n >= 2 {
        let circle = unit_circle_condition(a);
        if !circle.is_zero() {
            out.push((Condition::UnitCircle, circle));
        } else {
            out.extend(reciprocal_conditions(a));
        }
    }
    if circle_only {
        return out;
    }
    out.push((Condition::Discriminant, discriminant(a)));
    if let Some(t) = opposite_tie(a) {
        out.push((Condition::ModulusTie, t));
    }
    if let Some(t) = pair_tie(a) {
        out.push((Condition::ModulusTie, t));
    }
    out
}

/// χ(s) as a polynomial in Φ after dividing out every factor z − s that
/// divides χ identically in Φ: when χ(s) ≡ 0 (a root fixed at s for every
/// Φ), the other roots still cross s where (χ/(z − s)^m)(s) vanishes, and
/// χ(s) itself would hide that.
fn deflated_value_at_z(a: &[UPoly], s: &Q) -> UPoly {
    let value = value_at_unit(a, s).unwrap_or_else(|| horner_at_z(a, s));
    if !value.is_zero() || a.len() < 2 {
        return value;
    }
    let mut a = a.to_vec();
    loop {
        let value = horner_at_z(&a, s);
        if !value.is_zero() || a.len() < 2 {
            return value;
        }
        // Synthetic division by z − s (exact: the remainder χ(s) is zero).
        let n = a.len() - 1;
        let mut b = vec![UPoly::zero(); n];
        b[n - 1] = a[n].clone();
        for k in (1..n).rev() {
            b[k - 1] = &a[k] + &b[k].scale(s);
        }
        a = b;
    }
}

/// χ(s) = Σ a_k(Φ) s^k by Horner's rule over polynomials in Φ.
fn horner_at_z(a: &[UPoly], s: &Q) -> UPoly {
    a.iter().rev().fold(UPoly::zero(), |acc, c| &acc.scale(s) + c)
}

/// χ(±1) when every a_k has integer coefficients (χ's integer scaling
/// makes them so): sums and differences of the integers, with no
/// denominators sought; `None` for another `s` or a fraction.
fn value_at_unit(a: &[UPoly], s: &Q) -> Option<UPoly> {
    use num_traits::Signed;
    if !(s.is_integer() && s.numer().abs().is_one()) {
        return None;
    }
    let alternate = s.is_negative();
    let mut acc = vec![num_bigint::BigInt::default(); a.iter().map(|c| c.coeffs().len()).max()?];
    for (k, c) in a.iter().enumerate() {
        for (j, q) in c.coeffs().iter().enumerate() {
            if !q.is_integer() {
                return None;
            }
            if alternate && k % 2 == 1 {
                acc[j] -= q.numer();
            } else {
                acc[j] += q.numer();
            }
        }
    }
    Some(UPoly::new(acc.into_iter().map(Q::from_integer).collect()))
}

/// χ has a self-reciprocal factor g = gcd(χ, χ*) over Q(Φ): conditions of g
/// through G(x), and of the cofactor h through its inners determinant.
fn reciprocal_conditions(a: &[UPoly]) -> Vec<(Condition, UPoly)> {
    let rev: Vec<UPoly> = a.iter().rev().cloned().collect();
    let mut g = gcd_z(a, &rev);
    // g of χ's own degree: the cofactor is constant (χ self-reciprocal).
    let h = if g.len() == a.len() { Vec::new() } else { exact_div_z(a, &g) };
    let mut out = Vec::new();
    if h.len() >= 3 {
        let c = unit_circle_condition(&h);
        if !c.is_zero() {
            out.push((Condition::UnitCircle, c));
        }
    }
    // Strip the factors z ∓ 1 of g (identically in Φ), leaving a palindrome.
    for s in [Q::one(), -Q::one()] {
        loop {
            let val = g.iter().rev().fold(UPoly::zero(), |acc, c| &acc.scale(&s) + c);
            if !val.is_zero() || g.len() < 2 {
                break;
            }
            g = exact_div_z(&g, &[UPoly::constant(-s.clone()), UPoly::constant(Q::one())]);
        }
    }
    if g.len() >= 3 && (g.len() - 1).is_multiple_of(2) {
        let big_g = reciprocal_reduce(
            &g,
            UPoly::zero(),
            |x, y| x + y,
            |x, k| x.scale(&Q::from_integer(k.into())),
        );
        let big_g = integer_scaled(&big_g);
        if big_g.len() >= 3 {
            let d: Vec<UPoly> = big_g
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| c.scale(&Q::from_integer(k.into())))
                .collect();
            let disc = modular::resultant(&big_g, &d);
            if !disc.is_zero() {
                out.push((Condition::ReciprocalDiscriminant, disc));
            }
        }
    }
    out
}

/// Every positive root of every non-trivial condition, merged exactly.
pub(crate) fn critical_points(conditions: &[(Condition, UPoly)]) -> Vec<CriticalPoint> {
    // Narrow intervals make the printed "root of ... in [a, b]" readable.
    // Refined as soon as found (the refined interval depends only on the
    // isolating one): the merging and sorting below then compare narrow
    // intervals, which mostly separate at once, instead of refining copies
    // again in every comparison.
    let width = Q::new(1.into(), 1024.into());
    let mut points: Vec<CriticalPoint> = Vec::new();
    for (name, cond) in conditions {
        if cond.degree().unwrap_or(0) == 0 {
            continue;
        }
        for root in Algebraic::positive_roots(cond) {
            let root = root.refine(&width);
            match points.iter_mut().find(|p| p.at == root) {
                Some(p) if p.conditions.contains(name) => {}
                Some(p) => p.conditions.push(*name),
                None => {
                    points.push(CriticalPoint { at: root, conditions: vec![*name], bounded: None })
                }
            }
        }
    }
    points.sort_by(|x, y| x.at.cmp(&y.at));
    points
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// χ(±1) by integer sums is Horner's rule's (and fractions decline).
        #[test]
        fn value_at_unit_is_horner(
            a in proptest::collection::vec(proptest::collection::vec(-99i64..99, 0..5), 1..5),
            den in 1i64..3,
        ) {
            let a: Vec<UPoly> = a.iter().map(|c| UPoly::from_ints(c).scale(&Q::new(1.into(), den.into()))).collect();
            for s in [Q::one(), -Q::one()] {
                match value_at_unit(&a, &s) {
                    Some(v) => prop_assert_eq!(v, horner_at_z(&a, &s)),
                    None => prop_assert!(den > 1 && a.iter().any(|c| !c.is_zero())),
                }
            }
        }
    }

    /// The slow, obvious route to the polynomials of squares and of pair
    /// products: power sums of the roots, Newton's identities.
    fn by_power_sums(a: &[UPoly]) -> (ZPoly, ZPoly) {
        let n = a.len() - 1;
        let pairs = n * (n - 1) / 2;
        let p = scaled_power_sums(a, (2 * pairs).max(2 * n));
        let half = Q::new(1.into(), 2.into());
        let pair_sums: Vec<UPoly> =
            (0..=pairs).map(|k| (&(&p[k] * &p[k]) - &p[2 * k]).scale(&half)).collect();
        let square_sums: Vec<UPoly> = (0..=n).map(|k| p[2 * k].clone()).collect();
        let an_sq = &a[n] * &a[n];
        (
            poly_from_scaled_sums(&square_sums, n, &an_sq),
            poly_from_scaled_sums(&pair_sums, pairs, &an_sq),
        )
    }

    /// Power sums scaled to stay polynomial in Φ: p̃_k = a_n^k p_k.
    fn scaled_power_sums(a: &[UPoly], kmax: usize) -> Vec<UPoly> {
        let n = a.len() - 1;
        let an = &a[n];
        let mut an_pow = vec![UPoly::constant(Q::one())];
        for k in 1..=kmax {
            let next = &an_pow[k - 1] * an;
            an_pow.push(next);
        }
        let mut p = vec![UPoly::constant(Q::from_integer(n.into()))];
        for k in 1..=kmax {
            let mut s = UPoly::zero();
            for i in 1..=k.min(n) {
                if i < k {
                    s = &s + &(&(&a[n - i] * &an_pow[i - 1]) * &p[k - i]);
                } else {
                    s = &s + &(&a[n - k] * &an_pow[k - 1]).scale(&Q::from_integer(k.into()));
                }
            }
            p.push(-&s);
        }
        p
    }

    /// The coefficients (lowest power of x first) of a_n^{2m}·∏(x − w) over
    /// the m numbers w whose power sums, scaled by a_n^{2k}, are `sums[k]`.
    fn poly_from_scaled_sums(sums: &[UPoly], m: usize, an_sq: &UPoly) -> Vec<UPoly> {
        let mut e = vec![UPoly::constant(Q::one())];
        for k in 1..=m {
            let mut acc = UPoly::zero();
            for i in 1..=k {
                let term = &e[k - i] * &sums[i];
                acc = if i % 2 == 1 { &acc + &term } else { &acc - &term };
            }
            e.push(acc.scale(&Q::from_integer(k.into()).recip()));
        }
        let mut coeffs = vec![UPoly::zero(); m + 1];
        let mut an_pow = UPoly::constant(Q::one());
        for k in (0..=m).rev() {
            let c = &e[k] * &an_pow;
            coeffs[m - k] = if k % 2 == 0 { c } else { -&c };
            an_pow = &an_pow * an_sq;
        }
        coeffs
    }

    proptest! {
        /// An even quartic's pair tie in closed form has the roots of the
        /// resultant of the squares and pair products (the same square-free
        /// part).
        #[test]
        fn even_quartic_pair_tie_is_the_resultant(
            a0 in proptest::collection::vec(-4i64..=4, 1..3),
            a2 in proptest::collection::vec(-4i64..=4, 1..3),
            a4 in 1i64..=3,
        ) {
            let a = vec![
                UPoly::from_ints(&a0),
                UPoly::zero(),
                UPoly::from_ints(&a2),
                UPoly::zero(),
                UPoly::from_ints(&[a4]),
            ];
            let closed = even_quartic_pair_tie(&a).expect("an even quartic");
            let products = integer_scaled(&pair_products_poly(&a));
            let squares = integer_scaled(&squares_poly(&a));
            let general = modular::resultant(&squares, &products);
            prop_assert_eq!(closed.is_zero(), general.is_zero());
            if !closed.is_zero() {
                prop_assert_eq!(closed.squarefree(), general.squarefree());
            }
        }
    }

    proptest! {
        /// gcd_z of f and a multiple c·f (c = ±1, ±2, or a polynomial in
        /// Φ: content removed) is the remainder sequence's answer.
        #[test]
        fn gcd_of_a_multiple_is_the_remainder_sequence(
            c in proptest::collection::vec(proptest::collection::vec(-4i64..=4, 1..3), 2..5),
            k in proptest::sample::select(vec![vec![1i64], vec![-1], vec![2], vec![-3], vec![1, 1]]),
        ) {
            let f: Vec<UPoly> = c.iter().map(|v| UPoly::from_ints(v)).collect();
            prop_assume!(!f.last().unwrap().is_zero());
            let m = UPoly::from_ints(&k);
            let g: Vec<UPoly> = f.iter().map(|x| x * &m).collect();
            let slow = gcd_prs(primitive(f.clone()), primitive(g.clone()));
            prop_assert_eq!(gcd_z(&f, &g), slow);
        }
    }

    proptest! {
        /// An even χ's discriminant through F has the roots of the
        /// resultant Res(χ, χ′) (the same square-free part), degrees 4, 6
        /// and 8 in z (F of degree 4 may itself be even: the recursion),
        /// coefficients of degree ≤ 2 in Φ.
        #[test]
        fn even_discriminant_has_the_roots_of_the_resultant(
            c in proptest::collection::vec(proptest::collection::vec(-4i64..=4, 1..4), 2..5),
            lead in 1i64..=3,
        ) {
            let mut a = Vec::new();
            for v in &c {
                a.push(UPoly::from_ints(v));
                a.push(UPoly::zero());
            }
            a.push(UPoly::from_ints(&[lead]));
            let even = even_discriminant(&a).expect("even, constant a_n");
            let d: Vec<UPoly> = a
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| c.scale(&Q::from_integer(k.into())))
                .collect();
            let general = modular::resultant(&integer_scaled(&a), &integer_scaled(&d));
            prop_assert_eq!(even.is_zero(), general.is_zero());
            if !even.is_zero() {
                prop_assert_eq!(even.squarefree(), general.squarefree());
            }
        }
    }

    proptest! {
        /// The closed forms give exactly the power-sum polynomials, for
        /// degree 3 and 4 with coefficients polynomial in Φ (a₀ may vanish).
        #[test]
        fn closed_form_squares_and_pair_products_match_power_sums(
            c in proptest::collection::vec(proptest::collection::vec(-4i64..=4, 1..3), 4..6),
        ) {
            let a: Vec<UPoly> = c.iter().map(|v| UPoly::from_ints(v)).collect();
            prop_assume!(!a.last().unwrap().is_zero());
            let (squares, products) = by_power_sums(&a);
            prop_assert_eq!(squares_poly(&a), trim(squares));
            prop_assert_eq!(pair_products_poly(&a), trim(products));
        }
    }

    #[test]
    fn inners_square_times_chi_pm1_is_the_reciprocal_resultant() {
        // χ = 2z³ + z² − z + 3 − Φ·(z² + 1): compare with the Sylvester resultant.
        let a = vec![
            UPoly::from_ints(&[3, -1]),
            UPoly::from_ints(&[-1]),
            UPoly::from_ints(&[1, -1]),
            UPoly::from_ints(&[2]),
        ];
        let rev: Vec<UPoly> = a.iter().rev().cloned().collect();
        let r = modular::resultant(&a, &rev);
        let s = unit_circle_condition(&a);
        let chi = Charpoly::from_coeffs(a.clone());
        let p1 = chi.value_at_z(&Q::one());
        let m1 = chi.value_at_z(&-Q::one());
        let rhs = &(&(&p1 * &m1) * &s) * &s;
        // R = (−1)^n χ(1) χ(−1) S², n = 3.
        assert_eq!(r, -&rhs);
    }
}
