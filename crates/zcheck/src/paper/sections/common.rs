//! Shared machinery of the section modules: a claim collector, the paper's
//! equations parsed as exact polynomials, symbolic execution of a method's
//! step, and the exact range analysis of "always" statements.
//!
//! Every transcription is a pair: what the paper prints (Unicode, for the
//! report) and the same expression in `Poly::parse` syntax (for the
//! comparison). The comparison itself is always exact.

use std::fmt::Write as _;

use poly::advanced::Operand;
use poly::{Derivation, Method, Poly, PolyMatrix, Sym, Q};

use super::exact::{at_phi, p_q, paper};
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::Finding;

/// The claims of one section, in the paper's order.
pub(crate) struct Section {
    section: &'static str,
    prefix: &'static str,
    claims: Vec<Claim>,
}

impl Section {
    /// An empty section: `section` is the paper's numbering ("5", "A"),
    /// `prefix` starts every claim id ("sec05", "appA").
    pub(crate) fn new(section: &'static str, prefix: &'static str) -> Section {
        Section { section, prefix, claims: Vec::new() }
    }

    /// Records one claim.
    pub(crate) fn push(
        &mut self,
        key: &str,
        statement: impl Into<String>,
        derived: impl Into<String>,
        finding: Finding,
        evidence: impl Into<String>,
    ) {
        self.claims.push(Claim::new(
            format!("{}.{key}", self.prefix),
            self.section.to_owned(),
            statement.into(),
            roots_once(&derived.into()),
            finding,
            roots_once(&evidence.into()),
        ));
    }

    /// Sets the corrected line of the claim recorded last (an erratum's
    /// printed line as it should read, computed by the section).
    pub(crate) fn correct(&mut self, corrected: impl Into<String>) {
        if let Some(c) = self.claims.last_mut() {
            c.corrected = Some(corrected.into());
        }
    }

    /// The derived text of the claim recorded last (empty when none).
    pub(crate) fn last_derived(&self) -> String {
        self.claims.last().map(|c| c.derived.clone()).unwrap_or_default()
    }

    /// Adds to the evidence of the claim recorded last.
    pub(crate) fn append_evidence(&mut self, more: &str) {
        if let Some(c) = self.claims.last_mut() {
            c.evidence.push_str(more);
        }
    }

    /// The claims collected.
    pub(crate) fn finish(self) -> Vec<Claim> {
        self.claims
    }
}

/// A text with each "(the root of ...)" explanation kept at its first
/// occurrence only: an irrational boundary is named once, then by its value.
pub(crate) fn roots_once(text: &str) -> String {
    const OPEN: &str = " (the root of ";
    let mut out = String::new();
    let mut seen: Vec<String> = Vec::new();
    let mut rest = text;
    while let Some(k) = rest.find(OPEN) {
        out.push_str(&rest[..k]);
        let after = &rest[k + OPEN.len()..];
        // The explanation ends at the parenthesis that closes OPEN.
        let mut depth = 1;
        let end = after
            .char_indices()
            .find_map(|(i, ch)| {
                match ch {
                    '(' => depth += 1,
                    ')' => depth -= 1,
                    _ => {}
                }
                (depth == 0).then_some(i)
            })
            .unwrap_or(after.len().saturating_sub(1));
        let inner = &after[..end];
        if !seen.iter().any(|x| x == inner) {
            seen.push(inner.to_owned());
            out.push_str(OPEN);
            out.push_str(inner);
            out.push(')');
        }
        rest = &after[(end + 1).min(after.len())..];
    }
    out.push_str(rest);
    out
}

/// The symbol of a state variable (or its history) in symbolic execution:
/// `y` for the start value, `y_lag1` for `y@1`.
pub(crate) fn start_sym(m: &Method, op: Operand) -> Poly {
    match op {
        Operand::Start { var, lag: 0 } => Poly::var(&m.state()[var]),
        Operand::Start { var, lag } => Poly::var(&format!("{}_lag{lag}", m.state()[var])),
        Operand::Stmt(_) | Operand::Unknown(_) => Poly::var(&m.operand_name(op)),
    }
}

/// Symbolic execution of one step: the value of every assignment, in program
/// order, as a polynomial in the start values (`v`, `y`, `y@1`) and the
/// parameters, named by the variable it writes.
pub(crate) fn stage_values(m: &Method) -> Vec<(String, Poly)> {
    let mut values: Vec<Poly> = Vec::with_capacity(m.assigns().len());
    for a in m.assigns() {
        let mut acc = Poly::zero();
        for (op, c) in &a.terms {
            let src = match *op {
                Operand::Stmt(t) => values[t].clone(),
                start => start_sym(m, start),
            };
            acc += &(c * &src);
        }
        values.push(acc);
    }
    m.assigns().iter().map(|a| m.target_name(a).to_owned()).zip(values).collect()
}

/// The value of the last assignment to `name` in one step.
#[track_caller]
pub(crate) fn stage_value(m: &Method, name: &str) -> Poly {
    stage_values(m)
        .into_iter()
        .rev()
        .find(|(n, _)| n == name)
        .map(|(_, p)| p)
        .unwrap_or_else(|| panic!("{} assigns no {name}", m.name()))
}

/// One printed line of the paper: as printed, and in `Poly::parse` syntax.
#[derive(Clone, Copy)]
pub(crate) struct Printed {
    /// As the paper prints it.
    pub printed: &'static str,
    /// The right-hand side in `Poly::parse` syntax.
    pub parse: &'static str,
}

/// Compares printed right-hand sides with the step values of `method`
/// (the value assigned to `name`): returns (all equal, derived listing,
/// differences).
pub(crate) fn compare_stages(
    method: &Method,
    lines: &[(&str, Printed)],
) -> (Finding, String, String) {
    let mut derived = String::new();
    let mut printed = String::new();
    let mut diffs = String::new();
    for (name, line) in lines {
        let want = stage_value(method, name);
        let got = paper(line.parse);
        let _ = write!(derived, "{}{name} = {want}", if derived.is_empty() { "" } else { "; " });
        let _ = write!(printed, "{}{name} = {got}", if printed.is_empty() { "" } else { "; " });
        if want != got {
            let _ = write!(
                diffs,
                "{}printed `{}` expands to {got}, but the step gives {name} = {want} (difference {})",
                if diffs.is_empty() { "" } else { "; " },
                line.printed,
                &got - &want,
            );
        }
    }
    (Finding::same(printed, &derived), derived, diffs)
}

/// A z-domain row of the paper, `x = a v z⁻¹ + b y z⁻¹`, as the printed
/// text and the coefficients of v and y in `Poly::parse` syntax.
pub(crate) struct ZRow {
    /// As the paper prints it.
    pub printed: &'static str,
    /// The coefficient of `v z⁻¹`.
    pub v: &'static str,
    /// The coefficient of `y z⁻¹`.
    pub y: &'static str,
}

/// Compares printed z-domain rows with the rows of the derived transition
/// matrix P (state order v, y): row i of the z-domain equations is
/// `x_i = Σ_j P_ij x_j z⁻¹`.
pub(crate) fn compare_z_rows(d: &Derivation, rows: &[ZRow]) -> (Finding, String, String) {
    let p = &d.transition_matrix();
    let names = d.method().state();
    let mut derived = Vec::new();
    let mut printed = Vec::new();
    let mut diffs = Vec::new();
    for (i, row) in rows.iter().enumerate() {
        let want = [p[(i, 0)].clone(), p[(i, 1)].clone()];
        let got = [paper(row.v), paper(row.y)];
        derived.push(format!("{} = ({}) v z^-1 + ({}) y z^-1", names[i], want[0], want[1]));
        printed.push(format!("{} = ({}) v z^-1 + ({}) y z^-1", names[i], got[0], got[1]));
        for (k, var) in ["v", "y"].iter().enumerate() {
            if want[k] != got[k] {
                diffs.push(format!(
                    "row `{}`: the coefficient of {var} z^-1 is printed as {}, derived {}",
                    row.printed, got[k], want[k]
                ));
            }
        }
    }
    let derived = derived.join("; ");
    (Finding::same(printed.join("; "), &derived), derived, diffs.join("; "))
}

/// χ written in the paper's form `z^2 - 2*(p)*z + (q)`.
pub(crate) fn chi_text(d: &Derivation) -> String {
    match d.p_q() {
        Some((p, q)) => format!("z^2 - 2*({p})*z + ({q})"),
        None => d.charpoly().to_string(),
    }
}

/// The transition matrix as text, row by row.
pub(crate) fn matrix_text(m: &PolyMatrix) -> String {
    let rows: Vec<String> = (0..m.rows())
        .map(|i| {
            let r: Vec<String> = m.row(i).iter().map(ToString::to_string).collect();
            format!("[{}]", r.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

/// A polynomial truncated to powers of Φ below `k`.
pub(crate) fn truncate(p: &Poly, k: usize) -> Poly {
    let mut c = p.coeffs_in(Sym::phi());
    c.truncate(k);
    Poly::from_coeffs_in(Sym::phi(), &c)
}

/// A rational shown as a decimal with `digits` places (at most 18), rounded
/// half away from zero; exact, no float involved.
pub(crate) fn q_decimal(x: &Q, digits: u32) -> String {
    use num_traits::Signed;
    let scale = poly::q(10i64.pow(digits), 1);
    let rounded = (x.abs() * &scale + poly::q(1, 2)).floor().to_integer().to_string();
    let negative = x.is_negative() && rounded.chars().any(|c| c != '0');
    let padded = format!("{rounded:0>width$}", width = digits as usize + 1);
    let (int, frac) = padded.split_at(padded.len() - digits as usize);
    let sign = if negative { "-" } else { "" };
    if digits == 0 {
        format!("{sign}{int}")
    } else {
        format!("{sign}{int}.{frac}")
    }
}

/// A float rounded for a report: never a raw float.
pub(crate) fn fixed(x: f64, digits: usize) -> String {
    let s = format!("{x:.digits$}");
    // "-0.000" reads as a sign error; print it as zero.
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_owned()
    } else {
        s
    }
}

/// Ψ(Φ) of a second-order method at one Φ in floating point: the argument
/// of the upper root, `atan2(sqrt(q - p²), p)`, when the roots are complex.
pub(crate) fn psi_f64(d: &Derivation, phi: f64) -> Option<f64> {
    PsiF64::new(d).at(phi)
}

/// Ψ(Φ) in floating point with p and q converted to f64 once, for sweeps.
pub(crate) struct PsiF64 {
    p: Vec<f64>,
    q: Vec<f64>,
}

impl PsiF64 {
    /// The f64 coefficients of p and q of a second-order method.
    pub(crate) fn new(d: &Derivation) -> PsiF64 {
        let (p, q) = p_q(d);
        PsiF64 { p: f64_coeffs(&p), q: f64_coeffs(&q) }
    }

    /// Ψ at Φ, when the roots are complex.
    pub(crate) fn at(&self, phi: f64) -> Option<f64> {
        let horner = |c: &[f64]| c.iter().rev().fold(0.0, |acc, x| acc * phi + x);
        let (p, q) = (horner(&self.p), horner(&self.q));
        let s = q - p * p;
        (s > 0.0).then(|| s.sqrt().atan2(p))
    }
}

fn f64_coeffs(p: &Poly) -> Vec<f64> {
    use num_traits::ToPrimitive;
    p.coeffs_in(Sym::phi())
        .iter()
        .map(|c| c.as_constant().and_then(|c| c.to_f64()).expect("a polynomial in Phi only"))
        .collect()
}

/// A polynomial in Φ evaluated in floating point (Horner).
pub(crate) fn eval_f64(p: &Poly, phi: f64) -> f64 {
    check::sweep::HornerPoly::new(p, Sym::phi()).expect("a polynomial in Phi only").value(phi)
}

/// The canonical test oscillator of section 5 (v̇ = −ω0 y, ẏ = ω0 v) as the
/// matrix A in units of ω0, state order (v, y), in `Poly::parse` syntax.
pub(crate) const OSCILLATOR: [[&str; 2]; 2] = [["0", "-1"], ["1", "0"]];

/// How a method's transition matrix P must relate to the ODE matrix A.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Scheme {
    /// Standard Euler: P = I + ΦA exactly (section 4).
    Euler,
    /// Standard Heun on a linear system: P = I + ΦA + (ΦA)²/2 exactly.
    Heun,
    /// Any consistent method: P = I + ΦA + O(Φ²).
    Consistent,
}

/// The ODE matrix from its transcription.
pub(crate) fn ode_matrix(a: [[&str; 2]; 2]) -> PolyMatrix {
    PolyMatrix::from_rows(a.iter().map(|r| r.iter().map(|e| paper(e)).collect()).collect())
}

/// P − (I + ΦA [+ (ΦA)²/2]) for the scheme; zero (or O(Φ²) for
/// `Consistent`) when the method integrates the ODE A.
pub(crate) fn scheme_defect(d: &Derivation, a: &PolyMatrix, scheme: Scheme) -> PolyMatrix {
    let phi = Poly::sym(Sym::phi());
    let phi_a = a.map(|e| e * &phi);
    let mut model = PolyMatrix::identity(a.rows());
    for i in 0..a.rows() {
        for j in 0..a.cols() {
            model[(i, j)] = &model[(i, j)] + &phi_a[(i, j)];
        }
    }
    if scheme == Scheme::Heun {
        let sq = &phi_a * &phi_a;
        for i in 0..a.rows() {
            for j in 0..a.cols() {
                model[(i, j)] = &model[(i, j)] + &sq[(i, j)].scale(&poly::q(1, 2));
            }
        }
    }
    let p = &d.transition_matrix();
    let mut out = PolyMatrix::zeros(p.rows(), p.cols());
    for i in 0..p.rows() {
        for j in 0..p.cols() {
            let e = &p[(i, j)] - &model[(i, j)];
            out[(i, j)] = if scheme == Scheme::Consistent { truncate(&e, 2) } else { e };
        }
    }
    out
}

/// Whether every entry of a matrix is zero.
pub(crate) fn is_zero_matrix(m: &PolyMatrix) -> bool {
    (0..m.rows()).all(|i| m.row(i).iter().all(Poly::is_zero))
}

/// Records the claim that a section's printed ODE is the one its method
/// integrates.
pub(crate) fn ode_claim(
    s: &mut Section,
    method: &str,
    printed: &str,
    a: [[&str; 2]; 2],
    scheme: Scheme,
) {
    let d = builtin_derivation(method);
    let printed_a = ode_matrix(a);
    let defect = scheme_defect(&d, &printed_a, scheme);
    let ok = is_zero_matrix(&defect);
    let zero = PolyMatrix::zeros(defect.rows(), defect.cols());
    let canonical = scheme_defect(&d, &ode_matrix(OSCILLATOR), scheme);
    let rule = match scheme {
        Scheme::Euler => "P = I + ΦA exactly",
        Scheme::Heun => "P = I + ΦA + (ΦA)²/2 exactly",
        Scheme::Consistent => "P = I + ΦA + O(Φ²)",
    };
    let derived = format!(
        "{method}: P = {}; the printed ODE has A = {} (units of ω0, state v, y)",
        matrix_text(d.transition_matrix()),
        matrix_text(&printed_a)
    );
    let evidence = if ok {
        format!("{rule} holds for the printed A")
    } else {
        format!(
            "{rule} fails for the printed A (defect {} in the terms it checks); {}",
            matrix_text(&defect),
            if is_zero_matrix(&canonical) {
                "it holds for A = [[0, -1], [1, 0]], i.e. v̇ = −ω0 y, ẏ = ω0 v, the oscillator of \
                 section 5 that the section's own next lines use"
                    .to_owned()
            } else {
                "it fails for the canonical oscillator too".to_owned()
            }
        )
    };
    // The scheme's P for the printed A, less the derived P: zero when the
    // printed ODE is the one the method integrates.
    s.push(
        "ode",
        printed,
        derived,
        Finding::same(matrix_text(&defect), matrix_text(&zero)),
        evidence,
    );
    if !ok {
        s.correct(if is_zero_matrix(&canonical) {
            ode_text(&ode_matrix(OSCILLATOR))
        } else {
            "no oscillator fits: see the evidence".to_owned()
        });
    }
}

/// An ODE matrix over the state (v, y) as the paper writes it:
/// `v̇ = −ω0 y, ẏ = ω0 v`.
fn ode_text(a: &PolyMatrix) -> String {
    use num_traits::Signed;
    let names = ["v", "y"];
    let rows: Vec<String> = ["v̇", "ẏ"]
        .iter()
        .enumerate()
        .map(|(i, dot)| {
            let e = (0..2).fold(Poly::zero(), |acc, j| &acc + &(&a[(i, j)] * &Poly::var(names[j])));
            let negative = e.terms().all(|(_, c)| c.is_negative());
            let (sign, e) = if negative { ("−", -&e) } else { ("", e) };
            let body = if e.len() > 1 { format!("({e})") } else { e.to_string() };
            format!("{dot} = {sign}ω0 {body}")
        })
        .collect();
    rows.join(", ")
}

/// Records "the solution is always an unstable oscillation" (sections 5
/// and 9): the exact class map over every Φ > 0, no narrower range stated.
pub(crate) fn always_unstable_claim(s: &mut Section, method: &str) {
    use super::ranges;
    let (finding, map, failing) =
        ranges::always(method, |c| c == poly::RootClass::UnstableOscillation, None);
    let (p, q) = p_q(&builtin_derivation(method));
    let disc = &q - &(&p * &p);
    s.push(
        "always_unstable",
        "The solution is always an unstable oscillation.",
        map,
        finding,
        if failing.is_empty() {
            format!(
                "exact class map over all Φ > 0 (Sturm sequences on the discriminant and on χ(±1)): \
                 q − p² = {disc} and r² = q = {q}: {}; {}",
                ranges::sign_text(&disc, "a complex pair", "real roots"),
                ranges::sign_text(&(&q - &Poly::one()), "r > 1", "r < 1"),
            )
        } else {
            format!("exact class map: fails for {failing}")
        },
    );
}

/// Records a printed characteristic equation against the derived χ.
pub(crate) fn charpoly_claim(s: &mut Section, key: &str, method: &str, printed: &str, parse: &str) {
    let d = builtin_derivation(method);
    let got = paper(parse);
    let ok = got == *d.charpoly();
    let finding = Finding::same(&got, d.charpoly());
    let evidence = if ok {
        format!(
            "poly::derive({method}) gives χ by the z-domain determinant and by det(zI − P), \
             which agree; the printed equation, parsed, is the same polynomial"
        )
    } else {
        format!(
            "poly::derive({method}) gives {}; the printed equation differs by {}",
            d.charpoly(),
            &got - d.charpoly()
        )
    };
    s.push(key, printed, format!("χ(z) = {}", chi_text(&d)), finding, evidence);
}

/// Records printed intermediate values of one step against symbolic
/// execution of the method's program.
pub(crate) fn stages_claim(
    s: &mut Section,
    key: &str,
    method: &str,
    printed: &str,
    lines: &[(&str, Printed)],
) {
    let m = builtin_derivation(method).method().clone();
    let (finding, derived, diffs) = compare_stages(&m, lines);
    let evidence = if diffs.is_empty() {
        format!("symbolic execution of the {method} program (Appendix B) gives every printed value exactly")
    } else {
        format!("symbolic execution of the {method} program: {diffs}")
    };
    s.push(key, printed, derived, finding, evidence);
}

/// Records printed z-domain rows against the derived transition matrix.
pub(crate) fn z_rows_claim(s: &mut Section, method: &str, printed: &str, rows: &[ZRow]) {
    let d = builtin_derivation(method);
    let (finding, derived, diffs) = compare_z_rows(&d, rows);
    let evidence = if diffs.is_empty() {
        format!("the rows of P from poly::derive({method}) equal the printed coefficients exactly")
    } else {
        format!("poly::derive({method}): {diffs}")
    };
    s.push("z_rows", printed, derived, finding, evidence);
}

/// Records a printed r² against q (section 4: r1² = q for a conjugate pair).
pub(crate) fn r_squared_claim(s: &mut Section, method: &str, printed: &str, parse: &str) {
    let d = builtin_derivation(method);
    let (p, q) = p_q(&d);
    let ok = paper(parse) == q;
    let range = super::ranges::sign_text(
        &(&q - &(&p * &p)),
        "the roots are a conjugate pair",
        "they are real",
    );
    s.push(
        "r_squared",
        printed,
        format!("r² = q = {q} while {range}"),
        Finding::same(paper(parse), &q),
        format!(
            "for a conjugate pair z1·z2 = r² = q (section 4); q from poly::derive({method}) {} the printed r²",
            if ok { "equals" } else { "differs from" }
        ),
    );
}

/// Records printed eigenvalues `p ± j·sqrt(im²)` against χ: they are the
/// roots iff p is the derived p and im² = q − p².
pub(crate) fn eigen_claim(
    s: &mut Section,
    key: &str,
    method: &str,
    printed: &str,
    p_text: &str,
    im_sq: &str,
) {
    let d = builtin_derivation(method);
    let (p, q) = p_q(&d);
    let disc = &q - &(&p * &p);
    let ok_p = paper(p_text) == p;
    let ok_im = paper(im_sq) == disc;
    let range = super::ranges::sign_text(
        &disc,
        "they are a conjugate pair",
        "the same formula gives two real roots",
    );
    let evidence = match (ok_p, ok_im) {
        (true, true) => format!(
            "z = p ± j·sqrt(q − p²) solves z² − 2pz + q = 0 identically; the printed real part equals \
             p and the printed imaginary part squared equals q − p² = {disc} exactly"
        ),
        (false, _) => format!("the printed real part is {}, but p = {p}", paper(p_text)),
        (true, false) => format!("the printed imaginary part squared is {}, but q − p² = {disc}", paper(im_sq)),
    };
    s.push(
        key,
        printed,
        format!("p = {p}, q − p² = {disc}; {range}"),
        Finding::same(
            format!("p = {}, q − p² = {}", paper(p_text), paper(im_sq)),
            format!("p = {p}, q − p² = {disc}"),
        ),
        evidence,
    );
}

/// Records a printed tan Ψ = num/den against the roots: tan Ψ = sqrt(q − p²)/p,
/// so den must be p and num² must be q − p².
pub(crate) fn tan_claim(
    s: &mut Section,
    key: &str,
    method: &str,
    printed: &str,
    num_sq: &str,
    den: &str,
) {
    let d = builtin_derivation(method);
    let (p, q) = p_q(&d);
    let disc = &q - &(&p * &p);
    let ok = paper(den) == p && paper(num_sq) == disc;
    let p_sign = super::ranges::sign_text(
        &p,
        "p > 0 and Ψ = arctan(...) lies in (0, π/2)",
        "Ψ = π + arctan(...) lies in (π/2, π)",
    );
    s.push(
        key,
        printed,
        format!("tan Ψ = {} / ({p}); {p_sign}", sqrt_text(&disc)),
        Finding::same(
            format!("numerator² = {}, denominator = {}", paper(num_sq), paper(den)),
            format!("numerator² = {disc}, denominator = {p}"),
        ),
        if ok {
            "Ψ is the argument of z1 = p + j·sqrt(q − p²): the printed numerator squared equals q − p² \
             and the printed denominator equals p exactly"
                .to_owned()
        } else {
            format!("the printed form does not match p = {p}, q − p² = {disc}")
        },
    );
}

/// sqrt(p) for a polynomial in Φ, with the largest even power of Φ taken
/// out of the root: `Phi` for Φ², `Phi*sqrt(1 - 1/4*Phi^2)` for
/// Φ² − Φ⁴/4.
pub(crate) fn sqrt_text(p: &Poly) -> String {
    let c = p.coeffs_in(Sym::phi());
    let Some(low) = c.iter().position(|x| !x.is_zero()) else { return "0".to_owned() };
    let k = low / 2;
    let rest = Poly::from_coeffs_in(Sym::phi(), &c[2 * k..]);
    let outside = match k {
        0 => String::new(),
        1 => "Phi".to_owned(),
        k => format!("Phi^{k}"),
    };
    match (outside.is_empty(), rest.is_one()) {
        (true, _) => format!("sqrt({rest})"),
        (false, true) => outside,
        (false, false) => format!("{outside}*sqrt({rest})"),
    }
}

/// A transition matrix at one rational Φ (other parameters substituted by
/// the caller).
pub(crate) fn matrix_at(p: &PolyMatrix, phi: &Q) -> Vec<Vec<Q>> {
    (0..p.rows()).map(|i| p.row(i).iter().map(|e| at_phi(e, phi)).collect()).collect()
}

/// The exact states x_0, x_1, ..., x_n of x_{k+1} = P x_k.
pub(crate) fn iterate_exact(p: &[Vec<Q>], x0: &[Q], n: usize) -> Vec<Vec<Q>> {
    let mut out = vec![x0.to_vec()];
    for _ in 0..n {
        let x = out.last().expect("starts non-empty");
        let next = p
            .iter()
            .map(|row| row.iter().zip(x).fold(Q::from_integer(0.into()), |acc, (a, b)| acc + a * b))
            .collect();
        out.push(next);
    }
    out
}

#[cfg(test)]
mod tests {
    //! The claim builders fed perturbed statements: the verdict follows the
    //! statement, not the code path.
    use super::*;
    use crate::paper::policy::Verdict;
    use poly::RootClass;

    fn verdict_of(build: impl FnOnce(&mut Section)) -> Verdict {
        let mut s = Section::new("0", "test");
        build(&mut s);
        s.finish().pop().expect("one claim").verdict()
    }

    #[test]
    fn printed_objects_decide() {
        let chi = |text: &'static str| {
            verdict_of(|s| charpoly_claim(s, "chi", "false_euler", text, text))
        };
        assert_eq!(chi("z^2 - 2*(1 - Phi^2/2)*z + 1"), Verdict::Confirmed);
        assert_eq!(chi("z^2 - 2*(1 - Phi^2/2)*z + 1 + Phi^4/4"), Verdict::Errata);
        let r2 =
            |text: &'static str| verdict_of(|s| r_squared_claim(s, "standard_heun", text, text));
        assert_eq!(r2("1 + Phi^4/4"), Verdict::Confirmed);
        assert_eq!(r2("1 + Phi^2/4"), Verdict::Errata);
        let eig = |im: &'static str| {
            verdict_of(|s| eigen_claim(s, "e", "false_euler", im, "1 - Phi^2/2", im))
        };
        assert_eq!(eig("Phi^2*(1 - Phi^2/4)"), Verdict::Confirmed);
        assert_eq!(eig("Phi^2"), Verdict::Errata);
    }

    #[test]
    fn ranges_decide() {
        let always = |ok: fn(RootClass) -> bool, stated: Option<&str>| {
            verdict_of(|s| {
                let (finding, map, _) = super::super::ranges::always("false_euler", ok, stated);
                s.push("always", "always", map, finding, "");
            })
        };
        let harmonic = |c: RootClass| c == RootClass::Harmonic;
        assert_eq!(always(harmonic, Some("Phi^2 - 4")), Verdict::Refined);
        assert_eq!(always(harmonic, None), Verdict::Errata);
        assert_eq!(always(harmonic, Some("Phi^2 - 9")), Verdict::Errata);
        assert_eq!(always(|_| true, None), Verdict::Confirmed);
    }
}
