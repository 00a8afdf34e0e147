//! Exact stability analysis of a characteristic polynomial χ(z; Φ) over all
//! step sizes Φ > 0, in time polynomial in the degree of χ.
//!
//! The root class of χ (section 4's taxonomy, [`RootClass`]) can change only
//! at finitely many *critical* Φ, the positive roots of the polynomials in
//! Φ listed in `conditions`: the leading and constant coefficients, χ(1),
//! χ(−1), the unit-circle condition ∏_{i<j}(1 − z_i z_j) (Jury's inners
//! determinant, of degree ≤ (n − 1)·deg_Φ; for a self-reciprocal factor the
//! discriminant of G with g(z) = z^m G(z + 1/z)), the discriminant in z, and
//! ties for the largest modulus. Each is computed over Z\[Φ\] by modular
//! evaluation and interpolation, made square-free, and its positive real
//! roots are isolated with Sturm sequences as exact [`Algebraic`](crate::Algebraic) numbers.
//!
//! Between consecutive critical points the counts of roots inside, on and
//! outside the unit circle, and the class, are constant; one exact
//! computation at a rational sample decides them (`point.rs`: Schur–Cohn
//! inertia over Q, real-root isolation, rational brackets of the dominant
//! modulus). At each critical point the class is exact for rational points
//! and for second-order χ (signs of polynomials at an algebraic number);
//! boundedness at a critical point next to a bounded interval is decided
//! for any degree in Q(α): a repeated root on the circle (gcds over Q(α))
//! is bounded exactly when it is semisimple in the transition matrix P:
//! rank q(P) = rank q(P)² for the square-free q of the repeated roots on the
//! circle. [`Derivation::stability`] decides it so; an analysis of χ alone
//! ([`analyze`]) reports such a point as undecided, never as unbounded.
//!
//! No float decides anything.
//!
//! Limitations (stated, not hidden): for degree ≥ 5, ties for the largest
//! modulus between a real root and a complex pair are not among the critical
//! conditions, so a class change (monotonic ↔ oscillatory) from such a tie
//! inside an interval could go unlisted. For degree ≥ 3 the class exactly at
//! an irrational critical point is computed where a neighbouring class keeps
//! every root in the closed unit disc and a root lies on the circle there
//! (every stability limit): the roots on the circle are then those of
//! gcd(χ, z^n χ(1/z)) over Q(α). Elsewhere (a point strictly inside the
//! stable range, or between two unbounded classes) it is not computed
//! (`at_class` is `None`), while boundedness there is. The stability limit and the bounded/unbounded
//! split are exact for every degree, because boundedness changes only where
//! a root meets the unit circle.

mod conditions;
pub mod constants;
pub(crate) mod point;
mod rational;
mod report;

pub use constants::{limit_at_infinity, LimitAtInfinity};
#[doc(hidden)]
pub use point::classify_roots_by_products;
pub use point::Counts;
pub use point::{classify, classify_pq, PqSigns};
pub use report::{
    Boundary, ClassAt, ClassChange, ClassInterval, Condition, CriticalPoint, Marginal, Stability,
    StabilityReport, StableInterval,
};

use crate::error::{Error, ErrorKind};
use crate::multivariate::constants::has_generators;
use crate::{Derivation, Params, Poly, RootClass, Sym, UPoly, Q};

/// The exact stability analysis of a bare χ(z; Φ), for a caller who holds
/// only the polynomial (every parameter but Φ given a value). A repeated
/// root on the unit circle is bounded or not according to the transition
/// matrix, which χ does not carry: such a point is reported as
/// [`Stability::UndecidedAt`], never as unbounded. With a derivation at
/// hand, ask [`Derivation::stability`], which decides it.
///
/// ```
/// let chi = poly::Poly::parse("z^2 - 2*(1 - Phi^2/2)*z + 1")?; // False Euler
/// let report = poly::advanced::stability::analyze(&chi)?;
/// // Bounded below 2; at 2 a double root at −1, which only P decides.
/// assert_eq!(report.undecided_at().unwrap().to_string(), "2");
/// assert_eq!(report.boundary(), Some(poly::Boundary::DoubleRootAtMinusOne));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn analyze(charpoly: &Poly) -> Result<StabilityReport, Error> {
    if has_generators(charpoly) {
        return constants::analyze(charpoly, None);
    }
    rational::analyze(charpoly, None)
}

impl Derivation {
    /// The exact stability analysis over Φ > 0, with every parameter of the
    /// method but Φ bound in `params`: the stability limit, the stable
    /// intervals and the class on every interval. Boundedness where a root
    /// on the unit circle is repeated is decided from the transition matrix
    /// P (bounded exactly when P is semisimple there).
    ///
    /// ```
    /// let d = poly::derive(&poly::Method::builtin("false_euler")?)?;
    /// let report = d.stability(&poly::Params::new())?;
    /// assert_eq!(report.phi_max().unwrap().to_string(), "2");
    /// assert_eq!(report.bounded_at_phi_max(), Some(false));
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn stability(&self, params: &Params) -> Result<StabilityReport, Error> {
        self.refuse_scalar()?;
        let values = self.bind(params)?;
        let charpoly = self.charpoly().eval_partial(&values);
        if has_generators(&charpoly) {
            return constants::analyze(&charpoly, Some(&self.numerator_at(&values)));
        }
        let (rows, denominator) = self.step_matrix_in_phi(&values)?;
        rational::analyze(
            &charpoly,
            Some(rational::StepMatrix { numerator: &rows, denominator: &denominator }),
        )
    }

    /// The root class exactly at a rational Φ, with the method's other
    /// parameters bound in `params`, and whether the sequence stays bounded
    /// there: where χ has a repeated root on the unit circle
    /// ([`RootClass::DoubleRootOnCircle`], which χ alone leaves undecided),
    /// boundedness is decided from the transition matrix P, as
    /// [`Derivation::stability`] does (bounded exactly when P is semisimple
    /// there).
    ///
    /// ```
    /// let d = poly::derive(&poly::builtin("false_euler")?)?;
    /// // At Φ = 2 both roots meet at −1 and P is a Jordan block: it grows.
    /// let at = d.class_at(&poly::Params::new(), &poly::q(2, 1))?;
    /// assert_eq!(at.class, poly::RootClass::DoubleRootOnCircle);
    /// assert!(!at.bounded);
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn class_at(&self, params: &Params, phi: &Q) -> Result<ClassAt, Error> {
        let values = self.bind(params)?;
        let mut at = values.clone();
        at.insert(Sym::phi(), phi.clone());
        if self
            .p_denominator()
            .eval_partial(&at)
            .as_constant()
            .is_some_and(|d| num_traits::Zero::is_zero(&d))
        {
            return Ok(ClassAt { class: RootClass::Singular, bounded: false });
        }
        let charpoly = self.charpoly().eval_partial(&values);
        let class = class_at(&charpoly, phi)?;
        let bounded = match class.bounded() {
            Some(bounded) => bounded,
            None if has_generators(&charpoly) => {
                constants::scalar_at(&self.numerator_at(&values), phi)
            }
            None => {
                let (rows, denominator) = self.step_matrix_in_phi(&values)?;
                rational::bounded_on_circle_at(
                    &conditions::Charpoly::new(&charpoly)?,
                    phi,
                    rational::StepMatrix { numerator: &rows, denominator: &denominator },
                )
            }
        };
        Ok(ClassAt { class, bounded })
    }

    /// The numerator of P (P times det A) with the parameters but Φ bound.
    fn numerator_at(&self, values: &std::collections::HashMap<Sym, Q>) -> Vec<Vec<Poly>> {
        let p = self.transition_matrix();
        (0..p.rows()).map(|i| p.row(i).iter().map(|e| e.eval_partial(values)).collect()).collect()
    }

    /// The numerator of P and its denominator det A as polynomials in Φ,
    /// the other parameters bound.
    fn step_matrix_in_phi(
        &self,
        values: &std::collections::HashMap<Sym, Q>,
    ) -> Result<(Vec<Vec<UPoly>>, UPoly), Error> {
        let phi = Sym::phi();
        let in_phi = |e: &Poly, what: &str| {
            let e = e.eval_partial(values);
            e.to_upoly(phi).ok_or_else(|| {
                Error::analysis(
                    ErrorKind::ExtraSymbol,
                    format!("{what} {e} still contains a parameter; expected a polynomial in Phi only (give it a value)"),
                )
            })
        };
        let p = self.transition_matrix();
        let rows: Vec<Vec<UPoly>> = (0..p.rows())
            .map(|i| p.row(i).iter().map(|e| in_phi(e, "transition matrix entry")).collect())
            .collect::<Result<_, _>>()?;
        let denominator = in_phi(self.p_denominator(), "the step's determinant det A,")?;
        Ok((rows, denominator))
    }

    /// The values of every parameter of the method but Φ, refusing names
    /// the method does not declare and Φ itself (the analysis covers every
    /// Φ > 0).
    pub(crate) fn bind(&self, params: &Params) -> Result<std::collections::HashMap<Sym, Q>, Error> {
        let method = self.method();
        if let Some(name) = params.undeclared(method).next() {
            return Err(Error::analysis(
                ErrorKind::ExtraSymbol,
                format!(
                    "method `{}` has no parameter {name}; expected one of: {}",
                    method.name(),
                    param_list(method.params())
                ),
            ));
        }
        let others: Vec<Sym> =
            method.params().iter().copied().filter(|&s| s != Sym::phi()).collect();
        if params.value("Phi").is_some() {
            return Err(Error::analysis(
                ErrorKind::ExtraSymbol,
                "Phi is bound, but the analysis covers every Phi > 0; expected values for the other parameters only".to_owned(),
            ));
        }
        params.values_of(&others).map_err(|name| {
            let given = params
                .iter()
                .map(|(n, v)| (Sym::new(n), v.clone()))
                .collect::<std::collections::HashMap<_, _>>();
            let chi = self.charpoly().eval_partial(&given);
            Error::analysis(
                ErrorKind::ExtraSymbol,
                format!(
                    "characteristic polynomial {chi} still contains the parameter {name}; \
                     expected a polynomial in z and Phi only (give {name} a value)"
                ),
            )
        })
    }
}

fn param_list(params: &[Sym]) -> String {
    let names: Vec<&str> = params.iter().map(|s| s.name()).filter(|n| *n != "Phi").collect();
    if names.is_empty() {
        "none but Phi".to_owned()
    } else {
        names.join(", ")
    }
}

/// Only the verdict over Φ > 0 of a bare χ (root condition: a repeated root
/// on the circle is undecided), computing only the conditions where a root
/// meets the unit circle: the w-plane's axes and rays ask nothing else.
pub(crate) fn verdict(charpoly: &Poly) -> Result<Stability, Error> {
    if has_generators(charpoly) {
        return Ok(constants::analyze(charpoly, None)?.stability);
    }
    rational::verdict(charpoly)
}

/// The root class of χ at a rational Φ, exactly, from χ alone.
///
/// χ does not carry the transition matrix P, so this answer needs P to be a
/// verdict on boundedness: a repeated root on the unit circle comes back as
/// [`RootClass::DoubleRootOnCircle`], whose [`RootClass::bounded`] is
/// `None` (undecided without P), never as unbounded. With a derivation at
/// hand, ask [`Derivation::class_at`], which decides it from P.
///
/// ```
/// // Three substeps of False Euler at Φ = 3: χ = (z + 1)², and P = −I.
/// let chi = poly::Poly::parse("z^2 + 2*z + 1")?;
/// let class = poly::advanced::stability::class_at(&chi, &poly::q(3, 1))?;
/// assert_eq!(class, poly::RootClass::DoubleRootOnCircle);
/// assert_eq!(class.bounded(), None);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn class_at(charpoly: &Poly, phi: &Q) -> Result<RootClass, Error> {
    // Exact constants (sqrt(3), cbrt(2)): the norm-based layer.
    if has_generators(charpoly) {
        return constants::class_at(charpoly, phi);
    }
    let chi = conditions::Charpoly::new(charpoly)?;
    Ok(rational::class_at_rational(&chi, phi).0)
}
