//! The specialised step: a [`Step`] rewritten for speed, in `f64` or `f32`,
//! bit-for-bit the interpreter's operations in the interpreter's order.
//!
//! [`Kernel::new`] takes the instruction list of a compiled [`Step`] and
//! removes what costs time without computing anything:
//!
//! * **No moves.** The interpreter ends each step by swapping registers
//!   (`v ← v1`, `y@1 ← y`). Here the swaps become a renaming of registers
//!   at compile time: the step is unrolled over the period of that renaming
//!   (2 for False Euler, 3 for Verlet, at most [`MAX_UNROLL`]), so after a
//!   whole period every slot is back in its own register and no value is
//!   ever moved at run time. A method whose renaming does not come back
//!   within [`MAX_UNROLL`] steps ends each step with explicit copies.
//! * **One specialised operation per instruction.** Each instruction is
//!   matched once, at compile time, to an [`Op`] variant (`a + c·b`,
//!   `c₀·a + c₁·b + c₂·e`, ...), with its coefficients already rounded to
//!   the precision `T`.
//! * **Lanes in SIMD registers.** The batch runner keeps a block of 16 or
//!   64 lanes per register, runs every requested step on a block while it
//!   sits in L1 cache, and is compiled three times (baseline, AVX2,
//!   AVX-512F) with the widest chosen at run time, so each operation is a
//!   few full-width vector instructions.
//!
//! Every operation is the interpreter's: the same products summed left to
//! right, no fused multiply-add, so `Kernel::<f64>` agrees with
//! [`Step::advance`] bit for bit (tested on every built-in and on
//! generated programs). `Kernel::<f32>` runs the same operations in `f32`,
//! each coefficient rounded from its `f64` value.
//!
//! ```
//! use check::kernel::Kernel;
//! use check::numeric::{Params, ParamsF64, Step};
//! let step = Step::compile(&poly::builtin("false_euler")?, &Params::phi(0.5))?;
//! let kernel = Kernel::<f64>::new(&step);
//! let mut state = kernel.state(&[0.0, 1.0]);
//! kernel.advance(&mut state, 1);
//! assert_eq!(state.slots(), [-0.5, 0.75]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fmt;
use std::ops::{Add, Mul};

use crate::numeric::{Instr, Move, Step};

/// The longest unrolled period of the register renaming.
pub const MAX_UNROLL: usize = 8;

/// A floating-point type a [`Kernel`] runs in: `f64` or `f32`.
pub trait Real:
    Copy
    + Default
    + PartialEq
    + PartialOrd
    + fmt::Debug
    + fmt::Display
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Mul<Output = Self>
    + private::Sealed
{
    /// The type's name, `"f64"` or `"f32"`.
    const NAME: &'static str;
    /// Machine epsilon (the gap between 1 and the next number), as `f64`.
    const EPSILON: f64;
    /// The nearest value to `x`.
    fn from_f64(x: f64) -> Self;
    /// The exact value as `f64`.
    fn to_f64(self) -> f64;
}

mod private {
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for f32 {}
}

impl Real for f64 {
    const NAME: &'static str = "f64";
    const EPSILON: f64 = f64::EPSILON;
    fn from_f64(x: f64) -> f64 {
        x
    }
    fn to_f64(self) -> f64 {
        self
    }
}

impl Real for f32 {
    const NAME: &'static str = "f32";
    const EPSILON: f64 = f32::EPSILON as f64;
    fn from_f64(x: f64) -> f32 {
        x as f32
    }
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
}

/// One specialised operation on registers (`d` is the destination).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op<T> {
    /// `d = a`.
    Mov {
        /// Destination.
        d: u32,
        /// Source.
        a: u32,
    },
    /// `d = c0·a`.
    Scale {
        /// Destination.
        d: u32,
        /// Coefficient.
        c0: T,
        /// Source.
        a: u32,
    },
    /// `d = a + c1·b`.
    Add2 {
        /// Destination.
        d: u32,
        /// Unit-coefficient source.
        a: u32,
        /// Coefficient of `b`.
        c1: T,
        /// Source.
        b: u32,
    },
    /// `d = c0·a + c1·b`.
    Lin2 {
        /// Destination.
        d: u32,
        /// Coefficients.
        c: [T; 2],
        /// Sources.
        s: [u32; 2],
    },
    /// `d = a + c1·b + c2·e`.
    Add3 {
        /// Destination.
        d: u32,
        /// Coefficients of the second and third source.
        c: [T; 2],
        /// Sources (the first has coefficient 1).
        s: [u32; 3],
    },
    /// `d = c0·a + c1·b + c2·e`.
    Lin3 {
        /// Destination.
        d: u32,
        /// Coefficients.
        c: [T; 3],
        /// Sources.
        s: [u32; 3],
    },
    /// `d = a + c1·b + c2·e + c3·g`.
    Add4 {
        /// Destination.
        d: u32,
        /// Coefficients of the second to fourth source.
        c: [T; 3],
        /// Sources (the first has coefficient 1).
        s: [u32; 4],
    },
    /// `d = c0·a + c1·b + c2·e + c3·g`.
    Lin4 {
        /// Destination.
        d: u32,
        /// Coefficients.
        c: [T; 4],
        /// Sources.
        s: [u32; 4],
    },
    /// `d = d + c·a` (a sum longer than four terms goes on).
    Acc {
        /// Destination, also the first addend.
        d: u32,
        /// Coefficient.
        c: T,
        /// Source.
        a: u32,
    },
}

impl<T: Real> Op<T> {
    /// The destination register.
    pub fn dst(&self) -> usize {
        (match *self {
            Op::Mov { d, .. }
            | Op::Scale { d, .. }
            | Op::Add2 { d, .. }
            | Op::Lin2 { d, .. }
            | Op::Add3 { d, .. }
            | Op::Lin3 { d, .. }
            | Op::Add4 { d, .. }
            | Op::Lin4 { d, .. }
            | Op::Acc { d, .. } => d,
        }) as usize
    }

    /// Multiplications and additions this operation performs.
    pub fn flops(&self) -> (u32, u32) {
        match self {
            Op::Mov { .. } => (0, 0),
            Op::Scale { .. } => (1, 0),
            Op::Add2 { .. } => (1, 1),
            Op::Lin2 { .. } => (2, 1),
            Op::Add3 { .. } => (2, 2),
            Op::Lin3 { .. } => (3, 2),
            Op::Add4 { .. } => (3, 3),
            Op::Lin4 { .. } => (4, 3),
            Op::Acc { .. } => (1, 1),
        }
    }

    /// Evaluates on scalar registers (the definition every runner follows).
    #[inline(always)]
    fn eval(&self, r: &[T]) -> T {
        let g = |i: u32| r[i as usize];
        match *self {
            Op::Mov { a, .. } => g(a),
            Op::Scale { c0, a, .. } => c0 * g(a),
            Op::Add2 { a, c1, b, .. } => g(a) + c1 * g(b),
            Op::Lin2 { c, s, .. } => c[0] * g(s[0]) + c[1] * g(s[1]),
            Op::Add3 { c, s, .. } => g(s[0]) + c[0] * g(s[1]) + c[1] * g(s[2]),
            Op::Lin3 { c, s, .. } => c[0] * g(s[0]) + c[1] * g(s[1]) + c[2] * g(s[2]),
            Op::Add4 { c, s, .. } => g(s[0]) + c[0] * g(s[1]) + c[1] * g(s[2]) + c[2] * g(s[3]),
            Op::Lin4 { c, s, .. } => {
                c[0] * g(s[0]) + c[1] * g(s[1]) + c[2] * g(s[2]) + c[3] * g(s[3])
            }
            Op::Acc { d, c, a } => g(d) + c * g(a),
        }
    }
}

/// The operations of one instruction, registers renamed by `name`.
fn translate<T: Real>(ins: &Instr, name: &[u32], out: &mut Vec<Op<T>>) {
    let d = name[ins.dst];
    let s = |i: usize| name[ins.src[i]];
    let c = |i: usize| T::from_f64(ins.coef[i]);
    if ins.accumulate {
        for i in 0..ins.len as usize {
            out.push(Op::Acc { d, c: c(i), a: s(i) });
        }
        return;
    }
    out.push(match (ins.len, ins.unit_first) {
        (1, true) => Op::Mov { d, a: s(0) },
        (1, false) => Op::Scale { d, c0: c(0), a: s(0) },
        (2, true) => Op::Add2 { d, a: s(0), c1: c(1), b: s(1) },
        (2, false) => Op::Lin2 { d, c: [c(0), c(1)], s: [s(0), s(1)] },
        (3, true) => Op::Add3 { d, c: [c(1), c(2)], s: [s(0), s(1), s(2)] },
        (3, false) => Op::Lin3 { d, c: [c(0), c(1), c(2)], s: [s(0), s(1), s(2)] },
        (_, true) => Op::Add4 { d, c: [c(1), c(2), c(3)], s: [s(0), s(1), s(2), s(3)] },
        (_, false) => Op::Lin4 { d, c: [c(0), c(1), c(2), c(3)], s: [s(0), s(1), s(2), s(3)] },
    });
}

/// A [`Step`] specialised for speed in precision `T` (see the module docs).
#[derive(Clone, Debug)]
pub struct Kernel<T> {
    name: String,
    n_slots: usize,
    n_regs: usize,
    /// The unrolled period: `period` steps of `step_ops` operations each.
    ops: Vec<Op<T>>,
    step_ops: usize,
    period: usize,
    /// `maps[r][s]`: the register holding slot `s` after `r` steps of a
    /// period (`maps[0]` is the identity).
    maps: Vec<Vec<u32>>,
}

impl<T: Real> Kernel<T> {
    /// Specialises `step`.
    pub fn new(step: &Step) -> Kernel<T> {
        let n = step.order();
        let mut n_regs = step.n_regs();
        let mut name: Vec<u32> = (0..n_regs as u32).collect();
        let identity: Vec<u32> = (0..n as u32).collect();
        let mut ops = Vec::new();
        let mut maps = vec![identity.clone()];
        let mut step_ops = 0;
        let mut period = 0;
        for r in 1..=MAX_UNROLL {
            let before = ops.len();
            for ins in step.instrs() {
                translate(ins, &name, &mut ops);
            }
            for m in step.moves() {
                match *m {
                    Move::Swap(a, b) => name.swap(a, b),
                    Move::Copy { dst, src } => {
                        ops.push(Op::Mov { d: name[dst], a: name[src] });
                    }
                }
            }
            step_ops = ops.len() - before;
            maps.push(name[..n].to_vec());
            if name[..n] == identity[..] {
                period = r;
                break;
            }
        }
        if period == 0 {
            // No short period: one step, then put every slot back through
            // fresh scratch registers (a permutation cannot be done in place
            // by plain copies).
            ops.truncate(step_ops);
            let first = maps[1].clone();
            for (s, &p) in first.iter().enumerate() {
                ops.push(Op::Mov { d: (n_regs + s) as u32, a: p });
            }
            for s in 0..n {
                ops.push(Op::Mov { d: s as u32, a: (n_regs + s) as u32 });
            }
            n_regs += n;
            step_ops = ops.len();
            period = 1;
            maps = vec![identity.clone(), identity];
        }
        for op in &ops {
            let d = op.dst() as u32;
            let sources: Vec<u32> = match *op {
                Op::Mov { a, .. } | Op::Scale { a, .. } | Op::Acc { a, .. } => vec![a],
                Op::Add2 { a, b, .. } => vec![a, b],
                Op::Lin2 { s, .. } => s.to_vec(),
                Op::Add3 { s, .. } | Op::Lin3 { s, .. } => s.to_vec(),
                Op::Add4 { s, .. } | Op::Lin4 { s, .. } => s.to_vec(),
            };
            // The batch runner relies on both (see `run_block`).
            assert!((d as usize) < n_regs, "destination within the registers");
            for src in sources {
                assert!((src as usize) < n_regs && src != d, "a source is another register");
            }
        }
        Kernel { name: step.name().to_owned(), n_slots: n, n_regs, ops, step_ops, period, maps }
    }

    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The number of slots of the augmented state.
    pub fn order(&self) -> usize {
        self.n_slots
    }

    /// The operations of one step (the first of the unrolled period).
    pub fn step_ops(&self) -> &[Op<T>] {
        &self.ops[..self.step_ops]
    }

    /// Steps per unrolled period.
    pub fn period(&self) -> usize {
        self.period
    }

    /// Registers used (slots, scratch, renamed).
    pub fn n_regs(&self) -> usize {
        self.n_regs
    }

    /// The exact transition matrix of this kernel's step: the same
    /// operations in exact rational arithmetic, with the coefficients as
    /// rounded to `T` (so it is the matrix the rounded program would apply
    /// without any rounding of its own).
    pub fn exact_transition(&self) -> Vec<Vec<poly::Q>> {
        use num_traits::Zero;
        let n = self.n_slots;
        let q = |x: T| poly::Q::from_float(x.to_f64()).expect("finite coefficient");
        let mut p = vec![vec![poly::Q::zero(); n]; n];
        for j in 0..n {
            let mut regs = vec![poly::Q::zero(); self.n_regs];
            regs[j] = poly::Q::from_integer(1.into());
            for op in self.step_ops() {
                let g = |i: u32| &regs[i as usize];
                let lin = |c: &[T], s: &[u32], unit: bool| -> poly::Q {
                    let mut sum = if unit { g(s[0]).clone() } else { q(c[0]) * g(s[0]) };
                    let off = usize::from(!unit);
                    for (k, &si) in s.iter().enumerate().skip(1) {
                        sum += q(c[k - 1 + off]) * g(si);
                    }
                    sum
                };
                let v = match *op {
                    Op::Mov { a, .. } => g(a).clone(),
                    Op::Scale { c0, a, .. } => q(c0) * g(a),
                    Op::Add2 { a, c1, b, .. } => lin(&[c1], &[a, b], true),
                    Op::Lin2 { c, s, .. } => lin(&c, &s, false),
                    Op::Add3 { c, s, .. } => lin(&c, &s, true),
                    Op::Lin3 { c, s, .. } => lin(&c, &s, false),
                    Op::Add4 { c, s, .. } => lin(&c, &s, true),
                    Op::Lin4 { c, s, .. } => lin(&c, &s, false),
                    Op::Acc { d, c, a } => g(d) + q(c) * g(a),
                };
                regs[op.dst()] = v;
            }
            for (i, &r) in self.maps[1].iter().enumerate() {
                p[i][j] = regs[r as usize].clone();
            }
        }
        p
    }

    /// A single state starting from `initial` (one value per slot).
    #[track_caller]
    pub fn state(&self, initial: &[T]) -> KernelState<T> {
        assert_eq!(initial.len(), self.n_slots, "one initial value per slot");
        let mut regs = vec![T::default(); self.n_regs];
        regs[..self.n_slots].copy_from_slice(initial);
        KernelState { regs, n_slots: self.n_slots }
    }

    /// Advances one state by `n_steps` steps.
    #[track_caller]
    pub fn advance(&self, state: &mut KernelState<T>, n_steps: u64) {
        assert_eq!(state.regs.len(), self.n_regs, "state made by this kernel");
        let regs = &mut state.regs[..];
        let periods = n_steps / self.period as u64;
        let rest = (n_steps % self.period as u64) as usize;
        for _ in 0..periods {
            run_scalar(&self.ops, regs);
        }
        if rest > 0 {
            run_scalar(&self.ops[..rest * self.step_ops], regs);
            let slots: Vec<T> = self.maps[rest].iter().map(|&p| regs[p as usize]).collect();
            regs[..self.n_slots].copy_from_slice(&slots);
        }
    }

    /// Advances every lane of a struct-of-arrays batch by `n_steps` steps:
    /// `data[s * lanes + l]` is slot `s` of lane `l`.
    #[track_caller]
    pub fn advance_lanes(&self, data: &mut [T], lanes: usize, n_steps: u64) {
        assert_eq!(data.len(), lanes * self.n_slots, "one value per slot and lane");
        if lanes <= 16 {
            self.advance_blocks::<16>(data, lanes, n_steps);
        } else {
            self.advance_blocks::<64>(data, lanes, n_steps);
        }
    }

    fn advance_blocks<const B: usize>(&self, data: &mut [T], lanes: usize, n_steps: u64) {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx512f") {
                // SAFETY: the CPU has AVX-512F, checked just above.
                return unsafe { blocks_avx512::<T, B>(self, data, lanes, n_steps) };
            }
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the CPU has AVX2, checked just above.
                return unsafe { blocks_avx2::<T, B>(self, data, lanes, n_steps) };
            }
        }
        blocks::<T, B>(self, data, lanes, n_steps)
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
fn blocks_avx512<T: Real, const B: usize>(k: &Kernel<T>, data: &mut [T], lanes: usize, n: u64) {
    blocks::<T, B>(k, data, lanes, n)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn blocks_avx2<T: Real, const B: usize>(k: &Kernel<T>, data: &mut [T], lanes: usize, n: u64) {
    blocks::<T, B>(k, data, lanes, n)
}

/// The batch runner: blocks of `B` lanes, all steps per block.
#[inline(always)]
fn blocks<T: Real, const B: usize>(k: &Kernel<T>, data: &mut [T], lanes: usize, n_steps: u64) {
    let n = k.n_slots;
    let mut regs: Vec<[T; B]> = vec![[T::default(); B]; k.n_regs];
    let periods = n_steps / k.period as u64;
    let rest = (n_steps % k.period as u64) as usize;
    let mut start = 0;
    while start < lanes {
        let width = B.min(lanes - start);
        for (s, reg) in regs.iter_mut().enumerate().take(n) {
            reg[..width].copy_from_slice(&data[s * lanes + start..][..width]);
            reg[width..].fill(T::default());
        }
        for _ in 0..periods {
            run_block(&k.ops, &mut regs);
        }
        run_block(&k.ops[..rest * k.step_ops], &mut regs);
        for (s, &p) in k.maps[rest].iter().enumerate() {
            data[s * lanes + start..][..width].copy_from_slice(&regs[p as usize][..width]);
        }
        start += width;
    }
}

/// Every operation once, on scalar registers.
#[inline(always)]
fn run_scalar<T: Real>(ops: &[Op<T>], regs: &mut [T]) {
    for op in ops {
        let v = op.eval(regs);
        regs[op.dst()] = v;
    }
}

/// Every operation once, on a block of `B` lanes per register.
#[inline(always)]
fn run_block<T: Real, const B: usize>(ops: &[Op<T>], regs: &mut [[T; B]]) {
    let n_regs = regs.len();
    let base = regs.as_mut_ptr();
    for op in ops {
        debug_assert!(op.dst() < n_regs);
        // SAFETY: `Kernel::new` checked that every register index of every
        // operation is below the register count (`regs.len()`, asserted
        // in debug builds here too) and that no destination is one of its
        // own sources, so the one mutable view and the shared views are
        // in bounds and never overlap (an accumulation reads its
        // destination through the mutable view only).
        let d: &mut [T; B] = unsafe { &mut *base.add(op.dst()) };
        let r = |i: u32| -> &[T; B] {
            debug_assert!((i as usize) < n_regs);
            // SAFETY: as above.
            unsafe { &*base.add(i as usize) }
        };
        match *op {
            Op::Mov { a, .. } => *d = *r(a),
            Op::Scale { c0, a, .. } => {
                let a = r(a);
                for l in 0..B {
                    d[l] = c0 * a[l];
                }
            }
            Op::Add2 { a, c1, b, .. } => {
                let (a, b) = (r(a), r(b));
                for l in 0..B {
                    d[l] = a[l] + c1 * b[l];
                }
            }
            Op::Lin2 { c, s, .. } => {
                let (a, b) = (r(s[0]), r(s[1]));
                for l in 0..B {
                    d[l] = c[0] * a[l] + c[1] * b[l];
                }
            }
            Op::Add3 { c, s, .. } => {
                let (a, b, e) = (r(s[0]), r(s[1]), r(s[2]));
                for l in 0..B {
                    d[l] = a[l] + c[0] * b[l] + c[1] * e[l];
                }
            }
            Op::Lin3 { c, s, .. } => {
                let (a, b, e) = (r(s[0]), r(s[1]), r(s[2]));
                for l in 0..B {
                    d[l] = c[0] * a[l] + c[1] * b[l] + c[2] * e[l];
                }
            }
            Op::Add4 { c, s, .. } => {
                let (a, b, e, g) = (r(s[0]), r(s[1]), r(s[2]), r(s[3]));
                for l in 0..B {
                    d[l] = a[l] + c[0] * b[l] + c[1] * e[l] + c[2] * g[l];
                }
            }
            Op::Lin4 { c, s, .. } => {
                let (a, b, e, g) = (r(s[0]), r(s[1]), r(s[2]), r(s[3]));
                for l in 0..B {
                    d[l] = c[0] * a[l] + c[1] * b[l] + c[2] * e[l] + c[3] * g[l];
                }
            }
            Op::Acc { c, a, .. } => {
                let a = r(a);
                for l in 0..B {
                    d[l] = d[l] + c * a[l];
                }
            }
        }
    }
}

/// One state of a [`Kernel`]: the slots plus scratch registers.
#[derive(Clone, Debug, PartialEq)]
pub struct KernelState<T> {
    regs: Vec<T>,
    n_slots: usize,
}

impl<T: Real> KernelState<T> {
    /// The augmented state, in [`Step::slot_names`] order.
    pub fn slots(&self) -> &[T] {
        &self.regs[..self.n_slots]
    }

    /// The augmented state, writable.
    pub fn slots_mut(&mut self) -> &mut [T] {
        &mut self.regs[..self.n_slots]
    }
}
