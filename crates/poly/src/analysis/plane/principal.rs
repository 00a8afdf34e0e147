//! The principal root as a power series, in F(i) for F the field of the
//! method's exact constants: the branch z = 1 + t·ν(t) of χ(z, t) = 0 with
//! ν(0) = ν₀ a simple root of the lowest-order part.
//!
//! - On y' = λy (t = w): ν₀ solves a₁₀ν + a₀₁ = 0, so z₁(w) = 1 + ν₀w + …,
//!   and e^w − z₁(w) gives the order and the error constant.
//! - On the oscillator (t = Φ): ν₀ = i, the branch z ≈ e^{iΦ}, and
//!   log z = iΨ + ln|z| gives the dispersion Φ − Ψ and the dissipation
//!   1 − |z|.
//!
//! Each coefficient ν_n is one linear step: adding ν_n tⁿ changes the
//! coefficient of tⁿ of G(ν(t), t) by G_ν(ν₀, 0)·ν_n and nothing below it.

use num_traits::One;

use crate::multivariate::constants as field;
use crate::{Poly, Sym, Q};

/// An element of F(i): re + i·im, each a polynomial in the generators of F.
#[derive(Clone, Debug, PartialEq, Default)]
pub(crate) struct C {
    pub re: Poly,
    pub im: Poly,
}

impl C {
    pub fn real(re: Poly) -> C {
        C { re, im: Poly::zero() }
    }

    pub fn i() -> C {
        C { re: Poly::zero(), im: Poly::one() }
    }

    pub fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }

    pub fn add(&self, o: &C) -> C {
        C { re: &self.re + &o.re, im: &self.im + &o.im }
    }

    pub fn sub(&self, o: &C) -> C {
        C { re: &self.re - &o.re, im: &self.im - &o.im }
    }

    pub fn mul(&self, o: &C) -> C {
        if self.im.is_zero() && o.im.is_zero() {
            return C::real(field::reduce(&(&self.re * &o.re)));
        }
        C {
            re: field::reduce(&(&(&self.re * &o.re) - &(&self.im * &o.im))),
            im: field::reduce(&(&(&self.re * &o.im) + &(&self.im * &o.re))),
        }
    }

    pub fn scale(&self, q: &Q) -> C {
        C { re: self.re.scale(q), im: self.im.scale(q) }
    }

    /// 1/self, through the conjugate: None for zero.
    pub fn inv(&self) -> Option<C> {
        let n = field::reduce(&(&(&self.re * &self.re) + &(&self.im * &self.im)));
        let ninv = field::inverse(&n)?;
        Some(C { re: field::reduce(&(&self.re * &ninv)), im: field::reduce(&(-&self.im * &ninv)) })
    }
}

/// Why a branch does not exist.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum NoBranch {
    /// ν₀ is not a root of the lowest-order part: no root of χ leaves z = 1
    /// as the test equation's solution does (the method is not consistent).
    NotARoot,
    /// ν₀ is a repeated root there: the branch is not a power series.
    Repeated,
}

/// The truncated product of two series.
fn mul(a: &[C], b: &[C], len: usize) -> Vec<C> {
    let mut out = vec![C::default(); len];
    for (i, x) in a.iter().enumerate().take(len) {
        if x.is_zero() {
            continue;
        }
        for (j, y) in b.iter().enumerate().take(len - i) {
            if !y.is_zero() {
                out[i + j] = out[i + j].add(&x.mul(y));
            }
        }
    }
    out
}

/// The branch z = 1 + t·ν(t) of χ(z, t) = 0 (χ's other symbols are
/// generators of F only), grown one coefficient at a time.
pub(crate) struct Branch {
    /// G(ν, t) = Σ g[j][k] ν^j t^k, with χ(1 + tν, t) = t^m·G(ν, t).
    g: Vec<Vec<Poly>>,
    /// 1 / G_ν(ν₀, 0).
    inv_slope: C,
    /// ν's coefficients so far.
    pub nu: Vec<C>,
}

impl Branch {
    pub fn new(chi: &Poly, t: Sym, nu0: C) -> Result<Branch, NoBranch> {
        let z = Sym::z();
        let shifted = chi.subs(z, &(&Poly::one() + &Poly::sym(z)));
        // a[j][k]: the coefficient of u^j t^k in χ(1 + u, t).
        let a: Vec<Vec<Poly>> =
            shifted.coeffs_in(z).iter().map(|c| c.coeffs_in(t)).collect::<Vec<_>>();
        let m = a
            .iter()
            .enumerate()
            .flat_map(|(j, row)| {
                row.iter().enumerate().filter(|(_, c)| !c.is_zero()).map(move |(k, _)| j + k)
            })
            .min()
            .ok_or(NoBranch::NotARoot)?;
        // With u = tν: a[j][k] u^j t^k = a[j][k] ν^j t^(j+k), so
        // g[j][j + k − m] = a[j][k].
        let mut g: Vec<Vec<Poly>> = vec![Vec::new(); a.len()];
        for (j, row) in a.iter().enumerate() {
            for (k, c) in row.iter().enumerate() {
                if c.is_zero() {
                    continue;
                }
                let e = j + k - m;
                if g[j].len() <= e {
                    g[j].resize(e + 1, Poly::zero());
                }
                g[j][e] = c.clone();
            }
        }
        let at0 = |j: usize| g[j].first().cloned().unwrap_or_default();
        let mut value = C::default();
        let mut slope = C::default();
        let mut pow = C::real(Poly::one());
        for j in 0..g.len() {
            value = value.add(&pow.mul(&C::real(at0(j))));
            if j + 1 < g.len() {
                slope = slope
                    .add(&pow.mul(&C::real(at0(j + 1))).scale(&Q::from_integer((j + 1).into())));
            }
            pow = pow.mul(&nu0);
        }
        if !value.is_zero() {
            return Err(NoBranch::NotARoot);
        }
        let inv_slope = slope.inv().ok_or(NoBranch::Repeated)?;
        Ok(Branch { g, inv_slope, nu: vec![nu0] })
    }

    /// Adds the next coefficient of ν.
    pub fn grow(&mut self) {
        let n = self.nu.len();
        let len = n + 1;
        let mut nu = self.nu.clone();
        nu.push(C::default());
        // The coefficient of t^n in G(ν, t) with ν_n = 0.
        let mut r = C::default();
        let mut pow: Vec<C> = vec![C::real(Poly::one())];
        pow.resize(len, C::default());
        for row in &self.g {
            for (k, c) in row.iter().enumerate().take(len) {
                if !c.is_zero() && !pow[n - k].is_zero() {
                    r = r.add(&pow[n - k].mul(&C::real(c.clone())));
                }
            }
            pow = mul(&pow, &nu, len);
        }
        let next = C::default().sub(&r.mul(&self.inv_slope));
        self.nu.push(next);
    }

    /// z's coefficients 1, ν₀, ν₁, … (z = 1 + Σ ν_n t^(n+1)).
    pub fn z_coeffs(&self) -> Vec<C> {
        let mut z = vec![C::real(Poly::one())];
        z.extend(self.nu.iter().cloned());
        z
    }

    /// log z = log(1 + tν) to the same length as z's coefficients.
    pub fn log_coeffs(&self) -> Vec<C> {
        let len = self.nu.len() + 1;
        let mut x = vec![C::default()];
        x.extend(self.nu.iter().cloned());
        let mut out = vec![C::default(); len];
        let mut pow = x.clone();
        for k in 1..len {
            let c = Q::new(if k % 2 == 1 { 1.into() } else { (-1).into() }, (k as i64).into());
            for (o, p) in out.iter_mut().zip(&pow) {
                *o = o.add(&p.scale(&c));
            }
            pow = mul(&pow, &x, len);
        }
        out
    }
}

/// 1/n! as a rational.
pub(crate) fn inverse_factorial(n: usize) -> Q {
    let mut f = Q::one();
    for k in 2..=n {
        f *= Q::from_integer((k as i64).into());
    }
    f.recip()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Explicit Euler z − 1 − w: z₁ = 1 + w exactly.
    #[test]
    fn explicit_euler_branch_is_one_plus_w() {
        let chi = Poly::parse("z - 1 - w").unwrap();
        let mut b = Branch::new(&chi, Sym::w(), C::real(Poly::one())).unwrap();
        b.grow();
        b.grow();
        let z = b.z_coeffs();
        assert_eq!(z[1], C::real(Poly::one()));
        assert!(z[2].is_zero() && z[3].is_zero());
    }

    /// Backward Euler (1 − w)z − 1: z₁ = 1/(1 − w) = Σ wⁿ.
    #[test]
    fn backward_euler_branch_is_geometric() {
        let chi = Poly::parse("z - w*z - 1").unwrap();
        let mut b = Branch::new(&chi, Sym::w(), C::real(Poly::one())).unwrap();
        for _ in 0..5 {
            b.grow();
        }
        assert!(b.z_coeffs().iter().all(|c| *c == C::real(Poly::one())));
    }

    /// False Euler on the oscillator: z² − (2 − Φ²)z + 1, |z| = 1, and the
    /// principal root starts 1 + iΦ.
    #[test]
    fn false_euler_branch_starts_at_i() {
        let chi = Poly::parse("z^2 - 2*z + Phi^2*z + 1").unwrap();
        let mut b = Branch::new(&chi, Sym::phi(), C::i()).unwrap();
        for _ in 0..6 {
            b.grow();
        }
        let log = b.log_coeffs();
        assert!(log.iter().all(|c| c.re.is_zero()), "|z| = 1: {log:?}");
        assert_eq!(log[1], C::i());
        assert!(Branch::new(&chi, Sym::phi(), C::real(Poly::one())).is_err());
    }
}
