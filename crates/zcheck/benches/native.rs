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
use zcheck::tradeoff::kernels::TIMING_PHI;

mod common;
use common::{hand_batch, hand_single, names, BATCH_STEPS, LANES, SINGLE_STEPS};

fn single(c: &mut Criterion) {
    let mut g = c.benchmark_group("native_single");
    g.throughput(Throughput::Elements(SINGLE_STEPS));
    for name in names() {
        hand_single(&mut g, name);
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
        hand_batch(&mut g, name);
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
