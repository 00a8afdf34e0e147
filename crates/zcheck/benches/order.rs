//! `zcheck order`'s work per method, in process: read the tableau file and
//! make the method (as `zcheck order FILE` and Python's
//! `Method.from_tableau` do), then the whole order report (classical order by
//! rooted trees, linear and stage order, algebraic stability, symplecticity,
//! symmetry, the SSP coefficient, the failed conditions, the tolerance order
//! of decimal input) as JSON, on NodePy's RK catalogue as exported to
//! `tests/data/nodepy/rk` (read exactly).
//!
//! Run: `cargo bench -p zcheck --bench order -- --warm-up-time 1 --measurement-time 3`
//!
//! NodePy's side of the same job, in the same run:
//! `python crates/zcheck-py/bench/order_vs_nodepy.py`.

mod common;

use common::nodepy_files as files;
use criterion::{criterion_group, criterion_main, Criterion};

/// The `zcheck` binary's allocator, so the figures are the command's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// Load one method and write its whole order report.
fn order(path: &str) {
    let m = zcheck::api::load(path).expect("loads");
    report(&m);
}

/// The whole order report of a loaded method, as the JSON text Python's
/// `m.order()` reads.
fn report(m: &zcheck::load::LoadedMethod) {
    std::hint::black_box(zcheck::api::order_text(m, None, None).expect("a report"));
}

fn bench(c: &mut Criterion) {
    // ZCHECK_ORDER_BENCH=SSP63,PD8 keeps only those files (for profiling).
    let only = std::env::var("ZCHECK_ORDER_BENCH").ok();
    let all: Vec<String> = files("rk")
        .into_iter()
        .filter(|p| {
            only.as_ref().is_none_or(|o| o.split(',').any(|k| p.ends_with(&format!("/{k}.toml"))))
        })
        .collect();
    // Each method's best of five, slowest first: the per-method figures.
    let loaded: Vec<_> = all.iter().map(|p| zcheck::api::load(p).expect("loads")).collect();
    let best = |f: &dyn Fn()| {
        (0..5)
            .map(|_| {
                let t = std::time::Instant::now();
                f();
                t.elapsed().as_secs_f64()
            })
            .fold(f64::INFINITY, f64::min)
    };
    let mut per: Vec<(f64, f64, String)> = all
        .iter()
        .zip(&loaded)
        .map(|(p, m)| {
            let name = p.rsplit('/').next().unwrap_or(p).to_owned();
            (best(&|| report(m)), best(&|| order(p)), name)
        })
        .collect();
    per.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (t, whole, name) in &per {
        eprintln!("order {name}: report {:.3} ms, load and report {:.3} ms", t * 1e3, whole * 1e3);
    }
    let mut g = c.benchmark_group("order");
    g.bench_function("nodepy_rk_catalogue/report", |bch| {
        bch.iter(|| loaded.iter().for_each(report))
    });
    g.bench_function("nodepy_rk_catalogue/load_and_report", |bch| {
        bch.iter(|| all.iter().for_each(|p| order(p)))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
