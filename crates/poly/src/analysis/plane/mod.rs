//! The method on the scalar test equation y' = λy, in the complex plane of
//! w = hλ: order and error constant, the stable intervals of the real and
//! imaginary axes, A- and L-stability, A(α) and ρ∞, all exact. And, on the
//! oscillator, the orders and constants of dispersion and dissipation.
//!
//! "Stable" at w means the root condition: every root of χ(z, w) has
//! |z| ≤ 1, and those on the circle are simple.
//!
//! - `scalar.rs`: χ(z, w) from a derivation (a scalar program, or the
//!   scalar form of an oscillator program that treats y and v alike).
//! - `principal.rs`: the principal root as a power series.
//! - `sector.rs`: rays, the axes' limits and A(α).
//! - here: the report, ρ∞ (the largest modulus of the roots as the step
//!   grows without bound), and the series' leading terms.

mod principal;
mod scalar;
mod sector;

use num_traits::{One, Zero};

pub use sector::Sector;

use crate::analysis::stability::point::circle_counts;
use crate::analysis::stability::{verdict, Stability};
use crate::arith::rational::{add, mul};
use crate::error::{Error, ErrorKind};
use crate::multivariate::constants as field;
use crate::{Algebraic, Derivation, Params, Poly, Sym, UPoly, Q};
use principal::{inverse_factorial, Branch, NoBranch, C};
pub(crate) use scalar::at_imaginary;

/// The most terms of a series searched for its first nonzero one.
pub const MAX_SERIES_TERMS: usize = 40;

/// The method on y' = λy in the complex plane of w = hλ.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlaneReport {
    /// χ(z, w), primitive in z.
    pub charpoly: Poly,
    /// Whether w = 0 is stable (the root condition at w = 0, zero-stability).
    pub zero_stable: bool,
    /// The order p: e^w − z₁(w) = C·w^(p+1) + O(w^(p+2)) for the principal
    /// root z₁ (z₁(0) = 1). `None` when no simple root of χ(z, 0) is 1.
    pub order: Option<u32>,
    /// C, exact (rational, or in the field of the method's constants).
    pub error_constant: Option<Poly>,
    /// The supremum of r with (−r, 0] stable; `None` when all of (−∞, 0] is.
    pub real_limit: Option<Algebraic>,
    /// The supremum of r with i·(−r, r) stable; `None` when the whole axis is.
    pub imag_limit: Option<Algebraic>,
    /// Whether every w with Re w ≤ 0 is stable.
    pub a_stable: bool,
    /// The largest sector |arg(−w)| < α inside the region.
    pub a_alpha: Sector,
    /// A-stable, with every root tending to 0 as w → ∞.
    pub l_stable: bool,
    /// The limit of the largest |z| as w → ∞; `None` when a root tends to ∞.
    pub rho_inf: Option<Algebraic>,
}

impl Derivation {
    /// The method on y' = λy in the complex plane of w = hλ, every parameter
    /// bound in `params`. For an oscillator program, its scalar form
    /// ([`Derivation::scalar_charpoly`]).
    ///
    /// ```
    /// let d = poly::derive(&poly::Method::builtin("rk4")?)?;
    /// let r = d.plane(&poly::Params::new())?;
    /// assert_eq!(r.order, Some(4));
    /// assert_eq!(r.error_constant.unwrap().to_string(), "1/120");
    /// assert_eq!(r.imag_limit.unwrap().to_string(), "2*sqrt(2)");
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn plane(&self, params: &Params) -> Result<PlaneReport, Error> {
        plane_of(self.scalar_charpoly(params)?)
    }
}

/// [`Derivation::plane`] of a χ(z, w) (primitive in z).
pub fn plane_of(chi: Poly) -> Result<PlaneReport, Error> {
    let zero_stable = zero_stable(&chi)?;
    let (order, error_constant) = match order(&chi)? {
        Some((p, c)) => (Some(p), Some(c)),
        None => (None, None),
    };
    let (one, zero) = (Q::one(), Q::zero());
    let (real_limit, imag_limit) = if zero_stable {
        (
            sector::limit_along(&chi, (&-one.clone(), &zero))?,
            sector::limit_along(&chi, (&zero, &one))?,
        )
    } else {
        (Some(Algebraic::zero()), Some(Algebraic::zero()))
    };
    let a_alpha = if zero_stable && real_limit.is_none() {
        sector::sector(&chi, imag_limit.is_none())?
    } else {
        Sector::Empty
    };
    let a_stable = a_alpha == Sector::HalfPlane && imag_limit.is_none();
    let rho_inf = rho_at_infinity(&chi, Sym::w())?;
    let l_stable = a_stable && rho_inf.as_ref().is_some_and(|r| r.sign().is_eq());
    // Isolating intervals narrowed for display; the numbers are unchanged.
    let width = Q::new(1.into(), (1i64 << 40).into());
    let narrow = |x: Option<Algebraic>| x.map(|x| x.refine(&width));
    let (real_limit, imag_limit, rho_inf) =
        (narrow(real_limit), narrow(imag_limit), narrow(rho_inf));
    let a_alpha = match a_alpha {
        Sector::Angle { tan } => Sector::Angle { tan: tan.refine(&width) },
        other => other,
    };
    Ok(PlaneReport {
        charpoly: chi,
        zero_stable,
        order,
        error_constant,
        real_limit,
        imag_limit,
        a_stable,
        a_alpha,
        l_stable,
        rho_inf,
    })
}

/// The root condition at w = 0. With constants, the roots are those of
/// the norm (a superset: χ's and its conjugates'), and the repeated ones
/// those of the norm of gcd(f, f') over F.
impl crate::lang::multistep::Multistep {
    /// Whether ρ(z) = Σ α_j z^j satisfies the root condition (every root
    /// in the closed unit disc, those on the circle simple), decided
    /// exactly on χ(z, 0) of the method on y' = λy.
    pub fn zero_stable(&self) -> Result<bool, Error> {
        zero_stable(crate::derive(&self.scalar_method()?)?.charpoly())
    }
}

fn zero_stable(chi: &Poly) -> Result<bool, Error> {
    let z = Sym::z();
    let at0 = field::reduce(&chi.subs(Sym::w(), &Poly::zero()));
    let f = at0.coeffs_in(z);
    // Over Q the gcd of integer forms (modular, then primitive remainders):
    // Euclid over the field swells the coefficients (sand_cc3's ρ, degree
    // 9). Only the roots of the gcd are read, so any scalar multiple does.
    let repeated = match at0.to_upoly(z) {
        Some(u) if !u.is_zero() && !field::has_generators(&at0) => {
            Poly::from_upoly(z, &u.gcd(&u.derivative())).coeffs_in(z)
        }
        _ => scalar::gcd(&f, &scalar::derivative(&f)),
    };
    let in_z = |c: &[Poly]| -> Result<UPoly, Error> {
        let p = Poly::from_coeffs_in(z, c);
        let p = if field::has_generators(&p) { field::norm(&p) } else { p };
        p.to_upoly(z).ok_or_else(|| {
            Error::analysis(ErrorKind::ExtraSymbol, format!("χ(z, 0) = {at0}: expected z only"))
        })
    };
    let (f, repeated) = (in_z(&f)?, in_z(&repeated)?);
    Ok(circle_counts(&f).outside == 0
        && (repeated.degree().unwrap_or(0) == 0 || circle_counts(&repeated).on == 0))
}

/// The order and error constant from the principal root's series.
fn order(chi: &Poly) -> Result<Option<(u32, Poly)>, Error> {
    let (z, w) = (Sym::z(), Sym::w());
    let at = |p: &Poly| field::reduce(&p.subs(z, &Poly::one()).subs(w, &Poly::zero()));
    if !at(chi).is_zero() {
        return Ok(None);
    }
    let a10 = at(&chi.derivative(z));
    let a01 = at(&chi.derivative(w));
    let Some(inv) = field::inverse(&a10) else {
        return Ok(None);
    };
    let nu0 = field::reduce(&-(&a01 * &inv));
    let mut b = match Branch::<Poly>::new(chi, w, C::real(nu0)) {
        Ok(Some(b)) => b,
        Ok(None) | Err(NoBranch::NotARoot | NoBranch::Repeated) => return Ok(None),
    };
    for n in 1..=MAX_SERIES_TERMS {
        while b.nu.len() < n {
            b.grow();
        }
        let zn = &b.z_coeffs()[n];
        let d = field::reduce(&(&Poly::constant(inverse_factorial(n)) - &zn.re));
        if !d.is_zero() {
            return Ok(Some((n as u32 - 1, d)));
        }
    }
    Err(series_error(format!(
        "e^w − z₁(w) vanishes to w^{MAX_SERIES_TERMS}: expected a method of lower order"
    )))
}

fn series_error(msg: String) -> Error {
    Error::analysis(ErrorKind::NoSeries, msg)
}

/// The limit of the largest |z| of χ's roots as `t` → ∞ (any direction):
/// the roots of the coefficient of t's top power tend to the roots of that
/// polynomial in z, and one escapes to ∞ when it loses degree (`None`).
///
/// The largest modulus ρ of the roots z_i of g: ρ² is the largest positive
/// product z_i z_j (|z_i z_j| ≤ ρ², and z·z̄ or r·r attains it), so ρ is the
/// largest real root of Res_y(g(y), yⁿ g(x²/y)) = ∏(x² − z_i z_j).
pub fn rho_at_infinity(chi: &Poly, t: Sym) -> Result<Option<Algebraic>, Error> {
    let z = Sym::z();
    let a = chi.coeffs_in(z);
    let top = a.iter().map(|c| c.degree_in(t)).max().unwrap_or(0);
    let lim: Vec<Poly> =
        a.iter().map(|c| c.coeffs_in(t).get(top as usize).cloned().unwrap_or_default()).collect();
    if lim.last().is_none_or(Poly::is_zero) {
        return Ok(None);
    }
    let low = lim.iter().position(|c| !c.is_zero()).unwrap_or(0);
    let g = &lim[low..];
    if g.len() == 1 {
        return Ok(Some(Algebraic::zero()));
    }
    if g.iter().any(field::has_generators) {
        return rho_with_constants(g).map(Some);
    }
    // The roots of Φⁿ g(z/Φ) are Φ·z_i: all inside the unit circle exactly
    // for Φ < 1/ρ, so the exact engine's stability limit is 1/ρ.
    let (z, phi) = (Sym::z(), Sym::phi());
    let n = g.len() - 1;
    let scaled = Poly::from_coeffs_in(
        z,
        &g.iter()
            .enumerate()
            .map(|(k, c)| c * &Poly::sym(phi).pow((n - k) as u32))
            .collect::<Vec<_>>(),
    );
    // Every root Φ·z_i moves out along its ray at the same rate, so the
    // first Φ where a root reaches the circle is 1/ρ whatever happens
    // there: a limit, or a repeated root on the circle that χ alone leaves
    // undecided. Either way it is a modulus, not a verdict on boundedness.
    let limit = match verdict(&scaled)? {
        Stability::Limited { phi_max, .. } => phi_max,
        Stability::UndecidedAt { at, .. } if at.sign().is_gt() => at,
        other => {
            return Err(Error::analysis(
                ErrorKind::NoSeries,
                format!(
                    "ρ∞: the scaled limit polynomial is {}, expected a finite limit",
                    other.name()
                ),
            ))
        }
    };
    Ok(Some(reciprocal(&limit)))
}

/// 1/a for a positive algebraic number: the reversed defining polynomial,
/// and the image of an isolating interval that excludes 0.
fn reciprocal(a: &Algebraic) -> Algebraic {
    if let Some(r) = a.as_rational() {
        return Algebraic::from_rational(r.recip());
    }
    let mut width = Q::new(1.into(), 16.into());
    loop {
        let (lo, hi) = a.refine(&width).interval();
        if lo > Q::zero() {
            let p = a.defining_poly().reversed();
            if let Some(r) = Algebraic::from_isolating(&p, &hi.recip(), &lo.recip()) {
                return r;
            }
        }
        width = &width / &Q::from_integer(16.into());
    }
}

/// The largest modulus of the roots of g (lowest coefficient first, g(0) ≠
/// 0, degree 1 or 2) over the field F of exact constants, exactly: ρ is a
/// root of a polynomial P(X) over F (X − |x|, X² − c/a, or (X − s)² − t),
/// hence of its norm N over Q; the root of N within the enclosure of ρ
/// computed in F is ρ.
fn rho_with_constants(g: &[Poly]) -> Result<Algebraic, Error> {
    let x = Sym::new("x");
    let big = |width: &Q| -> (Poly, Q, Q) {
        // P(X), and a rational enclosure [lo, hi] of ρ of about `width`.
        let ap = |p: &Poly| field::approx(p, width);
        let abs = |p: &Poly| if field::sign(p).is_lt() { -p } else { p.clone() };
        let inv = |p: &Poly| field::inverse(p).expect("a nonzero element");
        let xs = Poly::sym(x);
        match g.len() {
            2 => {
                let r = abs(&field::reduce(&(&g[0] * &inv(&g[1]))));
                let v = ap(&r);
                (&xs - &r, &v - width, &v + width)
            }
            _ => {
                let (c, b, a) = (&g[0], &g[1], &g[2]);
                let ainv = inv(a);
                let disc = field::reduce(&(&(b * b) - &(&(a * c) * &Poly::int(4))));
                if field::sign(&disc).is_lt() {
                    // |z|² = c/a for the complex pair.
                    let q = field::reduce(&(c * &ainv));
                    let (lo, hi) = (ap(&q) - width, ap(&q) + width);
                    (&(&xs * &xs) - &q, sqrt_below(&lo), sqrt_above(&hi))
                } else {
                    // ρ = s + √t, s = |b|/(2|a|), t = disc/(4a²).
                    let half = Q::new(1.into(), 2.into());
                    let sgn = abs(&field::reduce(&(b * &ainv))).scale(&half);
                    let t = field::reduce(&(&disc * &(&ainv * &ainv))).scale(&(&half * &half));
                    let (s0, t0) = (ap(&sgn), ap(&t));
                    let p = &(&(&xs - &sgn) * &(&xs - &sgn)) - &t;
                    let tlo = if t0 > *width { &t0 - width } else { Q::zero() };
                    (p, &s0 - width + sqrt_below(&tlo), &s0 + width + sqrt_above(&(&t0 + width)))
                }
            }
        }
    };
    if g.len() > 3 {
        return Err(Error::analysis(
            ErrorKind::NoSeries,
            format!(
                "ρ∞ with exact constants is computed for limit polynomials of degree 1 and 2; \
                 this one has degree {}",
                g.len() - 1
            ),
        ));
    }
    let mut width = Q::new(1.into(), 1_000_000.into());
    let (p, _, _) = big(&width);
    let n = field::norm(&field::reduce(&p)).to_upoly(x).expect("a polynomial in x").squarefree();
    let roots = Algebraic::real_roots(&n);
    for _ in 0..12 {
        let (_, lo, hi) = big(&width);
        let inside: Vec<&Algebraic> = roots
            .iter()
            .filter(|r| {
                let (a, b) = r.refine(&width).interval();
                b >= lo && a <= hi
            })
            .collect();
        if let [only] = inside.as_slice() {
            return Ok((*only).clone());
        }
        width = &width * &width;
    }
    Err(Error::analysis(
        ErrorKind::NoSeries,
        "ρ∞: the enclosure does not single out a root".to_owned(),
    ))
}

/// A rational at most √q (q ≥ 0), within about 2⁻⁶⁰·(1 + √q).
fn sqrt_below(q: &Q) -> Q {
    sqrt_bracket(q).0
}

/// A rational at least √q (q ≥ 0).
fn sqrt_above(q: &Q) -> Q {
    sqrt_bracket(q).1
}

fn sqrt_bracket(q: &Q) -> (Q, Q) {
    if *q <= Q::zero() {
        return (Q::zero(), Q::zero());
    }
    let (mut lo, mut hi) = (Q::zero(), q.clone().max(Q::one()));
    let two = Q::from_integer(2.into());
    let eps = Q::new(1.into(), num_bigint::BigInt::from(1u64 << 60));
    while &hi - &lo > eps {
        let mid = (&lo + &hi) / &two;
        if &mid * &mid <= *q {
            lo = mid;
        } else {
            hi = mid;
        }
        // Keep the sizes small: round to a dyadic rational.
    }
    (lo, hi)
}

/// The leading term c·Φ^(k+1) of a series on the oscillator.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LeadingTerm {
    /// k: the order of the error.
    pub order: u32,
    /// c, exact.
    pub constant: Poly,
}

/// Dispersion and dissipation of the principal root z ≈ e^{iΦ} on the
/// oscillator.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PhaseErrors {
    /// Φ − Ψ(Φ) = c·Φ^(q+1) + …; `None` when the phase is exact.
    pub dispersion: Option<LeadingTerm>,
    /// 1 − |z(Φ)| = d·Φ^(r+1) + …; `None` when |z| ≡ 1 near 0.
    pub dissipation: Option<LeadingTerm>,
}

/// The leading terms of Φ − Ψ and 1 − |z| for χ(z, Φ) (every other symbol a
/// constant of F). `on_circle` says whether |z| ≡ 1 on the first stable
/// interval (decided by the stability engine), which ends the search for a
/// nonzero dissipation term.
pub fn phase_errors(chi: &Poly, on_circle: bool) -> Result<PhaseErrors, Error> {
    // Over Q (no generators) the series runs on rationals; else in F.
    match principal_branch::<Q>(chi)? {
        Some(b) => series_terms(branch_logs(b), on_circle, |q| Poly::constant(q.clone())),
        None => {
            let b = principal_branch::<Poly>(chi)?.expect("every χ is over F");
            series_terms(branch_logs(b), on_circle, field::reduce)
        }
    }
}

/// The coefficients of log z in Φ, from the principal branch's series.
fn branch_logs<T: principal::Scalar>(mut b: Branch<T>) -> impl FnMut(usize) -> C<T> {
    move |n| {
        while b.nu.len() < n {
            b.grow();
        }
        b.log_coeff(n).clone()
    }
}

/// The coefficients of log z in Φ for the principal root z = R(iΦ) of a
/// program generated from a tableau with rational entries, whose χ is
/// (z − R(iΦ))(z − R(−iΦ)) up to a factor (`derive_runge_kutta`): with
/// log R(w) = Σ c_n w^n, the coefficient of Φ^n in log z is c_n·iⁿ. The
/// series of log P and log Q come from (log f)′ = f′/f, a few rational
/// products a term, where the branch of χ solves for z's series first.
/// `None` (the branch of χ decides, errors included) unless R(0) = 1 and
/// R′(0) = 1, so that R(iΦ) is the root z ≈ e^{iΦ}.
fn stability_function_logs(method: &crate::Method) -> Option<impl FnMut(usize) -> C<Q>> {
    if method.is_scalar() {
        return None;
    }
    let r = method.stability_function.0.as_ref()?;
    let (p, q) = (r.0.to_upoly(Sym::w())?, r.1.to_upoly(Sym::w())?);
    let (p0, q0) = (p.coeff(0), q.coeff(0));
    if q0.is_zero() || p0 != q0 {
        return None;
    }
    if (&p.coeff(1) - &q.coeff(1)) / &q0 != Q::one() {
        return None;
    }
    let (mut log_p, mut log_q) = (LogSeries::new(&p, &q0), LogSeries::new(&q, &q0));
    Some(move |n: usize| {
        // (The crate's product and sum reduce by Lehmer's gcd, several
        // times faster than num-rational's operators on small numbers.)
        let c = mul(&add(&log_p.scaled(n), &-log_q.scaled(n)), &Q::new_raw(1.into(), n.into()));
        match n % 4 {
            0 => C { re: c, im: Q::zero() },
            1 => C { re: Q::zero(), im: c },
            2 => C { re: -c, im: Q::zero() },
            _ => C { re: Q::zero(), im: -c },
        }
    })
}

/// log f as a power series, for a polynomial f with f(0) = 1 (given over
/// a common `f0`), as M_k = k·L_k, the coefficients of w·f′/f: from
/// w·f′ = (w·L′)·f, M_k = k·f_k − Σ_{0<j<k} M_j·f_{k−j}, one product a
/// nonzero coefficient of f.
struct LogSeries {
    f: Vec<Q>,
    m: Vec<Q>,
}

impl LogSeries {
    fn new(f: &UPoly, f0: &Q) -> LogSeries {
        let f = if f0.is_one() {
            f.coeffs().to_vec()
        } else {
            f.coeffs().iter().map(|c| c / f0).collect()
        };
        LogSeries { f, m: vec![Q::zero()] }
    }

    /// M_n = n·L_n.
    fn scaled(&mut self, n: usize) -> Q {
        while self.m.len() <= n {
            let k = self.m.len();
            let mut mk = self.f.get(k).map_or_else(Q::zero, |c| mul(c, &Q::from_integer(k.into())));
            for (j, mj) in self.m.iter().enumerate().skip(1) {
                match self.f.get(k - j) {
                    Some(fk) if !fk.is_zero() && !mj.is_zero() => mk = add(&mk, &-mul(mj, fk)),
                    _ => {}
                }
            }
            self.m.push(mk);
        }
        self.m[n].clone()
    }
}

/// The branch z ≈ e^{iΦ}, or `None` where χ's coefficients are not `T`s.
fn principal_branch<T: principal::Scalar>(chi: &Poly) -> Result<Option<Branch<T>>, Error> {
    Branch::new(chi, Sym::phi(), C::i()).map_err(|e| {
        series_error(match e {
            NoBranch::NotARoot => "no root of χ leaves z = 1 as e^{iΦ}: the method is not consistent on the oscillator".to_owned(),
            NoBranch::Repeated => "the root leaving z = 1 as e^{iΦ} is repeated: its series does not exist".to_owned(),
        })
    })
}

/// The first nonzero terms of Φ − Ψ and 1 − |z| from log z = iΨ + ln|z|.
fn series_terms<T: principal::Scalar>(
    mut log_coeff: impl FnMut(usize) -> C<T>,
    on_circle: bool,
    to_poly: impl Fn(&T) -> Poly,
) -> Result<PhaseErrors, Error> {
    let (mut dispersion, mut dissipation) = (None, None);
    for n in 1..=MAX_SERIES_TERMS {
        let log = log_coeff(n);
        if dispersion.is_none() {
            let expected = if n == 1 { T::one() } else { T::zero() };
            let c = expected.sub(&log.im);
            if !c.is_zero() {
                dispersion = Some(LeadingTerm { order: n as u32 - 1, constant: to_poly(&c) });
            }
        }
        if dissipation.is_none() && !on_circle && !log.re.is_zero() {
            let c = T::zero().sub(&log.re);
            dissipation = Some(LeadingTerm { order: n as u32 - 1, constant: to_poly(&c) });
        }
        if dispersion.is_some() && (dissipation.is_some() || on_circle) {
            return Ok(PhaseErrors { dispersion, dissipation });
        }
    }
    Err(series_error(format!("no nonzero term of Φ − Ψ or 1 − |z| up to Φ^{MAX_SERIES_TERMS}")))
}

impl Derivation {
    /// Φ − Ψ and 1 − |z| of the principal root z ≈ e^{iΦ} on the oscillator,
    /// to their leading terms, for any number of states and with exact
    /// constants; every parameter but Φ bound in `params`.
    ///
    /// ```
    /// let d = poly::derive(&poly::Method::builtin("standard_euler")?)?;
    /// let e = d.phase_errors(&poly::Params::new())?;
    /// let dissipation = e.dissipation.unwrap(); // |z| = √(1 + Φ²)
    /// assert_eq!((dissipation.order, dissipation.constant.to_string()), (1, "-1/2".into()));
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn phase_errors(&self, params: &Params) -> Result<PhaseErrors, Error> {
        let report = self.stability(params)?;
        let on_circle = report
            .intervals
            .first()
            .is_some_and(|i| i.lo.sign().is_eq() && i.class == crate::RootClass::Harmonic);
        self.phase_errors_given(params, on_circle)
    }

    /// [`Derivation::phase_errors`] with `on_circle` given: whether |z| ≡ 1
    /// on the first stable interval, which a caller holding the stability
    /// report already knows ([`phase_errors`] of χ with the parameters
    /// bound). A program generated from a tableau with rational entries
    /// reads the series off its stability function R, whose R(iΦ) is the
    /// principal root: the same terms (tested against χ's branch), without
    /// solving χ for the root's series.
    pub fn phase_errors_given(
        &self,
        params: &Params,
        on_circle: bool,
    ) -> Result<PhaseErrors, Error> {
        let values = self.bind(params)?;
        if let Some(logs) = stability_function_logs(self.method()) {
            return series_terms(logs, on_circle, |q| Poly::constant(q.clone()));
        }
        phase_errors(&self.charpoly().eval_partial(&values), on_circle)
    }

    /// The limit of the spectral radius on the oscillator as Φ → ∞; `None`
    /// when a root tends to ∞.
    ///
    /// ```
    /// let d = poly::derive(&poly::Method::builtin("trapezoidal")?)?;
    /// assert_eq!(d.rho_inf(&poly::Params::new())?.unwrap().to_string(), "1");
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn rho_inf(&self, params: &Params) -> Result<Option<Algebraic>, Error> {
        self.refuse_scalar()?;
        let chi = self.charpoly().eval_partial(&self.bind(params)?);
        rho_at_infinity(&chi, Sym::phi())
    }

    /// Refuses a scalar program in an oscillator analysis.
    pub(crate) fn refuse_scalar(&self) -> Result<(), Error> {
        if self.method().is_scalar() {
            return Err(Error::analysis(
                ErrorKind::TestEquation,
                format!(
                    "`{}` is written for y' = λy (it reads `w`): the oscillator analyses need a \
                     program in `Phi`; its analysis is in the w-plane (`region`)",
                    self.method().name()
                ),
            ));
        }
        Ok(())
    }
}
