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

use num_traits::{One, Zero};

use crate::multivariate::constants as field;
use crate::{Poly, Sym, Q};

/// The scalars of a series: F's elements as polynomials in its generators
/// (reduced after every product), or, for a χ over Q, plain rationals, the
/// same algorithm without a map per number.
pub(crate) trait Scalar: Clone + PartialEq + std::fmt::Debug {
    fn zero() -> Self;
    fn one() -> Self;
    fn is_zero(&self) -> bool;
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn scale(&self, q: &Q) -> Self;
    fn inv(&self) -> Option<Self>;
    /// A coefficient of χ: `None` where it is not a scalar of this kind.
    fn of(p: &Poly) -> Option<Self>;
}

impl Scalar for Poly {
    fn zero() -> Self {
        Poly::zero()
    }
    fn one() -> Self {
        Poly::one()
    }
    fn is_zero(&self) -> bool {
        Poly::is_zero(self)
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        field::reduce(&(self * o))
    }
    fn scale(&self, q: &Q) -> Self {
        Poly::scale(self, q)
    }
    fn inv(&self) -> Option<Self> {
        field::inverse(&field::reduce(self))
    }
    fn of(p: &Poly) -> Option<Self> {
        Some(p.clone())
    }
}

impl Scalar for Q {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    // Sums and products reduced by Lehmer's gcd after cross-cancelling
    // (`arith::rational`): the same reduced values as num-rational's
    // operators, which reduce by the binary gcd.
    fn add(&self, o: &Self) -> Self {
        crate::arith::rational::add(self, o)
    }
    fn sub(&self, o: &Self) -> Self {
        crate::arith::rational::add(self, &-o)
    }
    fn mul(&self, o: &Self) -> Self {
        crate::arith::rational::mul(self, o)
    }
    fn scale(&self, q: &Q) -> Self {
        crate::arith::rational::mul(self, q)
    }
    fn inv(&self) -> Option<Self> {
        (!Zero::is_zero(self)).then(|| self.recip())
    }
    fn of(p: &Poly) -> Option<Self> {
        p.as_constant()
    }
}

/// An element of F(i): re + i·im.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct C<T = Poly> {
    pub re: T,
    pub im: T,
}

impl<T: Scalar> Default for C<T> {
    fn default() -> Self {
        C { re: T::zero(), im: T::zero() }
    }
}

impl<T: Scalar> C<T> {
    pub fn real(re: T) -> C<T> {
        C { re, im: T::zero() }
    }

    pub fn i() -> C<T> {
        C { re: T::zero(), im: T::one() }
    }

    pub fn is_zero(&self) -> bool {
        self.re.is_zero() && self.im.is_zero()
    }

    pub fn add(&self, o: &C<T>) -> C<T> {
        C { re: self.re.add(&o.re), im: self.im.add(&o.im) }
    }

    pub fn sub(&self, o: &C<T>) -> C<T> {
        C { re: self.re.sub(&o.re), im: self.im.sub(&o.im) }
    }

    pub fn mul(&self, o: &C<T>) -> C<T> {
        // On the oscillator most coefficients are real or imaginary: one
        // product instead of four.
        match (self.re.is_zero(), self.im.is_zero(), o.re.is_zero(), o.im.is_zero()) {
            (_, true, _, true) => return C::real(self.re.mul(&o.re)),
            (true, _, true, _) => return C::real(T::zero().sub(&self.im.mul(&o.im))),
            (_, true, true, _) => return C { re: T::zero(), im: self.re.mul(&o.im) },
            (true, _, _, true) => return C { re: T::zero(), im: self.im.mul(&o.re) },
            _ => {}
        }
        C {
            re: self.re.mul(&o.re).sub(&self.im.mul(&o.im)),
            im: self.re.mul(&o.im).add(&self.im.mul(&o.re)),
        }
    }

    pub fn scale(&self, q: &Q) -> C<T> {
        C { re: self.re.scale(q), im: self.im.scale(q) }
    }

    /// 1/self, through the conjugate: None for zero.
    pub fn inv(&self) -> Option<C<T>> {
        let ninv = self.re.mul(&self.re).add(&self.im.mul(&self.im)).inv()?;
        Some(C { re: self.re.mul(&ninv), im: T::zero().sub(&self.im).mul(&ninv) })
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

/// The branch z = 1 + t·ν(t) of χ(z, t) = 0 (χ's other symbols are
/// generators of F only), grown one coefficient at a time.
pub(crate) struct Branch<T = Poly> {
    /// G(ν, t) = Σ g[j][k] ν^j t^k, with χ(1 + tν, t) = t^m·G(ν, t).
    g: Vec<Vec<T>>,
    /// 1 / G_ν(ν₀, 0).
    inv_slope: C<T>,
    /// ν's coefficients so far.
    pub nu: Vec<C<T>>,
    /// log z's coefficients so far (`log_coeff`).
    log: Vec<C<T>>,
    /// ν^j's coefficients to t^(ν's length − 1), for j below χ's degree
    /// in z plus one (`grow`).
    pows: Vec<Vec<C<T>>>,
}

impl<T: Scalar> Branch<T> {
    /// The branch, or `Ok(None)` where a coefficient of χ is not a `T`.
    pub fn new(chi: &Poly, t: Sym, nu0: C<T>) -> Result<Option<Branch<T>>, NoBranch> {
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
        let mut g: Vec<Vec<T>> = vec![Vec::new(); a.len()];
        for (j, row) in a.iter().enumerate() {
            for (k, c) in row.iter().enumerate() {
                if c.is_zero() {
                    continue;
                }
                let Some(c) = T::of(c) else { return Ok(None) };
                let e = j + k - m;
                if g[j].len() <= e {
                    g[j].resize(e + 1, T::zero());
                }
                g[j][e] = c;
            }
        }
        let at0 = |j: usize| g[j].first().cloned().unwrap_or_else(T::zero);
        let mut value = C::default();
        let mut slope = C::default();
        let mut pow = C::real(T::one());
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
        Ok(Some(Branch { g, inv_slope, nu: vec![nu0], log: vec![C::default()], pows: Vec::new() }))
    }

    /// Adds the next coefficient of ν. The series of ν^j are kept from
    /// step to step: the coefficient of tⁿ of ν^j is found first with
    /// ν_n = 0, and then corrected by j·ν₀^(j−1)·ν_n once ν_n is known, so a
    /// step costs O(deg·n) products, not O(deg·n²).
    pub fn grow(&mut self) {
        let n = self.nu.len();
        let deg = self.g.len();
        if self.pows.is_empty() {
            // ν^j to t⁰: ν₀^j.
            let mut p = C::real(T::one());
            for _ in 0..deg {
                self.pows.push(vec![p.clone()]);
                p = p.mul(&self.nu[0]);
            }
        }
        // tentative[j]: the coefficient of tⁿ of ν^j with ν_n = 0.
        let mut tentative: Vec<C<T>> = vec![C::default(); deg];
        for j in 1..deg {
            let mut s = self.nu[0].mul(&tentative[j - 1]);
            for k in 1..n {
                let (a, b) = (&self.nu[k], &self.pows[j - 1][n - k]);
                if !a.is_zero() && !b.is_zero() {
                    s = s.add(&a.mul(b));
                }
            }
            tentative[j] = s;
        }
        // The coefficient of tⁿ in G(ν, t) with ν_n = 0.
        let mut r = C::default();
        for (j, row) in self.g.iter().enumerate() {
            for (k, c) in row.iter().enumerate().take(n + 1) {
                if c.is_zero() {
                    continue;
                }
                let p = if k == 0 { &tentative[j] } else { &self.pows[j][n - k] };
                if !p.is_zero() {
                    r = r.add(&p.mul(&C::real(c.clone())));
                }
            }
        }
        let next = C::default().sub(&r.mul(&self.inv_slope));
        for (j, mut v) in tentative.into_iter().enumerate() {
            if j > 0 && !next.is_zero() {
                let d = self.pows[j - 1][0].mul(&next).scale(&Q::from_integer((j as i64).into()));
                v = v.add(&d);
            }
            self.pows[j].push(v);
        }
        self.nu.push(next);
    }

    /// z's coefficients 1, ν₀, ν₁, … (z = 1 + Σ ν_n t^(n+1)).
    pub fn z_coeffs(&self) -> Vec<C<T>> {
        let mut z = vec![C::real(T::one())];
        z.extend(self.nu.iter().cloned());
        z
    }

    /// The coefficient of tⁿ of log z = log(1 + tν) (n ≤ ν's length),
    /// from z L' = z': L_n = z_n − (1/n) Σ_{k<n} k L_k z_(n−k), each
    /// coefficient computed once.
    pub fn log_coeff(&mut self, n: usize) -> &C<T> {
        while self.log.len() <= n {
            let m = self.log.len();
            let z = |k: usize| if k == 0 { C::real(T::one()) } else { self.nu[k - 1].clone() };
            let mut s = C::default();
            for k in 1..m {
                let zk = z(m - k);
                if !zk.is_zero() && !self.log[k].is_zero() {
                    s = s.add(&self.log[k].mul(&zk).scale(&Q::from_integer((k as i64).into())));
                }
            }
            let next = z(m).sub(&s.scale(&Q::new(1.into(), (m as i64).into())));
            self.log.push(next);
        }
        &self.log[n]
    }
}

/// 1/n! as a rational.
pub(crate) fn inverse_factorial(n: usize) -> Q {
    let mut f = <Q as One>::one();
    for k in 2..=n {
        f *= Q::from_integer((k as i64).into());
    }
    f.recip()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The truncated product of two series.
    fn mul<T: Scalar>(a: &[C<T>], b: &[C<T>], len: usize) -> Vec<C<T>> {
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

    /// The slow, obvious log: Σ_k (−1)^(k+1) x^k / k with x = tν, every
    /// power multiplied out.
    fn log_by_powers<T: Scalar>(nu: &[C<T>]) -> Vec<C<T>> {
        let len = nu.len() + 1;
        let mut x = vec![C::default()];
        x.extend(nu.iter().cloned());
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

    /// The slow, obvious step: every power of ν multiplied out again.
    fn grow_by_powers<T: Scalar>(b: &mut Branch<T>) {
        let n = b.nu.len();
        let len = n + 1;
        let mut nu = b.nu.clone();
        nu.push(C::default());
        // The coefficient of t^n in G(ν, t) with ν_n = 0.
        let mut r = C::default();
        let mut pow: Vec<C<T>> = vec![C::real(T::one())];
        pow.resize(len, C::default());
        for row in &b.g {
            for (k, c) in row.iter().enumerate().take(len) {
                if !c.is_zero() && !pow[n - k].is_zero() {
                    r = r.add(&pow[n - k].mul(&C::real(c.clone())));
                }
            }
            pow = mul(&pow, &nu, len);
        }
        let next = C::default().sub(&r.mul(&b.inv_slope));
        b.nu.push(next);
    }

    /// The kept powers against multiplying them out, on the same branches.
    #[test]
    fn incremental_powers_match_multiplied_out() {
        for text in [
            "z^2 - 2*(1 - Phi^2/2 + Phi^4/24)*z + 1 + Phi^6/36",
            "(1 + Phi^2/4)*z^2 - 2*(1 - Phi^2/4)*z + 1 + Phi^2/4 - Phi^3/7",
            "(z^2 - 2*z + Phi^2*z + 1 + Phi^3/5)*(z - Phi/2)",
            "(z^2 - 2*z + Phi^2*z + 1)*(z^2 - Phi*z/3 + Phi^2)*(z + Phi^4)",
        ] {
            let chi = Poly::parse(text).unwrap();
            let mut fast = Branch::<Q>::new(&chi, Sym::phi(), C::i()).unwrap().unwrap();
            let mut slow = Branch::<Q>::new(&chi, Sym::phi(), C::i()).unwrap().unwrap();
            for n in 1..12 {
                fast.grow();
                grow_by_powers(&mut slow);
                assert_eq!(fast.nu, slow.nu, "{text}: to t^{n}");
            }
        }
    }

    /// The recurrence against the powers, over Q and over Q(√2), on
    /// branches that neither stay on the circle nor are polynomials.
    #[test]
    fn log_recurrence_matches_powers() {
        for text in [
            "z^2 - 2*(1 - Phi^2/2 + Phi^4/24)*z + 1 + Phi^6/36",
            "(1 + Phi^2/4)*z^2 - 2*(1 - Phi^2/4)*z + 1 + Phi^2/4 - Phi^3/7",
            "(z^2 - 2*z + Phi^2*z + 1 + Phi^3/5)*(z - Phi/2)",
        ] {
            let chi = Poly::parse(text).unwrap();
            let mut q = Branch::<Q>::new(&chi, Sym::phi(), C::i()).unwrap().unwrap();
            let mut f = Branch::<Poly>::new(&chi, Sym::phi(), C::i()).unwrap().unwrap();
            for _ in 0..9 {
                q.grow();
                f.grow();
            }
            let (slow_q, slow_f) = (log_by_powers(&q.nu), log_by_powers(&f.nu));
            for n in 0..slow_q.len() {
                assert_eq!(*q.log_coeff(n), slow_q[n], "{text}: t^{n} over Q");
                assert_eq!(*f.log_coeff(n), slow_f[n], "{text}: t^{n} over F");
                assert_eq!(Poly::constant(slow_q[n].im.clone()), slow_f[n].im, "{text}: Q = F");
            }
        }
        let r2 = Poly::sym(field::generator(2, 2));
        let chi = &Poly::parse("z^2 - (2 - Phi^2)*z + 1").unwrap()
            + &(&r2 * &Poly::parse("Phi^3 - Phi^4*z").unwrap());
        assert!(Branch::<Q>::new(&chi, Sym::phi(), C::i()).unwrap().is_none(), "√2 is not in Q");
        let mut f = Branch::<Poly>::new(&chi, Sym::phi(), C::i()).unwrap().unwrap();
        for _ in 0..7 {
            f.grow();
        }
        let slow = log_by_powers(&f.nu);
        for (n, c) in slow.iter().enumerate() {
            assert_eq!(*f.log_coeff(n), *c, "sqrt(2): t^{n}");
        }
    }

    /// Explicit Euler z − 1 − w: z₁ = 1 + w exactly.
    #[test]
    fn explicit_euler_branch_is_one_plus_w() {
        let chi = Poly::parse("z - 1 - w").unwrap();
        let mut b = Branch::new(&chi, Sym::w(), C::real(Poly::one())).unwrap().unwrap();
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
        let mut b = Branch::new(&chi, Sym::w(), C::real(Poly::one())).unwrap().unwrap();
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
        let mut b = Branch::<Poly>::new(&chi, Sym::phi(), C::i()).unwrap().unwrap();
        for _ in 0..6 {
            b.grow();
        }
        let log: Vec<C> = (0..=6).map(|n| b.log_coeff(n).clone()).collect();
        assert!(log.iter().all(|c| c.re.is_zero()), "|z| = 1: {log:?}");
        assert_eq!(log[1], C::i());
        assert!(Branch::<Poly>::new(&chi, Sym::phi(), C::real(Poly::one())).is_err());
        // The same series over Q.
        let mut q = Branch::<Q>::new(&chi, Sym::phi(), C::i()).unwrap().unwrap();
        for _ in 0..6 {
            q.grow();
        }
        for (n, c) in log.iter().enumerate() {
            let d = q.log_coeff(n);
            assert_eq!(
                (Poly::constant(d.re.clone()), Poly::constant(d.im.clone())),
                (c.re.clone(), c.im.clone())
            );
        }
    }
}
