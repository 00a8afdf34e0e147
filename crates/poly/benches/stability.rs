//! Exact stability analysis of multistep and Runge–Kutta methods on the
//! oscillator (the built-ins of `poly::advanced::builtins::COMPARISON_BUILTINS`): `analyze` on χ, from the
//! derived characteristic polynomial to the full report.
//!
//! Run: `cargo bench -p poly --bench stability -- --warm-up-time 1
//! --measurement-time 3`; `benches/sympy_stability.py` does the same job in
//! SymPy for the ratio recorded in BENCHMARKS.md.

use criterion::{criterion_group, criterion_main, Criterion};

const METHODS: &[&str] = &[
    "ab2", "ab3", "ab4", "ab5", "ab6", "ab7", "ab8", "leapfrog", "nystrom3", "nystrom4",
    "nystrom5", "nystrom6", "rk4", "merson", "ssprk104",
];

fn charpoly(name: &str) -> poly::Poly {
    poly::advanced::charpoly(&poly::builtin(name).expect("a built-in")).expect("derives")
}

fn stability(c: &mut Criterion) {
    let mut g = c.benchmark_group("stability");
    for name in METHODS {
        let chi = charpoly(name);
        g.bench_function(*name, |b| {
            b.iter(|| poly::advanced::stability::analyze(&chi).expect("analysis"))
        });
    }
    g.finish();
}

criterion_group!(benches, stability);
criterion_main!(benches);
