//! Lowering: a parsed `.zm` program to a [`Method`].
//!
//! Lowering checks the semantic rules of the language and turns every
//! assignment into a linear combination
//!
//! $$ \text{target} = \sum_k c_k(\Phi, D, \dots)\,\text{operand}_k $$
//!
//! where an operand is a state variable as it stood before this step
//! (`Start`, possibly `lag` steps further back for `y@k`), the value of an
//! earlier assignment of this step (`Stmt`), or an unknown of the step's
//! implicit system. Coefficients are polynomials in the parameters.
//!
//! It reads the program twice. The first pass collects the declarations
//! (`state`, `param`, `unknown`, `const`), wherever they stand: a name may
//! be declared anywhere before its first use. The second lowers the lines
//! in order.
//!
//! **Equations.** A line `x' = r` or `k = r` (for an `unknown k`) defines
//! its unknown u as `u = r(s, u)`, with unknowns allowed on the right. Any
//! other line `lhs = rhs` is an equation `L = lhs − rhs = 0`, linear in the
//! unknowns, with unknowns on either side. Such an equation is stored in
//! the same form, `u = u − L`, for an unknown u that no line defines: the
//! k-th such equation in the file takes the k-th such unknown by name. Its
//! row of the system A u = E s is then ∂L/∂u whichever unknown it takes,
//! and the system is solved exactly as one written with `u = ...` lines.
//! Which row it fills only decides the sign of det A (the leading
//! coefficient of χ); taking the unknowns by name, not in declaration
//! order, keeps χ the same when declarations are reordered.

use std::collections::{BTreeMap, HashMap};

use num_traits::Zero;

use crate::error::{Error, ErrorKind, Span, Warning};
use crate::lang::constant::{self, use_before_declaration, ConstSource};
use crate::lang::method::{
    Assign, Body, Equation, GaussSeidelRead, Lowered, Method, Operand, Target, Unknown,
};
use crate::lang::syntax::{self, BinOp, Expr, ExprKind, Item};
use crate::multivariate::constants as field;
use crate::{Poly, Sym};

/// Parses and lowers `src` (no location added to errors, no check of the
/// implicit system: [`Method::parse`] does both).
pub(crate) fn lower(src: &str) -> Result<Method, Error> {
    let items = syntax::parse(src)?;
    let program = Program::read(items, src)?;
    program.lower()
}

/// A line that computes: an assignment (or a `NAME = ...` equation) or an
/// equation with any other left side.
enum Statement {
    Assign { target: String, target_span: Span, expr: Expr, text: String, primed: bool },
    Equation { lhs: Expr, rhs: Expr, text: String },
}

/// The program after the first pass: every declaration, and the lines
/// that compute, in order.
struct Program {
    name: String,
    state: Vec<String>,
    /// `Phi` first, then the declared parameters.
    params: Vec<Sym>,
    declared_unknowns: Vec<(String, Span)>,
    consts: Vec<ConstSource>,
    /// Where each declared name is declared (`Phi` on line 0).
    declared: HashMap<String, Span>,
    statements: Vec<Statement>,
}

fn decl_err(span: Span, msg: impl Into<String>) -> Error {
    Error::new(ErrorKind::Declaration, span, msg)
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

impl Program {
    /// The first pass: the `method` line first, then declarations and
    /// lines in any order.
    fn read(items: Vec<Item>, src: &str) -> Result<Program, Error> {
        let mut name: Option<String> = None;
        let mut state: Option<Vec<String>> = None;
        let mut params = vec![Sym::phi()];
        let mut declared: HashMap<String, Span> = HashMap::new();
        declared.insert("Phi".into(), Span::default());
        let mut declared_unknowns = Vec::new();
        let mut consts = Vec::new();
        let mut statements = Vec::new();
        for item in items {
            if let Item::Method(n, span) = item {
                if name.is_some() {
                    return Err(decl_err(span, "a second `method` line: expected exactly one"));
                }
                name = Some(n);
                continue;
            }
            if name.is_none() {
                let (span, before) = match &item {
                    Item::Const { span, .. } => (*span, "`const`"),
                    Item::State(_, span) | Item::Param(_, span) | Item::Unknown(_, span) => {
                        (*span, "`state` and `param`")
                    }
                    Item::Assign { target_span, .. } => (*target_span, "the first assignment"),
                    Item::Equation { lhs, .. } => (lhs.span, "the first equation"),
                    Item::Method(..) => unreachable!("handled above"),
                };
                return Err(decl_err(
                    span,
                    format!("missing `method NAME` line: expected it before {before}"),
                ));
            }
            match item {
                Item::Method(..) => unreachable!("handled above"),
                Item::Const { name: n, span, expr } => {
                    check_new_name(&declared, &n, span)?;
                    declared.insert(n.clone(), span);
                    consts.push((n, span, expr));
                }
                Item::State(names, span) => {
                    if state.is_some() {
                        return Err(decl_err(span, "a second `state` line: expected exactly one, listing every state variable"));
                    }
                    for (n, s) in &names {
                        check_new_name(&declared, n, *s)?;
                        declared.insert(n.clone(), *s);
                    }
                    state = Some(names.into_iter().map(|(n, _)| n).collect());
                }
                Item::Param(names, _) => {
                    for (n, s) in names {
                        check_new_name(&declared, &n, s)?;
                        declared.insert(n.clone(), s);
                        params.push(Sym::new(&n));
                    }
                }
                Item::Unknown(names, _) => {
                    for (n, s) in names {
                        check_new_name(&declared, &n, s)?;
                        declared.insert(n.clone(), s);
                        declared_unknowns.push((n, s));
                    }
                }
                Item::Assign { target, target_span, expr, line_text, primed } => {
                    statements.push(Statement::Assign {
                        target,
                        target_span,
                        expr,
                        text: line_text,
                        primed,
                    });
                }
                Item::Equation { lhs, rhs, line_text } => {
                    statements.push(Statement::Equation { lhs, rhs, text: line_text });
                }
            }
        }
        let eof = Span { line: src.lines().count().max(1) as u32, col: 1, len: 1 };
        // The `method` line belongs first: a file without one (the empty
        // file, one of comments only) is reported at 1:1.
        let name = name.ok_or_else(|| {
            decl_err(
                Span { line: 1, col: 1, len: 1 },
                "missing `method NAME` line: expected one naming the method",
            )
        })?;
        let Some(state) = state else {
            return Err(match statements.first() {
                Some(st) => decl_err(
                    st.span(),
                    "missing `state` line: expected `state NAME...` before the first assignment",
                ),
                None => decl_err(
                    eof,
                    "missing `state` line: expected `state NAME...` listing the state variables",
                ),
            });
        };
        Ok(Program { name, state, params, declared_unknowns, consts, declared, statements })
    }

    /// What a declared name other than a constant is, for messages.
    fn what(&self, n: &str) -> Option<&'static str> {
        if self.state.iter().any(|s| s == n) {
            Some("a state variable")
        } else if self.params.iter().any(|p| p.name() == n) {
            Some("a parameter")
        } else if self.declared_unknowns.iter().any(|(u, _)| u == n) {
            Some("an unknown")
        } else if self.statements.iter().any(|st| st.target() == Some(n)) {
            Some("a temporary")
        } else {
            None
        }
    }

    /// The second pass.
    fn lower(self) -> Result<Method, Error> {
        let constants = constant::evaluate(&self.consts, &self.declared, |n| self.what(n))?;
        let state = &self.state;
        let params = &self.params;
        let state_index: HashMap<&str, usize> =
            state.iter().enumerate().map(|(k, s)| (s.as_str(), k)).collect();
        let const_names: std::collections::HashSet<&str> =
            self.consts.iter().map(|(n, _, _)| n.as_str()).collect();
        let is_const = |t: &str| const_names.contains(t);
        let mut assigned_anywhere = HashMap::new();
        // Each state variable's first primed occurrence in an equation: the
        // primed variables there are the unknowns `x'`.
        let mut first_primed: Vec<Option<Span>> = vec![None; state.len()];
        for st in &self.statements {
            let (t, s, primed) = match st {
                Statement::Assign { target, target_span, primed, .. } => {
                    (target, *target_span, *primed)
                }
                Statement::Equation { lhs, rhs, .. } => {
                    primed_in(lhs, &state_index, &mut first_primed);
                    primed_in(rhs, &state_index, &mut first_primed);
                    continue;
                }
            };
            if let Some(d) = self.declared.get(t).filter(|d| d.line > s.line) {
                return Err(use_before_declaration(t, s, *d));
            }
            if primed {
                match state_index.get(t.as_str()) {
                    Some(&v) => {
                        first_primed[v].get_or_insert(s);
                        if let Statement::Assign { expr, .. } = st {
                            primed_in(expr, &state_index, &mut first_primed);
                        }
                    }
                    None => {
                        let what = if params.iter().any(|p| p.name() == t) {
                            Some("a parameter")
                        } else if is_const(t) {
                            Some("a constant")
                        } else if self.declared_unknowns.iter().any(|(n, _)| n == t) {
                            Some("an unknown (write its equation as `NAME = ...`)")
                        } else if self.statements.iter().any(|o| o.target() == Some(t)) {
                            Some("a temporary")
                        } else {
                            None
                        };
                        return Err(match what {
                            Some(w) => Error::new(ErrorKind::BadPrime, s, format!("`{t}'` primes {w}: expected an equation `x' = ...` only for a state variable ({})", state.join(", "))),
                            None => Error::new(ErrorKind::Equation, s, format!("equation for `{t}'`, but `{t}` is not declared: expected a state variable ({}) or `unknown {t}` with an equation `{t} = ...`", state.join(", "))),
                        });
                    }
                }
                continue;
            }
            if params.iter().any(|p| p.name() == t) {
                return Err(decl_err(s, format!("`{t}` is a parameter and cannot be assigned: expected a state variable or a temporary")));
            }
            if is_const(t) {
                return Err(decl_err(s, format!("`{t}` is a constant and cannot be assigned: expected a state variable or a temporary")));
            }
            if t == "z" {
                return Err(decl_err(
                    s,
                    "`z` is reserved for the z-transform variable: expected another name",
                ));
            }
            if self.declared_unknowns.iter().any(|(n, _)| n == t) {
                if let Statement::Assign { expr, .. } = st {
                    primed_in(expr, &state_index, &mut first_primed);
                }
            }
            assigned_anywhere.entry(t.clone()).or_insert(s.line);
        }
        // Unknowns: the primed state variables that some equation holds, in
        // state order, then the declared ones.
        let mut unknowns: Vec<Unknown> = Vec::new();
        for (v, _) in first_primed.iter().enumerate().filter(|(_, p)| p.is_some()) {
            unknowns.push(Unknown { name: format!("{}'", state[v]), state: Some(v) });
        }
        for (n, _) in &self.declared_unknowns {
            unknowns.push(Unknown { name: n.clone(), state: None });
        }
        let unknown_of: HashMap<String, usize> =
            unknowns.iter().enumerate().map(|(i, u)| (u.name.clone(), i)).collect();
        let reduce = constants.iter().any(|c| field::has_generators(&c.value));
        let mut lw = Lowerer {
            state,
            params,
            declared: &self.declared,
            latest_state: vec![None; state.len()],
            latest_temp: HashMap::new(),
            scalar_temps: HashMap::new(),
            assigned_anywhere,
            history: vec![0; state.len()],
            consts: constants.iter().map(|c| (c.name.clone(), c.value.clone())).collect(),
            unknown_of,
            reduce,
            line: 0,
            assign_lines: Vec::new(),
            gauss_seidel: Vec::new(),
            test_symbol: None,
            temp_defs: HashMap::new(),
            unread: Vec::new(),
        };
        let mut assigns: Vec<Assign> = Vec::new();
        // Whether each assignment's value depends on an unknown.
        let mut reads_unknown: Vec<bool> = Vec::new();
        let mut defined: Vec<Option<Equation>> = vec![None; unknowns.len()];
        // Where each `NAME = ...` equation stands.
        let mut defined_at: Vec<Span> = Vec::new();
        let mut general: Vec<General> = Vec::new();
        // The first equation holding each state variable's `x'`: no
        // assignment to x may follow it.
        let mut solved_on: Vec<Option<(u32, bool)>> = vec![None; state.len()];
        for st in self.statements {
            let (t, tspan, expr, text, primed) = match st {
                Statement::Assign { target, target_span, expr, text, primed } => {
                    (target, target_span, expr, text, primed)
                }
                Statement::Equation { lhs, rhs, text } => {
                    lw.line = lhs.span.line;
                    let left = lw.lower(&lhs)?;
                    let right = lw.lower(&rhs)?;
                    let lin = lw.fix_lin(left.add(right, -1));
                    let span = Span {
                        len: (rhs.span.col + rhs.span.len).saturating_sub(lhs.span.col).max(1),
                        ..lhs.span
                    };
                    let holds = |op: &Operand| match *op {
                        Operand::Unknown(_) => true,
                        Operand::Stmt(t) => reads_unknown[t],
                        Operand::Start { .. } => false,
                    };
                    if !lin.terms.keys().any(holds) {
                        return Err(Error::new(
                            ErrorKind::Equation,
                            lhs.span,
                            format!("this equation holds no unknown: expected an equation in the unknowns ({}), or `name = ...` to assign a value", unknown_list(&unknowns)),
                        ));
                    }
                    if !lin.scalar.is_zero() {
                        // Shown as a term of `rhs − lhs`, as a term on the
                        // right is written.
                        return Err(affine_err(&-&lin.scalar, span));
                    }
                    for op in lin.terms.keys() {
                        if let Operand::Unknown(u) = *op {
                            if let Some(v) = unknowns[u].state {
                                solved_on[v].get_or_insert((span.line, false));
                            }
                        }
                    }
                    general.push(General { lin, span, text });
                    continue;
                }
            };
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
                    return Err(affine_err(&lin.scalar, expr.span));
                }
                if let Some(prev) = &defined[u] {
                    return Err(Error::new(ErrorKind::Equation, tspan, format!("a second equation for `{}` (the first is on line {}): expected exactly one", unknowns[u].name, prev.line)));
                }
                if let Some(v) = unknowns[u].state {
                    solved_on[v].get_or_insert((tspan.line, true));
                }
                defined_at.push(tspan);
                defined[u] = Some(Equation {
                    unknown: u,
                    terms: lin.terms.into_iter().collect(),
                    line: tspan.line,
                    text,
                });
                continue;
            }
            if let Some(v) = state_index {
                match solved_on[v] {
                    Some((l, true)) => return Err(Error::new(ErrorKind::Equation, tspan, format!("`{t}` is assigned after its equation `{t}' = ...` on line {l}: expected every assignment to `{t}` before its equation (the equation's solution ends the step)"))),
                    Some((l, false)) => return Err(Error::new(ErrorKind::Equation, tspan, format!("`{t}` is assigned after its equation on line {l}, which holds `{t}'`: expected every assignment to `{t}` before the equations holding `{t}'` (their solution ends the step)"))),
                    None => {}
                }
            }
            if !is_state {
                lw.define_temp(&t, tspan);
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
                return Err(affine_err(&lin.scalar, expr.span));
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
            reads_unknown.push(lin.terms.keys().any(|op| match *op {
                Operand::Unknown(_) => true,
                Operand::Stmt(t) => reads_unknown[t],
                Operand::Start { .. } => false,
            }));
            lw.assign_lines.push(tspan.line);
            assigns.push(Assign {
                target,
                terms: lin.terms.into_iter().collect(),
                line: tspan.line,
                text,
            });
        }
        let equations = place_equations(
            defined,
            &defined_at,
            general,
            &unknowns,
            &self.declared_unknowns,
            &first_primed,
        )?;
        let scalar = matches!(lw.test_symbol, Some((true, _)));
        let mut warnings = lw.unread_warnings(&finals_or_solved(&lw.latest_state, &unknowns));
        for (v, name) in state.iter().enumerate() {
            let solved = unknowns.iter().any(|u| u.state == Some(v));
            if lw.latest_state[v].is_none() && !solved {
                let span = self.declared.get(name).copied().unwrap_or_default();
                warnings.push(Warning {
                    span,
                    message: format!("state variable `{name}` is never assigned: the step keeps its value (expected an assignment `{name} = ...` or an equation for `{name}'`)"),
                });
            }
        }
        warnings.sort_by_key(|w| (w.span.line, w.span.col));
        let (history, finals, gauss_seidel) = (lw.history, lw.latest_state, lw.gauss_seidel);
        Ok(Method {
            scalar,
            implicit: !unknowns.is_empty(),
            name: self.name,
            state: self.state,
            params: self.params,
            history,
            constants,
            stability_function: Default::default(),
            body: Body::lowered(Lowered {
                assigns,
                finals,
                unknowns,
                equations,
                gauss_seidel,
                warnings,
            }),
        })
    }
}

/// Which state variables the step sets (by an assignment or an equation
/// for `x'`), for the did-you-mean of an unread temporary.
fn finals_or_solved(latest: &[Option<usize>], unknowns: &[Unknown]) -> Vec<bool> {
    (0..latest.len())
        .map(|v| latest[v].is_some() || unknowns.iter().any(|u| u.state == Some(v)))
        .collect()
}

/// The edit distance between two names (insertions, deletions and
/// substitutions of characters).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

impl Statement {
    /// The assigned name, for an assignment (not `x' = ...`).
    fn target(&self) -> Option<&str> {
        match self {
            Statement::Assign { target, primed: false, .. } => Some(target),
            Statement::Assign { .. } | Statement::Equation { .. } => None,
        }
    }

    /// Where the line starts.
    fn span(&self) -> Span {
        match self {
            Statement::Assign { target_span, .. } => *target_span,
            Statement::Equation { lhs, .. } => lhs.span,
        }
    }
}

/// Records the first occurrence of each primed state variable in `e`.
fn primed_in(e: &Expr, state_index: &HashMap<&str, usize>, first: &mut [Option<Span>]) {
    match &e.kind {
        ExprKind::Primed(n) => {
            if let Some(&v) = state_index.get(n.as_str()) {
                first[v].get_or_insert(e.span);
            }
        }
        ExprKind::Neg(x) | ExprKind::Pow(x, _) => primed_in(x, state_index, first),
        ExprKind::Bin(_, l, r) => {
            primed_in(l, state_index, first);
            primed_in(r, state_index, first);
        }
        ExprKind::Num(_) | ExprKind::Name(_) | ExprKind::Hist(..) | ExprKind::Call { .. } => {}
    }
}

/// An equation `L = 0` whose left side is not a single name.
struct General {
    lin: Lin,
    span: Span,
    text: String,
}

fn unknown_list(unknowns: &[Unknown]) -> String {
    if unknowns.is_empty() {
        return "none are declared".to_owned();
    }
    unknowns.iter().map(|u| u.name.as_str()).collect::<Vec<_>>().join(", ")
}

/// Every unknown's equation, in unknown order: the `NAME = ...` lines for
/// the unknowns they name, and the other equations, in file order, for the
/// unknowns left, by name (`u = u − L`). Too many or too few equations are
/// errors on the equation or the unknown concerned.
fn place_equations(
    mut defined: Vec<Option<Equation>>,
    defined_at: &[Span],
    general: Vec<General>,
    unknowns: &[Unknown],
    declared_unknowns: &[(String, Span)],
    first_primed: &[Option<Span>],
) -> Result<Vec<Equation>, Error> {
    let free: Vec<usize> = (0..unknowns.len()).filter(|&u| defined[u].is_none()).collect();
    if general.len() > free.len() {
        // The first equation, in file order, beyond one per unknown.
        let mut at: Vec<Span> =
            defined_at.iter().copied().chain(general.iter().map(|g| g.span)).collect();
        at.sort_by_key(|s| (s.line, s.col));
        let n = unknowns.len();
        let above: Vec<String> = at[..n].iter().take(8).map(|s| s.line.to_string()).collect();
        let more = if n > above.len() { ", ..." } else { "" };
        return Err(Error::new(
            ErrorKind::Equation,
            at[n],
            format!("one equation too many: the {n} unknown(s) ({}) already have {n} equation(s) above (line(s) {}{more}); expected one equation per unknown, or `name = ...` to assign a value", unknown_list(unknowns), above.join(", ")),
        ));
    }
    if general.len() < free.len() {
        let u = unmatched_unknown(&general, &free);
        return Err(match unknowns[u].state {
            Some(v) => {
                let n = unknowns[u].name.trim_end_matches('\'');
                Error::new(
                    ErrorKind::Equation,
                    first_primed[v].unwrap_or_default(),
                    format!("`{n}'` is read but `{n}` has no equation: expected a line `{n}' = ...` defining its end-of-step value"),
                )
            }
            None => {
                let (n, s) = declared_unknowns
                    .iter()
                    .find(|(n, _)| *n == unknowns[u].name)
                    .expect("a declared unknown");
                Error::new(
                    ErrorKind::Equation,
                    *s,
                    format!("unknown `{n}` has no equation: expected one line `{n} = ...`"),
                )
            }
        });
    }
    let mut by_name = free;
    by_name.sort_by(|&a, &b| unknowns[a].name.cmp(&unknowns[b].name));
    for (g, &u) in general.into_iter().zip(&by_name) {
        let r = Lin::operand(Operand::Unknown(u)).add(g.lin, -1);
        defined[u] = Some(Equation {
            unknown: u,
            terms: r.terms.into_iter().collect(),
            line: g.span.line,
            text: g.text,
        });
    }
    Ok(defined.into_iter().map(|e| e.expect("every unknown has its equation")).collect())
}

/// With fewer general equations than free unknowns: the first free unknown
/// (in unknown order) left out of a largest matching of equations to the
/// free unknowns they hold, so that an unknown no equation holds is named
/// before one that merely has too few.
fn unmatched_unknown(general: &[General], free: &[usize]) -> usize {
    let holds: Vec<Vec<usize>> = general
        .iter()
        .map(|g| {
            free.iter()
                .enumerate()
                .filter(|(_, u)| g.lin.terms.contains_key(&Operand::Unknown(**u)))
                .map(|(k, _)| k)
                .collect()
        })
        .collect();
    // Augmenting paths (Kuhn): match[k] is the equation holding free[k].
    let mut matched: Vec<Option<usize>> = vec![None; free.len()];
    fn augment(
        g: usize,
        holds: &[Vec<usize>],
        matched: &mut [Option<usize>],
        seen: &mut [bool],
    ) -> bool {
        for &k in &holds[g] {
            if seen[k] {
                continue;
            }
            seen[k] = true;
            if matched[k].is_none_or(|h| augment(h, holds, matched, seen)) {
                matched[k] = Some(g);
                return true;
            }
        }
        false
    }
    for g in 0..general.len() {
        let mut seen = vec![false; free.len()];
        augment(g, &holds, &mut matched, &mut seen);
    }
    let k = matched.iter().position(Option::is_none).expect("more free unknowns than equations");
    free[k]
}

fn affine_err(scalar: &Poly, span: Span) -> Error {
    Error::new(
        ErrorKind::Affine,
        span,
        format!("term `{scalar}` does not depend on the state: expected every term to be a multiple of a state variable (the step must be linear)"),
    )
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
        // A number (a tableau's entry, mostly) scales term by term, without
        // a product of polynomials.
        let number = k.as_constant();
        let times = |c: &Poly| match &number {
            Some(q) => c.scale(q),
            None => c * k,
        };
        Lin {
            scalar: times(&self.scalar),
            terms: self
                .terms
                .into_iter()
                .map(|(op, c)| (op, times(&c)))
                .filter(|(_, c)| !c.is_zero())
                .collect(),
        }
    }
}

struct Lowerer<'a> {
    state: &'a [String],
    params: &'a [Sym],
    /// Where each declared name is declared.
    declared: &'a HashMap<String, Span>,
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
    /// Whether a constant involves a radical: coefficients are then reduced.
    reduce: bool,
    /// The line being lowered and the line of every assignment so far.
    line: u32,
    assign_lines: Vec<u32>,
    gauss_seidel: Vec<GaussSeidelRead>,
    /// The first read of `Phi` (false) or of the scalar test equation's `w`
    /// (true): a program is written for one test equation, not both.
    test_symbol: Option<(bool, Span)>,
    /// Each temporary's current definition: where, and whether it has been
    /// read since.
    temp_defs: HashMap<String, (Span, bool)>,
    /// Definitions of temporaries overwritten before any read.
    unread: Vec<(String, Span)>,
}

impl Lowerer<'_> {
    /// Records a new definition of the temporary `t`; an earlier one that
    /// nothing read is unread for good.
    fn define_temp(&mut self, t: &str, span: Span) {
        if let Some((s, false)) = self.temp_defs.insert(t.to_owned(), (span, false)) {
            self.unread.push((t.to_owned(), s));
        }
    }

    /// A warning per definition of a temporary that nothing reads, with a
    /// did-you-mean for the closest state variable (`sets[v]`: whether the
    /// step sets state variable v; one it never sets is the likelier
    /// meaning).
    fn unread_warnings(&mut self, sets: &[bool]) -> Vec<Warning> {
        let mut unread = std::mem::take(&mut self.unread);
        unread.extend(
            self.temp_defs.iter().filter(|(_, (_, read))| !read).map(|(t, (s, _))| (t.clone(), *s)),
        );
        unread
            .into_iter()
            .map(|(t, span)| {
                let closest = self
                    .state
                    .iter()
                    .enumerate()
                    .map(|(v, s)| (edit_distance(&t, s), sets[v], s))
                    // One edit away, or two from a variable the step never
                    // sets (a typo leaves one behind).
                    .filter(|(d, sets, s)| {
                        (*d == 1 || (*d == 2 && !sets))
                            && *d < s.chars().count().max(t.chars().count())
                    })
                    .min_by_key(|(d, sets, _)| (*d, *sets));
                let message = match closest {
                    Some((_, _, s)) => format!(
                        "`{t}` is assigned but never read: did you mean the state variable `{s}`?"
                    ),
                    None => {
                        format!("`{t}` is assigned but never read: no later line uses this value")
                    }
                };
                Warning { span, message }
            })
            .collect()
    }

    /// Records a read of `Phi` or `w`, refusing the second kind.
    fn note_test_symbol(&mut self, is_w: bool, span: Span) -> Result<(), Error> {
        match self.test_symbol {
            None => {
                self.test_symbol = Some((is_w, span));
                Ok(())
            }
            Some((first, at)) if first != is_w => {
                let (this, other) = if is_w { ("w", "Phi") } else { ("Phi", "w") };
                Err(Error::new(
                    ErrorKind::UnknownName,
                    span,
                    format!(
                        "`{this}` in a program that reads `{other}` on line {}: expected one test equation, \
                         the oscillator (`Phi` = ωT) or the scalar y' = λy (`w` = hλ), not both",
                        at.line
                    ),
                ))
            }
            Some(_) => Ok(()),
        }
    }

    fn describe_names(&self) -> String {
        let st = self.state.join(", ");
        let pa: Vec<&str> = self.params.iter().map(|s| s.name()).collect();
        format!(
            "a state variable ({st}), a parameter ({}) or a temporary assigned above",
            pa.join(", ")
        )
    }

    /// An error when `n` is declared on a later line than its use here.
    fn declared_before(&self, n: &str, span: Span) -> Result<(), Error> {
        match self.declared.get(n) {
            Some(d) if d.line > span.line => Err(use_before_declaration(n, span, *d)),
            _ => Ok(()),
        }
    }

    fn lower(&mut self, e: &Expr) -> Result<Lin, Error> {
        match &e.kind {
            ExprKind::Num(q) => Ok(Lin::scalar(Poly::constant(q.clone()))),
            ExprKind::Name(n) => self.name(n, e.span),
            ExprKind::Hist(n, k) => {
                self.declared_before(n, e.span)?;
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
            ExprKind::Call { .. } => unreachable!("the parser reads calls in `const` lines only"),
            ExprKind::Neg(x) => Ok(Lin::default().add(self.lower(x)?, -1)),
            ExprKind::Pow(b, n) => {
                let base = self.lower(b)?;
                if base.is_scalar() {
                    Ok(Lin::scalar(if self.reduce {
                        constant::pow_reduced(&base.scalar, *n)
                    } else {
                        base.scalar.pow(*n)
                    }))
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
                            if field::has_generators(&b.scalar)
                                && b.scalar
                                    .symbols()
                                    .iter()
                                    .all(|&s| field::generator_of(s).is_some())
                            {
                                // A nonzero constant of the field: exact inverse.
                                let inv =
                                    field::inverse(&b.scalar).expect("a nonzero field element");
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
                        Ok(a.scale(&Poly::constant(c.recip())))
                    }
                }
            }
        }
    }

    fn fix_lin(&self, l: Lin) -> Lin {
        if !self.reduce {
            return l;
        }
        Lin {
            scalar: field::reduce(&l.scalar),
            terms: l
                .terms
                .into_iter()
                .map(|(op, c)| (op, field::reduce(&c)))
                .filter(|(_, c)| !c.is_zero())
                .collect(),
        }
    }

    fn primed(&mut self, n: &str, span: Span) -> Result<Lin, Error> {
        self.declared_before(n, span)?;
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
        self.declared_before(n, span)?;
        if let Some(&p) = self.params.iter().find(|p| p.name() == n) {
            if p == Sym::phi() {
                self.note_test_symbol(false, span)?;
            }
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
        if let Some(d) = self.temp_defs.get_mut(n) {
            d.1 = true;
        }
        if let Some(p) = self.scalar_temps.get(n) {
            return Ok(Lin::scalar(p.clone()));
        }
        if let Some(&t) = self.latest_temp.get(n) {
            return Ok(Lin::operand(Operand::Stmt(t)));
        }
        if n == "w" && !self.assigned_anywhere.contains_key(n) {
            // The scalar test equation's w = hλ, unless the program gives
            // the name another meaning.
            self.note_test_symbol(true, span)?;
            return Ok(Lin::scalar(Poly::sym(Sym::w())));
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

#[cfg(test)]
mod tests {
    use super::*;

    /// An unknown that no general equation holds is named before one that
    /// only has too few equations.
    #[test]
    fn the_unknown_left_out_is_the_one_no_equation_holds() {
        let holding = |us: &[usize]| General {
            lin: Lin {
                scalar: Poly::zero(),
                terms: us.iter().map(|&u| (Operand::Unknown(u), Poly::one())).collect(),
            },
            span: Span::default(),
            text: String::new(),
        };
        // Equations hold {0, 1} and {0}: 1 is matched through augmenting
        // 0's match, and 2 is left.
        assert_eq!(unmatched_unknown(&[holding(&[0, 1]), holding(&[0])], &[0, 1, 2]), 2);
        // No equation holds 0.
        assert_eq!(unmatched_unknown(&[holding(&[1])], &[0, 1]), 0);
    }
}
