//! A method: a `.zm` program lowered to a linear step program (the
//! lowering itself is in `lower.rs`).
//!
//! Every assignment is a linear combination
//!
//! $$ \text{target} = \sum_k c_k(\Phi, D, \dots)\,\text{operand}_k $$
//!
//! where an operand is either a state variable as it stood before this step
//! (`Start`, possibly `lag` steps further back for `y@k`), the value of an
//! earlier assignment of this step (`Stmt`), or an unknown of the step's
//! implicit system. Coefficients are polynomials in the parameters. This
//! one form is what every interpreter reads: the two exact derivations in
//! `derive/routes.rs`, and the numeric ones in the `check` crate.

use std::fmt;

use num_traits::Zero;

use crate::error::Warning;
pub use crate::lang::constant::Constant;
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
///
/// A line `x' = r` or `k = r` is stored as written. Any other equation
/// `lhs = rhs` is stored as `u = u − (lhs − rhs)` for the unknown u it
/// was given (see `lower.rs`), so that every interpreter solves it as it
/// solves the others: its row of A = I − ∂r/∂u is ∂(lhs − rhs)/∂u.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Equation {
    /// The unknown whose row of the system it is, by index into
    /// [`Method::unknowns`].
    pub unknown: usize,
    /// Nonzero coefficients per operand; operands may be unknowns.
    pub terms: Vec<(Operand, Poly)>,
    /// The 1-based source line.
    pub line: u32,
    /// The equation as written, without its comment.
    pub text: String,
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
///
/// Its header (name, state, parameters, history depths, constants, whether
/// it is scalar or implicit) is always at hand; the lowered program itself
/// ([`Method::assigns`], [`Method::unknowns`], ...) may be generated on
/// first use. A program generated from a Butcher tableau is lowered only
/// when something reads its lines: the derivation of a tableau comes from
/// its stability function, so `zcheck stability` never lowers it. Clones
/// share the lowered program.
#[derive(Clone, Debug)]
pub struct Method {
    pub(crate) name: String,
    pub(crate) state: Vec<String>,
    pub(crate) params: Vec<Sym>,
    pub(crate) history: Vec<u32>,
    pub(crate) constants: Vec<Constant>,
    /// Whether the program is written for the scalar test equation
    /// y' = λy (it reads `w` = hλ) rather than the oscillator (`Phi`).
    pub(crate) scalar: bool,
    /// Whether the step solves a linear system (it has unknowns).
    pub(crate) implicit: bool,
    /// For a program generated from a Butcher tableau, its stability
    /// function: `derive` reads χ and P from it.
    pub(crate) stability_function: StabilityFunction,
    pub(crate) body: Body,
}

/// The lowered lines of a [`Method`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Lowered {
    pub(crate) assigns: Vec<Assign>,
    /// The last assignment to each state variable, if any.
    pub(crate) finals: Vec<Option<usize>>,
    pub(crate) unknowns: Vec<Unknown>,
    pub(crate) equations: Vec<Equation>,
    pub(crate) gauss_seidel: Vec<GaussSeidelRead>,
    /// What the program says that it probably does not mean.
    pub(crate) warnings: Vec<Warning>,
}

/// A generator of a program: parses and lowers it, to a method whose header
/// is the deferred method's.
type Generate = Box<dyn Fn() -> Result<Method, crate::Error> + Send + Sync>;

/// A method's lowered program, lowered already or on first use (shared by
/// clones).
#[derive(Clone)]
pub(crate) struct Body(std::sync::Arc<BodyCell>);

struct BodyCell {
    lowered: std::sync::OnceLock<Lowered>,
    generate: Option<Generate>,
}

impl Body {
    /// A program lowered already.
    pub(crate) fn lowered(lowered: Lowered) -> Body {
        Body(std::sync::Arc::new(BodyCell {
            lowered: std::sync::OnceLock::from(lowered),
            generate: None,
        }))
    }

    /// A program lowered on first use by `generate`, which must not fail
    /// and must give the header it is deferred under (a generator of a
    /// validated tableau's program; [`Method::lowered`] checks both).
    pub(crate) fn deferred(generate: Generate) -> Body {
        Body(std::sync::Arc::new(BodyCell {
            lowered: std::sync::OnceLock::new(),
            generate: Some(generate),
        }))
    }

    /// Whether the program has been lowered (for the tests of deferral).
    #[cfg(test)]
    pub(crate) fn is_lowered(&self) -> bool {
        self.0.lowered.get().is_some()
    }
}

impl fmt::Debug for Body {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0.lowered.get() {
            Some(l) => l.fmt(f),
            None => f.write_str("Body(deferred)"),
        }
    }
}

impl PartialEq for Method {
    /// Equal headers and equal lowered programs (lowering both if need be).
    fn eq(&self, other: &Method) -> bool {
        self.same_header(other) && self.lowered() == other.lowered()
    }
}

impl Eq for Method {}

/// A Runge–Kutta method's stability function R(w) = P(w)/Q(w) with
/// P = det(I − wA + w·1bᵀ) and Q = det(I − wA), exact polynomials in `w`
/// (and the program's constants), attached by `lang::tableau` to the
/// programs it generates (on the oscillator and on y' = λy). It is a fact of
/// the program, not part of it: two equal programs have the same R, so it
/// takes no part in comparisons.
#[derive(Clone, Debug, Default)]
pub(crate) struct StabilityFunction(pub(crate) Option<std::sync::Arc<(Poly, Poly)>>);

impl PartialEq for StabilityFunction {
    fn eq(&self, _: &StabilityFunction) -> bool {
        true
    }
}

impl Eq for StabilityFunction {}

impl Method {
    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The lowered program, lowering a deferred one now.
    ///
    /// # Panics
    ///
    /// When a deferred program's generator fails or gives another header:
    /// a bug in the generator (its input was validated), which the tests of
    /// `lang::tableau` hold on every catalogue and random tableau.
    pub(crate) fn lowered(&self) -> &Lowered {
        let cell = &self.body.0;
        cell.lowered.get_or_init(|| {
            let generate = cell.generate.as_ref().expect("a method is lowered or has a generator");
            let m = generate().unwrap_or_else(|e| {
                panic!("the program generated for method `{}` does not lower: {e}", self.name)
            });
            assert!(
                self.same_header(&m),
                "the program generated for method `{}` has another header: {m:?}",
                self.name
            );
            m.lowered().clone()
        })
    }

    /// Whether the two methods agree on everything but their lowered lines.
    fn same_header(&self, other: &Method) -> bool {
        self.name == other.name
            && self.state == other.state
            && self.params == other.params
            && self.history == other.history
            && self.constants == other.constants
            && self.scalar == other.scalar
            && self.implicit == other.implicit
    }

    /// What the program says that it probably does not mean (a value
    /// assigned and never read, a state variable never assigned), in file
    /// order. A method with warnings derives as written.
    pub fn warnings(&self) -> &[Warning] {
        &self.lowered().warnings
    }

    /// The state variables, in declaration order.
    pub fn state(&self) -> &[String] {
        &self.state
    }

    /// Whether the program is written for the scalar test equation y' = λy:
    /// it reads `w` = hλ (a complex number) instead of `Phi`. Its χ is a
    /// polynomial in z and w, analysed in the complex plane
    /// ([`Derivation::plane`](crate::Derivation::plane)), not over Φ > 0.
    pub fn is_scalar(&self) -> bool {
        self.scalar
    }

    /// The parameters: `Phi` first, then those declared by `param`.
    pub fn params(&self) -> &[Sym] {
        &self.params
    }

    /// The lowered assignments, in program order.
    pub fn assigns(&self) -> &[Assign] {
        &self.lowered().assigns
    }

    /// The deepest history read per state variable (0 when only the start
    /// value is read).
    pub fn history(&self) -> &[u32] {
        &self.history
    }

    /// The state size `N = Σ (1 + history)`: the size of the transition
    /// matrix and the degree of the characteristic polynomial (not an order
    /// of accuracy: that is `poly::advanced::order`).
    pub fn state_size(&self) -> usize {
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
        self.lowered().finals[var]
    }

    /// Where state variable `var`'s end-of-step value comes from.
    pub fn end_value(&self, var: usize) -> EndValue {
        if let Some(u) = self.unknowns().iter().position(|u| u.state == Some(var)) {
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
        &self.lowered().unknowns
    }

    /// The equations, one per unknown, in [`Method::unknowns`] order.
    pub fn equations(&self) -> &[Equation] {
        &self.lowered().equations
    }

    /// Whether the step solves a linear system (it has unknowns).
    pub fn is_implicit(&self) -> bool {
        self.implicit
    }

    /// The exact constants declared with `const`.
    pub fn constants(&self) -> &[Constant] {
        &self.constants
    }

    /// Every read of a state variable that an earlier line of the same step
    /// has already updated, in program order.
    pub fn gauss_seidel_reads(&self) -> &[GaussSeidelRead] {
        &self.lowered().gauss_seidel
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
            Operand::Unknown(u) => self.unknowns()[u].name.clone(),
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
        for c in &self.constants {
            match c.radical().filter(|r| !r.is_rational()) {
                Some(r) => {
                    let (k, n) = r.minimal_polynomial();
                    let n =
                        if n < crate::Q::zero() { format!("+ {}", -n) } else { format!("- {n}") };
                    writeln!(f, "const {} = {} (minimal polynomial x^{k} {n})", c.name, c.value)?;
                }
                None => writeln!(f, "const {} = {}", c.name, c.value)?,
            }
        }
        if !self.unknowns().is_empty() {
            let us: Vec<&str> = self.unknowns().iter().map(|u| u.name.as_str()).collect();
            writeln!(f, "unknown {}", us.join(" "))?;
        }
        let lines = self
            .assigns()
            .iter()
            .enumerate()
            .map(|(k, a)| (a.line, format!("%{k} ({})", self.target_name(a)), &a.terms))
            .chain(
                self.equations()
                    .iter()
                    .map(|e| (e.line, format!("{} =", self.unknowns()[e.unknown].name), &e.terms)),
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
