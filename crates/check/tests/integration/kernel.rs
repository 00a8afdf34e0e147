//! The specialised step (`check::kernel`) against its oracle, the
//! interpreter (`check::numeric::Step`): bit for bit, on every built-in and
//! on generated programs, one state and batches, any number of steps.

use check::kernel::Kernel;
use check::numeric::{Batch, Params, ParamsF64, Step};
use proptest::prelude::*;

/// A start that differs per slot and lane.
pub(crate) fn start(order: usize, lane: usize) -> Vec<f64> {
    (0..order).map(|s| ((lane * 7 + s * 3 + 1) as f64 * 0.37).sin()).collect()
}

/// One state and a batch of `lanes`, `n_steps` steps: the kernel equals the
/// interpreter bit for bit (compared as bits, so a NaN would be caught too).
#[track_caller]
fn check_same(step: &Step, n_steps: u64, lanes: usize) {
    let kernel = Kernel::<f64>::new(step);
    let order = step.order();
    let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    let mut oracle = step.state(&start(order, 0));
    step.advance(&mut oracle, n_steps);
    let mut fast = kernel.state(&start(order, 0));
    kernel.advance(&mut fast, n_steps);
    assert_eq!(
        bits(fast.slots()),
        bits(oracle.slots()),
        "{} one state, {n_steps} steps",
        step.name()
    );
    let mut batch = Batch::zeros(step, lanes);
    let mut data = vec![0.0; lanes * order];
    for l in 0..lanes {
        let x = start(order, l);
        batch.set_lane(l, &x);
        for (s, v) in x.iter().enumerate() {
            data[s * lanes + l] = *v;
        }
    }
    step.advance_batch(&mut batch, n_steps);
    kernel.advance_lanes(&mut data, lanes, n_steps);
    for l in 0..lanes {
        let lane: Vec<f64> = (0..order).map(|s| data[s * lanes + l]).collect();
        assert_eq!(bits(&lane), bits(&batch.lane(l)), "{} lane {l}, {n_steps} steps", step.name());
    }
}

/// Every built-in at several Φ, step counts that are and are not whole
/// unrolled periods, batches narrower and wider than a block.
#[test]
fn kernel_equals_interpreter_on_every_builtin() {
    for name in poly::advanced::builtins::builtin_names() {
        let m = poly::builtin(name).unwrap();
        for phi in [0.1, 0.7, 1.9] {
            let step = Step::compile(&m, &Params::phi(phi).with("D", 0.3)).unwrap();
            for n_steps in [0, 1, 2, 3, 7, 100] {
                for lanes in [1, 5, 16, 17, 64, 131] {
                    check_same(&step, n_steps, lanes);
                }
            }
        }
    }
}

/// The f32 kernel runs the same operations in f32: one state and every lane
/// of a batch agree with a plain f32 transcription of False Euler.
#[test]
fn f32_kernel_matches_hand_f32_loop() {
    let phi = 0.1f32;
    let step = Step::compile(&poly::builtin("false_euler").unwrap(), &Params::phi(0.1)).unwrap();
    let kernel = Kernel::<f32>::new(&step);
    let mut s = kernel.state(&[0.0, 1.0]);
    kernel.advance(&mut s, 1001);
    let (mut v, mut y) = (0.0f32, 1.0f32);
    for _ in 0..1001 {
        v += -phi * y;
        y += phi * v;
    }
    assert_eq!(s.slots(), [v, y]);
    let lanes = 40;
    let mut data = vec![0.0f32; 2 * lanes];
    data[lanes..].fill(1.0);
    kernel.advance_lanes(&mut data, lanes, 1001);
    assert!(data[..lanes].iter().all(|&x| x == v) && data[lanes..].iter().all(|&x| x == y));
}

/// A random linear `.zm` program: 1–3 state variables (some with history),
/// temporaries, sums of 1–7 terms (longer than one instruction holds), and
/// coefficients that are constants, Φ or products.
pub(crate) fn program() -> impl Strategy<Value = String> {
    (
        1usize..=3,
        prop::collection::vec((0u8..=1, prop::collection::vec((0u32..64, 0u32..6), 1..8)), 1..7),
        prop::collection::vec(0u8..=1, 3),
    )
        .prop_map(|(n_vars, assigns, hist)| {
            let vars: Vec<String> = (0..n_vars).map(|i| format!("x{i}")).collect();
            let mut src = format!("method gen\nstate {}\n", vars.join(" "));
            let mut temps: Vec<String> = Vec::new();
            let coefs = ["1", "-1", "0.5", "Phi", "-Phi", "0.25*Phi^2", "3", "-0.75*Phi"];
            for (k, (to_state, terms)) in assigns.iter().enumerate() {
                let mut operands: Vec<String> = vars.clone();
                for (i, v) in vars.iter().enumerate() {
                    if hist[i] == 1 {
                        operands.push(format!("{v}@1"));
                    }
                }
                operands.extend(temps.iter().cloned());
                let sum: Vec<String> = terms
                    .iter()
                    .map(|&(o, c)| {
                        format!(
                            "{}*{}",
                            coefs[(c as usize + o as usize) % coefs.len()],
                            operands[o as usize % operands.len()]
                        )
                    })
                    .collect();
                let target = if *to_state == 1 {
                    vars[k % n_vars].clone()
                } else {
                    temps.push(format!("t{k}"));
                    format!("t{k}")
                };
                src += &format!("{target} = {}\n", sum.join(" + "));
            }
            src
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    /// Generated programs: the kernel equals the interpreter bit for bit.
    #[test]
    fn kernel_equals_interpreter_on_generated_programs(src in program(), n_steps in 0u64..20, lanes in 1usize..80) {
        let m = poly::Method::parse("gen.zm", &src).map_err(|e| TestCaseError::fail(format!("{e}\n{src}")))?;
        let step = Step::compile(&m, &Params::phi(0.3)).unwrap();
        check_same(&step, n_steps, lanes);
    }
}
