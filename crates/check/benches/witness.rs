//! Criterion benchmarks of the numeric witnesses: a second-order Φ sweep
//! (spectral radius + class), whole sweeps of implicit built-ins with exact
//! constants, and the compiled step against hand-written
//! loops for one state and for a batch of 4096 states.

use check::numeric::ParamsF64;
use std::hint::black_box;

use check::numeric::{Batch, Params, Step};
use check::sweep::Classifier;
use criterion::{criterion_group, criterion_main, Criterion, Throughput};

const PHI: f64 = 0.5;
const LANES: usize = 4096;
const STEPS: u64 = 100;

fn sweep(c: &mut Criterion) {
    let mut g = c.benchmark_group("sweep");
    let n = 100_000;
    let grid: Vec<f64> = (0..n).map(|i| 1e-8 + 4.0 * i as f64 / n as f64).collect();
    g.throughput(Throughput::Elements(n as u64));
    for name in ["false_euler", "false_heun", "semi_false_heun"] {
        let classifier =
            Classifier::new(&poly::builtin(name).unwrap(), &Params::default()).unwrap();
        g.bench_function(format!("radius_and_class/{name}"), |b| {
            b.iter(|| {
                let mut acc = 0.0;
                for &phi in &grid {
                    let (r, class) = classifier.radius_and_class(black_box(phi));
                    acc += r + class as u8 as f64;
                }
                acc
            })
        });
    }
    g.finish();
    // The whole sweep (default grid, boundaries bisected to adjacent
    // floats) of methods whose χ carries exact constants or a det A
    // denominator: the general path, which evaluates χ exactly per point.
    let mut g = c.benchmark_group("full_sweep");
    g.sample_size(10);
    for name in ["trapezoidal", "sdirk2", "forest_ruth"] {
        let m = poly::builtin(name).unwrap();
        let params = Params::default().with("D", 0.3);
        g.bench_function(name, |b| {
            b.iter(|| check::sweep::sweep(&m, &params, &check::sweep::default_grid()).unwrap())
        });
    }
    g.finish();
}

fn single(c: &mut Criterion) {
    let mut g = c.benchmark_group("single_state");
    let n: u64 = 10_000;
    g.throughput(Throughput::Elements(n));
    // Methods whose states neither decay into subnormals nor overflow
    // (|z| = 1), so every iteration costs the same.
    for name in ["false_euler", "verlet", "damped_euler_matrix"] {
        let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(PHI)).unwrap();
        g.bench_function(format!("compiled/{name}"), |b| {
            let mut s = step.state(&[0.0, 1.0]);
            b.iter(|| {
                step.advance(&mut s, black_box(n));
                s.slots()[0]
            })
        });
    }
    g.bench_function("hand/false_euler", |b| {
        let (mut v, mut y) = (0.0f64, 1.0f64);
        let phi = black_box(PHI);
        b.iter(|| {
            for _ in 0..n {
                v -= phi * y;
                y += phi * v;
            }
            black_box((v, y))
        })
    });
    g.finish();
}

fn batch(c: &mut Criterion) {
    let mut g = c.benchmark_group("batch_4096");
    g.throughput(Throughput::Elements(LANES as u64 * STEPS));
    for name in ["false_euler", "verlet", "damped_euler_matrix"] {
        let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(PHI)).unwrap();
        let mut batch = Batch::zeros(&step, LANES);
        for l in 0..LANES {
            batch.set_lane(l, &[(l as f64).sin(), (l as f64).cos()]);
        }
        g.bench_function(format!("compiled/{name}"), |b| {
            b.iter(|| {
                step.advance_batch(&mut batch, black_box(STEPS));
                batch.slot(0)[0]
            })
        });
    }
    let init = |f: fn(f64) -> f64| (0..LANES).map(|l| f(l as f64)).collect::<Vec<f64>>();
    // The plain loop: every step sweeps all lanes.
    g.bench_function("hand/false_euler", |b| {
        let (mut v, mut y) = (init(f64::sin), init(f64::cos));
        let phi = black_box(PHI);
        b.iter(|| {
            for _ in 0..STEPS {
                for (v, y) in v.iter_mut().zip(y.iter_mut()) {
                    *v -= phi * *y;
                    *y += phi * *v;
                }
            }
            v[0]
        })
    });
    // The same loop blocked like the compiled runner (256 lanes stay in L1
    // for all steps), to separate blocking from interpretation.
    g.bench_function("hand_blocked/false_euler", |b| {
        let (mut v, mut y) = (init(f64::sin), init(f64::cos));
        let phi = black_box(PHI);
        b.iter(|| {
            for (vb, yb) in v.chunks_mut(256).zip(y.chunks_mut(256)) {
                for _ in 0..STEPS {
                    for (v, y) in vb.iter_mut().zip(yb.iter_mut()) {
                        *v -= phi * *y;
                        *y += phi * *v;
                    }
                }
            }
            v[0]
        })
    });
    g.finish();
}

criterion_group!(benches, sweep, single, batch);
criterion_main!(benches);
