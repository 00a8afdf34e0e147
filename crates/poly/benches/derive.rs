//! Speed of the exact derivation: every built-in by both routes, and the
//! determinant det(zI − P) of 12×12 polynomial matrices (RK4 on a six-mass
//! spring chain, and random dense entries of degree ≤ 2 in Phi).
//!
//! Run with `cargo bench -p poly --bench derive`; the figures are recorded in
//! BENCHMARKS.md, "Derivation (poly)".

use criterion::{criterion_group, criterion_main, Criterion};
use poly::{Method, Poly, PolyMatrix, Sym};
use std::hint::black_box;

use testkit::programs;

/// RK4 on a chain of six unit masses joined by springs to each other and to
/// two walls, written as a `.zm` step program with the four stages as
/// temporaries. Spring `k` (between mass k and k+1, walls at 0 and 7) has
/// stiffness `STIFFNESS[k]`, all scaled by Phi = omega0*T.
fn rk4_spring_chain_source() -> String {
    const N: usize = 6;
    const STIFFNESS: [i64; N + 1] = [1, 2, 3, 1, 2, 3, 1];
    let mut s = String::from("method rk4_chain\nstate");
    for i in 1..=N {
        s += &format!(" x{i}");
    }
    for i in 1..=N {
        s += &format!(" v{i}");
    }
    s.push('\n');
    // The acceleration of mass i from positions named `{pre}{j}`.
    let force = |pre: &str, i: usize| {
        let (kl, kr) = (STIFFNESS[i - 1], STIFFNESS[i]);
        let mut f = format!("-{}*{pre}{i}", kl + kr);
        if i > 1 {
            f += &format!(" + {kl}*{pre}{}", i - 1);
        }
        if i < N {
            f += &format!(" + {kr}*{pre}{}", i + 1);
        }
        f
    };
    for stage in 1..=4 {
        let (xs, vs) = if stage == 1 {
            ("x".to_owned(), "v".to_owned())
        } else {
            (format!("xs{stage}_"), format!("vs{stage}_"))
        };
        for i in 1..=N {
            s += &format!("kx{stage}_{i} = Phi*{vs}{i}\n");
            s += &format!("kv{stage}_{i} = Phi*({})\n", force(&xs, i));
        }
        if stage < 4 {
            let w = if stage < 3 { "0.5*" } else { "" };
            for i in 1..=N {
                s += &format!("xs{}_{i} = x{i} + {w}kx{stage}_{i}\n", stage + 1);
                s += &format!("vs{}_{i} = v{i} + {w}kv{stage}_{i}\n", stage + 1);
            }
        }
    }
    for i in 1..=N {
        s += &format!("x{i} = x{i} + (kx1_{i} + 2*kx2_{i} + 2*kx3_{i} + kx4_{i})/6\n");
    }
    for i in 1..=N {
        s += &format!("v{i} = v{i} + (kv1_{i} + 2*kv2_{i} + 2*kv3_{i} + kv4_{i})/6\n");
    }
    s
}

/// A 12×12 matrix with dense entries `a + b*Phi + c*Phi^2`, small integers
/// from a fixed-seed generator (xorshift), so every run sees the same matrix.
fn random_phi_matrix(n: usize, mut seed: u64) -> PolyMatrix {
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 7) as i64 - 3
    };
    let phi = Poly::sym(Sym::phi());
    let rows = (0..n)
        .map(|_| {
            (0..n)
                .map(|_| {
                    let (a, b, c) = (next(), next(), next());
                    Poly::int(a) + &phi * Poly::int(b) + phi.pow(2) * Poly::int(c)
                })
                .collect()
        })
        .collect();
    PolyMatrix::from_rows(rows)
}

fn bench_builtins(c: &mut Criterion) {
    let methods: Vec<Method> = poly::advanced::builtins::builtin_names()
        .map(|n| poly::builtin(n).expect("built-ins parse"))
        .collect();
    c.bench_function("derive/all_builtins_both_routes", |b| {
        b.iter(|| {
            for m in &methods {
                black_box(poly::derive(black_box(m)).expect("routes agree"));
            }
        })
    });
    // The phases of `derive`, each over all built-ins, to show where time goes.
    c.bench_function("derive/phase/z_route", |b| {
        b.iter(|| {
            for m in &methods {
                black_box(
                    poly::advanced::charpoly_z_route(black_box(m)).expect("degree within order"),
                );
            }
        })
    });
    c.bench_function("derive/phase/state_route", |b| {
        b.iter(|| {
            for m in &methods {
                black_box(poly::advanced::charpoly_state_route(
                    &poly::advanced::transition_matrix(black_box(m)),
                ));
            }
        })
    });
    c.bench_function("derive/all_builtins_parse_and_derive", |b| {
        b.iter(|| {
            for name in poly::advanced::builtins::builtin_names() {
                let m = poly::builtin(black_box(name)).expect("built-ins parse");
                black_box(poly::derive(&m).expect("routes agree"));
            }
        })
    });
}

fn bench_det12(c: &mut Criterion) {
    let rk4 = Method::parse("rk4_chain.zm", &rk4_spring_chain_source()).expect("rk4 chain parses");
    let p = poly::advanced::transition_matrix(&rk4);
    assert_eq!(p.rows(), 12);
    c.bench_function("det12/rk4_spring_chain/charpoly_berkowitz", |b| {
        b.iter(|| black_box(poly::advanced::charpoly_state_route(black_box(&p))))
    });
    // The determinant of zI − P itself (entries in z and Phi) and the whole
    // derivation (whose z route ends in a determinant in 1/z and Phi) take
    // the modular path; the group keeps its name and small sample size from
    // when they ran on the sparse path.
    let zi_minus_p = p.char_matrix(&Poly::sym(Sym::z()));
    let mut slow = c.benchmark_group("det12/rk4_spring_chain/bivariate");
    slow.sample_size(10);
    slow.bench_function("det_of_zI_minus_P", |b| {
        b.iter(|| black_box(black_box(&zi_minus_p).det()))
    });
    slow.bench_function("derive_both_routes", |b| {
        b.iter(|| black_box(poly::derive(black_box(&rk4)).expect("routes agree")))
    });
    slow.finish();
    let r = random_phi_matrix(12, 0x9E37_79B9_7F4A_7C15);
    c.bench_function("det12/random_deg2_phi/charpoly_berkowitz", |b| {
        b.iter(|| black_box(poly::advanced::charpoly_state_route(black_box(&r))))
    });
    c.bench_function("det12/random_deg2_phi/det", |b| b.iter(|| black_box(black_box(&r).det())));
}

/// Both routes of `derive` on RK4 spring chains of 6, 8 and 16 masses
/// (`benches/fixtures/rk4_chain_N.zm`, 12–32 states), each route on its own,
/// and the sparse path on the 6-mass chain for comparison; then parsing and
/// deriving chains of 10,000 temporaries (issue 27 asks for under a second)
/// and one of 100,000.
fn bench_chains(c: &mut Criterion) {
    let mut group = c.benchmark_group("chain");
    group.sample_size(10);
    for n in [6, 8, 16] {
        let m = Method::parse("rk4_chain.zm", &programs::rk4_chain(n)).expect("chain parses");
        group.bench_function(format!("rk4_{n}/derive_both_routes"), |b| {
            b.iter(|| black_box(poly::derive(black_box(&m)).expect("routes agree")))
        });
        group.bench_function(format!("rk4_{n}/z_route"), |b| {
            b.iter(|| {
                black_box(
                    poly::advanced::charpoly_z_route(black_box(&m)).expect("degree within order"),
                )
            })
        });
        group.bench_function(format!("rk4_{n}/state_route"), |b| {
            b.iter(|| {
                black_box(poly::advanced::charpoly_state_route(&poly::advanced::transition_matrix(
                    black_box(&m),
                )))
            })
        });
    }
    // Issue 27's hostile chains of 10,000 temporaries, parsed and derived:
    // copies (`t1 = v`, ..., `v = t10000 - Phi*y`), sums
    // (`x_k = x_{k-1} + Phi*y`), testkit's two-term recurrence, and the
    // copies read by an implicit step.
    for (name, src) in ten_thousand_chains() {
        group.bench_function(format!("temporaries_10000/{name}/parse_and_derive"), |b| {
            b.iter(|| {
                let m = Method::parse("chain.zm", black_box(&src)).expect("chain parses");
                black_box(poly::derive(&m).expect("routes agree"))
            })
        });
    }
    let src = programs::temporary_chain(100_000);
    group.bench_function("temporaries_100000/parse_and_derive", |b| {
        b.iter(|| {
            let m = Method::parse("chain.zm", black_box(&src)).expect("chain parses");
            black_box(poly::derive(&m).expect("routes agree"))
        })
    });
    group.bench_function("temporaries_100000/parse", |b| {
        b.iter(|| black_box(Method::parse("chain.zm", black_box(&src)).expect("chain parses")))
    });
    group.finish();
}

/// The chains of 10,000 temporaries of issue 27, by name.
fn ten_thousand_chains() -> Vec<(&'static str, String)> {
    const N: usize = 10_000;
    let mut copies = String::from("method copies\nstate v y\nt1 = v\n");
    for k in 2..=N {
        copies += &format!("t{k} = t{}\n", k - 1);
    }
    copies += &format!("v = t{N} - Phi*y\ny = y + Phi*v\n");
    let mut sums = String::from("method sums\nstate v y\nx0 = v\n");
    for k in 1..=N {
        sums += &format!("x{k} = x{} + Phi*y\n", k - 1);
    }
    sums += &format!("v = x{N}\ny = y + Phi*v\n");
    let mut implicit =
        String::from("method implicit\nstate v y\nunknown k\nk = -(y + Phi*k/2)\nt1 = k\n");
    for k in 2..=N {
        implicit += &format!("t{k} = t{}\n", k - 1);
    }
    implicit += &format!("v = v + Phi*t{N}\ny = y + Phi*v\n");
    vec![
        ("copies", copies),
        ("sums", sums),
        ("recurrence", programs::temporary_chain(N)),
        ("implicit_copies", implicit),
    ]
}

criterion_group!(benches, bench_builtins, bench_det12, bench_chains);
criterion_main!(benches);
