//! The step as source code to paste into an engine: Rust or C.
//!
//! The emitted function performs the interpreter's lowered operations
//! ([`check::numeric::Step::listing`]) in the interpreter's order: each
//! instruction is one expression summed left to right, the end-of-step moves
//! become a renaming of locals, and the new state is written back once. With
//! the parameters given, every coefficient is folded into an `f64` literal
//! (printed so that it reads back to the same number); without them, the
//! parameters are arguments and each coefficient is computed at entry the
//! way the interpreter computes it (`c·Φ^k` terms summed in order). For every
//! Φ ≠ 0 the result is bit for bit the interpreter's (the tests compile and
//! run both languages). C compilers must not contract `a + b*c` into a fused
//! multiply-add: the header says to compile with `-ffp-contract=off`.

use std::collections::HashSet;
use std::fmt::Write as _;

use check::numeric::{ListedMove, Params, ParamsF64, Step};
use poly::{Method, Poly, Sym, Q};

use crate::error::Error;

/// The language to emit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Lang {
    /// A Rust function on `&mut [f64; N]`.
    Rust,
    /// A C function on `double s[N]`.
    C,
}

/// How parameters appear in the emitted code.
#[derive(Clone, Debug)]
pub enum Binding {
    /// Folded at these exact values (every parameter of the method).
    Folded(Vec<(Sym, Q)>),
    /// Every parameter is a function argument.
    Parametric,
}

/// A C or Rust identifier from a slot or target name (`y@1` → `y_1`).
fn ident(name: &str) -> String {
    let s: String =
        name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect();
    if s.starts_with(|c: char| c.is_ascii_digit()) {
        format!("_{s}")
    } else {
        s
    }
}

/// An `f64` literal that reads back to exactly `x`, valid in Rust and C.
fn lit(x: f64) -> String {
    format!("{x:?}")
}

/// Φ_max as text, with the parameters other than Φ at `values`.
fn phi_max_text(method: &Method, values: &[(Sym, Q)]) -> String {
    let map = values.iter().filter(|(s, _)| s.name() != "Phi").cloned().collect();
    let Ok(derivation) = poly::derive(method) else { return "not derived".to_owned() };
    let chi = derivation.charpoly().eval_partial(&map);
    if chi.symbols().iter().any(|&s| {
        s.name() != "Phi" && s.name() != "z" && poly::advanced::field::generator_of(s).is_none()
    }) {
        return "depends on the parameters other than Phi".to_owned();
    }
    let params = values
        .iter()
        .filter(|(s, _)| s.name() != "Phi")
        .fold(poly::Params::new(), |p, (s, v)| p.bind(s.name(), v.clone()));
    match derivation.stability(&params) {
        Ok(r) if r.bounded_for_all() => "none: stable for every Phi > 0".to_owned(),
        Ok(r) => match r.phi_max() {
            Some(m) => format!(
                "{} (exact): stable for 0 < Phi < Phi_max",
                m.closed_form().unwrap_or_else(|| m.to_decimal(15))
            ),
            None => "none: unstable for every Phi > 0".to_owned(),
        },
        Err(e) => format!("not decided ({e})"),
    }
}

/// A coefficient polynomial as the interpreter evaluates it: each term's
/// rational rounded to `f64`, times the parameters' powers, summed in order.
fn poly_expr(p: &Poly, lang: Lang) -> String {
    let terms: Vec<String> = p
        .terms()
        .map(|(mono, c)| {
            let cf = check::numeric::q_to_f64(c);
            let mut parts: Vec<String> = Vec::new();
            for &(sym, exp) in mono.factors() {
                let x = ident(&sym.name().to_lowercase());
                parts.push(match (exp, lang) {
                    (1, _) => x,
                    (e, Lang::Rust) => format!("{x}.powi({e})"),
                    (e, Lang::C) => format!("zc_powi({x}, {e})"),
                });
            }
            match (cf, parts.is_empty()) {
                (_, true) => lit(cf),
                (1.0, false) => parts.join(" * "),
                (-1.0, false) => format!("-{}", parts.join(" * ")),
                _ => format!("{} * {}", lit(cf), parts.join(" * ")),
            }
        })
        .collect();
    if terms.is_empty() {
        "0.0".to_owned()
    } else {
        terms.join(" + ")
    }
}

/// The step of `method` as a function in `lang`.
pub fn emit(method: &Method, lang: Lang, binding: &Binding) -> Result<String, Error> {
    // The instruction list: at the given values, or (parametric) at generic
    // values where no coefficient but a constant 1 equals 1.
    let params: Params = match binding {
        Binding::Folded(values) => {
            let mut p = Params::new();
            for (s, q) in values {
                p.set(s.name(), check::numeric::q_to_f64(q));
            }
            p
        }
        Binding::Parametric => {
            method.params().iter().enumerate().fold(Params::new(), |p, (i, s)| {
                p.with(s.name(), std::f64::consts::FRAC_1_SQRT_2 / (7.0 + i as f64))
            })
        }
    };
    if method.is_implicit() && matches!(binding, Binding::Parametric) {
        let names: Vec<&str> = method.unknowns().iter().map(|u| u.name.as_str()).collect();
        return Err(Error::unsupported(format!(
            "{} is implicit: each step solves a linear system for {}, whose solution depends on \
             Phi; give --phi (and every --param) to fold that solve into the emitted step",
            method.name(),
            names.join(", ")
        )));
    }
    let step = Step::compile(method, &params)?;
    let listing = step.listing();
    let n = listing.n_slots;
    let fn_name = format!("{}_step", ident(method.name()));
    let param_names: Vec<String> =
        method.params().iter().map(|s| ident(&s.name().to_lowercase())).collect();

    let mut used: HashSet<String> = HashSet::new();
    let mut fresh = |base: String| -> String {
        let mut name = base.clone();
        let mut k = 1;
        while used.contains(&name) || param_names.contains(&name) || name == "s" {
            k += 1;
            name = format!("{base}_{k}");
        }
        used.insert(name.clone());
        name
    };
    let slot_names: Vec<String> = step.slot_names().iter().map(|s| fresh(ident(s))).collect();
    let mut reg: Vec<String> = slot_names.clone();
    reg.resize(listing.n_regs, String::new());

    let decl = |name: &str| match lang {
        Lang::Rust => format!("let {name}"),
        Lang::C => format!("double {name}"),
    };
    let mut body = String::new();
    let (mut n_mul, mut n_add) = (0usize, 0usize);
    // Coefficients: literals, or locals computed at entry.
    let mut coef_locals: Vec<(String, String)> = Vec::new();
    for (i, name) in slot_names.iter().enumerate() {
        writeln!(body, "    {} = s[{i}];", decl(name)).expect("string");
    }
    let n_assign = method.assigns().len();
    for ins in &listing.instrs {
        // An implicit step's unknowns come first: each a fixed combination
        // of the slots (A⁻¹E at the folded values), named after the unknown.
        if ins.dst >= n + n_assign {
            let u = &method.unknowns()[ins.dst - n - n_assign];
            let terms: Vec<String> =
                ins.terms.iter().map(|t| format!("{} * {}", lit(t.coef), reg[t.src])).collect();
            n_mul += terms.len();
            n_add += terms.len().saturating_sub(1) + usize::from(ins.accumulate);
            let expr = if terms.is_empty() { lit(0.0) } else { terms.join(" + ") };
            let expr = if ins.accumulate { format!("{} + {expr}", reg[ins.dst]) } else { expr };
            let name = fresh(ident(&u.name.replace('\'', "_next")));
            writeln!(body, "    {} = {expr};", decl(&name)).expect("string");
            reg[ins.dst] = name;
            continue;
        }
        let assign = method.assigns()[ins.dst - n].clone();
        let mut terms: Vec<String> = Vec::new();
        for (i, t) in ins.terms.iter().enumerate() {
            let src = reg[t.src].clone();
            if i == 0 && ins.unit_first {
                if let (Binding::Parametric, Some((a, k))) = (binding, t.origin) {
                    if !method.assigns()[a].terms[k].1.is_one() {
                        return Err(Error::unsupported(format!(
                            "{}: a coefficient equals 1 only at the sample values; give the parameters to fold them",
                            method.name()
                        )));
                    }
                }
                terms.push(src);
                continue;
            }
            let c = match (binding, t.origin) {
                (Binding::Parametric, Some((a, k)))
                    if method.assigns()[a].terms[k].1.as_constant().is_none() =>
                {
                    let expr = poly_expr(&method.assigns()[a].terms[k].1, lang);
                    let name = match coef_locals.iter().find(|(_, e)| *e == expr) {
                        Some((name, _)) => name.clone(),
                        None => {
                            let name = format!("k{}", coef_locals.len());
                            coef_locals.push((name.clone(), expr));
                            name
                        }
                    };
                    name
                }
                _ => lit(t.coef),
            };
            n_mul += 1;
            terms.push(format!("{c} * {src}"));
        }
        n_add += terms.len() - 1 + usize::from(ins.accumulate);
        let expr = terms.join(" + ");
        let expr = if ins.accumulate { format!("{} + {expr}", reg[ins.dst]) } else { expr };
        let name = fresh(ident(method.target_name(&assign)));
        writeln!(body, "    {} = {expr};", decl(&name)).expect("string");
        reg[ins.dst] = name;
    }
    for m in &listing.moves {
        match *m {
            ListedMove::Swap(a, b) => reg.swap(a, b),
            ListedMove::Copy { dst, src } => reg[dst] = reg[src].clone(),
        }
    }
    for (i, r) in reg.iter().take(n).enumerate() {
        writeln!(body, "    s[{i}] = {r};").expect("string");
    }

    let values: Vec<(Sym, Q)> = match binding {
        Binding::Folded(v) => v.clone(),
        Binding::Parametric => Vec::new(),
    };
    let cost = poly::advanced::cost::step_cost(method);
    let c = match lang {
        Lang::Rust => "//",
        Lang::C => "//",
    };
    let mut out = String::new();
    writeln!(
        out,
        "{c} {}: one step, emitted by zcheck from the lowered .zm method.",
        method.name()
    )
    .expect("string");
    match binding {
        Binding::Folded(v) => {
            let shown: Vec<String> = v.iter().map(|(s, q)| format!("{} = {q}", s.name())).collect();
            writeln!(out, "{c} Constants folded at {} (f64).", shown.join(", ")).expect("string");
        }
        Binding::Parametric => {
            writeln!(out, "{c} Parameters as arguments: {}.", param_names.join(", "))
                .expect("string")
        }
    }
    writeln!(out, "{c} Phi_max = {}.", phi_max_text(method, &values)).expect("string");
    writeln!(
        out,
        "{c} Operations per step: {n_mul} mul + {n_add} add as emitted{}; exact cost model: {} mul + {} add, copies {}.",
        if coef_locals.is_empty() { String::new() } else { format!(", plus {} coefficients at entry", coef_locals.len()) },
        cost.program.mul,
        cost.program.add,
        cost.program.copy
    )
    .expect("string");
    writeln!(out, "{c} State s, in order: {}.", step.slot_names().join(", ")).expect("string");
    writeln!(
        out,
        "{c} The interpreter's operations in its order: bit for bit the same results{}.",
        match lang {
            Lang::Rust => "",
            Lang::C => " when compiled with -ffp-contract=off (no fused multiply-add)",
        }
    )
    .expect("string");
    let args: Vec<String> = match binding {
        Binding::Folded(_) => Vec::new(),
        Binding::Parametric => param_names
            .iter()
            .map(|p| match lang {
                Lang::Rust => format!(", {p}: f64"),
                Lang::C => format!(", double {p}"),
            })
            .collect(),
    };
    let uses_powi = coef_locals.iter().any(|(_, e)| e.contains("zc_powi"));
    match lang {
        Lang::Rust => writeln!(out, "pub fn {fn_name}(s: &mut [f64; {n}]{}) {{", args.concat())
            .expect("string"),
        Lang::C => {
            if uses_powi {
                out += "#ifndef ZC_POWI\n#define ZC_POWI\n/* a^b by square-and-multiply, as Rust's powi */\nstatic double zc_powi(double a, int b) {\n    double r = 1.0;\n    for (;;) {\n        if (b & 1) r *= a;\n        b /= 2;\n        if (b == 0) break;\n        a *= a;\n    }\n    return r;\n}\n#endif\n";
            }
            writeln!(out, "static void {fn_name}(double s[{n}]{}) {{", args.concat())
                .expect("string")
        }
    }
    // Exact constants (cbrt(2), sqrt(3)) read by a coefficient: the value the
    // interpreter uses, as a literal.
    if !coef_locals.is_empty() {
        let mut generators: Vec<Sym> = method
            .assigns()
            .iter()
            .flat_map(|a| a.terms.iter().flat_map(|(_, c)| c.symbols()))
            .filter(|&s| poly::advanced::field::generator_of(s).is_some())
            .collect();
        generators.sort();
        generators.dedup();
        for g in generators {
            let value = poly::advanced::field::generator_value(g).expect("a generator has a value");
            let name = ident(&g.name().to_lowercase());
            let typed = match lang {
                Lang::Rust => format!("let {name}: f64"),
                Lang::C => format!("double {name}"),
            };
            writeln!(out, "    {typed} = {};", lit(check::numeric::q_to_f64(&value)))
                .expect("string");
        }
    }
    for (name, expr) in &coef_locals {
        writeln!(out, "    {} = {expr};", decl(name)).expect("string");
    }
    out += &body;
    out += "}\n";
    Ok(out)
}
