//! Linear multistep methods as input: a TOML file with `alpha` and `beta`,
//! the coefficients of y_{n+j} and h·f_{n+j} for j = 0..k, lowest j first
//! (as NodePy's `LinearMultistepMethod(alpha, beta)`), becomes the `.zm`
//! program of the method on the oscillator.
//!
//! ```toml
//! name = "bdf2"                          # optional: the file's stem
//! alpha = ["1/3", "-4/3", 1]
//! beta = [0, 0, "2/3"]
//! ```
//!
//! Entries are exact, as in a tableau ([`crate::tableau::exact_entry`]). The
//! meaning is `poly`'s (`poly::advanced::multistep`); this module reads the
//! file and blames every mistake on its line and column.

use poly::advanced::multistep;
use serde::Deserialize;
use toml::Spanned;

use crate::error::{line_col, Error};
use crate::tableau::{decimal_digits, entry_hint, exact_entry, method_name};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    name: Option<Spanned<String>>,
    alpha: Option<Spanned<Vec<Spanned<toml::Value>>>>,
    beta: Option<Spanned<Vec<Spanned<toml::Value>>>>,
}

/// A linear multistep method read exactly from a file.
#[derive(Clone, Debug)]
pub(crate) struct Multistep {
    source: String,
    method: multistep::Multistep,
    decimal_digits: usize,
    warnings: Vec<String>,
}

impl Multistep {
    /// Parses the text of a multistep file; `stem` names the method when the
    /// file has no `name`.
    pub(crate) fn parse(path: &str, stem: &str, text: &str) -> Result<Multistep, Error> {
        let err = |span: Option<std::ops::Range<usize>>, message: String| {
            let (line, col) = line_col(text, span.map_or(0, |s| s.start));
            Error::file(path, line, col, &message)
        };
        let raw: Raw = toml::from_str(text).map_err(|e| {
            err(e.span(), e.message().trim_end_matches('\n').replace('\n', "; ").to_string())
        })?;
        let (Some(alpha), Some(beta)) = (&raw.alpha, &raw.beta) else {
            let missing = if raw.alpha.is_none() { "alpha" } else { "beta" };
            return Err(err(
                None,
                format!(
                    "no `{missing}`: expected both `alpha = [...]` and `beta = [...]`, the \
                     coefficients of y_(n+j) and h f_(n+j), j = 0..k"
                ),
            ));
        };
        if alpha.get_ref().len() != beta.get_ref().len() {
            return Err(err(
                Some(beta.span()),
                format!(
                    "beta has {} coefficients and alpha {}: expected the same number, one per \
                     y_(n+j), j = 0..k",
                    beta.get_ref().len(),
                    alpha.get_ref().len()
                ),
            ));
        }
        let mut warnings = Vec::new();
        let mut digits = 0;
        let mut read = |what: &str, xs: &Spanned<Vec<Spanned<toml::Value>>>| {
            xs.get_ref()
                .iter()
                .enumerate()
                .map(|(j, v)| {
                    warnings.extend(entry_hint(path, text, v, &format!("{what}[{j}]")));
                    digits = digits.max(decimal_digits(v.get_ref()));
                    exact_entry(path, text, v, &format!("{what}[{j}]"))
                })
                .collect::<Result<Vec<_>, _>>()
        };
        let (a, b) = (read("alpha", alpha)?, read("beta", beta)?);
        let k = a.len().saturating_sub(1);
        if k >= 1 && a[k].is_zero() {
            return Err(err(
                Some(alpha.get_ref()[k].span()),
                format!("alpha[{k}] (the coefficient of y_(n+k)) is 0: expected the new value to appear"),
            ));
        }
        if !b.is_empty() && b.iter().all(|x| x.is_zero()) {
            return Err(err(
                Some(beta.span()),
                "beta is all zero: expected a method that reads f (some beta_j ≠ 0)".to_owned(),
            ));
        }
        let name = method_name(path, text, raw.name.as_ref(), stem)?;
        let method = multistep::Multistep::new(&name, a, b)
            .map_err(|e| err(Some(alpha.span()), e.message().to_owned()))?;
        let exact_err = |e: poly::Error| err(Some(alpha.span()), e.message().to_owned());
        let (line, col) = line_col(text, alpha.span().start);
        let [rho, drho, sigma] = method.at_one().map_err(exact_err)?;
        if !rho.is_zero() {
            warnings.push(format!(
                "{path}:{line}:{col}: ρ(1) = Σα_j = {}, expected 0: the method is not consistent",
                crate::warn::value_near(&rho, &poly::Poly::zero())
            ));
        } else if drho != sigma {
            warnings.push(format!(
                "{path}:{line}:{col}: ρ'(1) = Σjα_j = {} but σ(1) = Σβ_j = {}, expected them equal: the method is not consistent", crate::warn::value_near(&drho, &sigma), crate::warn::value(&sigma)
            ));
        }
        if !method.zero_stable().map_err(exact_err)? {
            warnings.push(format!(
                "{path}:{line}:{col}: ρ(z) = Σα_j z^j has a root outside the unit circle, or a repeated one on it: the method is not zero-stable, so it does not converge"
            ));
        }
        Ok(Multistep { source: path.to_owned(), method, decimal_digits: digits, warnings })
    }

    /// What the file says that it probably does not mean, located.
    pub(crate) fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// The exact coefficients (`poly`'s).
    pub(crate) fn exact(&self) -> &multistep::Multistep {
        &self.method
    }

    /// The most significant digits of a decimal coefficient
    /// ([`crate::tableau::decimal_digits`]).
    pub(crate) fn decimal_digits(&self) -> usize {
        self.decimal_digits
    }

    /// The `.zm` program of the method on the oscillator, or on the damped
    /// oscillator (`param D`) when `damped`.
    pub(crate) fn to_zm(&self, damped: bool) -> String {
        self.method.to_zm(&self.source, damped)
    }

    /// The `.zm` program of the method on y' = λy (in `w`).
    pub(crate) fn to_scalar_zm(&self) -> String {
        self.method.to_scalar_zm(&self.source)
    }
}
