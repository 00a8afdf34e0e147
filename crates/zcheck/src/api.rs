//! The door of other front ends, first the Python package
//! (`crates/zcheck-py`): a method loaded as the command line loads it, and
//! each question answered by the JSON document the matching command prints
//! with `--format json`, built by the same function. A field therefore has
//! one name and one meaning however it is reached, and a front end adds no
//! mathematics of its own.
//!
//! Numbers come in as the command line takes them: a parameter is
//! `NAME=VALUE` with an exact VALUE (`1/2`, `0.1`), a range `LO..HI`.
//! Errors are the command line's, with their locations.

use std::path::Path;

use serde_json::Value;

use crate::error::Error;
pub use crate::load::LoadedMethod;
use crate::scene::advisor::Options;
use crate::scene::file::SceneFile;
use crate::values::ParamArg;

/// A method argument as a command reads it: a built-in's name, a `.zm`
/// file, or a `.toml` file (a Butcher tableau, or `alpha` and `beta` of a
/// linear multistep method).
pub fn load(arg: &str) -> Result<LoadedMethod, Error> {
    LoadedMethod::load(arg)
}

/// A method made by `poly`'s front door (`.zm` text, a tableau, multistep
/// coefficients, a built-in), shown by its name.
pub fn loaded(method: poly::Method) -> LoadedMethod {
    LoadedMethod::of(method)
}

/// A built-in by name, as a command loads it (with its nonlinear reading,
/// where it has one).
pub fn builtin(name: &str) -> Result<LoadedMethod, Error> {
    LoadedMethod::builtin(name)
}

/// A Runge–Kutta method from its Butcher tableau's exact entries (text),
/// with `bhat` for an embedded pair: the program, and the tableau kept for
/// [`order_text`].
pub fn tableau(
    name: &str,
    a: &[Vec<&str>],
    b: &[&str],
    c: Option<&[&str]>,
    bhat: Option<&[&str]>,
) -> Result<LoadedMethod, Error> {
    // Every entry is read once: the method and its nonlinear reading share
    // the tableau (and its stability function, computed for the method).
    let tableau = poly::advanced::tableau::Tableau::from_text(name, a, b, c)?;
    let method = tableau.method(false)?;
    let reading = crate::readings::Reading::of_parsed_tableau(tableau, a, b, c, bhat)?;
    Ok(LoadedMethod::with_reading(method, reading))
}

/// A linear multistep method from α and β (exact text, lowest j first),
/// the coefficients kept for [`order_text`].
pub fn multistep(name: &str, alpha: &[&str], beta: &[&str]) -> Result<LoadedMethod, Error> {
    let method = poly::Method::from_multistep(name, alpha, beta)?;
    let reading = crate::readings::Reading::of_coefficients(name, alpha, beta)?;
    Ok(LoadedMethod::with_reading(method, reading))
}

/// A method's nonlinear reading, or the error that says it has none.
fn reading_of(method: &LoadedMethod) -> Result<&crate::readings::Reading, Error> {
    method.reading().ok_or_else(|| {
        Error::method(format!(
            "{}: no nonlinear reading (a tableau, pair, splitting or multistep method): a .zm \
             program is the method on the oscillator or on y' = λy only",
            method.method().name()
        ))
    })
}

/// `zcheck order --format json` of one method, as compact JSON text: the
/// classical order and what follows it, with `--modified N` and
/// `--tolerance T` (exact text). Written straight from the report: the
/// same text as the command's tree printed compactly.
pub fn order_text(
    method: &LoadedMethod,
    modified: Option<usize>,
    tolerance: Option<&str>,
) -> Result<String, Error> {
    use crate::answers::order::{report, to_json_text, Request};
    let request = Request::parse(modified, tolerance)?;
    let reading = reading_of(method)?;
    Ok(to_json_text(reading, &report(reading, &request)?))
}

/// `zcheck derive --format json`: M(z), P, χ(z) and, for an implicit
/// method, P's denominator.
pub fn derive(method: &LoadedMethod) -> Result<Value, Error> {
    Ok(crate::answers::derive::to_json(method.derivation()?))
}

/// `zcheck stability --format json` with `params` (`NAME=VALUE`) bound.
pub fn stability(method: &LoadedMethod, params: &[String]) -> Result<Value, Error> {
    crate::answers::stability::forget_rendered();
    let params = read_params(params)?;
    Ok(crate::answers::stability::Analysis::of(method.derivation()?, &params)?.to_json())
}

/// `zcheck region --format json` of one method with `params`
/// (`NAME=VALUE`) bound; a parameter the method lacks is an error.
pub fn region(method: &LoadedMethod, params: &[String]) -> Result<Value, Error> {
    let params = read_params(params)?;
    crate::values::check_declared(&params, &[method.method()])?;
    let name = method.method().name();
    let (shown, report, classical) = crate::answers::plane::plane(name, method, &params)?;
    Ok(crate::answers::plane::to_json(name, &shown, &report, classical))
}

/// One point of `zcheck verify --format json` (`check::verify`): the
/// numeric witnesses at Φ (exact text such as `1/2`, run at its nearest
/// f64) with `params` bound, over `steps` steps.
pub fn verify(
    method: &LoadedMethod,
    phi: &str,
    params: &[String],
    steps: u64,
) -> Result<Value, Error> {
    let phi: crate::values::Exact =
        phi.parse().map_err(|e: String| Error::usage(format!("phi {phi}: {e}")))?;
    phi.to_f64("phi")?;
    let params = read_params(params)?;
    crate::values::check_declared(&params, &[method.method()])?;
    let mut bound = check::Params::default();
    for p in &params {
        p.value.to_f64(&format!("parameter {}", p.name))?;
        bound.insert(&p.name, p.value.value.clone());
    }
    let bound = bound.bind("Phi", phi.value);
    let point = check::verify(method.derivation()?, &bound, steps)?;
    Ok(crate::answers::verify::point_json(&point))
}

/// `zcheck map --format json`: over (Φ, NAME) with `phi` (`LO..HI`) and
/// one range, or over two parameters (two ranges, no `phi`); `params` as
/// typed after `--param` (`NAME=LO..HI` or `NAME=VALUE`).
pub fn map(
    method: &LoadedMethod,
    phi: Option<&str>,
    params: &[String],
    grid: usize,
    samples: usize,
) -> Result<Value, Error> {
    crate::answers::region::compute(method, phi, params, grid, samples)?.to_json()
}

/// `zcheck design --format json` of a program (a `.zm` or a built-in): its
/// one or two free parameters chosen for the best exact `maximize`
/// (`phi_max`, `real_limit`, `imag_limit`, `ssp_coefficient`), with
/// `params` as typed after `--param` (`NAME=LO..HI` free, `NAME=VALUE`
/// bound), `min_order` and `per` (`stage` or `cost`). A tableau whose
/// entries name parameters is designed from the command line.
pub fn design(
    method: &LoadedMethod,
    maximize: &str,
    params: &[String],
    min_order: Option<usize>,
    per: Option<&str>,
) -> Result<Value, Error> {
    use crate::answers::design::{design, to_json, Request, Subject};
    let request = Request::parse(maximize, params, min_order, per)?;
    let subject = Subject::Program(Box::new(method.clone()));
    Ok(to_json(&design(&subject, &request)?))
}

/// `zcheck advise --scene FILE --format json`, the prediction checked by
/// simulation; with `solver` (`xpbd`, `xpbd_jacobi`, `soft_step`),
/// `--solver`'s document: the configuration `(substeps, iterations)`, or
/// without one the search; with `families` (`paper`, and solver names),
/// `--solvers`' table.
pub fn advise_scene_file(
    path: &Path,
    solver: Option<&str>,
    config: Option<(u64, u64)>,
    families: &[String],
) -> Result<Value, Error> {
    advise(&SceneFile::load(path)?, solver, config, families)
}

/// [`advise_scene_file`] on the text of a scene file, named `name` in
/// errors.
pub fn advise_scene_text(
    name: &str,
    text: &str,
    solver: Option<&str>,
    config: Option<(u64, u64)>,
    families: &[String],
) -> Result<Value, Error> {
    advise(&SceneFile::parse(name, text)?, solver, config, families)
}

fn advise(
    scene: &SceneFile,
    solver: Option<&str>,
    config: Option<(u64, u64)>,
    families: &[String],
) -> Result<Value, Error> {
    let options = Options {
        simulate: true,
        simulate_all: false,
        gauss_seidel: false,
        route: Default::default(),
        rank: Default::default(),
    };
    if !families.is_empty() {
        if solver.is_some() || config.is_some() {
            return Err(Error::usage("solvers= compares families: give it without solver="));
        }
        let families = crate::answers::families::parse_families(families)?;
        let table = crate::answers::families::family_table(scene, &families, &[], &[], options)?;
        return Ok(serde_json::to_value(table)?);
    }
    match solver {
        Some(word) => {
            let solver = crate::scene::solvers::Solver::parse(word)?;
            Ok(serde_json::to_value(crate::scene::solvers::solver_advice(scene, solver, config)?)?)
        }
        None if config.is_some() => {
            Err(Error::usage("substeps= and iterations= configure a solver: give solver= too"))
        }
        None => Ok(serde_json::to_value(crate::answers::advice::scene_advice(
            scene,
            &[],
            &[],
            options,
        )?)?),
    }
}

/// `zcheck paper --format json`: the claims, the summary and the overview.
pub fn paper() -> Result<Value, Error> {
    crate::paper::json_document()
}

/// The error as the command line prints it after `error: `: its message,
/// then each of its sources after `: `.
pub fn message(e: &Error) -> String {
    crate::error::with_sources(e)
}

/// `NAME=VALUE` arguments read as `--param` reads them.
fn read_params(params: &[String]) -> Result<Vec<ParamArg>, Error> {
    params
        .iter()
        .map(|s| s.parse().map_err(|e: String| Error::usage(format!("parameter {s}: {e}"))))
        .collect()
}
