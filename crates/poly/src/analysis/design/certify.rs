//! The certificate's shared lines: the problem restated, and what the
//! value at a point solves (the equation of the optimum, the conditions that
//! vanish there and the one that fails beyond it); and the evaluation of
//! the engine at a point, which both searches use.

use std::collections::HashMap;

use super::problem::{Engine, Problem, Setup, Subject};
use super::report::Score;
use super::system::Eval;
use crate::error::Error;
use crate::{Algebraic, Poly, Sym, Q};

/// The objective at a point of the search.
pub(crate) fn evaluate(s: &Setup, point: &[(Sym, Algebraic)]) -> Result<Eval, Error> {
    match &s.engine {
        Engine::Signs(sys) => sys.evaluate(point),
        Engine::Oscillator(o) => o.evaluate(point),
    }
}

pub(crate) fn header(problem: &Problem) -> String {
    let name = match &problem.subject {
        Subject::Program(d) => d.method().name().to_owned(),
        Subject::Tableau(t) => t.name().to_owned(),
    };
    let ranges: Vec<String> =
        problem.free.iter().map(|f| format!("{} in [{}, {}]", f.name, f.lo, f.hi)).collect();
    let mut line = format!("maximise {} of `{name}` over {}", problem.objective, ranges.join(", "));
    if !problem.bound.is_empty() {
        line.push_str(&format!(", with {}", problem.bound));
    }
    if let Some(p) = problem.min_order {
        line.push_str(&format!(", order at least {p}"));
    }
    line
}

/// What the value at a point solves, and which factors vanish there.
pub(crate) fn solves(s: &Setup, e: &Eval, point: &[(Sym, Algebraic)]) -> Vec<String> {
    let (var, labels, polys): (&str, Vec<String>, Vec<Poly>) = match &s.engine {
        Engine::Signs(sys) => (
            sys.x.name(),
            e.vanishing.iter().map(|&k| sys.factors[k].label.clone()).collect(),
            e.vanishing.iter().map(|&k| sys.factors[k].poly.clone()).collect(),
        ),
        Engine::Oscillator(o) => (
            "Phi",
            e.vanishing.iter().map(|&k| o.factors[k].label.clone()).collect(),
            e.vanishing.iter().map(|&k| o.factors[k].poly.clone()).collect(),
        ),
    };
    let mut out = Vec::new();
    match &e.score {
        Score::Infinite => out.push("there the method is stable for every step".to_owned()),
        Score::Finite(v) if v.sign().is_eq() => out.push("there no step > 0 is stable".to_owned()),
        Score::Finite(v) => {
            out.push(match v.as_rational() {
                Some(q) => format!("the optimum is {var} = {q}, rational"),
                None => format!(
                    "the optimum solves {} = 0 ({var} = {})",
                    v.defining_poly().to_string_in(var),
                    v.describe(var)
                ),
            });
            let rational: HashMap<Sym, Q> = point
                .iter()
                .filter_map(|(s, a)| a.as_rational().map(|q| (*s, q.clone())))
                .collect();
            for (l, p) in labels.iter().zip(&polys) {
                out.push(format!("active condition there: {l}, {} = 0", p.eval_partial(&rational)));
            }
            if let Some(c) = e.exit {
                if let Engine::Signs(sys) = &s.engine {
                    out.push(format!("beyond it {} fails", sys.conditions[c].label));
                }
            }
        }
    }
    out
}
