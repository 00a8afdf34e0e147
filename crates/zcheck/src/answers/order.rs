//! `zcheck order`: the order analysis beyond y' = λy (poly's
//! `poly::advanced::order`) of a method's nonlinear reading
//! ([`crate::readings`]), as a JSON document and as text a person reads;
//! and the classical order alone, for `zcheck region` and `zcheck methods`.
//!
//! Every field of the report is in the JSON, `null` where it does not apply
//! to the kind of method. An order is a number, or `null` with
//! `…_at_least` beside it when only a lower bound is proven (past the trees
//! generated; the notes say why). Every exact number is `{"exact",
//! "value"}` ([`super::exact`]).
//!
//! The default tolerance is the application's, not `poly`'s: `poly`'s exact
//! number does not know it was written as a decimal. When an entry is a
//! decimal of at least [`LONG_DECIMAL`] significant digits (a float written
//! out, such as Tsit5's published coefficients), the order within 1e-12 is
//! given beside the exact order; `--tolerance` sets the tolerance for any
//! input.

use std::fmt::Write as _;

use num_traits::ToPrimitive;
use poly::advanced::order::{self, Kind, Options, Order, OrderReport, Ssp};
use poly::Q;
use serde::Serialize;
use serde_json::{json, Value};

use super::exact::{constant, infinity, number};
use crate::error::Error;
use crate::readings::{Form, Reading};

/// A decimal entry with at least this many significant digits makes the
/// order within a tolerance part of the report.
pub(crate) const LONG_DECIMAL: usize = 10;

/// What the caller asks beyond the defaults: the modified equation up to
/// h^N, a tolerance.
#[derive(Clone, Debug, Default)]
pub(crate) struct Request {
    pub(crate) modified: Option<usize>,
    pub(crate) tolerance: Option<Q>,
}

impl Request {
    /// A request from the command line's text: `--modified N` (1 to the
    /// largest power the cached trees allow) and `--tolerance T` (an exact
    /// number ≥ 0, `1e-12` or `1/10^12`).
    pub(crate) fn parse(
        modified: Option<usize>,
        tolerance: Option<&str>,
    ) -> Result<Request, Error> {
        let most = order::MAX_TREE_ORDER - 1;
        if let Some(n) = modified {
            if n == 0 || n > most {
                return Err(Error::usage(format!(
                    "--modified {n}: the modified equation up to h^{n} needs rooted trees of \
                     order {}: expected a power from 1 to {most} (trees are generated up to \
                     order {})",
                    n + 1,
                    order::MAX_TREE_ORDER
                )));
            }
        }
        let tolerance = match tolerance {
            None => None,
            Some(t) => {
                let v: crate::values::Exact =
                    t.parse().map_err(|e: String| Error::usage(format!("--tolerance {t}: {e}")))?;
                if v.value < Q::from_integer(0.into()) {
                    return Err(Error::usage(format!("--tolerance {t}: expected a tolerance ≥ 0")));
                }
                Some(v.value)
            }
        };
        Ok(Request { modified, tolerance })
    }
}

/// 1e-12, the default tolerance for long decimals.
fn default_tolerance() -> Q {
    Q::from_integer(1.into()) / num_traits::pow(Q::from_integer(10.into()), 12)
}

/// The order report of a reading.
pub(crate) fn report(reading: &Reading, request: &Request) -> Result<OrderReport, Error> {
    let defaulted = request.tolerance.is_none() && reading.decimal_digits >= LONG_DECIMAL;
    let tolerance = request.tolerance.clone().or_else(|| defaulted.then(default_tolerance));
    let rk = matches!(reading.form, Form::RungeKutta { .. });
    let options = Options { modified: request.modified.filter(|_| rk), tolerance };
    let in_method = |e: poly::Error| Error::from(e).context(format!("method {}", reading.name));
    let mut r = match &reading.form {
        Form::RungeKutta { tableau, bhat } => {
            order::runge_kutta(tableau, bhat.as_deref(), &options)
        }
        Form::Partitioned { q, p } => order::partitioned(q, p, &options),
        Form::Splitting { drift, kick } => order::splitting(drift, kick, &options),
        Form::Multistep(m) => order::multistep(m, &options),
    }
    .map_err(in_method)?;
    if request.modified.is_some() && !rk {
        r.notes.push(
            "--modified: the modified equation is computed for Runge–Kutta tableaux only"
                .to_owned(),
        );
    }
    if defaulted && r.order_within_tolerance.is_some() {
        r.notes.push(format!(
            "an entry is a decimal of {} significant digits (a float written out): the order \
             within 1e-12 is given beside the exact order of the decimals (--tolerance sets \
             the tolerance)",
            reading.decimal_digits
        ));
    }
    Ok(r)
}

/// The classical order of a reading, alone.
pub(crate) fn classical_order(reading: &Reading) -> Result<Order, Error> {
    Ok(report(reading, &Request::default())?.order)
}

/// An order as JSON: `(number, at_least)`, one of them `null`.
pub(crate) fn order_json(o: Option<Order>) -> (Value, Value) {
    match o {
        Some(Order::Exact(p)) => (json!(p), Value::Null),
        Some(Order::AtLeast(p)) => (Value::Null, json!(p)),
        None => (Value::Null, Value::Null),
    }
}

/// The JSON object of `zcheck order` for one method, as a tree.
pub(crate) fn to_json(reading: &Reading, r: &OrderReport) -> Value {
    serde_json::to_value(Document::of(reading, r)).expect("a document serializes")
}

/// The JSON text of `zcheck order` for one method, compact: the same as
/// [`to_json`]'s tree printed, written straight from the report (no tree is
/// built; the keys are serialized in the tree's sorted order).
pub(crate) fn to_json_text(reading: &Reading, r: &OrderReport) -> String {
    serde_json::to_string(&Document::of(reading, r)).expect("a document serializes")
}

/// The document, field by field, in the sorted order of a JSON object's
/// keys (a test holds it to the tree built key by key).
#[derive(Serialize)]
struct Document<'a> {
    algebraically_stable: Option<bool>,
    embedded_linear_order: Option<usize>,
    embedded_linear_order_at_least: Option<usize>,
    embedded_order: Option<usize>,
    embedded_order_at_least: Option<usize>,
    embedded_order_within_tolerance: Option<Within>,
    failed_conditions: Option<Vec<Failed<'a>>>,
    kind: &'static str,
    linear_order: Option<usize>,
    linear_order_at_least: Option<usize>,
    method: &'a str,
    modified_equation: Option<Vec<Term<'a>>>,
    notes: &'a [String],
    order: Option<usize>,
    order_at_least: Option<usize>,
    order_within_tolerance: Option<Within>,
    reading: Option<&'static str>,
    reducible: Option<bool>,
    ssp_coefficient: Value,
    stage_order: Option<usize>,
    symmetric: Option<bool>,
    symplectic: Option<bool>,
}

#[derive(Serialize)]
struct Failed<'a> {
    differential: &'a str,
    residual: Constant,
    tree: &'a str,
}

#[derive(Serialize)]
struct Term<'a> {
    coefficient: Constant,
    differential: &'a str,
    power: usize,
    tree: &'a str,
}

#[derive(Serialize)]
struct Within {
    order: Option<usize>,
    order_at_least: Option<usize>,
    tolerance: Constant,
}

/// `{"exact", "value"}` of a constant of the method's field.
#[derive(Serialize)]
struct Constant {
    exact: String,
    value: Option<f64>,
}

impl Constant {
    fn of(x: &order::Value) -> Constant {
        match x.as_rational() {
            Some(q) => Constant::rational(q),
            None => {
                let v = constant(&x.to_poly());
                Constant {
                    exact: v["exact"].as_str().expect("text").to_owned(),
                    value: v["value"].as_f64(),
                }
            }
        }
    }

    fn rational(q: &Q) -> Constant {
        Constant { exact: q.to_string(), value: q.to_f64() }
    }
}

/// An order as `(number, at_least)`, one of them `None`.
fn split(o: Option<Order>) -> (Option<usize>, Option<usize>) {
    match o {
        Some(Order::Exact(p)) => (Some(p), None),
        Some(Order::AtLeast(p)) => (None, Some(p)),
        None => (None, None),
    }
}

impl<'a> Document<'a> {
    fn of(reading: &'a Reading, r: &'a OrderReport) -> Document<'a> {
        let (order, order_at_least) = split(Some(r.order));
        let (linear_order, linear_order_at_least) = split(Some(r.linear_order));
        let (embedded_order, embedded_order_at_least) = split(r.embedded_order);
        let (embedded_linear_order, embedded_linear_order_at_least) =
            split(r.embedded_linear_order);
        let within = |t: &Option<poly::advanced::order::ToleranceOrder>| {
            t.as_ref().map(|t| {
                let (order, order_at_least) = split(Some(t.order));
                Within { order, order_at_least, tolerance: Constant::rational(&t.tolerance) }
            })
        };
        Document {
            algebraically_stable: r.algebraically_stable,
            embedded_linear_order,
            embedded_linear_order_at_least,
            embedded_order,
            embedded_order_at_least,
            embedded_order_within_tolerance: within(&r.embedded_order_within_tolerance),
            failed_conditions: r.failed_conditions.as_ref().map(|f| {
                f.iter()
                    .map(|c| Failed {
                        differential: &c.differential,
                        residual: Constant::of(&c.residual),
                        tree: &c.tree,
                    })
                    .collect()
            }),
            kind: r.kind.name(),
            linear_order,
            linear_order_at_least,
            method: &reading.name,
            modified_equation: r.modified_equation.as_ref().map(|terms| {
                terms
                    .iter()
                    .map(|t| Term {
                        coefficient: Constant::of(&t.coefficient),
                        differential: &t.differential,
                        power: t.power,
                        tree: &t.tree,
                    })
                    .collect()
            }),
            notes: &r.notes,
            order,
            order_at_least,
            order_within_tolerance: within(&r.order_within_tolerance),
            reading: reading.about,
            reducible: r.reducible,
            ssp_coefficient: match &r.ssp_coefficient {
                None => Value::Null,
                Some(Ssp::Unbounded) => infinity(),
                Some(Ssp::Radius(a)) => number(a, "r"),
            },
            stage_order: r.stage_order,
            symmetric: r.symmetric,
            symplectic: r.symplectic,
        }
    }
}

fn show_order(o: Order) -> String {
    match o {
        Order::Exact(p) => p.to_string(),
        Order::AtLeast(p) => format!("at least {p}"),
    }
}

fn kind_text(k: Kind) -> &'static str {
    match k {
        Kind::RungeKutta => "Runge–Kutta tableau",
        Kind::EmbeddedPair => "embedded Runge–Kutta pair",
        Kind::Partitioned => "partitioned Runge–Kutta pair, for q' = f(q, p), p' = g(q, p)",
        Kind::Splitting => "splitting, for q' = f(p), p' = g(q)",
        Kind::Multistep => "linear multistep method",
    }
}

/// The summary a person reads.
pub(crate) fn to_text(shown: &str, reading: &Reading, r: &OrderReport) -> String {
    let mut s = String::new();
    let row = |s: &mut String, k: &str, v: String| {
        let _ = writeln!(s, "  {k:<22} {v}");
    };
    let about = reading.about.map(|a| format!(": {a}")).unwrap_or_default();
    let _ = writeln!(s, "{shown}: {}{about}", kind_text(r.kind));
    let what = match r.kind {
        Kind::Partitioned => "(all bicolored trees)",
        Kind::Splitting => "(bicolored trees, colours alternating)",
        Kind::Multistep => "(C_q = 0)",
        _ => "(rooted trees)",
    };
    row(&mut s, "classical order", format!("{} {what}", show_order(r.order)));
    let linear = match r.kind {
        Kind::Partitioned | Kind::Splitting => "(linear separable systems, the oscillator)",
        _ => "(y' = λy)",
    };
    row(&mut s, "linear order", format!("{} {linear}", show_order(r.linear_order)));
    if let Some(t) = &r.order_within_tolerance {
        let v = num_traits::ToPrimitive::to_f64(&t.tolerance).unwrap_or(f64::NAN);
        row(
            &mut s,
            "order within tolerance",
            format!("{} (|residual| ≤ {v:e})", show_order(t.order)),
        );
    }
    if let Some(q) = r.stage_order {
        row(&mut s, "stage order", q.to_string());
    }
    let yes = |b: bool| if b { "yes" } else { "no" }.to_owned();
    if let Some(b) = r.algebraically_stable {
        row(&mut s, "algebraically stable", yes(b));
    }
    if let Some(b) = r.symplectic {
        row(&mut s, "symplectic", yes(b));
    }
    if let Some(b) = r.symmetric {
        row(&mut s, "symmetric", yes(b));
    }
    match &r.ssp_coefficient {
        Some(Ssp::Unbounded) => row(&mut s, "SSP coefficient", "∞ (unbounded)".to_owned()),
        Some(Ssp::Radius(a)) => {
            let exact = a.closed_form();
            let text = match exact {
                Some(c) if a.is_rational() => c,
                Some(c) => format!("{c} ≈ {}", a.to_decimal(12)),
                None => format!(
                    "{} (a root of {})",
                    a.to_decimal(12),
                    a.defining_poly().to_string_in("r")
                ),
            };
            row(&mut s, "SSP coefficient", text);
        }
        None => {}
    }
    if let Some(e) = r.embedded_order {
        row(&mut s, "embedded order", show_order(e));
    }
    if let Some(e) = r.embedded_linear_order {
        row(&mut s, "embedded linear order", show_order(e));
    }
    if let Some(t) = &r.embedded_order_within_tolerance {
        row(&mut s, "embedded within tol.", show_order(t.order));
    }
    if let Some(failed) = r.failed_conditions.as_ref().filter(|f| !f.is_empty()) {
        let _ =
            writeln!(s, "  conditions failing at order {} (Φ(t) − 1/γ(t)):", r.order.value() + 1);
        for c in failed {
            let _ = writeln!(s, "    {:<14} {:<18} {}", c.tree, c.differential, c.residual);
        }
    }
    if let Some(terms) = &r.modified_equation {
        let _ = writeln!(s, "  modified equation: ỹ' = f + Σ h^k c(t) F(t)");
        for t in terms {
            let _ = writeln!(
                s,
                "    h^{:<3} {:<14} {:<18} {}",
                t.power, t.tree, t.differential, t.coefficient
            );
        }
    }
    for n in &r.notes {
        let _ = writeln!(s, "  note: {n}");
    }
    s
}

/// The reports of several arguments, in order, as one document: an
/// object for one method, an array for several.
pub(crate) fn document(readings: &[(String, Reading, OrderReport)]) -> Value {
    let docs: Vec<Value> = readings.iter().map(|(_, g, r)| to_json(g, r)).collect();
    if docs.len() == 1 {
        docs.into_iter().next().expect("one document")
    } else {
        Value::Array(docs)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set_order(v: &mut Value, key: &str, o: Option<Order>) {
        let (exact, at_least) = order_json(o);
        v[key] = exact;
        v[format!("{key}_at_least")] = at_least;
    }

    /// The document built key by key as a tree: the oracle of [`Document`].
    pub(crate) fn to_json_by_keys(reading: &Reading, r: &OrderReport) -> Value {
        let value = |x: &order::Value| constant(&x.to_poly());
        let mut v = json!({
            "method": reading.name,
            "kind": r.kind.name(),
            "reading": reading.about,
        });
        set_order(&mut v, "order", Some(r.order));
        set_order(&mut v, "linear_order", Some(r.linear_order));
        v["stage_order"] = json!(r.stage_order);
        v["algebraically_stable"] = json!(r.algebraically_stable);
        v["symplectic"] = json!(r.symplectic);
        v["reducible"] = json!(r.reducible);
        v["symmetric"] = json!(r.symmetric);
        v["ssp_coefficient"] = match &r.ssp_coefficient {
            None => Value::Null,
            Some(Ssp::Unbounded) => infinity(),
            Some(Ssp::Radius(a)) => number(a, "r"),
        };
        set_order(&mut v, "embedded_order", r.embedded_order);
        set_order(&mut v, "embedded_linear_order", r.embedded_linear_order);
        v["failed_conditions"] = json!(r.failed_conditions.as_ref().map(|f| {
            f.iter()
                .map(|c| {
                    json!({
                        "tree": c.tree,
                        "differential": c.differential,
                        "residual": value(&c.residual),
                    })
                })
                .collect::<Vec<_>>()
        }));
        v["modified_equation"] = json!(r.modified_equation.as_ref().map(|terms| {
            terms
                .iter()
                .map(|t| {
                    json!({
                        "power": t.power,
                        "tree": t.tree,
                        "differential": t.differential,
                        "coefficient": value(&t.coefficient),
                    })
                })
                .collect::<Vec<_>>()
        }));
        let tolerance_order = |t: &Option<poly::advanced::order::ToleranceOrder>| match t {
            None => Value::Null,
            Some(t) => {
                let mut w =
                    json!({ "tolerance": constant(&poly::Poly::constant(t.tolerance.clone())) });
                set_order(&mut w, "order", Some(t.order));
                w
            }
        };
        v["order_within_tolerance"] = tolerance_order(&r.order_within_tolerance);
        v["embedded_order_within_tolerance"] = tolerance_order(&r.embedded_order_within_tolerance);
        v["notes"] = json!(r.notes);
        v
    }

    /// The document written straight from the report is the tree built key
    /// by key, printed: on NodePy's 50 RK methods and every built-in reading
    /// (tableaux, pairs, partitioned pairs, splittings, multistep), with
    /// and without a modified equation and a tolerance.
    #[test]
    fn document_is_the_tree_built_key_by_key() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/nodepy/rk");
        let mut readings: Vec<Reading> = std::fs::read_dir(dir)
            .expect("the catalogue")
            .map(|e| e.expect("an entry").path())
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .map(|p| {
                let (shown, stem, text) = crate::tableau::read_file(&p).expect("reads");
                Reading::parse_bound(&shown, &stem, &text, &[]).expect("parses").0
            })
            .collect();
        readings.extend(
            crate::readings::BUILTIN_READINGS
                .iter()
                .map(|(name, _, _)| Reading::builtin(name).expect("a built-in").expect("reads")),
        );
        let asks = [Request::default(), Request::parse(Some(3), Some("1e-10")).expect("a request")];
        let mut compared = 0;
        for g in &readings {
            for ask in &asks {
                let r = report(g, ask).expect("a report");
                let tree = serde_json::to_string(&to_json_by_keys(g, &r)).expect("prints");
                assert_eq!(to_json_text(g, &r), tree, "{}", g.name);
                assert_eq!(serde_json::to_string(&to_json(g, &r)).expect("prints"), tree);
                compared += 1;
            }
        }
        assert!(compared >= 2 * (50 + crate::readings::BUILTIN_READINGS.len()), "{compared}");
    }
}
