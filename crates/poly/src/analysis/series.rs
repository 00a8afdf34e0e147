//! Exact Taylor series of the numerical frequency Ψ(Φ) and of |z|².
//!
//! [`Series`] is a power series over Q truncated after Φ^order, with the
//! arithmetic the frequency needs: products, inverse, square root, the
//! integral-defined functions atan, asin and log, exp, and composition.
//! Every coefficient is exact.
//!
//! For a second-order χ = a z² + b z + c with p = −b/(2a), q = c/a and a
//! complex pair z = p ± j√(q − p²), the angle increment satisfies
//! cos Ψ = p/√q, equivalently tan Ψ = √(q − p²)/p, and |z|² = q
//! (section 4). Near Φ = 0 a consistent method has q − p² = Φ^{2m} g(Φ) with
//! g(0) > 0, so Ψ = atan(Φ^m √g / p) is a power series in Φ. When g(0) is not
//! the square of a rational, Ψ = √d · (series over Q) for the square-free
//! part d of g(0); [`psi_series_scaled`] returns that form.
//!
//! Orders: the dispersion order is the exponent k of the first non-zero term
//! of Ψ − Φ (per-step phase error c Φ^k), the dissipation order the exponent
//! of the first non-zero term of |z|² − 1 (|z| − 1 has the same exponent and
//! half the coefficient).

use std::fmt;

use num_traits::{One, Signed, Zero};

use crate::error::{Error, ErrorKind};
use crate::{Poly, Sym, UPoly, Q};

/// A power series Σ c_k x^k over Q, known up to and including x^order.
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct Series {
    c: Vec<Q>,
}

impl Series {
    /// From coefficients c_0..=c_order (the length fixes the order).
    pub fn new(c: Vec<Q>) -> Series {
        assert!(!c.is_empty(), "a series needs at least its constant term");
        Series { c }
    }

    /// The constant `q` to the given order.
    pub fn constant(q: Q, order: usize) -> Series {
        let mut c = vec![Q::zero(); order + 1];
        c[0] = q;
        Series { c }
    }

    /// The variable x.
    pub fn x(order: usize) -> Series {
        Series::from_upoly(&UPoly::x(), order)
    }

    /// A polynomial, truncated.
    pub fn from_upoly(p: &UPoly, order: usize) -> Series {
        Series { c: (0..=order).map(|k| p.coeff(k)).collect() }
    }

    /// The highest power kept.
    pub fn order(&self) -> usize {
        self.c.len() - 1
    }

    /// Coefficients c_0..=c_order.
    pub fn coeffs(&self) -> &[Q] {
        &self.c
    }

    /// The coefficient of x^k (zero past the order).
    pub fn coeff(&self, k: usize) -> Q {
        self.c.get(k).cloned().unwrap_or_else(Q::zero)
    }

    /// The exponent of the first non-zero coefficient, `None` if all known
    /// coefficients vanish.
    pub fn valuation(&self) -> Option<usize> {
        self.c.iter().position(|c| !c.is_zero())
    }

    /// Sum.
    pub fn add(&self, o: &Series) -> Series {
        let n = self.order().min(o.order());
        Series { c: (0..=n).map(|k| &self.c[k] + &o.c[k]).collect() }
    }

    /// Difference.
    pub fn sub(&self, o: &Series) -> Series {
        let n = self.order().min(o.order());
        Series { c: (0..=n).map(|k| &self.c[k] - &o.c[k]).collect() }
    }

    /// Every coefficient times `q`.
    pub fn scale(&self, q: &Q) -> Series {
        Series { c: self.c.iter().map(|c| c * q).collect() }
    }

    /// Product, truncated to the smaller order.
    pub fn mul(&self, o: &Series) -> Series {
        let n = self.order().min(o.order());
        let mut c = vec![Q::zero(); n + 1];
        for (i, a) in self.c.iter().enumerate().take(n + 1) {
            if a.is_zero() {
                continue;
            }
            for (j, b) in o.c.iter().enumerate().take(n + 1 - i) {
                c[i + j] += a * b;
            }
        }
        Series { c }
    }

    /// 1/s; `None` when the constant term is zero.
    pub fn inverse(&self) -> Option<Series> {
        if self.c[0].is_zero() {
            return None;
        }
        let inv0 = self.c[0].recip();
        let mut r = vec![inv0.clone()];
        for k in 1..=self.order() {
            let mut s = Q::zero();
            for j in 1..=k {
                s += &self.c[j] * &r[k - j];
            }
            r.push(-s * &inv0);
        }
        Some(Series { c: r })
    }

    /// s / o; `None` when o has a zero constant term.
    pub fn div(&self, o: &Series) -> Option<Series> {
        Some(self.mul(&o.inverse()?))
    }

    /// The square root with positive constant term; `None` unless the
    /// constant term is the square of a non-zero rational.
    pub fn sqrt(&self) -> Option<Series> {
        let r0 = rational_sqrt(&self.c[0])?;
        if r0.is_zero() {
            return None;
        }
        // r² = s, coefficient by coefficient: 2 r0 r_k = s_k − Σ_{0<j<k} r_j r_{k−j}.
        let two_r0 = &r0 * Q::from_integer(2.into());
        let mut r = vec![r0];
        for k in 1..=self.order() {
            let mut s = self.c[k].clone();
            for j in 1..k {
                s -= &r[j] * &r[k - j];
            }
            r.push(s / &two_r0);
        }
        Some(Series { c: r })
    }

    /// The derivative (one order lower).
    pub fn derivative(&self) -> Series {
        if self.order() == 0 {
            return Series::constant(Q::zero(), 0);
        }
        Series { c: (1..=self.order()).map(|k| &self.c[k] * Q::from_integer(k.into())).collect() }
    }

    /// The integral with constant term `c0` (one order higher).
    pub fn integral(&self, c0: Q) -> Series {
        let mut c = vec![c0];
        c.extend(self.c.iter().enumerate().map(|(k, a)| a / Q::from_integer((k + 1).into())));
        Series { c }
    }

    /// atan(s) = ∫ s′/(1 + s²); `None` unless s has zero constant term.
    pub fn atan(&self) -> Option<Series> {
        if !self.c[0].is_zero() {
            return None;
        }
        let denom = Series::constant(Q::one(), self.order()).add(&self.mul(self));
        Some(self.derivative().div(&denom)?.integral(Q::zero()))
    }

    /// asin(s) = ∫ s′/√(1 − s²); `None` unless s has zero constant term.
    pub fn asin(&self) -> Option<Series> {
        if !self.c[0].is_zero() {
            return None;
        }
        let root = Series::constant(Q::one(), self.order()).sub(&self.mul(self)).sqrt()?;
        Some(self.derivative().div(&root)?.integral(Q::zero()))
    }

    /// log(s) = ∫ s′/s; `None` unless the constant term is 1.
    pub fn log(&self) -> Option<Series> {
        if !self.c[0].is_one() {
            return None;
        }
        Some(self.derivative().div(self)?.integral(Q::zero()))
    }

    /// exp(s) from e′ = s′ e; `None` unless s has zero constant term.
    pub fn exp(&self) -> Option<Series> {
        if !self.c[0].is_zero() {
            return None;
        }
        let d = self.derivative();
        let mut e = vec![Q::one()];
        // k e_k = Σ_{j=1}^{k} j s_j e_{k−j}.
        for k in 1..=self.order() {
            let mut acc = Q::zero();
            for j in 1..=k {
                acc += &d.c[j - 1] * &e[k - j];
            }
            e.push(acc / Q::from_integer(k.into()));
        }
        Some(Series { c: e })
    }

    /// s(inner(x)); `None` unless `inner` has zero constant term.
    pub fn compose(&self, inner: &Series) -> Option<Series> {
        if !inner.c[0].is_zero() {
            return None;
        }
        let n = self.order().min(inner.order());
        let mut acc = Series::constant(Q::zero(), n);
        for c in self.c.iter().take(n + 1).rev() {
            acc = acc.mul(inner).add(&Series::constant(c.clone(), n));
        }
        Some(acc)
    }

    /// Divides by x^k, losing k orders; `None` if a dropped coefficient is
    /// non-zero.
    pub fn shift_down(&self, k: usize) -> Option<Series> {
        if k > self.order() || self.c[..k].iter().any(|c| !c.is_zero()) {
            return None;
        }
        Some(Series { c: self.c[k..].to_vec() })
    }

    /// Multiplies by x^k (keeping the order).
    pub fn shift_up(&self, k: usize) -> Series {
        let mut c = vec![Q::zero(); k];
        c.extend(self.c.iter().take(self.c.len().saturating_sub(k)).cloned());
        Series { c }
    }

    /// Plain text, e.g. `Phi + 1/24*Phi^3 + O(Phi^6)`.
    pub fn to_string_in(&self, var: &str) -> String {
        let body = UPoly::new(self.c.clone()).to_string_in(var);
        format!("{body} + O({var}^{})", self.order() + 1)
    }
}

impl fmt::Display for Series {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_string_in("x"))
    }
}

/// √q when q is the square of a rational.
fn rational_sqrt(q: &Q) -> Option<Q> {
    if q.is_negative() {
        return None;
    }
    let n = q.numer().sqrt();
    let d = q.denom().sqrt();
    (&n * &n == *q.numer() && &d * &d == *q.denom()).then(|| Q::new(n, d))
}

/// The z-coefficients (c, b, a) of a second-order χ as polynomials in Φ.
fn quadratic(charpoly: &Poly) -> Result<[UPoly; 3], Error> {
    let (z, phi) = (Sym::z(), Sym::phi());
    if let Some(s) = charpoly.symbols().into_iter().find(|&s| s != z && s != phi) {
        return Err(Error::analysis(
            ErrorKind::ExtraSymbol,
            format!(
                "characteristic polynomial {charpoly} still contains the parameter {s}; \
                 expected a polynomial in z and Phi only"
            ),
        ));
    }
    let cs = charpoly.coeffs_in(z);
    if cs.len() != 3 {
        return Err(Error::analysis(
            ErrorKind::NotSecondOrder,
            format!(
                "the frequency series needs a second-order characteristic polynomial, \
                 got degree {} in z",
                cs.len() - 1
            ),
        ));
    }
    let u = |p: &Poly| p.to_upoly(phi).expect("only Phi remains");
    let a = u(&cs[2]);
    if a.coeff(0).is_zero() {
        return Err(Error::analysis(
            ErrorKind::NotOscillatory,
            "the leading coefficient of the characteristic polynomial vanishes at Phi = 0",
        ));
    }
    Ok([u(&cs[0]), u(&cs[1]), a])
}

/// p = −b/(2a) and q = c/a as series to `order`.
fn p_q_series(chi: &[UPoly; 3], order: usize) -> (Series, Series) {
    let [c, b, a] = chi;
    let inv_a = Series::from_upoly(a, order).inverse().expect("a(0) != 0 checked");
    let p = Series::from_upoly(b, order).mul(&inv_a).scale(&-Q::new(1.into(), 2.into()));
    let q = Series::from_upoly(c, order).mul(&inv_a);
    (p, q)
}

/// Ψ(Φ) = √d · Σ c_k Φ^k, exact: the square-free factor d (1 when Ψ is a
/// series over Q) and the coefficients of Φ^0..=Φ^order.
pub fn psi_series_scaled(charpoly: &Poly, order: usize) -> Result<(Q, Vec<Q>), Error> {
    let chi = quadratic(charpoly)?;
    let not_osc = || {
        Error::analysis(
            ErrorKind::NotOscillatory,
            "the roots are not a complex pair with Psi near 0 for small Phi > 0",
        )
    };
    // Find the valuation 2m of q − p² first, then work 2m orders deeper.
    let probe = order + 8;
    let (p, q) = p_q_series(&chi, probe);
    let s = q.sub(&p.mul(&p));
    let v = s.valuation().ok_or_else(not_osc)?;
    if v % 2 == 1 || v == 0 || !s.coeff(v).is_positive() || !p.coeff(0).is_positive() {
        return Err(not_osc());
    }
    let m = v / 2;
    let (p, q) = p_q_series(&chi, order + v);
    let g = q.sub(&p.mul(&p)).shift_down(v).expect("valuation v");
    // √g = √d · √(g/d·...): split g(0) = d·r² with d square-free, r rational.
    let (d, r) = split_square(&g.coeff(0));
    let sqrt_g = g.scale(&d.recip()).sqrt().expect("g(0)/d is a rational square");
    debug_assert_eq!(sqrt_g.coeff(0), r);
    // tan Ψ = Φ^m √d √(g/d) / p. With t = Φ^m √(g/d) / p (rational), atan
    // of √d·t is √d · Σ (−d)^k t^{2k+1}/(2k+1): a rational series times √d.
    let t = sqrt_g.div(&p.truncate(order)).expect("p(0) > 0 checked");
    let t = t.truncate(order).shift_up(m);
    let psi_over_sqrt_d = if d.is_one() {
        t.atan().expect("t(0) = 0")
    } else {
        // ∫ t′ / (1 + d t²).
        let denom = Series::constant(Q::one(), order).add(&t.mul(&t).scale(&d));
        t.derivative().div(&denom).expect("constant term 1").integral(Q::zero())
    };
    Ok((d, psi_over_sqrt_d.truncate(order).c))
}

impl Series {
    /// The same series known only to `order` (no-op when already lower).
    pub fn truncate(&self, order: usize) -> Series {
        Series { c: self.c.iter().take(order + 1).cloned().collect() }
    }
}

/// g0 = d · r² with d a square-free positive integer (as far as trial
/// division up to 10⁵ tells) and r a positive rational.
fn split_square(g0: &Q) -> (Q, Q) {
    let n = g0.numer() * g0.denom();
    let (root, rest) = crate::univariate::algebraic::square_part(&n, 100_000);
    (Q::from_integer(rest), Q::new(root, g0.denom().clone()))
}

/// The Taylor coefficients of Ψ(Φ), Φ^0..=Φ^order, exact.
///
/// ```
/// let chi = poly::Poly::parse("z^2 - 2*(1 - Phi^2/2)*z + 1")?; // False Euler
/// let psi = poly::advanced::series::psi_series(&chi, 3)?;
/// assert_eq!(psi, vec![poly::q(0, 1), poly::q(1, 1), poly::q(0, 1), poly::q(1, 24)]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn psi_series(charpoly: &Poly, order: usize) -> Result<Vec<Q>, Error> {
    let (d, c) = psi_series_scaled(charpoly, order)?;
    if !d.is_one() {
        return Err(Error::analysis(
            ErrorKind::IrrationalSeries,
            format!("Psi is sqrt({d}) times a series over Q, not a series over Q"),
        ));
    }
    Ok(c)
}

/// The Taylor coefficients of |z|² = q(Φ) of the complex pair,
/// Φ^0..=Φ^order.
pub fn modulus_sq_series(charpoly: &Poly, order: usize) -> Result<Vec<Q>, Error> {
    let chi = quadratic(charpoly)?;
    Ok(p_q_series(&chi, order).1.c)
}

/// The Taylor coefficients of |z| = √q(Φ), Φ^0..=Φ^order.
pub fn modulus_series(charpoly: &Poly, order: usize) -> Result<Vec<Q>, Error> {
    let chi = quadratic(charpoly)?;
    let q = p_q_series(&chi, order).1;
    q.sqrt().map(|s| s.c).ok_or_else(|| {
        Error::analysis(ErrorKind::IrrationalSeries, "|z|^2 at Phi = 0 is not a rational square")
    })
}

/// The leading term c Φ^k of an error series.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LeadingTerm {
    /// The exponent k.
    pub order: usize,
    /// The coefficient c (non-zero).
    pub coeff: Q,
}

/// How far [`dispersion_order`] looks for a non-zero term of Ψ − Φ.
pub const DISPERSION_SEARCH_ORDER: usize = 64;

/// The leading term of Ψ − Φ; `None` when every coefficient up to
/// [`DISPERSION_SEARCH_ORDER`] vanishes. When Ψ = √d·(series over Q) with
/// d ≠ 1 the error has order 1 and `coeff` is reported for the rational
/// part only, so this returns an [`ErrorKind::IrrationalSeries`] error.
pub fn dispersion_order(charpoly: &Poly) -> Result<Option<LeadingTerm>, Error> {
    let mut order = 8;
    loop {
        let psi = psi_series(charpoly, order)?;
        for (k, c) in psi.iter().enumerate() {
            let e = if k == 1 { c - Q::one() } else { c.clone() };
            if !e.is_zero() {
                return Ok(Some(LeadingTerm { order: k, coeff: e }));
            }
        }
        if order >= DISPERSION_SEARCH_ORDER {
            return Ok(None);
        }
        order = (order * 2).min(DISPERSION_SEARCH_ORDER);
    }
}

/// The leading term of |z|² − 1, exact; `None` when |z|² = 1 identically
/// (no dissipation, e.g. False Euler). |z| − 1 has the same order and half
/// the coefficient.
pub fn dissipation_order(charpoly: &Poly) -> Result<Option<LeadingTerm>, Error> {
    let [c, _, a] = quadratic(charpoly)?;
    // |z|² − 1 = (c − a)/a, and a(0) ≠ 0: the valuation is that of c − a.
    let diff = &c - &a;
    let Some(k) = diff.coeffs().iter().position(|x| !x.is_zero()) else {
        return Ok(None);
    };
    Ok(Some(LeadingTerm { order: k, coeff: diff.coeff(k) / a.coeff(0) }))
}

impl crate::Derivation {
    /// Ψ(Φ), the angle per step of the principal root, as an exact series:
    /// the coefficients of Φ^0..=Φ^`order` (Appendix A, for any
    /// second-order method), with the method's other parameters bound.
    ///
    /// ```
    /// let d = poly::derive(&poly::builtin("false_euler")?)?;
    /// let psi = d.psi_series(&poly::Params::new(), 5)?;
    /// assert_eq!(psi[3], poly::q(1, 24)); // Ψ = Φ + Φ³/24 + …
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn psi_series(&self, params: &crate::Params, order: usize) -> Result<Vec<Q>, crate::Error> {
        let values = self.bind(params)?;
        psi_series(&self.charpoly().eval_partial(&values), order)
    }

    /// |z|² of the complex pair as an exact series in Φ (coefficients of
    /// Φ^0..=Φ^`order`), with the method's other parameters bound.
    pub fn modulus_sq_series(
        &self,
        params: &crate::Params,
        order: usize,
    ) -> Result<Vec<Q>, crate::Error> {
        let values = self.bind(params)?;
        modulus_sq_series(&self.charpoly().eval_partial(&values), order)
    }
}
