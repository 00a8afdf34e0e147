//! The two exact derivations of a method's characteristic polynomial.
//!
//! **Route (a), the z-domain.** Every assignment of step *i* is one equation
//! in the unknowns of step *i* (the value of each assignment). A value carried
//! from the previous step carries z⁻¹, a history read `y@k` carries
//! z^-(k+1). Moving everything to the left gives `M(z) u = 0` with
//! `M = I − L − R(z⁻¹)`, a polynomial matrix in w = z⁻¹, and
//!
//! $$ \chi(z) = z^N \det M(1/z), \qquad N = \sum_{\text{state}} (1 + \text{history}). $$
//!
//! **Route (b), the state space.** Symbolic execution of the step on the
//! augmented state (each variable at every lag it is read at, companion form)
//! gives the transition matrix P, and χ(z) = det(zI − P).
//!
//! The routes share nothing but the lowered program and the determinant
//! code, and [`derive`] refuses to answer when they disagree.
//!
//! **Cost.** Both routes are linear in the program's length: M is stored by
//! rows ([`SparsePolyMatrix`]) and its temporaries are eliminated by forward
//! substitution, the state route executes each line once. What remains is
//! one determinant of the size of the state: route (a)'s is a pencil
//! B₀ + w·B₁ in w and the parameters, route (b)'s a characteristic
//! polynomial in the parameters, both taken by the modular path of
//! [`crate::multivariate::matrix`] (evaluation modulo primes, interpolation, CRT) unless
//! the dense `i128` Berkowitz finishes first. [`charpoly_z_route_dense`]
//! keeps the old, quadratic route (a) as the tests' oracle.

use crate::error::{Error, ErrorKind, Span};
use crate::lang::method::{EndValue, Method, Operand, Target};
use crate::multivariate::matrix::SparsePolyMatrix;
use crate::{Poly, PolyMatrix, Sym};

/// Everything derived from one method.
///
/// Sealed: only [`derive()`] builds one, after the z-domain route and the
/// state route agree, so χ and P never disagree. Read it through the
/// getters ([`Derivation::charpoly`], [`Derivation::transition_matrix`],
/// ...).
#[derive(Clone, Debug)]
pub struct Derivation {
    /// The method derived.
    method: Method,
    /// M as a polynomial matrix in w = z⁻¹ (see [`w`]); one row and column per
    /// assignment, plus one per state variable the step never assigns.
    /// Stored by rows: it is mostly zero. A tableau's derivation (from its
    /// stability function) builds it on first use.
    z_matrix: std::sync::OnceLock<SparsePolyMatrix>,
    /// The transition matrix P over the augmented state
    /// ([`Method::slots`] order); for an implicit step, P times
    /// [`Derivation::p_denominator`].
    transition_matrix: PolyMatrix,
    /// The common denominator d of P's entries: det A of the step's linear
    /// system for an implicit method, 1 for an explicit one.
    p_denominator: Poly,
    /// χ(z) = det(zI − P), a polynomial in z and the parameters; for an
    /// implicit method d·det(zI − P), whose leading coefficient in z is d.
    charpoly: Poly,
}

/// The symbol standing for z⁻¹ inside [`Derivation::z_matrix`]. Its name
/// cannot be written in a `.zm` file, so it never clashes with a parameter.
pub fn w() -> Sym {
    Sym::new("1/z")
}

impl Derivation {
    /// The method derived.
    pub fn method(&self) -> &Method {
        &self.method
    }

    /// χ(z), a polynomial in z, Φ and the method's parameters (for an
    /// implicit method, det A · det(zI − P)).
    pub fn charpoly(&self) -> &Poly {
        &self.charpoly
    }

    /// The transition matrix P over the augmented state (for an implicit
    /// method, P times [`Derivation::p_denominator`]).
    pub fn transition_matrix(&self) -> &PolyMatrix {
        &self.transition_matrix
    }

    /// The common denominator of P's entries (det A; 1 when explicit).
    pub fn p_denominator(&self) -> &Poly {
        &self.p_denominator
    }

    /// The z-domain matrix M, in w = z⁻¹.
    pub fn z_matrix(&self) -> &SparsePolyMatrix {
        self.z_matrix.get_or_init(|| z_matrix(&self.method))
    }

    /// χ's coefficients, highest power of z first (the first is 1 for an
    /// explicit method, det A for an implicit one).
    pub fn coeffs(&self) -> Vec<Poly> {
        let mut c = self.charpoly.coeffs_in(Sym::z());
        c.reverse();
        c
    }

    /// For a second-order method, `(p, q)` with χ(z) = z² − 2p·z + q, the
    /// paper's form (section 4).
    pub fn p_q(&self) -> Option<(Poly, Poly)> {
        let c = self.coeffs();
        if c.len() != 3 || !c[0].is_one() {
            return None;
        }
        let half = Poly::constant(crate::Q::new((-1).into(), 2.into()));
        Some((&c[1] * &half, c[2].clone()))
    }

    /// M with the temporaries eliminated: one row and column per value the
    /// step keeps (each state variable's end-of-step value, then each
    /// unknown of an implicit system), labelled by name. Its determinant
    /// is det M, so it carries the same χ; its size is the state's, not
    /// the program's, so a program of 10,000 temporaries prints in a few
    /// lines. Entries are polynomials in w = z⁻¹ ([`w`]) and the
    /// parameters.
    pub fn z_matrix_reduced(&self) -> ReducedZMatrix {
        let m = &self.method;
        let kept = kept_unknowns(m);
        let (order, matrix) = match reduce_z_matrix(self.z_matrix(), &kept) {
            Some(reduced) => (kept, reduced),
            None => eliminate_dense(self.z_matrix().to_dense(), &kept),
        };
        let n_a = m.assigns().len();
        let carried = carried_unknowns(m);
        let labels = order
            .iter()
            .map(|&i| {
                if let Some(v) = carried.iter().position(|&c| c == i) {
                    m.state()[v].clone()
                } else if i >= n_a && i - n_a < m.unknowns().len() {
                    m.unknowns()[i - n_a].name.clone()
                } else {
                    match &m.assigns()[i].target {
                        Target::State(v) => m.state()[*v].clone(),
                        Target::Temp(t) => t.clone(),
                    }
                }
            })
            .collect();
        ReducedZMatrix { labels, matrix }
    }

    /// An entry of M written as a Laurent polynomial in z: `1 - z^-1`.
    pub fn z_entry_string(p: &Poly) -> String {
        laurent(p, false)
    }

    /// An entry of M in LaTeX.
    pub fn z_entry_latex(p: &Poly) -> String {
        laurent(p, true)
    }
}

fn laurent(p: &Poly, latex: bool) -> String {
    if p.is_zero() {
        return "0".into();
    }
    let mut parts: Vec<(bool, String)> = Vec::new();
    for (k, c) in p.coeffs_in(w()).into_iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        let body = if latex { c.latex() } else { c.to_string() };
        let (neg, body) = match body.strip_prefix('-') {
            Some(rest) if c.len() == 1 => (true, rest.to_owned()),
            _ => (false, body),
        };
        let zpow = match (k, latex) {
            (0, _) => String::new(),
            (_, false) => format!("z^-{k}"),
            (_, true) => format!("z^{{-{k}}}"),
        };
        let s = if k == 0 {
            body
        } else if c.len() > 1 {
            if latex {
                format!("\\left({body}\\right) {zpow}")
            } else {
                format!("({body})*{zpow}")
            }
        } else if body == "1" {
            zpow
        } else if latex {
            format!("{body} {zpow}")
        } else {
            format!("{body}*{zpow}")
        };
        parts.push((neg, s));
    }
    let mut out = String::new();
    for (i, (neg, s)) in parts.into_iter().enumerate() {
        match (i, neg) {
            (0, true) => out.push('-'),
            (0, false) => {}
            (_, true) => out.push_str(" - "),
            (_, false) => out.push_str(" + "),
        }
        out.push_str(&s);
    }
    out
}

/// The unknown of M holding each state variable's value at the end of the
/// step: its final assignment, or an extra unknown (numbered after the
/// assignments) when the step never assigns it.
fn carried_unknowns(m: &Method) -> Vec<usize> {
    let n_a = m.assigns().len();
    let mut extra = n_a + m.unknowns().len();
    (0..m.state().len())
        .map(|v| match m.end_value(v) {
            EndValue::Assign(k) => k,
            EndValue::Unknown(u) => n_a + u,
            EndValue::Kept => {
                extra += 1;
                extra - 1
            }
        })
        .collect()
}

/// Route (a): M(w) with w = z⁻¹, stored by rows (a program of n lines has
/// an n×n matrix with O(n) nonzeros).
pub fn z_matrix(m: &Method) -> SparsePolyMatrix {
    let n_assign = m.assigns().len();
    let n_eq = m.unknowns().len();
    let unknown_of = carried_unknowns(m);
    let n = n_assign
        + n_eq
        + (0..m.state().len()).filter(|&v| m.end_value(v) == EndValue::Kept).count();
    let wp = Poly::sym(w());
    let deepest = m.history().iter().copied().max().unwrap_or(0);
    let w_pow: Vec<Poly> = (0..=deepest).map(|lag| wp.pow(lag + 1)).collect();
    let mut rows: Vec<Vec<(usize, Poly)>> = Vec::with_capacity(n);
    // Assignment rows, then one row per equation of the implicit system
    // (its unknown is read at this step: no power of z).
    let sources =
        m.assigns().iter().map(|a| &a.terms).chain(m.equations().iter().map(|e| &e.terms));
    for (s, terms) in sources.enumerate() {
        let mut row: Vec<(usize, Poly)> = Vec::with_capacity(terms.len() + 1);
        row.push((s, Poly::one()));
        for (op, c) in terms {
            row.push(match *op {
                Operand::Stmt(t) => (t, -c),
                Operand::Unknown(u) => (n_assign + u, -c),
                Operand::Start { var, lag } => (unknown_of[var], -(c * &w_pow[lag as usize])),
            });
        }
        rows.push(row);
    }
    rows.resize_with(n, Vec::new);
    for (u, row) in rows.iter_mut().enumerate().skip(n_assign + n_eq) {
        row.push((u, Poly::one()));
    }
    let mut mat = SparsePolyMatrix::from_row_entries(n, rows);
    // A variable the step never assigns keeps its value: x_i = z⁻¹ x_i.
    for (v, &u) in unknown_of.iter().enumerate() {
        if m.end_value(v) == EndValue::Kept {
            mat.add_to(u, u, &-&wp);
        }
    }
    mat
}

/// The Schur complement of M on its carried unknowns, by forward
/// substitution over M's rows: an unknown that no later step reads
/// (a temporary or an overwritten value) has a unit diagonal and reads only
/// earlier unknowns, so its row expresses it through the carried ones
/// without division, and the complement has the same determinant as M (the
/// eliminated block is unit lower triangular). One row and column per
/// state variable remain, in state order. The cost is linear in the number
/// of nonzeros of M times the number of state variables.
///
/// `None` when M does not have that shape (an unknown read before its own
/// row, or a diagonal other than 1 off the carried unknowns); the caller
/// then eliminates on the dense matrix.
fn reduce_z_matrix(mat: &SparsePolyMatrix, carried: &[usize]) -> Option<PolyMatrix> {
    let n = mat.rows();
    let s = carried.len();
    let mut carried_index = vec![None; n];
    for (v, &c) in carried.iter().enumerate() {
        carried_index[c] = Some(v);
    }
    // The last row reading each unknown, so that its value is dropped
    // once read for the last time.
    let mut last_read = vec![0; n];
    for row in 0..n {
        for (j, _) in mat.row_entries(row) {
            last_read[*j] = row;
        }
    }
    // Each eliminated unknown as a combination of the carried ones.
    let mut value: Vec<Option<Vec<Poly>>> = vec![None; n];
    let mut reduced = PolyMatrix::zeros(s, s);
    for row in 0..n {
        let mut acc = vec![Poly::zero(); s];
        let mut diagonal_is_one = false;
        for (j, x) in mat.row_entries(row) {
            if let Some(v) = carried_index[*j] {
                acc[v] += x;
            } else if *j == row {
                diagonal_is_one = x.is_one();
            } else {
                let earlier = value[*j].as_ref()?;
                for (a, y) in acc.iter_mut().zip(earlier) {
                    if y.is_zero() {
                        continue;
                    }
                    if x.is_one() {
                        *a += y;
                    } else {
                        *a += &(x * y);
                    }
                }
                if last_read[*j] == row {
                    value[*j] = None;
                }
            }
        }
        match carried_index[row] {
            Some(v) => {
                for (k, a) in acc.into_iter().enumerate() {
                    reduced[(v, k)] = a;
                }
            }
            // Row: u_row + Σ x_j u_j = 0, so u_row = −Σ x_j u_j.
            None if diagonal_is_one => {
                value[row] = Some(acc.into_iter().map(|a| -a).collect());
            }
            None => return None,
        }
    }
    Some(reduced)
}

/// det M on the dense matrix, by Gaussian elimination on the unknowns that
/// no later step reads, then sparse Berkowitz on what remains: the slow
/// route (a), the oracle the tests hold [`reduce_z_matrix`] and the fast
/// determinants against, and the fallback for a matrix of another shape.
fn det_z_matrix_dense(mat: PolyMatrix, carried: &[usize]) -> Poly {
    let (_, rest) = eliminate_dense(mat, carried);
    let c = rest.charpoly_berkowitz_sparse();
    let det = c.last().cloned().unwrap_or_else(Poly::one);
    if rest.rows() % 2 == 1 {
        -det
    } else {
        det
    }
}

/// Gaussian elimination of every unknown of M with a unit diagonal that is
/// not in `carried`: the unknowns that remain, by index, and M on them
/// (whose determinant is det M: each pivot is 1).
fn eliminate_dense(mut mat: PolyMatrix, carried: &[usize]) -> (Vec<usize>, PolyMatrix) {
    let n = mat.rows();
    let mut kept: Vec<usize> = Vec::new();
    let mut removed = vec![false; n];
    for c in 0..n {
        if carried.contains(&c) || !mat[(c, c)].is_one() {
            kept.push(c);
            continue;
        }
        let pivot_row: Vec<(usize, Poly)> = (0..n)
            .filter(|&j| j != c && !removed[j] && !mat[(c, j)].is_zero())
            .map(|j| (j, mat[(c, j)].clone()))
            .collect();
        for s in 0..n {
            if s == c || removed[s] || mat[(s, c)].is_zero() {
                continue;
            }
            let f = std::mem::take(&mut mat[(s, c)]);
            for (j, x) in &pivot_row {
                mat[(s, *j)] -= &(&f * x);
            }
        }
        removed[c] = true;
    }
    let rest = PolyMatrix::from_rows(
        kept.iter().map(|&i| kept.iter().map(|&j| mat[(i, j)].clone()).collect()).collect(),
    );
    (kept, rest)
}

/// [`Derivation::z_matrix_reduced`]: M on the values a step keeps.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReducedZMatrix {
    /// The value each row and column stands for: a state variable's
    /// end-of-step value, or an unknown of the implicit system.
    pub labels: Vec<String>,
    /// The matrix, in w = z⁻¹ and the parameters.
    pub matrix: PolyMatrix,
}

/// Route (a)'s characteristic polynomial, z^N det M(1/z).
pub fn charpoly_z_route(m: &Method) -> Result<Poly, Error> {
    charpoly_from_z_matrix(m, &z_matrix(m))
}

/// Route (a) the slow, obvious way: elimination on the dense M and sparse
/// Berkowitz. Quadratic in the program's length; for tests only.
#[doc(hidden)]
pub fn charpoly_z_route_dense(m: &Method) -> Result<Poly, Error> {
    let det = det_z_matrix_dense(z_matrix(m).to_dense(), &kept_unknowns(m));
    charpoly_from_det(m, &det)
}

/// The unknowns of M that stay in the reduced matrix: the carried ones,
/// then every unknown of the implicit system (`x' = ...`, `unknown a`),
/// whose rows need not have a unit diagonal nor read only earlier
/// unknowns; the pencil determinant handles the general block.
fn kept_unknowns(m: &Method) -> Vec<usize> {
    let mut kept = carried_unknowns(m);
    let n_a = m.assigns().len();
    for u in 0..m.unknowns().len() {
        if !kept.contains(&(n_a + u)) {
            kept.push(n_a + u);
        }
    }
    kept
}

fn charpoly_from_z_matrix(m: &Method, mat: &SparsePolyMatrix) -> Result<Poly, Error> {
    let kept = kept_unknowns(m);
    let mut det = match reduce_z_matrix(mat, &kept) {
        Some(reduced) => reduced.det_pencil(w()),
        None => det_z_matrix_dense(mat.to_dense(), &kept),
    };
    if !m.constants().is_empty() {
        det = crate::multivariate::constants::reduce(&det);
    }
    charpoly_from_det(m, &det)
}

fn charpoly_from_det(m: &Method, det: &Poly) -> Result<Poly, Error> {
    let mut coeffs = det.coeffs_in(w());
    let n = m.state_size();
    if coeffs.len() > n + 1 {
        return Err(Error::new(
            ErrorKind::RoutesDisagree,
            Span::default(),
            format!("det M(z) has degree {} in 1/z, above the order {n}", coeffs.len() - 1),
        ));
    }
    // The coefficient of w^k multiplies z^(N-k).
    coeffs.resize(n + 1, Poly::zero());
    coeffs.reverse();
    Ok(Poly::from_coeffs_in(Sym::z(), &coeffs))
}

/// Route (b): the transition matrix P by symbolic execution (for an
/// implicit method, d·P with d = det A: see `implicit.rs`).
pub fn transition_matrix(m: &Method) -> PolyMatrix {
    if m.is_implicit() {
        let sys = crate::lang::system::system(m);
        return crate::derive::implicit::transition_fraction(m, &sys).0;
    }
    let slots = m.slots();
    let n = slots.len();
    let slot_of: std::collections::HashMap<(usize, u32), usize> =
        slots.iter().enumerate().map(|(k, &s)| (s, k)).collect();
    let unit = |k: usize| {
        let mut v = vec![Poly::zero(); n];
        v[k] = Poly::one();
        v
    };
    // The last assignment reading each value (values carried to the next
    // step are read at the end, so they are never dropped early).
    let mut last_read = vec![usize::MAX; m.assigns().len()];
    for (s, a) in m.assigns().iter().enumerate() {
        for (op, _) in &a.terms {
            if let Operand::Stmt(t) = *op {
                last_read[t] = s;
            }
        }
    }
    for var in 0..m.state().len() {
        if let Some(t) = m.final_assign(var) {
            last_read[t] = usize::MAX;
        }
    }
    let mut values: Vec<Vec<Poly>> = Vec::with_capacity(m.assigns().len());
    for (s, a) in m.assigns().iter().enumerate() {
        let mut acc = vec![Poly::zero(); n];
        for (op, c) in &a.terms {
            match *op {
                Operand::Stmt(t) => {
                    for (x, s) in acc.iter_mut().zip(&values[t]) {
                        if s.is_zero() {
                            continue;
                        }
                        if c.is_one() {
                            *x += s;
                        } else {
                            *x += &(c * s);
                        }
                    }
                }
                Operand::Start { var, lag } => acc[slot_of[&(var, lag)]] += c,
                Operand::Unknown(_) => unreachable!("explicit route of an implicit method"),
            }
        }
        for (op, _) in &a.terms {
            if let Operand::Stmt(t) = *op {
                if last_read[t] == s {
                    values[t] = Vec::new();
                }
            }
        }
        values.push(acc);
    }
    let mut p = PolyMatrix::zeros(n, n);
    for (row, &(var, lag)) in slots.iter().enumerate() {
        let new = if lag == 0 {
            match m.end_value(var) {
                EndValue::Assign(t) => values[t].clone(),
                _ => unit(slot_of[&(var, 0)]),
            }
        } else {
            unit(slot_of[&(var, lag - 1)])
        };
        for (col, x) in new.into_iter().enumerate() {
            p[(row, col)] = x;
        }
    }
    p
}

/// Route (b)'s characteristic polynomial, det(zI − P), by Berkowitz.
pub fn charpoly_state_route(p: &PolyMatrix) -> Poly {
    let mut c = p.charpoly_berkowitz();
    c.reverse();
    Poly::from_coeffs_in(Sym::z(), &c)
}

/// Parses `src` (named `file` in error messages) and derives it by both
/// routes: the common case in one call.
///
/// ```
/// let src = "method mine\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n";
/// let d = poly::derive_source("mine.zm", src)?;
/// assert_eq!(d.charpoly().to_string(), "z^2 - 2*z + Phi^2*z + 1");
/// let bad = poly::derive_source("bad.zm", "method m\nstate v\nv = v*v\n").unwrap_err();
/// assert_eq!(bad.kind(), poly::ErrorKind::Nonlinear);
/// assert!(bad.to_string().starts_with("bad.zm:3:5:"));
/// # Ok::<(), poly::Error>(())
/// ```
pub fn derive_source(file: &str, src: &str) -> Result<Derivation, Error> {
    derive(&Method::parse(file, src)?)
}

/// Derives a method by both routes and checks that they agree exactly; a
/// program generated from a Butcher tableau is derived from its stability
/// function instead (the same fields, tested against both routes).
///
/// ```
/// let m = poly::builtin("false_euler")?;
/// let d = poly::derive(&m)?;
/// assert_eq!(d.charpoly().to_string(), "z^2 - 2*z + Phi^2*z + 1");
/// # Ok::<(), poly::Error>(())
/// ```
pub fn derive(method: &Method) -> Result<Derivation, Error> {
    match &method.stability_function.0 {
        Some(r) => Ok(derive_runge_kutta(method, &r.0, &r.1)),
        None => derive_both_routes(method),
    }
}

/// The derivation of a program generated from a Butcher tableau, read from
/// its stability function R(w) = P(w)/Q(w) (`Method::stability_function`)
/// instead of solving the stages' linear system, to the very same fields:
/// the oracle [`derive_both_routes`] is held to it in the tests.
///
/// - On y' = λy (one state y): det A = Q (A = I − wA at w = 0 is I),
///   d·P = P and χ = Q·z − P.
/// - On the oscillator v' = −ωy, y' = ωv: u = y + iv obeys u' = −iωu, so a
///   step multiplies u by R(−iΦ). With P(−iΦ) = P_r + iP_i and
///   Q(−iΦ) = Q_r + iQ_i (real coefficients), det A = det(I + Φ²A²) =
///   Q(iΦ)Q(−iΦ) = Q_r² + Q_i² = d, and d·R(−iΦ) = P(−iΦ)Q(iΦ) = α + iβ
///   with α = P_rQ_r + P_iQ_i, β = P_iQ_r − P_rQ_i. Over (v, y):
///   d·P = [[α, β], [−β, α]], a rotation-scaling, and
///   χ = d·det(zI − P) = d·z² − 2α·z + P_r² + P_i² (= |P(iΦ)|²).
fn derive_runge_kutta(method: &Method, p: &Poly, q: &Poly) -> Derivation {
    let fix = |x: Poly| crate::lang::system::fix(method, x);
    let z = Poly::sym(Sym::z());
    let rational = || Some((p.to_upoly(Sym::w())?, q.to_upoly(Sym::w())?));
    let (transition_matrix, p_denominator, charpoly) = if method.is_scalar() {
        let chi = fix(&(&z * q) - p);
        (PolyMatrix::from_rows(vec![vec![p.clone()]]), q.clone(), chi)
    } else {
        rational()
            .filter(|_| method.constants().is_empty())
            .and_then(|(p, q)| super::oscillator::in_words(&p, &q))
            .unwrap_or_else(|| super::oscillator::general(method, p, q))
    };
    Derivation {
        method: method.clone(),
        z_matrix: std::sync::OnceLock::new(),
        transition_matrix,
        p_denominator,
        charpoly,
    }
}

/// Derives a method by both routes and checks that they agree exactly:
/// [`derive`] for every program not generated from a tableau, and the
/// oracle of its Runge–Kutta route.
#[doc(hidden)]
pub fn derive_both_routes(method: &Method) -> Result<Derivation, Error> {
    let z_matrix = z_matrix(method);
    let a = charpoly_from_z_matrix(method, &z_matrix)?;
    let (transition_matrix, p_denominator, b) = if method.is_implicit() {
        let sys = crate::lang::system::system(method);
        let (p, d) = crate::derive::implicit::transition_fraction(method, &sys);
        (p, d, crate::derive::implicit::charpoly_pencil(method, &sys))
    } else {
        let mut p = transition_matrix(method);
        let mut b = charpoly_state_route(&p);
        if !method.constants().is_empty() {
            p = p.map(crate::multivariate::constants::reduce);
            b = crate::multivariate::constants::reduce(&b);
        }
        (p, Poly::one(), b)
    };
    if a != b {
        return Err(Error::new(
            ErrorKind::RoutesDisagree,
            Span::default(),
            format!(
                "method `{}`: the z-domain route gives {a} but the state-space route gives {b}",
                method.name()
            ),
        ));
    }
    Ok(Derivation {
        method: method.clone(),
        z_matrix: std::sync::OnceLock::from(z_matrix),
        transition_matrix,
        p_denominator,
        charpoly: a,
    })
}

/// The characteristic polynomial of a method, derived by both routes.
pub fn charpoly(method: &Method) -> Result<Poly, Error> {
    derive(method).map(|d| d.charpoly)
}
