//! The search over one parameter p ∈ [lo, hi] (or along a line of the
//! two-parameter box). The candidates are the ends and every root in the
//! range of the breakpoint polynomials (where the arrangement of the
//! conditions' roots in x changes, or a root is stationary in p); between
//! consecutive candidates the objective is one monotone branch.
//!
//! - A sign system's objective is upper semicontinuous, so its maximum is
//!   attained at a candidate: each is evaluated exactly, rational or
//!   algebraic, and one rational sample per piece shows whether the optimum
//!   holds on a whole interval.
//! - Φ_max may jump at a candidate: each piece's supremum is the larger of
//!   its limits at the two ends (`Oscillator::limit`), compared with the
//!   values at the candidates themselves.

use super::algebra::{between, roots_in};
use super::problem::Engine;
use super::report::Score;
use super::system::{Breakpoints, Eval};
use crate::error::Error;
use crate::{Algebraic, Sym, Q};

/// What a visited point is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Visit {
    /// A candidate: an end of the range or a breakpoint, with the reasons.
    Candidate(Vec<String>),
    /// A rational point inside a piece.
    Sample,
    /// The limit of the objective as p tends to the point from below
    /// (`false`) or above (`true`); not a value at the point.
    Limit(bool),
}

/// One evaluated point of the line.
#[derive(Clone, Debug)]
pub(crate) struct Visited {
    /// The point's value of p.
    pub p: Algebraic,
    /// What it is.
    pub visit: Visit,
    /// The objective there.
    pub eval: Eval,
}

/// The answer along a line.
#[derive(Clone, Debug)]
pub(crate) struct LineResult {
    /// Every visited point, increasing in p (limits next to their point).
    pub visited: Vec<Visited>,
    /// The supremum.
    pub best: Score,
    /// Whether a point attains it.
    pub attained: bool,
    /// The least p attaining it, or the limit point.
    pub at: Algebraic,
    /// The breakpoint polynomials asked.
    pub polys: usize,
}

/// The breakpoints in [lo, hi] of `polys` restricted to the line (the other
/// coordinates fixed at the rational `fixed`), with their reasons.
pub(crate) fn line_breakpoints(
    polys: &[Breakpoints],
    fixed: &[(Sym, Q)],
    p: Sym,
    lo: &Q,
    hi: &Q,
) -> Vec<(Algebraic, Vec<String>)> {
    let map: std::collections::HashMap<Sym, Q> = fixed.iter().cloned().collect();
    let mut out: Vec<(Algebraic, Vec<String>)> = Vec::new();
    let mut add = |r: Algebraic, why: String| match out.iter_mut().find(|(a, _)| *a == r) {
        Some((_, w)) => {
            if !w.contains(&why) {
                w.push(why)
            }
        }
        None => out.push((r, vec![why])),
    };
    add(Algebraic::from_rational(lo.clone()), format!("the end {p} = {lo} of the range"));
    add(Algebraic::from_rational(hi.clone()), format!("the end {p} = {hi} of the range"));
    for b in polys {
        let q = if map.is_empty() { b.poly.clone() } else { b.poly.eval_partial(&map) };
        let Some(u) = q.to_upoly(p) else { continue };
        for r in roots_in(&u, lo, hi) {
            add(r, format!("{} (a root of {} = 0)", b.label, u.to_string_in(p.name())));
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// The search along p ∈ [lo, hi] with the other coordinates `fixed`.
pub(crate) fn search_line(
    engine: &Engine,
    polys: &[Breakpoints],
    fixed: &[(Sym, Q)],
    p: Sym,
    lo: &Q,
    hi: &Q,
) -> Result<LineResult, Error> {
    let cands = line_breakpoints(polys, fixed, p, lo, hi);
    let point = |v: &Algebraic| -> Vec<(Sym, Algebraic)> {
        let mut pt: Vec<(Sym, Algebraic)> =
            fixed.iter().map(|(s, q)| (*s, Algebraic::from_rational(q.clone()))).collect();
        pt.push((p, v.clone()));
        pt
    };
    let eval = |v: &Algebraic| -> Result<Eval, Error> {
        match engine {
            Engine::Signs(s) => s.evaluate(&point(v)),
            Engine::Oscillator(o) => o.evaluate(&point(v)),
        }
    };
    let mut visited: Vec<Visited> = Vec::new();
    for (i, (c, why)) in cands.iter().enumerate() {
        if i > 0 {
            let prev = &cands[i - 1].0;
            match engine {
                Engine::Signs(_) => {
                    let s = Algebraic::from_rational(between(prev, c));
                    visited.push(Visited { eval: eval(&s)?, p: s, visit: Visit::Sample });
                }
                Engine::Oscillator(o) => {
                    let (lq, rq) = match (prev.as_rational(), c.as_rational()) {
                        (Some(l), Some(r)) => (l.clone(), r.clone()),
                        _ => {
                            // `evaluate` refuses irrational candidates first.
                            eval(if prev.is_rational() { c } else { prev })?;
                            unreachable!("an irrational candidate is refused")
                        }
                    };
                    let (from_left, sample) = o.limit(p, &lq, c)?;
                    let (from_right, _) = o.limit(p, &rq, prev)?;
                    let s = Algebraic::from_rational(sample);
                    let sample_eval = eval(&s)?;
                    // The limit at the left end, from above; at the right
                    // end, from below.
                    let lim = |score: Score| Eval { score, exit: None, vanishing: Vec::new() };
                    let last = visited.len() - 1;
                    visited.insert(
                        last + 1,
                        Visited {
                            p: prev.clone(),
                            visit: Visit::Limit(true),
                            eval: lim(from_left),
                        },
                    );
                    visited.push(Visited { p: s, visit: Visit::Sample, eval: sample_eval });
                    visited.push(Visited {
                        p: c.clone(),
                        visit: Visit::Limit(false),
                        eval: lim(from_right),
                    });
                }
            }
        }
        visited.push(Visited {
            eval: eval(c)?,
            p: c.clone(),
            visit: Visit::Candidate(why.clone()),
        });
    }
    let best = visited.iter().map(|v| v.eval.score.clone()).max().expect("at least one point");
    let attained_at = visited.iter().find(|v| {
        v.visit != Visit::Limit(true) && v.visit != Visit::Limit(false) && v.eval.score == best
    });
    let (attained, at) = match attained_at {
        Some(v) => (true, v.p.clone()),
        None => {
            let v = visited.iter().find(|v| v.eval.score == best).expect("the best is visited");
            (false, v.p.clone())
        }
    };
    Ok(LineResult { visited, best, attained, at, polys: polys.len() })
}
