//! Exact ranges in Φ > 0: where a polynomial in Φ is positive or negative,
//! and which root class (section 4) a method shows on each piece of the
//! positive axis. Every boundary is an exact algebraic number from
//! `poly::Algebraic` / `poly::advanced::stability`; no float decides anything here.

use std::cmp::Ordering;
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

use poly::StabilityReport;
use poly::{Algebraic, Poly, RootClass, Sym, UPoly, Q};

use super::exact::{at_phi, p_q, paper};
use crate::load::builtin_derivation;

/// An exact number written for a reader: the closed form when known, with
/// its decimal value ("sqrt(2) ≈ 1.4142", "2").
pub(crate) fn show(a: &Algebraic) -> String {
    match (a.is_rational(), a.closed_form()) {
        (true, Some(c)) => c,
        (false, Some(c)) => format!("{c} ≈ {}", a.to_decimal(4)),
        (_, None) => {
            format!("{} (the root of {})", a.to_decimal(4), a.defining_poly().to_string_in("Phi"))
        }
    }
}

/// The positive real roots of a polynomial in Φ, ascending.
pub(crate) fn positive_roots(p: &Poly) -> Vec<Algebraic> {
    let u: UPoly = p.to_upoly(Sym::phi()).expect("a polynomial in Phi only");
    if u.is_zero() {
        return Vec::new();
    }
    let mut roots = Algebraic::positive_roots(&u);
    roots.sort();
    roots
}

/// A rational in (0, a) for a positive `a`.
fn rational_below(a: &Algebraic) -> Q {
    Algebraic::rational_between(&Algebraic::zero(), a)
}

/// A rational above `a`.
fn rational_above(a: &Algebraic) -> Q {
    a.refine(&poly::q(1, 16)).interval().1 + poly::q(1, 1)
}

/// One piece of Φ > 0: an open interval (lo, hi) or a single point.
#[derive(Clone, Debug)]
pub(crate) enum Piece {
    /// lo < Φ < hi; `None` for 0 (lo) or ∞ (hi).
    Open(Option<Algebraic>, Option<Algebraic>),
    /// Φ = the number.
    Point(Algebraic),
}

impl Piece {
    /// The piece in words: "0 < Φ < sqrt(2) ≈ 1.4142", "Φ = 2".
    pub(crate) fn text(&self) -> String {
        match self {
            Piece::Open(None, None) => "every Φ > 0".to_owned(),
            Piece::Open(None, Some(h)) => format!("0 < Φ < {}", show(h)),
            Piece::Open(Some(l), None) => format!("Φ > {}", show(l)),
            Piece::Open(Some(l), Some(h)) => format!("{} < Φ < {}", show(l), show(h)),
            Piece::Point(a) => format!("Φ = {}", show(a)),
        }
    }

    /// A rational inside an open piece.
    pub(crate) fn sample(&self) -> Option<Q> {
        match self {
            Piece::Open(None, None) => Some(poly::q(1, 1)),
            Piece::Open(None, Some(h)) => Some(rational_below(h)),
            Piece::Open(Some(l), None) => Some(rational_above(l)),
            Piece::Open(Some(l), Some(h)) => Some(Algebraic::rational_between(l, h)),
            Piece::Point(a) => a.as_rational().cloned(),
        }
    }
}

/// The open pieces of Φ > 0 cut at `cuts` (ascending), with the cut points
/// in between.
pub(crate) fn pieces(cuts: &[Algebraic]) -> Vec<Piece> {
    let mut out = Vec::new();
    let mut lo: Option<Algebraic> = None;
    for c in cuts {
        out.push(Piece::Open(lo.clone(), Some(c.clone())));
        out.push(Piece::Point(c.clone()));
        lo = Some(c.clone());
    }
    out.push(Piece::Open(lo, None));
    out
}

/// Where a polynomial in Φ is positive and where negative, in words:
/// "`pos` for 0 < Φ < 2; `neg` for Φ > 2" (or "`pos` for every Φ > 0").
pub(crate) fn sign_text(p: &Poly, pos: &str, neg: &str) -> String {
    if p.symbols().iter().any(|s| *s != Sym::phi()) {
        return format!("{pos} where {p} > 0; {neg} where {p} < 0");
    }
    let roots = positive_roots(p);
    let mut parts = Vec::new();
    for piece in pieces(&roots) {
        let Piece::Open(..) = piece else { continue };
        let x = piece.sample().expect("open pieces have samples");
        let value = at_phi(p, &x);
        let word = match value.cmp(&poly::q(0, 1)) {
            Ordering::Greater => pos,
            Ordering::Less => neg,
            Ordering::Equal => "zero",
        };
        parts.push(format!("{word} for {}", piece.text()));
    }
    parts.join("; ")
}

/// The exact stability report of a built-in method, computed once per
/// process.
#[track_caller]
pub(crate) fn report(method: &str) -> StabilityReport {
    static CACHE: OnceLock<Mutex<HashMap<String, StabilityReport>>> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    if let Some(r) = cache.lock().expect("cache lock").get(method) {
        return r.clone();
    }
    let d = builtin_derivation(method);
    let r =
        d.stability(&poly::Params::new()).unwrap_or_else(|e| panic!("stability of {method}: {e}"));
    cache.lock().expect("cache lock").insert(method.to_owned(), r.clone());
    r
}

/// A method's root class on every piece of Φ > 0: the open intervals of
/// constant class and the change points between them (a point's class is
/// `None` when poly::advanced::stability did not decide it).
pub(crate) fn class_map(method: &str) -> Vec<(Piece, Option<RootClass>)> {
    let r = report(method);
    let mut out = Vec::new();
    for (k, interval) in r.intervals.iter().enumerate() {
        let lo = (interval.lo.sign() == Ordering::Greater).then(|| interval.lo.clone());
        out.push((Piece::Open(lo, interval.hi.clone()), Some(interval.class)));
        if let Some(change) = r.class_changes.get(k) {
            out.push((Piece::Point(change.at.clone()), change.at_class));
        }
    }
    out
}

/// A class map in words: "damped_oscillation for 0 < Φ < ...; ...".
pub(crate) fn class_map_text(map: &[(Piece, Option<RootClass>)]) -> String {
    map.iter()
        .filter_map(|(piece, class)| {
            class.map(|c| format!("{} for {}", class_words(c), piece.text()))
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// The built-ins whose class maps cover the paper's methods (the `_matrix`
/// twins have the same χ).
pub(crate) const METHODS: [&str; 8] = [
    "standard_euler",
    "damped_euler",
    "false_euler",
    "verlet",
    "standard_heun",
    "false_heun",
    "semi_false_heun",
    "damped_euler_d",
];

/// Classes reached by the paper's methods (`damped_euler_d` excluded: it has
/// a free parameter) that are not in `known`, with where they occur.
pub(crate) fn classes_outside(known: &[RootClass]) -> String {
    let mut out = Vec::new();
    for method in METHODS.iter().filter(|m| **m != "damped_euler_d") {
        for (piece, class) in class_map(method) {
            if let Some(c) = class {
                if !known.contains(&c) {
                    out.push(format!("{}: {} for {}", title(method), class_words(c), piece.text()));
                }
            }
        }
    }
    if out.is_empty() {
        "none".to_owned()
    } else {
        out.join("; ")
    }
}

/// Where the paper's second-order methods have a complex pair with negative
/// real part (Ψ > π/2), so that arctan(b1/a1) is off by π.
pub(crate) fn negative_real_part_text() -> String {
    let mut out = Vec::new();
    for method in METHODS.iter().filter(|m| !matches!(**m, "damped_euler_d" | "verlet")) {
        let d = builtin_derivation(method);
        let (p, q) = p_q(&d);
        let disc = &q - &(&p * &p);
        let mut cuts = positive_roots(&p);
        cuts.extend(positive_roots(&disc));
        cuts.sort();
        cuts.dedup();
        for piece in pieces(&cuts) {
            let Piece::Open(..) = piece else { continue };
            let x = piece.sample().expect("open piece");
            let zero = poly::q(0, 1);
            if at_phi(&p, &x) < zero && at_phi(&disc, &x) > zero {
                out.push(format!("{} for {}", title(method), piece.text()));
            }
        }
    }
    out.join("; ")
}

/// The finding of an "always" claim: every piece of Φ > 0 is a case, which
/// holds when its class satisfies `ok`. `stated` is the range the paper
/// states for the claim, as a polynomial in `Poly::parse` syntax whose
/// smallest positive root bounds it (`"Phi^2 - 4"` for section 7's Φ² = 4);
/// `None` when the paper states no narrower range, so that the wording's
/// "always" is the assertion. Returns the finding, the class map in words
/// and the pieces where `ok` fails.
pub(crate) fn always(
    method: &str,
    ok: impl Fn(RootClass) -> bool,
    stated: Option<&str>,
) -> (crate::paper::finding::Finding, String, String) {
    use crate::paper::finding::{Finding, Scope};
    let map = class_map(method);
    let bound = stated.map(|text| {
        positive_roots(&paper(text))
            .into_iter()
            .next()
            .unwrap_or_else(|| panic!("stated range {text:?} has no positive root"))
    });
    let inside = |piece: &Piece| match (&bound, piece) {
        (None, _) => true,
        (Some(b), Piece::Open(_, Some(h))) => h <= b,
        (Some(_), Piece::Open(_, None)) => false,
        (Some(b), Piece::Point(a)) => a < b,
    };
    let failing: Vec<String> = map
        .iter()
        .filter_map(|(piece, class)| {
            class.filter(|c| !ok(*c)).map(|c| format!("{} for {}", class_words(c), piece.text()))
        })
        .collect();
    let outside = match (stated, &bound) {
        (Some(text), Some(b)) => format!(
            "the paper states 0 < Φ < {} (where {text} first vanishes); only \"always\" reaches beyond",
            show(b),
        ),
        _ => String::new(),
    };
    let finding = Finding::scoped(map.iter().filter_map(|(piece, class)| {
        class.map(|c| {
            let scope = if inside(piece) { Scope::Stated } else { Scope::wording(outside.clone()) };
            (format!("{}: {}", piece.text(), class_words(c)), ok(c), scope)
        })
    }));
    (finding, class_map_text(&map), failing.join("; "))
}

/// A root class in words for running prose: "damped oscillation", not
/// `damped_oscillation`.
pub(crate) fn class_words(c: RootClass) -> String {
    c.to_string().replace('_', " ")
}

/// A method's name in words: "False Euler", "Semi-False Heun".
pub(crate) fn title(name: &str) -> String {
    name.split('_')
        .map(|w| {
            let mut c = w.chars();
            c.next().map(|f| f.to_uppercase().collect::<String>() + c.as_str()).unwrap_or_default()
        })
        .collect::<Vec<_>>()
        .join(" ")
        .replace("Semi False", "Semi-False")
}

/// Φ_max of a stability report: the largest Φ₀ with every 0 < Φ < Φ₀
/// bounded (`None` when there is none, or when every Φ is bounded).
pub(crate) fn limit_of(report: &StabilityReport) -> Option<Algebraic> {
    report.phi_max().cloned()
}

/// Φ_max of a built-in, in words ("2", "sqrt(2) ≈ 1.4142", "none").
pub(crate) fn limit_text(method: &str) -> String {
    limit_of(&report(method)).as_ref().map(show).unwrap_or_else(|| "none".to_owned())
}
