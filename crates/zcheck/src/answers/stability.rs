//! `zcheck stability`: the exact stability limit, the boundary kind and
//! every class change of a method over Φ > 0.
//!
//! The analysis is `poly::Derivation::stability`, exact throughout, which
//! has the transition matrix and so decides boundedness at a repeated root
//! on the circle; this file binds the `--param` values, adds the facts of an
//! implicit or constant-bearing step (det A, singular points, Φ → ∞) and the
//! limits as Φ → ∞ and Φ → 0 (ρ∞, phase and modulus errors), and prints.
//! Numbers are shown two ways:
//! the exact form (closed form, or defining polynomial and an isolating
//! interval narrowed to 1e-15) and an f64 taken from the exact decimal
//! expansion, which is the only place a float appears.

use crate::error::Error;
use crate::values::{self, ParamArg};
use poly::{Algebraic, Sym, Q};
use poly::{Stability, StabilityReport};
use serde_json::{json, Value};
use std::collections::HashMap;
use std::fmt::Write as _;

/// What `zcheck stability` reports of a method at the given parameter
/// values, before it is shown as text or JSON.
pub(crate) struct Analysis {
    name: String,
    shown: Vec<(String, Q)>,
    chi: poly::Poly,
    report: StabilityReport,
    facts: Option<ImplicitFacts>,
    far: FarAndNear,
}

impl Analysis {
    /// The analysis of `derivation` with `params` bound; a parameter the
    /// method does not declare is an error.
    pub(crate) fn of(
        derivation: &poly::Derivation,
        params: &[ParamArg],
    ) -> Result<Analysis, Error> {
        let method = &derivation.method();
        values::check_declared(params, &[method])?;
        let mut values = HashMap::new();
        let mut bound = poly::Params::new();
        let mut shown = Vec::new();
        for p in params {
            values.insert(Sym::new(&p.name), p.value.value.clone());
            bound.insert(&p.name, p.value.value.clone());
            shown.push((p.name.clone(), p.value.value.clone()));
        }
        let chi = derivation.charpoly().eval_partial(&values);
        // With the transition matrix, boundedness at a repeated root on the
        // circle is decided from P's Jordan structure (Merson at 2√3: P = I).
        let report = derivation
            .stability(&bound)
            .map_err(|e| Error::from(e).context(format!("method {}", method.name())))?;
        let facts = ImplicitFacts::of(derivation, &chi)?;
        let far = FarAndNear::of(derivation, &bound, &report);
        Ok(Analysis { name: method.name().to_owned(), shown, chi, report, facts, far })
    }

    /// The JSON document of `zcheck stability --format json`.
    pub(crate) fn to_json(&self) -> Value {
        let mut v = to_json(&self.name, &self.shown, &self.chi, &self.report);
        if let Some(f) = &self.facts {
            f.add_json(&mut v);
        }
        self.far.add_json(&mut v);
        v
    }

    pub(crate) fn text(&self) -> String {
        let mut names = Names::default();
        text(&self.name, &self.shown, &self.chi, &self.report, &mut names)
            + &self.facts.as_ref().map_or(String::new(), |f| f.text(&mut names))
            + &self.far.text(&mut names)
            + &names.definitions()
    }
}

/// For an implicit or constant-bearing method: the leading coefficient of
/// χ in z (det A), the Φ > 0 where the step's system is singular, and what
/// the roots do as Φ → ∞ (all decided exactly). Explicit methods print
/// nothing more, so their output is unchanged.
pub(crate) struct ImplicitFacts {
    lead: String,
    singular: Vec<Algebraic>,
    limit: &'static str,
}

impl ImplicitFacts {
    /// The facts of `derivation`, with χ at the given parameters; `None`
    /// for an explicit method without constants.
    fn of(derivation: &poly::Derivation, chi: &poly::Poly) -> Result<Option<ImplicitFacts>, Error> {
        let method = &derivation.method();
        if !method.is_implicit() && method.constants().is_empty() {
            return Ok(None);
        }
        let lead = chi.coeffs_in(Sym::z()).last().cloned().unwrap_or_default();
        let singular = derivation.singular_points();
        let limit = poly::advanced::stability::limit_at_infinity(chi)?;
        Ok(Some(ImplicitFacts { lead: lead.to_string(), singular, limit: limit.name() }))
    }

    fn text(&self, names: &mut Names) -> String {
        let mut s = format!("\nleading coefficient in z (det A): {}\n", self.lead);
        if self.singular.is_empty() {
            s += "the step's linear system is regular for every Phi > 0\n";
        } else {
            let pts: Vec<String> = self.singular.iter().map(|a| names.show(a)).collect();
            let _ = writeln!(s, "the step's linear system is singular at Phi = {}", pts.join(", "));
        }
        let _ = writeln!(s, "as Phi -> infinity: {}", self.limit);
        s
    }

    fn add_json(&self, v: &mut Value) {
        v["leading_coefficient"] = json!(self.lead);
        v["singular_points"] = json!(self.singular.iter().map(number_json).collect::<Vec<_>>());
        v["phi_to_infinity"] = json!(self.limit);
    }
}

/// The spectral radius as Φ → ∞, and the leading terms of the principal
/// root's phase and modulus errors as Φ → 0 (exact; an answer that does not
/// exist is null with the reason).
pub(crate) struct FarAndNear {
    rho_inf: Result<Option<Algebraic>, String>,
    phase: Result<poly::advanced::plane::PhaseErrors, String>,
}

impl FarAndNear {
    /// From the report already made (the phase series need only whether the
    /// first interval's pair lies on the circle).
    pub(crate) fn of(
        derivation: &poly::Derivation,
        params: &poly::Params,
        report: &StabilityReport,
    ) -> FarAndNear {
        let on_circle = report
            .intervals
            .first()
            .is_some_and(|i| i.lo.sign().is_eq() && i.class == poly::RootClass::Harmonic);
        FarAndNear {
            rho_inf: derivation.rho_inf(params).map_err(|e| e.message().to_owned()),
            phase: derivation
                .phase_errors_given(params, on_circle)
                .map_err(|e| e.message().to_owned()),
        }
    }

    pub(crate) fn add_json(&self, v: &mut Value) {
        match &self.rho_inf {
            Ok(r) => v["rho_inf"] = json!(r.as_ref().map(number_json)),
            Err(e) => {
                v["rho_inf"] = Value::Null;
                v["rho_inf_note"] = json!(e);
            }
        }
        let term = |t: &Option<poly::advanced::plane::LeadingTerm>| {
            (
                json!(t.as_ref().map(|t| t.order)),
                json!(t.as_ref().map(|t| {
                    let value = poly::advanced::field::approx(&t.constant, &fine());
                    json!({ "exact": t.constant.to_string(), "value": num_traits::ToPrimitive::to_f64(&value) })
                })),
            )
        };
        match &self.phase {
            Ok(p) => {
                (v["dispersion_order"], v["dispersion_constant"]) = term(&p.dispersion);
                (v["dissipation_order"], v["dissipation_constant"]) = term(&p.dissipation);
            }
            Err(e) => {
                for k in [
                    "dispersion_order",
                    "dispersion_constant",
                    "dissipation_order",
                    "dissipation_constant",
                ] {
                    v[k] = Value::Null;
                }
                v["phase_errors_note"] = json!(e);
            }
        }
    }

    pub(crate) fn text(&self, names: &mut Names) -> String {
        let mut s = String::from("\n");
        match &self.rho_inf {
            Ok(Some(r)) => {
                let _ =
                    writeln!(s, "spectral radius as Phi -> infinity (rho_inf): {}", names.show(r));
            }
            Ok(None) => {
                s += "spectral radius as Phi -> infinity: unbounded (a root tends to infinity)\n"
            }
            Err(e) => {
                let _ = writeln!(s, "rho_inf: not available ({e})");
            }
        }
        match &self.phase {
            Ok(p) => {
                match &p.dispersion {
                    Some(t) => {
                        let _ = writeln!(
                            s,
                            "dispersion: Phi - Psi = {} Phi^{} + ... (order {})",
                            t.constant,
                            t.order + 1,
                            t.order
                        );
                    }
                    None => s += "dispersion: none (the phase is exact)\n",
                }
                match &p.dissipation {
                    Some(t) => {
                        let _ = writeln!(
                            s,
                            "dissipation: 1 - |z| = {} Phi^{} + ... (order {})",
                            t.constant,
                            t.order + 1,
                            t.order
                        );
                    }
                    None => s += "dissipation: none (|z| = 1 near Phi = 0)\n",
                }
            }
            Err(e) => {
                let _ = writeln!(s, "dispersion and dissipation: not available ({e})");
            }
        }
        s
    }
}

/// 1e-15, the width the issue asks isolating intervals to be narrowed to.
pub(crate) fn fine() -> Q {
    static FINE: std::sync::LazyLock<Q> =
        std::sync::LazyLock::new(|| Q::new(1.into(), num_traits::pow(10.into(), 15)));
    FINE.clone()
}

/// One exact number rendered once: the same critical point stands in a
/// report's class changes, intervals and critical points, and refining a
/// root of a large polynomial to 1e-15 is the costly part of a document.
pub(crate) struct Rendered {
    value: f64,
    exact: String,
    /// The number refined to width ≤ 1e-15, for its decimal and interval
    /// (the limit's detail alone shows them).
    fine: Algebraic,
}

/// The numbers of one [`fingerprint`], each with its rendering.
type Bucket = Vec<(Algebraic, std::rc::Rc<Rendered>)>;

thread_local! {
    /// Rendered numbers by [`fingerprint`], each bucket checked by
    /// [`Algebraic::same_form`].
    static RENDERED: std::cell::RefCell<HashMap<u64, Bucket>> =
        std::cell::RefCell::new(HashMap::new());
}

/// A cheap hash of a number's form: the lowest words of its interval's
/// ends (no copy, no hashing of whole big integers; a collision only costs
/// a comparison in the bucket).
fn fingerprint(a: &Algebraic) -> u64 {
    let (lo, hi) = a.ends();
    [lo.numer(), lo.denom(), hi.numer(), hi.denom()].iter().fold(0u64, |h, x| {
        let word = x.iter_u64_digits().next().unwrap_or(0)
            ^ (u64::from(num_traits::Signed::is_negative(*x)) << 63);
        (h.rotate_left(5) ^ word).wrapping_mul(0x517c_c1b7_2722_0a95)
    })
}

/// Empties the cache of rendered numbers: a front end's call starts from
/// nothing, so its time is the whole work (`api::stability`).
pub(crate) fn forget_rendered() {
    RENDERED.with(|c| c.borrow_mut().clear());
}

pub(crate) fn render(a: &Algebraic) -> std::rc::Rc<Rendered> {
    let key = fingerprint(a);
    let hit = RENDERED.with(|c| {
        c.borrow()
            .get(&key)
            .and_then(|bucket| bucket.iter().find(|(b, _)| b.same_form(a)).map(|(_, r)| r.clone()))
    });
    if let Some(r) = hit {
        return r;
    }
    let (fine_a, value) = super::exact::narrowed_with_value(a, &fine());
    let r = std::rc::Rc::new(Rendered { value, exact: fine_a.describe("Phi"), fine: fine_a });
    RENDERED.with(|c| {
        let mut c = c.borrow_mut();
        if c.len() > 4096 {
            c.clear();
        }
        c.entry(key).or_default().push((a.clone(), r.clone()));
    });
    r
}

/// The f64 nearest the exact number (correctly rounded).
pub(crate) fn to_f64(a: &Algebraic) -> f64 {
    render(a).value
}

/// Exact text: the closed form, else the defining polynomial in Phi and an
/// isolating interval of width at most 1e-15.
pub(crate) fn exact(a: &Algebraic) -> String {
    render(a).exact.clone()
}

pub(crate) fn number_json(a: &Algebraic) -> Value {
    let r = render(a);
    let (lo, hi) = r.fine.interval();
    json!({
        "value": r.value,
        "exact": r.exact,
        // Width ≤ 1e-15: one sign decides between two neighbouring decimals.
        "decimal": r.fine.to_decimal(15),
        "defining_poly": a.defining_poly().to_string_in("Phi"),
        "interval": [lo.to_string(), hi.to_string()],
    })
}

/// The JSON document of a stability report.
pub(crate) fn to_json(
    name: &str,
    params: &[(String, Q)],
    chi: &poly::Poly,
    r: &StabilityReport,
) -> Value {
    let params: serde_json::Map<String, Value> =
        params.iter().map(|(n, v)| (n.clone(), json!(v.to_string()))).collect();
    json!({
        "method": name,
        "params": params,
        "charpoly": chi.to_string(),
        "degree": r.degree,
        "stability": r.stability.name(),
        "phi_max": r.phi_max().map(to_f64),
        "phi_max_exact": r.phi_max().map(exact),
        "phi_max_detail": r.phi_max().map(number_json),
        "bounded_at_phi_max": r.bounded_at_phi_max(),
        "boundary": r.boundary().map(|b| b.name()),
        "boundedness_from": if r.from_transition_matrix { "transition_matrix" } else { "charpoly" },
        "class_changes": r.class_changes.iter().map(|c| json!({
            "phi": to_f64(&c.at),
            "phi_exact": exact(&c.at),
            "from": c.from.name(),
            "to": c.to.name(),
            "at": c.at_class.map(|k| k.name()),
        })).collect::<Vec<_>>(),
        "intervals": r.intervals.iter().map(|i| json!({
            "lo": to_f64(&i.lo),
            "lo_exact": exact(&i.lo),
            "hi": i.hi.as_ref().map(to_f64),
            "hi_exact": i.hi.as_ref().map(exact),
            "class": i.class.name(),
            "sample_phi": i.sample.to_string(),
            "roots_inside": i.counts.inside,
            "roots_on": i.counts.on,
            "roots_outside": i.counts.outside,
        })).collect::<Vec<_>>(),
        "stable_intervals": r.stable_intervals.iter().map(|i| json!({
            "lo_exact": exact(&i.lo),
            "lo_closed": i.lo_closed,
            "hi_exact": i.hi.as_ref().map(exact),
            "hi_closed": i.hi_closed,
        })).collect::<Vec<_>>(),
        "marginal": r.marginal.as_ref().map(|m| json!({
            "coefficient": m.coefficient.to_string(),
            "power": m.power,
            "growth_threshold": m.threshold.to_string(),
            "practical_phi_max_exact": m.practical_phi_max.as_ref().map(exact),
            "practical_phi_max": m.practical_phi_max.as_ref().map(to_f64),
        })),
        "critical_points": r.critical_points.iter().map(|p| json!({
            "phi": to_f64(&p.at),
            "phi_exact": exact(&p.at),
            "conditions": p.conditions.iter().map(|c| c.name()).collect::<Vec<_>>(),
            "bounded": p.bounded,
        })).collect::<Vec<_>>(),
    })
}

/// Short exact-plus-decimal renderings for people. A number without a
/// closed form is shown by its decimals and a name (r1, r2, … in the order
/// met), and each name is defined once, at the end: AB8's limit is a root
/// of a degree-20 polynomial with 60-digit coefficients, and the report
/// names it at every interval it bounds.
#[derive(Default)]
pub(crate) struct Names {
    roots: Vec<Algebraic>,
}

impl Names {
    fn show(&mut self, a: &Algebraic) -> String {
        let closed = a.closed_form();
        let dec = a.to_decimal(15);
        match closed {
            Some(c) if c == dec.trim_end_matches('0').trim_end_matches('.') => c,
            Some(c) => format!("{c} ≈ {dec}"),
            None => {
                let k = match self.roots.iter().position(|r| r == a) {
                    Some(k) => k,
                    None => {
                        self.roots.push(a.clone());
                        self.roots.len() - 1
                    }
                };
                format!("{dec} (r{})", k + 1)
            }
        }
    }

    /// "where r1 = root of … in [lo, hi]", the interval narrower than 1e-15.
    fn definitions(&self) -> String {
        let mut s = String::new();
        if self.roots.is_empty() {
            return s;
        }
        let _ = writeln!(
            s,
            "
where"
        );
        for (k, r) in self.roots.iter().enumerate() {
            let (lo, hi) = r.refine(&fine()).interval();
            let _ = writeln!(
                s,
                "  r{} = root of {} in [{lo}, {hi}]",
                k + 1,
                r.defining_poly().to_string_in("Phi")
            );
        }
        s
    }
}

pub(crate) fn text(
    name: &str,
    params: &[(String, Q)],
    chi: &poly::Poly,
    r: &StabilityReport,
    names: &mut Names,
) -> String {
    let mut s = String::new();
    let given: Vec<String> = params.iter().map(|(n, v)| format!("{n} = {v}")).collect();
    let _ = writeln!(
        s,
        "method {name}{}",
        if given.is_empty() { String::new() } else { format!("   ({})", given.join(", ")) }
    );
    let _ = writeln!(s, "chi(z) = {chi}\n");
    match &r.stability {
        Stability::BoundedForAllPhi => {
            let _ = writeln!(s, "bounded for every Phi > 0");
        }
        Stability::UnboundedForAllPhi => {
            let _ = writeln!(s, "unbounded for every Phi > 0 (no stability limit)");
        }
        Stability::UnstableNearZero => {
            let _ = writeln!(s, "unstable for every small Phi > 0; bounded only further out");
        }
        Stability::Limited { phi_max: m, bounded_at_phi_max, boundary: b } => {
            let _ = writeln!(s, "stable for 0 < Phi < {}", names.show(m));
            let at = if *bounded_at_phi_max { "bounded" } else { "unbounded" };
            let _ = writeln!(s, "at the limit: {b}; the limit itself is {at}");
        }
        // Not from a derivation's analysis, which has P; kept total.
        Stability::UndecidedAt { at, boundary: b } => {
            let _ = writeln!(s, "stable for 0 < Phi < {}", names.show(at));
            let _ = writeln!(s, "at the limit: {b}; the limit itself is undecided without P");
        }
    }
    s += &classes(r, names);
    s + &extras(r, names)
}

/// Disjoint stable intervals and the marginal-verdict note, when present.
pub(crate) fn extras(r: &StabilityReport, names: &mut Names) -> String {
    let mut s = String::new();
    let near_zero = r.stable_intervals.first().is_some_and(|i| i.lo.sign().is_eq());
    let further: Vec<_> = r.stable_intervals.iter().skip(usize::from(near_zero)).collect();
    if !further.is_empty() {
        let _ = writeln!(s, "\nbounded further out:");
        for i in further {
            let hi = i.hi.as_ref().map_or("inf".to_owned(), |h| names.show(h));
            let (l, rb) =
                (if i.lo_closed { "[" } else { "(" }, if i.hi_closed { "]" } else { ")" });
            let _ = writeln!(s, "  {l}{}, {hi}{rb}", names.show(&i.lo));
        }
    }
    if let Some(m) = &r.marginal {
        let _ = writeln!(
            s,
            "\nnote: the verdict hangs on a tiny term: |z|^2 - 1 = c*Phi^{} + ... with c = {} \
             (|c| < 1e-12, below the rounding of 16-digit coefficients)",
            m.power,
            names.show(&poly::Algebraic::from_rational(m.coefficient.clone()))
        );
        let limit = m
            .practical_phi_max
            .as_ref()
            .map_or("none (within it for every Phi)".to_owned(), |l| names.show(l));
        let _ = writeln!(
            s,
            "practical limit for growth per step <= 1 + {}: Phi <= {limit}",
            m.threshold
        );
    }
    s
}

pub(crate) fn classes(r: &StabilityReport, names: &mut Names) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "\nroot classes over Phi > 0:");
    for (k, i) in r.intervals.iter().enumerate() {
        let hi = i.hi.as_ref().map_or("inf".to_owned(), |h| names.show(h));
        let _ = writeln!(s, "  ({}, {hi}): {}", names.show(&i.lo), i.class);
        if let Some(c) = r.class_changes.get(k) {
            let at = c.at_class.map_or("not computed".to_owned(), |k| k.name().to_owned());
            let _ = writeln!(s, "  at Phi = {}: {at}", names.show(&c.at));
        }
    }
    s
}
