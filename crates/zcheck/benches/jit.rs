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
use zcheck::tradeoff::kernels::{run_hand_kernel, run_hand_kernel_batch, TIMING_PHI};

const SINGLE_STEPS: u64 = 1000;
const LANES: usize = 4096;
const BATCH_STEPS: u64 = 8;

/// Built-ins with Φ as their only parameter (the hand kernels' set, and the
/// implicit ones, which have no hand kernel).
fn names() -> Vec<&'static str> {
    poly::advanced::builtins::builtin_names()
        .filter(|n| poly::builtin(n).unwrap().params().len() == 1)
        .collect()
}

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
        let (mut a, mut b) = (0.0, 1.0);
        if run_hand_kernel(name, &mut a, &mut b, TIMING_PHI, 0.0, 1) {
            g.bench_function(BenchmarkId::new("hand", name), |bench| {
                bench.iter(|| {
                    run_hand_kernel(name, &mut a, &mut b, black_box(TIMING_PHI), 0.0, SINGLE_STEPS)
                })
            });
        }
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
        let mut a: Vec<f64> = (0..LANES).map(|i| (i as f64 * 0.1).sin()).collect();
        let mut b: Vec<f64> = (0..LANES).map(|i| (i as f64 * 0.1).cos()).collect();
        let step = step_of(name);
        let start = |lane: usize| -> Vec<f64> {
            (0..step.order()).map(|s| ((lane * 3 + s) as f64 * 0.1).sin()).collect()
        };
        if run_hand_kernel_batch(name, &mut a[..1], &mut b[..1], TIMING_PHI, 0.0, 1) {
            g.bench_function(BenchmarkId::new("hand", name), |bench| {
                bench.iter(|| {
                    run_hand_kernel_batch(
                        name,
                        &mut a,
                        &mut b,
                        black_box(TIMING_PHI),
                        0.0,
                        BATCH_STEPS,
                    )
                })
            });
        }
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
