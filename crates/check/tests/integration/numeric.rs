//! The numeric interpreter against hand-written recursions and the exact
//! transition matrix.

use check::numeric::ParamsF64;
use check::numeric::{eval_poly, initial_slots, Batch, Params, Step};

fn compile(name: &str, params: &Params) -> Step {
    let m = poly::builtin(name).expect("built-in");
    Step::compile(&m, params).expect("compiles")
}

/// The compiled step reproduces a hand-written loop bit for bit.
#[track_caller]
fn check_hand(name: &str, phi: f64, start: &[f64], hand: impl Fn(&mut Vec<f64>)) {
    let step = compile(name, &Params::phi(phi));
    let mut state = step.state(start);
    let mut x = start.to_vec();
    for k in 0..1000 {
        step.advance(&mut state, 1);
        hand(&mut x);
        assert_eq!(state.slots(), &x[..], "{name} at step {k}");
    }
}

#[test]
fn compiled_step_matches_hand_loops_bit_for_bit() {
    let phi = 0.3;
    check_hand("false_euler", phi, &[0.0, 1.0], |x| {
        x[0] -= phi * x[1];
        x[1] += phi * x[0];
    });
    check_hand("standard_euler", phi, &[0.2, 1.0], |x| {
        let v = x[0] - phi * x[1];
        x[1] += phi * x[0];
        x[0] = v;
    });
    // Verlet on (y, y@1): y_new = (2 - Phi^2) y - y@1, then y@1 <- y.
    check_hand("verlet", phi, &[1.0, 1.0], |x| {
        let y = (2.0 - phi * phi) * x[0] + -x[1];
        x[1] = x[0];
        x[0] = y;
    });
}

/// Every lane of a batch equals the single-state run bit for bit, across a
/// partial last block.
#[test]
fn batch_lanes_equal_single_runs() {
    for name in ["false_heun", "verlet", "damped_euler", "semi_false_heun_matrix"] {
        let step = compile(name, &Params::phi(0.7));
        let lanes = check::numeric::BLOCK + 37;
        let mut batch = Batch::zeros(&step, lanes);
        let start = |l: usize| -> Vec<f64> {
            (0..step.order()).map(|s| ((l * 7 + s * 3) as f64 * 0.37).sin()).collect()
        };
        for l in 0..lanes {
            batch.set_lane(l, &start(l));
        }
        step.advance_batch(&mut batch, 57);
        for l in [0, 1, check::numeric::BLOCK - 1, check::numeric::BLOCK, lanes - 1] {
            let mut s = step.state(&start(l));
            step.advance(&mut s, 57);
            assert_eq!(batch.lane(l), s.slots(), "{name} lane {l}");
        }
    }
}

/// The numeric P from basis vectors equals the exact P evaluated at the same
/// parameters, to a few rounding errors.
#[test]
fn transition_matrix_matches_exact_entries() {
    for name in poly::advanced::builtins::builtin_names().filter(|n| *n != "damped_euler_d") {
        for phi in [1e-8, 0.1, 0.5, 1.0, 1.9, 3.7] {
            let params = Params::phi(phi);
            let m = poly::builtin(name).unwrap();
            let d = poly::derive(&m).unwrap();
            let p = compile(name, &params).transition_matrix();
            let n = p.nrows();
            for i in 0..n {
                for j in 0..n {
                    // An implicit step's P is d·P over its denominator d = det A.
                    let exact = eval_poly(&d.transition_matrix()[(i, j)], &params).unwrap()
                        / eval_poly(d.p_denominator(), &params).unwrap();
                    let scale = 1.0 + exact.abs() + phi.powi(4);
                    assert!(
                        (p[(i, j)] - exact).abs() <= 16.0 * f64::EPSILON * scale,
                        "{name} phi={phi} P[{i},{j}] = {} vs {exact}",
                        p[(i, j)]
                    );
                }
            }
        }
    }
}

/// A missing parameter is an error that names it.
#[test]
fn missing_parameter_is_an_error() {
    let m = poly::builtin("damped_euler_d").unwrap();
    let err = Step::compile(&m, &Params::phi(0.5)).unwrap_err();
    assert_eq!(
        err.to_string(),
        "method `damped_euler_d` needs a value for parameter `D`: expected it among the given parameters"
    );
    assert!(Step::compile(&m, &Params::phi(0.5).with("D", 0.25)).is_ok());
}

/// Initial slots repeat each variable's value over its history (Verlet's
/// `y2 := 1`).
#[test]
fn initial_slots_fill_history() {
    let m = poly::builtin("verlet").unwrap();
    assert_eq!(initial_slots(&m, |v| if v == "y" { 1.0 } else { 0.0 }), [1.0, 1.0]);
}

/// A float read as the decimal it was typed as: what a user writes reads
/// back as exactly that decimal, and every finite float is recovered from
/// its decimal (the slow oracle: the decimal text through `parse_number`,
/// and the float back through `q_to_f64`).
#[test]
fn floats_read_as_their_decimals() {
    use check::numeric::{f64_to_decimal_q, q_to_f64};
    for typed in ["0.1", "2.675", "1e-7", "123456.789", "0.3333333333333333", "5e-324"] {
        let x: f64 = typed.parse().unwrap();
        let q = poly::advanced::parse_number(typed).unwrap();
        assert_eq!(f64_to_decimal_q(x), Some(q.clone()), "{typed}");
        assert_eq!(f64_to_decimal_q(-x), Some(-q), "-{typed}");
    }
    assert_eq!(f64_to_decimal_q(f64::NAN), None);
    assert_eq!(f64_to_decimal_q(f64::INFINITY), None);
    proptest::proptest!(|(bits in proptest::num::u64::ANY)| {
        let x = f64::from_bits(bits);
        if x.is_finite() {
            let q = f64_to_decimal_q(x).unwrap();
            proptest::prop_assert_eq!(q_to_f64(&q).to_bits(), x.to_bits() & !(u64::from(x == 0.0) << 63));
        }
    });
}
