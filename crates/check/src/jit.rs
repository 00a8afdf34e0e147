//! The native compiler of a lowered step (feature `jit`): a [`Step`] turned
//! into machine code with cranelift, bit for bit the interpreter.
//!
//! [`Jit::compile`] emits two functions for a step:
//!
//! * **One state**, `fn(regs, n_steps)`: the registers live in SSA values
//!   (machine registers) for the whole run. The end-of-step swaps and copies
//!   are a renaming at compile time: the loop passes each register's new
//!   value as the argument of the loop header's parameter, so nothing is
//!   moved through memory. Only the registers whose start value a step reads
//!   (or keeps) are carried around the loop; after the last step every
//!   register is written back, so the [`State`] afterwards equals the
//!   interpreter's.
//! * **Struct-of-arrays lanes**, `fn(data, lanes, n_steps)`: the lanes are
//!   taken a group at a time (several 128-bit vectors, `f64x2` or `f32x4`,
//!   interleaved for instruction-level parallelism), every requested step
//!   runs on a group while it sits in registers, then the group is stored.
//!   Leftover lanes run one vector, then one scalar, at a time.
//!
//! Every instruction `dst = [dst +] Σ cᵢ·reg[srcᵢ]` is emitted as the
//! interpreter evaluates it: each product `cᵢ·x` is one multiplication
//! (skipped for a unit first coefficient), the products are added left to
//! right, an accumulating instruction adds them to the old value one by
//! one; no fused multiply-add, no reassociation (cranelift does neither on
//! floats). So the compiled step agrees with [`Step::advance`] bit for bit,
//! and `Jit<f32>` with [`crate::kernel::Kernel<f32>`] (coefficients rounded
//! from their `f64` values). The tests hold both on every built-in and on
//! generated programs.
//!
//! ```
//! use check::jit::JitStep;
//! use check::numeric::{Params, ParamsF64, Step};
//! let step = Step::compile(&poly::builtin("false_euler")?, &Params::phi(0.5))?;
//! let jit = JitStep::compile(&step)?;
//! let mut state = step.state(&[0.0, 1.0]);
//! jit.advance(&mut state, 1);
//! assert_eq!(state.slots(), [-0.5, 0.75]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fmt;
use std::marker::PhantomData;
use std::sync::OnceLock;

use cranelift_codegen::ir::{
    condcodes::IntCC, types, AbiParam, Block, BlockArg, ConstantData, InstBuilder, MemFlagsData,
    Type, UserFuncName, Value,
};
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{default_libcall_names, FuncId, Linkage, Module};

use crate::error::Error;
use crate::kernel::Real;
use crate::numeric::{Batch, Move, State, Step};

/// The host's code generator, made once per process.
fn host_isa() -> Result<OwnedTargetIsa, String> {
    static ISA: OnceLock<Result<OwnedTargetIsa, String>> = OnceLock::new();
    ISA.get_or_init(|| {
        let mut flags = settings::builder();
        // The IR verifier runs in debug builds (the tests); it is a third
        // of the compile time of a small step.
        let verify = if cfg!(debug_assertions) { "true" } else { "false" };
        for (name, value) in [
            ("opt_level", "speed"),
            ("enable_verifier", verify),
            ("use_colocated_libcalls", "false"),
            ("is_pic", "false"),
        ] {
            flags.set(name, value).map_err(|e| e.to_string())?;
        }
        let isa = cranelift_native::builder().map_err(|e| format!("unsupported host: {e}"))?;
        isa.finish(settings::Flags::new(flags)).map_err(|e| e.to_string())
    })
    .clone()
}

/// The machine types of a precision.
#[derive(Clone, Copy, Debug)]
struct Prec {
    scalar: Type,
    vector: Type,
    /// Lanes per vector.
    width: i64,
    /// Bytes per value.
    size: i64,
}

fn prec<T: Real>() -> Prec {
    if T::NAME == "f32" {
        Prec { scalar: types::F32, vector: types::F32X4, width: 4, size: 4 }
    } else {
        Prec { scalar: types::F64, vector: types::F64X2, width: 2, size: 8 }
    }
}

impl Prec {
    /// The coefficient `c` rounded to this precision, in every lane of `ty`.
    fn constant(&self, b: &mut FunctionBuilder, ty: Type, c: f64) -> Value {
        let f32 = self.size == 4;
        if ty == self.scalar {
            return if f32 { b.ins().f32const(c as f32) } else { b.ins().f64const(c) };
        }
        let bytes: Vec<u8> = if f32 {
            (0..self.width).flat_map(|_| (c as f32).to_le_bytes()).collect()
        } else {
            (0..self.width).flat_map(|_| c.to_le_bytes()).collect()
        };
        let handle = b.func.dfg.constants.insert(ConstantData::from(bytes));
        b.ins().vconst(ty, handle)
    }
}

/// The registers whose value at the start of a step is needed: read by an
/// instruction before it is overwritten, or still in some register at the
/// end of the step (kept or moved). The others are scratch.
fn carried(step: &Step) -> Vec<usize> {
    let n = step.n_regs();
    // `start[r] = Some(q)`: register r holds the start value of register q.
    let mut start: Vec<Option<usize>> = (0..n).map(Some).collect();
    let mut needed = vec![false; n];
    for ins in step.instrs() {
        let reads = ins.src[..ins.len as usize].iter().chain(ins.accumulate.then_some(&ins.dst));
        for &r in reads {
            if let Some(q) = start[r] {
                needed[q] = true;
            }
        }
        start[ins.dst] = None;
    }
    for m in step.moves() {
        match *m {
            Move::Swap(a, b) => start.swap(a, b),
            Move::Copy { dst, src } => start[dst] = start[src],
        }
    }
    for q in start.into_iter().flatten() {
        needed[q] = true;
    }
    (0..n).filter(|&r| needed[r]).collect()
}

/// Emits one step on `copies.len()` independent register sets of type
/// `ty`, instruction by instruction across the sets, in the interpreter's
/// order of operations; the moves rename registers.
fn emit_step(
    b: &mut FunctionBuilder,
    step: &Step,
    p: Prec,
    ty: Type,
    copies: &mut [Regs],
) -> Result<(), String> {
    let unset = |r: usize| format!("register {r} read before it is written");
    for ins in step.instrs() {
        for regs in copies.iter_mut() {
            let get = |r: usize| regs[r].ok_or_else(|| unset(r));
            let product = |b: &mut FunctionBuilder, i: usize| -> Result<Value, String> {
                let x = get(ins.src[i])?;
                let c = p.constant(b, ty, ins.coef[i]);
                // x·c, the constant second so it can stay in memory.
                Ok(b.ins().fmul(x, c))
            };
            // `v + c·x` for a term after the first: `v + x` when c is 1 and
            // `v − x` when c is −1 (the same value: 1·x is x, and v + (−x)
            // is v − x, in IEEE arithmetic, for every number; a NaN stays a
            // NaN), else the product and a sum.
            let add_term = |b: &mut FunctionBuilder, v: Value, i: usize| -> Result<Value, String> {
                let c = ins.coef[i];
                if c == 1.0 || c == -1.0 {
                    let x = get(ins.src[i])?;
                    return Ok(if c == 1.0 { b.ins().fadd(v, x) } else { b.ins().fsub(v, x) });
                }
                let t = product(b, i)?;
                Ok(b.ins().fadd(v, t))
            };
            let v = if ins.accumulate {
                let mut v = get(ins.dst)?;
                for i in 0..ins.len as usize {
                    v = add_term(b, v, i)?;
                }
                v
            } else {
                let mut v = if ins.unit_first { get(ins.src[0])? } else { product(b, 0)? };
                for i in 1..ins.len as usize {
                    v = add_term(b, v, i)?;
                }
                v
            };
            regs[ins.dst] = Some(v);
        }
    }
    for regs in copies.iter_mut() {
        for m in step.moves() {
            match *m {
                Move::Swap(a, c) => regs.swap(a, c),
                Move::Copy { dst, src } => regs[dst] = regs[src],
            }
        }
    }
    Ok(())
}

fn args(values: &[Value]) -> Vec<BlockArg> {
    values.iter().map(|&v| BlockArg::Value(v)).collect()
}

/// Values of the `carried` registers of each copy, in block-parameter order.
fn carried_values(
    copies: &[Regs],
    carried: &[usize],
    unset: impl Fn(usize) -> String,
) -> Result<Vec<Value>, String> {
    let mut out = Vec::with_capacity(copies.len() * carried.len());
    for regs in copies {
        for &r in carried {
            out.push(regs[r].ok_or_else(|| unset(r))?);
        }
    }
    Ok(out)
}

/// The value of each register of one register set (`None`: not known).
type Regs = Vec<Option<Value>>;

/// A do-while loop of `n ≥ 1` steps on `u` copies of the carried registers
/// (`initial`, copy-major), from the current block; switches to the block
/// after the loop and returns every register's final value per copy.
#[allow(clippy::too_many_arguments)]
fn emit_loop(
    b: &mut FunctionBuilder,
    step: &Step,
    p: Prec,
    ty: Type,
    carried: &[usize],
    u: usize,
    initial: &[Value],
    n: Value,
) -> Result<Vec<Regs>, String> {
    let body = b.create_block();
    for _ in 0..initial.len() {
        b.append_block_param(body, ty);
    }
    let counter = b.append_block_param(body, types::I64);
    let mut init_args = initial.to_vec();
    init_args.push(n);
    b.ins().jump(body, &args(&init_args));

    b.switch_to_block(body);
    let params = b.block_params(body).to_vec();
    let mut copies: Vec<Regs> = vec![vec![None; step.n_regs()]; u];
    for (k, regs) in copies.iter_mut().enumerate() {
        for (j, &r) in carried.iter().enumerate() {
            regs[r] = Some(params[k * carried.len() + j]);
        }
    }
    emit_step(b, step, p, ty, &mut copies)?;
    let left = b.ins().iadd_imm_s(counter, -1);
    let mut next = carried_values(&copies, carried, |r| format!("register {r} has no value"))?;
    next.push(left);
    let after = b.create_block();
    b.ins().brif(left, body, &args(&next), after, &[]);
    b.switch_to_block(after);
    Ok(copies)
}

/// `fn(regs: *mut T, n_steps: u64)`.
fn build_one(
    b: &mut FunctionBuilder,
    step: &Step,
    p: Prec,
    carried: &[usize],
) -> Result<(), String> {
    let entry = b.create_block();
    b.append_block_params_for_function_params(entry);
    b.switch_to_block(entry);
    let regs_ptr = b.block_params(entry)[0];
    let n = b.block_params(entry)[1];
    let run = b.create_block();
    let ret = b.create_block();
    b.ins().brif(n, run, &[], ret, &[]);

    b.switch_to_block(run);
    let flags = MemFlagsData::trusted();
    let initial: Vec<Value> = carried
        .iter()
        .map(|&r| b.ins().load(p.scalar, flags, regs_ptr, (r as i64 * p.size) as i32))
        .collect();
    let copies = emit_loop(b, step, p, p.scalar, carried, 1, &initial, n)?;
    for (r, v) in copies[0].iter().enumerate() {
        let v = v.ok_or_else(|| format!("register {r} has no final value"))?;
        b.ins().store(flags, v, regs_ptr, (r as i64 * p.size) as i32);
    }
    b.ins().jump(ret, &[]);

    b.switch_to_block(ret);
    b.ins().return_(&[]);
    Ok(())
}

/// `fn(data: *mut T, lanes: usize, n_steps: u64)`, `data[s * lanes + l]`
/// being slot `s` of lane `l`.
fn build_lanes(
    b: &mut FunctionBuilder,
    step: &Step,
    p: Prec,
    carried: &[usize],
    interleave: usize,
    ptr_ty: Type,
) -> Result<(), String> {
    let entry = b.create_block();
    b.append_block_params_for_function_params(entry);
    b.switch_to_block(entry);
    let data = b.block_params(entry)[0];
    let lanes = b.block_params(entry)[1];
    let n = b.block_params(entry)[2];
    let ret = b.create_block();
    // (type, vectors per group, lanes per vector)
    let mut groups = vec![(p.vector, interleave, p.width)];
    if interleave > 1 {
        groups.push((p.vector, 1, p.width));
    }
    groups.push((p.scalar, 1, 1));
    let heads: Vec<Block> = groups
        .iter()
        .map(|_| {
            let h = b.create_block();
            b.append_block_param(h, ptr_ty);
            h
        })
        .collect();
    let stride = b.ins().imul_imm_s(lanes, p.size);
    let zero = b.ins().iconst(ptr_ty, 0);
    b.ins().brif(n, heads[0], &args(&[zero]), ret, &[]);
    let flags = MemFlagsData::new().with_notrap();

    for (g, &(ty, u, width)) in groups.iter().enumerate() {
        let per_group = (u as i64) * width;
        let head = heads[g];
        b.switch_to_block(head);
        let i = b.block_params(head)[0];
        let end = b.ins().iadd_imm_s(i, per_group);
        let fits = b.ins().icmp(IntCC::UnsignedLessThanOrEqual, end, lanes);
        let pre = b.create_block();
        if g + 1 < groups.len() {
            b.ins().brif(fits, pre, &[], heads[g + 1], &args(&[i]));
        } else {
            b.ins().brif(fits, pre, &[], ret, &[]);
        }

        b.switch_to_block(pre);
        let offset = b.ins().imul_imm_s(i, p.size);
        let mut base = b.ins().iadd(data, offset);
        let mut slot_base = Vec::with_capacity(step.order());
        for s in 0..step.order() {
            if s > 0 {
                base = b.ins().iadd(base, stride);
            }
            slot_base.push(base);
        }
        let mut initial = Vec::with_capacity(u * carried.len());
        for k in 0..u {
            for &r in carried {
                let v = if r < step.order() {
                    b.ins().load(ty, flags, slot_base[r], (k as i64 * width * p.size) as i32)
                } else {
                    // Scratch carried into a step: the interpreter's batch
                    // registers start at zero.
                    p.constant(b, ty, 0.0)
                };
                initial.push(v);
            }
        }
        let copies = emit_loop(b, step, p, ty, carried, u, &initial, n)?;
        for (k, regs) in copies.iter().enumerate() {
            for (s, &addr) in slot_base.iter().enumerate() {
                let v = regs[s].ok_or_else(|| format!("slot {s} has no final value"))?;
                b.ins().store(flags, v, addr, (k as i64 * width * p.size) as i32);
            }
        }
        let next = b.ins().iadd_imm_s(i, per_group);
        b.ins().jump(head, &args(&[next]));
    }

    b.switch_to_block(ret);
    b.ins().return_(&[]);
    Ok(())
}

/// Lanes per block of the streaming batch runner: the block's slots stay in
/// L1 cache for all its steps.
const STREAM_BLOCK: i64 = 256;

/// `fn(data, lanes, n_steps)` for a long dependent step: blocks of
/// [`STREAM_BLOCK`] lanes; for each step, every group of `u` vectors of the
/// block loads its slots, runs one step and stores them back, so the groups
/// are independent work the processor overlaps (a long chain per step keeps
/// the register-resident runner waiting on latency). Needs every carried
/// register to be a slot (memory holds the state between steps).
fn build_lanes_streaming(
    b: &mut FunctionBuilder,
    step: &Step,
    p: Prec,
    carried: &[usize],
    u: usize,
    ptr_ty: Type,
) -> Result<(), String> {
    let n_slots = step.order();
    let entry = b.create_block();
    b.append_block_params_for_function_params(entry);
    b.switch_to_block(entry);
    let data = b.block_params(entry)[0];
    let lanes = b.block_params(entry)[1];
    let n = b.block_params(entry)[2];
    let ret = b.create_block();
    let stride = b.ins().imul_imm_s(lanes, p.size);
    let zero = b.ins().iconst(ptr_ty, 0);
    let block_head = b.create_block();
    let b0 = b.append_block_param(block_head, ptr_ty);
    b.ins().brif(n, block_head, &args(&[zero]), ret, &[]);

    // Block loop: lanes b0 .. end.
    b.switch_to_block(block_head);
    let more = b.ins().icmp(IntCC::UnsignedLessThan, b0, lanes);
    let block_pre = b.create_block();
    b.ins().brif(more, block_pre, &[], ret, &[]);
    b.switch_to_block(block_pre);
    let wanted = b.ins().iadd_imm_s(b0, STREAM_BLOCK);
    let end = b.ins().umin(wanted, lanes);
    let step_head = b.create_block();
    let k = b.append_block_param(step_head, types::I64);
    b.ins().jump(step_head, &args(&[n]));

    // Step loop: k steps left; each step sweeps the block's lanes in
    // groups of u vectors, then one vector, then one lane.
    b.switch_to_block(step_head);
    let flags = MemFlagsData::new().with_notrap();
    let mut groups = vec![(p.vector, u, p.width)];
    if u > 1 {
        groups.push((p.vector, 1, p.width));
    }
    groups.push((p.scalar, 1, 1));
    let heads: Vec<Block> = groups
        .iter()
        .map(|_| {
            let h = b.create_block();
            b.append_block_param(h, ptr_ty);
            h
        })
        .collect();
    let latch = b.create_block();
    b.ins().jump(heads[0], &args(&[b0]));
    for (g, &(ty, u, width)) in groups.iter().enumerate() {
        let per_group = (u as i64) * width;
        let head = heads[g];
        b.switch_to_block(head);
        let i = b.block_params(head)[0];
        let group_end = b.ins().iadd_imm_s(i, per_group);
        let fits = b.ins().icmp(IntCC::UnsignedLessThanOrEqual, group_end, end);
        let body = b.create_block();
        if g + 1 < groups.len() {
            b.ins().brif(fits, body, &[], heads[g + 1], &args(&[i]));
        } else {
            b.ins().brif(fits, body, &[], latch, &[]);
        }
        b.switch_to_block(body);
        let offset = b.ins().imul_imm_s(i, p.size);
        let mut base = b.ins().iadd(data, offset);
        let mut slot_base = Vec::with_capacity(n_slots);
        for s in 0..n_slots {
            if s > 0 {
                base = b.ins().iadd(base, stride);
            }
            slot_base.push(base);
        }
        let mut copies: Vec<Regs> = vec![vec![None; step.n_regs()]; u];
        for (c, regs) in copies.iter_mut().enumerate() {
            for &r in carried {
                let at = (c as i64 * width * p.size) as i32;
                regs[r] = Some(b.ins().load(ty, flags, slot_base[r], at));
            }
        }
        emit_step(b, step, p, ty, &mut copies)?;
        for (c, regs) in copies.iter().enumerate() {
            for (s, &addr) in slot_base.iter().enumerate() {
                let v = regs[s].ok_or_else(|| format!("slot {s} has no final value"))?;
                b.ins().store(flags, v, addr, (c as i64 * width * p.size) as i32);
            }
        }
        b.ins().jump(head, &args(&[group_end]));
    }
    b.switch_to_block(latch);
    let left = b.ins().iadd_imm_s(k, -1);
    let next_block = b.create_block();
    b.ins().brif(left, step_head, &args(&[left]), next_block, &[]);
    b.switch_to_block(next_block);
    b.ins().jump(block_head, &args(&[end]));

    b.switch_to_block(ret);
    b.ins().return_(&[]);
    Ok(())
}

/// Instructions per step from which [`BatchRunner::Auto`] streams: a long
/// dependent chain would leave the register-resident runner waiting on the
/// latency of each operation.
const STREAM_FROM: usize = 4;

/// Vectors per group of the streaming runner.
const STREAM_VECTORS: usize = 2;

/// How [`Jit::advance_lanes`] runs a batch. Both runners perform the same
/// operations per lane, so they agree bit for bit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BatchRunner {
    /// Registers for a short step, streaming for a long one.
    #[default]
    Auto,
    /// Each group of lanes (several vectors side by side) stays in registers
    /// for every step, then is stored.
    Registers,
    /// Blocks of lanes in L1 cache: each step sweeps the block's lanes,
    /// loading and storing the slots (falls back to registers for a step
    /// that carries a scratch register from one step to the next).
    Streaming,
}

/// Vectors interleaved per lane group: enough independent chains to hide
/// the latency of a dependent add, few enough to stay in the 16 vector
/// registers.
fn interleave_for(carried: usize) -> usize {
    match carried {
        0..=2 => 4,
        3..=5 => 2,
        _ => 1,
    }
}

/// The compiled code: freed when the [`Jit`] that owns its function
/// pointers is dropped.
struct Code(Option<JITModule>);

impl Drop for Code {
    fn drop(&mut self) {
        if let Some(module) = self.0.take() {
            // SAFETY: the only pointers into this module's code are the
            // function pointers of the `Jit` being dropped with it.
            unsafe { module.free_memory() };
        }
    }
}

// SAFETY: after `finalize_definitions` the module is never touched again
// until it is freed in `drop` (which has exclusive access); the generated
// code only reads and writes the buffers its callers pass.
unsafe impl Send for Code {}
// SAFETY: as above: shared references never reach the module.
unsafe impl Sync for Code {}

/// A [`Step`] compiled to native code in precision `T` (see the module
/// docs): [`JitStep`] for `f64`.
pub struct Jit<T> {
    name: String,
    n_slots: usize,
    n_regs: usize,
    interleave: usize,
    streaming: bool,
    one: unsafe extern "C" fn(*mut T, u64),
    lanes: unsafe extern "C" fn(*mut T, usize, u64),
    _code: Code,
    _t: PhantomData<T>,
}

/// The native step in `f64`, bit for bit [`Step`].
pub type JitStep = Jit<f64>;

impl<T> fmt::Debug for Jit<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Jit")
            .field("name", &self.name)
            .field("precision", &std::any::type_name::<T>())
            .field("n_slots", &self.n_slots)
            .field("n_regs", &self.n_regs)
            .field("interleave", &self.interleave)
            .field("streaming", &self.streaming)
            .finish_non_exhaustive()
    }
}

impl<T: Real> Jit<T> {
    /// Compiles `step` to native code for this machine.
    ///
    /// Errors (kind [`crate::ErrorKind::Jit`]) when the host has no
    /// cranelift back end or code generation fails.
    pub fn compile(step: &Step) -> Result<Jit<T>, Error> {
        Jit::compile_with(step, BatchRunner::Auto)
    }

    /// [`Jit::compile`] with a choice of batch runner.
    pub fn compile_with(step: &Step, runner: BatchRunner) -> Result<Jit<T>, Error> {
        let fail = |e: String| Error::jit(step.name(), &e);
        let isa = host_isa().map_err(fail)?;
        let mut module = JITModule::new(JITBuilder::with_isa(isa, default_libcall_names()));
        let p = prec::<T>();
        let carried = carried(step);
        let interleave = interleave_for(carried.len());
        // Memory holds the state between steps when streaming, so every
        // carried register must be a slot.
        let streaming = carried.iter().all(|&r| r < step.order())
            && match runner {
                BatchRunner::Auto => step.instrs().len() >= STREAM_FROM,
                BatchRunner::Registers => false,
                BatchRunner::Streaming => true,
            };
        let ptr_ty = module.target_config().pointer_type();
        let mut ctx = module.make_context();
        let mut fctx = FunctionBuilderContext::new();

        let config = module.target_config();
        let mut define = |module: &mut JITModule,
                          name: &str,
                          params: &[Type],
                          body: &dyn Fn(&mut FunctionBuilder) -> Result<(), String>|
         -> Result<FuncId, String> {
            let mut sig = module.make_signature();
            sig.params.extend(params.iter().map(|&t| AbiParam::new(t)));
            let id =
                module.declare_function(name, Linkage::Local, &sig).map_err(|e| e.to_string())?;
            ctx.func.signature = sig;
            ctx.func.name = UserFuncName::user(0, id.as_u32());
            {
                let mut b = FunctionBuilder::new(&mut ctx.func, &mut fctx);
                body(&mut b)?;
                b.seal_all_blocks();
                b.finalize(config);
            }
            module.define_function(id, &mut ctx).map_err(|e| format!("{e:?}"))?;
            module.clear_context(&mut ctx);
            Ok(id)
        };
        let one = define(&mut module, "step_one", &[ptr_ty, types::I64], &|b| {
            build_one(b, step, p, &carried)
        })
        .map_err(fail)?;
        let lanes = define(&mut module, "step_lanes", &[ptr_ty, ptr_ty, types::I64], &|b| {
            if streaming {
                build_lanes_streaming(b, step, p, &carried, STREAM_VECTORS, ptr_ty)
            } else {
                build_lanes(b, step, p, &carried, interleave, ptr_ty)
            }
        })
        .map_err(fail)?;
        module.finalize_definitions().map_err(|e| fail(e.to_string()))?;
        let one_ptr = module.get_finalized_function(one);
        let lanes_ptr = module.get_finalized_function(lanes);
        // SAFETY: the two functions were just defined with exactly these
        // signatures (pointer-sized integers for the pointer and `usize`,
        // i64 for the step count) in the host's default calling convention,
        // which is C's.
        let (one, lanes) = unsafe {
            (
                std::mem::transmute::<*const u8, unsafe extern "C" fn(*mut T, u64)>(one_ptr),
                std::mem::transmute::<*const u8, unsafe extern "C" fn(*mut T, usize, u64)>(
                    lanes_ptr,
                ),
            )
        };
        Ok(Jit {
            name: step.name().to_owned(),
            n_slots: step.order(),
            n_regs: step.n_regs(),
            interleave,
            streaming,
            one,
            lanes,
            _code: Code(Some(module)),
            _t: PhantomData,
        })
    }

    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The number of slots of the augmented state.
    pub fn order(&self) -> usize {
        self.n_slots
    }

    /// Vectors run side by side per group of lanes (register-resident
    /// batch runner).
    pub fn interleave(&self) -> usize {
        self.interleave
    }

    /// Whether batches stream through L1 blocks one step at a time
    /// ([`BatchRunner::Streaming`]) rather than keep each group of lanes in
    /// registers for all steps.
    pub fn streaming(&self) -> bool {
        self.streaming
    }

    /// Advances the register file of one state (the slots first, then the
    /// step's scratch registers, as [`Step`] numbers them) by `n_steps`.
    #[track_caller]
    pub fn advance_regs(&self, regs: &mut [T], n_steps: u64) {
        assert_eq!(regs.len(), self.n_regs, "one value per register of the step");
        // SAFETY: the function reads and writes registers 0..n_regs of the
        // buffer only, and `regs` has exactly that many.
        unsafe { (self.one)(regs.as_mut_ptr(), n_steps) }
    }

    /// Advances every lane of a struct-of-arrays batch by `n_steps` steps:
    /// `data[s * lanes + l]` is slot `s` of lane `l`.
    #[track_caller]
    pub fn advance_lanes(&self, data: &mut [T], lanes: usize, n_steps: u64) {
        assert_eq!(data.len(), lanes * self.n_slots, "one value per slot and lane");
        // SAFETY: the function touches `data[s * lanes + l]` for slots
        // `s < n_slots` and lanes `l < lanes` only, all inside `data`.
        unsafe { (self.lanes)(data.as_mut_ptr(), lanes, n_steps) }
    }
}

impl Jit<f64> {
    /// Advances one state by `n_steps` steps, as [`Step::advance`].
    #[track_caller]
    pub fn advance(&self, state: &mut State, n_steps: u64) {
        self.advance_regs(state.regs_mut(), n_steps);
    }

    /// Advances every lane of `batch` by `n_steps` steps, as
    /// [`Step::advance_batch`].
    #[track_caller]
    pub fn advance_batch(&self, batch: &mut Batch, n_steps: u64) {
        let lanes = batch.lanes();
        let (data, n_slots) = batch.data_mut();
        assert_eq!(n_slots, self.n_slots, "batch made for this step");
        self.advance_lanes(data, lanes, n_steps);
    }
}
