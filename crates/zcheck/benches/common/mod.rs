//! What the benches share: for the step-cost benches (`native`, `jit`,
//! `tradeoff`), the step counts, the built-ins they run, and the hand-written
//! baseline (`zcheck::tradeoff::kernels`) on one state and on a batch; for
//! `region` and `order`, NodePy's catalogues as exported to `tests/data`.

// Each bench is its own crate and uses only part of this module.
#![allow(dead_code)]

use std::hint::black_box;
use std::path::Path;

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId};
use zcheck::tradeoff::kernels::{run_hand_kernel, run_hand_kernel_batch, TIMING_PHI};

/// Steps per iteration on one state.
pub const SINGLE_STEPS: u64 = 1000;
/// States in a batch, stored struct-of-arrays.
pub const LANES: usize = 4096;
/// Steps per iteration on a batch.
pub const BATCH_STEPS: u64 = 8;

/// Built-ins with Φ as their only parameter (the hand kernels' set, and the
/// implicit ones, which have no hand kernel).
pub fn names() -> Vec<&'static str> {
    poly::advanced::builtins::builtin_names()
        .filter(|n| poly::builtin(n).unwrap().params().len() == 1)
        .collect()
}

/// The starting (position, velocity) lanes of a batch.
pub fn lanes() -> (Vec<f64>, Vec<f64>) {
    let a = (0..LANES).map(|i| (i as f64 * 0.1).sin()).collect();
    let b = (0..LANES).map(|i| (i as f64 * 0.1).cos()).collect();
    (a, b)
}

/// `hand/<name>` on one state, when `name` has a hand-written kernel.
pub fn hand_single(g: &mut BenchmarkGroup<'_, WallTime>, name: &'static str) {
    let (mut a, mut b) = (0.0, 1.0);
    if run_hand_kernel(name, &mut a, &mut b, TIMING_PHI, 0.0, 1) {
        g.bench_function(BenchmarkId::new("hand", name), |bench| {
            bench.iter(|| {
                run_hand_kernel(name, &mut a, &mut b, black_box(TIMING_PHI), 0.0, SINGLE_STEPS)
            })
        });
    }
}

/// `hand/<name>` on a batch of [`LANES`] states, when `name` has a
/// hand-written kernel.
pub fn hand_batch(g: &mut BenchmarkGroup<'_, WallTime>, name: &'static str) {
    let (mut a, mut b) = lanes();
    if run_hand_kernel_batch(name, &mut a[..1], &mut b[..1], TIMING_PHI, 0.0, 1) {
        g.bench_function(BenchmarkId::new("hand", name), |bench| {
            bench.iter(|| {
                run_hand_kernel_batch(name, &mut a, &mut b, black_box(TIMING_PHI), 0.0, BATCH_STEPS)
            })
        });
    }
}

/// The exported NodePy catalogue `kind` (`rk` or `lmm`): its `.toml`
/// files under `tests/data/nodepy`, sorted.
pub fn nodepy_files(kind: &str) -> Vec<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/nodepy").join(kind);
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("catalogue")
        .map(|e| e.expect("entry").path().display().to_string())
        .filter(|p| p.ends_with(".toml"))
        .collect();
    v.sort();
    v
}
