//! `zcheck._native`: the Rust half of the Python package `zcheck`.
//!
//! Every function here is a thin call through a front door, `poly`'s for
//! making a method and `zcheck::api` for every question, and returns what
//! the command line would print with `--format json`: as a JSON string the
//! Python half parses, or, for `stability`, as the Python objects of that
//! text (DESIGN.md, "How does a result cross into Python?").
//! There is no mathematics here.
//!
//! Each call runs with the GIL released and inside `catch_unwind`: a Rust
//! panic becomes `zcheck.Error` and never unwinds into the interpreter
//! (DESIGN.md, "How is a panic kept out of Python?").

use std::panic::{self, AssertUnwindSafe};
use std::path::PathBuf;

use pyo3::create_exception;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyFrozenSet, PyList, PyString};
use serde_json::Value;
use zcheck::api::{self, LoadedMethod};

/// The allocator of the `zcheck` binary: the exact engine allocates and
/// frees many small big integers (DESIGN.md, "Why mimalloc as the
/// allocator?").
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

create_exception!(
    zcheck,
    Error,
    PyValueError,
    "A method, a number, a parameter or a file zcheck cannot take, with the message the \
     command line prints (file:line:column where there is one)."
);

/// What a call gives back before it crosses: a JSON document, or the
/// message of an error.
type Answer<T> = Result<T, String>;

/// Runs `work` with the GIL released; an error and a panic both become
/// `zcheck.Error`.
fn run<T: Send>(py: Python<'_>, work: impl FnOnce() -> Answer<T> + Send) -> PyResult<T> {
    let caught = py.detach(|| panic::catch_unwind(AssertUnwindSafe(work)));
    match caught {
        Ok(Ok(v)) => Ok(v),
        Ok(Err(message)) => Err(Error::new_err(message)),
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "no message".to_owned());
            Err(Error::new_err(format!(
                "internal error (a bug in zcheck, please report it): {what}"
            )))
        }
    }
}

fn message(e: &zcheck::Error) -> String {
    api::message(e)
}

fn poly_message(e: &poly::Error) -> String {
    api::message(&zcheck::Error::from(e.clone()))
}

fn json(v: Result<serde_json::Value, zcheck::Error>) -> Answer<String> {
    let v = v.map_err(|e| message(&e))?;
    serde_json::to_string(&v).map_err(|e| e.to_string())
}

/// Which strings of a document become `zcheck.Exact`: those under the
/// keys of `keys` (the Python half's tagging hooks, by key).
struct Tagging<'py> {
    exact: Bound<'py, PyAny>,
    keys: Bound<'py, PyFrozenSet>,
}

/// A JSON document as the Python objects `json.loads` makes of its text
/// (an integer as `int`, any other number as `float`), with the strings
/// under `tagging`'s keys made `zcheck.Exact`. serde_json writes every
/// float with a point or an exponent and reads back the same f64, so the
/// two agree down to the types (a pytest holds them to it on every
/// built-in and catalogue method).
fn to_python<'py>(
    py: Python<'py>,
    v: &Value,
    tagging: &Tagging<'py>,
) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_u64(), n.as_f64()) {
            (Some(i), _, _) => i.into_pyobject(py)?.into_any(),
            (None, Some(u), _) => u.into_pyobject(py)?.into_any(),
            (None, None, Some(f)) => PyFloat::new(py, f).into_any(),
            (None, None, None) => unreachable!("a JSON number is an i64, a u64 or an f64"),
        },
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Array(xs) => {
            let items =
                xs.iter().map(|x| to_python(py, x, tagging)).collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        Value::Object(map) => {
            let d = PyDict::new(py);
            for (k, x) in map {
                let key = PyString::new(py, k);
                let value = match x {
                    Value::String(s) if tagging.keys.contains(&key)? => {
                        tagging.exact.call1((s.as_str(),))?
                    }
                    _ => to_python(py, x, tagging)?,
                };
                d.set_item(key, value)?;
            }
            d.into_any()
        }
    })
}

/// A method, derived once and kept: made by `zcheck.Method`'s constructors.
#[pyclass(frozen, module = "zcheck._native", name = "NativeMethod")]
struct NativeMethod {
    inner: LoadedMethod,
}

fn method(m: Answer<LoadedMethod>) -> Answer<NativeMethod> {
    m.map(|inner| NativeMethod { inner })
}

#[pymethods]
impl NativeMethod {
    /// The method's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.method().name().to_owned()
    }

    /// The names of the method's parameters other than Phi.
    #[getter]
    fn params(&self) -> Vec<String> {
        self.inner
            .method()
            .params()
            .iter()
            .map(|s| s.name().to_owned())
            .filter(|n| n != "Phi")
            .collect()
    }

    /// `zcheck derive --format json`, as JSON text.
    fn derive(&self, py: Python<'_>) -> PyResult<String> {
        run(py, || json(api::derive(&self.inner)))
    }

    /// `zcheck stability --format json` with `params` (`NAME=VALUE`) bound.
    fn stability(&self, py: Python<'_>, params: Vec<String>) -> PyResult<String> {
        run(py, || json(api::stability(&self.inner, &params)))
    }

    /// `zcheck stability --format json` with `params` bound, as Python
    /// objects: what `json.loads` gives of its text, with every string
    /// under a key in `exact_keys` made an instance of `exact`
    /// (`zcheck.Exact`), built without the text in between.
    fn stability_object<'py>(
        &self,
        py: Python<'py>,
        params: Vec<String>,
        exact: Bound<'py, PyAny>,
        exact_keys: Bound<'py, PyFrozenSet>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let v = run(py, || api::stability(&self.inner, &params).map_err(|e| message(&e)))?;
        to_python(py, &v, &Tagging { exact, keys: exact_keys })
    }

    /// `zcheck region --format json` with `params` (`NAME=VALUE`) bound.
    fn region(&self, py: Python<'_>, params: Vec<String>) -> PyResult<String> {
        run(py, || json(api::region(&self.inner, &params)))
    }

    /// One point of `zcheck verify --format json`: the witnesses at Φ.
    fn verify(
        &self,
        py: Python<'_>,
        phi: String,
        params: Vec<String>,
        steps: u64,
    ) -> PyResult<String> {
        run(py, || json(api::verify(&self.inner, &phi, &params, steps)))
    }

    /// `zcheck order --format json`: the classical order and what follows
    /// it, of the method's nonlinear reading.
    #[pyo3(signature = (modified=None, tolerance=None))]
    fn order(
        &self,
        py: Python<'_>,
        modified: Option<usize>,
        tolerance: Option<String>,
    ) -> PyResult<String> {
        run(py, || {
            api::order_text(&self.inner, modified, tolerance.as_deref()).map_err(|e| message(&e))
        })
    }

    /// `zcheck map --format json`.
    #[pyo3(signature = (phi, params, grid, samples))]
    fn map(
        &self,
        py: Python<'_>,
        phi: Option<String>,
        params: Vec<String>,
        grid: usize,
        samples: usize,
    ) -> PyResult<String> {
        run(py, || json(api::map(&self.inner, phi.as_deref(), &params, grid, samples)))
    }

    /// `zcheck design --format json`: the free parameters (`NAME=LO..HI`)
    /// chosen for the best exact objective, the others bound (`NAME=VALUE`).
    #[pyo3(signature = (maximize, params, min_order=None, per=None))]
    fn design(
        &self,
        py: Python<'_>,
        maximize: String,
        params: Vec<String>,
        min_order: Option<usize>,
        per: Option<String>,
    ) -> PyResult<String> {
        run(py, || json(api::design(&self.inner, &maximize, &params, min_order, per.as_deref())))
    }
}

/// A method as a command reads its argument: a `.zm`, or a `.toml` tableau
/// or multistep file.
#[pyfunction]
fn load(py: Python<'_>, arg: String) -> PyResult<NativeMethod> {
    run(py, || method(api::load(&arg).map_err(|e| message(&e))))
}

/// A built-in method by name.
#[pyfunction]
fn builtin(py: Python<'_>, name: String) -> PyResult<NativeMethod> {
    run(py, || method(api::builtin(&name).map_err(|e| message(&e))))
}

/// A method from `.zm` source text, `file` naming it in errors.
#[pyfunction]
fn from_zm(py: Python<'_>, file: String, text: String) -> PyResult<NativeMethod> {
    run(py, || {
        method(poly::Method::parse(&file, &text).map(api::loaded).map_err(|e| poly_message(&e)))
    })
}

/// A Runge–Kutta method from its Butcher tableau, every entry exact text,
/// with `bhat` for an embedded pair.
#[pyfunction]
#[pyo3(signature = (name, a, b, c=None, bhat=None))]
fn from_tableau(
    py: Python<'_>,
    name: String,
    a: Vec<Vec<String>>,
    b: Vec<String>,
    c: Option<Vec<String>>,
    bhat: Option<Vec<String>>,
) -> PyResult<NativeMethod> {
    run(py, || {
        let a: Vec<Vec<&str>> = a.iter().map(|r| r.iter().map(String::as_str).collect()).collect();
        let b: Vec<&str> = b.iter().map(String::as_str).collect();
        let c: Option<Vec<&str>> = c.as_ref().map(|c| c.iter().map(String::as_str).collect());
        let bhat: Option<Vec<&str>> = bhat.as_ref().map(|x| x.iter().map(String::as_str).collect());
        method(api::tableau(&name, &a, &b, c.as_deref(), bhat.as_deref()).map_err(|e| message(&e)))
    })
}

/// A linear multistep method from α and β (lowest j first), exact text.
#[pyfunction]
fn from_multistep(
    py: Python<'_>,
    name: String,
    alpha: Vec<String>,
    beta: Vec<String>,
) -> PyResult<NativeMethod> {
    run(py, || {
        let alpha: Vec<&str> = alpha.iter().map(String::as_str).collect();
        let beta: Vec<&str> = beta.iter().map(String::as_str).collect();
        method(api::multistep(&name, &alpha, &beta).map_err(|e| message(&e)))
    })
}

/// `substeps` and `iterations`, both or neither.
fn config_of(substeps: Option<u64>, iterations: Option<u64>) -> Answer<Option<(u64, u64)>> {
    match (substeps, iterations) {
        (Some(s), Some(n)) => Ok(Some((s, n))),
        (None, None) => Ok(None),
        _ => Err("substeps= and iterations= go together: give both, or neither for the search"
            .to_owned()),
    }
}

/// `zcheck advise --scene FILE --format json` (with `--solver`, its
/// configuration, or `--solvers`).
#[pyfunction]
#[pyo3(signature = (path, solver=None, substeps=None, iterations=None, solvers=Vec::new()))]
fn advise_file(
    py: Python<'_>,
    path: PathBuf,
    solver: Option<String>,
    substeps: Option<u64>,
    iterations: Option<u64>,
    solvers: Vec<String>,
) -> PyResult<String> {
    run(py, || {
        let config = config_of(substeps, iterations)?;
        json(api::advise_scene_file(&path, solver.as_deref(), config, &solvers))
    })
}

/// The same, on a scene's TOML text (`name` shown in errors).
#[pyfunction]
#[pyo3(signature = (name, text, solver=None, substeps=None, iterations=None, solvers=Vec::new()))]
fn advise_text(
    py: Python<'_>,
    name: String,
    text: String,
    solver: Option<String>,
    substeps: Option<u64>,
    iterations: Option<u64>,
    solvers: Vec<String>,
) -> PyResult<String> {
    run(py, || {
        let config = config_of(substeps, iterations)?;
        json(api::advise_scene_text(&name, &text, solver.as_deref(), config, &solvers))
    })
}

/// `zcheck paper --format json`.
#[pyfunction]
fn paper(py: Python<'_>) -> PyResult<String> {
    run(py, || json(api::paper()))
}

/// Panics inside the containment, for the test that no panic crosses.
#[pyfunction]
fn _panic_for_test(py: Python<'_>) -> PyResult<()> {
    run(py, || -> Answer<()> { panic!("a test panic") })
}

/// The Rust half of `zcheck`; import `zcheck`, not this module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("Error", m.py().get_type::<Error>())?;
    m.add_class::<NativeMethod>()?;
    m.add_function(wrap_pyfunction!(load, m)?)?;
    m.add_function(wrap_pyfunction!(builtin, m)?)?;
    m.add_function(wrap_pyfunction!(from_zm, m)?)?;
    m.add_function(wrap_pyfunction!(from_tableau, m)?)?;
    m.add_function(wrap_pyfunction!(from_multistep, m)?)?;
    m.add_function(wrap_pyfunction!(advise_file, m)?)?;
    m.add_function(wrap_pyfunction!(advise_text, m)?)?;
    m.add_function(wrap_pyfunction!(paper, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_test, m)?)?;
    Ok(())
}
