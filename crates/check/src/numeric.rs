//! The numeric interpreter of a lowered `.zm` method: one definition, run in
//! `f64`.
//!
//! [`Step::compile`] turns a [`poly::Method`] and numeric parameter values
//! ([`Params`]) into a flat list of instructions over registers:
//!
//! * registers `0 .. N` hold the augmented state, one per slot of
//!   [`Method::slots`] (each state variable at lag 0, 1, ..., its history);
//! * register `N + k` holds the value of assignment `k` of the current step.
//!
//! Each instruction computes `dst = Σ cᵢ·srcᵢ` (at most four terms; longer
//! sums continue with accumulating instructions) with coefficients evaluated
//! once at compile time: every coefficient polynomial is summed term by term,
//! each rational coefficient converted to the nearest `f64`. After the
//! instructions, history shifts (`y@1 ← y`) and the new state values are put
//! in place by swapping registers, never by recomputing.
//!
//! The same instructions run on one state ([`State`], [`Step::advance`]) or on
//! many states stored struct-of-arrays ([`Batch`], [`Step::advance_batch`]).
//! The batch runner works on blocks of [`BLOCK`] lanes that stay in L1 cache
//! for all requested steps, and every instruction loops over the lanes of a
//! fixed-width block so the compiler vectorises it. Both runners perform the
//! identical floating-point operations in the identical order, so one lane of
//! a batch is bit-for-bit the single-state run.
//!
//! [`Step::transition_matrix`] runs the step on the basis vectors: column `j`
//! of P is the state after one step from `e_j`.
//!
//! ```
//! use check::numeric::{Params, ParamsF64, Step};
//! let method = poly::builtin("false_euler")?;
//! let step = Step::compile(&method, &Params::phi(0.5))?;
//! let mut state = step.state(&[0.0, 1.0]); // v0 = 0, y0 = 1
//! step.advance(&mut state, 1);
//! assert_eq!(state.slots(), [-0.5, 0.75]); // v = v - Phi*y, y = y + Phi*v
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::collections::HashMap;

use nalgebra::DMatrix;
use num_traits::ToPrimitive;
use poly::advanced::Operand;
use poly::{Method, Poly, Sym, Q};

use crate::error::Error;

/// Lanes per block in [`Step::advance_batch`]: small enough that the
/// registers of a block stay in L1 cache, wide enough to amortise the
/// dispatch of each instruction.
pub const BLOCK: usize = 256;

pub use poly::Params;

/// The `f64` view of the one exact parameter type, [`poly::Params`].
///
/// Values set from an `f64` are stored exactly (every finite `f64` is a
/// rational); values read as `f64` are the nearest double to the exact
/// value. A decimal a user typed (parsed exactly by `poly`) therefore stays
/// the decimal on the exact side, and the numeric side sees its nearest
/// double.
pub trait ParamsF64: Sized {
    /// Only `Phi` set.
    ///
    /// # Panics
    /// When `phi` is not finite: validate user input at the boundary.
    fn phi(phi: f64) -> Self;

    /// This set with `name = value` added or replaced.
    ///
    /// # Panics
    /// When `value` is not finite: validate user input at the boundary
    /// (or use [`ParamsF64::try_with`]).
    fn with(self, name: &str, value: f64) -> Self;

    /// [`ParamsF64::with`], refusing a value that is not finite.
    fn try_with(self, name: &str, value: f64) -> Result<Self, Error>;

    /// Sets `name = value` (see [`ParamsF64::with`]).
    fn set(&mut self, name: &str, value: f64);

    /// The value of `name` as the nearest `f64`, if set.
    fn get(&self, name: &str) -> Option<f64>;

    /// The value of `Phi` as the nearest `f64` (NaN when unset).
    fn phi_value(&self) -> f64;

    /// Every `(name, value)` pair as `f64`, sorted by name.
    fn iter_f64(&self) -> Vec<(&'static str, f64)>;

    /// The values of `method`'s parameters in [`Method::params`] order.
    fn values_for(&self, method: &Method) -> Result<Vec<f64>, Error>;

    /// The exact values of the parameters `syms` of the method named
    /// `method`.
    ///
    /// This is the one parameter lookup of the crate: the compiled step, the
    /// exact reference and the classifier all bind parameters through it.
    fn exact_values(&self, method: &str, syms: &[Sym]) -> Result<HashMap<Sym, Q>, Error>;
}

impl ParamsF64 for Params {
    fn phi(phi: f64) -> Params {
        Params::new().with("Phi", phi)
    }

    fn with(mut self, name: &str, value: f64) -> Params {
        ParamsF64::set(&mut self, name, value);
        self
    }

    fn try_with(self, name: &str, value: f64) -> Result<Params, Error> {
        match f64_to_q(value) {
            Some(x) => Ok(self.bind(name, x)),
            None => Err(Error::not_finite(&format!("parameter `{name}`"))),
        }
    }

    fn set(&mut self, name: &str, value: f64) {
        let x =
            f64_to_q(value).unwrap_or_else(|| panic!("parameter `{name}` = {value} is not finite"));
        self.insert(name, x);
    }

    fn get(&self, name: &str) -> Option<f64> {
        self.value(name).map(q_to_f64)
    }

    fn phi_value(&self) -> f64 {
        ParamsF64::get(self, "Phi").unwrap_or(f64::NAN)
    }

    fn iter_f64(&self) -> Vec<(&'static str, f64)> {
        self.iter().map(|(k, v)| (k, q_to_f64(v))).collect()
    }

    fn values_for(&self, method: &Method) -> Result<Vec<f64>, Error> {
        method
            .params()
            .iter()
            .map(|s| {
                ParamsF64::get(self, s.name())
                    .ok_or_else(|| Error::missing_param(method.name(), s.name()))
            })
            .collect()
    }

    fn exact_values(&self, method: &str, syms: &[Sym]) -> Result<HashMap<Sym, Q>, Error> {
        self.values_of(syms).map_err(|name| Error::missing_param(method, name))
    }
}

/// Evaluates a polynomial in the parameters at numeric values: each term's
/// rational coefficient is rounded to the nearest `f64`, multiplied by the
/// powers of the parameter values, and the terms are summed in order.
///
/// Errors when a symbol of `p` has no value in `params`.
pub fn eval_poly(p: &Poly, params: &Params) -> Result<f64, Error> {
    let mut sum = 0.0;
    for (mono, c) in p.terms() {
        let mut term = q_to_f64(c);
        for &(sym, exp) in mono.factors() {
            // An exact constant's generator p^(1/L) has a value of its own.
            let x = match params.get(sym.name()) {
                Some(x) => x,
                None => poly::advanced::field::generator_value(sym)
                    .map(|q| q_to_f64(&q))
                    .ok_or_else(|| Error::missing_param("(polynomial)", sym.name()))?,
            };
            term *= x.powi(exp as i32);
        }
        sum += term;
    }
    Ok(sum)
}

/// The `f64` nearest to an exact rational (saturating to ±∞ beyond range).
pub fn q_to_f64(c: &poly::Q) -> f64 {
    c.to_f64().unwrap_or_else(|| {
        if c < &poly::Q::from_integer(0.into()) {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        }
    })
}

/// The exact rational value of a finite `f64` (None for NaN or ±∞).
pub fn f64_to_q(x: f64) -> Option<poly::Q> {
    poly::Q::from_float(x)
}

/// The decimal a finite `f64` was typed as: the shortest decimal that
/// reads back as `x` (Rust's `Display` of an `f64`), exactly, so `0.1` is
/// 1/10 and not 3602879701896397/36028797018963968 (None for NaN or ±∞).
/// The value a user wrote in a scene or on the command line is this one.
pub fn f64_to_decimal_q(x: f64) -> Option<poly::Q> {
    if !x.is_finite() {
        return None;
    }
    let q = poly::advanced::parse_number(&format!("{}", x.abs())).ok()?;
    Some(if x.is_sign_negative() { -q } else { q })
}

/// One instruction: `dst = Σ coef[i]·reg[src[i]]` over `len` terms (or
/// `dst += ...` when `accumulate`). When `unit_first`, `coef[0]` is exactly
/// 1 and the first product is skipped.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Instr {
    pub(crate) dst: usize,
    pub(crate) src: [usize; 4],
    pub(crate) coef: [f64; 4],
    pub(crate) len: u8,
    pub(crate) unit_first: bool,
    pub(crate) accumulate: bool,
    /// Where each coefficient came from: (assignment, term) of the method.
    pub(crate) origin: [(usize, usize); 4],
}

/// Appends the instructions for `dst = Σ c·reg[src]`; each term carries its
/// origin (assignment, term) in the method, `(k, usize::MAX)` for none.
fn push_sum(
    instrs: &mut Vec<Instr>,
    dst: usize,
    k: usize,
    mut terms: Vec<(usize, f64, (usize, usize))>,
) {
    // A unit coefficient first saves a multiplication; the sum is
    // then `a + c1*b + ...`, as a hand-written update reads.
    if let Some(i) = terms.iter().position(|&(_, c, _)| c == 1.0) {
        let t = terms.remove(i);
        terms.insert(0, t);
    }
    if terms.is_empty() {
        instrs.push(Instr {
            dst,
            src: [0; 4],
            coef: [0.0; 4],
            len: 1,
            unit_first: false,
            accumulate: false,
            origin: [(k, usize::MAX); 4],
        });
    }
    for (chunk_idx, chunk) in terms.chunks(4).enumerate() {
        let mut src = [0usize; 4];
        let mut coef = [0.0f64; 4];
        let mut origin = [(k, usize::MAX); 4];
        for (i, &(s, c, o)) in chunk.iter().enumerate() {
            src[i] = s;
            coef[i] = c;
            origin[i] = o;
        }
        instrs.push(Instr {
            dst,
            src,
            coef,
            len: chunk.len() as u8,
            unit_first: chunk_idx == 0 && coef[0] == 1.0,
            accumulate: chunk_idx > 0,
            origin,
        });
    }
}

/// A⁻¹E of an implicit step (unknowns as a linear map of the slots), by
/// one LU factorisation of A at the compiled parameters.
fn implicit_solution(
    method: &Method,
    coef_of: &dyn Fn(&Poly) -> Result<f64, Error>,
    n_slots: usize,
    slot_reg: &dyn Fn(usize, u32) -> usize,
) -> Result<DMatrix<f64>, Error> {
    let n_u = method.unknowns().len();
    let width = n_slots + n_u;
    let form = |terms: &[(Operand, Poly)], values: &[Vec<f64>]| -> Result<Vec<f64>, Error> {
        let mut acc = vec![0.0; width];
        for (op, c) in terms {
            let c = coef_of(c)?;
            match *op {
                Operand::Start { var, lag } => acc[slot_reg(var, lag)] += c,
                Operand::Unknown(u) => acc[n_slots + u] += c,
                Operand::Stmt(t) => {
                    for (a, v) in acc.iter_mut().zip(&values[t]) {
                        *a += c * v;
                    }
                }
            }
        }
        Ok(acc)
    };
    let mut values: Vec<Vec<f64>> = Vec::with_capacity(method.assigns().len());
    for a in method.assigns() {
        let v = form(&a.terms, &values)?;
        values.push(v);
    }
    let mut a = DMatrix::<f64>::identity(n_u, n_u);
    let mut e = DMatrix::<f64>::zeros(n_u, n_slots);
    for eq in method.equations() {
        let r = form(&eq.terms, &values)?;
        for (i, x) in r.into_iter().enumerate() {
            if i < n_slots {
                e[(eq.unknown, i)] = x;
            } else {
                a[(eq.unknown, i - n_slots)] -= x;
            }
        }
    }
    let phi = coef_of(&Poly::sym(poly::Sym::phi()))?;
    let singular = || Error::singular(method.name(), phi);
    let solved = a.lu().solve(&e).ok_or_else(singular)?;
    if solved.iter().any(|x| !x.is_finite()) {
        return Err(singular());
    }
    Ok(solved)
}

/// A register move done at the end of a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Move {
    Swap(usize, usize),
    Copy { dst: usize, src: usize },
}

/// A method compiled to `f64` instructions at fixed parameter values.
#[derive(Clone, Debug)]
pub struct Step {
    name: String,
    slot_names: Vec<String>,
    n_slots: usize,
    n_regs: usize,
    instrs: Vec<Instr>,
    moves: Vec<Move>,
    params: Params,
}

impl Step {
    /// Compiles `method` at the parameter values `params`.
    ///
    /// Errors when a parameter of the method has no value.
    pub fn compile(method: &Method, params: &Params) -> Result<Step, Error> {
        let values = params.values_for(method)?;
        let named: Params = method
            .params()
            .iter()
            .zip(&values)
            .fold(Params::default(), |acc, (s, &v)| acc.with(s.name(), v));
        let slots = method.slots();
        let n_slots = slots.len();
        let slot_reg = |var: usize, lag: u32| {
            slots.iter().position(|&s| s == (var, lag)).expect("lag within the method's history")
        };
        let n_assign = method.assigns().len();
        let unknown_reg = |u: usize| n_slots + n_assign + u;
        let coef_of = |c: &Poly| eval_poly(c, &named);
        let mut instrs = Vec::new();
        // An implicit step first solves its linear system: u = A⁻¹E·s, with
        // A⁻¹E from one LU factorisation at these parameters, so each step
        // costs one matrix-vector product.
        if method.is_implicit() {
            let solve = implicit_solution(method, &coef_of, n_slots, &slot_reg)?;
            for u in 0..method.unknowns().len() {
                let terms: Vec<(usize, f64, (usize, usize))> = (0..n_slots)
                    .map(|j| (j, solve[(u, j)], (usize::MAX, usize::MAX)))
                    .filter(|&(_, c, _)| c != 0.0)
                    .collect();
                push_sum(&mut instrs, unknown_reg(u), usize::MAX, terms);
            }
        }
        for (k, a) in method.assigns().iter().enumerate() {
            let dst = n_slots + k;
            let mut terms: Vec<(usize, f64, (usize, usize))> = Vec::with_capacity(a.terms.len());
            for (t_idx, (op, c)) in a.terms.iter().enumerate() {
                let src = match *op {
                    Operand::Start { var, lag } => slot_reg(var, lag),
                    Operand::Stmt(t) => n_slots + t,
                    Operand::Unknown(u) => unknown_reg(u),
                };
                terms.push((src, coef_of(c)?, (k, t_idx)));
            }
            push_sum(&mut instrs, dst, k, terms);
        }
        // End of step: shift each variable's history one lag deeper and put
        // its new value in slot lag 0. Swaps rotate the registers, so the
        // register that held the final assignment receives a stale value it
        // overwrites next step before anything reads it.
        let mut moves = Vec::new();
        for (var, &depth) in method.history().iter().enumerate() {
            let end_reg = match method.end_value(var) {
                poly::advanced::EndValue::Assign(k) => Some(n_slots + k),
                poly::advanced::EndValue::Unknown(u) => Some(unknown_reg(u)),
                poly::advanced::EndValue::Kept => None,
            };
            match end_reg {
                Some(r) => {
                    for lag in (1..=depth).rev() {
                        moves.push(Move::Swap(slot_reg(var, lag), slot_reg(var, lag - 1)));
                    }
                    moves.push(Move::Swap(slot_reg(var, 0), r));
                }
                None => {
                    for lag in (1..=depth).rev() {
                        moves.push(Move::Copy {
                            dst: slot_reg(var, lag),
                            src: slot_reg(var, lag - 1),
                        });
                    }
                }
            }
        }
        let slot_names = slots
            .iter()
            .map(|&(var, lag)| method.operand_name(Operand::Start { var, lag }))
            .collect();
        Ok(Step {
            name: method.name().to_owned(),
            slot_names,
            n_slots,
            n_regs: n_slots + n_assign + method.unknowns().len(),
            instrs,
            moves,
            params: named,
        })
    }

    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The order N: the number of slots of the augmented state.
    pub fn order(&self) -> usize {
        self.n_slots
    }

    /// Slot names in state order: `v`, `y`, `y@1`, ...
    pub fn slot_names(&self) -> &[String] {
        &self.slot_names
    }

    /// The parameter values the step was compiled at (only the method's).
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// The instructions of one step, in order.
    pub(crate) fn instrs(&self) -> &[Instr] {
        &self.instrs
    }

    /// The end-of-step register moves, in order.
    pub(crate) fn moves(&self) -> &[Move] {
        &self.moves
    }

    /// Registers: the slots, then one per assignment.
    pub(crate) fn n_regs(&self) -> usize {
        self.n_regs
    }

    /// The instructions and end-of-step moves as data, for printing the step
    /// as source code in another language.
    pub fn listing(&self) -> Listing {
        let instrs = self
            .instrs
            .iter()
            .map(|ins| Listed {
                dst: ins.dst,
                terms: (0..ins.len as usize)
                    .map(|i| ListedTerm {
                        src: ins.src[i],
                        coef: ins.coef[i],
                        origin: (ins.origin[i].1 != usize::MAX).then_some(ins.origin[i]),
                    })
                    .collect(),
                unit_first: ins.unit_first,
                accumulate: ins.accumulate,
            })
            .collect();
        let moves = self
            .moves
            .iter()
            .map(|m| match *m {
                Move::Swap(a, b) => ListedMove::Swap(a, b),
                Move::Copy { dst, src } => ListedMove::Copy { dst, src },
            })
            .collect();
        Listing { n_slots: self.n_slots, n_regs: self.n_regs, instrs, moves }
    }

    /// The number of instructions per step (a cost measure).
    pub fn n_instructions(&self) -> usize {
        self.instrs.len()
    }

    /// A single state starting from `initial` (one value per slot).
    #[track_caller]
    pub fn state(&self, initial: &[f64]) -> State {
        assert_eq!(initial.len(), self.n_slots, "one initial value per slot");
        let mut regs = vec![0.0; self.n_regs];
        regs[..self.n_slots].copy_from_slice(initial);
        State { regs, n_slots: self.n_slots }
    }

    /// Advances one state by `n_steps` steps.
    #[track_caller]
    pub fn advance(&self, state: &mut State, n_steps: u64) {
        assert_eq!(state.regs.len(), self.n_regs, "state made by this step");
        let regs = &mut state.regs[..];
        for _ in 0..n_steps {
            for ins in &self.instrs {
                let r = &*regs;
                let (s, c) = (&ins.src, &ins.coef);
                let v = if ins.accumulate {
                    accumulate_scalar(r[ins.dst], ins, r)
                } else {
                    let first = if ins.unit_first { r[s[0]] } else { c[0] * r[s[0]] };
                    match ins.len {
                        1 => first,
                        2 => first + c[1] * r[s[1]],
                        3 => first + c[1] * r[s[1]] + c[2] * r[s[2]],
                        _ => first + c[1] * r[s[1]] + c[2] * r[s[2]] + c[3] * r[s[3]],
                    }
                };
                regs[ins.dst] = v;
            }
            for m in &self.moves {
                match *m {
                    Move::Swap(a, b) => regs.swap(a, b),
                    Move::Copy { dst, src } => regs[dst] = regs[src],
                }
            }
        }
    }

    /// Advances every lane of `batch` by `n_steps` steps.
    #[track_caller]
    pub fn advance_batch(&self, batch: &mut Batch, n_steps: u64) {
        assert_eq!(batch.n_slots, self.n_slots, "batch made for this step");
        let lanes = batch.lanes;
        let mut regs: Vec<Vec<f64>> = vec![vec![0.0; BLOCK]; self.n_regs];
        let mut start = 0;
        while start < lanes {
            let width = BLOCK.min(lanes - start);
            for (s, reg) in regs.iter_mut().enumerate().take(self.n_slots) {
                reg[..width].copy_from_slice(&batch.data[s * lanes + start..][..width]);
                reg[width..].fill(0.0);
            }
            for _ in 0..n_steps {
                run_block::<BLOCK>(&self.instrs, &mut regs);
                for m in &self.moves {
                    match *m {
                        Move::Swap(a, b) => regs.swap(a, b),
                        Move::Copy { dst, src } => {
                            let v = std::mem::take(&mut regs[dst]);
                            let mut v = v;
                            v.copy_from_slice(&regs[src]);
                            regs[dst] = v;
                        }
                    }
                }
            }
            for (s, reg) in regs.iter().enumerate().take(self.n_slots) {
                batch.data[s * lanes + start..][..width].copy_from_slice(&reg[..width]);
            }
            start += width;
        }
    }

    /// The numeric transition matrix P: column `j` is one step from `e_j`.
    pub fn transition_matrix(&self) -> DMatrix<f64> {
        let n = self.n_slots;
        let mut p = DMatrix::zeros(n, n);
        let mut e = vec![0.0; n];
        for j in 0..n {
            e.iter_mut().for_each(|x| *x = 0.0);
            e[j] = 1.0;
            let mut s = self.state(&e);
            self.advance(&mut s, 1);
            for (i, &x) in s.slots().iter().enumerate() {
                p[(i, j)] = x;
            }
        }
        p
    }
}

fn accumulate_scalar(old: f64, ins: &Instr, r: &[f64]) -> f64 {
    let (s, c) = (&ins.src, &ins.coef);
    let mut v = old + c[0] * r[s[0]];
    for i in 1..ins.len as usize {
        v += c[i] * r[s[i]];
    }
    v
}

/// Runs every instruction once on a block of `B` lanes.
fn run_block<const B: usize>(instrs: &[Instr], regs: &mut [Vec<f64>]) {
    for ins in instrs {
        // Taking the destination out of the register file lets the sources
        // be borrowed at the same time; a destination is never its own source.
        let mut dst = std::mem::take(&mut regs[ins.dst]);
        {
            let d: &mut [f64; B] = (&mut dst[..]).try_into().expect("block width");
            let r =
                |i: usize| -> &[f64; B] { regs[ins.src[i]][..].try_into().expect("block width") };
            let c = ins.coef;
            match (ins.len, ins.unit_first, ins.accumulate) {
                (_, _, true) => {
                    for (i, &ci) in c.iter().enumerate().take(ins.len as usize) {
                        add_scaled(d, ci, r(i));
                    }
                }
                (1, true, _) => d.copy_from_slice(r(0)),
                (1, false, _) => lin::<B, 1, false>(d, &c, [r(0)]),
                (2, true, _) => lin::<B, 2, true>(d, &c, [r(0), r(1)]),
                (2, false, _) => lin::<B, 2, false>(d, &c, [r(0), r(1)]),
                (3, true, _) => lin::<B, 3, true>(d, &c, [r(0), r(1), r(2)]),
                (3, false, _) => lin::<B, 3, false>(d, &c, [r(0), r(1), r(2)]),
                (_, true, _) => lin::<B, 4, true>(d, &c, [r(0), r(1), r(2), r(3)]),
                (_, false, _) => lin::<B, 4, false>(d, &c, [r(0), r(1), r(2), r(3)]),
            }
        }
        regs[ins.dst] = dst;
    }
}

#[inline(always)]
fn add_scaled<const B: usize>(d: &mut [f64; B], c: f64, a: &[f64; B]) {
    for l in 0..B {
        d[l] += c * a[l];
    }
}

/// `d = Σ c[i]·src[i]` over the `N` sources, summed left to right (the
/// order of the single-state runner); with `UNIT` the first coefficient is
/// exactly 1 and its product is skipped.
#[inline(always)]
fn lin<const B: usize, const N: usize, const UNIT: bool>(
    d: &mut [f64; B],
    c: &[f64; 4],
    src: [&[f64; B]; N],
) {
    for l in 0..B {
        let mut v = if UNIT { src[0][l] } else { c[0] * src[0][l] };
        for i in 1..N {
            v += c[i] * src[i][l];
        }
        d[l] = v;
    }
}

/// A compiled step as data ([`Step::listing`]): registers `0..n_slots` are
/// the slots, the rest one per assignment.
#[derive(Clone, Debug, PartialEq)]
pub struct Listing {
    /// Slots of the augmented state.
    pub n_slots: usize,
    /// Registers in all.
    pub n_regs: usize,
    /// The instructions in order.
    pub instrs: Vec<Listed>,
    /// The end-of-step moves in order.
    pub moves: Vec<ListedMove>,
}

/// One instruction: `dst = Σ coef·src` (or `dst += ...` when `accumulate`),
/// summed left to right; when `unit_first` the first term's coefficient is
/// exactly 1 and its product is skipped.
#[derive(Clone, Debug, PartialEq)]
pub struct Listed {
    /// Destination register.
    pub dst: usize,
    /// The terms, in order.
    pub terms: Vec<ListedTerm>,
    /// The first term is taken without multiplying.
    pub unit_first: bool,
    /// Adds to the destination's value.
    pub accumulate: bool,
}

/// One term of an instruction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ListedTerm {
    /// Source register.
    pub src: usize,
    /// Coefficient at the compiled parameter values.
    pub coef: f64,
    /// `(assignment, term)` of [`Method::assigns`] the coefficient is the
    /// value of (`None` for the zero of an empty sum).
    pub origin: Option<(usize, usize)>,
}

/// An end-of-step register move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ListedMove {
    /// Exchange two registers.
    Swap(usize, usize),
    /// `dst = src`.
    Copy {
        /// Destination.
        dst: usize,
        /// Source.
        src: usize,
    },
}

/// One state of a compiled method: the slots plus the step's scratch
/// registers. Made by [`Step::state`].
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    regs: Vec<f64>,
    n_slots: usize,
}

impl State {
    /// The augmented state, in [`Step::slot_names`] order.
    pub fn slots(&self) -> &[f64] {
        &self.regs[..self.n_slots]
    }

    /// The augmented state, writable (for renormalising or resetting).
    pub fn slots_mut(&mut self) -> &mut [f64] {
        &mut self.regs[..self.n_slots]
    }

    /// Every register, writable (for the native compiler's runner).
    #[cfg(feature = "jit")]
    pub(crate) fn regs_mut(&mut self) -> &mut [f64] {
        &mut self.regs
    }
}

/// Many states of one compiled method, stored struct-of-arrays: slot `s` of
/// every lane is contiguous.
#[derive(Clone, Debug, PartialEq)]
pub struct Batch {
    lanes: usize,
    n_slots: usize,
    data: Vec<f64>,
}

impl Batch {
    /// `lanes` states of `step`, all zero.
    pub fn zeros(step: &Step, lanes: usize) -> Batch {
        Batch { lanes, n_slots: step.n_slots, data: vec![0.0; lanes * step.n_slots] }
    }

    /// The number of states.
    pub fn lanes(&self) -> usize {
        self.lanes
    }

    /// Slot `slot` of every lane.
    pub fn slot(&self, slot: usize) -> &[f64] {
        &self.data[slot * self.lanes..][..self.lanes]
    }

    /// Slot `slot` of every lane, writable.
    pub fn slot_mut(&mut self, slot: usize) -> &mut [f64] {
        &mut self.data[slot * self.lanes..][..self.lanes]
    }

    /// Sets every slot of lane `lane`.
    #[track_caller]
    pub fn set_lane(&mut self, lane: usize, values: &[f64]) {
        assert_eq!(values.len(), self.n_slots, "one value per slot");
        for (s, &v) in values.iter().enumerate() {
            self.data[s * self.lanes + lane] = v;
        }
    }

    /// Every slot of lane `lane`.
    pub fn lane(&self, lane: usize) -> Vec<f64> {
        (0..self.n_slots).map(|s| self.data[s * self.lanes + lane]).collect()
    }

    /// The slots of every lane (`data[s * lanes + l]`) and the slot count,
    /// writable (for the native compiler's runner).
    #[cfg(feature = "jit")]
    pub(crate) fn data_mut(&mut self) -> (&mut [f64], usize) {
        (&mut self.data, self.n_slots)
    }
}

/// Initial slot values from one value per state variable: every lag of a
/// variable starts at the variable's value (for Verlet, `y@1 = y0`, the
/// paper's `y2:=1 { v0=0 }`).
pub fn initial_slots(method: &Method, value_of: impl Fn(&str) -> f64) -> Vec<f64> {
    method.slots().iter().map(|&(var, _)| value_of(&method.state()[var])).collect()
}
