//! The walk over Φ > 0: critical points, a class per interval, the class
//! and boundedness at the points, the stability limit and the stable
//! intervals.

use num_traits::{One, Signed, Zero};

use crate::error::Error;
use crate::univariate::algebraic::Algebraic;
use crate::{Poly, RootClass, UPoly, Q};

use super::conditions::{conditions_of, critical_points, discriminant, Charpoly};
use super::point::{
    circle_counts, class_of_single_root, classify_quadratic_by, classify_with_counts,
    quadratic_counts_of, Counts,
};
use super::report::{
    Boundary, ClassChange, ClassInterval, Condition, CriticalPoint, Marginal, Stability,
    StabilityReport, StableInterval,
};
use crate::univariate::number_field::{FPoly, Field};

/// The class and root counts of χ at a rational Φ.
pub(crate) fn class_at_rational(chi: &Charpoly, phi: &Q) -> (RootClass, Counts) {
    if chi.degree() == 2 {
        // The signs of the sign polynomials at φ are the signs of the same
        // expressions in χ(φ)'s coefficients (evaluation commutes with them),
        // taken in integers: a positive scale keeps each sign. No polynomial
        // in Φ is formed (`QuadPolys` waits for an irrational point), and no
        // fraction: χ(φ)·q^n, made primitive.
        let ints = crate::univariate::upoly::primitive(scaled_at(chi, phi));
        let coeff = |k: usize| ints.get(k).cloned().unwrap_or_default();
        let values = super::point::quadratic_terms(&coeff(0), &coeff(1), &coeff(2));
        let class = classify_quadratic_by(|k| values[k].cmp(&num_bigint::BigInt::zero()));
        let counts = match ints.len() {
            0 => Counts::default(),
            3 => quadratic_counts_of(ints),
            _ => circle_counts(&chi.at(phi)),
        };
        return (class, counts);
    }
    classify_with_counts(&chi.at(phi))
}

/// χ(φ)'s coefficients in z times q^n, for φ = p/q and n the largest degree
/// in Φ: integers (χ's a_k are integer polynomials), in the ratios of
/// [`Charpoly::at`]'s and with its signs, each Σ c_j p^j q^(n−j) with no
/// fraction reduced.
fn scaled_at(chi: &Charpoly, phi: &Q) -> Vec<num_bigint::BigInt> {
    use num_bigint::BigInt;
    let (p, q) = (phi.numer(), phi.denom());
    let n = chi.a.iter().map(|c| c.coeffs().len()).max().unwrap_or(1).saturating_sub(1);
    let q_powers: Vec<BigInt> =
        std::iter::successors(Some(BigInt::one()), |x| Some(x * q)).take(n + 1).collect();
    chi.a
        .iter()
        .map(|c| {
            let d = c.coeffs().len().saturating_sub(1);
            let mut acc = BigInt::zero();
            for (j, x) in c.coeffs().iter().enumerate().rev() {
                debug_assert!(x.is_integer(), "χ's coefficients are integer polynomials");
                acc = acc * p + x.numer() * &q_powers[d - j];
            }
            acc * &q_powers[n - d]
        })
        .collect()
}

/// The class of χ exactly at an algebraic Φ, when computed (rational Φ,
/// or degree ≤ 2).
pub(crate) fn class_at_point(chi: &Charpoly, phi: &Algebraic) -> Option<RootClass> {
    if let Some(q) = phi.as_rational() {
        return Some(class_at_rational(chi, q).0);
    }
    match chi.degree() {
        2 => {
            let q = chi.quad();
            Some(classify_quadratic_by(|k| {
                let (p, i) = q.entry(k);
                phi.sign_of_with(p, i)
            }))
        }
        1 => {
            // One root r = −a0/a1: signs of r, r − 1, r + 1 from polynomials.
            let (a0, a1) = (&chi.a[0], &chi.a[1]);
            let by = |o: std::cmp::Ordering| if phi.sign_of(a1).is_gt() { o } else { o.reverse() };
            Some(class_of_single_root(
                by(phi.sign_of(&-a0)),
                by(phi.sign_of(&-&(a0 + a1))),
                by(phi.sign_of(&(a1 - a0))),
            ))
        }
        _ => None,
    }
}

/// The discriminant condition (the square-free one the walk computed), or
/// 0 when it was not computed.
fn disc_of(conditions: &[(Condition, UPoly)]) -> UPoly {
    conditions
        .iter()
        .find(|(name, _)| *name == Condition::Discriminant)
        .map_or_else(UPoly::zero, |(_, d)| d.clone())
}

/// Whether every root of a class lies in the closed unit disc.
fn in_closed_disc(class: RootClass) -> bool {
    class.bounded() == Some(true) || class == RootClass::DoubleRootOnCircle
}

/// The class exactly at an irrational critical point α of a χ of any
/// degree, when a neighbouring class keeps every root in the closed unit
/// disc (a stability limit, or a point inside the bounded range). By
/// continuity no root is outside the circle at α, so a root z whose
/// reciprocal 1/z is also a root lies on the circle, and the roots on the
/// circle are those of e = gcd(f, z^n f(1/z)) over Q(α), with their
/// multiplicities. A repeated one gives
/// [`RootClass::DoubleRootOnCircle`]; otherwise section 4's tie rules (as
/// in `classify_roots_by_products`): a complex one gives
/// [`RootClass::Harmonic`], else −1 [`RootClass::Alternating`], else +1
/// [`RootClass::Constant`]. With no root on the circle the dominant root is
/// inside, and which kind it is is not decided here (`None`).
///
/// Where the roots are simple (α is not a root of the discriminant) and χ
/// is not self-reciprocal, no gcd over Q(α) is needed: a pair z_i z_j = 1
/// of distinct roots, none outside, is a complex pair on the circle, so the
/// unit-circle condition vanishing at α says Harmonic, and χ(∓1) = 0 says
/// Alternating or Constant.
fn class_on_circle_at(
    chi: &Charpoly,
    point: &CriticalPoint,
    sides: [RootClass; 2],
    conditions: &[(Condition, UPoly)],
) -> Option<RootClass> {
    if !sides.iter().any(|&c| in_closed_disc(c)) {
        return None;
    }
    let alpha = &point.at;
    let has = |c: Condition| point.conditions.contains(&c);
    // A self-reciprocal factor's roots are paired with their reciprocals
    // for every Φ: its unit-circle condition is replaced by the reciprocal
    // discriminant, and the shortcut does not apply.
    let reciprocal = conditions.iter().any(|(n, _)| *n == Condition::ReciprocalDiscriminant);
    let disc = disc_of(conditions);
    if !reciprocal && !disc.is_zero() && !alpha.is_root_of(&disc) {
        return if has(Condition::UnitCircle) {
            Some(RootClass::Harmonic)
        } else if has(Condition::ChiAtMinusOne) {
            Some(RootClass::Alternating)
        } else if has(Condition::ChiAtOne) {
            Some(RootClass::Constant)
        } else {
            None
        };
    }
    let mut field = Field::new(alpha);
    let f: FPoly = field.trim(chi.a.iter().map(|c| field.reduce(c)).collect());
    // Roots at zero are inside the circle: strip them.
    let lowest = f.iter().position(|c| !field.is_zero(c))?;
    let f: FPoly = f[lowest..].to_vec();
    if f.len() < 2 {
        return Some(RootClass::Deadbeat);
    }
    let rev: FPoly = f.iter().rev().cloned().collect();
    let e = field.gcd(&f, &rev);
    if e.len() < 2 {
        return None;
    }
    let de = field.derivative(&e);
    if field.gcd(&e, &de).len() >= 2 {
        return Some(RootClass::DoubleRootOnCircle);
    }
    let vanishes_at = |x: i64, field: &Field| {
        let mut sum = UPoly::zero();
        let mut power = Q::one();
        for c in &e {
            sum = &sum + &c.scale(&power);
            power *= Q::from_integer(x.into());
        }
        field.is_zero(&sum)
    };
    let (at_one, at_minus_one) = (vanishes_at(1, &field), vanishes_at(-1, &field));
    let real_on_circle = usize::from(at_one) + usize::from(at_minus_one);
    Some(if e.len() - 1 > real_on_circle {
        RootClass::Harmonic
    } else if at_minus_one {
        RootClass::Alternating
    } else {
        RootClass::Constant
    })
}

/// The exact stability analysis of a χ(z; Φ) over Q, with the transition
/// matrix P when there is one: with P, boundedness where a root on the unit
/// circle is repeated is decided from P (bounded exactly when P is
/// semisimple there); without it, such a point is undecided.
pub(crate) fn analyze(
    charpoly: &Poly,
    step: Option<StepMatrix<'_>>,
) -> Result<StabilityReport, Error> {
    let chi = Charpoly::new(charpoly)?;
    Ok(run(&chi, step, Some(charpoly)))
}

/// The verdict alone (bare χ, no P), for callers that ask only where
/// boundedness holds (the w-plane's axes and rays): only the conditions
/// under which a root meets the unit circle or arrives from infinity are
/// computed, so the classes between them are not class-exact, and no
/// marginal analysis is made.
pub(crate) fn verdict(charpoly: &Poly) -> Result<Stability, Error> {
    let chi = Charpoly::new(charpoly)?;
    Ok(run_with(&chi, None, None, true).stability)
}

/// The transition matrix P = numerator / denominator, entries polynomials
/// in Φ (the denominator is det A of an implicit step's system, else 1).
#[derive(Clone, Copy)]
pub(crate) struct StepMatrix<'a> {
    pub(crate) numerator: &'a [Vec<UPoly>],
    pub(crate) denominator: &'a UPoly,
}

fn run(chi: &Charpoly, p: Option<StepMatrix<'_>>, charpoly: Option<&Poly>) -> StabilityReport {
    run_with(chi, p, charpoly, false)
}

fn run_with(
    chi: &Charpoly,
    p: Option<StepMatrix<'_>>,
    charpoly: Option<&Poly>,
    verdict_only: bool,
) -> StabilityReport {
    let conditions = conditions_of(chi, verdict_only);
    let mut points = critical_points(&conditions);

    // The class on each open interval, at a rational sample.
    let zero = Algebraic::zero();
    let mut samples = Vec::with_capacity(points.len() + 1);
    for k in 0..=points.len() {
        let lo = if k == 0 { &zero } else { &points[k - 1].at };
        let sample = match points.get(k) {
            Some(hi) => Algebraic::rational_between(lo, &hi.at),
            None => {
                let (_, hi) = lo.interval();
                hi.floor() + Q::one()
            }
        };
        samples.push(sample);
    }
    let at_samples: Vec<(RootClass, Counts)> =
        samples.iter().map(|s| class_at_rational(chi, s)).collect();
    let classes: Vec<RootClass> = at_samples.iter().map(|c| c.0).collect();
    // Boundedness on each open interval: the class's, except where a root
    // on the circle stays repeated over the whole interval (the class is
    // DoubleRootOnCircle there), which P decides at the sample and χ alone
    // leaves undecided (`None`).
    let bounded_on: Vec<Option<bool>> = classes
        .iter()
        .zip(&samples)
        .map(|(c, s)| c.bounded().or_else(|| p.map(|step| bounded_on_circle_at(chi, s, step))))
        .collect();
    let is_bounded = |k: usize| bounded_on[k] == Some(true);
    // Where the step's system is singular (det A = 0) the step is
    // undefined: its own class, never bounded.
    let at_classes: Vec<Option<RootClass>> = points
        .iter()
        .enumerate()
        .map(|(k, pt)| match p {
            Some(step) if pt.at.is_root_of(step.denominator) => Some(RootClass::Singular),
            _ if verdict_only => class_at_point(chi, &pt.at),
            _ => class_at_point(chi, &pt.at)
                .or_else(|| class_on_circle_at(chi, pt, [classes[k], classes[k + 1]], &conditions)),
        })
        .collect();

    // Boundedness exactly at every point next to a bounded interval.
    // The discriminant is one of the conditions already (computed once).
    // Only its roots may be used: for an even χ it is a₀·Disc F, with the
    // discriminant's roots but not its multiplicities or sign.
    let disc = std::cell::OnceCell::new();
    let disc = || {
        disc.get_or_init(|| {
            conditions
                .iter()
                .find(|(name, _)| *name == Condition::Discriminant)
                .map_or_else(|| discriminant(&chi.a), |(_, d)| d.clone())
        })
    };
    for (k, point) in points.iter_mut().enumerate() {
        if is_bounded(k) || is_bounded(k + 1) {
            // A root on the circle is ±1 (χ(±1) = 0) or has its conjugate
            // 1/z beside it (z_i z_j = 1): with none of those conditions
            // vanishing here, every root is strictly inside (next to a
            // bounded interval, none can be outside), whatever repeats.
            // This spares gcds over Q(α) of a high degree.
            let on_circle = point.conditions.iter().any(|c| {
                matches!(
                    c,
                    Condition::ChiAtOne
                        | Condition::ChiAtMinusOne
                        | Condition::UnitCircle
                        | Condition::ReciprocalDiscriminant
                )
            });
            point.bounded = if on_circle || at_classes[k].is_some() {
                bounded_at(chi, &point.at, at_classes[k], disc(), p)
            } else {
                Some(true)
            };
        }
    }

    // Merge intervals across critical points where nothing changes.
    let mut intervals = vec![ClassInterval {
        lo: zero.clone(),
        hi: None,
        class: classes[0],
        sample: samples[0].clone(),
        counts: at_samples[0].1,
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
            counts: at_samples[k + 1].1,
        });
    }

    // The stability limit: walk up from Φ = 0 while everything is bounded.
    let stability = if bounded_on[0].is_none() {
        // χ alone, a root on the circle repeated for every small Φ.
        Stability::UndecidedAt { at: zero.clone(), boundary: Boundary::Other }
    } else if !is_bounded(0) {
        Stability::UnboundedForAllPhi
    } else {
        let mut verdict = Stability::BoundedForAllPhi;
        for (k, point) in points.iter().enumerate() {
            let Some(at_bounded) = point.bounded else {
                // χ alone: a repeated root on the circle that P would decide.
                verdict = Stability::UndecidedAt {
                    at: point.at.clone(),
                    boundary: boundary_at(chi, point),
                };
                break;
            };
            if at_bounded && is_bounded(k + 1) {
                continue;
            }
            if at_bounded && bounded_on[k + 1].is_none() {
                // χ alone: a root on the circle repeated past this point.
                verdict = Stability::UndecidedAt {
                    at: point.at.clone(),
                    boundary: boundary_at(chi, point),
                };
                break;
            }
            verdict = Stability::Limited {
                phi_max: point.at.clone(),
                bounded_at_phi_max: at_bounded,
                boundary: if at_classes[k] == Some(RootClass::Singular) {
                    Boundary::SingularStep
                } else {
                    boundary_at(chi, point)
                },
            };
            break;
        }
        verdict
    };

    // Maximal bounded runs: open intervals joined through bounded points.
    let mut stable_intervals: Vec<StableInterval> = Vec::new();
    let mut open: Option<StableInterval> = None;
    for k in 0..=points.len() {
        if is_bounded(k) {
            if open.is_none() {
                let (lo, lo_closed) = if k == 0 {
                    (zero.clone(), false)
                } else {
                    (points[k - 1].at.clone(), points[k - 1].bounded == Some(true))
                };
                open = Some(StableInterval { lo, lo_closed, hi: None, hi_closed: false });
            }
            if let Some(pt) = points.get(k) {
                if pt.bounded == Some(true) && k + 1 < bounded_on.len() && is_bounded(k + 1) {
                    continue;
                }
                let mut s = open.take().expect("open");
                s.hi = Some(pt.at.clone());
                s.hi_closed = pt.bounded == Some(true);
                stable_intervals.push(s);
            }
        }
    }
    if let Some(s) = open {
        stable_intervals.push(s);
    }

    // "Unbounded for every Φ" only when no bounded interval exists at all.
    let stability = match stability {
        Stability::UnboundedForAllPhi if !stable_intervals.is_empty() => {
            Stability::UnstableNearZero
        }
        other => other,
    };

    let marginal = charpoly.and_then(|_| marginal(chi));
    StabilityReport {
        degree: chi.degree(),
        stability,
        from_transition_matrix: p.is_some(),
        class_changes,
        intervals,
        stable_intervals,
        critical_points: points,
        marginal,
    }
}

/// Whether Φ = α is bounded, given that every root at α has |z| ≤ 1 (the
/// point borders a bounded interval, and roots move continuously); `None`
/// when a root on the circle is repeated there and P is not at hand (χ alone
/// cannot tell: the root is bounded exactly when P is semisimple at α).
fn bounded_at(
    chi: &Charpoly,
    alpha: &Algebraic,
    at_class: Option<RootClass>,
    disc: &UPoly,
    p: Option<StepMatrix<'_>>,
) -> Option<bool> {
    match at_class.map(RootClass::bounded) {
        Some(Some(bounded)) => return Some(bounded),
        Some(None) => {}
        None => {
            if !disc.is_zero() && !alpha.is_root_of(disc) {
                // Simple roots, none outside: bounded.
                return Some(true);
            }
        }
    }
    let mut field = Field::new(alpha);
    let f: FPoly = field.trim(chi.a.iter().map(|c| field.reduce(c)).collect());
    // Roots at zero are inside the circle: strip them.
    let lowest = f.iter().position(|c| !field.is_zero(c)).unwrap_or(0);
    let f: FPoly = f[lowest..].to_vec();
    if f.len() < 3 {
        return Some(true);
    }
    let df = field.derivative(&f);
    let d = field.gcd(&f, &df);
    if d.len() < 2 {
        return Some(true);
    }
    let rev: FPoly = d.iter().rev().cloned().collect();
    let e = field.gcd(&d, &rev);
    if e.len() < 2 {
        return Some(true);
    }
    let StepMatrix { numerator: p, denominator } = p?;
    // P = numerator / d (d = det A for an implicit step): a step whose system
    // is singular at this point is not defined there, so not bounded.
    let den = field.reduce(denominator);
    if field.is_zero(&den) {
        return Some(false);
    }
    let den_inv = field.inv(&den);
    // q: the distinct repeated roots on the circle.
    let de = field.derivative(&e);
    let g = field.gcd(&e, &de);
    let q = if g.len() >= 2 { field.div(&e, &g) } else { e };
    let pm: Vec<Vec<UPoly>> = p
        .iter()
        .map(|row| row.iter().map(|x| field.mul(&field.reduce(x), &den_inv)).collect())
        .collect();
    let qp = field.poly_at_matrix(&q, &pm);
    let qp2 = field.mat_mul(&qp, &qp);
    Some(field.rank(qp) == field.rank(qp2))
}

/// Whether the sequence is bounded at a rational Φ where χ has a repeated
/// root on the unit circle and none outside (the class is
/// [`RootClass::DoubleRootOnCircle`]), decided from P: bounded exactly when
/// P is semisimple there.
pub(crate) fn bounded_on_circle_at(chi: &Charpoly, phi: &Q, p: StepMatrix<'_>) -> bool {
    let alpha = Algebraic::from_rational(phi.clone());
    bounded_at(chi, &alpha, Some(RootClass::DoubleRootOnCircle), &UPoly::zero(), Some(p))
        .expect("P is at hand")
}

/// What happens at the stability limit, from which conditions vanish there
/// (the point lists every condition with a root there).
fn boundary_at(chi: &Charpoly, point: &CriticalPoint) -> Boundary {
    let at = &point.at;
    let vanishes = |p: &UPoly| at.is_root_of(p);
    let one = Q::one();
    let minus_one = -Q::one();
    let named = |name: Condition| point.conditions.contains(&name);
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
    } else if named(Condition::LeadingCoefficient) {
        Boundary::RootFromInfinity
    } else if named(Condition::UnitCircle) {
        if named(Condition::Discriminant) {
            Boundary::RepeatedPairOnCircle
        } else {
            Boundary::ComplexPairLeavesCircle
        }
    } else if named(Condition::ReciprocalDiscriminant) || named(Condition::Discriminant) {
        Boundary::RepeatedPairOnCircle
    } else {
        Boundary::Other
    }
}

/// The lowest term c·Φ^k of |z|² − 1 = (a0 − a2)/a2 for a second-order χ
/// (`series::dissipation_order`, the oracle in the tests), read off χ's
/// coefficients in Φ as the walk holds them, scaled alike so the ratio is
/// the same; `None` when a2(0) = 0 or |z|² ≡ 1.
fn modulus_lead(chi: &Charpoly) -> Option<(usize, Q)> {
    let (a0, a2) = (&chi.a[0], &chi.a[2]);
    let at_zero = a2.coeff(0);
    if at_zero.is_zero() {
        return None;
    }
    let diff = a0 - a2;
    let power = diff.coeffs().iter().position(|x| !x.is_zero())?;
    Some((power, diff.coeff(power) / at_zero))
}

/// For a second-order χ whose |z|² − 1 = c·Φ^k + … has 0 < |c| < 10⁻¹²
/// (a term below the rounding of 16-digit decimal coefficients): the
/// practical limit for growth per step at most 1 + 10⁻⁹, exactly, as the
/// stability limit of χ((1 + ε) w).
fn marginal(chi: &Charpoly) -> Option<Marginal> {
    if chi.degree() != 2 {
        return None;
    }
    let (power, coefficient) = modulus_lead(chi)?;
    let tiny = Q::new(1.into(), num_traits::pow(num_bigint::BigInt::from(10), 12));
    if coefficient.abs() >= tiny {
        return None;
    }
    let threshold = Q::new(1.into(), num_traits::pow(num_bigint::BigInt::from(10), 9));
    let r = Q::one() + &threshold;
    // Roots of χ((1 + ε) w) are z / (1 + ε): |w| ≤ 1 ⇔ |z| ≤ 1 + ε.
    let mut pow = Q::one();
    let mut a = Vec::with_capacity(chi.a.len());
    for c in &chi.a {
        a.push(c.scale(&pow));
        pow *= &r;
    }
    let scaled = Charpoly::from_coeffs(a);
    let report = run(&scaled, None, None);
    let practical_phi_max = match report.stability {
        Stability::Limited { phi_max, .. } => Some(phi_max),
        Stability::BoundedForAllPhi => None,
        Stability::UnboundedForAllPhi
        | Stability::UnstableNearZero
        | Stability::UndecidedAt { .. } => return None,
    };
    Some(Marginal { coefficient, power, threshold, practical_phi_max })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The class of a second-order χ at a rational Φ from χ(Φ)'s own
        /// coefficients is the one from the sign polynomials in Φ
        /// (`QuadPolys`), and the general classifier's.
        #[test]
        fn class_at_a_rational_is_the_sign_polynomials_one(
            c in proptest::collection::vec(proptest::collection::vec((-6i64..7, 1i64..5), 1..5), 3),
            phi in (0i64..40, 1i64..9),
        ) {
            let a: Vec<UPoly> = (0..3)
                .map(|k| UPoly::new(c[k].iter().map(|&(n, d)| crate::q(n, d)).collect()))
                .collect();
            prop_assume!(!a[2].is_zero());
            let chi = Charpoly::from_coeffs(a);
            let phi = crate::q(phi.0, phi.1);
            let q = chi.quad();
            let by_polys = classify_quadratic_by(|k| q.entry(k).1.sign_at(&phi));
            let (class, counts) = class_at_rational(&chi, &phi);
            prop_assert_eq!(class, by_polys);
            let f = chi.at(&phi);
            // χ(φ)·q^n in integers is χ(φ) up to a positive factor.
            let scaled = crate::univariate::upoly::primitive(scaled_at(&chi, &phi));
            prop_assert_eq!(scaled, crate::univariate::upoly::int_primitive_of(&f));
            if f.degree() == Some(2) {
                prop_assert_eq!((class, counts), classify_with_counts(&f));
            }
        }

        /// The lowest term of |z|² − 1 read off the walk's scaled
        /// coefficients is `series::dissipation_order`'s, from χ itself.
        #[test]
        fn modulus_lead_is_the_series_one(
            c in proptest::collection::vec(proptest::collection::vec((-6i64..7, 1i64..5), 1..5), 3),
        ) {
            let coeff = |k: usize| -> UPoly {
                UPoly::new(c[k].iter().map(|&(n, d)| crate::q(n, d)).collect())
            };
            let a: Vec<UPoly> = (0..3).map(coeff).collect();
            prop_assume!(!a[2].is_zero());
            let chi = Charpoly::from_coeffs(a.clone());
            let z = Poly::sym(crate::Sym::z());
            let phi = crate::Sym::phi();
            let charpoly = (0..3).fold(Poly::zero(), |acc, k| {
                &acc + &(&Poly::from_upoly(phi, &a[k]) * &z.pow(k as u32))
            });
            let oracle = crate::analysis::series::dissipation_order(&charpoly)
                .ok()
                .flatten()
                .map(|t| (t.order, t.coeff));
            prop_assert_eq!(modulus_lead(&chi), oracle);
        }
    }
}
