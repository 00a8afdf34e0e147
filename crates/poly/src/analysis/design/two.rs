//! The search over a box of two parameters (a, b), for the objectives read
//! from signs (upper semicontinuous, so the maximum is attained).
//!
//! The maximum lies on an edge of the box (the one-parameter search along
//! each edge finds it there), or inside, at a point where the objective's
//! branch cannot be increased: a critical point of a smooth branch x(a, b)
//! (F = ∂F/∂a = ∂F/∂b = 0, which the breakpoint curves Res_x(F, ∂F/∂a) and
//! Res_x(F, ∂F/∂b) meet at), a critical point of the branch along a
//! breakpoint curve C (F = C = F_a C_b − F_b C_a = 0), of a double root
//! along its discriminant curve (F = F_x = F_a F_xb − F_b F_xa = 0), or a
//! point where two breakpoint curves meet, or where one is singular or has
//! a vertical or horizontal tangent. Each of these is a system of two
//! polynomials G₁, G₂ in (a, b) once x is eliminated; its solutions lie on
//! the grid of the roots of Res_b(G₁, G₂) in a and of Res_a(G₁, G₂) in b,
//! and a grid point is kept unless interval arithmetic on its isolating box
//! proves G₁ or G₂ nonzero there. Every kept point is a point of the box,
//! so evaluating extra ones never overstates the maximum.
//!
//! Where G₁ and G₂ share a component, the system is not zero-dimensional:
//! their gcd is divided out and the certificate counts such systems.

use std::cmp::Ordering;

use super::algebra::{eliminate, roots_in, sign_at};
use super::certify::{header, solves};
use super::one::search_line;
use super::problem::{Engine, Problem, Setup};
use super::report::{bound_error, Score, MAX_SYSTEM_DEGREE};
use super::system::{Breakpoints, Eval, SignSystem};
use crate::error::Error;
use crate::{Algebraic, Poly, Sym, Q};

pub(crate) type Found = (Score, bool, Vec<Algebraic>, Vec<String>, usize);

/// A point of the box, each free symbol with its exact value.
type Point = Vec<(Sym, Algebraic)>;

/// One zero-dimensional system, with what it means.
struct System2 {
    g1: Poly,
    g2: Poly,
    label: String,
}

fn inside(r: &Algebraic, lo: &Q, hi: &Q) -> bool {
    r.cmp_rational(lo) == Ordering::Greater && r.cmp_rational(hi) == Ordering::Less
}

/// Whether `g` may vanish at the point: exact with rational coordinates,
/// else false only when interval arithmetic excludes 0.
fn may_vanish(g: &Poly, point: &[(Sym, Algebraic)]) -> bool {
    if point.iter().all(|(_, a)| a.is_rational()) {
        return sign_at(g, point) == Some(Ordering::Equal);
    }
    let irr = super::algebra::irrational(point);
    if irr.len() == 1 {
        let q = super::algebra::substitute_rational(g, point);
        let (s, a) = &irr[0];
        return q.to_upoly(*s).is_none_or(|u| a.is_root_of(&u));
    }
    // A bounded refinement; `None` (not separated) keeps the point.
    let mut pt = point.to_vec();
    for _ in 0..6 {
        if let Some(s) = super::algebra::interval_sign(g, &pt) {
            return s == Ordering::Equal;
        }
        for (_, a) in pt.iter_mut() {
            let (l, h) = a.interval();
            *a = a.refine(&((&h - &l) / Q::from_integer(16.into())));
        }
    }
    true
}

fn systems(sys: &SignSystem, polys: &[Breakpoints], a: Sym, b: Sym) -> Result<Vec<System2>, Error> {
    let mut out = Vec::new();
    let curves: Vec<&Breakpoints> = polys.iter().collect();
    for (i, c) in curves.iter().enumerate() {
        out.extend(curve_systems(sys, &c.poly, &c.label, &curves[i + 1..], a, b)?);
    }
    for f in &sys.factors {
        if f.poly.degree_in(sys.x) == 0 {
            continue;
        }
        let x = sys.x;
        let (fa, fb, fx) = (f.poly.derivative(a), f.poly.derivative(b), f.poly.derivative(x));
        let k = &(&fa * &fx.derivative(b)) - &(&fb * &fx.derivative(a));
        out.push(System2 {
            g1: eliminate(&f.poly, &fx, x)?,
            g2: eliminate(&f.poly, &k, x)?,
            label: format!("a double root of {} is stationary along its tangency curve", f.label),
        });
    }
    Ok(out)
}

/// The systems of one curve C (a breakpoint curve, or a component two
/// conditions share): C meeting each of `others`, C's vertical and
/// horizontal tangents and singular points, and each factor's root
/// stationary along C (F = C = F_a C_b − F_b C_a = 0, x eliminated). The
/// objective along C is piecewise smooth in the curve's parameter, so its
/// maximum on C is at one of these or on the box's edge.
fn curve_systems(
    sys: &SignSystem,
    c: &Poly,
    label: &str,
    others: &[&Breakpoints],
    a: Sym,
    b: Sym,
) -> Result<Vec<System2>, Error> {
    let x = sys.x;
    let mut out = Vec::new();
    for d in others {
        out.push(System2 {
            g1: c.clone(),
            g2: d.poly.clone(),
            label: format!("{label} meets {}", d.label),
        });
    }
    for (s, what) in [(b, "vertical"), (a, "horizontal")] {
        out.push(System2 {
            g1: c.clone(),
            g2: c.derivative(s),
            label: format!("{label} has a {what} tangent or a singular point"),
        });
    }
    for f in &sys.factors {
        if f.poly.degree_in(x) == 0 {
            continue;
        }
        let (fa, fb) = (f.poly.derivative(a), f.poly.derivative(b));
        let j = &(&fa * &c.derivative(b)) - &(&fb * &c.derivative(a));
        out.push(System2 {
            g1: c.clone(),
            g2: eliminate(&f.poly, &j, x)?,
            label: format!("a root of {} is stationary along {label}", f.label),
        });
    }
    Ok(out)
}

/// The interior candidates of one system, with its label.
fn solve(
    s2: &System2,
    a: Sym,
    b: Sym,
    (alo, ahi): (&Q, &Q),
    (blo, bhi): (&Q, &Q),
    shared: &mut Vec<Poly>,
) -> Result<Vec<Vec<(Sym, Algebraic)>>, Error> {
    let (mut g1, mut g2) = (s2.g1.clone(), s2.g2.clone());
    if g1.is_zero() || g2.is_zero() || g1.as_constant().is_some() || g2.as_constant().is_some() {
        return Ok(Vec::new());
    }
    for g in [&g1, &g2] {
        let d = g.degree_in(a) as usize + g.degree_in(b) as usize;
        if d > MAX_SYSTEM_DEGREE {
            return Err(bound_error(format!(
                "{}: an equation of degree {d} in ({}, {}), past the bound MAX_SYSTEM_DEGREE = \
                 {MAX_SYSTEM_DEGREE}: its common factors with the other are not found in \
                 reasonable time, so the exact search stops here rather than guess",
                s2.label.replace("_design", ""),
                a.name(),
                b.name()
            )));
        }
    }
    let g = g1.gcd(&g2);
    if g.as_constant().is_none() {
        if !shared.contains(&g) {
            shared.push(g.clone());
        }
        g1 = g1.div_exact(&g).unwrap_or(g1);
        g2 = g2.div_exact(&g).unwrap_or(g2);
        if g1.as_constant().is_some() || g2.as_constant().is_some() {
            return Ok(Vec::new());
        }
    }
    let project = |s: Sym, other: Sym, lo: &Q, hi: &Q| -> Result<Vec<Algebraic>, Error> {
        let r = if g1.degree_in(other) == 0 {
            g1.clone()
        } else if g2.degree_in(other) == 0 {
            g2.clone()
        } else {
            eliminate(&g1, &g2, other)?
        };
        Ok(match r.to_upoly(s) {
            Some(u) => roots_in(&u, lo, hi).into_iter().filter(|r| inside(r, lo, hi)).collect(),
            None => Vec::new(),
        })
    };
    let ra = project(a, b, alo, ahi)?;
    if ra.is_empty() {
        return Ok(Vec::new());
    }
    let rb = project(b, a, blo, bhi)?;
    let mut out = Vec::new();
    for x in &ra {
        for y in &rb {
            let pt = vec![(a, x.clone()), (b, y.clone())];
            if may_vanish(&g1, &pt) && may_vanish(&g2, &pt) {
                out.push(pt);
            }
        }
    }
    Ok(out)
}

/// The search over the box.
pub(crate) fn search_box(
    problem: &Problem,
    s: &Setup,
    polys: &[Breakpoints],
) -> Result<Found, Error> {
    let Engine::Signs(sys) = &s.engine else {
        unreachable!("Φ_max over a box is searched through its disk bound (disk.rs)");
    };
    let (a, b) = (s.syms[0], s.syms[1]);
    let (fa, fb) = (&problem.free[0], &problem.free[1]);
    let mut best: Option<(Score, Point, Eval, Vec<String>)> = None;
    let mut evaluated = 0usize;
    let mut consider = |pt: Vec<(Sym, Algebraic)>, e: Eval, why: Vec<String>| {
        let better = match &best {
            None => true,
            Some((sc, at, _, _)) => e.score > *sc || (e.score == *sc && lex_less(&pt, at)),
        };
        if better {
            best = Some((e.score.clone(), pt, e, why));
        }
    };
    // The edges.
    for (fixed, p, lo, hi) in [
        (vec![(a, fa.lo.clone())], b, &fb.lo, &fb.hi),
        (vec![(a, fa.hi.clone())], b, &fb.lo, &fb.hi),
        (vec![(b, fb.lo.clone())], a, &fa.lo, &fa.hi),
        (vec![(b, fb.hi.clone())], a, &fa.lo, &fa.hi),
    ] {
        let line = search_line(&s.engine, polys, &fixed, p, lo, hi)?;
        for v in line.visited {
            evaluated += 1;
            let mut pt: Vec<(Sym, Algebraic)> =
                fixed.iter().map(|(s, q)| (*s, Algebraic::from_rational(q.clone()))).collect();
            pt.push((p, v.p.clone()));
            pt.sort_by_key(|(s, _)| if *s == a { 0 } else { 1 });
            let why = match v.visit {
                super::one::Visit::Candidate(w) => w,
                _ => vec!["a point inside a piece of an edge".to_owned()],
            };
            consider(pt, v.eval, why);
        }
    }
    // The interior: the systems of the breakpoint curves, then those of
    // every component two of their equations share (a curve of solutions,
    // searched as a breakpoint curve is).
    let mut shared: Vec<Poly> = Vec::new();
    let mut list = systems(sys, polys, a, b)?;
    let mut points: Vec<(Point, Vec<String>)> = Vec::new();
    let mut solve_all = |list: &[System2], shared: &mut Vec<Poly>| -> Result<(), Error> {
        for s2 in list {
            for pt in solve(s2, a, b, (&fa.lo, &fa.hi), (&fb.lo, &fb.hi), shared)? {
                match points.iter_mut().find(|(p, _)| *p == pt) {
                    Some((_, why)) => why.push(s2.label.clone()),
                    None => points.push((pt, vec![s2.label.clone()])),
                }
            }
        }
        Ok(())
    };
    solve_all(&list, &mut shared)?;
    let curves: Vec<&Breakpoints> = polys.iter().collect();
    let mut second = Vec::new();
    for (k, g) in shared.iter().enumerate() {
        let label = format!("the shared component {}", g);
        let mut more = curve_systems(sys, g, &label, &curves, a, b)?;
        // And the shared components meeting each other.
        for h in &shared[k + 1..] {
            more.push(System2 {
                g1: g.clone(),
                g2: h.clone(),
                label: format!("{label} meets {h}"),
            });
        }
        second.extend(more);
    }
    let mut unresolved: Vec<Poly> = Vec::new();
    solve_all(&second, &mut unresolved)?;
    unresolved.retain(|g| !shared.contains(g));
    let components = shared.len();
    list.extend(second);
    for (pt, why) in points {
        evaluated += 1;
        let e = sys.evaluate(&pt)?;
        consider(pt, e, why);
    }
    let (score, at, e, why) = best.expect("the corners are evaluated");
    let mut cert = vec![header(problem)];
    cert.push(format!(
        "the exact search evaluated {evaluated} points: the one-parameter search along each \
         edge of the box, and inside it the solutions of {} systems of two equations in ({}, {}) \
         from {} breakpoint curves (curves meeting, tangents, stationary roots along a curve, \
         critical points of a branch); the objective is upper semicontinuous, so its maximum is \
         attained at one of them{}",
        list.len(),
        a.name(),
        b.name(),
        polys.len(),
        if components > 0 {
            format!(
                "; {components} curves where two equations share a component were searched as \
                 breakpoint curves are"
            )
        } else {
            String::new()
        }
    ));
    if !unresolved.is_empty() {
        let list: Vec<String> = unresolved.iter().map(|g| g.to_string()).collect();
        cert.push(format!(
            "not certified along {}: the systems on those curves share a component again, and \
             the search does not go a level deeper",
            list.join(", ")
        ));
    }
    let names: Vec<String> =
        at.iter().map(|(s, v)| format!("{} = {}", s.name(), v.describe(s.name()))).collect();
    cert.push(format!("optimum {score} at {}, attained", names.join(", ")));
    cert.push(format!("the point is where {}", why.join("; ")));
    cert.extend(solves(s, &e, &at));
    Ok((score, true, at.into_iter().map(|(_, v)| v).collect(), cert, evaluated))
}

fn lex_less(p: &[(Sym, Algebraic)], q: &[(Sym, Algebraic)]) -> bool {
    for ((_, x), (_, y)) in p.iter().zip(q) {
        match x.cmp(y) {
            Ordering::Less => return true,
            Ordering::Greater => return false,
            Ordering::Equal => {}
        }
    }
    false
}
