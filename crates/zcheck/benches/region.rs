//! `zcheck region`'s work per method: load (parse the TOML or `.zm`,
//! generate and parse the program on y' = λy), derive χ(z, w), and the whole
//! w-plane report (order, error constant, both axes, A(α), ρ∞), on every
//! built-in with a scalar form and on NodePy's RK and multistep catalogues
//! as exported to `tests/data/nodepy` (read exactly).
//!
//! Run: `cargo bench -p zcheck --bench region -- --warm-up-time 1 --measurement-time 3`
//!
//! NodePy's side of the same job, in the same run:
//! `python crates/zcheck/benches/peers/region_vs_nodepy.py`.

mod common;

use std::path::Path;

use common::nodepy_files as files;
use criterion::{criterion_group, criterion_main, Criterion};
use zcheck::load::LoadedMethod;

/// The `zcheck` binary's allocator, so the figures are the command's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// Load, derive and analyse one method from scratch.
fn region(arg: &str) {
    let m = LoadedMethod::load_for_plane(arg).expect("loads");
    let d = m.plane_derivation().expect("derives");
    std::hint::black_box(d.plane(&poly::Params::new()).expect("a report"));
}

fn bench(c: &mut Criterion) {
    let builtins: Vec<String> = poly::advanced::builtins::all_builtin_names()
        .filter(|n| {
            let m = zcheck::api::load(n).expect("a built-in");
            m.plane_derivation().and_then(|d| Ok(d.plane(&poly::Params::new())?)).is_ok()
        })
        .map(str::to_owned)
        .collect();
    // The five slowest methods of all, each the best of five runs: the
    // per-method figure the target is about.
    let mut per: Vec<(f64, String)> = builtins
        .iter()
        .cloned()
        .chain(files("rk"))
        .chain(files("lmm"))
        .map(|m| {
            let best = (0..5)
                .map(|_| {
                    let t = std::time::Instant::now();
                    region(&m);
                    t.elapsed().as_secs_f64()
                })
                .fold(f64::INFINITY, f64::min);
            (best, m)
        })
        .collect();
    per.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (t, m) in per.iter().take(8) {
        eprintln!("slowest: {:8.3} ms  {m}", t * 1e3);
    }
    let mut g = c.benchmark_group("region");
    g.sample_size(10);
    for (name, set) in
        [("builtins", builtins), ("nodepy_rk", files("rk")), ("nodepy_lmm", files("lmm"))]
    {
        eprintln!("{name}: {} methods", set.len());
        g.bench_function(format!("{name}_all"), |b| b.iter(|| set.iter().for_each(|m| region(m))));
    }
    // The slowest single methods, one by one.
    for f in [
        "rk/SDIRK34.toml",
        "rk/PD8.toml",
        "lmm/sand_cc3.toml",
        "lmm/BDF6.toml",
        "rk/RadauIIA3.toml",
    ] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/nodepy").join(f);
        let path = path.display().to_string();
        g.bench_function(f, |b| b.iter(|| region(&path)));
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
