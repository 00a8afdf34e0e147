//! The native step of the default build (`zcheck::native`: the emitted Rust
//! step compiled by the rustc at hand) against the hand-written kernels
//! (`zcheck::tradeoff::kernels`): one state, and a batch of 4096 states
//! stored struct-of-arrays; and the time to compile every built-in in one
//! rustc call, and to load it from the cache.
//!
//! Throughput is in steps (state-steps for a batch): criterion's time per
//! iteration divided by the element count is ns per step. Φ = 1e-4 keeps
//! every state normal however long criterion runs.
//!
//! `cargo bench -p zcheck --bench native -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use check::numeric::{Params, ParamsF64};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use zcheck::native::native_step;
use zcheck::tradeoff::kernels::{run_hand_kernel, run_hand_kernel_batch, TIMING_PHI};

const SINGLE_STEPS: u64 = 1000;
const LANES: usize = 4096;
const BATCH_STEPS: u64 = 8;

/// Built-ins with Φ as their only parameter.
fn names() -> Vec<&'static str> {
    poly::advanced::builtins::builtin_names()
        .filter(|n| poly::builtin(n).unwrap().params().len() == 1)
        .collect()
}

fn single(c: &mut Criterion) {
    let mut g = c.benchmark_group("native_single");
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
        let native = native_step(&poly::builtin(name).unwrap(), &Params::phi(TIMING_PHI)).unwrap();
        let mut state = vec![1.0; native.slots()];
        g.bench_function(BenchmarkId::new("native", name), |bench| {
            bench.iter(|| native.advance(black_box(&mut state), SINGLE_STEPS))
        });
    }
    g.finish();
}

fn batch(c: &mut Criterion) {
    let mut g = c.benchmark_group("native_batch4096");
    g.throughput(Throughput::Elements(BATCH_STEPS * LANES as u64));
    for name in names() {
        let mut a: Vec<f64> = (0..LANES).map(|i| (i as f64 * 0.1).sin()).collect();
        let mut b: Vec<f64> = (0..LANES).map(|i| (i as f64 * 0.1).cos()).collect();
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
        let native = native_step(&poly::builtin(name).unwrap(), &Params::phi(TIMING_PHI)).unwrap();
        let mut data: Vec<f64> =
            (0..LANES * native.slots()).map(|i| (i as f64 * 0.1).sin()).collect();
        g.bench_function(BenchmarkId::new("native", name), |bench| {
            bench.iter(|| native.advance_batch(black_box(&mut data), LANES, BATCH_STEPS))
        });
    }
    g.finish();
}

criterion_group!(benches, single, batch);
criterion_main!(benches);
