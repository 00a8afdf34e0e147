//! `zcheck map`'s arguments read against the method and dispatched: the
//! exact (Φ, NAME) region over one parameter (`one`), or the region over
//! two parameters coloured by the exact Φ_max (`two`).

pub(crate) mod one;
pub(crate) mod two;

use crate::error::Error;
use crate::load::LoadedMethod;
use crate::values::{Exact, ParamArg};
use poly::Q;

/// `LO..HI` as exact rationals with LO < HI.
pub(crate) fn parse_range(flag: &str, s: &str) -> Result<(Q, Q), Error> {
    let Some((lo, hi)) = s.split_once("..") else {
        return Err(Error::usage(format!("{flag} {s}: expected LO..HI, e.g. 0..2.5")));
    };
    let read = |part: &str, which: &str| -> Result<Q, Error> {
        part.parse::<Exact>().map(|e| e.value).map_err(|e| {
            Error::usage(format!(
                "{flag} {s}: {which}: expected a number such as 2, 5/2 or 2.5: {e}"
            ))
        })
    };
    let (lo, hi) = (read(lo, "LO")?, read(hi, "HI")?);
    if lo >= hi {
        return Err(Error::usage(format!("{flag} {s}: expected LO < HI")));
    }
    Ok((lo, hi))
}

/// The `--param` arguments, read and checked against the method: the
/// ranges in the order given, and the values bound.
pub(crate) struct ParamArgs {
    ranges: Vec<(String, (Q, Q))>,
    /// The ranges as typed.
    typed: Vec<String>,
    fixed: Vec<(String, Q)>,
}

pub(crate) fn read_params(args: &[String], method: &poly::Method) -> Result<ParamArgs, Error> {
    let declared: Vec<&str> =
        method.params().iter().map(|s| s.name()).filter(|n| *n != "Phi").collect();
    let mut out = ParamArgs { ranges: Vec::new(), typed: Vec::new(), fixed: Vec::new() };
    for s in args {
        let Some((name, value)) = s.split_once('=') else {
            return Err(Error::usage(format!(
                "--param {s}: expected NAME=LO..HI (a range) or NAME=VALUE"
            )));
        };
        let name = name.trim();
        if value.contains("..") {
            // The name is checked as a NAME=VALUE argument would be.
            let _: ParamArg = format!("{name}=0")
                .parse()
                .map_err(|e: String| Error::usage(format!("--param {s}: {e}")))?;
            out.ranges.push((name.to_owned(), parse_range(&format!("--param {name}"), value)?));
            out.typed.push(s.clone());
        } else {
            let p: ParamArg =
                s.parse().map_err(|e: String| Error::usage(format!("--param {s}: {e}")))?;
            out.fixed.push((p.name, p.value.value));
        }
    }
    let listed = if declared.is_empty() { "none".to_owned() } else { declared.join(", ") };
    match out.ranges.len() {
        0 => {
            return Err(Error::usage(format!(
                "--param: expected one or two ranges NAME=LO..HI over the parameters of method {} (declared: {listed})",
                method.name()
            )))
        }
        1 | 2 => {}
        k => {
            return Err(Error::usage(format!(
                "--param: {k} ranges given; expected one (a (Phi, NAME) map) or two (a map over two parameters)"
            )))
        }
    }
    if out.ranges.len() == 2 && declared.len() < 2 {
        return Err(Error::usage(format!(
            "--param {}: two ranges given, but method {} has {} parameter{} ({listed}): expected one range and --phi for a (Phi, NAME) map",
            out.typed[1],
            method.name(),
            declared.len(),
            if declared.len() == 1 { "" } else { "s" }
        )));
    }
    let names: Vec<&str> = out
        .ranges
        .iter()
        .map(|r| r.0.as_str())
        .chain(out.fixed.iter().map(|f| f.0.as_str()))
        .collect();
    for (k, name) in names.iter().enumerate() {
        if names[..k].contains(name) {
            return Err(Error::usage(format!("--param {name}: given twice")));
        }
        if !declared.contains(name) {
            return Err(Error::usage(format!(
                "--param {name}: method {} has no parameter {name} (declared: {listed})",
                method.name()
            )));
        }
    }
    Ok(out)
}

/// A map as `zcheck map` computes it, before it is drawn or printed.
pub(crate) enum Map {
    /// Over (Φ, NAME).
    PhiParam(one::StabilityMap),
    /// Over two parameters, coloured by Φ_max.
    TwoParams(two::ParamMap),
}

impl Map {
    /// The JSON document of `zcheck map --format json`.
    pub(crate) fn to_json(&self) -> Result<serde_json::Value, Error> {
        Ok(match self {
            Map::PhiParam(m) => serde_json::to_value(m)?,
            Map::TwoParams(m) => serde_json::to_value(m)?,
        })
    }
}

/// The map of `method` over `--phi` (one range) and the `--param`
/// arguments as typed (`NAME=LO..HI` or `NAME=VALUE`), on a grid of `grid`
/// points per axis with `samples` curve samples.
pub(crate) fn compute(
    method: &LoadedMethod,
    phi: Option<&str>,
    params: &[String],
    grid: usize,
    samples: usize,
) -> Result<Map, Error> {
    if !(2..=400).contains(&grid) || !(2..=5000).contains(&samples) {
        return Err(Error::usage(format!(
            "--grid {grid} --samples {samples}: expected 2..=400 grid points and 2..=5000 samples"
        )));
    }
    let params = read_params(params, method.method())?;
    if params.ranges.len() == 2 {
        return compute_two(phi, method, params, grid, samples).map(Map::TwoParams);
    }
    let Some(phi_text) = phi else {
        return Err(Error::usage(format!(
            "--param {}: a map over (Phi, {}) needs --phi LO..HI",
            params.typed[0], params.ranges[0].0
        )));
    };
    let phi = parse_range("--phi", phi_text)?;
    if phi.0 < Q::from_integer(0.into()) {
        return Err(Error::usage(format!("--phi {phi_text}: expected Phi >= 0")));
    }
    let (param, range) = params.ranges.into_iter().next().expect("one range");
    let window = one::MapWindow { phi, param, range, fixed: params.fixed, grid, samples };
    one::map(method, &window).map(Map::PhiParam)
}

/// The map over two parameters.
pub(crate) fn compute_two(
    phi: Option<&str>,
    method: &LoadedMethod,
    params: ParamArgs,
    grid: usize,
    samples: usize,
) -> Result<two::ParamMap, Error> {
    if let Some(phi) = phi {
        return Err(Error::usage(format!(
            "--phi {phi}: a map over two parameters covers every Phi > 0 (each point is coloured by its Phi_max); drop --phi, or give one --param range for a (Phi, NAME) map"
        )));
    }
    let [(n0, r0), (n1, r1)]: [(String, (Q, Q)); 2] =
        params.ranges.try_into().map_err(|_| Error::usage("--param: expected two ranges"))?;
    let missing: Vec<&str> = method
        .method()
        .params()
        .iter()
        .map(|s| s.name())
        .filter(|n| *n != "Phi" && *n != n0 && *n != n1 && !params.fixed.iter().any(|f| f.0 == *n))
        .collect();
    if let Some(name) = missing.first() {
        return Err(Error::usage(format!(
            "--param: method {} has a parameter {name} with no value: give --param {name}=VALUE",
            method.method().name()
        )));
    }
    let window =
        two::ParamWindow { names: [n0, n1], ranges: [r0, r1], fixed: params.fixed, grid, samples };
    two::param_map(method, &window)
}

pub(crate) fn two_text(m: &two::ParamMap, svg: Option<&std::path::Path>) -> String {
    use std::fmt::Write as _;
    let mut out = String::new();
    let [a, b] = &m.axes;
    let fixed: Vec<String> = m.fixed.iter().map(|(k, v)| format!(", {k} = {v}")).collect();
    let _ = writeln!(
        out,
        "method {}: {a} in [{}, {}], {b} in [{}, {}]{}; each point coloured by its exact Phi_max",
        m.method,
        m.ranges[0].0,
        m.ranges[0].1,
        m.ranges[1].0,
        m.ranges[1].1,
        fixed.concat()
    );
    let _ = writeln!(
        out,
        "as Phi -> infinity the roots tend to those of L(z) = {}",
        m.limit_polynomial
    );
    if m.curves.is_empty() {
        let _ = writeln!(out, "L has no curve where a root can cross the unit circle");
    } else {
        let _ = writeln!(out, "exact curves where a root of L can cross the unit circle:");
    }
    for c in &m.curves {
        let role = match (&c.inequality, c.bounds_region) {
            (Some(i), _) => format!("bounds the region: {i}"),
            (None, true) => "separates grid points, on no one side".to_owned(),
            (None, false) => "not an edge on this grid".to_owned(),
        };
        let _ = writeln!(
            out,
            "  {:<12} {} = 0   ({role}; {} points traced)",
            c.kind,
            c.poly,
            c.points.len()
        );
    }
    let unconditional = m.grid.iter().filter(|g| g.unconditional).count();
    let finite: Vec<f64> = m.grid.iter().filter_map(|g| g.phi_max).collect();
    let none = m.grid.len() - unconditional - finite.len();
    let range = if finite.is_empty() {
        String::new()
    } else {
        let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = finite.iter().copied().fold(0.0, f64::max);
        format!(" (from {lo:.6} to {hi:.6})")
    };
    let _ = writeln!(
        out,
        "grid {}x{}: Phi_max = infinity at {unconditional}, finite at {}{range}, none at {none}",
        m.size.0,
        m.size.1,
        finite.len()
    );
    let _ = writeln!(out, "unconditional region: {}", m.region);
    let _ = writeln!(
        out,
        "numeric witnesses (nalgebra, faer eigenvalues) agree with the exact roots and verdict at {} of {} grid points (Phi = Phi_max/2 and 3*Phi_max/2, or 1/2 and 4)",
        m.grid.len() - m.disagreements,
        m.grid.len()
    );
    if let Some(p) = svg {
        let _ = writeln!(out, "wrote {}", p.display());
    }
    out
}
