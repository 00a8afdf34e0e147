//! `zcheck stability`'s work per method, in process, as Python's
//! `Method.from_nodepy(m).stability()` does it less the interpreter: make the
//! method from its tableau's entries (exact text), then the whole stability
//! document as JSON text, nothing cached between iterations. The ten common
//! methods of NodePy's catalogue that BENCHMARKS.md compares one by one with
//! NodePy's `stability_function()`, read from `tests/data/nodepy/rk`.
//!
//! Run: `cargo bench -p zcheck --bench stability -- --warm-up-time 1 --measurement-time 3`
//!
//! NodePy's side, with the interpreter on zcheck's:
//! `python crates/zcheck-py/bench/stability_vs_nodepy.py`.

use criterion::{criterion_group, criterion_main, Criterion};

/// The `zcheck` binary's allocator, so the figures are the command's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

const METHODS: [&str; 10] =
    ["RK44", "SSP33", "SSP104", "Mid22", "Heun33", "BS5", "DP5", "CK5", "Merson43", "Fehlberg45"];

/// A tableau file's `A` and `b` as entry texts.
fn entries(name: &str) -> (Vec<Vec<String>>, Vec<String>) {
    let path = format!("{}/tests/data/nodepy/rk/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    let table: toml::Table = std::fs::read_to_string(&path).expect("reads").parse().expect("TOML");
    let text = |v: &toml::Value| match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Integer(i) => i.to_string(),
        other => panic!("{path}: an entry {other:?}: expected an integer or a string"),
    };
    let list = |v: &toml::Value| v.as_array().expect("an array").iter().map(text).collect();
    let a = table["A"].as_array().expect("A").iter().map(list).collect();
    (a, list(&table["b"]))
}

/// Make the method and write its stability document.
fn stability(name: &str, a: &[Vec<&str>], b: &[&str]) -> String {
    let m = zcheck::api::tableau(name, a, b, None, None).expect("a tableau");
    serde_json::to_string(&zcheck::api::stability(&m, &[]).expect("a document")).expect("JSON")
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("stability");
    for name in METHODS {
        let (a, b) = entries(name);
        let a: Vec<Vec<&str>> = a.iter().map(|r| r.iter().map(String::as_str).collect()).collect();
        let b: Vec<&str> = b.iter().map(String::as_str).collect();
        g.bench_function(format!("{name}/make_and_document"), |bch| {
            bch.iter(|| std::hint::black_box(stability(name, &a, &b)))
        });
        g.bench_function(format!("{name}/make"), |bch| {
            bch.iter(|| std::hint::black_box(zcheck::api::tableau(name, &a, &b, None, None)))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
