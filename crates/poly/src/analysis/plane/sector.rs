//! Stability along rays of the w-plane, and the largest stable sector
//! |arg(−w)| < α (A(α)-stability), exactly.
//!
//! Along a ray w = Φ·d (d = d_r + i·d_i rational, Φ > 0), χ(z, Φd) = A + iB
//! with A, B real polynomials in z and Φ; A² + B² has the roots of χ and
//! their conjugates, so the exact engine over Φ > 0 decides the ray (and its
//! mirror image, which has the conjugate roots).
//!
//! The sector: the boundary locus Γ (the w where a root lies on the unit
//! circle) meets the ray of slope m = tan(arg(−w)) on a real algebraic curve
//! G(x, m) = 0; the slopes where the set of rays meeting Γ can change are
//! the critical values of m on that curve, roots of Res_x(G, ∂G/∂x), with
//! those of G's leading coefficient in x and of G at x = 0 (branches to ∞ and
//! through the origin). Between consecutive candidates one ray at a rational
//! slope decides the whole gap. So A(α) is exact: tan α is the candidate
//! that ends the last stable gap, an algebraic number.
//!
//! G comes from the structure of χ:
//! - linear in w (χ = ρ(z) − wσ(z), multistep methods): w = ρ/σ on the
//!   circle z = (1 + it)/(1 − it); with ρσ̄ = U + iV, G(t, m) = V − mU;
//! - linear in z (χ = Q(w)z − P(w), one-step methods): Γ is |P| = |Q|; on
//!   the ray w = −s(1 + im), G(s, m) = |Q|² − |P|² (divided by its power
//!   of s);
//! - otherwise: G(s, m) = Res_t(Re, Im) of χ((1 + it)/(1 − it), −s(1 + im))
//!   times (1 − it)^n.
//!
//! With exact constants, G is replaced by its norm over Q: its zero set
//! holds Γ's and the conjugates', which only adds candidates.

use std::cmp::Ordering;

use num_traits::{One, Zero};

use crate::analysis::stability::{verdict, Stability};
use crate::error::{Error, ErrorKind};
use crate::multivariate::constants as field;
use crate::multivariate::resultant::resultant;
use crate::{Algebraic, Poly, Sym, UPoly, Q};

/// The largest sector |arg(−w)| < α inside the stability region.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Sector {
    /// No sector: α = 0.
    Empty,
    /// The open left half-plane: α = 90°.
    HalfPlane,
    /// 0 < α < 90°, with tan α exact.
    Angle {
        /// tan α, an algebraic number.
        tan: Algebraic,
    },
}

/// (a + ib)^k for k = 0..=n, as pairs of polynomials (in whatever `a` and
/// `b` hold).
fn powers(a: &Poly, b: &Poly, n: usize) -> Vec<(Poly, Poly)> {
    let mut out = vec![(Poly::one(), Poly::zero())];
    for k in 0..n {
        let (re, im) = &out[k];
        out.push((&(re * a) - &(im * b), &(re * b) + &(im * a)));
    }
    out
}

/// χ(z, Φ·d) as A + iB, A and B real polynomials in z and Φ.
fn along(chi: &Poly, d: (&Q, &Q)) -> (Poly, Poly) {
    let (w, phi) = (Sym::w(), Sym::phi());
    let cw = chi.coeffs_in(w);
    let dk = powers(&Poly::constant(d.0.clone()), &Poly::constant(d.1.clone()), cw.len());
    let (mut a, mut b) = (Poly::zero(), Poly::zero());
    for (k, c) in cw.iter().enumerate() {
        let pk = Poly::sym(phi).pow(k as u32);
        let c = c * &pk;
        a += &(&c * &dk[k].0);
        b += &(&c * &dk[k].1);
    }
    (field::reduce(&a), field::reduce(&b))
}

/// c(Φ·d) for c over Q in w, as A + iB in Φ.
fn along_rational(c: &UPoly, d: (&Q, &Q)) -> (UPoly, UPoly) {
    let (mut re, mut im) = (Vec::new(), Vec::new());
    // Products and sums reduced by Lehmer's gcd (`arith::rational`).
    use crate::arith::rational::{add, mul};
    let (mut pr, mut pi) = (Q::one(), Q::zero());
    for ck in c.coeffs() {
        re.push(mul(ck, &pr));
        im.push(mul(ck, &pi));
        let next = (add(&mul(&pr, d.0), &-mul(&pi, d.1)), add(&mul(&pr, d.1), &mul(&pi, d.0)));
        (pr, pi) = next;
    }
    (UPoly::new(re), UPoly::new(im))
}

/// The polynomials multiplied by the lcm of all their denominators, so
/// that every coefficient is an integer.
fn integer_multiples<const N: usize>(ps: [UPoly; N]) -> [UPoly; N] {
    let mut lcm = num_bigint::BigInt::one();
    for c in ps.iter().flat_map(|p| p.coeffs()) {
        if !c.denom().is_one() {
            lcm = crate::arith::intgcd::lcm(&lcm, c.denom());
        }
    }
    if lcm.is_one() {
        return ps;
    }
    ps.map(|p| {
        UPoly::new(
            p.coeffs().iter().map(|c| Q::from_integer(c.numer() * (&lcm / c.denom()))).collect(),
        )
    })
}

/// The polynomial in z and Φ whose roots over Φ > 0 are those of χ along
/// the ray w = Φ·d and their conjugates (A itself on the real axis).
pub(crate) fn ray_poly(chi: &Poly, d: (&Q, &Q)) -> Poly {
    let (a, b) = along(chi, d);
    let p = if b.is_zero() { a } else { field::reduce(&(&(&a * &a) + &(&b * &b))) };
    // The constants engine reads second-order χ: a first-order one gains
    // the root z = 0, which changes no verdict.
    if field::has_generators(&p) && p.degree_in(Sym::z()) == 1 {
        return &p * &Poly::sym(Sym::z());
    }
    p
}

/// The supremum of r such that every 0 < Φ < r on the ray w = Φ·d is
/// stable; `None` when every Φ > 0 is.
///
/// A one-step χ = c₁(w)z + c₀(w) is decided by its margin
/// E(Φ) = |c₁(Φd)|² − |c₀(Φd)|² ≥ 0, without the conjugate roots (whose
/// meeting at z = ±1 on the circle, as Gauss–Legendre's root does at
/// w = ±2√3 i, is no repeated root of χ). Otherwise the exact engine
/// decides A² + B² over Φ > 0 (root condition: a repeated root of χ on the
/// circle is not stable).
///
/// Where that engine stops at a repeated root of A² + B² on the circle
/// ([`Stability::UndecidedAt`]), the limit is that point only when the
/// repeated root is χ's own: on the real axis A² + B² is χ itself; off it,
/// when χ's discriminant in z vanishes there. Otherwise a root of χ may
/// merely meet its conjugate's (at ±1), which the root condition allows,
/// and the answer is an error of kind [`ErrorKind::Undecided`], never a
/// limit that may be too small.
pub(crate) fn limit_along(chi: &Poly, d: (&Q, &Q)) -> Result<Option<Algebraic>, Error> {
    if chi.degree_in(Sym::z()) == 1 {
        return limit_one_step(chi, d);
    }
    Ok(match verdict(&ray_poly(chi, d))? {
        Stability::BoundedForAllPhi => None,
        Stability::Limited { phi_max, .. } => Some(phi_max),
        Stability::UndecidedAt { at, .. } if d.1.is_zero() || repeated_root_of_chi(chi, d, &at) => {
            Some(at)
        }
        Stability::UndecidedAt { at, .. } => {
            return Err(Error::analysis(
                ErrorKind::Undecided,
                format!(
                    "along w = Phi*({} + {}i) two roots meet on the unit circle at Phi = {at}, \
                     but chi's own roots stay simple there: whether the ray is stable beyond \
                     it is not decided",
                    d.0, d.1
                ),
            ))
        }
        _ => Some(Algebraic::zero()),
    })
}

/// Whether χ(z, Φ·d) itself has a repeated root at Φ = `at`: its
/// discriminant in z, A + iB along the ray, vanishes there (both parts).
/// With exact constants, not decided here (`false`).
fn repeated_root_of_chi(chi: &Poly, d: (&Q, &Q), at: &Algebraic) -> bool {
    let z = Sym::z();
    let c = chi.coeffs_in(z);
    let dc = chi.derivative(z).coeffs_in(z);
    let (a, b) = along(&resultant(&c, &dc), d);
    match (a.to_upoly(Sym::phi()), b.to_upoly(Sym::phi())) {
        (Some(a), Some(b)) => at.is_root_of(&a) && at.is_root_of(&b),
        _ => false,
    }
}

/// [`limit_along`] for χ of degree one in z: the first Φ > 0 after which
/// the margin E turns negative.
fn limit_one_step(chi: &Poly, d: (&Q, &Q)) -> Result<Option<Algebraic>, Error> {
    let phi = Sym::phi();
    let cz = chi.coeffs_in(Sym::z());
    let (a0, b0, a1, b1) = match (cz[0].to_upoly(Sym::w()), cz[1].to_upoly(Sym::w())) {
        // Over Q: dense univariate arithmetic.
        (Some(c0), Some(c1)) => {
            let (a0, b0) = along_rational(&c0, d);
            let (a1, b1) = along_rational(&c1, d);
            // Scaled by one positive integer L to integer coefficients: E
            // becomes L²·E (the same roots and signs), and the products and
            // sums below need no reductions.
            let [a0, b0, a1, b1] = integer_multiples([a0, b0, a1, b1]);
            let up = |u: UPoly| Poly::from_upoly(phi, &u);
            (up(a0), up(b0), up(a1), up(b1))
        }
        _ => {
            let (a0, b0) = along(&cz[0], d);
            let (a1, b1) = along(&cz[1], d);
            (a0, b0, a1, b1)
        }
    };
    let e = match (a0.to_upoly(phi), b0.to_upoly(phi), a1.to_upoly(phi), b1.to_upoly(phi)) {
        (Some(a0), Some(b0), Some(a1), Some(b1)) => {
            let sq = |u: &UPoly| u * u;
            let e = &(&sq(&a1) + &sq(&b1)) - &(&sq(&a0) + &sq(&b0));
            Poly::from_upoly(phi, &e)
        }
        _ => field::reduce(&(&(&(&a1 * &a1) + &(&b1 * &b1)) - &(&(&a0 * &a0) + &(&b0 * &b0)))),
    };
    if e.is_zero() {
        return Ok(None);
    }
    // On the real axis E = (a₁ − a₀)(a₁ + a₀): its roots keep the smaller
    // defining polynomials of the two factors.
    let factors =
        if b0.is_zero() && b1.is_zero() { vec![&a1 - &a0, &a1 + &a0] } else { vec![e.clone()] };
    let mut roots = Vec::new();
    for f in factors {
        let u = field_free(&f).to_upoly(phi).ok_or_else(|| {
            Error::analysis(
                ErrorKind::ExtraSymbol,
                format!("the margin {e} holds a symbol other than Phi"),
            )
        })?;
        if !u.is_zero() {
            roots.extend(Algebraic::positive_roots(&u));
        }
    }
    roots.sort_by(|a, b| a.partial_cmp(b).unwrap_or(Ordering::Equal));
    roots.dedup();
    let rational = e.to_upoly(phi);
    let negative_at = |x: &Q| match &rational {
        Some(u) => u.eval(x) < Q::zero(),
        None => {
            field::sign(&field::reduce(&e.subs(phi, &Poly::constant(x.clone())))) == Ordering::Less
        }
    };
    let mut lo = Algebraic::zero();
    for r in roots {
        let sample = Algebraic::rational_between(&lo, &r);
        if negative_at(&sample) {
            return Ok(Some(lo));
        }
        lo = r;
    }
    let beyond = lo.interval().1.clone() + Q::one();
    Ok(negative_at(&beyond).then_some(lo))
}

/// The real and imaginary parts, as polynomials in t, of
/// Σ c_j (1 + it)^j (1 − it)^(n−j) for coefficients c_j (lowest first).
fn on_circle(c: &[Poly], n: usize) -> (Poly, Poly) {
    let t = Poly::sym(Sym::new("t"));
    let plus = powers(&Poly::one(), &t, n);
    let minus = powers(&Poly::one(), &-&t, n);
    let (mut re, mut im) = (Poly::zero(), Poly::zero());
    for (j, cj) in c.iter().enumerate() {
        if cj.is_zero() {
            continue;
        }
        let (a, b) = (&plus[j], &minus[n - j]);
        let pr = &(&a.0 * &b.0) - &(&a.1 * &b.1);
        let pi = &(&a.0 * &b.1) + &(&a.1 * &b.0);
        re += &(cj * &pr);
        im += &(cj * &pi);
    }
    (re, im)
}

/// The curve G(x, m) on which the ray of slope m meets Γ, and its x.
fn boundary_curve(chi: &Poly) -> (Poly, Sym) {
    let (z, w, m, t, s) = (Sym::z(), Sym::w(), Sym::new("m"), Sym::new("t"), Sym::new("s"));
    let n = chi.degree_in(z) as usize;
    let g = if chi.degree_in(w) == 1 {
        let cw = chi.coeffs_in(w);
        let rho = cw[0].coeffs_in(z);
        let sigma: Vec<Poly> = cw[1].coeffs_in(z).iter().map(|c| -c).collect();
        let (rr, ri) = on_circle(&rho, n);
        let (sr, si) = on_circle(&sigma, n);
        let u = &(&rr * &sr) + &(&ri * &si);
        let v = &(&ri * &sr) - &(&rr * &si);
        return (field_free(&(&v - &(&Poly::sym(m) * &u))), t);
    } else {
        // w = −s(1 + im).
        let neg_s = -&Poly::sym(s);
        let mpow = powers(&Poly::one(), &Poly::sym(m), chi.degree_in(w) as usize);
        let at_ray = |c: &[Poly]| -> (Poly, Poly) {
            let (mut re, mut im) = (Poly::zero(), Poly::zero());
            for (k, ck) in c.iter().enumerate() {
                let f = ck * &neg_s.pow(k as u32);
                re += &(&f * &mpow[k].0);
                im += &(&f * &mpow[k].1);
            }
            (re, im)
        };
        if n == 1 {
            let cz = chi.coeffs_in(z);
            let (qr, qi) = at_ray(&cz[1].coeffs_in(w));
            let (pr, pi) = at_ray(&cz[0].coeffs_in(w));
            &(&(&qr * &qr) + &(&qi * &qi)) - &(&(&pr * &pr) + &(&pi * &pi))
        } else {
            // Each z-coefficient along the ray, then on the circle.
            let (mut r1, mut r2) = (Poly::zero(), Poly::zero());
            let (mut re_c, mut im_c) = (Vec::new(), Vec::new());
            for c in chi.coeffs_in(z) {
                let (re, im) = at_ray(&c.coeffs_in(w));
                re_c.push(re);
                im_c.push(im);
            }
            let (a, b) = on_circle(&re_c, n);
            let (c, d) = on_circle(&im_c, n);
            // (re_c + i im_c) on the circle: (a + ib) + i(c + id).
            r1 += &(&a - &d);
            r2 += &(&b + &c);
            resultant(&r1.coeffs_in(t), &r2.coeffs_in(t))
        }
    };
    // Every ray meets Γ at w = 0: divide out the power of s.
    let cs = g.coeffs_in(s);
    let low = cs.iter().position(|c| !c.is_zero()).unwrap_or(0);
    (field_free(&Poly::from_coeffs_in(s, &cs[low..])), s)
}

/// p over Q: itself, or its norm when it holds constants.
fn field_free(p: &Poly) -> Poly {
    let p = field::reduce(p);
    if field::has_generators(&p) {
        field::norm(&p)
    } else {
        p
    }
}

fn in_m(p: &Poly) -> Option<UPoly> {
    p.to_upoly(Sym::new("m"))
}

/// The positive slopes at which the set of rays meeting Γ can change.
fn candidate_slopes(chi: &Poly) -> Result<Vec<Algebraic>, Error> {
    let (g, x) = boundary_curve(chi);
    let gx = g.coeffs_in(x);
    let dx = g.derivative(x).coeffs_in(x);
    // Coefficients in x are polynomials in m over Q: the modular resultant
    // over Z[m] (the engine's), else the Sylvester determinant.
    let m = Sym::new("m");
    // Integer coefficients: G scaled by the lcm of its denominators (a
    // constant factor of the resultant).
    let lcm = g
        .terms()
        .map(|(_, c)| c.denom().clone())
        .fold(num_bigint::BigInt::from(1), |l, d| num_integer::Integer::lcm(&l, &d));
    let scale = Q::from_integer(lcm);
    let in_m_all =
        |c: &[Poly]| c.iter().map(|p| p.scale(&scale).to_upoly(m)).collect::<Option<Vec<UPoly>>>();
    let disc = match (in_m_all(&gx), in_m_all(&dx)) {
        (Some(a), Some(b)) if a.len() >= 2 && b.len() >= 2 => {
            Poly::from_upoly(m, &crate::univariate::modular::resultant(&a, &b))
        }
        _ => resultant(&gx, &dx),
    };
    let undecided = |what: &str| {
        Error::analysis(
            ErrorKind::NoRoots,
            format!(
                "A(α): the boundary locus {what}; expected a curve without repeated components"
            ),
        )
    };
    if disc.is_zero() {
        return Err(undecided("has a repeated component (its discriminant vanishes)"));
    }
    let mut polys = vec![disc];
    if let Some(lc) = gx.last() {
        polys.push(lc.clone());
    }
    polys.push(gx.first().cloned().unwrap_or_default());
    let mut out: Vec<Algebraic> = Vec::new();
    for p in polys {
        if p.is_zero() {
            continue;
        }
        let u = in_m(&p).ok_or_else(|| undecided("holds another symbol"))?;
        if u.degree().unwrap_or(0) == 0 {
            continue;
        }
        out.extend(Algebraic::positive_roots(&u));
    }
    out.sort_by(|a, b| a.partial_cmp(b).unwrap_or(Ordering::Equal));
    out.dedup();
    Ok(out)
}

/// Whether every w = −Φ(1 ± im), Φ > 0, is stable.
fn ray_stable(chi: &Poly, m: &Q) -> Result<bool, Error> {
    let (dr, di) = (-Q::one(), -m.clone());
    Ok(limit_along(chi, (&dr, &di))?.is_none())
}

/// Routh's table for a real polynomial (lowest coefficient first): the
/// number of roots in the open right half-plane, or `None` in a singular
/// case (a zero in the first column), left to the general route.
fn right_half_plane_roots(c: &[Q]) -> Option<usize> {
    let mut c = c.to_vec();
    while c.last().is_some_and(Zero::is_zero) {
        c.pop();
    }
    let n = c.len().checked_sub(1)?;
    // Rows of Routh's table from the highest power: a_n, a_{n−2}, … and
    // a_{n−1}, a_{n−3}, ….
    let hi: Vec<Q> = c.iter().rev().cloned().collect();
    let mut r0: Vec<Q> = hi.iter().step_by(2).cloned().collect();
    let mut r1: Vec<Q> = hi.iter().skip(1).step_by(2).cloned().collect();
    let mut first = vec![r0[0].clone()];
    for _ in 0..n {
        if r1.is_empty() || r1[0].is_zero() {
            return None;
        }
        first.push(r1[0].clone());
        let next: Vec<Q> = (0..r0.len().saturating_sub(1))
            .map(|k| {
                let b = r1.get(k + 1).cloned().unwrap_or_default();
                (&r1[0] * &r0[k + 1] - &r0[0] * &b) / &r1[0]
            })
            .collect();
        r0 = std::mem::replace(&mut r1, next);
        if first.len() == n + 1 {
            break;
        }
    }
    Some(first.windows(2).filter(|w| (w[0] > Q::zero()) != (w[1] > Q::zero())).count())
}

/// A one-step χ = Q(w)z − P(w) whose imaginary axis is stable is A-stable
/// when R = P/Q has no pole in Re w < 0 and deg P ≤ deg Q (the maximum
/// principle on the left half-plane); decided by Routh's table of Q(−w).
/// `None` when that does not settle it.
fn one_step_a_stable(chi: &Poly) -> Option<bool> {
    let (z, w) = (Sym::z(), Sym::w());
    if chi.degree_in(z) != 1 || field::has_generators(chi) {
        return None;
    }
    let cz = chi.coeffs_in(z);
    let (q, p) = (cz[1].to_upoly(w)?, cz[0].to_upoly(w)?);
    if p.degree() > q.degree() {
        return None;
    }
    let reflected: Vec<Q> = q
        .coeffs()
        .iter()
        .enumerate()
        .map(|(k, c)| if k % 2 == 1 { -c.clone() } else { c.clone() })
        .collect();
    (right_half_plane_roots(&reflected)? == 0).then_some(true)
}

/// The largest stable sector, for a χ whose negative real axis (and w = 0)
/// is stable; `imag_stable` says whether the whole imaginary axis is.
pub(crate) fn sector(chi: &Poly, imag_stable: bool) -> Result<Sector, Error> {
    if imag_stable && one_step_a_stable(chi) == Some(true) {
        return Ok(Sector::HalfPlane);
    }
    let cands = candidate_slopes(chi)?;
    let mut prev: Option<&Algebraic> = None;
    for c in &cands {
        let probe = match prev {
            None => rational_below(c) / Q::from_integer(2.into()),
            Some(p) => Algebraic::rational_between(p, c),
        };
        if !ray_stable(chi, &probe)? {
            return Ok(match prev {
                None => Sector::Empty,
                Some(p) => Sector::Angle { tan: p.clone() },
            });
        }
        prev = Some(c);
    }
    let beyond = match prev {
        None => Q::one(),
        Some(p) => p.interval().1.clone() + Q::one(),
    };
    if !ray_stable(chi, &beyond)? {
        return Ok(match prev {
            None => Sector::Empty,
            Some(p) => Sector::Angle { tan: p.clone() },
        });
    }
    Ok(Sector::HalfPlane)
}

/// A positive rational below a positive algebraic number.
fn rational_below(c: &Algebraic) -> Q {
    let mut w = Q::one();
    loop {
        let r = c.refine(&w);
        let lo = r.interval().0.clone();
        if lo > Q::zero() {
            return lo;
        }
        w /= Q::from_integer(16.into());
    }
}
