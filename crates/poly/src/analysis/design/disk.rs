//! Φ_max over a box of two parameters, for χ of degree 2 in z.
//!
//! Φ_max is not upper semicontinuous (a repeated root on the unit circle
//! may be unbounded, so the root condition is not a closed one), and its
//! supremum over a box could be a limit along a curve. It is bounded by an
//! objective that is: the disk bound Φ_disk, the first step after which a
//! root of χ = a z² + b z + c leaves the closed unit disk. For a real
//! quadratic with a ≠ 0 the roots lie in the closed disk exactly when
//!
//! a(a − c) ≥ 0, a(a + c) ≥ 0, a·χ(1) ≥ 0, a·χ(−1) ≥ 0
//!
//! (Jury's triangle |c/a| ≤ 1, |b/a| ≤ 1 + c/a, closed). These are sign
//! conditions, so Φ_disk is searched and certified over the box by
//! `two.rs`, its maximum attained at a point p*.
//!
//! Every stable step is in the disk, so Φ_max ≤ Φ_disk everywhere. Where
//! Φ_max(p*) = Φ_disk(p*), p* attains the supremum of Φ_max too, with the
//! same value (and p* is the least point of Φ_max's maximisers, which lie
//! among Φ_disk's). They can differ only where, at a step below Φ_disk,
//! χ has a repeated root on the circle (a real quadratic's repeated root is
//! real: z = ±1) or a = 0 (the step's system is singular):
//!
//! - at a rational p* the stability engine gives Φ_max(p*) exactly, and it
//!   is compared;
//! - at an irrational p* the positive roots of the discriminant, of χ(±1)
//!   and of a at p* (covered by their products over the conjugates) are
//!   shown not to meet below Φ_disk.
//!
//! Otherwise the search stops and says why; it never guesses.
//!
//! A tableau's χ is |Q|²z² − 2 Re(P Q̄) z + |P|² along w = −iΦ (R = P/Q):
//! a + c, χ(1) = |Q − P|² and χ(−1) = |Q + P|² are sums of squares, never
//! negative, so the disk is the one condition a(a − c) ≥ 0, |R(iΦ)| ≤ 1;
//! and the step R(ΦJ) (J skew) is a normal matrix, so a repeated root on
//! the circle is semisimple and bounded: Φ_max is the disk bound.

use std::cmp::Ordering;

use super::algebra::roots_cover;
use super::oscillator::Oscillator;
use super::problem::{Engine, Problem, Setup};
use super::report::{bound_error, input_error, Score};
use super::system::{SignCondition, SignSystem};
use super::two::{search_box as search_signs, Found};
use crate::error::Error;
use crate::{Algebraic, Poly, Sym};

/// The disk bound's sign system for χ = a z² + b z + c in Φ and the free
/// parameters, with the discriminant, a and χ(±1) kept for the check at
/// the optimum.
struct Disk {
    system: SignSystem,
    lead: Poly,
    disc: Poly,
    at_plus_one: Poly,
    at_minus_one: Poly,
    tableau: bool,
}

impl Disk {
    /// `tableau`: χ comes from a tableau's R = P/Q (the module's note).
    fn new(chi: &Poly, name: &str, tableau: bool) -> Result<Disk, Error> {
        let (z, phi) = (Sym::z(), Sym::phi());
        let degree = chi.degree_in(z);
        if degree != 2 {
            return Err(input_error(format!(
                "phi_max over two parameters is decided exactly for chi of degree 2 in z (two \
                 states), through the closed unit disk's conditions on a quadratic; `{name}` has \
                 chi of degree {degree} in z: bind one parameter"
            )));
        }
        let k = chi.coeffs_in(z);
        let (a, b, c) = (k[2].clone(), k[1].clone(), k[0].clone());
        let at_plus_one = &(&a + &b) + &c;
        let at_minus_one = &(&a - &b) + &c;
        let disc = &(&b * &b) - &(&a * &c).scale(&crate::q(4, 1));
        let mut system = SignSystem { x: phi, factors: Vec::new(), conditions: Vec::new() };
        let lead =
            system.factor(a.clone(), "the leading coefficient a of chi (a root at infinity)");
        let minus = system.factor(&a - &c, "a - c (the roots' product is 1)");
        if tableau {
            system.conditions.push(SignCondition {
                factors: vec![lead, minus],
                label: "a (a - c) >= 0: |R(i Phi)| <= 1".to_owned(),
            });
            return Ok(Disk { system, lead: a, disc, at_plus_one, at_minus_one, tableau });
        }
        let plus = system.factor(&a + &c, "a + c (the roots' product is -1)");
        let one = system.factor(at_plus_one.clone(), "chi(1) (a root through +1)");
        let minus_one = system.factor(at_minus_one.clone(), "chi(-1) (a root through -1)");
        for (k, label) in [
            (minus, "a (a - c) >= 0: the roots' product c/a is at most 1"),
            (plus, "a (a + c) >= 0: the roots' product c/a is at least -1"),
            (one, "a chi(1) >= 0: no root has crossed +1"),
            (minus_one, "a chi(-1) >= 0: no root has crossed -1"),
        ] {
            system
                .conditions
                .push(SignCondition { factors: vec![lead, k], label: label.to_owned() });
        }
        Ok(Disk { system, lead: a, disc, at_plus_one, at_minus_one, tableau })
    }
}

/// The supremum of Φ_max over the box of the setup's two free parameters.
pub(crate) fn search_box(problem: &Problem, s: &Setup) -> Result<Found, Error> {
    let Engine::Oscillator(o) = &s.engine else {
        unreachable!("the disk bound is Φ_max's");
    };
    let (name, tableau) = match &problem.subject {
        super::problem::Subject::Program(d) => (d.method().name().to_owned(), false),
        super::problem::Subject::Tableau(t) => (t.name().to_owned(), true),
    };
    let disk = Disk::new(&o.chi, &name, tableau)?;
    let weak = Setup {
        engine: Engine::Signs(disk.system.clone()),
        syms: s.syms.clone(),
        order_conditions: Vec::new(),
    };
    let polys = disk.system.breakpoints(&s.syms)?;
    let (score, attained, at, mut cert, evaluated) = search_signs(problem, &weak, &polys)?;
    let point: Vec<(Sym, Algebraic)> = s.syms.iter().copied().zip(at.iter().cloned()).collect();
    let agreement = agree(o, &disk, &point, &score)?;
    let preface = if disk.tableau {
        "phi_max is bounded above by the disk bound: the first step after which a root of chi \
         = |Q|^2 z^2 - 2 Re(P conj(Q)) z + |P|^2 (R = P/Q along w = -i Phi) leaves the closed \
         unit disk, that is after which a (a - c) = |Q|^2 (|Q|^2 - |P|^2) turns negative (a + \
         c, chi(1) = |Q - P|^2 and chi(-1) = |Q + P|^2 are sums of squares, never negative; a \
         closed condition, so the bound is upper semicontinuous and its maximum over the box \
         is attained); every stable step lies in the disk, and the step R(Phi J) of a tableau \
         (J skew) is a normal matrix, so a repeated root on the circle is bounded and phi_max \
         is the disk bound wherever the step is regular; the search below is the disk bound's"
    } else {
        "phi_max is bounded above by the disk bound: the first step after which a root of chi \
         = a z^2 + b z + c leaves the closed unit disk, that is after which a (a - c), a (a + \
         c), a chi(1) or a chi(-1) turns negative (Jury's triangle, closed conditions, so the \
         bound is upper semicontinuous and its maximum over the box is attained); every stable \
         step lies in the disk, so phi_max <= the disk bound everywhere, and the search below \
         is the disk bound's"
    };
    cert.insert(1, preface.to_owned());
    cert.push(agreement);
    Ok((score, attained, at, cert, evaluated))
}

/// Whether Φ_max equals the disk bound at the point: the certificate's
/// line, or the reason the search stops.
fn agree(
    o: &Oscillator,
    disk: &Disk,
    point: &[(Sym, Algebraic)],
    score: &Score,
) -> Result<String, Error> {
    let shown: Vec<String> =
        point.iter().map(|(s, a)| format!("{} = {}", s.name(), a.describe(s.name()))).collect();
    let shown = shown.join(", ");
    if matches!(score, Score::Finite(v) if v.sign().is_eq()) {
        return Ok(format!(
            "the disk bound is 0 on the whole box, so no step > 0 is stable anywhere in it: \
             phi_max is 0 at {shown}"
        ));
    }
    if point.iter().all(|(_, a)| a.is_rational()) {
        let exact = o.evaluate(point)?.score;
        if exact != *score {
            return Err(bound_error(format!(
                "at {shown}, where the disk bound is largest ({score}), phi_max is {exact}: a \
                 repeated root on the unit circle (or a singular step) below the bound makes the \
                 method unbounded there, and the exact search over two parameters does not \
                 follow phi_max's jumps; bind one parameter"
            )));
        }
        return Ok(format!(
            "at {shown} the stability engine gives phi_max = {exact} exactly (deciding a \
             repeated root on the circle from the transition matrix): the bound is attained, so \
             it is phi_max's supremum"
        ));
    }
    // The positive roots below the bound of each polynomial at the point,
    // over every conjugate point (a superset of the true ones).
    let phi = Sym::phi();
    let below = |p: &Poly| -> Result<Vec<Algebraic>, Error> {
        let cover = roots_cover(&super::algebra::strip_power(p, phi), point, phi)?;
        if cover.is_zero() {
            return Err(bound_error(format!(
                "{p} may vanish for every Phi at {shown}, which the exact search over two \
                 parameters does not decide; bind one parameter"
            )));
        }
        Ok(Algebraic::positive_roots(&cover)
            .into_iter()
            .filter(|r| match score {
                Score::Finite(v) => r.cmp(v) == Ordering::Less,
                Score::Infinite => true,
            })
            .collect())
    };
    if disk.lead.degree_in(phi) > 0 {
        if let Some(r) = below(&disk.lead)?.first() {
            return Err(bound_error(format!(
                "at {shown} the leading coefficient of chi may vanish at Phi = {} below the disk \
                 bound {score} (a singular step), which the exact search over two parameters \
                 does not rule out at an irrational point; bind one parameter",
                r.describe("Phi")
            )));
        }
    }
    if disk.tableau {
        return Ok(format!(
            "at {shown} the leading coefficient |Q|^2 of chi does not vanish for 0 < Phi < \
             {score}, and the step R(Phi J) of a tableau (J skew) is a normal matrix, so a \
             repeated root on the circle is bounded: phi_max equals the bound there and the \
             bound is its supremum"
        ));
    }
    let disc = below(&disk.disc)?;
    for p in [&disk.at_plus_one, &disk.at_minus_one] {
        if let Some(r) = below(p)?.into_iter().find(|r| disc.contains(r)) {
            return Err(bound_error(format!(
                "at {shown} chi may have a repeated root on the unit circle at Phi = {} below \
                 the disk bound {score}, where phi_max can stop short of it; the exact search \
                 over two parameters does not decide that at an irrational point; bind one \
                 parameter",
                r.describe("Phi")
            )));
        }
    }
    Ok(format!(
        "at {shown} no root of chi repeats on the unit circle and its leading coefficient does \
         not vanish for 0 < Phi < {score} (the roots there of the discriminant and of chi(1) and \
         chi(-1), over the point's conjugates, are disjoint): every step in the disk is stable, \
         so phi_max equals the bound there and the bound is its supremum"
    ))
}
