//! Linear multistep methods as input: Σ_j α_j y_{n+j} = h Σ_j β_j f_{n+j},
//! j = 0..k, lowest j first (NodePy's `LinearMultistepMethod(alpha, beta)`),
//! become the `.zm` program of the method applied to the oscillator, so an
//! analyst starts from the coefficients they know.
//!
//! Every coefficient is exact, as in a tableau ([`Exact`]). The program
//! keeps y and v with history k − 1 and ends the step with the equations
//! `y' = …`, `v' = …` (implicit when β_k ≠ 0, solved exactly). It treats y
//! and v alike, so its scalar form on y' = λy is ρ(z) − wσ(z)
//! ([`Derivation::plane`](crate::Derivation::plane)).
//!
//! ```
//! let m = poly::Method::from_multistep("bdf2", &["1/3", "-4/3", "1"], &["0", "0", "2/3"])?;
//! let d = poly::derive(&m)?;
//! let plane = d.plane(&poly::Params::new())?;
//! assert!(plane.a_stable && plane.l_stable);
//! assert_eq!(plane.order, Some(2));
//! # Ok::<(), poly::Error>(())
//! ```

use std::fmt::Write as _;

use super::generated::declarations;
use super::tableau::{entry_error, method_ident, probe, sum_of, Exact};
use crate::error::{Error, ErrorKind, Span};
use crate::lang::method::Method;
use crate::Poly;

/// The most steps read: beyond any published method, and a bound on the
/// size of the generated program.
pub const MAX_STEPS: usize = 64;

/// A linear multistep method read exactly.
#[derive(Clone, Debug)]
pub struct Multistep {
    name: String,
    alpha: Vec<Exact>,
    beta: Vec<Exact>,
    constants: Vec<(String, String)>,
}

impl Multistep {
    /// A method from α_0..α_k and β_0..β_k. Refused: lengths that differ
    /// or are below 2, more than [`MAX_STEPS`] steps, α_k = 0, an all-zero
    /// β, and a name that is not a `.zm` identifier.
    pub fn new(name: &str, alpha: Vec<Exact>, beta: Vec<Exact>) -> Result<Multistep, Error> {
        let shape = |m: String| Error::new(ErrorKind::Syntax, Span::default(), m);
        if alpha.len() != beta.len() {
            return Err(shape(format!(
                "alpha has {} coefficients and beta {}: expected the same number, one per \
                 y_(n+j), j = 0..k",
                alpha.len(),
                beta.len()
            )));
        }
        let k = alpha.len().saturating_sub(1);
        if k == 0 || k > MAX_STEPS {
            return Err(shape(format!(
                "{} coefficients: expected 2 to {} (k = 1 to {MAX_STEPS} steps)",
                alpha.len(),
                MAX_STEPS + 1
            )));
        }
        if alpha[k].zero {
            return Err(shape(format!(
                "alpha[{k}] (the coefficient of y_(n+k)) is 0: expected the new value to appear"
            )));
        }
        if beta.iter().all(|b| b.zero) {
            return Err(shape(
                "beta is all zero: expected a method that reads f (some beta_j ≠ 0)".to_owned(),
            ));
        }
        let id = method_ident(name);
        if id != name {
            return Err(shape(format!(
                "name {name:?}: expected letters, digits and `_` (such as {id:?})"
            )));
        }
        let mut constants: Vec<(String, String)> = Vec::new();
        for e in alpha.iter().chain(&beta) {
            for r in &e.radicals {
                if !constants.contains(r) {
                    constants.push(r.clone());
                }
            }
        }
        Ok(Multistep { name: id, alpha, beta, constants })
    }

    /// The number of steps k.
    pub fn steps(&self) -> usize {
        self.alpha.len() - 1
    }

    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The coefficients as read: α_0..α_k and β_0..β_k.
    pub fn coefficients(&self) -> (&[Exact], &[Exact]) {
        (&self.alpha, &self.beta)
    }

    /// Whether β_k = 0 (an explicit method).
    pub fn is_explicit(&self) -> bool {
        self.beta[self.steps()].zero
    }

    /// Whether ρ(1) = Σα_j = 0 and ρ'(1) = Σ jα_j = σ(1) = Σβ_j
    /// (consistency), decided exactly.
    pub fn consistency(&self) -> Result<(bool, bool), Error> {
        let sum = |terms: Vec<String>| format!("0 + {}", terms.join(" + "));
        let rho1 = sum(self.alpha.iter().map(|a| format!("({})", a.expr)).collect());
        let drho_minus_sigma = sum(self
            .alpha
            .iter()
            .zip(&self.beta)
            .enumerate()
            .map(|(j, (a, b))| format!("{j}*({}) - ({})", a.expr, b.expr))
            .collect());
        Ok((
            probe(&rho1, &self.constants).map_err(entry_error)?,
            probe(&drho_minus_sigma, &self.constants).map_err(entry_error)?,
        ))
    }

    /// ρ(1) = Σα_j, ρ'(1) = Σ jα_j and σ(1) = Σβ_j, exactly: a consistent
    /// method has ρ(1) = 0 and ρ'(1) = σ(1).
    pub fn at_one(&self) -> Result<[Poly; 3], Error> {
        let c = &self.constants;
        let scaled: Vec<Exact> = self
            .alpha
            .iter()
            .enumerate()
            .map(|(j, a)| Exact {
                expr: format!("{j}*({})", a.expr),
                number: a.number.as_ref().map(|q| q * crate::Q::from_integer(j.into())),
                value: a.value.as_ref().map(|p| p.scale(&crate::Q::from_integer(j.into()))),
                ..a.clone()
            })
            .collect();
        Ok([sum_of(self.alpha.iter(), c)?, sum_of(scaled.iter(), c)?, sum_of(self.beta.iter(), c)?])
    }

    /// The method on the oscillator, or on the damped oscillator (`param
    /// D`) when `damped`.
    pub fn method(&self, damped: bool) -> Result<Method, Error> {
        Method::parse(
            &format!("<multistep>/{}.zm", self.name),
            &self.to_zm("the coefficients", damped),
        )
    }

    /// The method on y' = λy (a program in `w`), for the w-plane.
    pub fn scalar_method(&self) -> Result<Method, Error> {
        Method::parse(
            &format!("<multistep>/{}.zm", self.name),
            &self.to_scalar_zm("the coefficients"),
        )
    }

    /// The `.zm` program of the method on y' = λy: Σ α_j y_{n+j} =
    /// w Σ β_j y_{n+j}, solved for y_{n+k}.
    pub fn to_scalar_zm(&self, source: &str) -> String {
        let k = self.steps();
        let at = |j: usize| -> String {
            if j == k {
                "y'".to_owned()
            } else if j + 1 == k {
                "y".to_owned()
            } else {
                format!("y@{}", k - 1 - j)
            }
        };
        let combo = |coefs: &[Exact], upto: usize| -> Option<String> {
            let terms: Vec<String> = coefs[..upto]
                .iter()
                .enumerate()
                .filter(|(_, e)| !e.zero)
                .map(|(j, e)| format!("({})*{}", e.expr.trim(), at(j)))
                .collect();
            (!terms.is_empty()).then(|| terms.join(" + "))
        };
        let mut out = format!(
            "# Generated by zcheck from {source}: a {k}-step linear multistep method on y' = lambda y, w = h lambda.\n"
        );
        declarations(&mut out, &self.name, "y", false, &self.constants);
        let history = combo(&self.alpha, k).map(|c| format!("-({c})"));
        let slope = combo(&self.beta, k + 1).map(|c| format!("w*({c})"));
        let rhs: Vec<String> = history.into_iter().chain(slope).collect();
        out += &format!("y' = ({})/({})\n", rhs.join(" + "), self.alpha[k].expr.trim());
        out
    }

    /// The `.zm` program of the method on the oscillator (damped: v' =
    /// −ω(2Dv + y)); `source` names where the coefficients came from, in the
    /// program's first comment.
    pub fn to_zm(&self, source: &str, damped: bool) -> String {
        let k = self.steps();
        let mut out = String::new();
        let w = |out: &mut String, line: String| writeln!(out, "{line}").expect("string");
        w(
            &mut out,
            format!(
                "# Generated by zcheck from {source}: a {k}-step linear multistep method, {}.",
                if self.is_explicit() { "explicit" } else { "implicit" }
            ),
        );
        w(
            &mut out,
            "# sum_j alpha_j y_(n+j) = h sum_j beta_j f_(n+j) on v' = -w0 y, y' = w0 v;".to_owned(),
        );
        w(&mut out, "# x@m is x_(n+k-1-m), x' is x_(n+k).".to_owned());
        declarations(&mut out, &self.name, "y v", damped, &self.constants);
        // x_(n+j) for j < k, and the new value for j = k.
        let at = |x: &str, j: usize| -> String {
            if j == k {
                format!("{x}'")
            } else if j + 1 == k {
                x.to_owned()
            } else {
                format!("{x}@{}", k - 1 - j)
            }
        };
        // Σ_j c_j f(j) over the nonzero c_j, j < upto.
        let combo = |coefs: &[Exact], f: &dyn Fn(usize) -> String, upto: usize| -> Option<String> {
            let terms: Vec<String> = coefs[..upto]
                .iter()
                .enumerate()
                .filter(|(_, e)| !e.zero)
                .map(|(j, e)| format!("({})*{}", e.expr.trim(), f(j)))
                .collect();
            (!terms.is_empty()).then(|| terms.join(" + "))
        };
        let ak = self.alpha[k].expr.trim().to_owned();
        let v_slope = |j: usize| {
            if damped {
                format!("(2*D*{} + {})", at("v", j), at("y", j))
            } else {
                at("y", j)
            }
        };
        for x in ["y", "v"] {
            let history = combo(&self.alpha, &|j| at(x, j), k).map(|c| format!("-({c})"));
            let slope = if x == "y" {
                combo(&self.beta, &|j| at("v", j), k + 1).map(|c| format!("Phi*({c})"))
            } else {
                combo(&self.beta, &v_slope, k + 1).map(|c| format!("-Phi*({c})"))
            };
            let rhs: Vec<String> = history.into_iter().chain(slope).collect();
            w(&mut out, format!("{x}' = ({})/({ak})", rhs.join(" + ")));
        }
        out
    }
}

impl Method {
    /// The linear multistep method Σ α_j y_{n+j} = h Σ β_j f_{n+j} (lowest j
    /// first) on the oscillator, from its coefficients as text; an error
    /// names the entry (`alpha[0]`, `beta[2]`, counted from 0 as j is).
    pub fn from_multistep(name: &str, alpha: &[&str], beta: &[&str]) -> Result<Method, Error> {
        let read = |what: &str, xs: &[&str]| {
            xs.iter()
                .enumerate()
                .map(|(j, t)| {
                    Exact::parse(t).map_err(|e| {
                        Error::new(
                            e.kind(),
                            Span::default(),
                            format!("{what}[{j}]: {}", e.message()),
                        )
                    })
                })
                .collect::<Result<Vec<_>, _>>()
        };
        Multistep::new(name, read("alpha", alpha)?, read("beta", beta)?)?.method(false)
    }
}
