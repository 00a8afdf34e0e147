//! Butcher tableaux through the library: a tableau read entry by entry
//! derives its built-in's χ (moved here from `lang/tableau.rs`, whose unit
//! tests may not reach up to `derive`).

use poly::advanced::tableau::{Exact, Tableau};

fn e(s: &str) -> Exact {
    Exact::parse(s).unwrap()
}

/// RK4's tableau gives the RK4 built-in's χ.
#[test]
fn rk4_tableau_is_the_builtin() {
    let z = || e("0");
    let a = vec![
        vec![z(), z(), z(), z()],
        vec![e("1/2"), z(), z(), z()],
        vec![z(), e("1/2"), z(), z()],
        vec![z(), z(), e("1"), z()],
    ];
    let b = vec![e("1/6"), e("1/3"), e("1/3"), e("1/6")];
    let c = Some(vec![z(), e("1/2"), e("1/2"), e("1")]);
    let t = Tableau::new("rk4", a, b, c).unwrap();
    assert!(t.is_explicit());
    assert_eq!(t.c_mismatch(), Some(&[][..]));
    let mine = poly::derive(&t.method(false).unwrap()).unwrap();
    let builtin = poly::derive(&poly::builtin("rk4").unwrap()).unwrap();
    assert_eq!(mine.charpoly(), builtin.charpoly());
}

mod stability_function_route {
    use super::*;
    use proptest::prelude::*;

    /// An entry: mostly zero (explicit and diagonally implicit shapes
    /// arise), a fraction, or a radical expression.
    fn entry() -> impl Strategy<Value = String> {
        prop_oneof![
            3 => Just("0".to_owned()),
            4 => (-9i64..10, 1i64..7).prop_map(|(n, d)| format!("{n}/{d}")),
            1 => (-3i64..4, 1i64..5).prop_map(|(n, d)| format!("{n}/{d} + sqrt(3)/{d}")),
            1 => (1i64..4).prop_map(|n| format!("1/{n} - sqrt(2)/4")),
        ]
    }

    fn tableau() -> impl Strategy<Value = (Vec<Vec<String>>, Vec<String>, bool)> {
        (1usize..4).prop_flat_map(|s| {
            (
                proptest::collection::vec(proptest::collection::vec(entry(), s), s),
                proptest::collection::vec(entry(), s),
                any::<bool>(),
            )
        })
    }

    /// A plain entry: zero, a fraction or a decimal, of either sign.
    fn plain_entry() -> impl Strategy<Value = String> {
        prop_oneof![
            3 => Just("0".to_owned()),
            4 => (-99i64..100, 1i64..13).prop_map(|(n, d)| format!("{n}/{d}")),
            1 => (-999i64..1000).prop_map(|n| format!("{}", n as f64 / 8.0)),
        ]
    }

    fn plain_tableau() -> impl Strategy<Value = (Vec<Vec<String>>, Vec<String>, bool)> {
        (1usize..7).prop_flat_map(|s| {
            (
                proptest::collection::vec(proptest::collection::vec(plain_entry(), s), s),
                proptest::collection::vec(plain_entry(), s),
                any::<bool>(),
            )
        })
    }

    /// The tableau of the entry texts; `lower` zeroes A on and above its
    /// diagonal (an explicit method).
    fn read(a: &[Vec<String>], b: &[String], lower: bool) -> Tableau {
        let entry = |i: usize, j: usize| e(if lower && j >= i { "0" } else { &a[i][j] });
        let s = b.len();
        let a: Vec<Vec<Exact>> = (0..s).map(|i| (0..s).map(|j| entry(i, j)).collect()).collect();
        let b: Vec<Exact> = b.iter().map(|x| e(x)).collect();
        Tableau::new("random", a, b, None).unwrap()
    }

    /// `b` with its last entry replaced by 1 − Σ of the others (plain
    /// entries: fractions, or decimals in eighths).
    fn summing_to_one(b: &[String]) -> Vec<String> {
        let value = |s: &str| -> poly::Q {
            if let Some((n, d)) = s.split_once('/') {
                poly::q(n.parse().unwrap(), d.parse().unwrap())
            } else {
                poly::q((s.parse::<f64>().unwrap() * 8.0) as i64, 8)
            }
        };
        let rest: poly::Q = b[..b.len() - 1].iter().map(|s| value(s)).sum();
        let last = poly::Q::from_integer(1.into()) - rest;
        let mut out = b.to_vec();
        *out.last_mut().unwrap() = last.to_string();
        out
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// The method of a plain tableau, whose program is lowered on first
        /// use under a header known in advance, is the program parsed from
        /// its text (the oracle): the same header and the same lines.
        #[test]
        fn deferred_programs_are_the_parsed_ones((a, b, lower) in plain_tableau()) {
            let t = read(&a, &b, lower);
            let parsed = poly::Method::parse("random.zm", &t.to_zm("the tableau", false)).unwrap();
            prop_assert_eq!(&t.method(false).unwrap(), &parsed);
            prop_assert_eq!(t.method(false).unwrap().is_implicit(), parsed.is_implicit());
            let scalar = poly::Method::parse("random.zm", &t.to_scalar_zm("the tableau")).unwrap();
            prop_assert_eq!(&t.scalar_method().unwrap(), &scalar);
        }

        /// The phase and modulus errors read off a plain tableau's
        /// stability function R (log R(iΦ)) are those of χ's principal
        /// branch (the oracle), with |z| ≡ 1 on the first interval said or
        /// not; `consistent` makes Σb = 1, so that R(iΦ) is the root
        /// z ≈ e^{iΦ} (otherwise both give χ's error).
        #[test]
        fn phase_errors_from_r_are_the_branch_ones(
            (a, b, lower) in plain_tableau(),
            consistent in any::<bool>(),
        ) {
            let b = if consistent { summing_to_one(&b) } else { b };
            let t = read(&a, &b, lower);
            let d = poly::derive(&t.method(false).unwrap()).unwrap();
            for on_circle in [false, true] {
                let fast = d.phase_errors_given(&poly::Params::new(), on_circle);
                let slow = poly::advanced::plane::phase_errors(d.charpoly(), on_circle);
                prop_assert_eq!(fast, slow);
            }
        }

        /// On random tableaux (explicit, diagonally and fully implicit,
        /// with radicals; `lower` makes A strictly lower triangular), the
        /// derivation read from R = P/Q is exactly the one of both routes
        /// (the oracle), on the oscillator and on y' = λy: χ, d·P, d, M.
        #[test]
        fn matches_both_routes((a, b, lower) in tableau()) {
            let t = read(&a, &b, lower);
            for m in [t.method(false), t.scalar_method()] {
                let m = m.unwrap();
                // A system singular for every Φ is refused by both.
                let slow = match poly::advanced::derive_both_routes(&m) {
                    Ok(d) => d,
                    Err(_) => continue,
                };
                let fast = poly::derive(&m).unwrap();
                prop_assert_eq!(&fast.charpoly(), &slow.charpoly());
                prop_assert_eq!(&fast.transition_matrix(), &slow.transition_matrix());
                prop_assert_eq!(&fast.p_denominator(), &slow.p_denominator());
                prop_assert_eq!(&fast.z_matrix(), &slow.z_matrix());
            }
        }
    }
}
