//! The native step (`check::jit`, feature `jit`) against the hand-written
//! kernels (`zcheck::tradeoff::kernels`) and the specialised interpreter
//! (`check::kernel::Kernel`): one state, a batch of 4096 states stored
//! struct-of-arrays, and the time to compile a method.
//!
//! Throughput is in steps (state-steps for a batch): criterion's time per
//! iteration divided by the element count is ns per step. Φ = 1e-4 keeps
//! every state normal however long criterion runs.
//!
//! `cargo bench -p zcheck --features jit --bench jit -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use check::jit::JitStep;
use check::kernel::Kernel;
use check::numeric::{Batch, Params, ParamsF64, Step};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use zcheck::tradeoff::kernels::TIMING_PHI;

mod common;
use common::{hand_batch, hand_single, names, BATCH_STEPS, LANES, SINGLE_STEPS};

fn step_of(name: &str) -> Step {
    Step::compile(&poly::builtin(name).unwrap(), &Params::phi(TIMING_PHI)).unwrap()
}

fn compile(c: &mut Criterion) {
    let mut g = c.benchmark_group("jit_compile");
    for name in ["false_euler", "standard_heun", "gauss_legendre_2"] {
        let method = poly::builtin(name).unwrap();
        let step = step_of(name);
        g.bench_function(BenchmarkId::new("native", name), |bench| {
            bench.iter(|| JitStep::compile(black_box(&step)).unwrap())
        });
        g.bench_function(BenchmarkId::new("step_and_native", name), |bench| {
            bench.iter(|| {
                let step = Step::compile(black_box(&method), &Params::phi(TIMING_PHI)).unwrap();
                JitStep::compile(&step).unwrap()
            })
        });
    }
    g.finish();
}

fn single(c: &mut Criterion) {
    let mut g = c.benchmark_group("jit_single");
    g.throughput(Throughput::Elements(SINGLE_STEPS));
    for name in names() {
        hand_single(&mut g, name);
        let step = step_of(name);
        let kernel = Kernel::<f64>::new(&step);
        let mut kstate = kernel.state(&vec![1.0; step.order()]);
        g.bench_function(BenchmarkId::new("kernel", name), |bench| {
            bench.iter(|| kernel.advance(black_box(&mut kstate), SINGLE_STEPS))
        });
        let jit = JitStep::compile(&step).unwrap();
        let mut state = step.state(&vec![1.0; step.order()]);
        g.bench_function(BenchmarkId::new("jit", name), |bench| {
            bench.iter(|| jit.advance(black_box(&mut state), SINGLE_STEPS))
        });
    }
    g.finish();
}

fn batch(c: &mut Criterion) {
    let mut g = c.benchmark_group("jit_batch4096");
    g.throughput(Throughput::Elements(BATCH_STEPS * LANES as u64));
    for name in names() {
        let step = step_of(name);
        let start = |lane: usize| -> Vec<f64> {
            (0..step.order()).map(|s| ((lane * 3 + s) as f64 * 0.1).sin()).collect()
        };
        hand_batch(&mut g, name);
        let kernel = Kernel::<f64>::new(&step);
        let mut data = vec![0.0; LANES * step.order()];
        for l in 0..LANES {
            for (s, x) in start(l).into_iter().enumerate() {
                data[s * LANES + l] = x;
            }
        }
        g.bench_function(BenchmarkId::new("kernel", name), |bench| {
            bench.iter(|| kernel.advance_lanes(black_box(&mut data), LANES, BATCH_STEPS))
        });
        let jit = JitStep::compile(&step).unwrap();
        let mut states = Batch::zeros(&step, LANES);
        for l in 0..LANES {
            states.set_lane(l, &start(l));
        }
        g.bench_function(BenchmarkId::new("jit", name), |bench| {
            bench.iter(|| jit.advance_batch(black_box(&mut states), BATCH_STEPS))
        });
    }
    g.finish();
}

criterion_group!(benches, compile, single, batch);
criterion_main!(benches);
