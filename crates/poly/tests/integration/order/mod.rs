//! The order analysis (issue 35) against its oracles and the literature:
//! tree conditions against the Taylor expansion of the numerical step on
//! polynomial systems (with h a symbol, SymPy-free), the B-series identity
//! term by term, the SSP coefficient against exact tests at rational r and
//! bisection, PSD against all principal minors, the modified equation
//! against the flow of the modified field, and published values.

use std::cmp::Ordering;

use poly::advanced::field;
use poly::advanced::multistep::Multistep;
use poly::advanced::order::{self, Options, Order, Ssp, Value};
use poly::advanced::tableau::{Exact, Tableau};
use poly::{q, Algebraic, Poly, Sym, Q};
use proptest::prelude::*;

mod partitioned;

fn e(s: &str) -> Exact {
    Exact::parse(s).unwrap_or_else(|err| panic!("{s}: {err}"))
}

fn tableau(a: &[&[&str]], b: &[&str]) -> Tableau {
    let a = a.iter().map(|r| r.iter().map(|x| e(x)).collect()).collect();
    Tableau::new("t", a, b.iter().map(|x| e(x)).collect(), None).unwrap()
}

fn report(t: &Tableau) -> order::OrderReport {
    order::runge_kutta(t, None, &Options::default()).unwrap()
}

fn gauss(s: usize) -> Tableau {
    match s {
        1 => tableau(&[&["1/2"]], &["1"]),
        2 => tableau(&[&["1/4", "1/4 - sqrt(3)/6"], &["1/4 + sqrt(3)/6", "1/4"]], &["1/2", "1/2"]),
        _ => tableau(
            &[
                &["5/36", "2/9 - sqrt(15)/15", "5/36 - sqrt(15)/30"],
                &["5/36 + sqrt(15)/24", "2/9", "5/36 - sqrt(15)/24"],
                &["5/36 + sqrt(15)/30", "2/9 + sqrt(15)/15", "5/36"],
            ],
            &["5/18", "4/9", "5/18"],
        ),
    }
}

fn radau_iia(s: usize) -> Tableau {
    match s {
        1 => tableau(&[&["1"]], &["1"]),
        2 => tableau(&[&["5/12", "-1/12"], &["3/4", "1/4"]], &["3/4", "1/4"]),
        _ => tableau(
            &[
                &["(88 - 7*sqrt(6))/360", "(296 - 169*sqrt(6))/1800", "(-2 + 3*sqrt(6))/225"],
                &["(296 + 169*sqrt(6))/1800", "(88 + 7*sqrt(6))/360", "(-2 - 3*sqrt(6))/225"],
                &["(16 - sqrt(6))/36", "(16 + sqrt(6))/36", "1/9"],
            ],
            &["(16 - sqrt(6))/36", "(16 + sqrt(6))/36", "1/9"],
        ),
    }
}

fn lobatto_iiic(s: usize) -> Tableau {
    match s {
        2 => tableau(&[&["1/2", "-1/2"], &["1/2", "1/2"]], &["1/2", "1/2"]),
        _ => tableau(
            &[&["1/6", "-1/3", "1/6"], &["1/6", "5/12", "-1/12"], &["1/6", "2/3", "1/6"]],
            &["1/6", "2/3", "1/6"],
        ),
    }
}

fn rk4() -> Tableau {
    tableau(
        &[
            &["0", "0", "0", "0"],
            &["1/2", "0", "0", "0"],
            &["0", "1/2", "0", "0"],
            &["0", "0", "1", "0"],
        ],
        &["1/6", "1/3", "1/3", "1/6"],
    )
}

fn issue35() -> Tableau {
    tableau(
        &[
            &["0", "0", "0", "0"],
            &["1", "0", "0", "0"],
            &["0", "1/2", "0", "0"],
            &["0", "0", "1/3", "0"],
        ],
        &["5/24", "7/24", "1/4", "1/4"],
    )
}

fn ssprk33() -> Tableau {
    tableau(&[&["0", "0", "0"], &["1", "0", "0"], &["1/4", "1/4", "0"]], &["1/6", "1/6", "2/3"])
}

fn ssprk104() -> Tableau {
    let a: Vec<Vec<Exact>> = (0..10)
        .map(|i| {
            (0..10)
                .map(|j| {
                    e(match (i, j) {
                        _ if j >= i => "0",
                        (0..=4, _) => "1/6",
                        (_, 0..=4) => "1/15",
                        _ => "1/6",
                    })
                })
                .collect()
        })
        .collect();
    Tableau::new("ssprk104", a, vec![e("1/10"); 10], None).unwrap()
}

fn euler() -> Tableau {
    tableau(&[&["0"]], &["1"])
}

fn merson() -> (Tableau, Vec<Exact>) {
    let t = tableau(
        &[
            &["0", "0", "0", "0", "0"],
            &["1/3", "0", "0", "0", "0"],
            &["1/6", "1/6", "0", "0", "0"],
            &["1/8", "0", "3/8", "0", "0"],
            &["1/2", "0", "-3/2", "2", "0"],
        ],
        &["1/6", "0", "0", "2/3", "1/6"],
    );
    (t, ["1/10", "0", "3/10", "2/5", "1/5"].iter().map(|x| e(x)).collect())
}

// ---------------------------------------------------------------------
// Literature values.

#[test]
fn gauss_radau_lobatto() {
    for s in 1..=3 {
        let r = report(&gauss(s));
        assert_eq!(r.order, Order::Exact(2 * s), "Gauss {s}");
        assert_eq!(r.linear_order, Order::Exact(2 * s), "Gauss {s}");
        assert_eq!(r.stage_order, Some(s), "Gauss {s}");
        assert_eq!(r.algebraically_stable, Some(true), "Gauss {s}");
        assert_eq!(r.symplectic, Some(true), "Gauss {s}");
        assert_eq!(r.symmetric, Some(true), "Gauss {s}");
        assert_eq!(r.reducible, Some(false));
        let r = report(&radau_iia(s));
        assert_eq!(r.order, Order::Exact(2 * s - 1), "Radau IIA {s}");
        assert_eq!(r.stage_order, Some(s), "Radau IIA {s}");
        assert_eq!(r.algebraically_stable, Some(true), "Radau IIA {s}");
        assert_eq!((r.symplectic, r.symmetric), (Some(false), Some(false)), "Radau IIA {s}");
    }
    for s in 2..=3 {
        let r = report(&lobatto_iiic(s));
        assert_eq!(r.order, Order::Exact(2 * s - 2), "Lobatto IIIC {s}");
        assert_eq!(r.algebraically_stable, Some(true), "Lobatto IIIC {s}");
        assert_eq!(r.symplectic, Some(false));
    }
    // Gauss has negative entries: no SSP radius.
    assert_eq!(report(&gauss(2)).ssp_coefficient, Some(Ssp::Radius(Algebraic::zero())));
    assert_eq!(
        report(&gauss(1)).ssp_coefficient,
        Some(Ssp::Radius(Algebraic::from_rational(q(2, 1))))
    );
}

#[test]
fn explicit_methods() {
    let r = report(&rk4());
    assert_eq!(
        (r.order, r.linear_order, r.stage_order),
        (Order::Exact(4), Order::Exact(4), Some(1))
    );
    assert_eq!(r.ssp_coefficient, Some(Ssp::Radius(Algebraic::zero())));
    assert_eq!(r.algebraically_stable, Some(false));
    assert_eq!(r.failed_conditions.as_ref().map(Vec::len), Some(9));
    let r = report(&issue35());
    assert_eq!((r.order, r.linear_order), (Order::Exact(2), Order::Exact(4)));
    let failed = r.failed_conditions.unwrap();
    assert_eq!(failed.len(), 1);
    assert_eq!(failed[0].tree, "[[][]]");
    assert_eq!(failed[0].differential, "f''(f,f)");
    assert_eq!(failed[0].residual, Value::from(q(7, 144)));
    let one = |n: i64| Some(Ssp::Radius(Algebraic::from_rational(q(n, 1))));
    assert_eq!(report(&ssprk33()).ssp_coefficient, one(1));
    assert_eq!(report(&ssprk33()).order, Order::Exact(3));
    let r = report(&ssprk104());
    assert_eq!((r.order, r.ssp_coefficient.clone()), (Order::Exact(4), one(6)));
    let r = report(&euler());
    assert_eq!((r.order, r.ssp_coefficient), (Order::Exact(1), one(1)));
    assert_eq!(report(&radau_iia(1)).ssp_coefficient, Some(Ssp::Unbounded));
}

#[test]
fn merson_pair() {
    let (t, bhat) = merson();
    let r = order::runge_kutta(&t, Some(&bhat), &Options::default()).unwrap();
    assert_eq!(r.kind, order::Kind::EmbeddedPair);
    assert_eq!(r.order, Order::Exact(4));
    assert_eq!(r.embedded_order, Some(Order::Exact(3)));
    assert_eq!(r.embedded_linear_order, Some(Order::Exact(5)));
    let short = &bhat[..4];
    let err = order::runge_kutta(&t, Some(short), &Options::default()).unwrap_err();
    assert!(err.message().contains("bhat has 4 entries: expected 5"), "{err}");
}

/// Reducible tableaux are asked on their reduced form: implicit midpoint
/// written with a duplicated stage is still symplectic and symmetric.
#[test]
fn reducible_tableaux() {
    let t = tableau(&[&["1/4", "1/4"], &["1/4", "1/4"]], &["1/2", "1/2"]);
    let r = report(&t);
    assert_eq!(r.reducible, Some(true));
    assert_eq!((r.symplectic, r.symmetric, r.order), (Some(true), Some(true), Order::Exact(2)));
    // An unused stage with a nonzero M entry (DJ-reducible).
    let t = tableau(&[&["1/2", "0"], &["1", "1"]], &["1", "0"]);
    let r = report(&t);
    assert_eq!((r.reducible, r.symplectic), (Some(true), Some(true)));
}

#[test]
fn tolerance_and_caps() {
    let t = tableau(&[&["0", "0"], &["0.6666666666667", "0"]], &["0.25", "0.75"]);
    let opts = Options { tolerance: Some(q(1, 1_000_000_000_000)), ..Options::default() };
    let r = order::runge_kutta(&t, None, &opts).unwrap();
    assert_eq!(r.order, Order::Exact(1));
    assert_eq!(r.order_within_tolerance.unwrap().order, Order::Exact(2));
    assert!(order::trees(12).is_err());
    let opts = Options { modified: Some(11), ..Options::default() };
    let err = order::runge_kutta(&rk4(), None, &opts).unwrap_err();
    assert_eq!(err.kind(), poly::ErrorKind::TreeOrder);
}

#[test]
fn multistep_orders() {
    let ms = |a: &[&str], b: &[&str]| {
        let m =
            Multistep::new("m", a.iter().map(|x| e(x)).collect(), b.iter().map(|x| e(x)).collect())
                .unwrap();
        order::multistep(&m, &Options::default()).unwrap().order
    };
    assert_eq!(ms(&["-1", "1"], &["0", "1"]), Order::Exact(1));
    assert_eq!(ms(&["0", "-1", "1"], &["-1/2", "3/2", "0"]), Order::Exact(2));
    assert_eq!(ms(&["1/3", "-4/3", "1"], &["0", "0", "2/3"]), Order::Exact(2));
    assert_eq!(ms(&["-1", "0", "1"], &["1/3", "4/3", "1/3"]), Order::Exact(4));
}

// ---------------------------------------------------------------------
// The Taylor oracle: the step applied to polynomial systems, h a symbol.

const N: u32 = 5;

fn h() -> Sym {
    Sym::new("h")
}

/// Terms of degree ≤ n in h, radicals reduced.
fn trunc(p: &Poly, n: u32) -> Poly {
    let p = field::reduce(p);
    Poly::from_terms(
        p.terms().filter(|(m, _)| m.exponent(h()) <= n).map(|(m, c)| (c.clone(), m.clone())),
    )
}

/// A vector field as polynomials in the state symbols.
struct System {
    vars: Vec<Sym>,
    f: Vec<Poly>,
}

impl System {
    fn at(&self, y: &[Poly], n: u32) -> Vec<Poly> {
        self.f
            .iter()
            .map(|fi| {
                let mut p = fi.clone();
                for (v, yi) in self.vars.iter().zip(y) {
                    p = trunc(&p.subs(*v, yi), n);
                }
                p
            })
            .collect()
    }

    /// The exact flow's Taylor polynomial to h^n, by Picard iteration.
    fn flow(&self, y0: &[Q], n: u32) -> Vec<Poly> {
        let start: Vec<Poly> = y0.iter().map(|x| Poly::constant(x.clone())).collect();
        let mut y = start.clone();
        for _ in 0..=n {
            let f = self.at(&y, n);
            y = start.iter().zip(&f).map(|(s, fi)| s + &integrate(fi)).collect();
            y = y.iter().map(|p| trunc(p, n)).collect();
        }
        y
    }
}

/// ∫_0^h p dh.
fn integrate(p: &Poly) -> Poly {
    let mut out = Poly::zero();
    for (m, c) in p.terms() {
        let k = m.exponent(h());
        out += &(&Poly::term(c / Q::from_integer((k + 1).into()), m.clone()) * &Poly::sym(h()));
    }
    out
}

fn values(t: &Tableau) -> (Vec<Vec<Poly>>, Vec<Poly>) {
    let (a, b, _) = t.entries();
    let mut all: Vec<Exact> = a.iter().flatten().cloned().collect();
    all.extend(b.iter().cloned());
    let v = Value::read(&all).unwrap();
    let s = b.len();
    let a = (0..s).map(|i| (0..s).map(|j| v[i * s + j].to_poly()).collect()).collect();
    (a, v[s * s..].iter().map(Value::to_poly).collect())
}

/// One step of the tableau from y0, to h^n: the stages by fixed-point
/// iteration (each sweep fixes one more power of h).
fn rk_step(sys: &System, t: &Tableau, y0: &[Q], n: u32) -> Vec<Poly> {
    let (a, b) = values(t);
    let s = b.len();
    let start: Vec<Poly> = y0.iter().map(|x| Poly::constant(x.clone())).collect();
    let mut stages = vec![start.clone(); s];
    let hp = Poly::sym(h());
    for _ in 0..=n {
        let f: Vec<Vec<Poly>> = stages.iter().map(|y| sys.at(y, n)).collect();
        stages = (0..s)
            .map(|i| {
                (0..start.len())
                    .map(|d| {
                        let mut acc = start[d].clone();
                        for j in 0..s {
                            acc += &(&(&a[i][j] * &hp) * &f[j][d]);
                        }
                        trunc(&acc, n)
                    })
                    .collect()
            })
            .collect();
    }
    let f: Vec<Vec<Poly>> = stages.iter().map(|y| sys.at(y, n)).collect();
    (0..start.len())
        .map(|d| {
            let mut acc = start[d].clone();
            for j in 0..s {
                acc += &(&(&b[j] * &hp) * &f[j][d]);
            }
            trunc(&acc, n)
        })
        .collect()
}

/// The largest p ≤ n with x and y equal up to h^p.
fn agree(x: &[Poly], y: &[Poly], n: u32) -> usize {
    let mut low = n + 1;
    for (p, q) in x.iter().zip(y) {
        let d = trunc(&(p - q), n);
        for (m, _) in d.terms() {
            low = low.min(m.exponent(h()));
        }
    }
    low as usize - 1
}

fn systems() -> Vec<(System, Vec<Q>)> {
    let (y1, y2) = (Sym::new("y1"), Sym::new("y2"));
    let p = |s: &str| Poly::parse(s).unwrap();
    vec![
        (
            System { vars: vec![y1, y2], f: vec![p("y1*y2 + 1/2*y2 + 1"), p("y1^2 - y2 + 1/3")] },
            vec![q(1, 2), q(-1, 3)],
        ),
        (
            System {
                vars: vec![y1, y2],
                f: vec![p("y2^2 + 2*y1 - 1/5"), p("y1*y2^2 + y1^3 + 3/2")],
            },
            vec![q(2, 3), q(1, 4)],
        ),
    ]
}

fn catalogue() -> Vec<(&'static str, Tableau)> {
    vec![
        ("euler", euler()),
        ("rk4", rk4()),
        ("issue35", issue35()),
        ("ssprk33", ssprk33()),
        ("gauss1", gauss(1)),
        ("gauss2", gauss(2)),
        ("radau2", radau_iia(2)),
        ("lobatto3c2", lobatto_iiic(2)),
        ("merson", merson().0),
        ("heun", tableau(&[&["0", "0"], &["1", "0"]], &["1/2", "1/2"])),
        ("bad", tableau(&[&["0", "0"], &["1/3", "0"]], &["1/4", "3/4"])),
    ]
}

/// Order by trees = order by Taylor expansion, and the step's Taylor
/// coefficients are Σ_|t|=k Φ(t)/σ(t)·F(t)(y₀), tree by tree.
#[test]
fn trees_against_taylor_expansion() {
    for (name, t) in catalogue() {
        let r = report(&t);
        let mut taylor = N as usize;
        for (sys, y0) in systems() {
            let step = rk_step(&sys, &t, &y0, N);
            taylor = taylor.min(agree(&step, &sys.flow(&y0, N), N));
            // The B-series, term by term.
            let weights = order::elementary_weights(&t, N as usize).unwrap();
            let mut series: Vec<Poly> = y0.iter().map(|x| Poly::constant(x.clone())).collect();
            for (tree, phi) in &weights {
                let f = differential(&sys, tree.notation(), &y0);
                let k = Poly::sym(h()).pow(tree.order() as u32);
                let c = phi.to_poly().scale(&Q::new(1.into(), tree.symmetry().into()));
                for (s, fi) in series.iter_mut().zip(&f) {
                    *s += &(&(&c * &k) * &Poly::constant(fi.clone()));
                }
            }
            let series: Vec<Poly> = series.iter().map(|p| trunc(p, N)).collect();
            assert_eq!(series, step, "{name}: the B-series");
        }
        let trees = match r.order {
            Order::Exact(p) => p.min(N as usize),
            Order::AtLeast(_) => unreachable!(),
        };
        assert_eq!(trees, taylor, "{name}");
    }
}

/// F(t)(y₀) of a tree in notation, for a system in its symbols.
fn differential(sys: &System, notation: &str, y0: &[Q]) -> Vec<Q> {
    let env: std::collections::HashMap<Sym, Q> =
        sys.vars.iter().copied().zip(y0.iter().cloned()).collect();
    symbolic_differential(sys, notation).iter().map(|p| p.eval(&env).unwrap()).collect()
}

// ---------------------------------------------------------------------
// The modified equation.

#[test]
fn modified_equation_of_euler() {
    let opts = Options { modified: Some(3), ..Options::default() };
    let r = order::runge_kutta(&euler(), None, &opts).unwrap();
    let m = r.modified_equation.unwrap();
    let got: Vec<(usize, &str, String)> =
        m.iter().map(|t| (t.power, t.differential.as_str(), t.coefficient.to_string())).collect();
    assert_eq!(got[0], (1, "f'f", "-1/2".to_owned()));
    assert_eq!(got[1], (2, "f'f'f", "1/3".to_owned()));
    assert_eq!(got[2], (2, "f''(f,f)", "1/12".to_owned()));
    assert_eq!(got.len(), 1 + 2 + 4);
}

/// The exact flow of the modified field, truncated at h^N, reproduces the
/// step to h^(N+1).
#[test]
fn modified_equation_against_its_flow() {
    let n = 3usize;
    for (name, t) in [
        ("euler", euler()),
        ("heun", catalogue().remove(9).1),
        ("radau2", radau_iia(2)),
        ("gauss2", gauss(2)),
    ] {
        let opts = Options { modified: Some(n), ..Options::default() };
        let terms = order::runge_kutta(&t, None, &opts).unwrap().modified_equation.unwrap();
        for (sys, y0) in systems() {
            // f̃ = f + Σ h^k c(t) F(t), as polynomials in the state and h.
            let mut ft: Vec<Poly> = sys.f.clone();
            for term in &terms {
                let f = symbolic_differential(&sys, &term.tree);
                let c = &term.coefficient.to_poly() * &Poly::sym(h()).pow(term.power as u32);
                for (x, fi) in ft.iter_mut().zip(&f) {
                    *x += &(&c * fi);
                }
            }
            let modified = System { vars: sys.vars.clone(), f: ft };
            let top = n as u32 + 1;
            let flow = modified_flow(&modified, &y0, top);
            let step = rk_step(&sys, &t, &y0, top);
            assert_eq!(agree(&flow, &step, top), top as usize, "{name}");
        }
    }
}

/// F(t) of a tree in notation, as polynomials in the system's symbols.
fn symbolic_differential(sys: &System, notation: &str) -> Vec<Poly> {
    fn parse(s: &[u8], at: &mut usize) -> Vec<Vec<u8>> {
        *at += 1;
        let mut kids = Vec::new();
        while s[*at] == b'[' {
            let start = *at;
            parse(s, at);
            kids.push(s[start..*at].to_vec());
        }
        *at += 1;
        kids
    }
    // Σ over index tuples of ∂^m f_i / ∂y_j1..∂y_jm · ∏ F(t_l)_jl.
    fn field(sys: &System, notation: &[u8]) -> Vec<Poly> {
        let mut at = 0;
        let kids = parse(notation, &mut at);
        let args: Vec<Vec<Poly>> = kids.iter().map(|k| field(sys, k)).collect();
        sys.f
            .iter()
            .map(|fi| {
                let mut terms = vec![(fi.clone(), Poly::one())];
                for arg in &args {
                    terms = terms
                        .iter()
                        .flat_map(|(d, w)| {
                            sys.vars.iter().zip(arg).map(move |(v, a)| (d.derivative(*v), w * a))
                        })
                        .collect();
                }
                terms.iter().fold(Poly::zero(), |acc, (d, w)| &acc + &(d * w))
            })
            .collect()
    }
    field(sys, notation.as_bytes())
}

/// The flow over time h of a field that itself holds h: Picard in a
/// separate time symbol τ, then τ = h.
fn modified_flow(sys: &System, y0: &[Q], n: u32) -> Vec<Poly> {
    let tau = Sym::new("tau");
    let cut = |p: &Poly| {
        Poly::from_terms(
            field::reduce(p)
                .terms()
                .filter(|(m, _)| m.exponent(h()) + m.exponent(tau) <= n)
                .map(|(m, c)| (c.clone(), m.clone())),
        )
    };
    let start: Vec<Poly> = y0.iter().map(|x| Poly::constant(x.clone())).collect();
    let mut y = start.clone();
    for _ in 0..=n {
        let f: Vec<Poly> = sys
            .f
            .iter()
            .map(|fi| {
                let mut p = fi.clone();
                for (v, yi) in sys.vars.iter().zip(&y) {
                    p = cut(&p.subs(*v, yi));
                }
                p
            })
            .collect();
        y = start
            .iter()
            .zip(&f)
            .map(|(s, fi)| {
                let mut integral = Poly::zero();
                for (m, c) in fi.terms() {
                    let k = m.exponent(tau);
                    integral += &(&Poly::term(c / Q::from_integer((k + 1).into()), m.clone())
                        * &Poly::sym(tau));
                }
                cut(&(s + &integral))
            })
            .collect();
    }
    y.iter().map(|p| trunc(&p.subs(tau, &Poly::sym(h())), n)).collect()
}

// ---------------------------------------------------------------------
// SSP against exact tests at rational r.

fn ssp_checked(name: &str, t: &Tableau) {
    let r = order::ssp_coefficient(t).unwrap();
    let at = |x: &Q| order::absolutely_monotone_at(t, x).unwrap();
    match r {
        Ssp::Unbounded => {
            for x in [q(1, 2), q(7, 1), q(1000, 1)] {
                assert!(at(&x), "{name} at {x}");
            }
        }
        Ssp::Radius(radius) => {
            let hi = radius.interval().1 + q(1, 1000);
            assert!(!at(&hi), "{name}: fails just past {radius}");
            if radius.sign() == Ordering::Greater {
                let lo = radius.interval().0 - q(1, 1000);
                for k in 0..=8 {
                    let x = &lo * q(k, 8);
                    if x >= Q::from_integer(0.into())
                        && Algebraic::from_rational(x.clone()) < radius
                    {
                        assert!(at(&x), "{name} at {x} < {radius}");
                    }
                }
                // Bisection on rational r to 2^-16 brackets the radius.
                let (mut a, mut b) = (Q::from_integer(0.into()), hi);
                while &b - &a > q(1, 1 << 16) {
                    let m = (&a + &b) / Q::from_integer(2.into());
                    if at(&m) {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                assert!(radius.cmp_rational(&a) != Ordering::Less, "{name}");
                assert!(radius.cmp_rational(&b) != Ordering::Greater, "{name}");
            }
        }
    }
}

#[test]
fn ssp_against_rational_points() {
    for (name, t) in catalogue() {
        ssp_checked(name, &t);
    }
    ssp_checked("ssprk104", &ssprk104());
    ssp_checked("radau1", &radau_iia(1));
    ssp_checked("lobatto3c2", &lobatto_iiic(2));
    // Implicit, nonnegative: the two-stage SSP SDIRK (Ferracina–Spijker),
    // radius 4, and an irrational radius.
    ssp_checked("sdirk", &tableau(&[&["1/4", "0"], &["1/2", "1/4"]], &["1/2", "1/2"]));
    ssp_checked(
        "irrational",
        &tableau(
            &[&["0", "0", "0"], &["1", "0", "0"], &["1/3", "1/5", "0"]],
            &["1/7", "1/2", "5/14"],
        ),
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Random explicit tableaux with nonnegative entries: the exact radius
    /// against exact tests at rational points.
    #[test]
    fn ssp_random_explicit(entries in proptest::collection::vec(0i64..4, 6), b in proptest::collection::vec(0i64..4, 3)) {
        let x = |n: i64| format!("{n}/3");
        let a = vec![
            vec![e("0"), e("0"), e("0")],
            vec![e(&x(entries[0])), e("0"), e("0")],
            vec![e(&x(entries[1])), e(&x(entries[2])), e("0")],
        ];
        let b: Vec<Exact> = b.iter().map(|&n| e(&format!("{n}/5"))).collect();
        let t = Tableau::new("r", a, b, None).unwrap();
        ssp_checked("random", &t);
    }

    /// Random implicit tableaux with nonnegative entries (diagonally
    /// implicit, and full): the exact radius, whose polynomials and D come
    /// from Faddeev–LeVerrier on integers, against exact tests at rational
    /// points, which invert I + rK.
    #[test]
    fn ssp_random_implicit(entries in proptest::collection::vec(0i64..4, 9), b in proptest::collection::vec(0i64..4, 3), full in proptest::bool::ANY) {
        let x = |n: i64| e(&format!("{n}/4"));
        let a = (0..3)
            .map(|i| (0..3).map(|j| if full || j <= i { x(entries[3 * i + j]) } else { e("0") }).collect())
            .collect();
        let b: Vec<Exact> = b.iter().map(|&n| e(&format!("{n}/5"))).collect();
        let t = Tableau::new("r", a, b, None).unwrap();
        ssp_checked("random implicit", &t);
    }

    /// PSD by elimination = PSD by all principal minors.
    #[test]
    fn psd_against_principal_minors(
        vecs in proptest::collection::vec(proptest::collection::vec(-2i64..3, 4), 0..4),
        shift in proptest::collection::vec(-1i64..2, 4),
        n in 1usize..5,
    ) {
        let mut m = vec![vec![Q::from_integer(0.into()); n]; n];
        for v in &vecs {
            for i in 0..n {
                for j in 0..n {
                    m[i][j] += Q::from_integer((v[i] * v[j]).into());
                }
            }
        }
        for i in 0..n {
            m[i][i] += Q::new(shift[i].into(), 2.into());
        }
        let values: Vec<Vec<Value>> = m.iter().map(|r| r.iter().cloned().map(Value::from).collect()).collect();
        prop_assert_eq!(order::positive_semidefinite(&values), Some(minors_nonnegative(&m)));
    }
}

/// Every principal minor ≥ 0 (the slow oracle of PSD).
fn minors_nonnegative(m: &[Vec<Q>]) -> bool {
    let n = m.len();
    (1u32..1 << n).all(|mask| {
        let idx: Vec<usize> = (0..n).filter(|&i| mask & (1 << i) != 0).collect();
        let sub: Vec<Vec<Q>> =
            idx.iter().map(|&i| idx.iter().map(|&j| m[i][j].clone()).collect()).collect();
        det(sub) >= Q::from_integer(0.into())
    })
}

fn det(mut m: Vec<Vec<Q>>) -> Q {
    let n = m.len();
    let mut d = Q::from_integer(1.into());
    for c in 0..n {
        let Some(p) = (c..n).find(|&i| m[i][c] != Q::from_integer(0.into())) else {
            return Q::from_integer(0.into());
        };
        if p != c {
            m.swap(p, c);
            d = -d;
        }
        d *= m[c][c].clone();
        for i in c + 1..n {
            let f = &m[i][c] / &m[c][c];
            let row = m[c].clone();
            for (x, y) in m[i].iter_mut().zip(&row) {
                *x -= &f * y;
            }
        }
    }
    d
}

/// PSD over Q(√2): [[√2, 1], [1, √2/2]] has determinant 0 (PSD), and a
/// little less on the corner is not.
#[test]
fn psd_with_radicals() {
    let v = Value::read(&[e("sqrt(2)"), e("1"), e("sqrt(2)/2"), e("sqrt(2)/2 - 1/1000")]).unwrap();
    let m = vec![vec![v[0].clone(), v[1].clone()], vec![v[1].clone(), v[2].clone()]];
    assert_eq!(order::positive_semidefinite(&m), Some(true));
    let m = vec![vec![v[0].clone(), v[1].clone()], vec![v[1].clone(), v[3].clone()]];
    assert_eq!(order::positive_semidefinite(&m), Some(false));
}

/// By hand, beside NodePy: `ORDER_CATALOGUE=nodepy.json cargo test --release
/// -p poly --test integration order::catalogue -- --ignored --nocapture`,
/// the file a list of `{"name", "A", "b", "bhat"}` with exact entries.
#[test]
#[ignore]
fn catalogue_report() {
    let Ok(path) = std::env::var("ORDER_CATALOGUE") else { return };
    let text = std::fs::read_to_string(path).unwrap();
    // A minimal reader of that one shape: strings in nested lists.
    for item in text.split("{\"name\": ").skip(1) {
        let name = item.split('"').nth(1).unwrap();
        let field = |key: &str| -> Option<String> {
            let at = item.find(&format!("\"{key}\": "))? + key.len() + 4;
            let rest = &item[at..];
            if rest.starts_with("null") {
                return None;
            }
            let mut depth = 0;
            let end = rest
                .char_indices()
                .find(|&(_, c)| {
                    depth += match c {
                        '[' => 1,
                        ']' => -1,
                        _ => 0,
                    };
                    depth == 0
                })
                .unwrap()
                .0;
            Some(rest[..=end].to_owned())
        };
        let strings = |s: &str| -> Vec<String> {
            s.split('"').skip(1).step_by(2).map(str::to_owned).collect()
        };
        let a_text = field("A").unwrap();
        let rows: Vec<Vec<String>> =
            a_text[1..a_text.len() - 1].split("], [").map(strings).collect();
        let b = strings(&field("b").unwrap());
        let bhat = field("bhat").map(|s| strings(&s));
        let read = |v: &[String]| v.iter().map(|x| Exact::parse(x)).collect::<Result<Vec<_>, _>>();
        let (Ok(a), Ok(b)) =
            (rows.iter().map(|r| read(r)).collect::<Result<Vec<_>, _>>(), read(&b))
        else {
            println!("{name}: entries not read");
            continue;
        };
        let t = Tableau::new("m", a, b, None).unwrap();
        let bhat: Option<Vec<Exact>> = bhat.map(|v| read(&v).unwrap());
        let opts = Options { tolerance: Some(q(1, 1_000_000_000_000)), ..Options::default() };
        let start = std::time::Instant::now();
        let r = order::runge_kutta(&t, bhat.as_deref(), &opts).unwrap();
        let ssp = match &r.ssp_coefficient {
            Some(Ssp::Radius(x)) => x.to_decimal(6),
            Some(Ssp::Unbounded) => "inf".to_owned(),
            None => "undecided".to_owned(),
        };
        println!(
            "{name} order={:?} tol={:?} linear={:?} stage={:?} alg={:?} sympl={:?} sym={:?} ssp={ssp} emb={:?} elin={:?} {:.2}ms",
            r.order,
            r.order_within_tolerance.map(|x| x.order),
            r.linear_order,
            r.stage_order,
            r.algebraically_stable,
            r.symplectic,
            r.symmetric,
            r.embedded_order,
            r.embedded_linear_order,
            start.elapsed().as_secs_f64() * 1000.0
        );
    }
}
