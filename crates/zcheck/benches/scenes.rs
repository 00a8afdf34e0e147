//! Cost of the appendix scenes: one step of each, a full run of Appendix D,
//! the reference integrations, and the appendix claims `zcheck paper` builds.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

use zcheck::scene::aircraft::{self, AircraftConfig, AircraftState};
use zcheck::scene::three_body::{self, ThreeBodyConfig};

fn scenes(c: &mut Criterion) {
    let config = ThreeBodyConfig::appendix_c();
    let mut state = config.initial_state();
    c.bench_function("three_body_false_euler step", |b| {
        b.iter(|| three_body::step(&config, black_box(&mut state), 0.0, false))
    });
    let energy = ThreeBodyConfig::appendix_d_energy();
    let mut state = energy.initial_state();
    let e0 = state.energy_consistent(energy.force_law);
    c.bench_function("three_body_euler_energy step", |b| {
        b.iter(|| three_body::step(&energy, black_box(&mut state), e0, false))
    });
    let air = AircraftConfig::default();
    let mut plane = AircraftState::default();
    c.bench_function("aircraft step", |b| b.iter(|| aircraft::step(&air, black_box(&mut plane))));

    let mut group = c.benchmark_group("runs");
    group.sample_size(10);
    group.bench_function("three_body_euler_energy 100000 steps, invariants followed", |b| {
        b.iter(|| three_body::simulate(black_box(&energy), 100_000, &mut |_| {}))
    });
    group.bench_function(
        "three_body_false_euler reference 1000 steps (Dormand-Prince 1e-12)",
        |b| b.iter(|| three_body::reference(black_box(&config), 1000)),
    );
    group.bench_function("aircraft 300 steps with RK4 reference", |b| {
        b.iter(|| aircraft::simulate(black_box(&air), 300, &mut |_| {}))
    });
    group.bench_function("appendix claims (C, D, E)", |b| b.iter(zcheck::paper::appendix::claims));
    group.finish();
}

criterion_group!(benches, scenes);
criterion_main!(benches);
