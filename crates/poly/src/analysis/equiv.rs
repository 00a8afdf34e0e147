//! Identities between methods, decided exactly: are two transition matrices
//! equal, similar by a permutation of the state, similar by a constant
//! diagonal scaling (or both), similar by a change of variables whose
//! entries depend on Φ (and the other parameters), or do they merely share
//! χ? And is one program the other with its updates reordered?
//!
//! Similarity by a permutation Π and a diagonal S means
//! $$P_b = S\,\Pi P_a \Pi^T S^{-1},\quad (P_b)_{ij} = \tfrac{s_i}{s_j} (P_a)_{\pi(i)\pi(j)},$$
//! so the diagonal must agree, the zero patterns must agree, and each
//! off-diagonal ratio must be one rational constant consistent along every
//! cycle of the pattern. Every permutation is tried (the methods have at
//! most a handful of slots).
//!
//! Similarity by a change of variables means `T P_a = P_b T` with `T`
//! invertible over the rational functions Q(Φ, D, ...). Two routes find it:
//!
//! - **Through the observed variable** `y`. With `c` the row that reads
//!   `y` and `O = [c; cP; …; cP^{n−1}]` the observability matrix, a `T` with
//!   `c_b T = c_a` (the same `y` samples from mapped starts) must satisfy
//!   `O_b T = O_a`. When both `O` are invertible and χ agrees, `T = O_b⁻¹ O_a`
//!   is such a change: the sample sequences agree for `k < n` by
//!   construction and beyond by the common recurrence χ (Cayley–Hamilton),
//!   so `O_b P_b T = O_a P_a = O_b T P_a`. It is checked all the same.
//! - **Otherwise**, the solutions of the linear equation `X P_a = P_b X`
//!   are found exactly (fraction-free elimination over Q[Φ, ...]). If the
//!   matrices were similar, `X ↦ T X` and `X ↦ X T` would map the
//!   solutions of `X P_a = P_a X` and of `X P_b = P_b X` onto them, so
//!   three dimensions that differ prove that no `T` exists. When they agree
//!   (then the matrices are similar, by Byrnes and Gauger's criterion), an
//!   invertible member is searched: the basis, sums of pairs, small
//!   combinations, and at last the grid `{0, …, n}^k`, on which a nonzero
//!   determinant polynomial of degree n cannot vanish everywhere.

use std::collections::VecDeque;

use crate::lang::method::Operand;
use crate::multivariate::matrix::echelon;
use crate::{Derivation, Method, Poly, PolyMatrix, Q};

/// The state variable whose samples a change of variables carries over
/// when it can: the position `y`, the output the paper plots.
pub const OBSERVED: &str = "y";

/// A change of variables `x_b = T x_a` with `T P_a = P_b T`, `T` and `T⁻¹`
/// with entries rational in the parameters (each a polynomial matrix over
/// a common denominator).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Change {
    /// T's numerator: `x_b = (t / t_denominator) x_a`.
    pub t: PolyMatrix,
    /// T's common denominator.
    pub t_denominator: Poly,
    /// T⁻¹'s numerator: `x_a = (inverse / inverse_denominator) x_b`.
    pub inverse: PolyMatrix,
    /// T⁻¹'s common denominator.
    pub inverse_denominator: Poly,
    /// The state variable with identical samples: `y_n` of `b` started from
    /// `T x₀` equals `y_n` of `a` started from `x₀` for every `n ≥ 0` and
    /// every start (because `c_b T = c_a` and `T P_a = P_b T`). `None` when
    /// no such `T` was found (the variable is missing, or its samples do
    /// not determine the state).
    pub observed: Option<String>,
}

impl Change {
    /// A polynomial whose zeros are the only parameter values where `T` or
    /// `T⁻¹` is undefined; elsewhere both exist and `T P_a T⁻¹ = P_b`.
    pub fn undefined_at(&self) -> Poly {
        &self.t_denominator * &self.inverse_denominator
    }

    /// Row `i` of `T` over its own denominator, common factors cancelled:
    /// slot `i` of `b` is `Σ_j entries[j]·(slot j of a) / denominator`.
    pub fn t_row(&self, i: usize) -> (Vec<Poly>, Poly) {
        cancel(self.t.row(i).to_vec(), self.t_denominator.clone())
    }

    /// Row `i` of `T⁻¹` over its own denominator, as [`Change::t_row`].
    pub fn inverse_row(&self, i: usize) -> (Vec<Poly>, Poly) {
        cancel(self.inverse.row(i).to_vec(), self.inverse_denominator.clone())
    }
}

/// How two methods relate, strongest first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Relation {
    /// The transition matrices are equal.
    Equal,
    /// `P_b = Π P_a Πᵀ`: the same step with the state variables in another
    /// order; `perm[i]` is the slot of `a` that becomes slot `i` of `b`.
    Permutation {
        /// Slot `i` of `b` is slot `perm[i]` of `a`.
        perm: Vec<usize>,
    },
    /// `P_b = S P_a S⁻¹` with a constant diagonal `S` (a rescaled state).
    Scaling {
        /// The diagonal of `S`, first entry 1.
        scale: Vec<Q>,
    },
    /// `P_b = S Π P_a Πᵀ S⁻¹`: reordered and rescaled.
    PermutationAndScaling {
        /// Slot `i` of `b` is slot `perm[i]` of `a`.
        perm: Vec<usize>,
        /// The diagonal of `S`.
        scale: Vec<Q>,
    },
    /// `P_b = T P_a T⁻¹` with `T`'s entries rational functions of the
    /// parameters, and no signed permutation or scaling does it.
    ChangeOfVariables(Box<Change>),
    /// Only the characteristic polynomials are equal: the transition
    /// matrices are not similar over the rational functions of the
    /// parameters (beyond six slots, no similarity is searched).
    SameCharpoly,
    /// Not even χ agrees.
    Different,
}

impl Relation {
    /// The relation's name, snake_case, for JSON.
    pub fn name(&self) -> &'static str {
        match self {
            Relation::Equal => "equal",
            Relation::Permutation { .. } => "permutation",
            Relation::Scaling { .. } => "scaling",
            Relation::PermutationAndScaling { .. } => "permutation_and_scaling",
            Relation::ChangeOfVariables(_) => "change_of_variables",
            Relation::SameCharpoly => "same_charpoly",
            Relation::Different => "different",
        }
    }

    /// Whether the two share χ (every relation but `Different`).
    pub fn shares_charpoly(&self) -> bool {
        !matches!(self, Relation::Different)
    }
}

/// The constant `c` with `b = c·a`, if there is one (`a` non-zero).
fn constant_ratio(b: &Poly, a: &Poly) -> Option<Q> {
    let (_, ca) = a.terms().next()?;
    let (mb, cb) = b.terms().next()?;
    let (ma, _) = a.terms().next()?;
    if ma != mb {
        return None;
    }
    let c = cb / ca;
    (a.scale(&c) == *b).then_some(c)
}

/// The diagonal scaling with `b = S q S⁻¹`, if one exists.
fn scaling(q: &PolyMatrix, b: &PolyMatrix) -> Option<Vec<Q>> {
    let n = q.rows();
    for i in 0..n {
        if q[(i, i)] != b[(i, i)] {
            return None;
        }
        for j in 0..n {
            if q[(i, j)].is_zero() != b[(i, j)].is_zero() {
                return None;
            }
        }
    }
    // s_i = r_ij s_j along every non-zero off-diagonal entry.
    let mut scale: Vec<Option<Q>> = vec![None; n];
    for root in 0..n {
        if scale[root].is_some() {
            continue;
        }
        scale[root] = Some(crate::q(1, 1));
        let mut queue = VecDeque::from([root]);
        while let Some(i) = queue.pop_front() {
            let si = scale[i].clone().expect("visited");
            for j in 0..n {
                if i == j {
                    continue;
                }
                // b_ij = s_i/s_j q_ij and b_ji = s_j/s_i q_ji.
                let links = [
                    (!q[(i, j)].is_zero())
                        .then(|| constant_ratio(&b[(i, j)], &q[(i, j)]).map(|r| &si / &r)),
                    (!q[(j, i)].is_zero())
                        .then(|| constant_ratio(&b[(j, i)], &q[(j, i)]).map(|r| &si * &r)),
                ];
                for link in links.into_iter().flatten() {
                    let sj = link?;
                    match &scale[j] {
                        Some(existing) if *existing != sj => return None,
                        Some(_) => {}
                        None => {
                            scale[j] = Some(sj);
                            queue.push_back(j);
                        }
                    }
                }
            }
        }
    }
    Some(scale.into_iter().map(|s| s.expect("every slot scaled")).collect())
}

fn permutations(n: usize) -> Vec<Vec<usize>> {
    if n == 0 {
        return vec![Vec::new()];
    }
    let mut out = Vec::new();
    for p in permutations(n - 1) {
        for k in 0..=p.len() {
            let mut q = p.clone();
            q.insert(k, n - 1);
            out.push(q);
        }
    }
    out
}

/// The strongest relation between two derivations' transition matrices.
///
/// An implicit method's P is stored as `transition_matrix / p_denominator`;
/// the two are compared as fractions, by cross-multiplying with the other
/// side's denominator, so backward Euler's P is never mistaken for its
/// numerator.
pub fn relate(a: &Derivation, b: &Derivation) -> Relation {
    let (da, db) = (a.p_denominator(), b.p_denominator());
    let same_den = da == db;
    let cross = |m: &PolyMatrix, d: &Poly| if same_den { m.clone() } else { m.map(|e| e * d) };
    let (pa, pb) = (&cross(a.transition_matrix(), db), &cross(b.transition_matrix(), da));
    if pa == pb {
        return Relation::Equal;
    }
    // Every similarity keeps χ: compared first, it settles most pairs.
    let same_charpoly = if same_den {
        a.charpoly() == b.charpoly()
    } else {
        a.charpoly() * db == b.charpoly() * da
    };
    if !same_charpoly {
        return Relation::Different;
    }
    let n = pa.rows();
    if pb.rows() != n || n > 6 {
        return Relation::SameCharpoly;
    }
    let one = crate::q(1, 1);
    let mut perms = permutations(n);
    perms.sort();
    // Permutation alone first, then scaling alone, then both.
    let mut best: Option<Relation> = None;
    for perm in perms {
        let q = PolyMatrix::from_rows(
            (0..n).map(|i| (0..n).map(|j| pa[(perm[i], perm[j])].clone()).collect()).collect(),
        );
        let Some(scale) = scaling(&q, pb) else { continue };
        let identity = perm.iter().enumerate().all(|(i, p)| i == *p);
        let unit = scale.iter().all(|s| *s == one);
        let r = match (identity, unit) {
            (true, true) => Relation::Equal,
            (false, true) => Relation::Permutation { perm },
            (true, false) => Relation::Scaling { scale },
            (false, false) => Relation::PermutationAndScaling { perm, scale },
        };
        let rank = |r: &Relation| match r {
            Relation::Equal => 0,
            Relation::Permutation { .. } => 1,
            Relation::Scaling { .. } => 2,
            _ => 3,
        };
        if best.as_ref().is_none_or(|b| rank(&r) < rank(b)) {
            best = Some(r);
        }
    }
    if let Some(r) = best {
        return r;
    }
    // P_a and P_b are both scaled by d_a·d_b here, which changes no T.
    let observed = |m: &Method| {
        let var = m.state().iter().position(|v| v == OBSERVED)?;
        m.slots().iter().position(|&(v, lag)| v == var && lag == 0)
    };
    let through_samples = match (observed(a.method()), observed(b.method())) {
        (Some(ya), Some(yb)) => through_observed(pa, pb, ya, yb),
        _ => None,
    };
    match through_samples.or_else(|| through_sylvester(pa, pb)) {
        Some(change) => Relation::ChangeOfVariables(Box::new(change)),
        None => Relation::SameCharpoly,
    }
}

/// `[c; cP; …; cP^{n−1}]` for the row `c` that reads slot `slot`.
fn observability(p: &PolyMatrix, slot: usize) -> PolyMatrix {
    let n = p.rows();
    let mut row: Vec<Poly> =
        (0..n).map(|j| if j == slot { Poly::one() } else { Poly::zero() }).collect();
    let mut rows = Vec::with_capacity(n);
    for _ in 0..n {
        let next = (0..n)
            .map(|j| (0..n).fold(Poly::zero(), |acc, k| &acc + &(&row[k] * &p[(k, j)])))
            .collect();
        rows.push(std::mem::replace(&mut row, next));
    }
    PolyMatrix::from_rows(rows)
}

/// `X / d = A⁻¹ B` when `A` is invertible over the rational functions.
fn solve(a: &PolyMatrix, b: &PolyMatrix) -> Option<(PolyMatrix, Poly)> {
    let n = a.rows();
    let rows = (0..n).map(|i| a.row(i).iter().chain(b.row(i)).cloned().collect()).collect();
    let e = echelon::reduce(rows);
    if e.pivots.len() < n || e.pivots[n - 1] != n - 1 {
        return None;
    }
    let x = PolyMatrix::from_rows(e.rows.iter().take(n).map(|r| r[n..].to_vec()).collect());
    Some((x, e.d))
}

/// The change of variables that keeps slot `ya` of `a` as slot `yb` of `b`:
/// `T = O_b⁻¹ O_a` (module docs), when both observability matrices are
/// invertible and `T` checks.
fn through_observed(pa: &PolyMatrix, pb: &PolyMatrix, ya: usize, yb: usize) -> Option<Change> {
    let (oa, ob) = (observability(pa, ya), observability(pb, yb));
    let (t, t_den) = solve(&ob, &oa)?;
    let (inverse, inverse_den) = solve(&oa, &ob)?;
    if &t * pa != pb * &t {
        return None;
    }
    Some(change(t, t_den, inverse, inverse_den, Some(OBSERVED.to_owned())))
}

/// The coefficient rows of `X P_a − P_b X = 0` in the unknowns `X[i][j]`
/// (column `i·n + j`).
fn sylvester(pa: &PolyMatrix, pb: &PolyMatrix) -> Vec<Vec<Poly>> {
    let n = pa.rows();
    let mut rows = vec![vec![Poly::zero(); n * n]; n * n];
    for i in 0..n {
        for j in 0..n {
            let row = &mut rows[i * n + j];
            for l in 0..n {
                row[i * n + l] += &pa[(l, j)];
                row[l * n + j] -= &pb[(i, l)];
            }
        }
    }
    rows
}

/// Some invertible `T` with `T P_a = P_b T`, from the solution space (module
/// docs); `None` exactly when there is none.
fn through_sylvester(pa: &PolyMatrix, pb: &PolyMatrix) -> Option<Change> {
    let n = pa.rows();
    let dim = |x: &PolyMatrix, y: &PolyMatrix| n * n - echelon::reduce(sylvester(x, y)).rank();
    let e = echelon::reduce(sylvester(pa, pb));
    let k = n * n - e.rank();
    if k == 0 || dim(pa, pa) != k || dim(pb, pb) != k {
        return None;
    }
    let basis: Vec<PolyMatrix> = e
        .null_space(n * n)
        .into_iter()
        .map(|x| PolyMatrix::from_rows(x.chunks(n).map(<[Poly]>::to_vec).collect()))
        .collect();
    let combine = |c: &[i64]| {
        let mut m = PolyMatrix::zeros(n, n);
        for (b, &ci) in basis.iter().zip(c) {
            if ci != 0 {
                for i in 0..n {
                    for j in 0..n {
                        m[(i, j)] += &b[(i, j)].scale(&crate::q(ci, 1));
                    }
                }
            }
        }
        m
    };
    let unit = |i: usize| (0..k).map(|j| i64::from(i == j)).collect::<Vec<_>>();
    let pairs = (0..k).flat_map(move |i| {
        (i + 1..k).map(move |j| (0..k).map(|l| i64::from(l == i || l == j)).collect::<Vec<_>>())
    });
    // A fixed pseudo-random sequence of small coefficients (a linear
    // congruential generator): deterministic, and almost surely invertible
    // at the first try when the basis and its pairs are not.
    let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
    let random = (0..256).map(move |_| {
        (0..k)
            .map(|_| {
                seed = seed
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                (seed >> 59) as i64 - 15
            })
            .collect::<Vec<_>>()
    });
    let grid = (1..(n as u64 + 1).saturating_pow(k as u32)).map(move |mut index| {
        (0..k)
            .map(|_| {
                let digit = index % (n as u64 + 1);
                index /= n as u64 + 1;
                digit as i64
            })
            .collect::<Vec<_>>()
    });
    let t = (0..k)
        .map(unit)
        .chain(pairs)
        .chain(random)
        .chain(grid)
        .map(|c| combine(&c))
        .find(|t| !t.det().is_zero())?;
    let (inverse, inverse_den) = solve(&t, &PolyMatrix::identity(n))?;
    Some(change(t, Poly::one(), inverse, inverse_den, None))
}

/// A [`Change`] with each matrix's common factors cancelled.
fn change(
    t: PolyMatrix,
    t_den: Poly,
    inverse: PolyMatrix,
    inverse_den: Poly,
    observed: Option<String>,
) -> Change {
    let reduced = |m: PolyMatrix, d: Poly| {
        let (rows, cols) = (m.rows(), m.cols());
        let (entries, d) = cancel(m.data, d);
        (
            PolyMatrix::from_rows(
                entries.chunks(cols.max(1)).take(rows).map(<[Poly]>::to_vec).collect(),
            ),
            d,
        )
    };
    let (t, t_denominator) = reduced(t, t_den);
    let (inverse, inverse_denominator) = reduced(inverse, inverse_den);
    Change { t, t_denominator, inverse, inverse_denominator, observed }
}

/// `entries / den` with their greatest common factor cancelled and `den`'s
/// leading coefficient made 1.
fn cancel(entries: Vec<Poly>, den: Poly) -> (Vec<Poly>, Poly) {
    let common = entries.iter().fold(den.clone(), |g, e| g.gcd(e));
    let divide = |p: &Poly| p.div_exact(&common).expect("a common factor divides");
    let (entries, den) = (entries.iter().map(divide).collect::<Vec<_>>(), divide(&den));
    let lead = den.leading_term().map_or_else(|| crate::q(1, 1), |(_, c)| crate::q(1, 1) / c);
    (entries.iter().map(|p| p.scale(&lead)).collect(), den.scale(&lead))
}

/// One assignment as its source reads: its target and its terms, each
/// operand by the name the source writes (`y`, `y@1`), sorted. A read of `v`
/// is written `v` whether it sees the start value or a value assigned
/// earlier in the step: reordering the updates changes which, not the text.
fn described(m: &Method, k: usize) -> String {
    let a = &m.assigns()[k];
    let mut terms: Vec<String> = a
        .terms
        .iter()
        .map(|(op, c)| {
            let name = match *op {
                Operand::Stmt(t) => m.target_name(&m.assigns()[t]).to_owned(),
                start => m.operand_name(start),
            };
            format!("{c}*{name}")
        })
        .collect();
    terms.sort();
    format!("{} <- {}", m.target_name(a), terms.join(" + "))
}

/// Whether `b`'s step is `a`'s updates in another order (same state, the
/// same assignments by name, a different sequence).
pub fn reordered_updates(a: &Method, b: &Method) -> bool {
    if a.state() != b.state() || a.assigns().len() != b.assigns().len() {
        return false;
    }
    let list = |m: &Method| (0..m.assigns().len()).map(|k| described(m, k)).collect::<Vec<_>>();
    let (la, lb) = (list(a), list(b));
    if la == lb {
        return false;
    }
    let (mut sa, mut sb) = (la, lb);
    sa.sort();
    sb.sort();
    sa == sb
}

impl Derivation {
    /// The strongest relation this method bears to `other`: equal P,
    /// similar by a signed permutation or scaling, similar by a change of
    /// variables T(Φ), the same χ only, or different.
    pub fn relate(&self, other: &Derivation) -> Relation {
        relate(self, other)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn derive(src: &str) -> Derivation {
        crate::derive(&Method::parse("t.zm", src).expect("parses")).expect("derives")
    }

    /// Each relation once, and the negative cases: a different χ, and a
    /// matrix with the same χ that no change of variables reaches.
    #[test]
    fn relations() {
        let fe = derive("method a\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n");
        let swapped = derive("method b\nstate y v\nv = v - Phi*y\ny = y + Phi*v\n");
        let scaled = derive("method c\nstate v y\nv = v - 2*Phi*y\ny = y + 1/2*Phi*v\n");
        let damped =
            derive("method d\nstate v y\nv1 = v - Phi*(y + Phi*v)\ny = y + Phi*v\nv = v1\n");
        let euler = derive("method e\nstate v y\nv1 = v - Phi*y\ny = y + Phi*v\nv = v1\n");
        let verlet = derive("method f\nstate y\ny = 2*y - y@1 - Phi^2*y\n");
        assert_eq!(relate(&fe, &fe), Relation::Equal);
        assert_eq!(relate(&fe, &swapped), Relation::Permutation { perm: vec![1, 0] });
        assert_eq!(
            relate(&fe, &scaled),
            Relation::Scaling { scale: vec![crate::q(1, 1), crate::q(1, 2)] }
        );
        assert!(matches!(relate(&fe, &damped), Relation::PermutationAndScaling { .. }));
        assert!(matches!(relate(&fe, &verlet), Relation::ChangeOfVariables(_)));
        assert_eq!(relate(&fe, &euler), Relation::Different);
        // The same χ = (z − c)², c = 1 − Φ²/2: c·I against a Jordan block.
        let scalar = derive("method g\nstate v y\nv = (1 - Phi^2/2)*v\ny = (1 - Phi^2/2)*y\n");
        let jordan =
            derive("method h\nstate v y\nv = (1 - Phi^2/2)*v\ny = (1 - Phi^2/2)*y + Phi*v\n");
        assert_eq!(scalar.charpoly(), jordan.charpoly());
        assert_eq!(relate(&scalar, &jordan), Relation::SameCharpoly);
        assert_eq!(relate(&jordan, &scalar), Relation::SameCharpoly);
        // Reordered updates: the same two assignments, y first.
        let ab = Method::parse("a", "method a\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n").unwrap();
        let ba = Method::parse("b", "method b\nstate v y\ny = y + Phi*v\nv = v - Phi*y\n").unwrap();
        assert!(reordered_updates(&ab, &ba));
        assert!(!reordered_updates(&ab, &ab));
        let other =
            Method::parse("c", "method c\nstate v y\ny = y + Phi*v\nv = v - 2*Phi*y\n").unwrap();
        assert!(!reordered_updates(&ab, &other));
    }

    fn builtin(name: &str) -> Derivation {
        crate::derive(&crate::builtin(name).expect("a built-in")).expect("derives")
    }

    fn p(s: &str) -> Poly {
        Poly::parse(s).expect("parses")
    }

    fn matrix(rows: &[&[&str]]) -> PolyMatrix {
        PolyMatrix::from_rows(rows.iter().map(|r| r.iter().map(|e| p(e)).collect()).collect())
    }

    /// `T P_a = P_b T` by multiplying the matrices, T·T⁻¹ = I, and the
    /// observed samples: `c_b P_b^k T = c_a P_a^k` for k = 0, …, 2n, with
    /// `c` the row reading `y`. Every product is exact.
    #[track_caller]
    fn check_change(a: &Derivation, b: &Derivation, change: &Change) {
        let (pa, pb) = (a.transition_matrix(), b.transition_matrix());
        assert!(a.p_denominator().is_one() && b.p_denominator().is_one(), "explicit methods only");
        let n = pa.rows();
        assert_eq!(&change.t * pa, pb * &change.t, "T P_a = P_b T");
        let product = &change.t * &change.inverse;
        let scale = &change.t_denominator * &change.inverse_denominator;
        assert_eq!(product, PolyMatrix::identity(n).map(|e| e * &scale), "T T⁻¹ = I");
        assert!(!change.t.det().is_zero());
        let Some(name) = &change.observed else { return };
        let slot = |d: &Derivation| {
            let var = d.method().state().iter().position(|v| v == name).expect("observed");
            d.method().slots().iter().position(|&(v, lag)| v == var && lag == 0).expect("lag 0")
        };
        let row =
            |k: usize| -> Vec<Poly> { (0..n).map(|j| Poly::int(i64::from(j == k))).collect() };
        let times = |r: &[Poly], m: &PolyMatrix| -> Vec<Poly> {
            (0..n)
                .map(|j| (0..n).fold(Poly::zero(), |acc, k| &acc + &(&r[k] * &m[(k, j)])))
                .collect()
        };
        let (mut ra, mut rb) = (row(slot(a)), row(slot(b)));
        for k in 0..=2 * n {
            let lhs = times(&rb, &change.t);
            let rhs: Vec<Poly> = ra.iter().map(|e| e * &change.t_denominator).collect();
            assert_eq!(lhs, rhs, "the samples of {name} differ at step {k}");
            ra = times(&ra, pa);
            rb = times(&rb, pb);
        }
    }

    /// Verlet and False Euler: the secant velocity v = (y − y@1)/Φ carries
    /// Verlet's state to False Euler's, and y's samples are the same; the
    /// way back is the polynomial T⁻¹ = [[0, 1], [−Φ, 1]].
    #[test]
    fn verlet_is_false_euler_through_a_change_of_variables() {
        let (verlet, fe) = (builtin("verlet"), builtin("false_euler"));
        let Relation::ChangeOfVariables(change) = relate(&verlet, &fe) else {
            panic!("expected a change of variables, got {:?}", relate(&verlet, &fe))
        };
        check_change(&verlet, &fe, &change);
        assert_eq!(change.observed.as_deref(), Some("y"));
        // Verlet's slots are (y, y@1), False Euler's (v, y).
        assert_eq!(change.t, matrix(&[&["1", "-1"], &["Phi", "0"]]));
        assert_eq!(change.t_denominator, p("Phi"));
        assert_eq!(change.inverse, matrix(&[&["0", "1"], &["-Phi", "1"]]));
        assert!(change.inverse_denominator.is_one());
        assert_eq!(change.undefined_at(), p("Phi"));
        assert_eq!(change.t_row(1), (vec![p("1"), p("0")], p("1")));
        // The other way round, the roles of T and T⁻¹ swap.
        let Relation::ChangeOfVariables(back) = relate(&fe, &verlet) else { panic!("symmetric") };
        check_change(&fe, &verlet, &back);
        assert_eq!((back.t, back.inverse), (change.inverse.clone(), change.t.clone()));
    }

    /// Damped Euler (D = Φ/2) is the symplectic Euler that updates y first,
    /// exactly; both are False Euler up to a signed permutation, which is
    /// stronger than a change of variables and reported as such.
    #[test]
    fn damped_euler_is_the_y_first_symplectic_euler() {
        let y_first = derive("method y_first\nstate v y\ny = y + Phi*v\nv = v - Phi*y\n");
        let (damped, fe) = (builtin("damped_euler"), builtin("false_euler"));
        assert_eq!(relate(&y_first, &damped), Relation::Equal);
        assert_eq!(relate(&damped, &builtin("damped_euler_matrix")), Relation::Equal);
        for m in [&damped, &y_first] {
            assert_eq!(
                relate(m, &fe),
                Relation::PermutationAndScaling {
                    perm: vec![1, 0],
                    scale: vec![crate::q(1, 1), crate::q(-1, 1)]
                }
            );
        }
        // With the damping ratio free, only D = Φ/2 gives False Euler's χ.
        assert_eq!(relate(&builtin("damped_euler_d"), &fe), Relation::Different);
    }

    /// Without a variable named y, the solutions of X P_a = P_b X give the
    /// change of variables; it is checked like the other.
    #[test]
    fn change_of_variables_without_an_observed_variable() {
        let a = derive("method a\nstate p q\np = p - Phi*q\nq = q + Phi*p\n");
        let b = derive("method b\nstate s\ns = 2*s - s@1 - Phi^2*s\n");
        for (x, y) in [(&a, &b), (&b, &a)] {
            let Relation::ChangeOfVariables(change) = relate(x, y) else {
                panic!("expected a change of variables")
            };
            assert_eq!(change.observed, None);
            check_change(x, y, &change);
        }
    }

    /// The relation found is a true identity: rebuilding P_b from P_a with
    /// the permutation and scaling gives P_b exactly.
    #[test]
    fn relation_reconstructs() {
        let fe = derive("method a\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n");
        let damped =
            derive("method d\nstate v y\nv1 = v - Phi*(y + Phi*v)\ny = y + Phi*v\nv = v1\n");
        let Relation::PermutationAndScaling { perm, scale } = relate(&fe, &damped) else {
            panic!("expected a signed permutation")
        };
        let pa = fe.transition_matrix();
        for i in 0..2 {
            for j in 0..2 {
                let rebuilt = pa[(perm[i], perm[j])].scale(&(&scale[i] / &scale[j]));
                assert_eq!(rebuilt, damped.transition_matrix()[(i, j)], "({i}, {j})");
            }
        }
    }
}
