//! The bodies of the fuzz targets that read `.zm` text, one function per
//! target.
//!
//! They live here, not in the `fuzz_targets/` binaries, so that the same
//! functions replay the committed corpora as ordinary tests under
//! `cargo test --workspace` (`crates/poly/tests/integration/fuzz_corpus.rs`),
//! on machines without the nightly toolchain cargo-fuzz needs. A target
//! fails by panicking: every input must give an `Ok` or a located, bounded
//! `Err`.

/// The largest error text any input may produce, in bytes.
const MAX_ERROR_BYTES: usize = 4000;

/// An error, rendered: bounded, single-line head with a location, and no
/// control character but the line feeds of the snippet.
fn check_error(e: &poly::Error) {
    let shown = e.to_string();
    assert!(shown.len() <= MAX_ERROR_BYTES, "error of {} bytes", shown.len());
    assert!(
        !shown.chars().any(|c| c.is_control() && c != '\n'),
        "control character in error: {shown:?}"
    );
    if e.span().line > 0 {
        assert!(shown.starts_with(&format!("fuzz.zm:{}:{}: ", e.span().line, e.span().col)));
    }
}

/// Parsing: the `.zm` reader on raw bytes, the polynomial reader and the
/// command-line number reader on the text.
pub fn parse(data: &[u8]) {
    if let Err(e) = poly::Method::parse_bytes("fuzz.zm", data) {
        check_error(&e);
    }
    if let Ok(text) = std::str::from_utf8(data) {
        if text.len() <= 2000 {
            let _ = poly::Poly::parse(text);
        }
        let _ = poly::advanced::parse_number(text);
    }
}

/// Parse and derive: every method that parses derives, with the z-domain
/// and state-space routes agreeing and χ of the state's degree.
pub fn parse_derive(data: &[u8]) {
    let Ok(method) = poly::Method::parse_bytes("fuzz.zm", data) else { return };
    let d = poly::derive(&method).unwrap_or_else(|e| panic!("derivation failed: {e}"));
    assert_eq!(d.coeffs().len(), method.slots().len() + 1, "degree of chi");
}

/// Stability on derived polynomials: every parameter but Φ set to a value
/// taken from the input, then the exact analysis returns Ok or Err, never
/// panics.
pub fn stability(data: &[u8]) {
    let (values, src) = match data.split_first() {
        Some((&k, rest)) => (k, rest),
        None => return,
    };
    let Ok(method) = poly::Method::parse_bytes("fuzz.zm", src) else { return };
    let Ok(chi) = poly::advanced::charpoly(&method) else { return };
    // Parameter values 0, 1/4, 1/2, ..., 15/4 and their negatives, picked
    // by the first byte, so that special values (0, 1) are reached.
    let value =
        poly::q(i64::from(values & 0x0f), 4) * poly::q(if values & 0x10 == 0 { 1 } else { -1 }, 1);
    let at: std::collections::HashMap<poly::Sym, poly::Q> =
        method.params().iter().filter(|s| s.name() != "Phi").map(|s| (*s, value.clone())).collect();
    let chi = chi.eval_partial(&at);
    let _ = poly::advanced::stability::analyze(&chi);
}
