//! `zcheck emit`: the emitted Rust and C functions, compiled by the
//! toolchains on this machine (rustc from `RUSTC` or PATH; `cc`, skipped
//! cleanly when absent) and run, agree bit for bit with the interpreter on
//! every built-in, with the constants folded and with Φ as an argument.

use std::process::Command;

use check::numeric::{Params, ParamsF64, Step};
use poly::{q, Sym, Q};
use testkit::scratch::Scratch;
use zcheck::emit::{emit, Binding, Lang};

const STEPS: u64 = 1000;
const PHI: (i64, i64) = (1, 10);
const D: (i64, i64) = (3, 10);

/// (case name, method, binding) for every built-in, folded and parametric.
fn cases() -> Vec<(String, poly::Method, Binding)> {
    let mut out = Vec::new();
    // An implicit built-in solves a linear system each step: emitted only
    // folded, with the solve A⁻¹E precomputed at the given values.
    for name in poly::advanced::builtins::builtin_names() {
        let m = poly::builtin(name).unwrap();
        let values: Vec<(Sym, Q)> = m
            .params()
            .iter()
            .map(|s| (*s, if s.name() == "Phi" { q(PHI.0, PHI.1) } else { q(D.0, D.1) }))
            .collect();
        out.push((format!("{name}_folded"), m.clone(), Binding::Folded(values)));
        if !m.is_implicit() {
            out.push((format!("{name}_param"), m, Binding::Parametric));
        }
    }
    out
}

fn start(n: usize) -> Vec<f64> {
    (0..n).map(|i| 0.3 + 0.7 * i as f64).collect()
}

/// The interpreter's state after STEPS steps, as bit patterns.
fn oracle(m: &poly::Method) -> Vec<u64> {
    let params = Params::phi(PHI.0 as f64 / PHI.1 as f64).with("D", D.0 as f64 / D.1 as f64);
    let step = Step::compile(m, &params).unwrap();
    let mut s = step.state(&start(step.order()));
    step.advance(&mut s, STEPS);
    s.slots().iter().map(|x| x.to_bits()).collect()
}

/// The argument list a parametric function takes after the state.
fn args(m: &poly::Method, binding: &Binding) -> String {
    match binding {
        Binding::Folded(_) => String::new(),
        Binding::Parametric => {
            m.params().iter().map(|s| if s.name() == "Phi" { ", 0.1" } else { ", 0.3" }).collect()
        }
    }
}

fn scratch(name: &str) -> Scratch {
    Scratch::new(&format!("emit-{name}"))
}

/// Parses the program's lines `case hex hex ...` and compares each case.
#[track_caller]
fn compare(stdout: &str, cases: &[(String, poly::Method, Binding)]) {
    let mut seen = 0;
    for line in stdout.lines() {
        let mut it = line.split_whitespace();
        let case = it.next().unwrap();
        let bits: Vec<u64> = it.map(|h| u64::from_str_radix(h, 16).unwrap()).collect();
        let (_, m, _) = cases.iter().find(|(c, _, _)| c == case).expect("known case");
        assert_eq!(bits, oracle(m), "{case}");
        seen += 1;
    }
    assert_eq!(seen, cases.len(), "every case ran");
}

#[test]
fn emitted_rust_matches_the_interpreter() {
    let cases = cases();
    let mut src = String::from("#![allow(warnings)]\n");
    let mut main = String::from("fn main() {\n");
    for (case, m, binding) in &cases {
        let code = emit(m, Lang::Rust, binding).unwrap();
        let fname = format!("{}_step", m.name());
        src += &code.replace(&format!("fn {fname}("), &format!("fn {case}("));
        let n = Step::compile(m, &Params::phi(0.1).with("D", 0.3)).unwrap().order();
        main += &format!(
            "    let mut s: [f64; {n}] = {:?};\n    for _ in 0..{STEPS} {{ {case}(&mut s{}); }}\n    print!(\"{case}\");\n    for x in s {{ print!(\" {{:x}}\", x.to_bits()); }}\n    println!();\n",
            start(n),
            args(m, binding)
        );
    }
    src += &main;
    src += "}\n";
    let dir = scratch("rust");
    std::fs::write(dir.join("emitted.rs"), &src).unwrap();
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".to_owned());
    let out = Command::new(&rustc)
        .args(["--edition", "2021", "-O", "emitted.rs", "-o", "emitted"])
        .current_dir(dir.path())
        .output()
        .expect("rustc runs");
    assert!(out.status.success(), "rustc: {}", String::from_utf8_lossy(&out.stderr));
    let run = Command::new(dir.join("emitted")).output().unwrap();
    assert!(run.status.success());
    compare(&String::from_utf8_lossy(&run.stdout), &cases);
}

#[test]
fn emitted_c_matches_the_interpreter() {
    if Command::new("cc").arg("--version").output().is_err() {
        eprintln!("no cc on PATH: C emission not compiled");
        return;
    }
    let cases = cases();
    let mut src = String::from("#include <stdio.h>\n#include <string.h>\n#include <stdint.h>\n");
    let mut main = String::from("int main(void) {\n    uint64_t b;\n");
    for (case, m, binding) in &cases {
        let code = emit(m, Lang::C, binding).unwrap();
        let fname = format!("{}_step", m.name());
        src += &code.replace(&format!("void {fname}("), &format!("void {case}("));
        let n = Step::compile(m, &Params::phi(0.1).with("D", 0.3)).unwrap().order();
        let init: Vec<String> = start(n).iter().map(|x| format!("{x:?}")).collect();
        main += &format!(
            "    {{ double s[{n}] = {{{}}};\n      for (int k = 0; k < {STEPS}; k++) {case}(s{});\n      printf(\"{case}\");\n      for (int i = 0; i < {n}; i++) {{ memcpy(&b, &s[i], 8); printf(\" %llx\", (unsigned long long)b); }}\n      printf(\"\\n\"); }}\n",
            init.join(", "),
            args(m, binding)
        );
    }
    src += &main;
    src += "    return 0;\n}\n";
    let dir = scratch("c");
    std::fs::write(dir.join("emitted.c"), &src).unwrap();
    let out = Command::new("cc")
        .args(["-O2", "-ffp-contract=off", "-std=c99", "emitted.c", "-o", "emitted"])
        .current_dir(dir.path())
        .output()
        .expect("cc runs");
    assert!(out.status.success(), "cc: {}", String::from_utf8_lossy(&out.stderr));
    let run = Command::new(dir.join("emitted")).output().unwrap();
    assert!(run.status.success());
    compare(&String::from_utf8_lossy(&run.stdout), &cases);
}

/// The folded function's header names Φ_max and the operation count.
#[test]
fn header_states_the_limit_and_the_count() {
    let m = poly::builtin("false_euler").unwrap();
    let code = emit(&m, Lang::Rust, &Binding::Folded(vec![(Sym::new("Phi"), q(1, 10))])).unwrap();
    assert!(code.contains("Phi_max = 2 (exact)"), "{code}");
    assert!(code.contains("2 mul + 2 add as emitted"), "{code}");
}

/// Without --phi an implicit method cannot be emitted: the solve depends on
/// Φ. The error names the unknowns and the flag.
#[test]
fn implicit_methods_need_folded_values() {
    for name in poly::advanced::builtins::IMPLICIT_METHODS {
        let m = poly::builtin(name).unwrap();
        if !m.is_implicit() {
            continue;
        }
        let e = emit(&m, Lang::Rust, &Binding::Parametric).unwrap_err().to_string();
        assert!(e.contains("is implicit") && e.contains("--phi"), "{name}: {e}");
        assert!(e.contains(&m.unknowns()[0].name), "{name}: {e}");
    }
}
