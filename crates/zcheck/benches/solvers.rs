//! The game-engine solvers (`zcheck advise --scene FILE --solver ...`),
//! through the library's front door (`zcheck::api`), as the command runs
//! them: one configuration (xpbd, 8 substeps x 2 iterations, the full
//! analysis with its norm certificate and simulation check) and the search
//! (S in 1..64, N in 1..16), on every example scene of at most 200 degrees
//! of freedom; then one configuration on chains of 10 to 1000 masses (the
//! 1000:1 mass-ratio chain), for how the cost grows with the degrees of
//! freedom.
//!
//! Run: `cargo bench -p zcheck --bench solvers -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use zcheck::api;

const EXAMPLES: [&str; 7] = [
    "spring_120hz.toml",
    "quarter_car.toml",
    "building3.toml",
    "chain10.toml",
    "rope2d.toml",
    "cloth_strip.toml",
    "cloth8.toml",
];

fn example(name: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name);
    std::fs::read_to_string(path).expect("an example scene")
}

/// A chain hanging from the ground, masses alternating 1000 kg and 1 kg,
/// 1000 N/m springs.
fn chain(n: usize) -> String {
    let mut s = String::from("tick_hz = 60\nduration_s = 2\n");
    for i in 0..n {
        let kg = if i % 2 == 0 { 1000.0 } else { 1.0 };
        s += &format!("[[mass]]\nname = \"m{i}\"\nkg = {kg}\n");
    }
    for i in 0..n {
        let prev = if i == 0 { "ground".to_owned() } else { format!("m{}", i - 1) };
        s += &format!("[[spring]]\nbetween = [\"{prev}\", \"m{i}\"]\nstiffness = 1000\n");
    }
    s
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("solvers");
    g.sample_size(10);
    for name in EXAMPLES {
        let text = example(name);
        g.bench_function(BenchmarkId::new("xpbd 8x2", name), |b| {
            b.iter(|| api::advise_scene_text(name, &text, Some("xpbd"), Some((8, 2)), &[]).unwrap())
        });
        g.bench_function(BenchmarkId::new("xpbd search", name), |b| {
            b.iter(|| api::advise_scene_text(name, &text, Some("xpbd"), None, &[]).unwrap())
        });
    }
    g.finish();
    let mut g = c.benchmark_group("solvers_dof");
    g.sample_size(10);
    for n in [10usize, 50, 100, 200, 500, 1000] {
        let text = chain(n);
        g.bench_function(BenchmarkId::new("xpbd 8x2 chain", n), |b| {
            b.iter(|| {
                api::advise_scene_text("chain", &text, Some("xpbd"), Some((8, 2)), &[]).unwrap()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
