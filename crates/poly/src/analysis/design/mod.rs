//! Design, not only check: the free parameters of a method chosen for the
//! best exact stability, with a certificate (issue 37, the library core).
//!
//! The objective (Φ_max on the oscillator, the real or imaginary stability
//! limit on y' = λy, or the SSP coefficient of a tableau) is piecewise
//! algebraic in the parameters. Its breakpoints are where the conditions
//! that bound it change their arrangement: roots of resultants and
//! discriminants in the parameters, found exactly. The objective is
//! evaluated exactly at every breakpoint, at the ends of the range and
//! inside every piece, and the values are compared exactly; the optimum is
//! an exact number or +∞, never a float. Where the search cannot finish
//! (a breakpoint polynomial past [`MAX_BREAKPOINT_DEGREE`], an irrational
//! point where the engine only reads rational ones), it stops with an error
//! that says so.
//!
//! - `report.rs`: the answer types. `problem.rs`: the input, checked, and
//!   the engine of each objective. `tableau.rs`: tableaux with parameters.
//! - `system.rs`: objectives read from signs (the axes of one-step methods,
//!   the SSP coefficient), exact at algebraic points; `oscillator.rs`: Φ_max.
//! - `algebra.rs`: elimination, roots in a range, signs at algebraic points.
//! - `one.rs`: the search along one parameter; `two.rs`: over a box of two,
//!   for the objectives read from signs; `disk.rs`: Φ_max over a box of
//!   two, through the closed disk's sign conditions (χ of degree 2 in z);
//!   `order_set.rs`: two parameters under `min_order`, cut to a point or
//!   a line (then searched as one parameter).
//! - here: the entry, the grid check and the certificate.
//!
//! ```
//! use poly::advanced::design::{maximize, FreeParam, Objective, Problem, Subject};
//! let d = poly::derive_source("cheb.zm", "method cheb\nparam a2\nstate y\ny = y + w*y + a2*w^2*y\n")?;
//! let problem = Problem {
//!     subject: Subject::Program(&d),
//!     objective: Objective::RealLimit,
//!     free: vec![FreeParam::new("a2", poly::q(0, 1), poly::q(1, 2))],
//!     bound: poly::Params::new(),
//!     min_order: None,
//! };
//! let design = maximize(&problem)?;
//! assert_eq!(design.optimum.to_string(), "8");
//! assert_eq!(design.at[0].1.to_string(), "1/8");
//! # Ok::<(), poly::Error>(())
//! ```

mod algebra;
mod certify;
mod disk;
mod one;
mod order_set;
mod oscillator;
mod problem;
mod report;
mod system;
mod tableau;
mod two;

use crate::error::{Error, ErrorKind};
use crate::{Algebraic, Poly, Sym, Q};

use certify::{evaluate, header, solves};
use one::{search_line, LineResult, Visit};
use order_set::{Line, OrderSet};
use problem::{setup, Engine, Setup};
pub use problem::{Problem, Subject};
pub use report::{
    Design, FreeParam, GridCheck, Objective, Score, GRID_ONE, GRID_TWO, MAX_BREAKPOINT_DEGREE,
    MAX_SYSTEM_DEGREE,
};
use system::Eval;
pub use tableau::ParamTableau;

/// The exact supremum of the problem's objective over its box (and its
/// allowed set, under `min_order`), where it is attained, why, and the
/// exact grid check.
pub fn maximize(problem: &Problem) -> Result<Design, Error> {
    match bound_tableau(problem)? {
        Some(t) => maximize_bound(&Problem { subject: Subject::Tableau(&t), ..problem.clone() }),
        None => maximize_bound(problem),
    }
}

/// A tableau subject with its bound parameters replaced by their values,
/// when there are any (a program reads them at each evaluation).
fn bound_tableau(problem: &Problem) -> Result<Option<ParamTableau>, Error> {
    match problem.subject {
        Subject::Tableau(t) if !problem.bound.is_empty() => {
            let values: std::collections::HashMap<Sym, Q> =
                problem.bound.iter().map(|(n, v)| (Sym::new(n), v.clone())).collect();
            Ok(Some(t.bind(&values)?))
        }
        _ => Ok(None),
    }
}

/// [`maximize`] once a tableau's bound values are in its entries.
fn maximize_bound(problem: &Problem) -> Result<Design, Error> {
    let s = setup(problem)?;
    let ((optimum, attained, at, certificate, candidates), grid_check) = if s.syms.len() == 2
        && !s.order_conditions.is_empty()
    {
        on_order_set(problem, &s)?
    } else if s.syms.len() == 2 && matches!(s.engine, Engine::Oscillator(_)) {
        (disk::search_box(problem, &s)?, grid(problem, &s)?)
    } else {
        let polys = breakpoints(&s)?;
        let found = if s.syms.len() == 1 {
            let f = &problem.free[0];
            if s.order_conditions.is_empty() {
                let line = search_line(&s.engine, &polys, &[], s.syms[0], &f.lo, &f.hi)?;
                let cert = certificate_one(problem, &s, &line);
                (line.best.clone(), line.attained, vec![line.at.clone()], cert, line.visited.len())
            } else {
                let pts = allowed_points(&s, &f.lo, &f.hi)?;
                finite_set(problem, &s, &pts, None)?
            }
        } else {
            two::search_box(problem, &s, &polys)?
        };
        (found, grid(problem, &s)?)
    };
    if grid_check.max > optimum {
        return Err(Error::analysis(
            ErrorKind::Undecided,
            format!(
                "internal check failed: the grid reaches {} above the optimum {} found by the \
                 exact search",
                grid_check.max, optimum
            ),
        ));
    }
    let mut certificate = certificate;
    certificate.push(format!(
        "grid check: {} points of the allowed set evaluated exactly; their largest value {} \
         does not exceed the optimum",
        grid_check.points, grid_check.max
    ));
    // The objective's variable reads as x, y or r.
    let certificate = certificate.into_iter().map(|l| l.replace("_design", "")).collect();
    let at = problem.free.iter().map(|f| f.name.clone()).zip(at).collect();
    Ok(Design {
        objective: problem.objective,
        params: problem.free.clone(),
        optimum,
        attained,
        at,
        certificate,
        grid_check,
        candidates,
    })
}

/// The breakpoint polynomials of the setup's engine.
fn breakpoints(s: &Setup) -> Result<Vec<system::Breakpoints>, Error> {
    match &s.engine {
        Engine::Signs(sys) => sys.breakpoints(&s.syms),
        Engine::Oscillator(o) => system::arrangement(&o.factors, Sym::phi(), &s.syms),
    }
}

/// Two free parameters under `min_order`: the order conditions solved
/// (`order_set.rs`), then the objective at the one allowed point, or the
/// one-parameter search along the allowed line (or at its allowed points).
fn on_order_set(problem: &Problem, s: &Setup) -> Result<(Found, GridCheck), Error> {
    let ranges: Vec<(Q, Q)> = problem.free.iter().map(|f| (f.lo.clone(), f.hi.clone())).collect();
    let order = problem.min_order.unwrap_or(0);
    let (a, b) = (s.syms[0], s.syms[1]);
    match order_set::solve(s, &ranges, order)? {
        OrderSet::Point(pt) => {
            let point: Vec<(Sym, Algebraic)> =
                pt.iter().map(|(s, q)| (*s, Algebraic::from_rational(q.clone()))).collect();
            let e = evaluate(s, &point)?;
            let shown: Vec<String> = pt.iter().map(|(s, q)| format!("{s} = {q}")).collect();
            let shown = shown.join(", ");
            let mut cert = vec![header(problem)];
            cert.push(format!(
                "min_order {order}: the order conditions are affine in ({a}, {b}) and hold at \
                 one point only, {shown}, inside the box: the allowed set is that point"
            ));
            cert.push(format!("optimum {} at {shown}, attained", e.score));
            cert.extend(solves(s, &e, &point));
            let grid = GridCheck { points: 1, max: e.score.clone(), at: named(&point) };
            let at = point.into_iter().map(|(_, v)| v).collect();
            Ok(((e.score, true, at, cert, 1), grid))
        }
        OrderSet::Line(line) => {
            let r = order_set::restrict(s, &line);
            let t = line.t;
            let set = format!(
                "min_order {order}: the order conditions affine in ({a}, {b}) hold exactly on the \
                 line {} (its part inside the box); the search runs along it in {t}",
                line.describe()
            );
            let (found, points) = if r.order_conditions.is_empty() {
                let polys = breakpoints(&r)?;
                let res = search_line(&r.engine, &polys, &[], t, &line.lo, &line.hi)?;
                let mut cert = certificate_one(problem, &r, &res);
                cert.insert(1, set);
                if let Some(k) = cert.iter().position(|l| l.starts_with("optimum ")) {
                    let d = line.dependent_at(&res.at);
                    let there =
                        format!("there {} = {}", line.dependent, d.describe(line.dependent.name()));
                    cert.insert(k + 1, there);
                }
                let points = axis(&line.lo, &line.hi, GRID_ONE)
                    .into_iter()
                    .map(|q| vec![(t, Algebraic::from_rational(q))])
                    .collect();
                let at = line.point(&s.syms, &res.at).into_iter().map(|(_, v)| v).collect();
                ((res.best, res.attained, at, cert, res.visited.len()), points)
            } else {
                let pts = allowed_points(&r, &line.lo, &line.hi)?;
                let mut found = finite_set(problem, &r, &pts, Some((&line, &s.syms)))?;
                found.3.insert(1, set);
                let points = pts.into_iter().map(|v| vec![(t, v)]).collect();
                (found, points)
            };
            let grid = grid_over(&r, points, |pt| line.point(&s.syms, &pt[0].1))?;
            Ok((found, grid))
        }
    }
}

/// The objective at one rational point of the free parameters, by the
/// engine the search uses (the oracle tests compare it with the front
/// door's [`Derivation::stability`](crate::Derivation::stability),
/// [`Derivation::plane`](crate::Derivation::plane) and
/// [`ssp_coefficient`](crate::advanced::order::ssp_coefficient)).
pub fn objective_at(problem: &Problem, values: &[(&str, Q)]) -> Result<Score, Error> {
    let bound = bound_tableau(problem)?;
    let problem = match &bound {
        Some(t) => Problem { subject: Subject::Tableau(t), ..problem.clone() },
        None => problem.clone(),
    };
    let s = setup(&problem)?;
    let point: Vec<(Sym, Q)> = values.iter().map(|(n, v)| (Sym::new(n), v.clone())).collect();
    Ok(evaluate_rational(&s, &point)?.score)
}

fn evaluate_rational(s: &Setup, point: &[(Sym, Q)]) -> Result<Eval, Error> {
    let alg: Vec<(Sym, Algebraic)> =
        point.iter().map(|(s, q)| (*s, Algebraic::from_rational(q.clone()))).collect();
    match &s.engine {
        Engine::Signs(sys) => sys.evaluate(&alg),
        Engine::Oscillator(o) => o.evaluate(&alg),
    }
}

/// The points of [lo, hi] where every order condition vanishes (one
/// parameter): the roots of their gcd.
fn allowed_points(s: &Setup, lo: &Q, hi: &Q) -> Result<Vec<Algebraic>, Error> {
    let p = s.syms[0];
    let g = s.order_conditions.iter().fold(Poly::zero(), |g, c| g.gcd(c));
    let u = g.to_upoly(p).ok_or_else(|| {
        report::input_error("the order conditions hold a symbol other than the parameter".into())
    })?;
    let pts = algebra::roots_in(&u, lo, hi);
    if pts.is_empty() {
        return Err(Error::analysis(
            ErrorKind::NoRoots,
            format!(
                "no {} in [{lo}, {hi}] has the order asked: the order conditions have no common \
                 root there",
                p.name()
            ),
        ));
    }
    Ok(pts)
}

type Found = (Score, bool, Vec<Algebraic>, Vec<String>, usize);

/// The optimum over a finite allowed set of one parameter (on a line of
/// the box, with the line and the problem's symbols to name the points).
fn finite_set(
    problem: &Problem,
    s: &Setup,
    pts: &[Algebraic],
    line: Option<(&Line, &[Sym])>,
) -> Result<Found, Error> {
    let p = s.syms[0];
    let mut best: Option<(Score, Algebraic, Eval)> = None;
    for a in pts {
        let e = evaluate(s, &[(p, a.clone())])?;
        if best.as_ref().is_none_or(|b| e.score > b.0) {
            best = Some((e.score.clone(), a.clone(), e));
        }
    }
    let (score, at, e) = best.expect("a nonempty set");
    let full = |v: &Algebraic| match line {
        Some((l, syms)) => l.point(syms, v),
        None => vec![(p, v.clone())],
    };
    let shown = |v: &Algebraic| {
        full(v)
            .iter()
            .map(|(s, a)| format!("{s} = {}", a.describe(s.name())))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let set = match line {
        Some(_) => pts.iter().map(|a| format!("({})", shown(a))).collect::<Vec<_>>().join(", "),
        None => format!(
            "{p} = {}",
            pts.iter().map(|a| a.describe(p.name())).collect::<Vec<_>>().join(", ")
        ),
    };
    let mut cert = vec![header(problem)];
    cert.push(format!(
        "min_order {}: the order conditions hold only at {set} in the range",
        problem.min_order.unwrap_or(0),
    ));
    cert.push(format!("optimum {score} at {}, attained", shown(&at)));
    cert.extend(solves(s, &e, &[(p, at.clone())]));
    let at = full(&at).into_iter().map(|(_, v)| v).collect();
    Ok((score, true, at, cert, pts.len()))
}

fn certificate_one(problem: &Problem, s: &Setup, line: &LineResult) -> Vec<String> {
    let p = s.syms[0];
    let name = p.name();
    let mut cert = vec![header(problem)];
    let breaks = line
        .visited
        .iter()
        .filter(|v| matches!(&v.visit, Visit::Candidate(w) if w.iter().any(|w| !w.starts_with("the end"))))
        .count();
    cert.push(format!(
        "the exact search evaluated {} points: both ends, {breaks} breakpoints in the range (the \
         roots there of {} breakpoint polynomials: where the conditions' roots in the objective's \
         variable meet, pass through 0 or infinity, or are stationary in {name}), and a rational \
         point inside each piece{}",
        line.visited.len(),
        line.polys,
        if matches!(s.engine, Engine::Oscillator(_)) {
            ", with the exact limits at both ends of each piece"
        } else {
            "; the objective is upper semicontinuous, so its maximum is attained at one of them"
        }
    ));
    let how = if line.attained { "attained" } else { "approached, not attained" };
    cert.push(format!("optimum {} at {name} = {}, {how}", line.best, line.at.describe(name)));
    if let Some(v) = line.visited.iter().find(|v| v.p == line.at && v.eval.score == line.best) {
        if let Visit::Candidate(why) = &v.visit {
            cert.push(format!("{name} = {} is {}", v.p.describe(name), why.join("; ")));
        }
        cert.extend(solves(s, &v.eval, &[(p, v.p.clone())]));
    }
    // The neighbouring pieces.
    let idx = line.visited.iter().position(|v| v.p == line.at).unwrap_or(0);
    let side = |v: &one::Visited, word: &str| -> String {
        let labels: Vec<String> = match &s.engine {
            Engine::Signs(sys) => {
                v.eval.vanishing.iter().map(|&k| sys.factors[k].label.clone()).collect()
            }
            Engine::Oscillator(o) => {
                v.eval.vanishing.iter().map(|&k| o.factors[k].label.clone()).collect()
            }
        };
        let value = match &v.eval.score {
            Score::Finite(a) => format!("{} (about {})", a.describe("x"), a.to_decimal(6)),
            Score::Infinite => "inf".to_owned(),
        };
        let active = if labels.is_empty() {
            String::new()
        } else {
            format!(", limited by {}", labels.join(" and "))
        };
        format!(
            "{word} ({name} = {}): {} = {value}{active}",
            v.p.describe(name),
            problem_objective(problem)
        )
    };
    if let Some(v) = line.visited[..idx].iter().rev().find(|v| v.visit == Visit::Sample) {
        cert.push(side(v, "just below"));
    }
    if let Some(v) = line.visited[idx..].iter().find(|v| v.visit == Visit::Sample) {
        cert.push(side(v, "just above"));
    }
    // A whole interval of maximisers.
    let run: Vec<&one::Visited> = line.visited[idx..]
        .iter()
        .filter(|v| !matches!(v.visit, Visit::Limit(_)))
        .take_while(|v| v.eval.score == line.best)
        .collect();
    if run.iter().any(|v| v.visit == Visit::Sample) {
        let last = run.last().expect("nonempty");
        cert.push(format!(
            "the maximisers form a set: every {name} in [{}, {}] attains the optimum (the \
             objective is constant on those pieces); `at` is its least point",
            line.at.describe(name),
            last.p.describe(name)
        ));
    }
    cert
}

fn problem_objective(problem: &Problem) -> &'static str {
    problem.objective.name()
}

/// `n` equally spaced points of [lo, hi] (one when the range is a point).
fn axis(lo: &Q, hi: &Q, n: usize) -> Vec<Q> {
    if lo == hi || n < 2 {
        return vec![lo.clone()];
    }
    let step = (hi - lo) / Q::from_integer(((n - 1) as i64).into());
    (0..n).map(|k| lo + &step * Q::from_integer((k as i64).into())).collect()
}

/// The objective on a grid of the box, or at every point of a finite
/// allowed set (algebraic ones too), exactly.
fn grid(problem: &Problem, s: &Setup) -> Result<GridCheck, Error> {
    let rational = |pt: Vec<(Sym, Q)>| -> Vec<(Sym, Algebraic)> {
        pt.into_iter().map(|(s, q)| (s, Algebraic::from_rational(q))).collect()
    };
    let mut points: Vec<Vec<(Sym, Algebraic)>> = Vec::new();
    if !s.order_conditions.is_empty() {
        let f = &problem.free[0];
        for a in allowed_points(s, &f.lo, &f.hi)? {
            points.push(vec![(s.syms[0], a)]);
        }
    } else if s.syms.len() == 1 {
        let f = &problem.free[0];
        for q in axis(&f.lo, &f.hi, GRID_ONE) {
            points.push(rational(vec![(s.syms[0], q)]));
        }
    } else {
        let (f, g) = (&problem.free[0], &problem.free[1]);
        for a in axis(&f.lo, &f.hi, GRID_TWO) {
            for b in axis(&g.lo, &g.hi, GRID_TWO) {
                points.push(rational(vec![(s.syms[0], a.clone()), (s.syms[1], b)]));
            }
        }
    }
    grid_over(s, points, |pt| pt.to_vec())
}

/// The objective at each point of the setup, exactly: the largest value,
/// and the first point reaching it, in the problem's coordinates (`full`).
fn grid_over(
    s: &Setup,
    points: Vec<Vec<(Sym, Algebraic)>>,
    full: impl Fn(&[(Sym, Algebraic)]) -> Vec<(Sym, Algebraic)>,
) -> Result<GridCheck, Error> {
    let mut max = Score::zero();
    let mut at = Vec::new();
    for pt in &points {
        let e = evaluate(s, pt)?;
        if at.is_empty() || e.score > max {
            max = e.score;
            at = named(&full(pt));
        }
    }
    Ok(GridCheck { points: points.len(), max, at })
}

fn named(point: &[(Sym, Algebraic)]) -> Vec<(String, Algebraic)> {
    point.iter().map(|(s, a)| (s.name().to_owned(), a.clone())).collect()
}
