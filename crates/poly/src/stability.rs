//! Exact stability analysis of a characteristic polynomial χ(z; Φ) over all
//! step sizes Φ > 0.
//!
//! The root class of χ (section 4's taxonomy, [`RootClass`]) can change only
//! at finitely many *critical* Φ: where a root lies on the unit circle
//! (χ(1) = 0, χ(−1) = 0, or a product of two roots z_i z_j = 1, which for a
//! complex pair is |z|² = 1), where roots collide (the discriminant in z),
//! where the leading coefficient vanishes (a root comes from infinity), and
//! where two roots of different kind tie for the largest modulus. Each of
//! these conditions is a polynomial in Φ with rational coefficients; its
//! positive real roots are isolated with Sturm sequences and kept as exact
//! [`Algebraic`] numbers. Between consecutive critical points the class is
//! constant, so one exact evaluation at a rational sample Φ decides it.
//!
//! For second-order methods, χ = a z² + b z + c, the class is a Boolean
//! function of the signs of a, b, c, b² − 4ac, c − a (|z|² = 1), a + b + c
//! (χ(1)), a − b + c (χ(−1)), −b ∓ 2a (p = ±1). Signs of polynomials in Φ are
//! exact at algebraic Φ too, so the class *at* each critical point is exact.
//!
//! For higher degree the unit-circle condition is ∏_{i<j}(1 − z_i z_j),
//! built from power sums by Newton's identities, and the class at a rational
//! Φ comes from [`classify_roots`]. Limitation: for degree ≥ 3 the class
//! exactly at an irrational critical point is not computed (`None`), and for
//! degree ≥ 4 ties for the dominant modulus between roots strictly inside or
//! outside the circle are not among the critical conditions, so such a class
//! change inside an interval could go unlisted; the stability limit and the
//! bounded/unbounded split stay exact, because boundedness changes only where
//! a root meets the unit circle.

use std::cmp::Ordering;
use std::collections::HashMap;
use std::fmt;

use num_traits::{One, Zero};

use crate::algebraic::Algebraic;
use crate::sturm::sign;
use crate::{Poly, RootClass, Sym, UPoly, Q};

/// Why a polynomial could not be analysed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StabilityError {
    kind: StabilityErrorKind,
    message: String,
}

/// What kind of input an [`StabilityError`] rejects.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum StabilityErrorKind {
    /// A symbol other than `z` and `Phi` remains: give it a value first.
    ExtraSymbol,
    /// The polynomial does not depend on `z` (no roots to classify).
    NoRoots,
}

impl StabilityError {
    fn new(kind: StabilityErrorKind, message: impl Into<String>) -> StabilityError {
        StabilityError { kind, message: message.into() }
    }

    /// What went wrong.
    pub fn kind(&self) -> StabilityErrorKind {
        self.kind
    }
}

impl fmt::Display for StabilityError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for StabilityError {}

/// What happens at the stability limit Φ_max.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Boundary {
    /// Two roots meet at z = −1 (False Euler at Φ = 2).
    DoubleRootAtMinusOne,
    /// Two roots meet at z = +1.
    DoubleRootAtPlusOne,
    /// A real root passes through z = +1.
    RootThroughPlusOne,
    /// A real root passes through z = −1.
    RootThroughMinusOne,
    /// A complex pair crosses the unit circle.
    ComplexPairLeavesCircle,
    /// A complex pair on the unit circle becomes a repeated pair.
    RepeatedPairOnCircle,
    /// The leading coefficient vanishes: a root arrives from infinity.
    RootFromInfinity,
    /// None of the above was recognised.
    Other,
}

impl Boundary {
    /// The snake_case name used in JSON and reports.
    pub fn name(self) -> &'static str {
        match self {
            Boundary::DoubleRootAtMinusOne => "double_root_at_minus_one",
            Boundary::DoubleRootAtPlusOne => "double_root_at_plus_one",
            Boundary::RootThroughPlusOne => "root_through_plus_one",
            Boundary::RootThroughMinusOne => "root_through_minus_one",
            Boundary::ComplexPairLeavesCircle => "complex_pair_leaves_circle",
            Boundary::RepeatedPairOnCircle => "repeated_pair_on_circle",
            Boundary::RootFromInfinity => "root_from_infinity",
            Boundary::Other => "other",
        }
    }
}

impl fmt::Display for Boundary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A Φ where the root class changes.
#[derive(Clone, Debug)]
pub struct ClassChange {
    /// The critical Φ.
    pub at: Algebraic,
    /// The class just below.
    pub from: RootClass,
    /// The class just above.
    pub to: RootClass,
    /// The class exactly at `at` (`None` when not computed: degree ≥ 3 at an
    /// irrational point).
    pub at_class: Option<RootClass>,
}

/// A maximal open Φ-interval of one class.
#[derive(Clone, Debug)]
pub struct ClassInterval {
    /// Lower end (zero for the first interval).
    pub lo: Algebraic,
    /// Upper end; `None` for ∞.
    pub hi: Option<Algebraic>,
    /// The class everywhere strictly inside.
    pub class: RootClass,
    /// The rational Φ at which the class was decided.
    pub sample: Q,
}

/// A critical Φ and the conditions that vanish there.
#[derive(Clone, Debug)]
pub struct CriticalPoint {
    /// The critical Φ.
    pub at: Algebraic,
    /// Names of the vanishing conditions, e.g. "chi(-1)", "discriminant".
    pub conditions: Vec<&'static str>,
}

/// The result of [`analyze`].
#[derive(Clone, Debug)]
pub struct StabilityReport {
    /// Degree of χ in z.
    pub degree: usize,
    /// The largest Φ₀ such that every 0 < Φ < Φ₀ gives a bounded sequence;
    /// `None` when no such Φ₀ exists (unbounded for every small Φ > 0) or
    /// when every Φ > 0 is bounded ([`StabilityReport::bounded_for_all`]).
    pub phi_max: Option<Algebraic>,
    /// Bounded for every Φ > 0.
    pub bounded_for_all: bool,
    /// Whether Φ = Φ_max itself is bounded (`None` when not decided).
    pub bounded_at_phi_max: Option<bool>,
    /// What happens at Φ_max.
    pub boundary: Option<Boundary>,
    /// Every class change over Φ > 0, increasing.
    pub class_changes: Vec<ClassChange>,
    /// The classes between the changes, covering (0, ∞).
    pub intervals: Vec<ClassInterval>,
    /// Every critical Φ > 0 examined, with its vanishing conditions.
    pub critical_points: Vec<CriticalPoint>,
}

impl StabilityReport {
    /// The class exactly at each change point, in the order of
    /// [`StabilityReport::class_changes`].
    pub fn class_at_changes(&self) -> Vec<Option<RootClass>> {
        self.class_changes.iter().map(|c| c.at_class).collect()
    }

    /// Whether every 0 < Φ < `phi` is bounded (exact).
    pub fn is_stable_below(&self, phi: &Q) -> bool {
        if self.bounded_for_all {
            return true;
        }
        match &self.phi_max {
            Some(m) => m.cmp_rational(phi) != Ordering::Less,
            None => false,
        }
    }
}

/// χ split into its coefficients in z, each a polynomial in Φ.
struct Charpoly {
    /// a[k] multiplies z^k.
    a: Vec<UPoly>,
}

impl Charpoly {
    fn new(chi: &Poly) -> Result<Charpoly, StabilityError> {
        let (z, phi) = (Sym::z(), Sym::phi());
        if let Some(s) = chi.symbols().into_iter().find(|&s| s != z && s != phi) {
            return Err(StabilityError::new(
                StabilityErrorKind::ExtraSymbol,
                format!(
                    "characteristic polynomial {chi} still contains the parameter {s}; \
                     expected a polynomial in z and Phi only (give {s} a value)"
                ),
            ));
        }
        let a: Vec<UPoly> =
            chi.coeffs_in(z).iter().map(|c| c.to_upoly(phi).expect("only Phi remains")).collect();
        if a.len() < 2 {
            return Err(StabilityError::new(
                StabilityErrorKind::NoRoots,
                format!("characteristic polynomial {chi} does not depend on z"),
            ));
        }
        Ok(Charpoly { a })
    }

    fn degree(&self) -> usize {
        self.a.len() - 1
    }

    /// χ at a rational Φ, as a polynomial in z.
    fn at(&self, phi: &Q) -> UPoly {
        UPoly::new(self.a.iter().map(|c| c.eval(phi)).collect())
    }

    /// χ(x) as a polynomial in Φ, for a rational x.
    fn value_at_z(&self, x: &Q) -> UPoly {
        let mut acc = UPoly::zero();
        for c in self.a.iter().rev() {
            acc = &acc.scale(x) + c;
        }
        acc
    }

    /// χ′(x) as a polynomial in Φ.
    fn derivative_at_z(&self, x: &Q) -> UPoly {
        let d = Charpoly {
            a: self
                .a
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| c.scale(&Q::from_integer(k.into())))
                .collect(),
        };
        if d.a.is_empty() {
            UPoly::zero()
        } else {
            d.value_at_z(x)
        }
    }
}

/// The root class of χ at a rational Φ, exactly.
pub fn class_at(charpoly: &Poly, phi: &Q) -> Result<RootClass, StabilityError> {
    let chi = Charpoly::new(charpoly)?;
    if chi.degree() == 2 {
        return Ok(classify_quadratic(&chi.a, |p| sign(&p.eval(phi))));
    }
    Ok(classify_roots(&chi.at(phi)))
}

/// The root class of χ exactly at an algebraic Φ; `Ok(None)` when χ has
/// degree ≥ 3 and Φ is irrational (not computed, see the module notes).
pub fn class_at_algebraic(
    charpoly: &Poly,
    phi: &Algebraic,
) -> Result<Option<RootClass>, StabilityError> {
    if let Some(q) = phi.as_rational() {
        return class_at(charpoly, q).map(Some);
    }
    let chi = Charpoly::new(charpoly)?;
    if chi.degree() == 2 {
        return Ok(Some(classify_quadratic(&chi.a, |p| phi.sign_of(p))));
    }
    Ok(None)
}

/// The class of a real root r alone (a first-degree χ).
fn class_of_single_root(
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

/// The class of a z² + b z + c from the signs of polynomials in its
/// coefficients; `sgn` evaluates the sign of a polynomial in Φ at the point
/// of interest. Writing p = −b/(2a), q = c/a: complex roots have |z|² = q;
/// real roots are dominated by the one on the side of p; a tie ±√(−q)
/// (p = 0) counts as alternating, because the sequence then flips sign.
fn classify_quadratic(a: &[UPoly], sgn: impl Fn(&UPoly) -> Ordering) -> RootClass {
    let (c, b, a) = (&a[0], &a[1], &a[2]);
    let sa = sgn(a);
    if sa == Ordering::Equal {
        let sb = sgn(b);
        if sb == Ordering::Equal {
            return RootClass::Deadbeat;
        }
        // The one root r = −c/b: r − 1 = −(c + b)/b, r + 1 = (b − c)/b.
        let by_b = |o: Ordering| if sb == Ordering::Greater { o } else { o.reverse() };
        return class_of_single_root(by_b(sgn(&-c)), by_b(sgn(&-&(c + b))), by_b(sgn(&(b - c))));
    }
    let by_a = |o: Ordering| if sa == Ordering::Greater { o } else { o.reverse() };
    let disc = sgn(&(&(b * b) - &(a * c).scale(&Q::from_integer(4.into()))));
    let two_a = a.scale(&Q::from_integer(2.into()));
    let p = by_a(sgn(&-b));
    if disc == Ordering::Less {
        return match by_a(sgn(&(c - a))) {
            Ordering::Less => RootClass::DampedOscillation,
            Ordering::Equal => RootClass::Harmonic,
            Ordering::Greater => RootClass::UnstableOscillation,
        };
    }
    match p {
        Ordering::Equal => {
            // Roots ±√(−q).
            if by_a(sgn(c)) == Ordering::Equal {
                return RootClass::Deadbeat;
            }
            match by_a(sgn(&-&(c + a))) {
                Ordering::Less => RootClass::AlternatingStable,
                Ordering::Equal => RootClass::Alternating,
                Ordering::Greater => RootClass::AlternatingUnstable,
            }
        }
        Ordering::Greater => {
            let p_minus_one = by_a(sgn(&-&(b + &two_a)));
            if disc == Ordering::Equal {
                return match p_minus_one {
                    Ordering::Less => RootClass::MonotonicStable,
                    Ordering::Equal => RootClass::DoubleRootOnCircle,
                    Ordering::Greater => RootClass::MonotonicUnstable,
                };
            }
            // χ(1)/a < 0 puts 1 between the roots; = 0 makes 1 a root, the
            // larger one unless p > 1; > 0 puts both roots on one side of 1.
            match (by_a(sgn(&(&(a + b) + c))), p_minus_one) {
                (Ordering::Less, _) => RootClass::MonotonicUnstable,
                (Ordering::Equal, Ordering::Greater) => RootClass::MonotonicUnstable,
                (Ordering::Equal, _) => RootClass::Constant,
                (Ordering::Greater, Ordering::Greater) => RootClass::MonotonicUnstable,
                (Ordering::Greater, _) => RootClass::MonotonicStable,
            }
        }
        Ordering::Less => {
            let p_plus_one = by_a(sgn(&(&two_a - b)));
            if disc == Ordering::Equal {
                return match p_plus_one {
                    Ordering::Greater => RootClass::AlternatingStable,
                    Ordering::Equal => RootClass::DoubleRootOnCircle,
                    Ordering::Less => RootClass::AlternatingUnstable,
                };
            }
            match (by_a(sgn(&(&(a - b) + c))), p_plus_one) {
                (Ordering::Less, _) => RootClass::AlternatingUnstable,
                (Ordering::Equal, Ordering::Less) => RootClass::AlternatingUnstable,
                (Ordering::Equal, _) => RootClass::Alternating,
                (Ordering::Greater, Ordering::Less) => RootClass::AlternatingUnstable,
                (Ordering::Greater, _) => RootClass::AlternatingStable,
            }
        }
    }
}

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
    // x^m − e1 x^{m−1} + e2 x^{m−2} − ...
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
    // Each real root of modulus ρ gives z_i² = ρ², each conjugate pair of
    // modulus ρ gives z z̄ = ρ² once; no other product of roots equals ρ²
    // (|z_i z_j| = ρ² forces both moduli to be ρ and z_j = z̄_i·(ρ²/|z_i|²)).
    let mult = rho_sq.multiplicity_in(&pair_products_with_squares(f));
    (real, mult.saturating_sub(real))
}

/// The root class of a polynomial in z with rational coefficients, exactly,
/// for any degree. The dominant modulus² ρ² is the largest positive root of
/// the polynomial whose roots are the products z_i z_j (i ≤ j); real roots
/// with r² = ρ² and conjugate pairs with z z̄ = ρ² are then counted exactly.
/// Ties are resolved towards oscillation (a dominant complex pair wins),
/// then alternation (a dominant negative root wins); a repeated dominant
/// root on the unit circle gives [`RootClass::DoubleRootOnCircle`].
pub fn classify_roots(f: &UPoly) -> RootClass {
    let Some(n) = f.degree() else { return RootClass::Deadbeat };
    // Strip roots at zero: they never dominate unless all roots are zero.
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
        // A repeated dominant root: a root of gcd(g, g′) of the same modulus.
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

/// Power sums scaled to stay polynomial in Φ: p̃_k = a_n^k p_k, from
/// a_n^k p_k = −Σ_{i=1}^{min(k−1,n)} a_{n−i} a_n^{i−1} p̃_{k−i} − [k ≤ n] k a_{n−k} a_n^{k−1}.
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

/// Determinant of a square matrix over Q[Φ] by fraction-free (Bareiss)
/// elimination: every division is exact.
fn det_upoly(mut m: Vec<Vec<UPoly>>) -> UPoly {
    let n = m.len();
    let mut prev = UPoly::constant(Q::one());
    let mut negate = false;
    for k in 0..n {
        let Some(pivot) = (k..n).find(|&i| !m[i][k].is_zero()) else {
            return UPoly::zero();
        };
        if pivot != k {
            m.swap(pivot, k);
            negate = !negate;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let num = &(&m[i][j] * &m[k][k]) - &(&m[i][k] * &m[k][j]);
                m[i][j] = num.div_rem(&prev).0;
            }
        }
        prev = m[k][k].clone();
    }
    let d = m[n - 1][n - 1].clone();
    if negate {
        -&d
    } else {
        d
    }
}

/// The Hankel determinant det[s_{i+j}], i, j < m: for power sums of roots it
/// is the discriminant (up to a power of the leading coefficient).
fn hankel_det(s: &[UPoly], m: usize) -> UPoly {
    det_upoly((0..m).map(|i| (0..m).map(|j| s[i + j].clone()).collect()).collect())
}

/// The critical conditions of χ, each a polynomial in Φ with a name.
fn critical_conditions(chi: &Charpoly) -> Vec<(&'static str, UPoly)> {
    let a = &chi.a;
    let n = chi.degree();
    let one = Q::one();
    let mut out = vec![
        ("leading coefficient", a[n].clone()),
        ("constant coefficient", a[0].clone()),
        ("chi(1)", chi.value_at_z(&one)),
        ("chi(-1)", chi.value_at_z(&-one.clone())),
    ];
    if n == 2 {
        let (c, b, a) = (&a[0], &a[1], &a[2]);
        let two_a = a.scale(&Q::from_integer(2.into()));
        out.push(("discriminant", &(b * b) - &(a * c).scale(&Q::from_integer(4.into()))));
        out.push(("|z|^2 = 1", c - a));
        out.push(("p = 0", b.clone()));
        out.push(("p = 1", -&(b + &two_a)));
        out.push(("p = -1", &two_a - b));
        return out;
    }
    let an = &a[n];
    // Products of roots, from power sums scaled by a_n^k: the squares z_i²
    // (power sums p_{2k}) and the pair products z_i z_j, i < j (power sums
    // (p_k² − p_{2k})/2), each as a polynomial in x with coefficients in Φ.
    let pairs = n * (n - 1) / 2;
    // Indices needed: 2·pairs for the pair sums, 4(n − 1) for the Hankel
    // matrix of the squares.
    let p = scaled_power_sums(a, (2 * pairs).max(4 * (n - 1)).max(2 * n));
    let half = Q::new(1.into(), 2.into());
    let pair_sums: Vec<UPoly> =
        (0..=pairs).map(|k| (&(&p[k] * &p[k]) - &p[2 * k]).scale(&half)).collect();
    // At least n + 1 sums: the squares polynomial of a first-order χ needs p_2.
    let square_sums: Vec<UPoly> = (0..=(2 * (n - 1)).max(n)).map(|k| p[2 * k].clone()).collect();
    let an_sq = an * an;
    let products = poly_from_scaled_sums(&pair_sums, pairs, &an_sq);
    let squares = poly_from_scaled_sums(&square_sums, n, &an_sq);
    // Unit circle: ∏_{i<j} (1 − z_i z_j) = the pair-product polynomial at 1.
    let circle = products.iter().fold(UPoly::zero(), |acc, c| &acc + c);
    out.push(("z_i z_j = 1", circle));
    out.push(("discriminant", hankel_det(&p, n)));
    // Ties for the largest modulus: r_i = −r_j (a repeated square) and
    // r² = z z̄ (a square equal to a pair product). Ties between two complex
    // pairs (degree ≥ 4) are not covered; see the module notes.
    out.push(("modulus tie", hankel_det(&square_sums, n)));
    out.push(("modulus tie", sylvester_det(&squares, &products)));
    out
}

/// The coefficients (lowest power of x first, each a polynomial in Φ) of
/// a_n^{2m}·∏(x − w) over the m numbers w whose power sums, scaled by
/// a_n^{2k}, are `sums[k]`; Newton's identities with ẽ_k = a_n^{2k} e_k.
fn poly_from_scaled_sums(sums: &[UPoly], m: usize, an_sq: &UPoly) -> Vec<UPoly> {
    let mut e = vec![UPoly::constant(Q::one())];
    for k in 1..=m {
        let mut acc = UPoly::zero();
        for i in 1..=k {
            let term = &e[k - i] * &sums[i];
            acc = if i % 2 == 1 { &acc + &term } else { &acc - &term };
        }
        e.push(acc.scale(&(Q::one() / Q::from_integer(k.into()))));
    }
    // Coefficient of x^{m−k} is (−1)^k ẽ_k a_n^{2(m−k)}.
    let mut coeffs = vec![UPoly::zero(); m + 1];
    let mut an_pow = UPoly::constant(Q::one());
    for k in (0..=m).rev() {
        let c = &e[k] * &an_pow;
        coeffs[m - k] = if k % 2 == 0 { c } else { -&c };
        an_pow = &an_pow * an_sq;
    }
    coeffs
}

/// The resultant of two polynomials in x (coefficients in Φ, lowest power
/// first) as the Sylvester determinant.
fn sylvester_det(f: &[UPoly], g: &[UPoly]) -> UPoly {
    let (m, n) = (f.len() - 1, g.len() - 1);
    let size = m + n;
    let mut rows = Vec::with_capacity(size);
    for shift in 0..n {
        let mut row = vec![UPoly::zero(); size];
        for (k, c) in f.iter().rev().enumerate() {
            row[shift + k] = c.clone();
        }
        rows.push(row);
    }
    for shift in 0..m {
        let mut row = vec![UPoly::zero(); size];
        for (k, c) in g.iter().rev().enumerate() {
            row[shift + k] = c.clone();
        }
        rows.push(row);
    }
    det_upoly(rows)
}

/// A rational strictly between the numbers `lo < hi`, as simple as possible.
fn rational_between(lo: &Algebraic, hi: &Algebraic) -> Q {
    let (mut a, mut b) = (lo.clone(), hi.clone());
    let four = Q::from_integer(4.into());
    loop {
        let ((_, ahi), (blo, _)) = (a.interval(), b.interval());
        if ahi < blo {
            // (ahi, blo) lies strictly between the two numbers.
            return simplest_between(&ahi, &blo);
        }
        let (alo, ahi) = a.interval();
        let (blo, bhi) = b.interval();
        a = a.refine(&((&ahi - &alo) / &four));
        b = b.refine(&((&bhi - &blo) / &four));
    }
}

/// The rational with the smallest denominator (then numerator) strictly
/// inside (l, r), l < r, by continued fractions.
fn simplest_between(l: &Q, r: &Q) -> Q {
    let fl = l.floor();
    if &fl + Q::one() < *r {
        return fl + Q::one();
    }
    let frac_l = l - &fl;
    let frac_r = r - &fl;
    if frac_l.is_zero() {
        // (fl, r) with r ≤ fl + 1: fl + 1/k for the least k with 1/k < frac_r.
        let k = (Q::one() / &frac_r).floor() + Q::one();
        return fl + Q::one() / k;
    }
    fl + Q::one() / simplest_between(&(Q::one() / frac_r), &(Q::one() / frac_l))
}

/// The exact stability analysis of χ(z; Φ) over Φ > 0.
///
/// ```
/// let chi = poly::Poly::parse("z^2 - 2*(1 - Phi^2/2)*z + 1")?; // False Euler
/// let report = poly::stability::analyze(&chi)?;
/// assert_eq!(report.phi_max.unwrap().to_string(), "2");
/// assert_eq!(report.boundary, Some(poly::stability::Boundary::DoubleRootAtMinusOne));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn analyze(charpoly: &Poly) -> Result<StabilityReport, StabilityError> {
    let chi = Charpoly::new(charpoly)?;
    let conditions = critical_conditions(&chi);

    // Every positive root of every non-trivial condition, merged exactly.
    let mut points: Vec<CriticalPoint> = Vec::new();
    for (name, cond) in &conditions {
        if cond.degree().unwrap_or(0) == 0 {
            continue;
        }
        for root in Algebraic::positive_roots(cond) {
            match points.iter_mut().find(|p| p.at == root) {
                Some(p) if p.conditions.contains(name) => {}
                Some(p) => p.conditions.push(name),
                None => points.push(CriticalPoint { at: root, conditions: vec![name] }),
            }
        }
    }
    points.sort_by(|x, y| x.at.cmp(&y.at));
    // Narrow intervals make the printed "root of ... in [a, b]" readable.
    let width = Q::new(1.into(), 1024.into());
    for p in &mut points {
        p.at = p.at.refine(&width);
    }

    // The class on each open interval, at a rational sample.
    let zero = Algebraic::zero();
    let mut samples = Vec::with_capacity(points.len() + 1);
    for k in 0..=points.len() {
        let lo = if k == 0 { &zero } else { &points[k - 1].at };
        let sample = match points.get(k) {
            Some(hi) => rational_between(lo, &hi.at),
            None => {
                let (_, hi) = lo.interval();
                hi.floor() + Q::one()
            }
        };
        samples.push(sample);
    }
    let classes: Vec<RootClass> =
        samples.iter().map(|s| class_at(charpoly, s)).collect::<Result<_, _>>()?;
    let at_classes: Vec<Option<RootClass>> =
        points.iter().map(|p| class_at_algebraic(charpoly, &p.at)).collect::<Result<_, _>>()?;

    // Merge intervals across critical points where nothing changes.
    let mut intervals = vec![ClassInterval {
        lo: zero.clone(),
        hi: None,
        class: classes[0],
        sample: samples[0].clone(),
    }];
    let mut class_changes = Vec::new();
    for (k, point) in points.iter().enumerate() {
        let (from, to, at_class) = (classes[k], classes[k + 1], at_classes[k]);
        if from == to && (at_class.is_none() || at_class == Some(from)) {
            continue;
        }
        class_changes.push(ClassChange { at: point.at.clone(), from, to, at_class });
        intervals.last_mut().expect("one interval at least").hi = Some(point.at.clone());
        intervals.push(ClassInterval {
            lo: point.at.clone(),
            hi: None,
            class: to,
            sample: samples[k + 1].clone(),
        });
    }

    // The stability limit: walk up from Φ = 0 while everything is bounded.
    let mut phi_max = None;
    let mut bounded_at_phi_max = None;
    let mut bounded_for_all = classes[0].is_bounded();
    if bounded_for_all {
        for (k, point) in points.iter().enumerate() {
            let at_bounded = match at_classes[k] {
                Some(c) => Some(c.is_bounded()),
                // Between two bounded intervals no root can be outside the
                // circle at the point itself; only a repeated root on it
                // could break boundedness there.
                None if classes[k + 1].is_bounded() => {
                    if point.conditions.contains(&"discriminant") {
                        None
                    } else {
                        Some(true)
                    }
                }
                None => None,
            };
            if at_bounded == Some(true) && classes[k + 1].is_bounded() {
                continue;
            }
            phi_max = Some(point.at.clone());
            bounded_at_phi_max = at_bounded;
            bounded_for_all = false;
            break;
        }
    }
    let boundary = phi_max.as_ref().map(|m| boundary_at(&chi, &conditions, m));
    Ok(StabilityReport {
        degree: chi.degree(),
        phi_max,
        bounded_for_all,
        bounded_at_phi_max,
        boundary,
        class_changes,
        intervals,
        critical_points: points,
    })
}

/// What happens at the stability limit, from which conditions vanish there.
fn boundary_at(chi: &Charpoly, conditions: &[(&'static str, UPoly)], at: &Algebraic) -> Boundary {
    let vanishes = |p: &UPoly| at.is_root_of(p);
    let one = Q::one();
    let minus_one = -Q::one();
    let named = |name: &str| {
        conditions
            .iter()
            .find(|(n, _)| *n == name)
            .is_some_and(|(_, p)| !p.is_zero() && vanishes(p))
    };
    let at_minus_one = vanishes(&chi.value_at_z(&minus_one));
    let at_plus_one = vanishes(&chi.value_at_z(&one));
    if at_minus_one && vanishes(&chi.derivative_at_z(&minus_one)) {
        Boundary::DoubleRootAtMinusOne
    } else if at_plus_one && vanishes(&chi.derivative_at_z(&one)) {
        Boundary::DoubleRootAtPlusOne
    } else if at_plus_one {
        Boundary::RootThroughPlusOne
    } else if at_minus_one {
        Boundary::RootThroughMinusOne
    } else if named("leading coefficient") {
        Boundary::RootFromInfinity
    } else if named("|z|^2 = 1") || named("z_i z_j = 1") {
        if named("discriminant") {
            Boundary::RepeatedPairOnCircle
        } else {
            Boundary::ComplexPairLeavesCircle
        }
    } else if named("discriminant") {
        Boundary::RepeatedPairOnCircle
    } else {
        Boundary::Other
    }
}

/// Substitutes rational values for every parameter except Φ (and z).
pub fn substitute_params(charpoly: &Poly, values: &HashMap<Sym, Q>) -> Poly {
    charpoly.eval_partial(values)
}
