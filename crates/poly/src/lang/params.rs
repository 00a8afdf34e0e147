//! [`Params`]: the one parameter binding of zcheck, exact.
//!
//! Both the exact side (`poly`) and the numeric side (`check`) bind a
//! method's parameters (`Phi`, `D`, ...) through this type. Values are exact
//! rationals: a decimal typed by a user is the decimal (0.1 is 1/10), never
//! the binary fraction nearest to it. `check` adds an `f64` view on top
//! (`check::numeric::ParamsF64`); `poly` itself never sees a float.

use std::collections::{BTreeMap, HashMap};
use std::fmt;

use crate::{Method, Sym, Q};

/// Exact values of named parameters, kept sorted by name.
///
/// Values for parameters a method does not declare are allowed, so one set
/// can serve several methods; [`Params::for_method`] reads exactly the ones
/// a method declares and reports the first missing one.
///
/// ```
/// use poly::{q, Params};
/// let p = Params::new().bind("Phi", q(1, 2)).bind("D", q(1, 10));
/// assert_eq!(p.value("D"), Some(&q(1, 10)));
/// assert_eq!(p.to_string(), "D=1/10, Phi=1/2");
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Params {
    values: BTreeMap<&'static str, Q>,
}

impl Params {
    /// No parameter bound.
    pub fn new() -> Params {
        Params::default()
    }

    /// This set with `name = value` added or replaced.
    pub fn bind(mut self, name: &str, value: Q) -> Params {
        self.insert(name, value);
        self
    }

    /// Binds `name = value`, replacing any earlier value.
    pub fn insert(&mut self, name: &str, value: Q) {
        self.values.insert(Sym::new(name).name(), value);
    }

    /// The exact value of `name`, if bound.
    pub fn value(&self, name: &str) -> Option<&Q> {
        self.values.get(name)
    }

    /// Whether nothing is bound.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// Every `(name, value)` pair, sorted by name.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, &Q)> {
        self.values.iter().map(|(k, v)| (*k, v))
    }

    /// The values of the symbols `syms`, by symbol; `Err(name)` names the
    /// first symbol without a value.
    pub fn values_of(&self, syms: &[Sym]) -> Result<HashMap<Sym, Q>, &'static str> {
        syms.iter()
            .map(|&s| self.values.get(s.name()).map(|v| (s, v.clone())).ok_or(s.name()))
            .collect()
    }

    /// The values of every parameter `method` declares (Φ among them, when
    /// it uses Φ); `Err(name)` names the first one without a value.
    pub fn for_method(&self, method: &Method) -> Result<HashMap<Sym, Q>, &'static str> {
        self.values_of(method.params())
    }

    /// The names bound here that `method` does not declare: a caller that
    /// took these from a user should refuse them rather than ignore them.
    pub fn undeclared<'a>(&'a self, method: &'a Method) -> impl Iterator<Item = &'static str> + 'a {
        self.values.keys().copied().filter(move |k| !method.params().iter().any(|s| s.name() == *k))
    }
}

impl fmt::Display for Params {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, (k, v)) in self.values.iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            write!(f, "{k}={v}")?;
        }
        Ok(())
    }
}
