//! Partitioned Runge–Kutta pairs and splittings: orders against the Taylor
//! expansion of the step itself (a pair on a general partitioned system, a
//! splitting's drifts and kicks on a separable one, h a symbol), and the
//! literature: Störmer–Verlet (as the Lobatto IIIA–IIIB pair and as a
//! splitting), symplectic Euler, Strang splitting, Yoshida/Forest–Ruth.

use super::{agree, e, h, tableau, trunc, System};
use poly::advanced::order::{self, Options, Order, Value};
use poly::advanced::tableau::{Exact, Tableau};
use poly::{q, Poly, Sym, Q};

const N: u32 = 5;

fn pair(q: &Tableau, p: &Tableau) -> order::OrderReport {
    order::partitioned(q, p, &Options::default()).unwrap()
}

fn exacts(xs: &[&str]) -> Vec<Exact> {
    xs.iter().map(|x| e(x)).collect()
}

fn split(drift: &[&str], kick: &[&str]) -> order::OrderReport {
    order::splitting(&exacts(drift), &exacts(kick), &Options::default()).unwrap()
}

fn verlet_pair() -> (Tableau, Tableau) {
    (
        tableau(&[&["0", "0"], &["1/2", "1/2"]], &["1/2", "1/2"]),
        tableau(&[&["1/2", "0"], &["1/2", "0"]], &["1/2", "1/2"]),
    )
}

fn lobatto3_pair() -> (Tableau, Tableau) {
    (
        tableau(
            &[&["0", "0", "0"], &["5/24", "1/3", "-1/24"], &["1/6", "2/3", "1/6"]],
            &["1/6", "2/3", "1/6"],
        ),
        tableau(
            &[&["1/6", "-1/6", "0"], &["1/6", "1/3", "0"], &["1/6", "5/6", "0"]],
            &["1/6", "2/3", "1/6"],
        ),
    )
}

fn euler_pairs() -> Vec<(&'static str, Tableau, Tableau)> {
    vec![
        // q implicit in p, p explicit: symplectic Euler.
        ("symplectic euler", tableau(&[&["1"]], &["1"]), tableau(&[&["0"]], &["1"])),
        ("explicit euler", tableau(&[&["0"]], &["1"]), tableau(&[&["0"]], &["1"])),
    ]
}

/// Forest–Ruth (Yoshida's triple jump of Verlet), θ = 1/(2 − ∛2).
const THETA: &str = "1/(2 - cbrt(2))";

fn forest_ruth() -> (Vec<String>, Vec<String>) {
    let t = THETA;
    (
        vec![
            format!("({t})/2"),
            format!("(1 - {t})/2"),
            format!("(1 - {t})/2"),
            format!("({t})/2"),
        ],
        vec![t.to_owned(), format!("1 - 2*({t})"), t.to_owned(), "0".to_owned()],
    )
}

fn strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

#[test]
fn pairs_from_the_literature() {
    let (q, p) = verlet_pair();
    let r = pair(&q, &p);
    assert_eq!(r.kind, order::Kind::Partitioned);
    assert_eq!((r.order, r.symplectic, r.symmetric), (Order::Exact(2), Some(true), Some(true)));
    assert_eq!(r.linear_order, Order::Exact(2));
    let (q, p) = lobatto3_pair();
    let r = pair(&q, &p);
    assert_eq!((r.order, r.symplectic, r.symmetric), (Order::Exact(4), Some(true), Some(true)));
    let r = pair(&euler_pairs()[0].1, &euler_pairs()[0].2);
    assert_eq!((r.order, r.symplectic, r.symmetric), (Order::Exact(1), Some(true), Some(false)));
    let r = pair(&euler_pairs()[1].1, &euler_pairs()[1].2);
    assert_eq!((r.order, r.symplectic), (Order::Exact(1), Some(false)));
    // Gauss 2 on both: the pair is Gauss itself.
    let g = super::gauss(2);
    let r = pair(&g, &g);
    assert_eq!((r.order, r.symplectic, r.symmetric), (Order::Exact(4), Some(true), Some(true)));
    let err = order::partitioned(&q, &g, &Options::default()).unwrap_err();
    assert!(err.message().contains("[p] has 2 stages and [q] 3"), "{err}");
}

#[test]
fn splittings_from_the_literature() {
    let r = split(&["1/2", "1/2"], &["1", "0"]);
    assert_eq!(r.kind, order::Kind::Splitting);
    assert_eq!((r.order, r.symplectic, r.symmetric), (Order::Exact(2), Some(true), Some(true)));
    assert_eq!(r.linear_order, Order::Exact(2));
    let r = split(&["1"], &["1"]);
    assert_eq!((r.order, r.symmetric), (Order::Exact(1), Some(false)));
    // Zero flows dropped, neighbours merged: D(1/2) K(1/2) K(1/2) D(1/2).
    let r = split(&["1/2", "0", "1/2"], &["1/2", "1/2", "0"]);
    assert_eq!((r.order, r.symmetric), (Order::Exact(2), Some(true)));
    let (d, k) = forest_ruth();
    let r = split(&strs(&d), &strs(&k));
    assert_eq!((r.order, r.symplectic, r.symmetric), (Order::Exact(4), Some(true), Some(true)));
    // Kick first (the position form): also order 4 and symmetric.
    let t = THETA;
    let r = split(
        &["0", t, &format!("1 - 2*({t})"), t],
        &[
            &format!("({t})/2"),
            &format!("(1 - {t})/2"),
            &format!("(1 - {t})/2"),
            &format!("({t})/2"),
        ],
    );
    assert_eq!((r.order, r.symmetric), (Order::Exact(4), Some(true)));
    let err = order::splitting(&exacts(&["1"]), &exacts(&["1", "0"]), &Options::default());
    assert!(err.unwrap_err().message().contains("drift has 1 coefficients and kick 2"));
}

// ---------------------------------------------------------------------
// Taylor oracles.

fn read(t: &Tableau) -> (Vec<Vec<Poly>>, Vec<Poly>) {
    super::values(t)
}

/// One step of the pair on q' = f(q, p), p' = g(q, p) (scalar q, p), to h^n.
fn prk_step(sys: &System, q_t: &Tableau, p_t: &Tableau, y0: &[Q], n: u32) -> Vec<Poly> {
    let ((aq, bq), (ap, bp)) = (read(q_t), read(p_t));
    let s = bq.len();
    let start: Vec<Poly> = y0.iter().map(|x| Poly::constant(x.clone())).collect();
    let hp = Poly::sym(h());
    let mut stages = vec![start.clone(); s];
    let combine = |f: &[Vec<Poly>], coef: &dyn Fn(usize) -> (Poly, Poly)| -> Vec<Poly> {
        let mut out = start.clone();
        for (j, fj) in f.iter().enumerate() {
            let (cq, cp) = coef(j);
            out[0] += &(&(&cq * &hp) * &fj[0]);
            out[1] += &(&(&cp * &hp) * &fj[1]);
        }
        out.iter().map(|x| trunc(x, n)).collect()
    };
    for _ in 0..=n {
        let f: Vec<Vec<Poly>> = stages.iter().map(|y| sys.at(y, n)).collect();
        stages = (0..s).map(|i| combine(&f, &|j| (aq[i][j].clone(), ap[i][j].clone()))).collect();
    }
    let f: Vec<Vec<Poly>> = stages.iter().map(|y| sys.at(y, n)).collect();
    combine(&f, &|j| (bq[j].clone(), bp[j].clone()))
}

/// The drifts and kicks applied in turn on a separable system, to h^n.
fn split_step(f: &Poly, g: &Poly, drift: &[&str], kick: &[&str], y0: &[Q], n: u32) -> Vec<Poly> {
    let (qs, ps) = (Sym::new("q"), Sym::new("p"));
    let mut all = exacts(drift);
    all.extend(exacts(kick));
    let v: Vec<Poly> = Value::read(&all).unwrap().iter().map(Value::to_poly).collect();
    let (d, k) = v.split_at(drift.len());
    let hp = Poly::sym(h());
    let (mut q, mut p) = (Poly::constant(y0[0].clone()), Poly::constant(y0[1].clone()));
    for (a, b) in d.iter().zip(k) {
        q = trunc(&(&q + &(&(a * &hp) * &trunc(&f.subs(ps, &p), n))), n);
        p = trunc(&(&p + &(&(b * &hp) * &trunc(&g.subs(qs, &q), n))), n);
    }
    vec![q, p]
}

fn systems() -> Vec<(System, Vec<Q>)> {
    let (qs, ps) = (Sym::new("q"), Sym::new("p"));
    let p = |s: &str| Poly::parse(s).unwrap();
    vec![
        (
            System { vars: vec![qs, ps], f: vec![p("p + q*p + 1/3"), p("q^2 - p^2/2 + 2")] },
            vec![q(1, 2), q(-1, 3)],
        ),
        (
            System { vars: vec![qs, ps], f: vec![p("p^2 - q + 1"), p("q*p^2 + q^3 - 1/2")] },
            vec![q(2, 3), q(1, 4)],
        ),
    ]
}

#[test]
fn pairs_against_taylor_expansion() {
    let mut cases = vec![
        ("verlet", verlet_pair().0, verlet_pair().1),
        ("lobatto3", lobatto3_pair().0, lobatto3_pair().1),
    ];
    cases.extend(euler_pairs());
    cases.push(("gauss1/euler", super::gauss(1), tableau(&[&["0"]], &["1"])));
    cases.push(("radau/gauss", super::radau_iia(2), super::gauss(2)));
    for (name, q_t, p_t) in cases {
        let r = pair(&q_t, &p_t);
        let mut taylor = N as usize;
        for (sys, y0) in systems() {
            let step = prk_step(&sys, &q_t, &p_t, &y0, N);
            taylor = taylor.min(agree(&step, &sys.flow(&y0, N), N));
        }
        assert_eq!(r.order.value().min(N as usize), taylor, "{name}");
    }
}

#[test]
fn splittings_against_taylor_expansion() {
    let (d, k) = forest_ruth();
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (vec!["1/2", "1/2"], vec!["1", "0"]),
        (vec!["1"], vec!["1"]),
        (vec!["1/3", "2/3"], vec!["3/4", "1/4"]),
        (vec!["1/2", "0", "1/2"], vec!["1/2", "1/2", "0"]),
        (strs(&d), strs(&k)),
    ];
    let (qs, ps) = (Sym::new("q"), Sym::new("p"));
    let p = |s: &str| Poly::parse(s).unwrap();
    let separable =
        [(p("p + p^2/2 + 1/3"), p("-q + q^3/3 - 1/5")), (p("p^3 - 2*p + 1"), p("q^2 + 1/2*q"))];
    for (drift, kick) in cases {
        let r = order::splitting(&exacts(&drift), &exacts(&kick), &Options::default()).unwrap();
        let mut taylor = N as usize;
        for (f, g) in &separable {
            let y0 = [q(1, 3), q(-1, 2)];
            let sys = System { vars: vec![qs, ps], f: vec![f.clone(), g.clone()] };
            let step = split_step(f, g, &drift, &kick, &y0, N);
            taylor = taylor.min(agree(&step, &sys.flow(&y0, N), N));
        }
        assert_eq!(r.order.value().min(N as usize), taylor, "{drift:?} {kick:?}");
    }
}
