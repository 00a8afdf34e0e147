//! Operations per step, counted exactly from the lowered method.
//!
//! The paper's third criterion is "speed, expressed by the number of
//! calculations per step" (section 1), and section 8 says False Euler and
//! Verlet both need "two multiplications and two additions per step". This
//! module makes that count mechanical, on the same lowered program every
//! other interpreter reads ([`Method::assigns`]), under one stated model of
//! what a compiler removes.
//!
//! # The model
//!
//! A lowered assignment is `target = Σ_k c_k(Φ, params) · operand_k`.
//!
//! 1. **Constant folding.** Every coefficient c_k depends on the parameters
//!    only, so it is computed once per Φ (and per value of the other
//!    parameters) before the run and costs nothing per step. Powers of Φ are
//!    therefore free too: `(1 − Φ²/2)` is one register, not three operations.
//!    Parameter-only temporaries (Appendix B's `D:=0.5*woT`) are already
//!    folded by lowering.
//! 2. **Multiplication by ±1 is free.** A term with coefficient +1 is an
//!    addition, one with −1 a subtraction.
//! 3. **Common factors are shared.** Terms whose coefficients are equal up to
//!    sign share one multiplication: `½·a + ½·b` costs `½·(a + b)`, one
//!    multiplication and one addition, as the source `0.5*(dv1+dv2)` does.
//!    The sign is folded into the precomputed register, so `−Φ·y` is one
//!    multiplication.
//! 4. **Additions.** An assignment with m terms costs m − 1
//!    additions/subtractions. A lone −1 term (`x = −y`) or a sum whose terms
//!    are all −1 costs one more (a negation), since no register can absorb
//!    the sign.
//! 5. **Dead code is removed.** An assignment nothing reads (neither a later
//!    assignment nor the end of the step) costs nothing; see [`live_assigns`].
//! 6. **Copies are counted apart.** An assignment `x = y` (one term,
//!    coefficient +1) and each history shift (`y@1 ← y` for a method that
//!    reads `y@1`) is a copy, not arithmetic: [`OpCount::copy`]. A compiler
//!    usually removes copies by renaming registers in an unrolled loop.
//!
//! Under this model False Euler costs 2 mul + 2 add. Verlet's lowered step
//! `y = (2 − Φ²)·y − y@1` costs 1 mul + 1 add + 1 copy: the paper's Pascal
//! line `2*y0-y2+Sqr(dT)*(-wo*wo*y0)` spends a multiplication on `2*y0` and
//! keeps `Φ²` apart from the 2 that folding merges with it.
//!
//! [`StepCost::matrix_form`] counts, under the same model, the program that
//! applies the transition matrix P directly (one assignment per slot of the
//! augmented state, reading only start-of-step values): the cheapest form a
//! programmer can write for a linear spring, and what Appendix B's
//! "Transition matrix" branches do.
//!
//! ```
//! let m = poly::builtin("false_euler")?;
//! let c = poly::advanced::cost::step_cost(&m);
//! assert_eq!((c.program.mul, c.program.add), (2, 2));
//! # Ok::<(), poly::Error>(())
//! ```

use std::fmt;
use std::ops::{Add, AddAssign};

use num_traits::One;

use crate::lang::method::{Method, Operand};
use crate::{Poly, PolyMatrix};

/// Counts of per-step operations.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct OpCount {
    /// Multiplications.
    pub mul: u32,
    /// Additions and subtractions (negations included).
    pub add: u32,
    /// Register copies and history shifts (no arithmetic).
    pub copy: u32,
}

impl OpCount {
    /// Arithmetic operations: `mul + add` (copies excluded).
    pub fn arithmetic(self) -> u32 {
        self.mul + self.add
    }
}

impl Add for OpCount {
    type Output = OpCount;
    fn add(self, o: OpCount) -> OpCount {
        OpCount { mul: self.mul + o.mul, add: self.add + o.add, copy: self.copy + o.copy }
    }
}

impl AddAssign for OpCount {
    fn add_assign(&mut self, o: OpCount) {
        *self = *self + o;
    }
}

impl fmt::Display for OpCount {
    /// `2 mul + 2 add`, with `+ 1 copy` when there are copies.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} mul + {} add", self.mul, self.add)?;
        match self.copy {
            0 => Ok(()),
            1 => write!(f, " + 1 copy"),
            n => write!(f, " + {n} copies"),
        }
    }
}

/// The per-step cost of one method (see the module docs for the model).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StepCost {
    /// The whole step as written (all assignments plus history shifts).
    pub program: OpCount,
    /// One count per lowered assignment, in program order (zero for dead
    /// assignments).
    pub per_assign: Vec<OpCount>,
    /// History shifts per step (also included in `program.copy`).
    pub shifts: u32,
    /// The step written as the transition matrix applied to the augmented
    /// state (see [`matrix_cost`]).
    pub matrix_form: OpCount,
    /// For an implicit step, the per-step solve (also included in
    /// `program`): the unknowns as A⁻¹E applied to the N slots, n·N
    /// multiplications and n·(N − 1) additions with the factorisation done
    /// once per Φ (as `check` compiles it); zero for an explicit step.
    pub solve: OpCount,
}

/// The cost of one linear combination `Σ c_k · x_k` under the model.
///
/// The coefficients are given without their operands: only their values
/// matter. An empty combination (the constant 0) costs nothing.
pub fn combination_cost<'a>(coeffs: impl IntoIterator<Item = &'a Poly>) -> OpCount {
    let coeffs: Vec<&Poly> = coeffs.into_iter().filter(|c| !c.is_zero()).collect();
    let m = coeffs.len() as u32;
    if m == 0 {
        return OpCount::default();
    }
    let minus_one = -Poly::one();
    // One multiplication per distinct coefficient up to sign, other than ±1.
    let mut groups: Vec<Poly> = Vec::new();
    for c in &coeffs {
        if is_unit(c) {
            continue;
        }
        let neg = -*c;
        if !groups.iter().any(|g| g == *c || *g == neg) {
            groups.push((*c).clone());
        }
    }
    let all_unit_negative = groups.is_empty() && coeffs.iter().all(|c| **c == minus_one);
    if m == 1 && coeffs[0].is_one() {
        return OpCount { mul: 0, add: 0, copy: 1 };
    }
    OpCount { mul: groups.len() as u32, add: m - 1 + u32::from(all_unit_negative), copy: 0 }
}

/// The cost of applying a transition matrix row by row, each row as one
/// combination of start-of-step values (see [`combination_cost`]). A row
/// that is a single 1 (a history shift, or a variable the step leaves alone
/// read back in place) is a copy; a row equal to its own unit vector costs
/// nothing, since the value stays where it is.
pub fn matrix_cost(p: &PolyMatrix) -> OpCount {
    let mut total = OpCount::default();
    for i in 0..p.rows() {
        let row = p.row(i);
        let unit_in_place =
            row.iter().enumerate().all(|(j, x)| if j == i { x.is_one() } else { x.is_zero() });
        if unit_in_place {
            continue;
        }
        total += combination_cost(row.iter());
    }
    total
}

/// The per-step cost of a method's lowered program, and of its transition
/// matrix applied directly.
///
/// ```
/// let verlet = poly::advanced::cost::step_cost(&poly::builtin("verlet")?);
/// assert_eq!(verlet.program.to_string(), "1 mul + 1 add + 1 copy");
/// # Ok::<(), poly::Error>(())
/// ```
pub fn step_cost(method: &Method) -> StepCost {
    let live = live_assigns(method);
    let per_assign: Vec<OpCount> = method
        .assigns()
        .iter()
        .zip(&live)
        .map(|(a, &live)| {
            if live {
                combination_cost(a.terms.iter().map(|(_, c)| c))
            } else {
                OpCount::default()
            }
        })
        .collect();
    let shifts: u32 = method.history().iter().sum();
    let mut program = per_assign.iter().copied().fold(OpCount::default(), Add::add);
    program.copy += shifts;
    let matrix_form = matrix_cost(&crate::derive::routes::transition_matrix(method));
    let (n_u, n_s) = (method.unknowns().len() as u32, method.state_size() as u32);
    let solve = OpCount { mul: n_u * n_s, add: n_u * n_s.saturating_sub(1), copy: 0 };
    program += solve;
    StepCost { program, per_assign, shifts, matrix_form, solve }
}

/// Which assignments are live: the last assignment to each state variable,
/// and every assignment a live one reads. The rest is dead code a compiler
/// removes (Semi-False Heun's `v11:= v0+dv1`, which nothing reads).
pub fn live_assigns(method: &Method) -> Vec<bool> {
    let assigns = method.assigns();
    let mut live = vec![false; assigns.len()];
    for var in 0..method.state().len() {
        if let crate::lang::method::EndValue::Assign(k) = method.end_value(var) {
            live[k] = true;
        }
    }
    for k in (0..assigns.len()).rev() {
        if !live[k] {
            continue;
        }
        for (op, _) in &assigns[k].terms {
            if let Operand::Stmt(t) = *op {
                live[t] = true;
            }
        }
    }
    live
}

/// Whether a coefficient is a plain ±1 (free under the model).
pub fn is_unit(c: &Poly) -> bool {
    c.as_constant().is_some_and(|q| q.is_one() || (-q).is_one())
}

impl crate::Derivation {
    /// Operations per step under the stated constant-folding model (see
    /// the module docs).
    pub fn cost(&self) -> StepCost {
        step_cost(self.method())
    }
}
