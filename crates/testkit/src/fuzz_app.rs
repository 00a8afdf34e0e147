//! The bodies of the fuzz targets that read the application's TOML files:
//! the scene reader, the Butcher-tableau reader and the coefficient files of
//! `zcheck order` (pairs, splittings, `bhat`). Behind testkit's `app`
//! feature, because they need the `zcheck` crate; `zcheck`'s integration
//! tests replay their corpora.

/// The largest error text any input may produce, in bytes.
const MAX_ERROR_BYTES: usize = 4000;

/// A rendered error: bounded, located in `fuzz.toml`, no control character.
fn check_error(e: &zcheck::Error) {
    let shown = e.to_string();
    assert!(shown.len() <= MAX_ERROR_BYTES, "error of {} bytes", shown.len());
    assert!(!shown.chars().any(|c| c.is_control()), "control character in error: {shown:?}");
    let Some(at) = e.location() else { panic!("no location: {shown}") };
    assert!(at.line >= 1 && at.col >= 1, "no location: {shown}");
    assert!(shown.starts_with(&format!("fuzz.toml:{}:{}: ", at.line, at.col)), "{shown}");
}

/// The TOML scene reader: every input parses to a scene or gives a located,
/// bounded error; a scene that parses has at least one degree of freedom.
pub fn scene_toml(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    match zcheck::scene::file::SceneFile::parse("fuzz.toml", text) {
        Ok(scene) => assert!(scene.dof() >= 1, "a scene without a degree of freedom"),
        Err(e) => check_error(&e),
    }
}

/// The tableau reader: every input gives a tableau or a located, bounded
/// error; every tableau's generated programs (undamped and damped) parse
/// and derive with their two routes agreeing.
pub fn tableau(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    match zcheck::tableau::Tableau::parse("fuzz.toml", "fuzz", text) {
        Ok(t) => {
            // Bounded work: derivation of a large implicit tableau is cubic.
            if t.stages() > 6 {
                return;
            }
            for damped in [false, true] {
                let src = t.to_zm(damped);
                let m = poly::Method::parse("generated.zm", &src)
                    .unwrap_or_else(|e| panic!("generated program does not parse: {e}\n{src}"));
                if let Err(e) = poly::derive(&m) {
                    // A singular system for every Φ is a real property of
                    // some tableaux (and a clear error), never a panic.
                    assert!(e.to_string().len() <= MAX_ERROR_BYTES, "{e}");
                }
            }
        }
        Err(e) => check_error(&e),
    }
}

/// The readers of `zcheck order` (a tableau with `bhat`, a partitioned pair
/// `[q]`/`[p]`, a splitting `drift`/`kick`, a multistep method): every input
/// gives a reading whose lists all have one entry per stage (per flow, per
/// step), with located, bounded warnings, or a located, bounded error.
pub fn order_toml(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else { return };
    match zcheck::readings::read_coefficients("fuzz.toml", "fuzz", text) {
        Ok(r) => {
            let s = r.lengths[0];
            assert!(s >= 1, "a {} without a stage: {:?}", r.kind, r.lengths);
            assert!(r.lengths.iter().all(|&n| n == s), "{}: lengths {:?}", r.kind, r.lengths);
            for w in &r.warnings {
                assert!(w.len() <= MAX_ERROR_BYTES, "warning of {} bytes", w.len());
                assert!(!w.chars().any(|c| c.is_control()), "control character in warning: {w:?}");
                assert!(w.starts_with("fuzz.toml:"), "warning not located: {w}");
            }
        }
        Err(e) => check_error(&e),
    }
}
