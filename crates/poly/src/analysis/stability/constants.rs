//! Stability of a characteristic polynomial whose coefficients hold exact
//! constants (elements of the field F of `multivariate/constants.rs`, here
//! `field`), and the behaviour of any χ as Φ → ∞.
//!
//! This is the thin layer between a constant-bearing χ and the rational
//! engine (`rational.rs`): the conditions under which a root of χ can meet
//! the unit circle or change class (leading and constant coefficients, χ(±1),
//! the discriminant, |z|² = 1) are polynomials in Φ over F. Their norms over
//! Q (products of all conjugates, `field::norm`) are polynomials over Q whose
//! positive real roots include every critical Φ of χ itself; they are
//! isolated as exact [`Algebraic`] numbers. Between consecutive candidates
//! the class of χ is constant and is decided at a rational sample by exact
//! sign decisions in F (`field::sign`). A candidate that belongs only to a
//! conjugate of χ changes nothing and is merged away, so Φ_max is the first
//! candidate at which χ's own class becomes unbounded: an exact algebraic
//! number with its defining polynomial over Q.
//!
//! Scope: second-order χ (the oscillator with two state variables), which is
//! every constant-bearing built-in; higher degrees with constants are
//! rejected with a clear error rather than answered by floats.

use std::cmp::Ordering;

use super::conditions::critical_points;
use super::point::{classify_quadratic_by, quadratic_terms, Counts};
use super::report::{
    Boundary, ClassChange, ClassInterval, Condition, Stability, StabilityReport, StableInterval,
};
use crate::error::{Error, ErrorKind};
use crate::multivariate::constants as field;
use crate::{Algebraic, Poly, RootClass, Sym, UPoly, Q};

/// Coefficients of χ in z (lowest first), each a polynomial in Φ over F.
fn z_coeffs(chi: &Poly) -> Result<Vec<Poly>, Error> {
    let (z, phi) = (Sym::z(), Sym::phi());
    if let Some(s) =
        chi.symbols().into_iter().find(|&s| s != z && s != phi && field::generator_of(s).is_none())
    {
        return Err(Error::analysis(
            ErrorKind::ExtraSymbol,
            format!("characteristic polynomial {chi} still contains the parameter {s}; expected a polynomial in z and Phi only (give {s} a value)"),
        ));
    }
    let a = chi.coeffs_in(z);
    if a.len() < 2 {
        return Err(Error::analysis(
            ErrorKind::NoRoots,
            format!("characteristic polynomial {chi} does not depend on z"),
        ));
    }
    Ok(a)
}

/// The class of c + b z + a z² (elements of F) from exact signs in F, by
/// the one root-class table of the rational engine.
pub(crate) fn classify_quadratic(c: &Poly, b: &Poly, a: &Poly) -> RootClass {
    let terms = quadratic_terms(c, b, a);
    classify_quadratic_by(|k| field::sign(&field::reduce(&terms[k])))
}

/// The class of a constant-bearing second-order χ at a rational Φ, exactly.
pub fn class_at(chi: &Poly, phi: &Q) -> Result<RootClass, Error> {
    let a = z_coeffs(chi)?;
    if a.len() != 3 {
        return Err(degree_error(a.len() - 1));
    }
    let at = |p: &Poly| field::reduce(&p.subs(Sym::phi(), &Poly::constant(phi.clone())));
    Ok(classify_quadratic(&at(&a[0]), &at(&a[1]), &at(&a[2])))
}

fn degree_error(n: usize) -> Error {
    Error::analysis(
        ErrorKind::NoRoots,
        format!("characteristic polynomial of degree {n} with exact irrational constants: expected degree 2 (only second-order constant-bearing methods are analysed exactly so far)"),
    )
}

/// A rational strictly between two distinct algebraic numbers.
fn between(lo: &Algebraic, hi: &Algebraic) -> Q {
    let mut w = Q::new(1.into(), 8.into());
    loop {
        let (l, h) = (lo.refine(&w), hi.refine(&w));
        let (_, lu) = l.interval();
        let (hl, _) = h.interval();
        if lu < hl {
            return (lu + hl) / Q::from_integer(2.into());
        }
        w /= Q::from_integer(16.into());
    }
}

/// The exact stability analysis of a second-order χ over F; see the module
/// notes. With the numerator N of the transition matrix P = N/d, a limit
/// where a root on the circle is repeated is decided from P: bounded there
/// only when P is scalar (a 2×2 matrix with a double eigenvalue is
/// semisimple exactly then), and P is not scalar where the norm of an entry
/// of N − (tr N/2)·I does not vanish. Without N, or when every such norm
/// vanishes there, the limit is [`Stability::UndecidedAt`].
pub(crate) fn analyze(
    chi: &Poly,
    numerator: Option<&[Vec<Poly>]>,
) -> Result<StabilityReport, Error> {
    let a = z_coeffs(chi)?;
    if a.len() != 3 {
        return Err(degree_error(a.len() - 1));
    }
    let (c, b, lead) = (&a[0], &a[1], &a[2]);
    // |z|^2 = 1 for a complex pair is c = a; p = 0 is the tie between
    // the moduli of the two real roots z and −z.
    let conditions: Vec<(Condition, Poly)> = vec![
        (Condition::LeadingCoefficient, lead.clone()),
        (Condition::ConstantCoefficient, c.clone()),
        (Condition::ChiAtOne, &(lead + b) + c),
        (Condition::ChiAtMinusOne, &(lead - b) + c),
        (Condition::Discriminant, &(b * b) - &(&Poly::int(4) * &(lead * c))),
        (Condition::UnitCircle, c - lead),
        (Condition::ModulusTie, b.clone()),
    ];
    let mut norms: Vec<(Condition, UPoly)> = Vec::new();
    for (name, cond) in &conditions {
        let n = field::norm(&field::reduce(cond));
        if let Some(u) = n.to_upoly(Sym::phi()) {
            norms.push((*name, u.squarefree()));
        }
    }
    let points = critical_points(&norms);
    let zero = Algebraic::zero();
    let mut samples = Vec::with_capacity(points.len() + 1);
    for k in 0..=points.len() {
        let lo = if k == 0 { &zero } else { &points[k - 1].at };
        samples.push(match points.get(k) {
            Some(hi) => between(lo, &hi.at),
            None => lo.interval().1.floor() + Q::from_integer(1.into()),
        });
    }
    let classes: Vec<RootClass> =
        samples.iter().map(|s| class_at(chi, s)).collect::<Result<_, _>>()?;
    let counts: Vec<Counts> = samples.iter().map(|s| counts_at(&a, s)).collect();
    let mut intervals = vec![ClassInterval {
        lo: zero.clone(),
        hi: None,
        class: classes[0],
        sample: samples[0].clone(),
        counts: counts[0],
    }];
    let mut class_changes = Vec::new();
    let mut phi_max = None;
    let mut boundary = None;
    let mut bounded_for_all = classes[0].bounded() == Some(true);
    for (k, point) in points.iter().enumerate() {
        let (from, to) = (classes[k], classes[k + 1]);
        if from == to {
            continue;
        }
        let at_class = class_at_point(&a, &point.at, [&samples[k], &samples[k + 1]]);
        class_changes.push(ClassChange { at: point.at.clone(), from, to, at_class });
        intervals.last_mut().expect("one interval at least").hi = Some(point.at.clone());
        intervals.push(ClassInterval {
            lo: point.at.clone(),
            hi: None,
            class: to,
            sample: samples[k + 1].clone(),
            counts: counts[k + 1],
        });
        if bounded_for_all && to.bounded() != Some(true) {
            bounded_for_all = false;
            phi_max = Some(point.at.clone());
            boundary = Some(boundary_between(from, to));
        }
    }
    let stability = match (phi_max, boundary) {
        (Some(phi_max), Some(boundary)) => match bounded_at_limit(boundary) {
            Some(bounded) => Stability::Limited { phi_max, bounded_at_phi_max: bounded, boundary },
            None if numerator.is_some_and(|n| not_scalar_at(n, &phi_max)) => {
                Stability::Limited { phi_max, bounded_at_phi_max: false, boundary }
            }
            None => Stability::UndecidedAt { at: phi_max, boundary },
        },
        _ if bounded_for_all => Stability::BoundedForAllPhi,
        _ => Stability::UnboundedForAllPhi,
    };
    // The bounded runs: from Φ = 0 up to the limit (the classes are
    // merged, so a bounded interval is followed by an unbounded one).
    let stable_intervals: Vec<StableInterval> = match &stability {
        Stability::BoundedForAllPhi => {
            vec![StableInterval { lo: zero.clone(), lo_closed: false, hi: None, hi_closed: false }]
        }
        Stability::Limited { phi_max, bounded_at_phi_max, .. } => vec![StableInterval {
            lo: zero.clone(),
            lo_closed: false,
            hi: Some(phi_max.clone()),
            hi_closed: *bounded_at_phi_max,
        }],
        Stability::UndecidedAt { at, .. } => vec![StableInterval {
            lo: zero.clone(),
            lo_closed: false,
            hi: Some(at.clone()),
            hi_closed: false,
        }],
        // Unstable near zero: the bounded classes further out, if any (their
        // ends are not decided here, so they are left open).
        _ => {
            let mut runs: Vec<StableInterval> = Vec::new();
            for iv in intervals.iter().filter(|iv| iv.class.bounded() == Some(true)) {
                match runs.last_mut() {
                    Some(run) if run.hi.as_ref() == Some(&iv.lo) => run.hi = iv.hi.clone(),
                    _ => runs.push(StableInterval {
                        lo: iv.lo.clone(),
                        lo_closed: false,
                        hi: iv.hi.clone(),
                        hi_closed: false,
                    }),
                }
            }
            runs
        }
    };
    // "Unbounded for every Φ" only when no bounded interval exists at all.
    let stability = match stability {
        Stability::UnboundedForAllPhi if !stable_intervals.is_empty() => {
            Stability::UnstableNearZero
        }
        other => other,
    };
    Ok(StabilityReport {
        degree: 2,
        stability,
        from_transition_matrix: false,
        class_changes,
        intervals,
        stable_intervals,
        critical_points: points,
        marginal: None,
    })
}

/// The class of c + b z + a z² (polynomials in Φ over F) exactly at a
/// critical point α, from the signs of the classifying terms there. A term
/// T's sign at α is decided exactly from its signs at the rational samples
/// on either side (α is the only critical point between them, and every
/// root of T is a root of its norm N over Q, hence critical): different
/// signs put a root of T at α; equal signs give that sign unless T has a
/// root of even multiplicity at α, which makes α a multiple root of N. So
/// where α is a simple root of N (or no root), the sign is the samples'.
/// `None` only where a term's norm has a multiple root at α with equal
/// signs on both sides.
fn class_at_point(coeffs: &[Poly], alpha: &Algebraic, samples: [&Q; 2]) -> Option<RootClass> {
    let terms = quadratic_terms(&coeffs[0], &coeffs[1], &coeffs[2]);
    let signs: Vec<Ordering> = terms
        .iter()
        .map(|t| {
            let t = field::reduce(t);
            let at = |q: &Q| {
                field::sign(&field::reduce(&t.subs(Sym::phi(), &Poly::constant(q.clone()))))
            };
            let (left, right) = (at(samples[0]), at(samples[1]));
            if left != right || t.is_zero() {
                return Some(Ordering::Equal);
            }
            let norm = field::norm(&t).to_upoly(Sym::phi())?;
            if !alpha.is_root_of(&norm) || !alpha.is_root_of(&norm.derivative()) {
                Some(left)
            } else {
                None
            }
        })
        .collect::<Option<_>>()?;
    Some(classify_quadratic_by(|k| signs[k]))
}

/// Whether χ is bounded exactly at the limit, from what happens there: a
/// simple root at ±1 or a pair of distinct roots on the circle is bounded;
/// a root on the circle that is repeated needs P (`None`); anything else
/// has a root outside.
fn bounded_at_limit(boundary: Boundary) -> Option<bool> {
    match boundary {
        Boundary::RootThroughPlusOne
        | Boundary::RootThroughMinusOne
        | Boundary::ComplexPairLeavesCircle => Some(true),
        Boundary::DoubleRootAtMinusOne
        | Boundary::DoubleRootAtPlusOne
        | Boundary::RepeatedPairOnCircle => None,
        _ => Some(false),
    }
}

/// Whether the 2×2 numerator N of P is certainly not a multiple of I at
/// Φ = α: the norm over Q of N₁₂, N₂₁ or N₁₁ − N₂₂ does not vanish at α.
fn not_scalar_at(n: &[Vec<Poly>], alpha: &Algebraic) -> bool {
    if n.len() != 2 || n.iter().any(|row| row.len() != 2) {
        return false;
    }
    let off = [n[0][1].clone(), n[1][0].clone(), &n[0][0] - &n[1][1]];
    off.iter().any(|g| {
        let norm = field::norm(&field::reduce(g));
        match norm.to_upoly(Sym::phi()) {
            Some(u) => !u.is_zero() && !alpha.is_root_of(&u),
            None => false,
        }
    })
}

/// Whether P = N/d (2×2 over F) is semisimple at a rational Φ where χ has
/// a double root on the unit circle (d ≠ 0 there): a 2×2 matrix with a
/// double eigenvalue is semisimple exactly when it is scalar, that is when
/// N − (tr N/2)·I vanishes there.
pub(crate) fn scalar_at(n: &[Vec<Poly>], phi: &Q) -> bool {
    if n.len() != 2 || n.iter().any(|row| row.len() != 2) {
        return false;
    }
    let at = |p: &Poly| field::reduce(&p.subs(Sym::phi(), &Poly::constant(phi.clone())));
    [n[0][1].clone(), n[1][0].clone(), &n[0][0] - &n[1][1]].iter().all(|g| at(g).is_zero())
}

/// The counts of roots of c + b z + a z² (over F, Φ = `phi`) inside, on and
/// outside the unit circle, from exact signs.
fn counts_at(coeffs: &[Poly], phi: &Q) -> Counts {
    let at = |p: &Poly| field::reduce(&p.subs(Sym::phi(), &Poly::constant(phi.clone())));
    let (c, b, a) = (at(&coeffs[0]), at(&coeffs[1]), at(&coeffs[2]));
    let sgn = |p: &Poly| field::sign(&field::reduce(p));
    let counts = |inside, on, outside| Counts { inside, on, outside };
    let sa = sgn(&a);
    if sa == Ordering::Equal {
        // b z + c: one root −c/b (or none).
        if sgn(&b) == Ordering::Equal {
            return counts(0, 0, 0);
        }
        return match sgn(&(&(&b * &b) - &(&c * &c))) {
            Ordering::Greater => counts(1, 0, 0),
            Ordering::Equal => counts(0, 1, 0),
            Ordering::Less => counts(0, 0, 1),
        };
    }
    let by_a = |o: Ordering| if sa == Ordering::Greater { o } else { o.reverse() };
    // |c/a| against 1: the product of the roots.
    let product = sgn(&(&(&c * &c) - &(&a * &a)));
    let disc = sgn(&(&(&b * &b) - &(&Poly::int(4) * &(&a * &c))));
    if disc == Ordering::Less {
        return match product {
            Ordering::Less => counts(2, 0, 0),
            Ordering::Equal => counts(0, 2, 0),
            Ordering::Greater => counts(0, 0, 2),
        };
    }
    let at_one = by_a(sgn(&(&(&a + &b) + &c)));
    let at_minus_one = by_a(sgn(&(&(&a - &b) + &c)));
    match (at_one, at_minus_one) {
        (Ordering::Equal, Ordering::Equal) => counts(0, 2, 0),
        (Ordering::Equal, _) | (_, Ordering::Equal) => match product {
            Ordering::Less => counts(1, 1, 0),
            Ordering::Equal => counts(0, 2, 0),
            Ordering::Greater => counts(0, 1, 1),
        },
        (Ordering::Greater, Ordering::Greater) => match product {
            Ordering::Less => counts(2, 0, 0),
            _ => counts(0, 0, 2),
        },
        (Ordering::Less, Ordering::Less) => counts(0, 0, 2),
        _ => counts(1, 0, 1),
    }
}

/// What happens at a limit, by continuity from the exact classes on either
/// side: a pair on or inside the circle that becomes two real roots, one
/// beyond −1, met on the real axis at a point of modulus 1, so at −1.
fn boundary_between(from: RootClass, to: RootClass) -> Boundary {
    use RootClass::*;
    let complex = matches!(from, DampedOscillation | Harmonic);
    match to {
        UnstableOscillation => Boundary::ComplexPairLeavesCircle,
        AlternatingUnstable if complex => Boundary::DoubleRootAtMinusOne,
        AlternatingUnstable => Boundary::RootThroughMinusOne,
        MonotonicUnstable if complex => Boundary::DoubleRootAtPlusOne,
        MonotonicUnstable => Boundary::RootThroughPlusOne,
        _ => Boundary::Other,
    }
}

/// What the roots of χ do as Φ → ∞, decided exactly.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LimitAtInfinity {
    /// Every root tends to 0 (L-stable-like on the oscillator: backward
    /// Euler, Radau IIA, SDIRK2).
    ToZero,
    /// The largest modulus tends to a value in (0, 1).
    InsideCircle,
    /// The largest modulus tends to 1 (the trapezoidal rule, Gauss–Legendre).
    ToCircle,
    /// The largest modulus tends to a value above 1, or a root to ∞.
    Outside,
}

impl LimitAtInfinity {
    /// The snake_case name used in JSON and reports.
    pub fn name(self) -> &'static str {
        match self {
            LimitAtInfinity::ToZero => "modulus_to_zero",
            LimitAtInfinity::InsideCircle => "modulus_to_below_one",
            LimitAtInfinity::ToCircle => "modulus_to_one",
            LimitAtInfinity::Outside => "modulus_above_one",
        }
    }
}

/// The limit of χ's roots as Φ → ∞: the roots of the polynomial formed by
/// the coefficients of the highest power of Φ present in any z-coefficient
/// (a root escapes to ∞ when that polynomial loses degree in z).
pub fn limit_at_infinity(chi: &Poly) -> Result<LimitAtInfinity, Error> {
    let a = z_coeffs(chi)?;
    let phi = Sym::phi();
    let top = a.iter().map(|c| c.degree_in(phi)).max().unwrap_or(0);
    let lim: Vec<Poly> =
        a.iter().map(|c| c.coeffs_in(phi).get(top as usize).cloned().unwrap_or_default()).collect();
    let n = a.len() - 1;
    if lim[n].is_zero() {
        return Ok(LimitAtInfinity::Outside);
    }
    if lim[..n].iter().all(Poly::is_zero) {
        return Ok(LimitAtInfinity::ToZero);
    }
    let class = if lim.iter().any(field::has_generators) {
        if n != 2 {
            return Err(degree_error(n));
        }
        classify_quadratic(&lim[0], &lim[1], &lim[2])
    } else {
        let u = UPoly::new(lim.iter().map(|c| c.as_constant().unwrap_or_default()).collect());
        super::point::classify(&u)
    };
    use RootClass::*;
    Ok(match class {
        Deadbeat => LimitAtInfinity::ToZero,
        DampedOscillation | MonotonicStable | AlternatingStable => LimitAtInfinity::InsideCircle,
        Harmonic | Constant | Alternating | DoubleRootOnCircle => LimitAtInfinity::ToCircle,
        _ => LimitAtInfinity::Outside,
    })
}
