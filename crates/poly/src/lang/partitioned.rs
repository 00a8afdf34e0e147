//! Partitioned Runge–Kutta pairs and splittings on the oscillator: the
//! `.zm` program of one step of q' = f(p), p' = g(q) with q = y, p = v,
//! f(p) = ω·v and g(q) = −ω·y (the paper's test equation, state `v y`),
//! so that every command that reads a program (stability, verify, derive,
//! the plots) reads these methods too. The nonlinear questions (order,
//! symplecticity) stay with [`crate::advanced::order`].
//!
//! A splitting's step is drift(a₁h) kick(b₁h) … drift(a_s h) kick(b_s h):
//! drift `y = y + a·Φ·v`, kick `v = v − b·Φ·y`, each reading the values
//! the previous flow left (a zero coefficient writes nothing). A pair
//! (a, b) for q and (â, b̂) for p has the stage slopes
//! k_iy = v + Φ Σ_j â_ij k_jv and k_iv = −(y + Φ Σ_j a_ij k_jy), then
//! y += Φ Σ b_i k_iy and v += Φ Σ b̂_i k_iv; its slopes are unknowns
//! unless both tableaux are strictly lower triangular.
//!
//! ```
//! use poly::advanced::tableau::Exact;
//! use poly::advanced::partitioned::splitting_zm;
//! let e = |s: &str| Exact::parse(s).unwrap();
//! let text = splitting_zm("strang", "strang.toml", &[e("1/2"), e("1/2")], &[e("1"), e("0")]);
//! let m = poly::Method::parse("strang.toml", &text)?;
//! let d = poly::derive(&m)?;
//! // Störmer–Verlet on the oscillator: stable up to Φ = 2.
//! let s = d.stability(&poly::Params::new())?;
//! assert_eq!(s.phi_max().map(|p| p.to_string()), Some("2".to_owned()));
//! # Ok::<(), poly::Error>(())
//! ```

use std::fmt::Write as _;

use super::tableau::{Exact, Tableau};

/// `(c)` for a coefficient, parenthesised unless it is a plain unsigned
/// number.
fn coefficient(e: &Exact) -> String {
    let c = e.expr.trim();
    if c.chars().all(|ch| ch.is_ascii_digit() || ch == '/' || ch == '.') {
        c.to_owned()
    } else {
        format!("({c})")
    }
}

/// The radicals of `entries`, each once, in order of appearance.
fn constants<'a>(entries: impl Iterator<Item = &'a Exact>) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    for e in entries {
        for r in &e.radicals {
            if !out.contains(r) {
                out.push(r.clone());
            }
        }
    }
    out
}

fn line(out: &mut String, text: &str) {
    writeln!(out, "{text}").expect("writing to a String");
}

/// The oscillator program of a splitting with drift coefficients `drift`
/// and kick coefficients `kick` (the same length), generated from the file
/// `source`.
pub fn splitting_zm(name: &str, source: &str, drift: &[Exact], kick: &[Exact]) -> String {
    let mut out = String::new();
    line(
        &mut out,
        &format!(
            "# Generated from the splitting {source}: {} drift/kick pairs, on q' = f(p), p' = g(q).",
            drift.len()
        ),
    );
    line(&mut out, "# Oscillator: q = y, p = v, drift y += a Phi v, kick v -= b Phi y.");
    line(&mut out, &format!("method {name}"));
    line(&mut out, "state v y");
    for (c, radical) in constants(drift.iter().chain(kick)) {
        line(&mut out, &format!("const {c} = {radical}"));
    }
    let mut wrote = false;
    for (a, b) in drift.iter().zip(kick) {
        if !a.zero {
            line(&mut out, &format!("y = y + {}*Phi*v", coefficient(a)));
            wrote = true;
        }
        if !b.zero {
            line(&mut out, &format!("v = v - {}*Phi*y", coefficient(b)));
            wrote = true;
        }
    }
    if !wrote {
        line(&mut out, "v = v");
        line(&mut out, "y = y");
    }
    out
}

/// The oscillator program of the partitioned pair `q` (integrating q = y)
/// and `p` (integrating p = v), generated from the file `source`.
pub fn partitioned_zm(name: &str, source: &str, q: &Tableau, p: &Tableau) -> String {
    let s = q.stages();
    let strictly_lower =
        |t: &Tableau| t.a.iter().enumerate().all(|(i, row)| row[i..].iter().all(|e| e.zero));
    let explicit = strictly_lower(q) && strictly_lower(p);
    let mut out = String::new();
    line(
        &mut out,
        &format!(
            "# Generated from the partitioned pair {source}: {s} stages, {}, on q' = f(p), p' = g(q).",
            if explicit { "explicit" } else { "implicit" }
        ),
    );
    line(&mut out, "# Oscillator: q = y, p = v; stage slopes k{i}y = V_i, k{i}v = -Y_i.");
    line(&mut out, &format!("method {name}"));
    line(&mut out, "state v y");
    let all = q.a.iter().flatten().chain(&q.b).chain(p.a.iter().flatten()).chain(&p.b);
    for (c, radical) in constants(all) {
        line(&mut out, &format!("const {c} = {radical}"));
    }
    if !explicit {
        let names: Vec<String> =
            (1..=s).flat_map(|i| [format!("k{i}v"), format!("k{i}y")]).collect();
        line(&mut out, &format!("unknown {}", names.join(" ")));
    }
    // Σ_j m_j k{j}x, or None when every m_j is zero.
    let combo = |coefs: &[Exact], x: char| -> Option<String> {
        let terms: Vec<String> = coefs
            .iter()
            .enumerate()
            .filter(|(_, e)| !e.zero)
            .map(|(j, e)| format!("{}*k{}{x}", coefficient(e), j + 1))
            .collect();
        (!terms.is_empty()).then(|| terms.join(" + "))
    };
    for i in 0..s {
        let k = i + 1;
        match combo(&q.a[i], 'y') {
            Some(c) => line(&mut out, &format!("k{k}v = -(y + Phi*({c}))")),
            None => line(&mut out, &format!("k{k}v = -y")),
        }
        match combo(&p.a[i], 'v') {
            Some(c) => line(&mut out, &format!("k{k}y = v + Phi*({c})")),
            None => line(&mut out, &format!("k{k}y = v")),
        }
    }
    for (x, b) in [('v', &p.b), ('y', &q.b)] {
        match combo(b, x) {
            Some(c) => line(&mut out, &format!("{x} = {x} + Phi*({c})")),
            None => line(&mut out, &format!("{x} = {x}")),
        }
    }
    out
}
