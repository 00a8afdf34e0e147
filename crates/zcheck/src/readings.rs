//! The nonlinear reading of a method: the coefficients that define it on
//! any y' = f(y) (a Butcher tableau, with `bhat` for an embedded pair), on
//! partitioned systems q' = f(p), p' = g(q) (a partitioned pair, a
//! splitting), or as a linear multistep method. It is what `zcheck order`
//! reads, and what the classical order of `zcheck region` and `zcheck
//! methods` comes from. A `.zm` program is the method on the oscillator
//! only, and has none.
//!
//! A coefficient file says which by its keys: `[q]` and `[p]` (a pair),
//! `drift` and `kick` (a splitting), `alpha` and `beta` (multistep), else
//! `A` and `b` (a tableau). A built-in has a reading where its program is
//! one of these methods on the oscillator, written in `BUILTIN_READINGS`
//! as the TOML a user would write; its `_matrix` twin shares it. The
//! paper's methods on the separable system y' = f(v), v' = g(y) (position
//! y is q, velocity v is p), each derived from its program:
//!
//! - Standard Euler is explicit Euler; Standard Heun is Heun's RK2.
//! - Damped Euler (D = Φ/2) updates y with the old v, then v from the new y:
//!   v₁ = v − Φ(y + Φv) = v − Φ y₁, the symplectic Euler drift(h) kick(h).
//!   False Euler updates v first: kick(h) drift(h).
//! - Verlet's two-step y₊ = 2y − y₋ + h² g(y) is Störmer–Verlet,
//!   drift(h/2) kick(h) drift(h/2).
//! - Semi-False Heun evaluates g at y₀ and at Y₂ = y₀ + h f(v₀), and f at
//!   v₀ and at V₂ = v₀ + h g(Y₂): the pair `[q]` A = [[0, 0], [1, 0]],
//!   `[p]` A = [[0, 0], [0, 1]], b = b̂ = (1/2, 1/2), stage i evaluating f and
//!   g at one point (Yᵢ, Vᵢ).
//! - False Heun evaluates g at y₀ and at Y₂ = y₀ + h f(V₁), and f at
//!   V₁ = v₀ + h g(y₀) and at V₂ = v₀ + h g(Y₂): the pair with the same
//!   `[q]` and `[p]` A = [[1, 0], [0, 1]].
//!
//! The damped-spring built-ins (a free D), Newmark's methods (defined for
//! y'' = g(y), whose velocity update is not a Runge–Kutta stage of a
//! general f) and the soft spring (one Gauss–Seidel pass) have none.

use std::path::Path;

use poly::advanced::multistep;
use poly::advanced::tableau::{self as exact, Exact};
use poly::Q;

use crate::error::Error;
use crate::multistep::Multistep;
use crate::partitioned::{is_partitioned, is_splitting, Partitioned, Splitting};
use crate::tableau::{decimal_digits_in, Tableau};

/// What kind of coefficients a reading holds.
#[derive(Clone, Debug)]
pub(crate) enum Form {
    /// A Butcher tableau, with the embedded weights of a pair.
    RungeKutta { tableau: exact::Tableau, bhat: Option<Vec<Exact>> },
    /// A partitioned pair: `[q]` integrates q, `[p]` integrates p.
    Partitioned { q: exact::Tableau, p: exact::Tableau },
    /// drift(a₁h) kick(b₁h) … drift(a_s h) kick(b_s h).
    Splitting { drift: Vec<Exact>, kick: Vec<Exact> },
    /// α and β, lowest j first.
    Multistep(multistep::Multistep),
}

/// A method's nonlinear reading.
#[derive(Clone, Debug)]
pub(crate) struct Reading {
    /// The method's name.
    pub(crate) name: String,
    pub(crate) form: Form,
    /// The most significant digits of a decimal entry (0: none), for the
    /// default tolerance of `zcheck order`.
    pub(crate) decimal_digits: usize,
    /// A built-in's: what the reading is.
    pub(crate) about: Option<&'static str>,
    /// The parameters a tableau file declared (`params`), bound as read.
    pub(crate) params: Vec<String>,
}

/// `(built-in, what its reading is, the reading as TOML)`.
pub(crate) const BUILTIN_READINGS: &[(&str, &str, &str)] = &[
    ("standard_euler", "explicit Euler", "A = [[0]]\nb = [1]"),
    ("damped_euler", "symplectic Euler, drift(h) kick(h)", "drift = [1]\nkick = [1]"),
    ("false_euler", "symplectic Euler, kick(h) drift(h)", "drift = [0, 1]\nkick = [1, 0]"),
    (
        "verlet",
        "Störmer–Verlet, drift(h/2) kick(h) drift(h/2)",
        "drift = [\"1/2\", \"1/2\"]\nkick = [1, 0]",
    ),
    ("standard_heun", "Heun's RK2", "A = [[0, 0], [1, 0]]\nb = [\"1/2\", \"1/2\"]"),
    (
        "false_heun",
        "a partitioned pair (implicit in [p] on general systems)",
        "[q]\nA = [[0, 0], [1, 0]]\nb = [\"1/2\", \"1/2\"]\n\
         [p]\nA = [[1, 0], [0, 1]]\nb = [\"1/2\", \"1/2\"]",
    ),
    (
        "semi_false_heun",
        "a partitioned pair (implicit in [p] on general systems)",
        "[q]\nA = [[0, 0], [1, 0]]\nb = [\"1/2\", \"1/2\"]\n\
         [p]\nA = [[0, 0], [0, 1]]\nb = [\"1/2\", \"1/2\"]",
    ),
    (
        "trapezoidal",
        "the trapezoidal rule (Lobatto IIIA, 2 stages)",
        "A = [[0, 0], [\"1/2\", \"1/2\"]]\nb = [\"1/2\", \"1/2\"]",
    ),
    ("implicit_midpoint", "the implicit midpoint rule", "A = [[\"1/2\"]]\nb = [1]"),
    ("backward_euler", "implicit Euler", "A = [[1]]\nb = [1]"),
    ("bdf2", "BDF2", "alpha = [\"1/3\", \"-4/3\", 1]\nbeta = [0, 0, \"2/3\"]"),
    (
        "gauss_legendre_2",
        "Gauss–Legendre, 2 stages",
        include_str!("../tableaux/gauss_legendre_2.toml"),
    ),
    ("radau_iia_2", "Radau IIA, 2 stages", include_str!("../tableaux/radau_iia_2.toml")),
    ("sdirk2", "SDIRK, 2 stages", include_str!("../tableaux/sdirk2.toml")),
    (
        "forest_ruth",
        "Forest–Ruth, θ = 1/(2 − ∛2)",
        "drift = [\"1/(2 - cbrt(2))/2\", \"(1 - 1/(2 - cbrt(2)))/2\", \
         \"(1 - 1/(2 - cbrt(2)))/2\", \"1/(2 - cbrt(2))/2\"]\n\
         kick = [\"1/(2 - cbrt(2))\", \"1 - 2/(2 - cbrt(2))\", \"1/(2 - cbrt(2))\", 0]",
    ),
    ("ab2", "2-step Adams–Bashforth", "alpha = [0, -1, 1]\nbeta = [\"-1/2\", \"3/2\", 0]"),
    (
        "ab3",
        "3-step Adams–Bashforth",
        "alpha = [0, 0, -1, 1]\nbeta = [\"5/12\", \"-4/3\", \"23/12\", 0]",
    ),
    (
        "ab4",
        "4-step Adams–Bashforth",
        "alpha = [0, 0, 0, -1, 1]\nbeta = [\"-3/8\", \"37/24\", \"-59/24\", \"55/24\", 0]",
    ),
    (
        "ab5",
        "5-step Adams–Bashforth",
        "alpha = [0, 0, 0, 0, -1, 1]\n\
         beta = [\"251/720\", \"-637/360\", \"109/30\", \"-1387/360\", \"1901/720\", 0]",
    ),
    (
        "ab6",
        "6-step Adams–Bashforth",
        "alpha = [0, 0, 0, 0, 0, -1, 1]\n\
         beta = [\"-95/288\", \"959/480\", \"-3649/720\", \"4991/720\", \"-2641/480\", \
         \"4277/1440\", 0]",
    ),
    (
        "ab7",
        "7-step Adams–Bashforth",
        "alpha = [0, 0, 0, 0, 0, 0, -1, 1]\n\
         beta = [\"19087/60480\", \"-5603/2520\", \"135713/20160\", \"-10754/945\", \
         \"235183/20160\", \"-18637/2520\", \"198721/60480\", 0]",
    ),
    (
        "ab8",
        "8-step Adams–Bashforth",
        "alpha = [0, 0, 0, 0, 0, 0, 0, -1, 1]\n\
         beta = [\"-5257/17280\", \"32863/13440\", \"-115747/13440\", \"2102243/120960\", \
         \"-296053/13440\", \"242653/13440\", \"-1152169/120960\", \"16083/4480\", 0]",
    ),
    ("leapfrog", "explicit midpoint (2-step Nyström)", "alpha = [-1, 0, 1]\nbeta = [0, 2, 0]"),
    (
        "nystrom3",
        "3-step explicit Nyström",
        "alpha = [0, -1, 0, 1]\nbeta = [\"1/3\", \"-2/3\", \"7/3\", 0]",
    ),
    (
        "nystrom4",
        "4-step explicit Nyström",
        "alpha = [0, 0, -1, 0, 1]\nbeta = [\"-1/3\", \"4/3\", \"-5/3\", \"8/3\", 0]",
    ),
    (
        "nystrom5",
        "5-step explicit Nyström",
        "alpha = [0, 0, 0, -1, 0, 1]\n\
         beta = [\"29/90\", \"-73/45\", \"49/15\", \"-133/45\", \"269/90\", 0]",
    ),
    (
        "nystrom6",
        "6-step explicit Nyström",
        "alpha = [0, 0, 0, 0, -1, 0, 1]\n\
         beta = [\"-14/45\", \"169/90\", \"-71/15\", \"287/45\", \"-203/45\", \"33/10\", 0]",
    ),
    (
        "rk3",
        "Kutta's RK3",
        "A = [[0, 0, 0], [\"1/2\", 0, 0], [-1, 2, 0]]\nb = [\"1/6\", \"2/3\", \"1/6\"]",
    ),
    ("rk4", "the classical RK4", include_str!("../tableaux/rk4.toml")),
    (
        "merson",
        "Merson 4(3), with its estimator",
        "A = [[0, 0, 0, 0, 0], [\"1/3\", 0, 0, 0, 0], [\"1/6\", \"1/6\", 0, 0, 0],\n\
         [\"1/8\", 0, \"3/8\", 0, 0], [\"1/2\", 0, \"-3/2\", 2, 0]]\n\
         b = [\"1/6\", 0, 0, \"2/3\", \"1/6\"]\n\
         bhat = [\"1/10\", 0, \"3/10\", \"2/5\", \"1/5\"]",
    ),
    (
        "ssprk104",
        "Ketcheson's SSPRK(10,4)",
        "A = [[0, 0, 0, 0, 0, 0, 0, 0, 0, 0],\n\
         [\"1/6\", 0, 0, 0, 0, 0, 0, 0, 0, 0],\n\
         [\"1/6\", \"1/6\", 0, 0, 0, 0, 0, 0, 0, 0],\n\
         [\"1/6\", \"1/6\", \"1/6\", 0, 0, 0, 0, 0, 0, 0],\n\
         [\"1/6\", \"1/6\", \"1/6\", \"1/6\", 0, 0, 0, 0, 0, 0],\n\
         [\"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/15\", 0, 0, 0, 0, 0],\n\
         [\"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/6\", 0, 0, 0, 0],\n\
         [\"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/6\", \"1/6\", 0, 0, 0],\n\
         [\"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/6\", \"1/6\", \"1/6\", 0, 0],\n\
         [\"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/15\", \"1/6\", \"1/6\", \"1/6\", \"1/6\", 0]]\n\
         b = [\"1/10\", \"1/10\", \"1/10\", \"1/10\", \"1/10\", \"1/10\", \"1/10\", \"1/10\", \
         \"1/10\", \"1/10\"]",
    ),
];

impl Reading {
    /// The reading of a method argument: a built-in's, or a `.toml`
    /// coefficient file's (its warnings reported as every command reports
    /// them). A `.zm` program has none.
    /// A tableau's parameters (`params`) take their values from `values`.
    pub(crate) fn load(arg: &str, values: &[(String, Q)]) -> Result<Reading, Error> {
        if arg.ends_with(".toml") {
            let (shown, stem, text) = crate::tableau::read_file(Path::new(arg))?;
            let (reading, warnings) = Reading::parse_bound(&shown, &stem, &text, values)?;
            crate::warn::report(warnings)?;
            return Ok(reading);
        }
        if let Some(r) = Reading::builtin(arg) {
            return r;
        }
        if poly::builtin(arg).is_ok() {
            return Err(Error::method(format!(
                "{arg}: this built-in has no nonlinear reading (no tableau, pair, splitting or \
                 multistep form; `zcheck methods` lists the classical order of those that have \
                 one): its program is the method on the oscillator only"
            )));
        }
        if arg.ends_with(".zm") || check::load::is_path(arg) {
            return Err(Error::method(format!(
                "{arg}: a .zm program is the method on the oscillator (or on y' = λy) only, with \
                 no nonlinear reading: expected a .toml file (a Butcher tableau, a partitioned \
                 pair [q]/[p], a splitting drift/kick, or multistep alpha/beta) or a built-in"
            )));
        }
        // An unknown name: the built-ins' error, with the names it knows.
        poly::builtin(arg)?;
        unreachable!("poly::builtin refused {arg}")
    }

    /// The reading of a coefficient file's text, and its warnings
    /// (located); `stem` names the method when the file has no `name`.
    pub(crate) fn parse(
        path: &str,
        stem: &str,
        text: &str,
    ) -> Result<(Reading, Vec<String>), Error> {
        Reading::parse_bound(path, stem, text, &[])
    }

    /// [`Reading::parse`], a tableau's parameters bound to `values`
    /// ([`Tableau::parse_bound`]).
    pub(crate) fn parse_bound(
        path: &str,
        stem: &str,
        text: &str,
        values: &[(String, Q)],
    ) -> Result<(Reading, Vec<String>), Error> {
        if is_partitioned(text) {
            let p = Partitioned::parse(path, stem, text)?;
            let form = Form::Partitioned { q: p.q, p: p.p };
            Ok((Reading::new(p.name, form, p.decimal_digits), p.warnings))
        } else if is_splitting(text) {
            let s = Splitting::parse(path, stem, text)?;
            let form = Form::Splitting { drift: s.drift, kick: s.kick };
            Ok((Reading::new(s.name, form, s.decimal_digits), s.warnings))
        } else if crate::tableau::is_multistep(text) {
            let m = Multistep::parse(path, stem, text)?;
            Ok((Reading::of_multistep(&m), m.warnings().to_vec()))
        } else {
            let t = Tableau::parse_bound(path, stem, text, values)?;
            let mut reading = Reading::of_tableau(&t);
            reading.params = t.bound().iter().map(|(n, _)| n.clone()).collect();
            Ok((reading, t.warnings().to_vec()))
        }
    }

    /// The lengths of every list the reading holds, which all agree (one
    /// entry per stage, per flow or per step): for the fuzz target.
    fn lengths(&self) -> Vec<usize> {
        let table = |t: &exact::Tableau| {
            let (a, b, c) = t.entries();
            let mut n = vec![a.len(), b.len()];
            n.extend(a.iter().map(Vec::len));
            n.extend(c.map(<[Exact]>::len));
            n
        };
        match &self.form {
            Form::RungeKutta { tableau, bhat } => {
                let mut n = table(tableau);
                n.extend(bhat.as_ref().map(Vec::len));
                n
            }
            Form::Partitioned { q, p } => [table(q), table(p)].concat(),
            Form::Splitting { drift, kick } => vec![drift.len(), kick.len()],
            Form::Multistep(m) => {
                let (alpha, beta) = m.coefficients();
                vec![alpha.len(), beta.len()]
            }
        }
    }

    /// A built-in's reading (a `_matrix` twin's is its direct method's);
    /// `None` when it has none.
    pub(crate) fn builtin(name: &str) -> Option<Result<Reading, Error>> {
        let base = poly::advanced::builtins::direct_twin(name).unwrap_or(name);
        let (_, about, text) = BUILTIN_READINGS.iter().find(|(n, _, _)| *n == base)?;
        let path = format!("<builtin>/{base}.toml");
        Some(Reading::parse(&path, base, text).map(|(mut r, _)| {
            r.name = name.to_owned();
            r.about = Some(about);
            r
        }))
    }

    /// A tableau file's reading.
    pub(crate) fn of_tableau(t: &Tableau) -> Reading {
        let form =
            Form::RungeKutta { tableau: t.exact().clone(), bhat: t.bhat().map(<[Exact]>::to_vec) };
        Reading::new(t.exact().name().to_owned(), form, t.decimal_digits())
    }

    /// A partitioned pair's reading.
    pub(crate) fn of_partitioned(p: &crate::partitioned::Partitioned) -> Reading {
        let form = Form::Partitioned { q: p.q.clone(), p: p.p.clone() };
        Reading::new(p.name.clone(), form, p.decimal_digits)
    }

    /// A splitting's reading.
    pub(crate) fn of_splitting(s: &crate::partitioned::Splitting) -> Reading {
        let form = Form::Splitting { drift: s.drift.clone(), kick: s.kick.clone() };
        Reading::new(s.name.clone(), form, s.decimal_digits)
    }

    /// A multistep file's reading.
    pub(crate) fn of_multistep(m: &Multistep) -> Reading {
        Reading::new(
            m.exact().name().to_owned(),
            Form::Multistep(m.exact().clone()),
            m.decimal_digits(),
        )
    }

    /// A tableau's reading (the Python module's `Method.from_tableau`):
    /// the tableau already read from its entries' text, which give the
    /// decimal digits; `bhat`, when given, is read here, one entry per
    /// stage.
    pub(crate) fn of_parsed_tableau(
        tableau: exact::Tableau,
        a: &[Vec<&str>],
        b: &[&str],
        c: Option<&[&str]>,
        bhat: Option<&[&str]>,
    ) -> Result<Reading, Error> {
        let digits = a
            .iter()
            .flatten()
            .chain(b)
            .chain(c.into_iter().flatten())
            .chain(bhat.into_iter().flatten())
            .map(|x| decimal_digits_in(x))
            .max()
            .unwrap_or(0);
        let bhat = bhat
            .map(|xs| {
                xs.iter()
                    .enumerate()
                    .map(|(i, x)| {
                        Exact::parse(x).map_err(|e| {
                            Error::method(format!("bhat[{}] = {x:?}: {}", i + 1, e.message()))
                        })
                    })
                    .collect::<Result<Vec<_>, _>>()
            })
            .transpose()?;
        if let Some(bh) = &bhat {
            if bh.len() != b.len() {
                return Err(Error::method(format!(
                    "bhat has {} entries: expected {}, one per stage",
                    bh.len(),
                    b.len()
                )));
            }
        }
        let name = tableau.name().to_owned();
        Ok(Reading::new(name, Form::RungeKutta { tableau, bhat }, digits))
    }

    /// A multistep method's reading from its coefficients' text (the
    /// Python module's `Method.from_multistep`).
    pub(crate) fn of_coefficients(
        name: &str,
        alpha: &[&str],
        beta: &[&str],
    ) -> Result<Reading, Error> {
        let digits = alpha.iter().chain(beta).map(|x| decimal_digits_in(x)).max().unwrap_or(0);
        let read = |xs: &[&str]| xs.iter().map(|x| Exact::parse(x)).collect::<Result<Vec<_>, _>>();
        let m = multistep::Multistep::new(name, read(alpha)?, read(beta)?)?;
        Ok(Reading::new(name.to_owned(), Form::Multistep(m), digits))
    }

    pub(crate) fn new(name: String, form: Form, decimal_digits: usize) -> Reading {
        Reading { name, form, decimal_digits, about: None, params: Vec::new() }
    }
}

/// A coefficient file's text as `zcheck order` reads it: its kind, the
/// lengths of every list it holds, its warnings.
#[derive(Clone, Debug)]
pub struct Coefficients {
    /// "runge_kutta", "embedded_pair", "partitioned", "splitting" or
    /// "multistep".
    pub kind: &'static str,
    /// Every list's length (rows and each row of `A`, `b`, `c`, `bhat`;
    /// both tables of a pair; `drift` and `kick`; `alpha` and `beta`): all
    /// equal in a file that reads.
    pub lengths: Vec<usize>,
    /// The warnings, each located.
    pub warnings: Vec<String>,
}

/// Reads a coefficient file's text as `zcheck order` does (a tableau with
/// an optional `bhat`, a partitioned pair `[q]`/`[p]`, a splitting
/// `drift`/`kick`, a multistep method `alpha`/`beta`, told apart by the
/// keys), for the fuzz target `order_toml` (`testkit::fuzz`).
pub fn read_coefficients(path: &str, stem: &str, text: &str) -> Result<Coefficients, Error> {
    let (reading, warnings) = Reading::parse(path, stem, text)?;
    let kind = match &reading.form {
        Form::RungeKutta { bhat: None, .. } => "runge_kutta",
        Form::RungeKutta { bhat: Some(_), .. } => "embedded_pair",
        Form::Partitioned { .. } => "partitioned",
        Form::Splitting { .. } => "splitting",
        Form::Multistep(_) => "multistep",
    };
    Ok(Coefficients { kind, lengths: reading.lengths(), warnings })
}
