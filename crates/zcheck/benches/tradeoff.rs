//! Measured cost per step of every built-in: the hand-written kernel, the
//! interpreter (`check::numeric::Step`) and the specialised step
//! (`check::kernel::Kernel`), on one state and on a batch of
//! 4096 states stored struct-of-arrays.
//!
//! Throughput is reported in steps (state-steps for a batch), so criterion's
//! "elem/s" is steps per second and its time per iteration divided by the
//! element count is ns per step. Φ = 1e-4 keeps every method's state normal
//! (no overflow, no subnormals) however long criterion runs.
//!
//! `cargo bench -p check --bench tradeoff`

use check::numeric::ParamsF64;
use std::hint::black_box;
use std::time::Duration;

use check::kernel::Kernel;
use check::numeric::{Batch, Params, Step};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use zcheck::tradeoff::kernels::TIMING_PHI;

mod common;
use common::{hand_batch, hand_single, lanes, names, BATCH_STEPS, LANES, SINGLE_STEPS};

fn single(c: &mut Criterion) {
    let mut g = c.benchmark_group("tradeoff_single");
    g.throughput(Throughput::Elements(SINGLE_STEPS));
    for name in names() {
        hand_single(&mut g, name);
        let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(TIMING_PHI)).unwrap();
        let mut state = step.state(&vec![1.0; step.order()]);
        g.bench_function(BenchmarkId::new("compiled", name), |bench| {
            bench.iter(|| step.advance(black_box(&mut state), SINGLE_STEPS))
        });
        let kernel = Kernel::<f64>::new(&step);
        let mut kstate = kernel.state(&vec![1.0; step.order()]);
        g.bench_function(BenchmarkId::new("kernel", name), |bench| {
            bench.iter(|| kernel.advance(black_box(&mut kstate), SINGLE_STEPS))
        });
    }
    g.finish();
}

fn batch(c: &mut Criterion) {
    let mut g = c.benchmark_group("tradeoff_batch4096");
    g.throughput(Throughput::Elements(BATCH_STEPS * LANES as u64));
    for name in names() {
        hand_batch(&mut g, name);
        let (a, b) = lanes();
        let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(TIMING_PHI)).unwrap();
        let mut states = Batch::zeros(&step, LANES);
        for lane in 0..LANES {
            let x = lane as f64 * 0.1;
            states.set_lane(lane, &[x.sin(), x.cos()]);
        }
        g.bench_function(BenchmarkId::new("compiled", name), |bench| {
            bench.iter(|| step.advance_batch(black_box(&mut states), BATCH_STEPS))
        });
        let kernel = Kernel::<f64>::new(&step);
        let mut data: Vec<f64> = a.iter().chain(&b).copied().collect();
        g.bench_function(BenchmarkId::new("kernel", name), |bench| {
            bench.iter(|| kernel.advance_lanes(black_box(&mut data), LANES, BATCH_STEPS))
        });
    }
    g.finish();
}

/// The drift runner's shape: 16 lanes, many steps, f64 and f32, one thread.
fn drift_lanes(c: &mut Criterion) {
    const STEPS: u64 = 100_000;
    const W: usize = 16;
    let mut g = c.benchmark_group("drift_lanes16");
    g.throughput(Throughput::Elements(STEPS * W as u64));
    for name in ["false_euler", "verlet", "false_euler_matrix"] {
        let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(0.1)).unwrap();
        let k64 = Kernel::<f64>::new(&step);
        let mut d64: Vec<f64> = (0..W * step.order()).map(|i| (i as f64).sin()).collect();
        g.bench_function(BenchmarkId::new("f64", name), |bench| {
            bench.iter(|| k64.advance_lanes(black_box(&mut d64), W, STEPS))
        });
        let k32 = Kernel::<f32>::new(&step);
        let mut d32: Vec<f32> = (0..W * step.order()).map(|i| (i as f32).sin()).collect();
        g.bench_function(BenchmarkId::new("f32", name), |bench| {
            bench.iter(|| k32.advance_lanes(black_box(&mut d32), W, STEPS))
        });
    }
    g.finish();
}

fn config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_millis(800))
        .sample_size(20)
}

criterion_group! { name = benches; config = config(); targets = single, batch, drift_lanes }
criterion_main!(benches);
