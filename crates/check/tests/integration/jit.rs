//! The native step (`check::jit`, feature `jit`) against its oracle, the
//! interpreter (`check::numeric::Step`): bit for bit, on every built-in
//! (explicit, implicit, damped) and on generated programs, one state (every
//! register, not just the slots) and batches of odd widths; the `f32` step
//! against the `f32` kernel.

use check::jit::{BatchRunner, Jit, JitStep};
use check::kernel::Kernel;
use check::numeric::{Batch, Params, ParamsF64, Step};
use proptest::prelude::*;

use super::kernel::{program, start};

fn bits(x: &[f64]) -> Vec<u64> {
    x.iter().map(|v| v.to_bits()).collect()
}

/// Both batch runners of a step (and the automatic choice, the one `compile`
/// makes).
fn both_runners(step: &Step) -> Vec<JitStep> {
    [BatchRunner::Auto, BatchRunner::Registers, BatchRunner::Streaming]
        .into_iter()
        .map(|r| JitStep::compile_with(step, r).unwrap())
        .collect()
}

/// One state and a batch of `lanes`, `n_steps` steps: the native step
/// equals the interpreter bit for bit.
#[track_caller]
fn check_same(step: &Step, jit: &JitStep, n_steps: u64, lanes: usize) {
    let order = step.order();
    let mut oracle = step.state(&start(order, 0));
    step.advance(&mut oracle, n_steps);
    let mut fast = step.state(&start(order, 0));
    jit.advance(&mut fast, n_steps);
    assert_eq!(
        bits(fast.slots()),
        bits(oracle.slots()),
        "{} one state, {n_steps} steps",
        step.name()
    );
    // Every register, scratch included, as the interpreter leaves it.
    assert_eq!(fast, oracle, "{} registers after {n_steps} steps", step.name());

    let mut batch = Batch::zeros(step, lanes);
    for l in 0..lanes {
        batch.set_lane(l, &start(order, l));
    }
    let mut native = batch.clone();
    step.advance_batch(&mut batch, n_steps);
    jit.advance_batch(&mut native, n_steps);
    for l in 0..lanes {
        assert_eq!(
            bits(&native.lane(l)),
            bits(&batch.lane(l)),
            "{} lane {l} of {lanes}, {n_steps} steps",
            step.name()
        );
    }
}

/// Every built-in (explicit, implicit, damped, multistep) at several Φ, step counts
/// 0 to 100, batches of every width modulo the vector groups.
#[test]
fn jit_equals_interpreter_on_every_builtin() {
    let names: Vec<&str> = poly::advanced::builtins::all_builtin_names().collect();
    assert!(
        names.iter().any(|n| poly::advanced::builtins::IMPLICIT_METHODS.contains(n)),
        "implicit built-ins too"
    );
    for name in names {
        let m = poly::builtin(name).unwrap();
        for phi in [0.1, 0.7, 1.9] {
            let step = match Step::compile(&m, &Params::phi(phi).with("D", 0.3)) {
                Ok(s) => s,
                // An implicit step singular at this Φ has no step to compile.
                Err(e) if e.kind() == check::ErrorKind::NotFinite => continue,
                Err(e) => panic!("{name}: {e}"),
            };
            for jit in both_runners(&step) {
                for n_steps in [0, 1, 2, 3, 7, 100] {
                    for lanes in [1, 2, 3, 5, 7, 8, 9, 15, 17, 33, 131, 300] {
                        check_same(&step, &jit, n_steps, lanes);
                    }
                }
            }
        }
    }
}

/// The implicit built-ins compile at Φ = 0.7 (so the loop above really
/// covers them rather than skipping them as singular).
#[test]
fn implicit_builtins_are_compiled() {
    for name in poly::advanced::builtins::IMPLICIT_METHODS {
        let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(0.7)).unwrap();
        JitStep::compile(&step).unwrap();
    }
}

/// A long run stays bit for bit (rounding differences would compound).
#[test]
fn jit_equals_interpreter_over_a_long_run() {
    for name in ["false_euler", "verlet", "standard_heun", "bdf2", "gauss_legendre_2"] {
        let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(0.3)).unwrap();
        for jit in both_runners(&step) {
            check_same(&step, &jit, 20_000, 13);
        }
    }
}

/// A state advanced in pieces equals one advanced at once (the scratch
/// registers a piece leaves behind are never read by the next).
#[test]
fn jit_runs_compose() {
    let step = Step::compile(&poly::builtin("verlet").unwrap(), &Params::phi(0.2)).unwrap();
    let jit = JitStep::compile(&step).unwrap();
    let mut a = step.state(&[1.0, 0.5]);
    let mut b = a.clone();
    jit.advance(&mut a, 5);
    jit.advance(&mut a, 0);
    jit.advance(&mut a, 6);
    step.advance(&mut b, 11);
    assert_eq!(a, b);
}

/// The f32 native step equals the f32 kernel (coefficients rounded from
/// f64, the same operations in f32) on every lane, and a hand-written f32
/// False Euler loop.
#[test]
fn f32_jit_equals_f32_kernel() {
    for name in ["false_euler", "verlet", "false_heun", "bdf2", "standard_heun_matrix"] {
        let step = Step::compile(&poly::builtin(name).unwrap(), &Params::phi(0.1)).unwrap();
        let kernel = Kernel::<f32>::new(&step);
        let registers = Jit::<f32>::compile_with(&step, BatchRunner::Registers).unwrap();
        let streaming = Jit::<f32>::compile_with(&step, BatchRunner::Streaming).unwrap();
        for (jit, lanes) in [&registers, &streaming]
            .into_iter()
            .flat_map(|j| [1, 3, 4, 5, 11, 37, 300].map(|l| (j, l)))
        {
            let mut a: Vec<f32> =
                (0..lanes * step.order()).map(|i| ((i * 5 + 1) as f32 * 0.3).sin()).collect();
            let mut b = a.clone();
            kernel.advance_lanes(&mut a, lanes, 1001);
            jit.advance_lanes(&mut b, lanes, 1001);
            let bits32 = |x: &[f32]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits32(&a), bits32(&b), "{name}, {lanes} lanes");
        }
    }
    let phi = 0.1f32;
    let step = Step::compile(&poly::builtin("false_euler").unwrap(), &Params::phi(0.1)).unwrap();
    let jit = Jit::<f32>::compile(&step).unwrap();
    let mut regs = vec![0.0f32; 4];
    regs[1] = 1.0;
    jit.advance_regs(&mut regs, 1001);
    let (mut v, mut y) = (0.0f32, 1.0f32);
    for _ in 0..1001 {
        v += -phi * y;
        y += phi * v;
    }
    assert_eq!(regs[..2], [v, y]);
}

/// A random implicit `.zm` program: 1–3 state variables, each given by a
/// primed equation whose right side mixes start values, history and the
/// other new values (`x0' = ... + c*x1'`).
fn implicit_program() -> impl Strategy<Value = String> {
    (
        1usize..=3,
        prop::collection::vec(prop::collection::vec((0u32..64, 0u32..6), 1..5), 3),
        0u8..=1,
    )
        .prop_map(|(n_vars, rhs, hist)| {
            let vars: Vec<String> = (0..n_vars).map(|i| format!("x{i}")).collect();
            let mut operands: Vec<String> = vars.clone();
            operands.extend(vars.iter().map(|v| format!("{v}'")));
            if hist == 1 {
                operands.push("x0@1".to_owned());
            }
            let coefs = ["1", "-1", "0.5", "Phi", "-Phi", "0.25*Phi^2", "-0.75*Phi"];
            let mut src = format!("method gen\nstate {}\n", vars.join(" "));
            for (i, v) in vars.iter().enumerate() {
                let sum: Vec<String> = rhs[i]
                    .iter()
                    .map(|&(o, c)| {
                        format!(
                            "{}*{}",
                            coefs[(c as usize + o as usize) % coefs.len()],
                            operands[o as usize % operands.len()]
                        )
                    })
                    .collect();
                src += &format!("{v}' = {v} + {}\n", sum.join(" + "));
            }
            src
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    /// Generated explicit programs at a random Φ: the native step equals
    /// the interpreter bit for bit.
    #[test]
    fn jit_equals_interpreter_on_generated_programs(
        src in program(), phi in 0.01f64..2.0, n_steps in 0u64..40, lanes in 1usize..300,
    ) {
        let m = poly::Method::parse("gen.zm", &src).map_err(|e| TestCaseError::fail(format!("{e}\n{src}")))?;
        let step = Step::compile(&m, &Params::phi(phi)).unwrap();
        for jit in both_runners(&step) {
            check_same(&step, &jit, n_steps, lanes);
        }
    }

    /// Generated implicit programs (where the system is regular at Φ).
    #[test]
    fn jit_equals_interpreter_on_generated_implicit_programs(
        src in implicit_program(), phi in 0.01f64..2.0, n_steps in 0u64..40, lanes in 1usize..300,
    ) {
        let m = match poly::Method::parse("gen.zm", &src) {
            Ok(m) => m,
            // A system singular for every Φ is refused when parsed.
            Err(e) if e.to_string().contains("singular for every Phi") => {
                return Err(TestCaseError::reject("singular for every Phi"));
            }
            Err(e) => return Err(TestCaseError::fail(format!("{e}\n{src}"))),
        };
        prop_assert!(m.is_implicit(), "{}", src);
        let step = Step::compile(&m, &Params::phi(phi));
        prop_assume!(step.is_ok());
        let step = step.unwrap();
        for jit in both_runners(&step) {
            check_same(&step, &jit, n_steps, lanes);
        }
    }
}

/// The automatic choice keeps a short step in registers and streams a long
/// one (so both runners are the ones users get, not only test variants).
#[test]
fn auto_runner_depends_on_the_step_length() {
    let short = Step::compile(&poly::builtin("false_euler").unwrap(), &Params::phi(0.1)).unwrap();
    let long = Step::compile(&poly::builtin("false_heun").unwrap(), &Params::phi(0.1)).unwrap();
    assert!(!JitStep::compile(&short).unwrap().streaming());
    assert!(JitStep::compile(&long).unwrap().streaming());
    assert!(!JitStep::compile_with(&long, BatchRunner::Registers).unwrap().streaming());
}
