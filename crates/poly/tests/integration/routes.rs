//! The two derivations agree on random linear step programs, and the
//! transition matrix agrees with an independent exact interpreter.
//!
//! Each case is a `.zm` source text generated from a small program tree:
//! 1–4 state variables, a declared parameter `K`, a parameter-only temporary
//! `g`, temporaries, Gauss-Seidel reads (a state variable read after it was
//! updated in this step), history reads `y@k` with k ≤ 2 and coefficients
//! built from integers, fractions, decimals, Phi, K and g.
//!
//! The oracle never uses the crate's lowering: it runs the generated tree on
//! exact rationals at a random point (Phi, K), once per basis vector of the
//! augmented state, which gives the numeric transition matrix column by
//! column. The derived P evaluated at that point must equal it, and the
//! derived χ(z) must equal det(z₀I − P) (exact Gaussian elimination) at N + 1
//! integer points z₀, which pins down a degree-N polynomial.

use std::collections::HashMap;

use num_traits::{One, Zero};
use poly::{q, Method, Poly, Sym, Q};
use proptest::prelude::*;

use crate::common::{nonzero_q, small_q};

/// A coefficient: a polynomial expression in Phi, K and g.
#[derive(Clone, Debug)]
enum Coef {
    Int(i64),
    Frac(i64, i64),
    /// A decimal literal and its exact value in hundredths.
    Decimal(i64),
    Phi,
    K,
    /// The parameter-only temporary `g` defined at the top of the program.
    G,
    Add(Box<Coef>, Box<Coef>),
    Sub(Box<Coef>, Box<Coef>),
    Mul(Box<Coef>, Box<Coef>),
    Neg(Box<Coef>),
    Pow(Box<Coef>, u32),
    Div(Box<Coef>, i64),
}

impl Coef {
    fn render(&self) -> String {
        match self {
            Coef::Int(n) => n.to_string(),
            Coef::Frac(n, d) => format!("{n}/{d}"),
            Coef::Decimal(h) => format!("{}.{:02}", h / 100, h % 100),
            Coef::Phi => "Phi".into(),
            Coef::K => "K".into(),
            Coef::G => "g".into(),
            Coef::Add(a, b) => format!("({} + {})", a.render(), b.render()),
            Coef::Sub(a, b) => format!("({} - {})", a.render(), b.render()),
            Coef::Mul(a, b) => format!("{}*{}", a.render(), b.render()),
            Coef::Neg(a) => format!("(-{})", a.render()),
            Coef::Pow(a, e) => format!("({})^{e}", a.render()),
            Coef::Div(a, d) => format!("({})/{d}", a.render()),
        }
    }

    /// This coefficient with `g` replaced by Phi, for `g`'s own definition.
    fn without_g(self) -> Coef {
        let b = |c: Box<Coef>| Box::new(c.without_g());
        match self {
            Coef::G => Coef::Phi,
            Coef::Add(x, y) => Coef::Add(b(x), b(y)),
            Coef::Sub(x, y) => Coef::Sub(b(x), b(y)),
            Coef::Mul(x, y) => Coef::Mul(b(x), b(y)),
            Coef::Neg(x) => Coef::Neg(b(x)),
            Coef::Pow(x, e) => Coef::Pow(b(x), e),
            Coef::Div(x, d) => Coef::Div(b(x), d),
            leaf => leaf,
        }
    }

    fn eval(&self, at: &Point) -> Q {
        match self {
            Coef::Int(n) => q(*n, 1),
            Coef::Frac(n, d) => q(*n, *d),
            Coef::Decimal(h) => q(*h, 100),
            Coef::Phi => at.phi.clone(),
            Coef::K => at.k.clone(),
            Coef::G => at.g.clone(),
            Coef::Add(a, b) => a.eval(at) + b.eval(at),
            Coef::Sub(a, b) => a.eval(at) - b.eval(at),
            Coef::Mul(a, b) => a.eval(at) * b.eval(at),
            Coef::Neg(a) => -a.eval(at),
            Coef::Pow(a, e) => num_traits::pow(a.eval(at), *e as usize),
            Coef::Div(a, d) => a.eval(at) / q(*d, 1),
        }
    }
}

fn coef() -> impl Strategy<Value = Coef> {
    let leaf = prop_oneof![
        (-4i64..=4).prop_map(Coef::Int),
        (-5i64..=5, 2i64..=4).prop_map(|(n, d)| Coef::Frac(n, d)),
        (0i64..=250).prop_map(Coef::Decimal),
        Just(Coef::Phi),
        Just(Coef::Phi),
        Just(Coef::K),
        Just(Coef::G),
    ];
    leaf.prop_recursive(2, 6, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Coef::Add(a.into(), b.into())),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Coef::Sub(a.into(), b.into())),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Coef::Mul(a.into(), b.into())),
            inner.clone().prop_map(|a| Coef::Neg(a.into())),
            (inner.clone(), 0u32..=2).prop_map(|(a, e)| Coef::Pow(a.into(), e)),
            (inner, prop_oneof![-3i64..=-1, 1i64..=3]).prop_map(|(a, d)| Coef::Div(a.into(), d)),
        ]
    })
}

/// What a term reads.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Read {
    /// A state variable's latest value in this step (Gauss-Seidel).
    State(usize),
    /// `x@lag`: the value `lag` steps before the start of this step.
    Hist(usize, u32),
    /// A temporary assigned earlier in this step.
    Temp(usize),
}

/// How a term is written; all forms mean `sign * coef * read`.
#[derive(Clone, Debug)]
enum Term {
    /// `coef*read` or, flipped, `read*coef`.
    Scaled(Coef, Read, bool),
    /// `read` or `-read`.
    Bare(Read, bool),
    /// `read/d`.
    Divided(Read, i64),
    /// `coef*(a - b)`.
    Grouped(Coef, Read, Read),
}

#[derive(Clone, Debug)]
struct Stmt {
    /// `State(i)` or `Temp(j)`.
    target: Read,
    terms: Vec<Term>,
}

/// A generated program: the tree the oracle runs and the text the crate
/// parses.
#[derive(Clone, Debug)]
struct Program {
    n_state: usize,
    g: Coef,
    stmts: Vec<Stmt>,
}

/// Raw choices for one term; [`build`] maps them onto the reads that are
/// legal at that point of the program.
type RawTerm = (u8, u16, u16, Coef, i64);

fn raw_program() -> impl Strategy<Value = (usize, Coef, Vec<(u8, Vec<RawTerm>)>)> {
    let term = (0u8..4, any::<u16>(), any::<u16>(), coef(), prop_oneof![-3i64..=-1, 2i64..=4]);
    let stmt = (any::<u8>(), proptest::collection::vec(term, 1..=3));
    (1usize..=4, coef(), proptest::collection::vec(stmt, 1..=7))
}

/// Turns raw choices into a valid program: reads only name temporaries
/// assigned before, and a target is a state variable, an existing temporary
/// or a new one.
fn build((n_state, g, raw): (usize, Coef, Vec<(u8, Vec<RawTerm>)>)) -> Program {
    let mut n_temps = 0;
    let mut stmts = Vec::new();
    for (target, raw_terms) in raw {
        let readable = |choice: u16| {
            let mut reads: Vec<Read> = (0..n_state).map(Read::State).collect();
            for v in 0..n_state {
                reads.extend((0..=2).map(|lag| Read::Hist(v, lag)));
            }
            reads.extend((0..n_temps).map(Read::Temp));
            reads[choice as usize % reads.len()]
        };
        let terms = raw_terms
            .into_iter()
            .map(|(form, r1, r2, c, d)| match form {
                0 => Term::Scaled(c, readable(r1), r2 % 2 == 0),
                1 => Term::Bare(readable(r1), r2 % 2 == 0),
                2 => Term::Divided(readable(r1), d),
                _ => Term::Grouped(c, readable(r1), readable(r2)),
            })
            .collect();
        let slot = target as usize % (n_state + n_temps + 1);
        let target = if slot < n_state {
            Read::State(slot)
        } else if slot < n_state + n_temps {
            Read::Temp(slot - n_state)
        } else {
            n_temps += 1;
            Read::Temp(n_temps - 1)
        };
        stmts.push(Stmt { target, terms });
    }
    Program { n_state, g: g.without_g(), stmts }
}

fn program() -> impl Strategy<Value = Program> {
    raw_program().prop_map(build)
}

const STATE_NAMES: [&str; 4] = ["v", "y", "x", "w"];

impl Program {
    fn read_text(r: Read) -> String {
        match r {
            Read::State(v) => STATE_NAMES[v].into(),
            Read::Hist(v, lag) => format!("{}@{lag}", STATE_NAMES[v]),
            Read::Temp(t) => format!("t{t}"),
        }
    }

    fn source(&self) -> String {
        let mut s = format!(
            "# generated\nmethod random_program\nstate {}\nparam K\ng = {}   # parameter-only\n",
            STATE_NAMES[..self.n_state].join(" "),
            self.g.render()
        );
        for st in &self.stmts {
            let terms: Vec<String> = st
                .terms
                .iter()
                .map(|t| match t {
                    Term::Scaled(c, r, false) => format!("{}*{}", c.render(), Self::read_text(*r)),
                    Term::Scaled(c, r, true) => format!("{}*{}", Self::read_text(*r), c.render()),
                    Term::Bare(r, false) => Self::read_text(*r),
                    Term::Bare(r, true) => format!("-{}", Self::read_text(*r)),
                    Term::Divided(r, d) => format!("{}/({d})", Self::read_text(*r)),
                    Term::Grouped(c, a, b) => {
                        format!(
                            "{}*({} - {})",
                            c.render(),
                            Self::read_text(*a),
                            Self::read_text(*b)
                        )
                    }
                })
                .collect();
            s += &format!("{} = {}\n", Self::read_text(st.target), terms.join(" + "));
        }
        s
    }

    /// The deepest history read of each state variable.
    fn history(&self) -> Vec<u32> {
        let mut h = vec![0; self.n_state];
        let mut see = |r: &Read| {
            if let Read::Hist(v, lag) = *r {
                h[v] = h[v].max(lag);
            }
        };
        for st in &self.stmts {
            for t in &st.terms {
                match t {
                    Term::Scaled(_, r, _) | Term::Bare(r, _) | Term::Divided(r, _) => see(r),
                    Term::Grouped(_, a, b) => {
                        see(a);
                        see(b);
                    }
                }
            }
        }
        h
    }

    /// The augmented state: each variable at lags 0..=its history.
    fn slots(&self) -> Vec<(usize, u32)> {
        let h = self.history();
        (0..self.n_state).flat_map(|v| (0..=h[v]).map(move |lag| (v, lag))).collect()
    }

    /// One step on exact rationals from the augmented state `start`.
    fn step(&self, start: &[Q], at: &Point) -> Vec<Q> {
        let slots = self.slots();
        let slot = |v: usize, lag: u32| {
            start[slots.iter().position(|&s| s == (v, lag)).expect("lag in the augmented state")]
                .clone()
        };
        let mut state: Vec<Q> = (0..self.n_state).map(|v| slot(v, 0)).collect();
        let mut temps: HashMap<usize, Q> = HashMap::new();
        for st in &self.stmts {
            let read = |r: Read, state: &[Q]| match r {
                Read::State(v) => state[v].clone(),
                Read::Hist(v, lag) => slot(v, lag),
                Read::Temp(t) => temps[&t].clone(),
            };
            let mut value = Q::zero();
            for t in &st.terms {
                value += match t {
                    Term::Scaled(c, r, _) => c.eval(at) * read(*r, &state),
                    Term::Bare(r, neg) => {
                        if *neg {
                            -read(*r, &state)
                        } else {
                            read(*r, &state)
                        }
                    }
                    Term::Divided(r, d) => read(*r, &state) / q(*d, 1),
                    Term::Grouped(c, a, b) => c.eval(at) * (read(*a, &state) - read(*b, &state)),
                };
            }
            match st.target {
                Read::State(v) => state[v] = value,
                Read::Temp(t) => {
                    temps.insert(t, value);
                }
                Read::Hist(..) => unreachable!("targets are never history reads"),
            }
        }
        slots
            .iter()
            .map(|&(v, lag)| if lag == 0 { state[v].clone() } else { slot(v, lag - 1) })
            .collect()
    }

    /// The numeric transition matrix, column k = one step from basis vector k.
    fn transition_matrix(&self, at: &Point) -> Vec<Vec<Q>> {
        let n = self.slots().len();
        let cols: Vec<Vec<Q>> = (0..n)
            .map(|k| {
                let e: Vec<Q> = (0..n).map(|i| if i == k { Q::one() } else { Q::zero() }).collect();
                self.step(&e, at)
            })
            .collect();
        (0..n).map(|i| (0..n).map(|j| cols[j][i].clone()).collect()).collect()
    }
}

/// A point (Phi, K) and the value the program's `g` takes there.
#[derive(Debug)]
struct Point {
    phi: Q,
    k: Q,
    g: Q,
}

/// The determinant by exact Gaussian elimination over Q.
fn det_q(mut a: Vec<Vec<Q>>) -> Q {
    let n = a.len();
    let mut det = Q::one();
    for col in 0..n {
        let Some(pivot) = (col..n).find(|&r| !a[r][col].is_zero()) else {
            return Q::zero();
        };
        if pivot != col {
            a.swap(pivot, col);
            det = -det;
        }
        det *= &a[col][col];
        let (above, below) = a.split_at_mut(col + 1);
        let pivot_row = &above[col];
        for row in below {
            let f = &row[col] / &pivot_row[col];
            if f.is_zero() {
                continue;
            }
            for (x, p) in row.iter_mut().zip(pivot_row).skip(col) {
                *x -= &f * p;
            }
        }
    }
    det
}

#[track_caller]
fn check_program(prog: &Program, phi: Q, k: Q) {
    let src = prog.source();
    let method = Method::parse("random.zm", &src).unwrap_or_else(|e| panic!("{e}\n{src}"));
    assert_eq!(method.history(), prog.history(), "{src}");
    assert_eq!(method.slots(), prog.slots(), "{src}");
    let n = prog.slots().len();
    assert_eq!(method.state_size(), n, "{src}");

    let p = poly::advanced::transition_matrix(&method);
    let a = poly::advanced::charpoly_z_route(&method).unwrap_or_else(|e| panic!("{e}\n{src}"));
    let b = poly::advanced::charpoly_state_route(&p);
    assert_eq!(a, b, "routes disagree on\n{src}");
    // The z route eliminates temporaries before its determinant; on small
    // programs, hold it against Berkowitz on the whole of M.
    let m_full = poly::advanced::z_matrix(&method).to_dense();
    if m_full.rows() <= 6 {
        let det = m_full.det();
        let z = Poly::sym(Sym::z());
        let w_to_z = det
            .coeffs_in(poly::advanced::w())
            .iter()
            .enumerate()
            .fold(Poly::zero(), |acc, (k, c)| acc + c * z.pow((n - k) as u32));
        assert_eq!(w_to_z, a, "z^N det M(1/z) on the whole matrix\n{src}");
    }
    // M with the temporaries eliminated (what `derive` prints) keeps det M.
    let d = poly::derive(&method).unwrap_or_else(|e| panic!("{e}\n{src}"));
    let reduced = d.z_matrix_reduced();
    assert_eq!(reduced.labels.len(), reduced.matrix.rows(), "{src}");
    assert_eq!(reduced.labels, method.state(), "{src}");
    if reduced.matrix.rows() <= 6 {
        assert_eq!(chi_of_det(&reduced.matrix, n), a, "z^N det of the reduced M(1/z)\n{src}");
    }
    // The fast route (a) (sparse M, forward substitution, modular
    // determinant) against the slow one (dense elimination, sparse Berkowitz).
    let slow =
        poly::advanced::charpoly_z_route_dense(&method).unwrap_or_else(|e| panic!("{e}\n{src}"));
    assert_eq!(a, slow, "fast and slow z routes\n{src}");
    let d = poly::derive(&method).unwrap_or_else(|e| panic!("{e}\n{src}"));
    assert_eq!(*d.charpoly(), a);
    assert_eq!(d.charpoly().degree_in(Sym::z()) as usize, n, "degree = order\n{src}");
    assert!(d.coeffs()[0].is_one(), "monic\n{src}");
    assert_eq!(d.coeffs().len(), n + 1);

    // The oracle, at one random point.
    let g = prog.g.eval(&Point { phi: phi.clone(), k: k.clone(), g: Q::zero() });
    let at = Point { phi: phi.clone(), k: k.clone(), g };
    let values: HashMap<Sym, Q> = [(Sym::phi(), phi), (Sym::new("K"), k)].into_iter().collect();
    let oracle = prog.transition_matrix(&at);
    for (i, row) in oracle.iter().enumerate() {
        for (j, want) in row.iter().enumerate() {
            let got = p[(i, j)].eval(&values).expect("P depends on Phi and K only");
            assert_eq!(&got, want, "P[{i}][{j}] at {at:?}\n{src}\nP =\n{p}");
        }
    }
    for z0 in 0..=n as i64 {
        let zi_minus_p: Vec<Vec<Q>> = oracle
            .iter()
            .enumerate()
            .map(|(i, row)| {
                row.iter()
                    .enumerate()
                    .map(|(j, x)| if i == j { q(z0, 1) - x } else { -x.clone() })
                    .collect()
            })
            .collect();
        let mut at_z = values.clone();
        at_z.insert(Sym::z(), q(z0, 1));
        let chi = d.charpoly().eval(&at_z).expect("chi depends on z, Phi and K only");
        assert_eq!(chi, det_q(zi_minus_p), "chi({z0}) at {at:?}\n{src}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn routes_agree_and_match_the_exact_interpreter(
        prog in program(), phi in nonzero_q(), k in small_q()
    ) {
        check_program(&prog, phi, k);
    }
}

/// The oracle itself, on the paper's False Euler (Gauss-Seidel read of v):
/// P = [[1, -Phi], [Phi, 1 - Phi^2]] at Phi = 1/2.
#[test]
fn oracle_reproduces_false_euler_by_hand() {
    let prog = Program {
        n_state: 2,
        g: Coef::Int(0),
        stmts: vec![
            Stmt {
                target: Read::State(0),
                terms: vec![
                    Term::Bare(Read::State(0), false),
                    Term::Scaled(Coef::Neg(Coef::Phi.into()), Read::State(1), false),
                ],
            },
            Stmt {
                target: Read::State(1),
                terms: vec![
                    Term::Bare(Read::State(1), false),
                    Term::Scaled(Coef::Phi, Read::State(0), true),
                ],
            },
        ],
    };
    let half = q(1, 2);
    let at = Point { phi: half.clone(), k: Q::zero(), g: Q::zero() };
    let want = vec![vec![q(1, 1), q(-1, 2)], vec![q(1, 2), q(3, 4)]];
    assert_eq!(prog.transition_matrix(&at), want);
    assert_eq!(det_q(want), q(1, 1));
    check_program(&prog, half, Q::zero());
    let parsed = Method::parse("fe.zm", &prog.source()).expect("parses");
    let d = poly::derive(&parsed).expect("derives");
    assert_eq!(*d.charpoly(), Poly::parse("z^2 - (2 - Phi^2)*z + 1").expect("parses"));
}

/// On every built-in, implicit ones included, M with its temporaries
/// eliminated has one row per kept value (the state, then the unknowns of
/// an implicit system) and the determinant of the whole M: z^N det of it
/// at 1/z is χ. The oracle is Berkowitz on the small reduced matrix,
/// independent of the route that derived χ.
#[test]
fn reduced_z_matrix_keeps_the_determinant() {
    for (name, src) in poly::advanced::builtins::BUILTINS {
        let method = Method::parse(&format!("{name}.zm"), src).expect("built-in parses");
        if !method.constants().is_empty() {
            continue;
        }
        let d = poly::derive(&method).expect("built-in derives");
        let reduced = d.z_matrix_reduced();
        let n_kept =
            method.state().len() + method.unknowns().iter().filter(|u| u.state.is_none()).count();
        assert!(
            reduced.labels.len() <= n_kept.max(method.state().len()),
            "{name}: {:?}",
            reduced.labels
        );
        assert!(reduced.labels.starts_with(method.state()), "{name}: {:?}", reduced.labels);
        let chi = chi_of_det(&reduced.matrix, method.state_size());
        assert_eq!(&chi, d.charpoly(), "{name}: reduced M on {:?}", reduced.labels);
    }
}

/// z^N det M(1/z) of a matrix in w = 1/z, by Berkowitz (`PolyMatrix::det`).
fn chi_of_det(m: &poly::PolyMatrix, n: usize) -> Poly {
    let z = Poly::sym(Sym::z());
    m.det()
        .coeffs_in(poly::advanced::w())
        .iter()
        .enumerate()
        .fold(Poly::zero(), |acc, (k, c)| acc + c * z.pow((n - k) as u32))
}
