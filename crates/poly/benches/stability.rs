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

const CHEBYSHEV2: &str = "method chebyshev2\nparam a2\nstate y\ny = y + w*y + a2*w^2*y\n";
const KINNMARK_GRAY: &str =
    "method kinnmark_gray\nparam a3\nstate y\ny = y + w*y + 1/2*w^2*y + a3*w^3*y\n";
const THETA: &str = "method theta\nparam theta\nstate y\ny' = y + w*((1 - theta)*y + theta*y')\n";

/// Every known optimum of the design tests, each a design from the method's
/// text (derived in the loop, as the command does).
fn design(c: &mut Criterion) {
    use poly::advanced::design::{maximize, FreeParam, Objective, ParamTableau, Problem, Subject};
    use poly::{q, Params, Q};
    let mut g = c.benchmark_group("design");
    g.sample_size(10);
    let one = |name: &str, lo: Q, hi: Q| vec![FreeParam::new(name, lo, hi)];
    type Case = (&'static str, &'static str, Objective, Vec<FreeParam>, Params, Option<usize>);
    let programs: Vec<Case> = vec![
        (
            "chebyshev2_real_limit",
            CHEBYSHEV2,
            Objective::RealLimit,
            one("a2", q(0, 1), q(1, 2)),
            Params::new(),
            None,
        ),
        (
            "kinnmark_gray_imag_limit",
            KINNMARK_GRAY,
            Objective::ImagLimit,
            one("a3", q(0, 1), q(1, 2)),
            Params::new(),
            None,
        ),
        (
            "kinnmark_gray_imag_limit_order3",
            KINNMARK_GRAY,
            Objective::ImagLimit,
            one("a3", q(0, 1), q(1, 2)),
            Params::new(),
            Some(3),
        ),
        (
            "theta_real_limit",
            THETA,
            Objective::RealLimit,
            one("theta", q(0, 1), q(2, 5)),
            Params::new(),
            None,
        ),
        (
            "newmark_beta_phi_max",
            NEWMARK,
            Objective::PhiMax,
            one("beta", q(0, 1), q(1, 5)),
            Params::new().bind("gamma", q(1, 2)),
            None,
        ),
        (
            "newmark_beta_gamma_phi_max (two parameters)",
            NEWMARK,
            Objective::PhiMax,
            vec![
                FreeParam::new("beta", q(0, 1), q(1, 5)),
                FreeParam::new("gamma", q(1, 2), q(3, 5)),
            ],
            Params::new(),
            None,
        ),
        (
            "shifted_chebyshev_real_limit (two parameters)",
            CUBIC,
            Objective::RealLimit,
            vec![FreeParam::new("a2", q(0, 1), q(1, 2)), FreeParam::new("a3", q(0, 1), q(1, 6))],
            Params::new(),
            Some(1),
        ),
    ];
    for (name, text, objective, free, bound, min_order) in programs {
        g.bench_function(name, |b| {
            b.iter(|| {
                let d = poly::derive_source("design.zm", text).expect("derives");
                let p = Problem {
                    subject: Subject::Program(&d),
                    objective,
                    free: free.clone(),
                    bound: bound.clone(),
                    min_order,
                };
                maximize(&p).expect("a design")
            })
        });
    }
    g.bench_function("rk2_family_ssp_coefficient", |b| {
        b.iter(|| {
            let t = ParamTableau::new(
                "rk2",
                &["c"],
                &[vec!["0", "0"], vec!["c", "0"]],
                &["1 - 1/(2*c)", "1/(2*c)"],
            )
            .expect("a tableau");
            let p = Problem {
                subject: Subject::Tableau(&t),
                objective: Objective::SspCoefficient,
                free: one("c", q(1, 4), q(2, 1)),
                bound: Params::new(),
                min_order: None,
            };
            maximize(&p).expect("a design")
        })
    });
    g.finish();
}

criterion_group!(benches, stability, design);
criterion_main!(benches);
