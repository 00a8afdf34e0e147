//! `zcheck plot` writes SVG files that state Φ, and the samples it draws are
//! the compiled recursion from v0 = 0, y0 = 1.

use check::numeric::ParamsF64;
use std::process::Command;

use check::numeric::Params;
use zcheck::plot::samples;

/// Every figure is written, is SVG, and carries its Φ in the title.
#[test]
fn plot_all_writes_svg_files() {
    let dir = std::env::temp_dir().join(format!("zcheck-plot-{}", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_zcheck"))
        .args(["plot", "all", "--phi", "0.7", "--out"])
        .arg(&dir)
        .output()
        .expect("runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for name in ["yt_false_euler.svg", "yt_verlet.svg", "yt_all.svg", "zplane.svg"] {
        let text = std::fs::read_to_string(dir.join(name)).expect(name);
        assert!(text.starts_with("<svg"), "{name}");
        if name.starts_with("yt_") {
            assert!(text.contains("Phi = 0.7"), "{name} states Phi");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
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
