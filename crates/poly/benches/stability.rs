//! Exact stability analysis of multistep and Runge–Kutta methods on the
//! oscillator (the built-ins of `poly::advanced::builtins::COMPARISON_BUILTINS`): `analyze` on χ, from the
//! derived characteristic polynomial to the full report.
//!
//! Run: `cargo bench -p poly --bench stability -- --warm-up-time 1
//! --measurement-time 3`; `benches/sympy_stability.py` does the same job in
//! SymPy for the ratio recorded in BENCHMARKS.md.
//!
//! The `design` group times the exact optimiser (`poly::advanced::design`,
//! issue 37) on one one-parameter and one two-parameter known optimum, the
//! derivation included: Newmark's beta with gamma = 1/2 for Phi_max (2*sqrt(5)
//! at 1/5; target 1 s) and the shifted Chebyshev polynomial's (a2, a3) for
//! the real limit (18 at (4/27, 4/729); target 10 s).

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

const NEWMARK: &str = "method newmark\nparam beta\nparam gamma\nstate v y\n\
    y' = y + Phi*v + Phi^2*((1/2 - beta)*(-y) + beta*(-y'))\n\
    v' = v + Phi*((1 - gamma)*(-y) + gamma*(-y'))\n";

const CUBIC: &str =
    "method cubic\nparam a2\nparam a3\nstate y\ny = y + w*y + a2*w^2*y + a3*w^3*y\n";

fn design(c: &mut Criterion) {
    use poly::advanced::design::{maximize, FreeParam, Objective, Problem, Subject};
    use poly::{q, Params};
    let mut g = c.benchmark_group("design");
    g.sample_size(10);
    g.bench_function("newmark_beta_phi_max", |b| {
        b.iter(|| {
            let d = poly::derive_source("newmark.zm", NEWMARK).expect("derives");
            let p = Problem {
                subject: Subject::Program(&d),
                objective: Objective::PhiMax,
                free: vec![FreeParam::new("beta", q(0, 1), q(1, 5))],
                bound: Params::new().bind("gamma", q(1, 2)),
                min_order: None,
            };
            maximize(&p).expect("a design")
        })
    });
    g.bench_function("shifted_chebyshev_real_limit", |b| {
        b.iter(|| {
            let d = poly::derive_source("cubic.zm", CUBIC).expect("derives");
            let p = Problem {
                subject: Subject::Program(&d),
                objective: Objective::RealLimit,
                free: vec![
                    FreeParam::new("a2", q(0, 1), q(1, 2)),
                    FreeParam::new("a3", q(0, 1), q(1, 6)),
                ],
                bound: Params::new(),
                min_order: Some(1),
            };
            maximize(&p).expect("a design")
        })
    });
    g.finish();
}

criterion_group!(benches, stability, design);
criterion_main!(benches);
