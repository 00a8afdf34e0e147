//! `zcheck plot` writes SVG files that state Φ, and the samples it draws are
//! the compiled recursion from v0 = 0, y0 = 1.

use check::numeric::ParamsF64;
use std::process::Command;

use check::numeric::Params;
use testkit::scratch::Scratch;
use zcheck::plot::samples;

/// Every figure is written, is SVG, and carries its Φ in the title.
#[test]
fn plot_all_writes_svg_files() {
    let scratch = Scratch::new("plot");
    let dir = scratch.path().to_path_buf();
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(["plot", "all", "--phi", "0.7", "--out"])
        .arg(&dir)
        .output()
        .expect("runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for name in [
        "yt_false_euler.svg",
        "yt_verlet.svg",
        "yt_all.svg",
        "zplane.svg",
        "spectral_radius.svg",
        "period.svg",
    ] {
        let text = std::fs::read_to_string(dir.join(name)).expect(name);
        assert!(text.starts_with("<svg"), "{name}");
        if name.starts_with("yt_") {
            assert!(text.contains("Phi = 0.7"), "{name} states Phi");
        }
    }
}

/// Sample k of False Euler is the paper's y1 := y0 + woT*v1 recursion, and
/// Verlet starts from y@1 = y0 (the paper's y2 := 1).
#[test]
fn samples_follow_the_recursions() {
    let phi = 0.7;
    let fe = samples(&poly::builtin("false_euler").unwrap(), &Params::phi(phi), 50).unwrap();
    let (mut v, mut y) = (0.0f64, 1.0f64);
    for (k, &(t, yk)) in fe.iter().enumerate().skip(1) {
        v -= phi * y;
        y += phi * v;
        assert_eq!((t, yk), (k as f64 * phi, y));
    }
    let vl = samples(&poly::builtin("verlet").unwrap(), &Params::phi(phi), 2).unwrap();
    assert_eq!(vl[1].1, 2.0 - phi * phi - 1.0, "y1 = 2 y0 - y2 - Phi^2 y0 with y2 = y0 = 1");
}

/// The structural-dynamics figures, several methods overlaid: each is SVG,
/// names every method in its legend (with the parameters bound), and says
/// what it plots. The numbers behind them are held to closed forms in
/// `spectral`'s unit tests.
#[test]
fn spectral_radius_and_period_figures() {
    let scratch = Scratch::new("hughes");
    let dir = scratch.path().to_path_buf();
    let newmark = concat!(env!("CARGO_MANIFEST_DIR"), "/methods/newmark.zm");
    let methods = format!("trapezoidal,backward_euler,bdf2,{newmark}");
    for (what, file, titles) in [
        ("spectral-radius", "spectral_radius.svg", &["spectral radius rho(Phi)", "log scale"][..]),
        ("period", "period.svg", &["period elongation", "algorithmic damping", "Phi / 2 pi"][..]),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
            .args(["plot", what, "--methods", &methods, "--param", "beta=0.3025", "--param"])
            .args(["gamma=0.6", "--out"])
            .arg(&dir)
            .output()
            .expect("runs");
        assert!(out.status.success(), "{what}: {}", String::from_utf8_lossy(&out.stderr));
        assert!(String::from_utf8_lossy(&out.stdout).contains(file), "{what}");
        let text = std::fs::read_to_string(dir.join(file)).expect(file);
        assert!(text.starts_with("<svg"), "{file}");
        for label in ["trapezoidal", "backward_euler", "bdf2", "(beta = 121/400, gamma = 3/5)"] {
            assert!(text.contains(label), "{file}: legend lacks {label}");
        }
        for t in titles {
            assert!(text.contains(t), "{file}: lacks {t}");
        }
    }
    // A parameter left without a value, or one no method declares: exit 2.
    for extra in [&["--param", "beta=1/4"][..], &["--param", "beta=1/4", "--param", "delta=1"][..]]
    {
        let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
            .args(["plot", "period", "--methods", newmark, "--out"])
            .arg(&dir)
            .args(extra)
            .output()
            .expect("runs");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {err}");
        assert!(err.contains("gamma") || err.contains("delta"), "{extra:?}: {err}");
    }
}
