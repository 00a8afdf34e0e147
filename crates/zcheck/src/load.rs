//! Resolving a method argument, once.
//!
//! Every command that takes a method reads its argument here, into one
//! [`LoadedMethod`]: the parsed method, the name shown for it, the kernels a
//! built-in has, and its derivation, made the first time a command asks for
//! it and then kept, so that a command derives each method once.
//!
//! An argument is a built-in's name, a `.zm` file (`check::load` tells the
//! two apart, and reads the file), or a `.toml` file of coefficients: a
//! Butcher tableau ([`crate::tableau`]) or a linear multistep method
//! (`multistep`, told apart by its `alpha` and `beta`), turned into
//! its `.zm` program.
//!
//! The whole-scene advisor asks for the method on the damped spring
//! (`LoadedMethod::load_damped`): a built-in's damped twin
//! (`false_euler` → `false_euler_damped`, `standard_euler` →
//! `damped_euler_d`), shown by its base name and with its system kernel;
//! a tableau's program with `param D`; a `.zm` file as it is.

use std::collections::HashMap;
use std::path::Path;
use std::sync::{Mutex, OnceLock};

use poly::{Derivation, Method, Q};

use crate::error::Error;
use crate::multistep::Multistep;
use crate::readings::Reading;
use crate::scene::vector::Kernel;
use crate::tableau::Tableau;
use crate::values::ParamArg;

/// A method argument, resolved: the method and everything the commands
/// ask of it.
#[derive(Clone, Debug)]
pub struct LoadedMethod {
    method: Method,
    display: String,
    hand_kernel: Option<&'static str>,
    system_kernel: Option<Kernel>,
    derivation: OnceLock<Result<Derivation, poly::Error>>,
    /// The program on y' = λy of a tableau or multistep file: the w-plane
    /// derives it rather than the oscillator's (one state, not two).
    scalar: Option<Method>,
    scalar_derivation: OnceLock<Result<Derivation, poly::Error>>,
    /// The nonlinear reading (a tableau, pair, splitting or multistep
    /// method), where the method has one: `zcheck order`'s input.
    reading: Option<Reading>,
    /// The parameters a tableau file declares, bound as it was read: they
    /// are not the program's ([`unclaimed`]).
    tableau_params: Vec<String>,
}

/// The oscillator a tableau's program is written for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Oscillator {
    /// v' = −ω y, y' = ω v.
    Undamped,
    /// v' = −ω (2 D v + y), y' = ω v (`param D`).
    Damped,
}

impl LoadedMethod {
    /// The method `arg` names, shown as `arg`: a built-in, a `.zm` file, or
    /// a Butcher tableau's program on the undamped oscillator.
    pub(crate) fn load(arg: &str) -> Result<LoadedMethod, Error> {
        LoadedMethod::load_with(arg, &[])
    }

    /// [`LoadedMethod::load`], the parameters a tableau file declares
    /// (`params`) bound to their values in `values` (the command's
    /// `--param NAME=VALUE`; see `Tableau::parse_bound`).
    pub(crate) fn load_with(arg: &str, values: &[(String, Q)]) -> Result<LoadedMethod, Error> {
        let (method, scalar, reading, taken) = resolve(arg, Oscillator::Undamped, values)?;
        let mut loaded = LoadedMethod::new(method, arg.to_owned(), None, None);
        loaded.scalar = scalar;
        loaded.reading = reading;
        loaded.tableau_params = taken;
        Ok(loaded)
    }

    /// The method `arg` names, for the w-plane only: a tableau or multistep
    /// file as its program on y' = λy alone (its oscillator program is not
    /// generated), anything else as `LoadedMethod::load` reads it.
    pub fn load_for_plane(arg: &str) -> Result<LoadedMethod, Error> {
        LoadedMethod::load_for_plane_with(arg, &[])
    }

    /// [`LoadedMethod::load_for_plane`] with a tableau's parameters bound
    /// to `values`, as [`LoadedMethod::load_with`] binds them.
    pub(crate) fn load_for_plane_with(
        arg: &str,
        values: &[(String, Q)],
    ) -> Result<LoadedMethod, Error> {
        if !arg.ends_with(".toml") {
            return LoadedMethod::load_with(arg, values);
        }
        let (shown, stem, text) = crate::tableau::read_file(Path::new(arg))?;
        let mut taken = Vec::new();
        let (method, what, reading) = if crate::tableau::is_multistep(&text) {
            let m = Multistep::parse(&shown, &stem, &text)?;
            crate::warn::report(m.warnings().to_vec())?;
            (
                Method::parse(arg, &m.to_scalar_zm()),
                "multistep coefficients",
                Reading::of_multistep(&m),
            )
        } else {
            let t = Tableau::parse_bound(&shown, &stem, &text, values)?;
            crate::warn::report(t.warnings().to_vec())?;
            taken = t.bound().iter().map(|(n, _)| n.clone()).collect();
            (t.scalar_program(arg), "tableau", Reading::of_tableau(&t))
        };
        let method = method.map_err(|e| {
            Error::method(format!(
                "{arg}: the program generated from the {what} does not parse: {}",
                e.message()
            ))
        })?;
        let mut loaded = LoadedMethod::new(method, arg.to_owned(), None, None);
        loaded.reading = Some(reading);
        loaded.tableau_params = taken;
        Ok(loaded)
    }

    /// The method `arg` names, on the damped spring (`param D`), for the
    /// whole-scene advisor: a built-in's damped twin, shown by its base
    /// name and with its system kernel; a tableau's program on the damped
    /// oscillator; anything else as [`LoadedMethod::load`] reads it.
    /// A tableau's parameters are bound to `values`, as
    /// [`LoadedMethod::load_with`] binds them.
    pub(crate) fn load_damped(arg: &str, values: &[(String, Q)]) -> Result<LoadedMethod, Error> {
        match damped_twin(arg) {
            Some(name) => LoadedMethod::builtin(name),
            None => {
                let (method, _, _, taken) = resolve(arg, Oscillator::Damped, values)?;
                let mut loaded = LoadedMethod::new(method, arg.to_owned(), None, None);
                loaded.tableau_params = taken;
                Ok(loaded)
            }
        }
    }

    /// The built-in `name` as a candidate of a comparison, shown by its
    /// base name (`false_euler_damped` as `false_euler`, `damped_euler_d`
    /// as `standard_euler`), with its hand-written kernel and, for one of
    /// the damped direct methods, its system kernel.
    pub fn builtin(name: &str) -> Result<LoadedMethod, Error> {
        let method = poly::builtin(name)?;
        let hand =
            poly::advanced::builtins::all_builtin_names().find(|n| *n == name).map(|n| match n {
                "damped_euler_d" => "standard_euler_damped",
                n => n,
            });
        let system = if poly::advanced::builtins::DAMPED_METHODS.contains(&name) {
            Kernel::for_method(name)
        } else {
            None
        };
        let mut loaded = LoadedMethod::new(method, base_name(name).to_owned(), hand, system);
        loaded.reading = Reading::builtin(name).transpose()?;
        Ok(loaded)
    }

    /// A method already made (from `.zm` text, a tableau, multistep
    /// coefficients), shown by its name.
    pub(crate) fn of(method: Method) -> LoadedMethod {
        let display = method.name().to_owned();
        LoadedMethod::new(method, display, None, None)
    }

    /// A method made from its nonlinear reading's coefficients, with the
    /// reading kept (`zcheck order` answers it).
    pub(crate) fn with_reading(method: Method, reading: Reading) -> LoadedMethod {
        let mut loaded = LoadedMethod::of(method);
        loaded.reading = Some(reading);
        loaded
    }

    /// The seven direct methods on the damped spring, the whole-scene
    /// advisor's default candidates.
    pub(crate) fn damped_builtins() -> Result<Vec<LoadedMethod>, Error> {
        poly::advanced::builtins::DAMPED_METHODS.iter().map(|n| LoadedMethod::builtin(n)).collect()
    }

    fn new(
        method: Method,
        display: String,
        hand_kernel: Option<&'static str>,
        system_kernel: Option<Kernel>,
    ) -> LoadedMethod {
        LoadedMethod {
            method,
            display,
            hand_kernel,
            system_kernel,
            derivation: OnceLock::new(),
            scalar: None,
            scalar_derivation: OnceLock::new(),
            reading: None,
            tableau_params: Vec::new(),
        }
    }

    /// The method.
    pub fn method(&self) -> &Method {
        &self.method
    }

    /// The name shown for it: the argument as typed, or a built-in's base
    /// name.
    pub(crate) fn display(&self) -> &str {
        &self.display
    }

    /// The name of the hand-written scalar kernel of a built-in candidate
    /// ([`crate::tradeoff::kernels`]; `damped_euler_d` runs Standard
    /// Euler's damped kernel), the baseline its compiled step is timed
    /// against. A user's method has none; a name without a kernel times
    /// nothing.
    pub(crate) fn hand_kernel(&self) -> Option<&'static str> {
        self.hand_kernel
    }

    /// The kernel that steps a whole scene (all bodies at once), for the
    /// damped direct methods loaded as built-ins.
    pub(crate) fn system_kernel(&self) -> Option<Kernel> {
        self.system_kernel
    }

    /// The parameters a tableau file declared, bound as it was read.
    pub(crate) fn tableau_params(&self) -> &[String] {
        &self.tableau_params
    }

    /// The nonlinear reading, where the method has one (a coefficient file,
    /// a built-in with a tableau, pair, splitting or multistep form).
    pub(crate) fn reading(&self) -> Option<&Reading> {
        self.reading.as_ref()
    }

    /// The derivation, made on the first call and kept.
    pub(crate) fn derivation(&self) -> Result<&Derivation, Error> {
        self.derivation
            .get_or_init(|| poly::derive(&self.method))
            .as_ref()
            .map_err(|e| Error::from(e.clone()))
    }
}

impl LoadedMethod {
    /// The derivation the w-plane reads: the program on y' = λy of a
    /// tableau or multistep file, else the method's own derivation (a
    /// scalar program, or an oscillator program with a scalar form).
    pub fn plane_derivation(&self) -> Result<&Derivation, Error> {
        match &self.scalar {
            Some(m) => self
                .scalar_derivation
                .get_or_init(|| poly::derive(m))
                .as_ref()
                .map_err(|e| Error::from(e.clone())),
            None => self.derivation(),
        }
    }
}

/// A built-in method's derivation, derived once per process: the paper's
/// report and its overview ask for the same few methods many times. The
/// built-ins are part of the binary, so a failure is a programmer error.
#[track_caller]
pub(crate) fn builtin_derivation(name: &str) -> Derivation {
    try_builtin_derivation(name).unwrap_or_else(|e| panic!("built-in {name}: {e}"))
}

/// [`builtin_derivation`], with a failure to parse or derive returned (and
/// not kept): for the claim that every built-in derives, and for a command
/// that lists built-ins.
pub(crate) fn try_builtin_derivation(name: &str) -> Result<Derivation, poly::Error> {
    static CACHE: OnceLock<Mutex<HashMap<String, Derivation>>> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    if let Some(d) = cache.lock().expect("cache lock").get(name) {
        return Ok(d.clone());
    }
    let d = poly::derive(&poly::builtin(name)?)?;
    cache.lock().expect("cache lock").insert(name.to_owned(), d.clone());
    Ok(d)
}

/// What [`resolve`] finds: the method, for a coefficient file its program
/// on y' = λy, its nonlinear reading where it has one, and the parameters
/// a tableau file declared (bound).
type Resolved = (Method, Option<Method>, Option<Reading>, Vec<String>);

/// The method `arg` names, a tableau's parameters bound to `values`.
fn resolve(arg: &str, oscillator: Oscillator, values: &[(String, Q)]) -> Result<Resolved, Error> {
    // A TOML file is a Butcher tableau, or a linear multistep method when it
    // has `alpha` or `beta`.
    if arg.ends_with(".toml") {
        let (shown, stem, text) = crate::tableau::read_file(Path::new(arg))?;
        let damped = oscillator == Oscillator::Damped;
        let mut taken = Vec::new();
        if crate::partitioned::is_partitioned(&text) || crate::partitioned::is_splitting(&text) {
            let (src, reading, warnings) = partitioned_program(arg, &shown, &stem, &text, damped)?;
            crate::warn::report(warnings)?;
            let method = Method::parse(arg, &src).map_err(|e| {
                Error::method(format!(
                    "{arg}: the program generated from the partitioned method does not parse: {}",
                    e.message()
                ))
            })?;
            // No program on y' = λy: a partitioned method needs the split.
            return Ok((method, None, Some(reading), taken));
        }
        let (method, scalar, what, reading) = if crate::tableau::is_multistep(&text) {
            let m = Multistep::parse(&shown, &stem, &text)?;
            crate::warn::report(m.warnings().to_vec())?;
            let (src, scalar) = (m.to_zm(damped), m.to_scalar_zm());
            let reading = Reading::of_multistep(&m);
            (
                Method::parse(arg, &src),
                Method::parse(arg, &scalar),
                "multistep coefficients",
                reading,
            )
        } else {
            let t = Tableau::parse_bound(&shown, &stem, &text, values)?;
            crate::warn::report(t.warnings().to_vec())?;
            taken = t.bound().iter().map(|(n, _)| n.clone()).collect();
            (t.program(arg, damped), t.scalar_program(arg), "tableau", Reading::of_tableau(&t))
        };
        let parsed = |m: Result<Method, poly::Error>| {
            m.map_err(|e| {
                Error::method(format!(
                    "{arg}: the program generated from the {what} does not parse: {}",
                    e.message()
                ))
            })
        };
        return Ok((parsed(method)?, Some(parsed(scalar)?), Some(reading), taken));
    }
    let method = check::load::load_method(arg)?;
    if check::load::is_path(arg) {
        let mut warnings = crate::warn::of_method(arg, &method);
        // The file parsed, so it is UTF-8 text within the size limit.
        if let Ok(text) = std::fs::read_to_string(arg) {
            warnings.extend(crate::warn::zm_decimal_hints(arg, &text));
        }
        crate::warn::report(warnings)?;
        return Ok((method, None, None, Vec::new()));
    }
    Ok((method, None, Reading::builtin(arg).transpose()?, Vec::new()))
}

/// A partitioned pair's or a splitting's program on the oscillator (q = y,
/// p = v; `poly::advanced::partitioned`), its reading and its warnings.
/// The damped spring is not separable, so it has none.
fn partitioned_program(
    arg: &str,
    shown: &str,
    stem: &str,
    text: &str,
    damped: bool,
) -> Result<(String, Reading, Vec<String>), Error> {
    if damped {
        return Err(Error::method(format!(
            "{arg}: a partitioned method integrates q' = f(p), p' = g(q); the damped spring \
             (p' depends on p) is not of that form"
        )));
    }
    use poly::advanced::partitioned::{partitioned_zm, splitting_zm};
    if crate::partitioned::is_partitioned(text) {
        let p = crate::partitioned::Partitioned::parse(shown, stem, text)?;
        let src = partitioned_zm(&p.name, shown, &p.q, &p.p);
        Ok((src, Reading::of_partitioned(&p), p.warnings))
    } else {
        let s = crate::partitioned::Splitting::parse(shown, stem, text)?;
        let src = splitting_zm(&s.name, shown, &s.drift, &s.kick);
        Ok((src, Reading::of_splitting(&s), s.warnings))
    }
}

/// The `--param NAME=VALUE` values as the loaders bind a tableau's
/// parameters; a range (`NAME=LO..HI`) or a malformed argument is skipped
/// here and reported by the command.
pub(crate) fn values_of(params: &[String]) -> Vec<(String, Q)> {
    params
        .iter()
        .filter(|s| !s.contains(".."))
        .filter_map(|s| s.parse::<ParamArg>().ok())
        .map(|p| (p.name, p.value.value))
        .collect()
}

/// The parameter's name in a `--param NAME=...` argument as typed.
pub(crate) fn arg_name(s: &str) -> &str {
    s.split('=').next().unwrap_or("").trim()
}

/// [`values_of`] for arguments already read.
pub(crate) fn values_of_args(params: &[ParamArg]) -> Vec<(String, Q)> {
    params.iter().map(|p| (p.name.clone(), p.value.value.clone())).collect()
}

/// The `--param` arguments left for the methods' programs once each
/// tableau with parameters has taken its own (they were bound as it was
/// read): a name some tableau took is dropped unless some program declares
/// it too. A name nobody declares stays, for the command to refuse.
pub(crate) fn unclaimed<T: Clone>(
    params: &[T],
    name: impl Fn(&T) -> &str,
    loaded: &[&LoadedMethod],
) -> Vec<T> {
    params
        .iter()
        .filter(|p| {
            let n = name(p);
            let taken = loaded.iter().any(|m| m.tableau_params.iter().any(|t| t == n));
            let declared = loaded.iter().any(|m| m.method.params().iter().any(|s| s.name() == n));
            !taken || declared
        })
        .cloned()
        .collect()
}

/// The damped twin of a built-in's name: itself for a damped built-in,
/// `damped_euler_d` for Standard Euler, `<name>_damped` where it exists.
fn damped_twin(arg: &str) -> Option<&'static str> {
    let wanted = match arg {
        "standard_euler" => "damped_euler_d".to_owned(),
        a if poly::advanced::builtins::DAMPED_METHODS.contains(&a) => a.to_owned(),
        a => format!("{a}_damped"),
    };
    poly::advanced::builtins::DAMPED_METHODS.iter().copied().find(|n| *n == wanted)
}

/// A built-in's name without its damping: `false_euler_damped` is
/// `false_euler`, `damped_euler_d` is `standard_euler`.
fn base_name(name: &str) -> &str {
    match name {
        "damped_euler_d" => "standard_euler",
        n => n.strip_suffix("_damped").unwrap_or(n),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each damped twin is found by its base name and shown by it; an
    /// argument without a twin loads as it is, shown as typed.
    #[test]
    fn damped_twins_and_their_names() {
        for (arg, name, shown) in [
            ("standard_euler", "damped_euler_d", "standard_euler"),
            ("damped_euler_d", "damped_euler_d", "standard_euler"),
            ("false_euler", "false_euler_damped", "false_euler"),
            ("false_euler_damped", "false_euler_damped", "false_euler"),
            ("verlet", "verlet_damped", "verlet"),
        ] {
            let m = LoadedMethod::load_damped(arg, &[]).unwrap();
            assert_eq!((m.method().name(), m.display()), (name, shown), "{arg}");
            assert!(m.system_kernel().is_some() && m.hand_kernel().is_some(), "{arg}");
        }
        let m = LoadedMethod::load_damped("gauss_legendre_2", &[]).unwrap();
        assert_eq!((m.method().name(), m.display()), ("gauss_legendre_2", "gauss_legendre_2"));
        assert_eq!((m.hand_kernel(), m.system_kernel()), (None, None));
        let d = LoadedMethod::builtin("damped_euler_d").unwrap();
        assert_eq!(d.hand_kernel(), Some("standard_euler_damped"));
    }

    /// The derivation is made once and kept.
    #[test]
    fn derives_once() {
        let m = LoadedMethod::load("false_euler").unwrap();
        let first: *const Derivation = m.derivation().unwrap();
        let second: *const Derivation = m.derivation().unwrap();
        assert_eq!(first, second);
    }
}
