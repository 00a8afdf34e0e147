//! A method: a `.zm` program lowered to a linear step program.
//!
//! Lowering checks the semantic rules of the language and turns every
//! assignment into a linear combination
//!
//! $$ \text{target} = \sum_k c_k(\Phi, D, \dots)\,\text{operand}_k $$
//!
//! where an operand is either a state variable as it stood before this step
//! (`Start`, possibly `lag` steps further back for `y@k`) or the value of an
//! earlier assignment of this step (`Stmt`). Coefficients are polynomials in
//! the parameters. This one form is what every interpreter reads: the two
//! exact derivations in `derive.rs`, and the numeric ones in the `check` crate.

use std::collections::{BTreeMap, HashMap};
use std::fmt;

use num_traits::Zero;

use crate::error::{Error, ErrorKind, Span};
use crate::lang::syntax::{self, BinOp, Expr, ExprKind, Item};
use crate::{Poly, Sym};

/// Where a value read by an assignment comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Operand {
    /// State variable `var` as it was `lag` steps before the start of this
    /// step: `lag = 0` is the value the step started from (z⁻¹ in the
    /// z-domain), `y@k` is `lag = k` (z^-(k+1)).
    Start {
        /// Index into [`Method::state`].
        var: usize,
        /// How many steps further back than the start of this step.
        lag: u32,
    },
    /// The value computed by assignment `.0` earlier in this step.
    Stmt(usize),
    /// Unknown `.0` of the step's implicit system ([`Method::unknowns`]): a
    /// primed state `x'` or an `unknown` temporary.
    Unknown(usize),
}

/// An unknown of the implicit system.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unknown {
    /// `x'` for a primed state variable, else the declared name.
    pub name: String,
    /// The state variable whose end-of-step value this is (`x'`), if any.
    pub state: Option<usize>,
}

/// One equation of the implicit system: `unknown = Σ coeff · operand`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Equation {
    /// The unknown it defines, by index into [`Method::unknowns`].
    pub unknown: usize,
    /// Nonzero coefficients per operand; operands may be unknowns.
    pub terms: Vec<(Operand, Poly)>,
    /// The 1-based source line.
    pub line: u32,
    /// The equation as written, without its comment.
    pub text: String,
}

/// An exact algebraic constant `const NAME = sqrt(N)` and its value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Constant {
    /// The name in the program.
    pub name: String,
    /// The radical in normal form (√12 = 2·√3).
    pub radical: crate::multivariate::constants::Radical,
    /// The value as an element of the field spanned by the generators.
    pub value: Poly,
    /// The 1-based source line.
    pub line: u32,
}

/// A read of a state variable that an earlier line of the same step has
/// already updated (a Gauss–Seidel read, as opposed to reading the value the
/// step started from).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GaussSeidelRead {
    /// Where the read is.
    pub line: u32,
    /// Its column.
    pub col: u32,
    /// The state variable read.
    pub name: String,
    /// The line of the assignment whose value it reads.
    pub updated_on: u32,
}

/// Where a state variable's value at the end of the step comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EndValue {
    /// Its last assignment, by index.
    Assign(usize),
    /// Its primed unknown `x'`, by index into [`Method::unknowns`].
    Unknown(usize),
    /// It is neither assigned nor solved for: it keeps its value.
    Kept,
}

/// What an assignment writes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Target {
    /// A state variable, by index into [`Method::state`].
    State(usize),
    /// A temporary, by name.
    Temp(String),
}

/// One lowered assignment: `target = Σ coeff · operand`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Assign {
    /// What is written.
    pub target: Target,
    /// Nonzero coefficients (polynomials in the parameters) per operand.
    pub terms: Vec<(Operand, Poly)>,
    /// The 1-based source line.
    pub line: u32,
    /// The assignment as written, without its comment.
    pub text: String,
}

/// A validated, lowered `.zm` method.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Method {
    name: String,
    state: Vec<String>,
    params: Vec<Sym>,
    assigns: Vec<Assign>,
    history: Vec<u32>,
    /// The last assignment to each state variable, if any.
    finals: Vec<Option<usize>>,
    unknowns: Vec<Unknown>,
    equations: Vec<Equation>,
    constants: Vec<Constant>,
    gauss_seidel: Vec<GaussSeidelRead>,
}

/// The linear value of a sub-expression during lowering.
#[derive(Clone, Default)]
struct Lin {
    scalar: Poly,
    terms: BTreeMap<Operand, Poly>,
}

impl Lin {
    fn scalar(p: Poly) -> Lin {
        Lin { scalar: p, terms: BTreeMap::new() }
    }
    fn operand(op: Operand) -> Lin {
        Lin { scalar: Poly::zero(), terms: BTreeMap::from([(op, Poly::one())]) }
    }
    fn is_scalar(&self) -> bool {
        self.terms.is_empty()
    }
    /// `self + other` (`sign` 1) or `self − other` (`sign` −1), reusing
    /// `other`'s coefficients rather than multiplying them by the sign.
    fn add(mut self, other: Lin, sign: i64) -> Lin {
        let signed = |p: Poly| if sign < 0 { -p } else { p };
        if !other.scalar.is_zero() {
            self.scalar += &signed(other.scalar);
        }
        for (op, c) in other.terms {
            match self.terms.entry(op) {
                std::collections::btree_map::Entry::Vacant(e) => {
                    e.insert(signed(c));
                }
                std::collections::btree_map::Entry::Occupied(mut e) => {
                    *e.get_mut() += &signed(c);
                    if e.get().is_zero() {
                        e.remove();
                    }
                }
            }
        }
        self
    }
    fn scale(self, k: &Poly) -> Lin {
        Lin {
            scalar: &self.scalar * k,
            terms: self
                .terms
                .into_iter()
                .map(|(op, c)| (op, &c * k))
                .filter(|(_, c)| !c.is_zero())
                .collect(),
        }
    }
}

struct Lowerer<'a> {
    state: &'a [String],
    params: &'a [Sym],
    /// Latest assignment index per state variable in this step.
    latest_state: Vec<Option<usize>>,
    /// Latest assignment index per temporary.
    latest_temp: HashMap<String, usize>,
    /// Temporaries holding parameter-only values, folded where read.
    scalar_temps: HashMap<String, Poly>,
    /// Every name that is assigned anywhere, with its first line.
    assigned_anywhere: HashMap<String, u32>,
    history: Vec<u32>,
    /// Constants by name, with their values in the field of the generators.
    consts: HashMap<String, Poly>,
    /// Unknowns by name (`x'` or the declared name).
    unknown_of: HashMap<String, usize>,
    /// Whether any constant exists: coefficients are then reduced.
    reduce: bool,
    /// The line being lowered and the line of every assignment so far.
    line: u32,
    assign_lines: Vec<u32>,
    gauss_seidel: Vec<GaussSeidelRead>,
}

impl Lowerer<'_> {
    fn describe_names(&self) -> String {
        let st = self.state.join(", ");
        let pa: Vec<&str> = self.params.iter().map(|s| s.name()).collect();
        format!(
            "a state variable ({st}), a parameter ({}) or a temporary assigned above",
            pa.join(", ")
        )
    }

    fn lower(&mut self, e: &Expr) -> Result<Lin, Error> {
        match &e.kind {
            ExprKind::Num(q) => Ok(Lin::scalar(Poly::constant(q.clone()))),
            ExprKind::Name(n) => self.name(n, e.span),
            ExprKind::Hist(n, k) => {
                let Some(var) = self.state.iter().position(|s| s == n) else {
                    return Err(Error::new(
                        if self.params.iter().any(|p| p.name() == n) || self.latest_temp.contains_key(n) {
                            ErrorKind::Syntax
                        } else {
                            ErrorKind::UnknownName
                        },
                        e.span,
                        format!("`{n}@{k}` reads history of `{n}`, which is not a state variable: expected `NAME@k` with NAME one of {}", self.state.join(", ")),
                    ));
                };
                self.history[var] = self.history[var].max(*k);
                Ok(Lin::operand(Operand::Start { var, lag: *k }))
            }
            ExprKind::Primed(n) => self.primed(n, e.span),
            ExprKind::Neg(x) => Ok(Lin::default().add(self.lower(x)?, -1)),
            ExprKind::Pow(b, n) => {
                let base = self.lower(b)?;
                if base.is_scalar() {
                    Ok(Lin::scalar(self.fix(base.scalar.pow(*n))))
                } else if *n == 1 {
                    Ok(base)
                } else {
                    Err(Error::new(
                        ErrorKind::Nonlinear,
                        e.span,
                        format!("nonlinear term: a state-dependent value raised to the power {n}; expected the step to be linear in the state"),
                    ))
                }
            }
            ExprKind::Bin(op, l, r) => {
                let (a, b) = (self.lower(l)?, self.lower(r)?);
                match op {
                    BinOp::Add => Ok(a.add(b, 1)),
                    BinOp::Sub => Ok(a.add(b, -1)),
                    BinOp::Mul => {
                        if a.is_scalar() {
                            Ok(self.fix_lin(b.scale(&a.scalar)))
                        } else if b.is_scalar() {
                            Ok(self.fix_lin(a.scale(&b.scalar)))
                        } else {
                            Err(Error::new(
                                ErrorKind::Nonlinear,
                                e.span,
                                "nonlinear term: both factors depend on the state; expected the step to be linear in the state (at most one factor may contain a state variable)",
                            ))
                        }
                    }
                    BinOp::Div => {
                        if !b.is_scalar() {
                            return Err(Error::new(
                                ErrorKind::BadDivision,
                                r.span,
                                "division by a state-dependent value: expected a nonzero constant divisor",
                            ));
                        }
                        let Some(c) = b.scalar.as_constant() else {
                            if crate::multivariate::constants::has_generators(&b.scalar)
                                && b.scalar.symbols().iter().all(|&s| {
                                    crate::multivariate::constants::generator_of(s).is_some()
                                })
                            {
                                // A nonzero constant of the field: exact inverse.
                                let inv = crate::multivariate::constants::inverse(&b.scalar)
                                    .expect("a nonzero field element");
                                return Ok(self.fix_lin(a.scale(&inv)));
                            }
                            let names: Vec<&str> =
                                b.scalar.symbols().iter().map(|s| s.name()).collect();
                            return Err(Error::new(
                                ErrorKind::BadDivision,
                                r.span,
                                format!("division by the parameter expression in {}: expected a nonzero constant divisor", names.join(", ")),
                            ));
                        };
                        if c.is_zero() {
                            return Err(Error::new(
                                ErrorKind::BadDivision,
                                r.span,
                                "division by zero: expected a nonzero constant divisor",
                            ));
                        }
                        Ok(a.scale(&Poly::constant(crate::Q::from_integer(1.into()) / c)))
                    }
                }
            }
        }
    }

    /// `p` reduced modulo the constants' minimal polynomials, when any.
    fn fix(&self, p: Poly) -> Poly {
        if self.reduce {
            crate::multivariate::constants::reduce(&p)
        } else {
            p
        }
    }

    fn fix_lin(&self, l: Lin) -> Lin {
        if !self.reduce {
            return l;
        }
        Lin {
            scalar: crate::multivariate::constants::reduce(&l.scalar),
            terms: l
                .terms
                .into_iter()
                .map(|(op, c)| (op, crate::multivariate::constants::reduce(&c)))
                .filter(|(_, c)| !c.is_zero())
                .collect(),
        }
    }

    fn primed(&mut self, n: &str, span: Span) -> Result<Lin, Error> {
        let key = format!("{n}'");
        if let Some(&u) = self.unknown_of.get(&key) {
            return Ok(Lin::operand(Operand::Unknown(u)));
        }
        if self.state.iter().any(|s| s == n) {
            return Err(Error::new(
                ErrorKind::Equation,
                span,
                format!("`{n}'` is read but `{n}` has no equation: expected a line `{n}' = ...` defining its end-of-step value"),
            ));
        }
        let what = if self.params.iter().any(|p| p.name() == n) {
            "a parameter"
        } else if self.consts.contains_key(n) {
            "a constant"
        } else if self.unknown_of.contains_key(n) {
            "an unknown (it is already the solution; read it as `NAME`)"
        } else if self.assigned_anywhere.contains_key(n) {
            "a temporary"
        } else {
            return Err(Error::new(
                ErrorKind::UnknownName,
                span,
                format!(
                    "unknown name `{n}'`: expected a primed state variable ({})",
                    self.state.join(", ")
                ),
            ));
        };
        Err(Error::new(
            ErrorKind::BadPrime,
            span,
            format!(
                "`{n}'` primes {what}: expected a prime only on a state variable ({})",
                self.state.join(", ")
            ),
        ))
    }

    fn name(&mut self, n: &str, span: Span) -> Result<Lin, Error> {
        if let Some(&p) = self.params.iter().find(|p| p.name() == n) {
            return Ok(Lin::scalar(Poly::sym(p)));
        }
        if let Some(c) = self.consts.get(n) {
            return Ok(Lin::scalar(c.clone()));
        }
        if let Some(var) = self.state.iter().position(|s| s == n) {
            return Ok(Lin::operand(match self.latest_state[var] {
                Some(t) => {
                    self.gauss_seidel.push(GaussSeidelRead {
                        line: self.line,
                        col: span.col,
                        name: n.to_owned(),
                        updated_on: self.assign_lines[t],
                    });
                    Operand::Stmt(t)
                }
                None => Operand::Start { var, lag: 0 },
            }));
        }
        if let Some(&u) = self.unknown_of.get(n) {
            return Ok(Lin::operand(Operand::Unknown(u)));
        }
        if let Some(p) = self.scalar_temps.get(n) {
            return Ok(Lin::scalar(p.clone()));
        }
        if let Some(&t) = self.latest_temp.get(n) {
            return Ok(Lin::operand(Operand::Stmt(t)));
        }
        if let Some(line) = self.assigned_anywhere.get(n) {
            return Err(Error::new(
                ErrorKind::ReadBeforeAssign,
                span,
                format!("temporary `{n}` is read before it is assigned (first assigned on line {line}): expected an assignment to `{n}` on an earlier line"),
            ));
        }
        Err(Error::new(
            ErrorKind::UnknownName,
            span,
            format!("unknown name `{n}`: expected {}", self.describe_names()),
        ))
    }
}

enum ItemKind {
    State,
    Unknown,
    Other,
}

fn check_new_name(declared: &HashMap<String, Span>, n: &str, s: Span) -> Result<(), Error> {
    if n == "Phi" {
        return Err(decl_err(s, "`Phi` is always a parameter: expected it not to be declared"));
    }
    if n == "z" {
        return Err(decl_err(
            s,
            "`z` is reserved for the z-transform variable: expected another name",
        ));
    }
    if let Some(prev) = declared.get(n) {
        return Err(decl_err(
            s,
            format!(
                "`{n}` is declared twice (first on line {}): expected distinct names",
                prev.line
            ),
        ));
    }
    Ok(())
}

fn affine_err(lin: &Lin, span: Span) -> Error {
    Error::new(
        ErrorKind::Affine,
        span,
        format!("term `{}` does not depend on the state: expected every term to be a multiple of a state variable (the step must be linear)", lin.scalar),
    )
}

/// The radical a `const` line defines, or a located error.
fn radical_of(
    func: &str,
    args: &[(crate::Q, Span)],
    call: Span,
) -> Result<crate::multivariate::constants::Radical, Error> {
    let bad = |s: Span, what: &str| {
        Error::new(ErrorKind::BadConstant, s, format!("{what}: expected `sqrt(N)`, `cbrt(N)` or `root(K, N)` with N a positive integer (at most {}) and K an integer from 2 to 64", crate::multivariate::constants::MAX_RADICAND))
    };
    let (k, n) = match (func, args) {
        ("sqrt", [n]) => (2, n),
        ("cbrt", [n]) => (3, n),
        ("root", [(k, ks), n]) => {
            let k = crate::multivariate::constants::radicand(k)
                .filter(|&k| (2..=64).contains(&k))
                .ok_or_else(|| bad(*ks, &format!("root index {k}")))?;
            (k as u32, n)
        }
        _ => return Err(bad(call, &format!("`{func}` with {} argument(s)", args.len()))),
    };
    let value = crate::multivariate::constants::radicand(&n.0)
        .ok_or_else(|| bad(n.1, &format!("{} is not a positive integer", n.0)))?;
    Ok(crate::multivariate::constants::Radical::root(k, value))
}

fn decl_err(span: Span, msg: impl Into<String>) -> Error {
    Error::new(ErrorKind::Declaration, span, msg)
}

impl Method {
    /// Lowers a `.zm` program (no location added to errors, no check of
    /// the implicit system: [`Method::parse`] does both).
    pub(crate) fn lower(src: &str) -> Result<Method, Error> {
        let items = syntax::parse(src)?;
        let mut name: Option<String> = None;
        let mut state: Option<Vec<String>> = None;
        let mut params = vec![Sym::phi()];
        let mut declared: HashMap<String, Span> = HashMap::new();
        declared.insert("Phi".into(), Span::default());
        let mut assigns_src = Vec::new();
        let mut declared_unknowns: Vec<(String, Span)> = Vec::new();
        let mut const_src: Vec<(String, Span, crate::multivariate::constants::Radical)> =
            Vec::new();
        for item in items {
            let item_kind = match item {
                Item::State(..) => ItemKind::State,
                Item::Unknown(..) => ItemKind::Unknown,
                _ => ItemKind::Other,
            };
            match item {
                Item::Method(n, span) => {
                    if name.is_some() {
                        return Err(decl_err(span, "a second `method` line: expected exactly one"));
                    }
                    if !assigns_src.is_empty() || state.is_some() {
                        return Err(decl_err(
                            span,
                            "`method` comes after other lines: expected it first",
                        ));
                    }
                    name = Some(n);
                }
                Item::Const { name: n, span, func, args, call_span } => {
                    if name.is_none() {
                        return Err(decl_err(
                            span,
                            "missing `method NAME` line: expected it before `const`",
                        ));
                    }
                    if !assigns_src.is_empty() {
                        return Err(decl_err(span, "declaration after an assignment: expected `const` lines before the first assignment"));
                    }
                    check_new_name(&declared, &n, span)?;
                    declared.insert(n.clone(), span);
                    let radical = radical_of(&func, &args, call_span)?;
                    const_src.push((n, span, radical));
                }
                Item::State(names, span)
                | Item::Param(names, span)
                | Item::Unknown(names, span) => {
                    if name.is_none() {
                        return Err(decl_err(
                            span,
                            "missing `method NAME` line: expected it before `state` and `param`",
                        ));
                    }
                    if !assigns_src.is_empty() {
                        return Err(decl_err(span, "declaration after an assignment: expected `state`, `param`, `unknown` and `const` lines before the first assignment"));
                    }
                    let is_state = matches!(item_kind, ItemKind::State);
                    if is_state && state.is_some() {
                        return Err(decl_err(span, "a second `state` line: expected exactly one, listing every state variable"));
                    }
                    let mut vars = Vec::new();
                    for (n, s) in names {
                        check_new_name(&declared, &n, s)?;
                        declared.insert(n.clone(), s);
                        vars.push((n, s));
                    }
                    match item_kind {
                        ItemKind::State => state = Some(vars.into_iter().map(|(n, _)| n).collect()),
                        ItemKind::Unknown => declared_unknowns.extend(vars),
                        ItemKind::Other => params.extend(vars.iter().map(|(n, _)| Sym::new(n))),
                    }
                }
                Item::Assign { target, target_span, expr, line_text, primed } => {
                    if name.is_none() {
                        return Err(decl_err(
                            target_span,
                            "missing `method NAME` line: expected it before the first assignment",
                        ));
                    }
                    if state.is_none() {
                        return Err(decl_err(target_span, "missing `state` line: expected `state NAME...` before the first assignment"));
                    }
                    assigns_src.push((target, target_span, expr, line_text, primed));
                }
            }
        }
        let eof = Span { line: src.lines().count().max(1) as u32, col: 1, len: 1 };
        let name = name.ok_or_else(|| {
            decl_err(eof, "missing `method NAME` line: expected one naming the method")
        })?;
        let state = state.ok_or_else(|| {
            decl_err(
                eof,
                "missing `state` line: expected `state NAME...` listing the state variables",
            )
        })?;

        // Constants: one generator per prime, with the index every constant
        // of this program needs.
        let index =
            crate::multivariate::constants::generator_indices(const_src.iter().map(|(_, _, r)| r));
        let constants: Vec<Constant> = const_src
            .iter()
            .map(|(n, s, r)| Constant {
                name: n.clone(),
                radical: r.clone(),
                value: r.to_poly(&index),
                line: s.line,
            })
            .collect();

        let mut assigned_anywhere = HashMap::new();
        // Unknowns: the primed state variables that have an equation, in
        // state order, then the declared ones.
        let mut primed_vars = vec![false; state.len()];
        for (t, s, _, _, primed) in &assigns_src {
            if *primed {
                match state.iter().position(|v| v == t) {
                    Some(v) => primed_vars[v] = true,
                    None => {
                        let what = if params.iter().any(|p| p.name() == t) {
                            Some("a parameter")
                        } else if const_src.iter().any(|(n, _, _)| n == t) {
                            Some("a constant")
                        } else if declared_unknowns.iter().any(|(n, _)| n == t) {
                            Some("an unknown (write its equation as `NAME = ...`)")
                        } else if assigns_src.iter().any(|(n, _, _, _, p)| n == t && !p) {
                            Some("a temporary")
                        } else {
                            None
                        };
                        return Err(match what {
                            Some(w) => Error::new(ErrorKind::BadPrime, *s, format!("`{t}'` primes {w}: expected an equation `x' = ...` only for a state variable ({})", state.join(", "))),
                            None => Error::new(ErrorKind::Equation, *s, format!("equation for `{t}'`, but `{t}` is not declared: expected a state variable ({}) or `unknown {t}` with an equation `{t} = ...`", state.join(", "))),
                        });
                    }
                }
                continue;
            }
            if params.iter().any(|p| p.name() == t) {
                return Err(decl_err(*s, format!("`{t}` is a parameter and cannot be assigned: expected a state variable or a temporary")));
            }
            if const_src.iter().any(|(n, _, _)| n == t) {
                return Err(decl_err(*s, format!("`{t}` is a constant and cannot be assigned: expected a state variable or a temporary")));
            }
            if t == "z" {
                return Err(decl_err(
                    *s,
                    "`z` is reserved for the z-transform variable: expected another name",
                ));
            }
            assigned_anywhere.entry(t.clone()).or_insert(s.line);
        }
        let mut unknowns: Vec<Unknown> = Vec::new();
        for (v, _) in primed_vars.iter().enumerate().filter(|(_, p)| **p) {
            unknowns.push(Unknown { name: format!("{}'", state[v]), state: Some(v) });
        }
        for (n, _) in &declared_unknowns {
            unknowns.push(Unknown { name: n.clone(), state: None });
        }
        let unknown_of: HashMap<String, usize> =
            unknowns.iter().enumerate().map(|(i, u)| (u.name.clone(), i)).collect();
        let mut lw = Lowerer {
            state: &state,
            params: &params,
            latest_state: vec![None; state.len()],
            latest_temp: HashMap::new(),
            scalar_temps: HashMap::new(),
            assigned_anywhere,
            history: vec![0; state.len()],
            consts: constants.iter().map(|c| (c.name.clone(), c.value.clone())).collect(),
            unknown_of,
            reduce: !constants.is_empty(),
            line: 0,
            assign_lines: Vec::new(),
            gauss_seidel: Vec::new(),
        };
        let state_index: HashMap<&str, usize> =
            state.iter().enumerate().map(|(k, s)| (s.as_str(), k)).collect();
        let mut assigns = Vec::new();
        let mut equations: Vec<Option<Equation>> = vec![None; unknowns.len()];
        // The line of each state variable's equation, once seen.
        let mut solved_on: Vec<Option<u32>> = vec![None; state.len()];
        for (t, tspan, expr, text, primed) in assigns_src {
            lw.line = tspan.line;
            let lin = lw.lower(&expr)?;
            let lin = lw.fix_lin(lin);
            let state_index = state_index.get(t.as_str()).copied();
            let is_state = state_index.is_some();
            let unknown = if primed {
                lw.unknown_of.get(&format!("{t}'")).copied()
            } else if is_state {
                None
            } else {
                lw.unknown_of.get(&t).copied()
            };
            if let Some(u) = unknown {
                if !lin.scalar.is_zero() {
                    return Err(affine_err(&lin, expr.span));
                }
                if let Some(prev) = &equations[u] {
                    return Err(Error::new(ErrorKind::Equation, tspan, format!("a second equation for `{}` (the first is on line {}): expected exactly one", unknowns[u].name, prev.line)));
                }
                if let Some(v) = unknowns[u].state {
                    solved_on[v] = Some(tspan.line);
                }
                equations[u] = Some(Equation {
                    unknown: u,
                    terms: lin.terms.into_iter().collect(),
                    line: tspan.line,
                    text,
                });
                continue;
            }
            if let Some(v) = state_index {
                if let Some(l) = solved_on[v] {
                    return Err(Error::new(ErrorKind::Equation, tspan, format!("`{t}` is assigned after its equation `{t}' = ...` on line {l}: expected every assignment to `{t}` before its equation (the equation's solution ends the step)")));
                }
            }
            if !is_state && lin.is_scalar() {
                // A temporary that depends on the parameters only (Appendix B's
                // `D:=0.5*woT`) is folded into the coefficients that read it.
                lw.latest_temp.remove(&t);
                lw.scalar_temps.insert(t, lin.scalar);
                continue;
            }
            let idx = assigns.len();
            if !lin.scalar.is_zero() {
                return Err(affine_err(&lin, expr.span));
            }
            let target = match state_index {
                Some(v) => {
                    lw.latest_state[v] = Some(idx);
                    Target::State(v)
                }
                None => {
                    lw.scalar_temps.remove(&t);
                    lw.latest_temp.insert(t.clone(), idx);
                    Target::Temp(t)
                }
            };
            lw.assign_lines.push(tspan.line);
            assigns.push(Assign {
                target,
                terms: lin.terms.into_iter().collect(),
                line: tspan.line,
                text,
            });
        }
        let n_primed = unknowns.iter().filter(|u| u.state.is_some()).count();
        let equations: Vec<Equation> = equations
            .into_iter()
            .enumerate()
            .map(|(u, e)| {
                e.ok_or_else(|| {
                    let (n, s) = &declared_unknowns[u - n_primed];
                    Error::new(
                        ErrorKind::Equation,
                        *s,
                        format!("unknown `{n}` has no equation: expected one line `{n} = ...`"),
                    )
                })
            })
            .collect::<Result<_, _>>()?;
        let history = lw.history;
        let finals = lw.latest_state;
        let gauss_seidel = lw.gauss_seidel;
        let m = Method {
            name,
            state,
            params,
            assigns,
            history,
            unknowns,
            equations,
            constants,
            gauss_seidel,
            finals,
        };
        Ok(m)
    }

    /// The error for an implicit system singular for every Φ, located on
    /// the first equation.
    pub(crate) fn singular_error(&self) -> Error {
        let line = self.equations.iter().map(|e| e.line).min().unwrap_or(1);
        Error::new(
            ErrorKind::Singular,
            Span { line, col: 1, len: 1 },
            format!("the implicit system in {} is singular for every Phi: its determinant det(I - d(right-hand sides)/d(unknowns)) is 0; expected equations that determine every unknown", self.unknowns.iter().map(|u| u.name.as_str()).collect::<Vec<_>>().join(", ")),
        )
    }

    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The state variables, in declaration order.
    pub fn state(&self) -> &[String] {
        &self.state
    }

    /// The parameters: `Phi` first, then those declared by `param`.
    pub fn params(&self) -> &[Sym] {
        &self.params
    }

    /// The lowered assignments, in program order.
    pub fn assigns(&self) -> &[Assign] {
        &self.assigns
    }

    /// The deepest history read per state variable (0 when only the start
    /// value is read).
    pub fn history(&self) -> &[u32] {
        &self.history
    }

    /// The order `N = Σ (1 + history)`: the size of the transition matrix and
    /// the degree of the characteristic polynomial.
    pub fn order(&self) -> usize {
        self.history.iter().map(|&h| 1 + h as usize).sum()
    }

    /// The slots of the augmented state, in transition-matrix order: each
    /// state variable at lag 0, 1, ..., its history depth.
    pub fn slots(&self) -> Vec<(usize, u32)> {
        let mut v = Vec::new();
        for (var, &h) in self.history.iter().enumerate() {
            for lag in 0..=h {
                v.push((var, lag));
            }
        }
        v
    }

    /// The index of the last assignment to state variable `var`, if any.
    /// A variable with an equation `x' = ...` ends the step with its
    /// unknown instead: see [`Method::end_value`].
    pub fn final_assign(&self, var: usize) -> Option<usize> {
        self.finals[var]
    }

    /// Where state variable `var`'s end-of-step value comes from.
    pub fn end_value(&self, var: usize) -> EndValue {
        if let Some(u) = self.unknowns.iter().position(|u| u.state == Some(var)) {
            return EndValue::Unknown(u);
        }
        match self.final_assign(var) {
            Some(k) => EndValue::Assign(k),
            None => EndValue::Kept,
        }
    }

    /// The unknowns of the implicit system: primed state variables (in state
    /// order), then declared `unknown`s. Empty for an explicit method.
    pub fn unknowns(&self) -> &[Unknown] {
        &self.unknowns
    }

    /// The equations, one per unknown, in [`Method::unknowns`] order.
    pub fn equations(&self) -> &[Equation] {
        &self.equations
    }

    /// Whether the step solves a linear system (it has unknowns).
    pub fn is_implicit(&self) -> bool {
        !self.unknowns.is_empty()
    }

    /// The exact constants declared with `const`.
    pub fn constants(&self) -> &[Constant] {
        &self.constants
    }

    /// Every read of a state variable that an earlier line of the same step
    /// has already updated, in program order.
    pub fn gauss_seidel_reads(&self) -> &[GaussSeidelRead] {
        &self.gauss_seidel
    }

    /// The name an assignment writes.
    pub fn target_name<'a>(&'a self, a: &'a Assign) -> &'a str {
        match &a.target {
            Target::State(v) => &self.state[*v],
            Target::Temp(n) => n,
        }
    }

    /// An operand written as the lowered listing shows it: `v`, `y@1`, `%0`.
    pub fn operand_name(&self, op: Operand) -> String {
        match op {
            Operand::Start { var, lag: 0 } => self.state[var].clone(),
            Operand::Start { var, lag } => format!("{}@{lag}", self.state[var]),
            Operand::Stmt(t) => format!("%{t}"),
            Operand::Unknown(u) => self.unknowns[u].name.clone(),
        }
    }
}

impl fmt::Display for Method {
    /// The lowered program in SSA style: one line per assignment,
    /// `%k (name) = c*operand + ...`, where `%k` is the value of assignment k
    /// of this step and a bare state name is its value at the start of the
    /// step.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "method {}", self.name)?;
        writeln!(f, "state {}", self.state.join(" "))?;
        let ps: Vec<&str> = self.params.iter().map(|p| p.name()).collect();
        writeln!(f, "param {}", ps.join(" "))?;
        if !self.constants.is_empty() {
            for c in &self.constants {
                let (k, n) = c.radical.minimal_polynomial();
                writeln!(f, "const {} = {} (minimal polynomial x^{k} - {n})", c.name, c.value)?;
            }
        }
        if !self.unknowns.is_empty() {
            let us: Vec<&str> = self.unknowns.iter().map(|u| u.name.as_str()).collect();
            writeln!(f, "unknown {}", us.join(" "))?;
        }
        let lines = self
            .assigns
            .iter()
            .enumerate()
            .map(|(k, a)| (a.line, format!("%{k} ({})", self.target_name(a)), &a.terms))
            .chain(
                self.equations
                    .iter()
                    .map(|e| (e.line, format!("{} =", self.unknowns[e.unknown].name), &e.terms)),
            );
        let mut lines: Vec<_> = lines.collect();
        lines.sort_by_key(|l| l.0);
        for (_, head, terms) in lines {
            let mut rhs = String::new();
            for (i, (op, c)) in terms.iter().enumerate() {
                // A one-term negative coefficient prints as a subtraction.
                let neg = c.len() == 1 && c.terms().all(|(_, q)| q < &crate::Q::zero());
                let body = if neg { -c } else { c.clone() };
                rhs += match (i, neg) {
                    (0, true) => "-",
                    (0, false) => "",
                    (_, true) => " - ",
                    (_, false) => " + ",
                };
                let o = self.operand_name(*op);
                rhs += &if body.is_one() {
                    o
                } else if body.len() == 1 {
                    format!("{body}*{o}")
                } else {
                    format!("({body})*{o}")
                };
            }
            if rhs.is_empty() {
                rhs.push('0');
            }
            match head.strip_suffix(" =") {
                Some(u) => writeln!(f, "{u} = {rhs}")?,
                None => writeln!(f, "{head} = {rhs}")?,
            }
        }
        Ok(())
    }
}
