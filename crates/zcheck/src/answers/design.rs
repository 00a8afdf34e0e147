//! `zcheck design`: the free parameters of a method chosen for the best
//! exact stability, with a certificate (issue 37). The search is `poly`'s
//! ([`poly::advanced::design`]); here the method is loaded (a `.zm` program
//! or built-in, or a Butcher tableau whose entries name its parameters),
//! the `--param` arguments are read (`NAME=LO..HI` free, `NAME=VALUE`
//! bound), `--per` divides the objective by the stage count or the step's
//! multiplications, and the design becomes the JSON document and the text
//! the command prints (the Python module's `zcheck.design` returns the
//! same document).
//!
//! Every exact number is `{"exact", "value"}` ([`super::exact`]), +∞ is
//! `{"exact": "inf", "value": null}`; the optimum is never a float.

use std::fmt::Write as _;
use std::path::Path;

use poly::advanced::design::{
    maximize, Design, FreeParam, Objective, ParamTableau, Problem, Score, Subject as Of,
};
use poly::{Algebraic, Params, UPoly, Q};
use serde_json::{json, Map, Value};

use super::exact::{constant, fine, infinity, number};
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::readings::Form;
use crate::values::{Exact, ParamArg};

/// What `--per` divides the objective by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Per {
    /// The stage count of a tableau.
    Stage,
    /// The step's multiplications (`poly::advanced::cost`).
    Cost,
}

/// The question: the objective, the free parameters with their ranges,
/// the bound ones, the least order and the divisor.
#[derive(Clone, Debug)]
pub(crate) struct Request {
    objective: Objective,
    free: Vec<FreeParam>,
    bound: Vec<(String, Q)>,
    min_order: Option<usize>,
    per: Option<Per>,
}

impl Request {
    /// The request from the command line's text: the objective's name, the
    /// `--param` arguments (`NAME=LO..HI` a free range, `NAME=VALUE` a
    /// bound value), `--min-order P` and `--per stage|cost`.
    pub(crate) fn parse(
        objective: &str,
        params: &[String],
        min_order: Option<usize>,
        per: Option<&str>,
    ) -> Result<Request, Error> {
        let objective = Objective::parse(objective)
            .map_err(|e| Error::usage(format!("--maximize {objective}: {}", e.message())))?;
        let per = match per {
            None => None,
            Some("stage") => Some(Per::Stage),
            Some("cost") => Some(Per::Cost),
            Some(other) => {
                return Err(Error::usage(format!("--per {other}: expected stage or cost")));
            }
        };
        let mut free = Vec::new();
        let mut bound: Vec<(String, Q)> = Vec::new();
        for s in params {
            let Some((name, value)) = s.split_once('=') else {
                return Err(Error::usage(format!(
                    "--param {s}: expected NAME=LO..HI (a free range) or NAME=VALUE (a bound value)"
                )));
            };
            let name = name.trim();
            // The name is checked as a NAME=VALUE argument's is.
            let _: ParamArg = format!("{name}=0")
                .parse()
                .map_err(|e: String| Error::usage(format!("--param {s}: {e}")))?;
            let given = free.iter().any(|f: &FreeParam| f.name == name)
                || bound.iter().any(|(n, _)| n == name);
            if given {
                return Err(Error::usage(format!("--param {name}: given twice")));
            }
            if let Some((lo, hi)) = value.split_once("..") {
                let read = |part: &str, which: &str| -> Result<Q, Error> {
                    part.parse::<Exact>().map(|e| e.value).map_err(|e| {
                        Error::usage(format!(
                            "--param {s}: {which}: expected an exact number such as 0, 1/2 or 0.5: {e}"
                        ))
                    })
                };
                let (lo, hi) = (read(lo, "LO")?, read(hi, "HI")?);
                if lo > hi {
                    return Err(Error::usage(format!(
                        "--param {s}: the range is empty: expected LO <= HI"
                    )));
                }
                free.push(FreeParam::new(name, lo, hi));
            } else {
                let p: ParamArg =
                    s.parse().map_err(|e: String| Error::usage(format!("--param {s}: {e}")))?;
                bound.push((p.name, p.value.value));
            }
        }
        match free.len() {
            1 | 2 => {}
            0 => {
                return Err(Error::usage(
                    "--param: no free parameter: give one or two ranges NAME=LO..HI",
                ))
            }
            k => {
                let names: Vec<&str> = free.iter().map(|f| f.name.as_str()).collect();
                return Err(Error::usage(format!(
                    "--param: {k} free parameters ({}): the exact search takes one or two; bind \
                     the others with NAME=VALUE",
                    names.join(", ")
                )));
            }
        }
        Ok(Request { objective, free, bound, min_order, per })
    }

    /// The bound values, as the loaders take them.
    pub(crate) fn bound(&self) -> &[(String, Q)] {
        &self.bound
    }
}

/// The method whose parameters are chosen.
#[derive(Debug)]
pub(crate) enum Subject {
    /// A `.zm` program or a built-in.
    Program(Box<LoadedMethod>),
    /// A Butcher tableau whose entries name parameters, the bound ones
    /// substituted.
    Tableau(ParamTableau),
}

impl Subject {
    /// The method `arg` names: a `.toml` file is a Butcher tableau (its
    /// `params` the parameters, `bound` substituted), anything else a
    /// program as every command loads it.
    pub(crate) fn load(arg: &str, bound: &[(String, Q)]) -> Result<Subject, Error> {
        if !arg.ends_with(".toml") {
            return Ok(Subject::Program(Box::new(LoadedMethod::load(arg)?)));
        }
        let (shown, stem, text) = crate::tableau::read_file(Path::new(arg))?;
        let kind = if crate::tableau::is_multistep(&text) {
            Some("a linear multistep method")
        } else if crate::partitioned::is_partitioned(&text) {
            Some("a partitioned pair")
        } else if crate::partitioned::is_splitting(&text) {
            Some("a splitting")
        } else {
            None
        };
        if let Some(kind) = kind {
            return Err(Error::usage(format!(
                "{shown}: holds {kind}: zcheck design reads a Butcher tableau whose entries name \
                 its parameters (`params = [...]`) or a .zm program with `param` declarations"
            )));
        }
        Ok(Subject::Tableau(crate::tableau::family(&shown, &stem, &text, bound)?))
    }

    fn name(&self) -> &str {
        match self {
            Subject::Program(m) => m.method().name(),
            Subject::Tableau(t) => t.name(),
        }
    }
}

/// A design, its objective divided as `--per` asked.
#[derive(Clone, Debug)]
pub(crate) struct Answer {
    method: String,
    design: Design,
    /// The bound parameters' values, in the order given.
    bound: Vec<(String, Q)>,
    /// The divisor and what it counts, under `--per`.
    per: Option<(u32, String)>,
}

/// The design of `subject` under `request`: poly's exact search, then the
/// division of `--per`.
pub(crate) fn design(subject: &Subject, request: &Request) -> Result<Answer, Error> {
    let bound = request.bound.iter().fold(Params::new(), |p, (n, v)| p.bind(n, v.clone()));
    let of = match subject {
        Subject::Program(m) => Of::Program(m.derivation()?),
        Subject::Tableau(t) => Of::Tableau(t),
    };
    let problem = Problem {
        subject: of,
        objective: request.objective,
        free: request.free.clone(),
        bound,
        min_order: request.min_order,
    };
    let mut design = maximize(&problem)?;
    let per = match request.per {
        None => None,
        Some(per) => Some(divisor(subject, request, per)?),
    };
    if let Some((k, what)) = &per {
        design.optimum = divide(&design.optimum, *k)?;
        design.grid_check.max = divide(&design.grid_check.max, *k)?;
        design.certificate.insert(
            1,
            format!(
                "per {}: the optimum and the grid's largest value reported are {} divided by \
                 {what}; the lines below give {} itself",
                if request.per == Some(Per::Stage) { "stage" } else { "cost" },
                request.objective,
                request.objective
            ),
        );
    }
    Ok(Answer { method: subject.name().to_owned(), design, bound: request.bound.clone(), per })
}

/// The divisor of `--per`: the stage count, or the multiplications of one
/// step (the program on the objective's test equation; a tableau's counted
/// at a generic point of the box and at every point where it could change,
/// and refused unless all agree).
fn divisor(subject: &Subject, request: &Request, per: Per) -> Result<(u32, String), Error> {
    let name = subject.name();
    let k = match (per, subject) {
        (Per::Stage, Subject::Tableau(t)) => {
            let s = t.stages() as u32;
            return Ok((s, format!("the {s} stages")));
        }
        (Per::Stage, Subject::Program(m)) => match m.reading().map(|r| &r.form) {
            Some(Form::RungeKutta { tableau, .. }) => {
                let s = tableau.stages() as u32;
                return Ok((s, format!("the {s} stages")));
            }
            _ => {
                return Err(Error::usage(format!(
                    "--per stage: `{name}` is a program, with no stages: divide by its \
                     multiplications with --per cost, or give its Butcher tableau"
                )))
            }
        },
        (Per::Cost, Subject::Program(m)) => {
            (poly::advanced::cost::step_cost(m.method()).program.mul, String::new())
        }
        (Per::Cost, Subject::Tableau(t)) => {
            let bound: Vec<(poly::Sym, Q)> =
                request.bound.iter().map(|(n, v)| (poly::Sym::new(n), v.clone())).collect();
            // The multiplications of one step at a point of the box.
            let count_at = |free: &[(poly::Sym, Q)]| -> Result<u32, Error> {
                let values: Vec<(poly::Sym, Q)> = free.iter().chain(&bound).cloned().collect();
                let tab = t.at(&values)?;
                let program = if request.objective == Objective::PhiMax {
                    tab.method(false)?
                } else {
                    tab.scalar_method()?
                };
                Ok(poly::advanced::cost::step_cost(&program).program.mul)
            };
            if request.free.len() > 1 {
                return Err(Error::unsupported(format!(
                    "--per cost: with two free parameters, the multiply count of `{name}`'s step \
                     changes along the curves where an entry is 0 or ±1 or two entries agree, \
                     which the search does not follow; bind one parameter, or divide by stages \
                     with --per stage"
                )));
            }
            let f = &request.free[0];
            let sym = poly::Sym::new(&f.name);
            let generic = &f.lo + &((&f.hi - &f.lo) * Q::new(7.into(), 17.into()));
            let mul = count_at(&[(sym, generic.clone())])?;
            // The count is one number over the box unless it changes at a
            // point where an entry that varies is 0 or ±1 or meets another:
            // each such point is counted, and a change is refused (dividing
            // by the other count would misstate the objective per cost).
            for (x, why) in t.cost_breaks(&bound, sym, &f.lo, &f.hi) {
                let shown = x.describe(&f.name);
                let Some(q) = x.as_rational() else {
                    return Err(Error::unsupported(format!(
                        "--per cost: the multiply count of `{name}`'s step may change at {} = \
                         {shown} ({why}), an irrational point where no program is written; \
                         search a box without it, or divide by stages with --per stage",
                        f.name
                    )));
                };
                let there = count_at(&[(sym, q.clone())])?;
                if there != mul {
                    return Err(Error::unsupported(format!(
                        "--per cost: the multiply count of `{name}`'s step is not one number over \
                         the box: {there} at {} = {shown} ({why}), {mul} elsewhere, so the \
                         objective per cost is not one division of it; search a box without \
                         that point, or divide by stages with --per stage",
                        f.name
                    )));
                }
            }
            (
                mul,
                format!(" (the same at every point of the box; counted at {} = {generic})", f.name),
            )
        }
    };
    let (mul, note) = k;
    if mul == 0 {
        return Err(Error::unsupported(format!(
            "--per cost: one step of `{name}` takes no multiplication{note}: nothing to divide by"
        )));
    }
    let word = if mul == 1 { "multiplication" } else { "multiplications" };
    Ok((mul, format!("the {mul} {word} of one step{note}")))
}

/// `s / k`, exactly: a root of p(x) is k times a root of p(k·y).
fn divide(s: &Score, k: u32) -> Result<Score, Error> {
    let Score::Finite(a) = s else { return Ok(Score::Infinite) };
    let kq = Q::from_integer(k.into());
    if let Some(q) = a.as_rational() {
        return Ok(Score::Finite(Algebraic::from_rational(q / &kq)));
    }
    let p = a.defining_poly();
    let scaled = UPoly::new(
        p.coeffs().iter().enumerate().map(|(i, c)| c * num_traits::pow(kq.clone(), i)).collect(),
    );
    let (lo, hi) = a.refine(&fine()).interval();
    Algebraic::from_isolating(&scaled, &(lo / &kq), &(hi / &kq)).map(Score::Finite).ok_or_else(
        || Error::unsupported(format!("--per: {} / {k} could not be isolated", s.describe())),
    )
}

/// The objective's variable, in the defining polynomials of its values.
fn var(objective: Objective) -> &'static str {
    match objective {
        Objective::PhiMax => "Phi",
        Objective::RealLimit => "x",
        Objective::ImagLimit => "y",
        Objective::SspCoefficient => "r",
    }
}

fn score_json(s: &Score, var: &str) -> Value {
    match s {
        Score::Finite(a) => number(a, var),
        Score::Infinite => infinity(),
    }
}

/// A rational as `{"exact", "value"}`, as `zcheck order` writes one.
fn rational_json(q: &Q) -> Value {
    constant(&poly::Poly::constant(q.clone()))
}

/// The JSON document of `zcheck design --format json`: `method`,
/// `objective`, `params` (the free ones with their ranges), `optimum`,
/// `attained`, `at`, `certificate`, `grid_check`.
pub(crate) fn to_json(a: &Answer) -> Value {
    let d = &a.design;
    let v = var(d.objective);
    let mut params = Map::new();
    for f in &d.params {
        params.insert(
            f.name.clone(),
            json!({ "lo": rational_json(&f.lo), "hi": rational_json(&f.hi) }),
        );
    }
    let mut at = Map::new();
    for (n, x) in &d.at {
        at.insert(n.clone(), number(x, n));
    }
    let mut grid_at = Map::new();
    for (n, x) in &d.grid_check.at {
        let value = match x.as_rational() {
            Some(q) => rational_json(q),
            None => number(x, n),
        };
        grid_at.insert(n.clone(), value);
    }
    json!({
        "method": a.method,
        "objective": d.objective.name(),
        "params": params,
        "optimum": score_json(&d.optimum, v),
        "attained": d.attained,
        "at": at,
        "certificate": d.certificate,
        "grid_check": {
            "points": d.grid_check.points,
            "max": score_json(&d.grid_check.max, v),
            "at": grid_at,
        },
    })
}

/// A value for people: its closed form (or the root it is), and its
/// decimal when that says more.
fn shown(s: &Score) -> String {
    match s {
        Score::Infinite => "inf (stable for every step)".to_owned(),
        Score::Finite(a) => {
            let exact = s.describe();
            let approx = a.to_decimal(6);
            if (a.is_rational() && exact.len() <= approx.len()) || exact.contains("about") {
                exact
            } else {
                format!("{exact} ≈ {approx}")
            }
        }
    }
}

fn shown_at(name: &str, x: &Algebraic) -> String {
    let exact = x.describe(name);
    if x.is_rational() {
        exact
    } else {
        format!("{exact} ≈ {}", x.to_decimal(6))
    }
}

/// The text `zcheck design` prints.
pub(crate) fn to_text(a: &Answer) -> String {
    let d = &a.design;
    let mut out = String::new();
    let ranges: Vec<String> = d
        .params
        .iter()
        .map(|f| format!("{} in [{}, {}]", f.name, f.lo, f.hi))
        .chain(a.bound.iter().map(|(n, v)| format!("{n} = {v}")))
        .collect();
    let per = match &a.per {
        Some((_, what)) => format!(", divided by {what}"),
        None => String::new(),
    };
    let _ = writeln!(out, "design {}: maximise {}{per}", a.method, d.objective);
    let _ = writeln!(out, "  over        {}", ranges.join(", "));
    let _ = writeln!(out, "  optimum     {}", shown(&d.optimum));
    let at: Vec<String> = d.at.iter().map(|(n, x)| format!("{n} = {}", shown_at(n, x))).collect();
    let how = if d.attained { "attained" } else { "approached, not attained (the limit point)" };
    let _ = writeln!(out, "  at          {} ({how})", at.join(", "));
    let grid_at: Vec<String> =
        d.grid_check.at.iter().map(|(n, x)| format!("{n} = {}", shown_at(n, x))).collect();
    let _ = writeln!(
        out,
        "  grid check  {} points evaluated exactly: largest {} at {}, not above the optimum",
        d.grid_check.points,
        shown(&d.grid_check.max),
        grid_at.join(", ")
    );
    let _ = writeln!(out, "certificate ({} candidate points searched exactly):", d.candidates);
    for line in &d.certificate {
        let _ = writeln!(out, "  - {line}");
    }
    out
}
