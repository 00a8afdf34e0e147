//! The whole-scene advisor on a 1000-mass chain: modal reduction (eigenvalues of
//! a 1000×1000 symmetric matrix), the exact (Φ, D) region of the seven
//! direct methods, exact membership of every mode, accuracy per mode and a
//! brief timing of each method's kernel; no checking simulation. Then the
//! default command's work (with the checking simulation) on that chain and
//! on every example scene (`crates/zcheck/scenes/`).
//!
//! Then the 10⁶-mass grid (`advise_large`, half a minute an iteration).
//!
//! Run: `cargo bench -p zcheck --bench advise -- --warm-up-time 1 --measurement-time 3`

use criterion::{criterion_group, criterion_main, Criterion};
use zcheck::load::LoadedMethod;
use zcheck::scene::advisor::{advise, Options};
use zcheck::scene::file::SceneFile;
use zcheck::scene::modal::{reduce_with, Shapes};

/// A chain of `n` masses hanging from the ground, undamped or with a
/// damper c = k/2000 in every link (Rayleigh damping).
fn chain(n: usize, damped: bool) -> SceneFile {
    let mut s = String::from("tick_hz = 60\nduration_s = 1\n");
    for i in 0..n {
        s += &format!("[[mass]]\nname = \"m{i}\"\nkg = 0.1\n");
    }
    for i in 0..n {
        let prev = if i == 0 { "ground".to_owned() } else { format!("m{}", i - 1) };
        s += &format!("[[spring]]\nbetween = [\"{prev}\", \"m{i}\"]\nstiffness = 1000.0\n");
        if damped {
            s += "damping = 0.5\n";
        }
    }
    SceneFile::parse("chain.toml", &s).expect("a valid chain")
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("advise");
    g.sample_size(10);
    for (name, damped) in [("chain1000_undamped", false), ("chain1000_rayleigh", true)] {
        let scene = chain(1000, damped);
        g.bench_function(name, |b| {
            b.iter(|| {
                let modal = reduce_with(&scene, Shapes::WhenNeeded).unwrap();
                let specs: Vec<LoadedMethod> = poly::advanced::builtins::DAMPED_METHODS
                    .iter()
                    .map(|n| LoadedMethod::builtin(n).unwrap())
                    .collect();
                advise(
                    &scene,
                    &modal,
                    specs,
                    Options {
                        simulate: false,
                        simulate_all: false,
                        gauss_seidel: false,
                        route: Default::default(),
                        rank: Default::default(),
                    },
                )
                .unwrap()
            })
        });
    }
    g.finish();
    let mut g = c.benchmark_group("advise_default");
    g.sample_size(10);
    let examples = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scenes: Vec<(String, SceneFile)> =
        vec![("chain1000_undamped".into(), chain(1000, false))];
    let mut files: Vec<_> = std::fs::read_dir(&examples)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    for f in files {
        let name = f.file_stem().unwrap().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(&f).unwrap();
        scenes.push((name, SceneFile::parse(f.to_str().unwrap(), &text).unwrap()));
    }
    for (name, scene) in &scenes {
        g.bench_function(name.as_str(), |b| {
            b.iter(|| {
                let modal = reduce_with(scene, Shapes::Compute).unwrap();
                let specs: Vec<LoadedMethod> = poly::advanced::builtins::DAMPED_METHODS
                    .iter()
                    .map(|n| LoadedMethod::builtin(n).unwrap())
                    .collect();
                advise(
                    scene,
                    &modal,
                    specs,
                    Options {
                        simulate: true,
                        simulate_all: false,
                        gauss_seidel: false,
                        route: Default::default(),
                        rank: Default::default(),
                    },
                )
                .unwrap()
            })
        });
    }
    g.finish();
    // The scalar grid of 1000×1000 masses (10⁶ DOF, springs to the four
    // neighbours and to ground along the edges), `--no-simulate`: the file
    // read (164 MB of TOML, parsed in chunks), the sparse route and the
    // advice. About 30 s an iteration: run it by name.
    let mut g = c.benchmark_group("advise_large");
    g.sample_size(10);
    let text = grid_text(1000);
    g.bench_function("grid1000_no_simulate", |b| {
        b.iter(|| {
            let scene = SceneFile::parse("grid1000.toml", &text).unwrap();
            let modal = reduce_with(&scene, Shapes::WhenNeeded).unwrap();
            let specs: Vec<LoadedMethod> = poly::advanced::builtins::DAMPED_METHODS
                .iter()
                .map(|n| LoadedMethod::builtin(n).unwrap())
                .collect();
            let options = Options {
                simulate: false,
                simulate_all: false,
                gauss_seidel: false,
                route: Default::default(),
                rank: Default::default(),
            };
            advise(&scene, &modal, specs, options).unwrap()
        })
    });
    g.finish();
}

/// The n×n scalar grid as a scene file: 10 g masses, 100 N/m springs to
/// the four neighbours, and to ground along the edges; 60 Hz, 1 s.
fn grid_text(n: usize) -> String {
    use std::fmt::Write as _;
    let mut s = String::from("tick_hz = 60\nduration_s = 1\n");
    for i in 0..n {
        for j in 0..n {
            let _ = write!(s, "[[mass]]\nname = \"m{i}_{j}\"\nkg = 0.01\n");
        }
    }
    let mut spring = |a: String, b: String| {
        let _ = write!(s, "[[spring]]\nbetween = [\"{a}\", \"{b}\"]\nstiffness = 100.0\n");
    };
    for i in 0..n {
        for j in 0..n {
            if j + 1 < n {
                spring(format!("m{i}_{j}"), format!("m{i}_{}", j + 1));
            }
            if i + 1 < n {
                spring(format!("m{i}_{j}"), format!("m{}_{j}", i + 1));
            }
            if i == 0 || j == 0 || i == n - 1 || j == n - 1 {
                spring("ground".to_owned(), format!("m{i}_{j}"));
            }
        }
    }
    s
}

criterion_group!(benches, bench);
criterion_main!(benches);
