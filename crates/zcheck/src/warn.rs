//! Warnings: what an input says that it probably does not mean (a value
//! assigned and never read, a tableau whose weights do not sum to 1, a
//! decimal that is 1/3 to twelve digits). Each goes to stderr once, as
//! `warning: file:line:col: ...`, and the command goes on (exit 0), unless
//! `--deny-warnings` turns them into an error (exit 2) before any output.

use std::collections::HashSet;
use std::io::Write as _;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, OnceLock};

use crate::error::Error;

static DENY: AtomicBool = AtomicBool::new(false);

fn shown() -> &'static Mutex<Vec<String>> {
    static SHOWN: OnceLock<Mutex<Vec<String>>> = OnceLock::new();
    SHOWN.get_or_init(Default::default)
}

/// `--deny-warnings`: every warning is an error.
pub(crate) fn deny(on: bool) {
    DENY.store(on, Ordering::Relaxed);
}

/// Shows the warnings of one input (`file:line:col: message` each), each at
/// most once per run however often the input is read; with
/// `--deny-warnings`, refuses the input when it has any.
pub(crate) fn report(warnings: Vec<String>) -> Result<(), Error> {
    if warnings.is_empty() {
        return Ok(());
    }
    let mut seen = shown().lock().unwrap_or_else(|e| e.into_inner());
    let known: HashSet<&String> = seen.iter().collect();
    let new: Vec<String> = warnings.into_iter().filter(|w| !known.contains(w)).collect();
    for w in &new {
        print_error(&format!("warning: {w}"));
    }
    let n = new.len();
    seen.extend(new);
    if DENY.load(Ordering::Relaxed) && n > 0 {
        return Err(Error::usage(format!(
            "{n} warning{} above, and --deny-warnings makes them errors",
            if n == 1 { "" } else { "s" }
        )));
    }
    Ok(())
}

/// An exact value as a warning shows it: as written when short; a long
/// rational (the sum of decimals read exactly) as its 17-digit decimal.
pub(crate) fn value(p: &poly::Poly) -> String {
    let s = p.to_string();
    match p.as_constant() {
        Some(q) if s.len() > 24 => {
            format!(
                "{} (exactly a ratio of {}-digit integers)",
                check::numeric::q_to_f64(&q),
                q.denom().to_string().len()
            )
        }
        _ => s,
    }
}

/// An exact value against the one expected: as written when short, else as
/// its distance from the expected value (`1 + 4.4e-17`, the sum of
/// decimals that nearly cancel).
pub(crate) fn value_near(p: &poly::Poly, expected: &poly::Poly) -> String {
    let s = p.to_string();
    match (p - expected).as_constant() {
        Some(d) if s.len() > 24 && check::numeric::q_to_f64(&d).abs() < 1e-6 => {
            let d = check::numeric::q_to_f64(&d);
            let sign = if d < 0.0 { '-' } else { '+' };
            format!("{expected} {sign} {:.2e}", d.abs())
        }
        _ => value(p),
    }
}

/// The warnings of a `.zm` program read from `path`.
pub(crate) fn of_method(path: &str, m: &poly::Method) -> Vec<String> {
    m.warnings().iter().map(|w| format!("{path}:{w}")).collect()
}

/// The long decimals of a `.zm` program's text that are within 1e-12 of a
/// simple closed form, located (comments skipped).
pub(crate) fn zm_decimal_hints(path: &str, text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("");
        let chars: Vec<char> = line.chars().collect();
        let mut k = 0;
        while k < chars.len() {
            let starts = chars[k].is_ascii_digit()
                && (k == 0
                    || !(chars[k - 1].is_alphanumeric()
                        || chars[k - 1] == '_'
                        || chars[k - 1] == '.'));
            if !starts {
                k += 1;
                continue;
            }
            let begin = k;
            while k < chars.len() && (chars[k].is_ascii_digit() || chars[k] == '.') {
                k += 1;
            }
            if k < chars.len() && (chars[k] == 'e' || chars[k] == 'E') {
                let mut e = k + 1;
                if e < chars.len() && (chars[e] == '+' || chars[e] == '-') {
                    e += 1;
                }
                if e < chars.len() && chars[e].is_ascii_digit() {
                    k = e;
                    while k < chars.len() && chars[k].is_ascii_digit() {
                        k += 1;
                    }
                }
            }
            let token: String = chars[begin..k].iter().collect();
            if token.contains('.') {
                if let Some(hint) = closed_form_hint(&token) {
                    out.push(format!(
                        "{path}:{}:{}: {token} is within 1e-12 of {hint}: write {hint} if that is meant (the analysis uses the decimal as written)",
                        i + 1,
                        begin + 1
                    ));
                }
            }
        }
    }
    out
}

/// The exact closed form a decimal was probably meant as, when it has ten
/// or more significant digits and lies within 1e-12 of a fraction p/q with
/// q ≤ 1000 or of (a + b√N)/k with small integers: `0.3333333333333333`
/// suggests `1/3`, `0.7886751345948129` suggests `(3 + sqrt(3))/6`. The
/// search is in floats (it only suggests); the analysis keeps what was
/// written.
pub(crate) fn closed_form_hint(decimal: &str) -> Option<String> {
    let digits = decimal.trim_start_matches(['-', '+']);
    let mantissa = digits.split(['e', 'E']).next().unwrap_or("");
    let significant =
        mantissa.trim_start_matches(['0', '.']).chars().filter(char::is_ascii_digit).count();
    if significant < 10 {
        return None;
    }
    let x: f64 = decimal.parse().ok().filter(|x: &f64| x.is_finite() && *x != 0.0)?;
    let close = |y: f64| (x - y).abs() <= 1e-12 * x.abs().max(1.0);
    for q in 1..=1000i64 {
        let p = nearest(x * q as f64);
        if close(p / q as f64) {
            // Exactly p/q already (a decimal like 0.1234567890 is itself).
            if decimal_is(decimal, p as i64, q) {
                return None;
            }
            return Some(if q == 1 { format!("{p}") } else { format!("{p}/{q}") });
        }
    }
    // √N once (the same correctly rounded values the search computes).
    let roots = SQUAREFREE.map(|n| (n as f64).sqrt());
    let surd_value = |a: i64, sb: i64, root: f64, k: i64| (a as f64 + sb as f64 * root) / k as f64;
    // Within the tolerance, neighbouring a (1/k ≥ 1/24 apart) cannot both
    // be close: only the a nearest k·x − s·b·√n can be, so one is tried per
    // sign instead of 25, and the first in the search order (a increasing,
    // the sign + first) is kept. Beyond |x| = 10^9 the
    // tolerance is wide, and the whole search runs.
    if x.abs() > 1e9 {
        return surd_search(&close);
    }
    for k in 1..=24i64 {
        for b in 1..=4i64 {
            for (n, root) in SQUAREFREE.into_iter().zip(roots) {
                let mut best: Option<(i64, i64)> = None;
                for sign in [1i64, -1] {
                    let a = nearest(k as f64 * x - (sign * b) as f64 * root);
                    if !(-12.0..=12.0).contains(&a) {
                        continue;
                    }
                    let a = a as i64;
                    let earlier = best.is_none_or(|(ba, bs)| (a, -sign) < (ba, -bs));
                    if earlier && close(surd_value(a, sign * b, root, k)) {
                        best = Some((a, sign));
                    }
                }
                if let Some((a, sign)) = best {
                    return Some(surd(a, sign * b, n, k));
                }
            }
        }
    }
    None
}

/// `v.round()` without the call into libm (the search's hot loop): below
/// 2^38, adding and subtracting 1.5·2^52 rounds to the nearest integer.
/// That rounds halves to even where `round` rounds them away from zero,
/// but below 2^38 a half is never within the search's tolerance of a
/// candidate (0.5/q > 1e-12·|x| there), so no answer changes.
fn nearest(v: f64) -> f64 {
    const MAGIC: f64 = 6_755_399_441_055_744.0;
    if v.abs() < (1u64 << 38) as f64 {
        (v + MAGIC) - MAGIC
    } else {
        v.round()
    }
}

const SQUAREFREE: [i64; 15] = [2, 3, 5, 6, 7, 10, 11, 13, 14, 15, 17, 19, 21, 22, 23];

/// The search for (a + b√N)/k near x, every candidate in order: the oracle
/// of [`closed_form_hint`]'s shortcut, and its route for huge |x|.
fn surd_search(close: &dyn Fn(f64) -> bool) -> Option<String> {
    for k in 1..=24i64 {
        for b in 1..=4i64 {
            for n in SQUAREFREE {
                for a in -12..=12i64 {
                    for sign in [1i64, -1] {
                        let y = (a as f64 + (sign * b) as f64 * (n as f64).sqrt()) / k as f64;
                        if close(y) {
                            return Some(surd(a, sign * b, n, k));
                        }
                    }
                }
            }
        }
    }
    None
}

/// Whether the decimal text is exactly p/q.
fn decimal_is(decimal: &str, p: i64, q: i64) -> bool {
    poly::advanced::parse_number(decimal.trim_start_matches('-'))
        .map(|v| {
            let v = if decimal.starts_with('-') { -v } else { v };
            v == poly::Q::new(p.into(), q.into())
        })
        .unwrap_or(false)
}

/// (a + b√n)/k as the entry syntax writes it.
fn surd(a: i64, b: i64, n: i64, k: i64) -> String {
    let root = match b.abs() {
        1 => format!("sqrt({n})"),
        m => format!("{m}*sqrt({n})"),
    };
    let num = match (a, b < 0) {
        (0, false) => root,
        (0, true) => format!("-{root}"),
        (a, false) => format!("{a} + {root}"),
        (a, true) => format!("{a} - {root}"),
    };
    match (k, a) {
        (1, _) => num,
        (_, 0) => format!("{num}/{k}"),
        _ => format!("({num})/{k}"),
    }
}

/// The most bytes of an error message printed: enough for any real error,
/// and a bound on what a hostile input can put on the terminal.
const MAX_ERROR_BYTES: usize = 4000;

/// Prints an error on stderr: control and invisible characters (other than
/// line feeds) as `U+XXXX`, and at most [`MAX_ERROR_BYTES`]. A failure to
/// write stderr is ignored: there is nowhere left to report it.
pub(crate) fn print_error(text: &str) {
    let lines: Vec<String> = text
        .trim_end()
        .split('\n')
        .map(|l| poly::advanced::show_invisible(l).into_owned())
        .collect();
    let mut shown = lines.join("\n");
    if shown.len() > MAX_ERROR_BYTES {
        let mut cut = MAX_ERROR_BYTES;
        while !shown.is_char_boundary(cut) {
            cut -= 1;
        }
        let more = shown.len() - cut;
        shown.truncate(cut);
        shown.push_str(&format!("… ({more} more bytes)"));
    }
    let _ = writeln!(std::io::stderr().lock(), "{shown}");
}

#[cfg(test)]
mod tests {
    use super::closed_form_hint;

    /// The fast rounding is `round` wherever the value is not a half.
    #[test]
    fn nearest_is_round_off_the_halves() {
        let mut v = 0.001f64;
        while v < (1u64 << 40) as f64 {
            for x in [v, -v, v + 0.5, v * 1.000_000_1, -(v * 0.999_999_3)] {
                if x.fract().abs() != 0.5 {
                    assert_eq!(super::nearest(x), x.round(), "{x}");
                }
            }
            v *= 1.37;
        }
        assert_eq!(super::nearest(2.5), 2.0);
        assert_eq!(super::nearest((1u64 << 39) as f64 + 0.5), ((1u64 << 39) as f64 + 0.5).round());
    }

    /// The shortcut of the surd search finds what the whole search finds:
    /// on surds themselves, near them, and on numbers that are none.
    #[test]
    fn surd_shortcut_matches_the_search() {
        let mut xs = Vec::new();
        for k in [1, 2, 3, 6, 7, 12, 24] {
            for b in [-4, -1, 1, 3] {
                for n in super::SQUAREFREE {
                    for a in [-12, -5, 0, 1, 7, 12] {
                        let y = (a as f64 + b as f64 * (n as f64).sqrt()) / k as f64;
                        xs.extend([y, y * (1.0 + 3e-13), y + 1e-9]);
                    }
                }
            }
        }
        xs.extend((1..2000).map(|i| (i as f64 * 0.7548776662466927).fract() * 20.0 - 10.0));
        for x in xs.into_iter().filter(|x| *x != 0.0) {
            let text = format!("{x}");
            let close = |y: f64| (x - y).abs() <= 1e-12 * x.abs().max(1.0);
            let slow = super::surd_search(&close);
            let significant = text
                .split(['e', 'E'])
                .next()
                .unwrap_or("")
                .trim_start_matches(['-', '0', '.'])
                .chars()
                .filter(char::is_ascii_digit)
                .count();
            let fraction = (1..=1000i64).any(|q| close((x * q as f64).round() / q as f64));
            if significant >= 10 && !fraction {
                assert_eq!(closed_form_hint(&text), slow, "{text}");
            }
        }
    }

    /// What each decimal was probably meant as, computed back exactly from
    /// the suggestion: the hint is within 1e-12 and is never the decimal
    /// itself.
    #[test]
    fn hints() {
        for (decimal, hint) in [
            ("0.3333333333333333", Some("1/3")),
            ("-0.16666666666666666", Some("-1/6")),
            ("0.7886751345948129", Some("(3 + sqrt(3))/6")),
            ("0.21132486540518713", Some("(3 - sqrt(3))/6")),
            ("0.7071067811865476", Some("sqrt(2)/2")),
            ("1.4142135623730951", Some("sqrt(2)")),
            ("0.1", None),
            ("0.125", None),
            ("0.1234567891", None),
            ("0.3333333", None),
            ("0.5000000000", None),
        ] {
            assert_eq!(closed_form_hint(decimal).as_deref(), hint, "{decimal}");
        }
    }
}
