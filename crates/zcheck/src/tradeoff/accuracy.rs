//! Accuracy of a second-order method at a step Φ, from its exact
//! characteristic polynomial, and the largest step that meets a target.
//!
//! For χ(z) = z² − 2p(Φ)z + q(Φ) the principal roots are
//! z = p ± j√(q − p²) = r·e^{±jΨ} when Δ = q − p² > 0 (section 4). The exact
//! spring v̇ = −ω₀(y + 2Dv), ẏ = ω₀v advances by e^{(−D ± j√(1−D²))Φ} per
//! step. Per step the method is off by
//!
//! $$ \delta\Psi = \Psi - \Phi\sqrt{1 - D^2}, \qquad
//!    \delta\ln r = \ln r + D\Phi = \tfrac12 \ln(1 + (q - 1)) + D\Phi, $$
//!
//! and over a duration of P periods (n = P·2π/Φ steps) the phase drifts by
//! n·|δΨ| radians and the amplitude by the factor e^{n·δln r}.
//!
//! **Precision.** p, q − 1 and Δ are exact polynomials in Φ, converted to f64
//! coefficients once and evaluated by Horner, so each has full relative
//! precision at small Φ (no `1 − (1 − Φ²/2)²` cancellation); ln r uses
//! `ln_1p(q − 1)`. Only δΨ = Ψ − Φ cancels: its absolute error is a few ulps
//! of Ψ, i.e. a relative error of about ε·Φ/|δΨ| (≈ 24ε/Φ² for False Euler),
//! below 1e-6 for Φ ≥ 1e-4. The search below never goes under `PHI_MIN`.

use std::collections::HashMap;
use std::f64::consts::PI;

use poly::{Poly, Sym, Q};

use crate::error::Error;

/// The smallest step the admissible-Φ search considers.
pub(crate) const PHI_MIN: f64 = 1e-5;

/// A polynomial in Φ with f64 coefficients: `check`'s one evaluator.
#[derive(Clone, Debug)]
struct PhiPoly(check::sweep::HornerPoly);

impl PhiPoly {
    fn from_exact(p: &Poly) -> Result<PhiPoly, Error> {
        check::sweep::HornerPoly::new(p, Sym::phi()).map(PhiPoly).ok_or_else(|| {
            Error::unsupported(format!(
                "coefficient {p} depends on more than Phi: expected every other parameter to have \
                 a value"
            ))
        })
    }

    fn eval(&self, phi: f64) -> f64 {
        self.0.value(phi)
    }
}

/// The exact spring a method is judged against: undamped (D = 0) or with a
/// physical damping ratio 0 ≤ D < 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Spring {
    /// The damping ratio D of ÿ + 2Dω₀ẏ + ω₀²y = 0.
    pub damping: f64,
}

impl Spring {
    /// The undamped spring of sections 5–11.
    pub(crate) const UNDAMPED: Spring = Spring { damping: 0.0 };

    /// The exact phase advance per step, Φ√(1 − D²).
    pub(crate) fn psi_exact(self, phi: f64) -> f64 {
        phi * (1.0 - self.damping * self.damping).sqrt()
    }

    /// The exact ln|z| per step, −DΦ.
    pub(crate) fn ln_r_exact(self, phi: f64) -> f64 {
        -self.damping * phi
    }
}

/// What a duration of simulation must meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Target {
    /// Largest accumulated phase error over the duration, in radians.
    pub phase_tol: f64,
    /// Largest relative amplitude change over the duration (0.01 = 1 %).
    pub amp_tol: f64,
    /// The duration, in periods of the undamped spring (2π/Φ steps each).
    pub periods: f64,
}

impl Target {
    /// The defaults of `zcheck tradeoff`: 0.1 rad and 1 % over 10 periods.
    pub(crate) const DEFAULT: Target = Target { phase_tol: 0.1, amp_tol: 0.01, periods: 10.0 };
}

/// One method's second-order model, χ = a·z² + b·z + c with a, b, c
/// polynomials in Φ (a = 1 for an explicit method, det A for an implicit
/// one): p = −b/2a, q − 1 = (c − a)/a and Δ = q − p² = (4ac − b²)/4a², each
/// numerator exact before it is rounded.
#[derive(Clone, Debug)]
pub(crate) struct SecondOrder {
    /// −b/2, the numerator of p.
    p: PhiPoly,
    /// c − a, the numerator of q − 1.
    q_minus_one: PhiPoly,
    /// 4ac − b², the numerator of 4a²Δ.
    disc: PhiPoly,
    /// a, the leading coefficient (`None` when it is 1).
    lead: Option<PhiPoly>,
}

/// The principal root and its errors at one Φ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Accuracy {
    /// The step.
    pub phi: f64,
    /// Whether the roots are a complex pair (an oscillation); a method with
    /// real roots at Φ does not oscillate and meets no target.
    pub oscillating: bool,
    /// The angle of the principal root, in [0, π].
    pub psi: f64,
    /// Ψ − Φ√(1 − D²): the phase error per step (positive: too fast).
    pub phase_error_per_step: f64,
    /// ln|z| + DΦ: the log amplitude error per step (positive: gains energy).
    pub ln_growth_per_step: f64,
}

impl Accuracy {
    /// Steps in `periods` periods: P·2π/Φ (not rounded: a duration is time).
    pub(crate) fn steps(&self, periods: f64) -> f64 {
        periods * 2.0 * PI / self.phi
    }

    /// |z/z_exact|^(2π/Φ): the amplitude factor per period.
    pub(crate) fn amplitude_factor_per_period(&self) -> f64 {
        (self.ln_growth_per_step * self.steps(1.0)).exp()
    }

    /// The accumulated phase error over `periods`, in radians.
    pub(crate) fn phase_drift(&self, periods: f64) -> f64 {
        if !self.oscillating {
            return f64::INFINITY;
        }
        self.phase_error_per_step.abs() * self.steps(periods)
    }

    /// The relative amplitude change over `periods`, |e^{n·δln r} − 1|.
    pub(crate) fn amplitude_drift(&self, periods: f64) -> f64 {
        (self.ln_growth_per_step * self.steps(periods)).exp_m1().abs()
    }

    /// The larger of the two drifts (radians and relative amplitude, which
    /// are comparable for small errors): the error axis of the
    /// work-precision figure.
    pub(crate) fn error(&self, periods: f64) -> f64 {
        self.phase_drift(periods).max(self.amplitude_drift(periods))
    }

    /// Whether the target is met at this Φ.
    pub(crate) fn meets(&self, target: &Target) -> bool {
        self.oscillating
            && self.phase_drift(target.periods) <= target.phase_tol
            && self.amplitude_drift(target.periods) <= target.amp_tol
    }
}

impl SecondOrder {
    /// The model of `charpoly` (a polynomial in z and the parameters) with
    /// every parameter but Φ given a value. Errs unless χ is monic of degree 2.
    pub(crate) fn new(charpoly: &Poly, params: &[(Sym, Q)]) -> Result<SecondOrder, Error> {
        let values: HashMap<Sym, Q> = params.iter().cloned().collect();
        let chi = charpoly.eval_partial(&values);
        let c = chi.coeffs_in(Sym::z());
        if c.len() != 3 {
            return Err(Error::unsupported(format!(
                "characteristic polynomial {chi} is not of degree 2 in z: expected a second-order method"
            )));
        }
        let a = &c[2];
        let p = &c[1] * &Poly::constant(poly::q(-1, 2));
        let q_minus_one = &c[0] - a;
        // 4a²Δ = 4ac − b² = 4(ac − p²).
        let disc = &(&(a * &c[0]) - &(&p * &p)) * &Poly::int(4);
        Ok(SecondOrder {
            p: PhiPoly::from_exact(&p)?,
            q_minus_one: PhiPoly::from_exact(&q_minus_one)?,
            disc: PhiPoly::from_exact(&disc)?,
            lead: if a.is_one() { None } else { Some(PhiPoly::from_exact(a)?) },
        })
    }

    /// a(Φ), or 1.
    fn a(&self, phi: f64) -> f64 {
        self.lead.as_ref().map_or(1.0, |a| a.eval(phi))
    }

    /// The principal root's angle and log modulus at Φ: `(psi, ln_r,
    /// oscillating)`. For real roots, the root of largest modulus, at angle
    /// 0 or π.
    pub(crate) fn principal_root(&self, phi: f64) -> (f64, f64, bool) {
        let a = self.a(phi);
        let p = self.p.eval(phi) / a;
        let disc = self.disc.eval(phi) / (4.0 * a * a);
        if disc > 0.0 {
            let ln_r = 0.5 * (self.q_minus_one.eval(phi) / a).ln_1p();
            (disc.sqrt().atan2(p), ln_r, true)
        } else {
            let s = (-disc).sqrt();
            let big = if p >= 0.0 { p + s } else { p - s };
            (if big >= 0.0 { 0.0 } else { PI }, big.abs().ln(), false)
        }
    }

    /// The accuracy at Φ against `spring`.
    pub(crate) fn accuracy(&self, phi: f64, spring: Spring) -> Accuracy {
        let (psi, ln_r, oscillating) = self.principal_root(phi);
        Accuracy {
            phi,
            oscillating,
            psi,
            phase_error_per_step: psi - spring.psi_exact(phi),
            ln_growth_per_step: ln_r - spring.ln_r_exact(phi),
        }
    }

    /// The largest Φ below `phi_cap` such that every step in [PHI_MIN, Φ]
    /// meets `target` (the first failure on a log grid of 64 points per
    /// decade, then bisection to a relative width of 1e-12). `None` when
    /// even `PHI_MIN` fails or the cap is below it.
    ///
    /// The caller passes a cap strictly below the exact stability limit, so
    /// the answer is never a step at or beyond `phi_max`.
    pub(crate) fn largest_admissible_phi(
        &self,
        spring: Spring,
        target: &Target,
        phi_cap: f64,
    ) -> Option<f64> {
        if phi_cap.is_nan() || phi_cap <= PHI_MIN || !self.accuracy(PHI_MIN, spring).meets(target) {
            return None;
        }
        let per_decade = 64.0;
        let n = ((phi_cap / PHI_MIN).log10() * per_decade).ceil() as usize;
        let mut lo = PHI_MIN;
        let mut hi = None;
        for k in 1..=n {
            let phi = (PHI_MIN * 10f64.powf(k as f64 / per_decade)).min(phi_cap);
            if self.accuracy(phi, spring).meets(target) {
                lo = phi;
            } else {
                hi = Some(phi);
                break;
            }
        }
        // Every grid point up to the cap passed.
        let Some(mut hi) = hi else { return Some(lo) };
        while (hi - lo) > 1e-12 * lo {
            let mid = 0.5 * (lo + hi);
            if self.accuracy(mid, spring).meets(target) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(lo)
    }
}
