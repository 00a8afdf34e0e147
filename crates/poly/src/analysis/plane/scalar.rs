//! χ(z, w) on the scalar test equation y' = λy, w = hλ, from a derivation.
//!
//! - A scalar program (it reads `w`) has it as its characteristic
//!   polynomial.
//! - An oscillator program over `y` and `v` (y' = ωv, v' = −ωy) has one
//!   when the step treats the two alike: then, in u = y + iv, the oscillator
//!   is u' = −iωu, the scalar test equation with w = −iΦ, and the transition
//!   matrix commutes with the complex structure, P = [[A, −B], [B, A]] over
//!   (y slots, v slots). The scalar step is C = A + iB at Φ = iw; its
//!   entries are real exactly when A is even and B odd in Φ. A partitioned
//!   method (symplectic Euler, Verlet, Newmark) has no such structure, and
//!   no scalar form: it is refused, with the reason.
//!
//! Either way the result is made primitive in z (the content over F\[w\] is
//! divided out), so a factor of the step's determinant that every
//! coefficient shares (D(−w) of D(w)D(−w)) cannot pose as a pole.

use num_traits::{One, Zero};

use crate::error::{Error, ErrorKind};
use crate::multivariate::constants as field;
use crate::{Derivation, Params, Poly, PolyMatrix, Sym, Q};

fn refuse(msg: String) -> Error {
    Error::analysis(ErrorKind::TestEquation, msg)
}

impl Derivation {
    /// χ(z, w) of the method on y' = λy, w = hλ, with every parameter bound
    /// in `params`; primitive in z, over Q or the field of the method's
    /// constants. For an oscillator program, its scalar form when the step
    /// treats `y` and `v` alike (Runge–Kutta and multistep methods written
    /// for the oscillator); a partitioned method is refused.
    ///
    /// ```
    /// let d = poly::derive(&poly::Method::builtin("standard_heun")?)?;
    /// let chi = d.scalar_charpoly(&poly::Params::new())?;
    /// assert_eq!(chi.to_string(), "z - 1 - w - 1/2*w^2");
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn scalar_charpoly(&self, params: &Params) -> Result<Poly, Error> {
        let values = self.bind(params)?;
        let chi = if self.method().is_scalar() {
            self.charpoly().eval_partial(&values)
        } else {
            let p = self.transition_matrix().map(|e| e.eval_partial(&values));
            let d = self.p_denominator().eval_partial(&values);
            self.scalar_from_oscillator(&p, &d)?
        };
        let (z, w) = (Sym::z(), Sym::w());
        if let Some(s) = chi
            .symbols()
            .into_iter()
            .find(|&s| s != z && s != w && field::generator_of(s).is_none())
        {
            return Err(Error::analysis(
                ErrorKind::ExtraSymbol,
                format!("χ(z, w) still contains the parameter {s}; expected a value for it"),
            ));
        }
        if chi.degree_in(z) == 0 {
            return Err(Error::analysis(
                ErrorKind::NoRoots,
                format!("χ = {chi} does not depend on z: expected a step with a state"),
            ));
        }
        Ok(primitive_in_z(&chi))
    }

    /// χ(z, w) with the parameters in `values` bound and every other one
    /// kept as a symbol (the design search lifts the axes' conditions with
    /// the free parameters in them); not made primitive.
    pub(crate) fn symbolic_scalar_charpoly(
        &self,
        values: &std::collections::HashMap<Sym, Q>,
    ) -> Result<Poly, Error> {
        if self.method().is_scalar() {
            return Ok(self.charpoly().eval_partial(values));
        }
        let p = self.transition_matrix().map(|e| e.eval_partial(values));
        let d = self.p_denominator().eval_partial(values);
        self.scalar_from_oscillator(&p, &d)
    }

    fn scalar_from_oscillator(&self, p: &PolyMatrix, d: &Poly) -> Result<Poly, Error> {
        let m = self.method();
        let name = m.name();
        let var = |n: &str| m.state().iter().position(|s| s == n);
        let (Some(y), Some(v)) = (var("y"), var("v")) else {
            return Err(refuse(format!(
                "`{name}` is an oscillator program over {}; a scalar form on y' = λy is read \
                 from the first-order pair `y`, `v` (y' = ωv, v' = −ωy), so a method for the \
                 second-order equation has none: expected those names, or a scalar program in \
                 `w`",
                m.state().join(", ")
            )));
        };
        if m.state().len() != 2 {
            return Err(refuse(format!(
                "`{name}` has state {}: its scalar form is read from exactly `y` and `v`",
                m.state().join(", ")
            )));
        }
        let slots = m.slots();
        let ys: Vec<usize> = (0..slots.len()).filter(|&i| slots[i].0 == y).collect();
        let vs: Vec<usize> = ys
            .iter()
            .map(|&i| slots.iter().position(|&(var, lag)| var == v && lag == slots[i].1))
            .collect::<Option<_>>()
            .filter(|vs: &Vec<usize>| vs.len() * 2 == slots.len())
            .ok_or_else(|| {
                refuse(format!(
                    "`{name}` keeps a different history of y and v: it is partitioned, and has \
                     no scalar form on y' = λy"
                ))
            })?;
        let n = ys.len();
        let partitioned = || {
            refuse(format!(
                "`{name}`'s transition matrix does not commute with u = y + iv: it treats y and \
                 v differently (a partitioned method), or its test equation is not the undamped \
                 oscillator; y' = λy has no step of it, and its analysis is on the oscillator \
                 (`stability`)"
            ))
        };
        let (mut s, mut im) = (PolyMatrix::zeros(n, n), false);
        for a in 0..n {
            for b in 0..n {
                let (pyy, pyv) = (&p[(ys[a], ys[b])], &p[(ys[a], vs[b])]);
                let (pvy, pvv) = (&p[(vs[a], ys[b])], &p[(vs[a], vs[b])]);
                if pyy != pvv || *pyv != -pvy {
                    return Err(partitioned());
                }
                // C = A + iB at Φ = iw, with A = P_yy and B = P_vy:
                // i·B(iw) = i·re_b − im_b.
                let (re_a, im_a) = at_i_w(pyy);
                let (re_b, im_b) = at_i_w(pvy);
                s[(a, b)] = &re_a - &im_b;
                im |= !(&im_a + &re_b).is_zero();
            }
        }
        let (d_re, d_im) = at_i_w(d);
        if im || !d_im.is_zero() {
            return Err(refuse(format!(
                "`{name}`'s step at Φ = iw has complex coefficients: it has no real scalar form"
            )));
        }
        // χ = det(z·d(iw)·I − S), S = d·C.
        let zd = &Poly::sym(Sym::z()) * &d_re;
        let chi = PolyMatrix::from_rows(
            (0..n)
                .map(|a| {
                    (0..n).map(|b| if a == b { &zd - &s[(a, b)] } else { -&s[(a, b)] }).collect()
                })
                .collect(),
        )
        .det();
        Ok(field::reduce(&chi))
    }
}

/// p(Φ) at Φ = iw, split into real and imaginary parts (each a polynomial
/// in w).
fn at_i_w(p: &Poly) -> (Poly, Poly) {
    at_imaginary(p, Sym::phi(), Sym::w())
}

/// p at x = i·y, split into real and imaginary parts (each a polynomial in
/// y): the term a_k x^k becomes a_k i^k y^k.
pub(crate) fn at_imaginary(p: &Poly, x: Sym, y: Sym) -> (Poly, Poly) {
    let (mut re, mut im) = (Poly::zero(), Poly::zero());
    for (k, c) in p.coeffs_in(x).iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        let t = c * &Poly::sym(y).pow(k as u32);
        match k % 4 {
            0 => re += &t,
            1 => im += &t,
            2 => re -= &t,
            _ => im -= &t,
        }
    }
    (re, im)
}

/// Polynomials in w over F, lowest power first, for Euclid's algorithm.
type Upf = Vec<Poly>;

fn trim(mut a: Upf) -> Upf {
    while a.last().is_some_and(Poly::is_zero) {
        a.pop();
    }
    a
}

/// a mod b over F (b ≠ 0).
fn rem(a: &Upf, b: &Upf) -> Upf {
    let mut r = trim(a.clone());
    let b = trim(b.clone());
    let lead_inv = field::inverse(b.last().expect("nonzero divisor")).expect("a field element");
    while r.len() >= b.len() && !r.is_empty() {
        let shift = r.len() - b.len();
        let f = field::reduce(&(r.last().unwrap() * &lead_inv));
        for (i, c) in b.iter().enumerate() {
            r[shift + i] = field::reduce(&(&r[shift + i] - &(&f * c)));
        }
        r = trim(r);
    }
    r
}

/// a / b over F, exact (the remainder is assumed zero).
fn div(a: &Upf, b: &Upf) -> Upf {
    let mut r = trim(a.clone());
    let b = trim(b.clone());
    let lead_inv = field::inverse(b.last().expect("nonzero divisor")).expect("a field element");
    let mut q = vec![Poly::zero(); r.len().saturating_sub(b.len()) + 1];
    while r.len() >= b.len() && !r.is_empty() {
        let shift = r.len() - b.len();
        let f = field::reduce(&(r.last().unwrap() * &lead_inv));
        for (i, c) in b.iter().enumerate() {
            r[shift + i] = field::reduce(&(&r[shift + i] - &(&f * c)));
        }
        q[shift] = f;
        r = trim(r);
    }
    q
}

/// The gcd over F (not normalised).
pub(crate) fn gcd(a: &[Poly], b: &[Poly]) -> Upf {
    let (mut a, mut b) = (trim(a.to_vec()), trim(b.to_vec()));
    while !b.is_empty() {
        let r = rem(&a, &b);
        a = b;
        b = r;
    }
    a
}

/// The derivative of a polynomial given by its coefficients.
pub(crate) fn derivative(a: &[Poly]) -> Upf {
    a.iter()
        .enumerate()
        .skip(1)
        .map(|(k, c)| c.scale(&Q::from_integer((k as i64).into())))
        .collect()
}

/// χ divided by the gcd over F\[w\] of its coefficients in z, scaled so
/// that its leading coefficient's first nonzero rational is positive.
pub(crate) fn primitive_in_z(chi: &Poly) -> Poly {
    let (z, w) = (Sym::z(), Sym::w());
    if !field::has_generators(chi) {
        return primitive_rational(chi);
    }
    let cz: Vec<Upf> = chi.coeffs_in(z).iter().map(|c| c.coeffs_in(w)).collect();
    let mut g: Upf = Vec::new();
    for c in &cz {
        g = gcd(&g, c);
        if g.len() == 1 {
            break;
        }
    }
    let g = trim(g);
    let parts: Vec<Poly> = if g.len() > 1 {
        cz.iter().map(|c| Poly::from_coeffs_in(w, &div(c, &g))).collect()
    } else {
        chi.coeffs_in(z)
    };
    // Normalised so that the lowest term in w of the leading coefficient in
    // z is 1 (z − R(w) reads as it is written).
    let lead = parts.last().cloned().unwrap_or_default();
    let low = lead.coeffs_in(w).into_iter().find(|c| !c.is_zero()).unwrap_or_else(Poly::one);
    match field::inverse(&low) {
        Some(inv) => field::reduce(&(&Poly::from_coeffs_in(z, &parts) * &inv)),
        None => Poly::from_coeffs_in(z, &parts),
    }
}

/// [`primitive_in_z`] over Q: gcds of univariate polynomials in w.
fn primitive_rational(chi: &Poly) -> Poly {
    let (z, w) = (Sym::z(), Sym::w());
    let cz: Vec<crate::UPoly> =
        chi.coeffs_in(z).iter().map(|c| c.to_upoly(w).expect("a polynomial in w")).collect();
    let mut g = crate::UPoly::zero();
    for c in &cz {
        g = g.gcd(c);
        if g.degree() == Some(0) {
            break;
        }
    }
    let parts: Vec<crate::UPoly> =
        if g.degree().unwrap_or(0) > 0 { cz.iter().map(|c| c.div_rem(&g).0).collect() } else { cz };
    let lead = parts.last().cloned().unwrap_or_else(crate::UPoly::zero);
    let low = lead.coeffs().iter().find(|c| !c.is_zero()).cloned().unwrap_or_else(Q::one);
    let parts: Vec<Poly> =
        parts.iter().map(|c| Poly::from_upoly(w, &c.scale(&low.recip()))).collect();
    Poly::from_coeffs_in(z, &parts)
}
