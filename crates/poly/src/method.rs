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
use crate::syntax::{self, BinOp, Expr, ExprKind, Item};
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
            ExprKind::Neg(x) => Ok(Lin::default().add(self.lower(x)?, -1)),
            ExprKind::Pow(b, n) => {
                let base = self.lower(b)?;
                if base.is_scalar() {
                    Ok(Lin::scalar(base.scalar.pow(*n)))
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
                            Ok(b.scale(&a.scalar))
                        } else if b.is_scalar() {
                            Ok(a.scale(&b.scalar))
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

    fn name(&mut self, n: &str, span: Span) -> Result<Lin, Error> {
        if let Some(&p) = self.params.iter().find(|p| p.name() == n) {
            return Ok(Lin::scalar(Poly::sym(p)));
        }
        if let Some(var) = self.state.iter().position(|s| s == n) {
            return Ok(Lin::operand(match self.latest_state[var] {
                Some(t) => Operand::Stmt(t),
                None => Operand::Start { var, lag: 0 },
            }));
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
    Other,
}

fn decl_err(span: Span, msg: impl Into<String>) -> Error {
    Error::new(ErrorKind::Declaration, span, msg)
}

impl Method {
    /// Parses and lowers a `.zm` program. `file` names the source in errors.
    ///
    /// ```
    /// let m = poly::Method::parse("fe.zm", "method fe\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n")?;
    /// assert_eq!(m.state(), ["v", "y"]);
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn parse(file: &str, src: &str) -> Result<Method, Error> {
        // A byte-order mark some editors put first is not part of the text.
        let src = src.strip_prefix('\u{FEFF}').unwrap_or(src);
        Method::parse_inner(src).map_err(|e| e.located(file, src))
    }

    /// [`Method::parse`] on raw bytes: bytes that are not UTF-8 are an
    /// [`ErrorKind::Encoding`](crate::ErrorKind::Encoding) error located at
    /// the first bad byte's line and column.
    pub fn parse_bytes(file: &str, bytes: &[u8]) -> Result<Method, Error> {
        match std::str::from_utf8(bytes) {
            Ok(src) => Method::parse(file, src),
            Err(e) => Err(Error::not_utf8(file, bytes, e)),
        }
    }

    fn parse_inner(src: &str) -> Result<Method, Error> {
        let items = syntax::parse(src)?;
        let mut name: Option<String> = None;
        let mut state: Option<Vec<String>> = None;
        let mut params = vec![Sym::phi()];
        let mut declared: HashMap<String, Span> = HashMap::new();
        declared.insert("Phi".into(), Span::default());
        let mut assigns_src = Vec::new();
        for item in items {
            let item_kind = match item {
                Item::State(..) => ItemKind::State,
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
                Item::State(names, span) | Item::Param(names, span) => {
                    let is_state = matches!(item_kind, ItemKind::State);
                    if name.is_none() {
                        return Err(decl_err(
                            span,
                            "missing `method NAME` line: expected it before `state` and `param`",
                        ));
                    }
                    if !assigns_src.is_empty() {
                        return Err(decl_err(span, "declaration after an assignment: expected `state` and `param` lines before the first assignment"));
                    }
                    if is_state && state.is_some() {
                        return Err(decl_err(span, "a second `state` line: expected exactly one, listing every state variable"));
                    }
                    let mut vars = Vec::new();
                    for (n, s) in names {
                        if n == "Phi" {
                            return Err(decl_err(
                                s,
                                "`Phi` is always a parameter: expected it not to be declared",
                            ));
                        }
                        if n == "z" {
                            return Err(decl_err(s, "`z` is reserved for the z-transform variable: expected another name"));
                        }
                        if let Some(prev) = declared.get(&n) {
                            return Err(decl_err(s, format!("`{n}` is declared twice (first on line {}): expected distinct names", prev.line)));
                        }
                        declared.insert(n.clone(), s);
                        vars.push(n);
                    }
                    if is_state {
                        state = Some(vars);
                    } else {
                        params.extend(vars.iter().map(|n| Sym::new(n)));
                    }
                }
                Item::Assign { target, target_span, expr, line_text } => {
                    if name.is_none() {
                        return Err(decl_err(
                            target_span,
                            "missing `method NAME` line: expected it before the first assignment",
                        ));
                    }
                    if state.is_none() {
                        return Err(decl_err(target_span, "missing `state` line: expected `state NAME...` before the first assignment"));
                    }
                    assigns_src.push((target, target_span, expr, line_text));
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

        let mut assigned_anywhere = HashMap::new();
        for (t, s, _, _) in &assigns_src {
            if params.iter().any(|p| p.name() == t) {
                return Err(decl_err(*s, format!("`{t}` is a parameter and cannot be assigned: expected a state variable or a temporary")));
            }
            if t == "z" {
                return Err(decl_err(
                    *s,
                    "`z` is reserved for the z-transform variable: expected another name",
                ));
            }
            assigned_anywhere.entry(t.clone()).or_insert(s.line);
        }
        let mut lw = Lowerer {
            state: &state,
            params: &params,
            latest_state: vec![None; state.len()],
            latest_temp: HashMap::new(),
            scalar_temps: HashMap::new(),
            assigned_anywhere,
            history: vec![0; state.len()],
        };
        let state_index: HashMap<&str, usize> =
            state.iter().enumerate().map(|(k, s)| (s.as_str(), k)).collect();
        let mut assigns = Vec::new();
        for (t, tspan, expr, text) in assigns_src {
            let lin = lw.lower(&expr)?;
            let state_index = state_index.get(t.as_str()).copied();
            let is_state = state_index.is_some();
            if !is_state && lin.is_scalar() {
                // A temporary that depends on the parameters only (Appendix B's
                // `D:=0.5*woT`) is folded into the coefficients that read it.
                lw.latest_temp.remove(&t);
                lw.scalar_temps.insert(t, lin.scalar);
                continue;
            }
            let idx = assigns.len();
            if !lin.scalar.is_zero() {
                return Err(Error::new(
                    ErrorKind::Affine,
                    expr.span,
                    format!("term `{}` does not depend on the state: expected every term to be a multiple of a state variable (the step must be linear)", lin.scalar),
                ));
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
            assigns.push(Assign {
                target,
                terms: lin.terms.into_iter().collect(),
                line: tspan.line,
                text,
            });
        }
        let history = lw.history;
        let finals = lw.latest_state;
        Ok(Method { name, state, params, assigns, history, finals })
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
    pub fn final_assign(&self, var: usize) -> Option<usize> {
        self.finals[var]
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
        for (k, a) in self.assigns.iter().enumerate() {
            let mut rhs = String::new();
            for (i, (op, c)) in a.terms.iter().enumerate() {
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
            writeln!(f, "%{k} ({}) = {rhs}", self.target_name(a))?;
        }
        Ok(())
    }
}
