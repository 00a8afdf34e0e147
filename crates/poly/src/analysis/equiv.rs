//! Identities between methods, decided exactly: are two transition matrices
//! equal, similar by a permutation of the state, similar by a constant
//! diagonal scaling (or both), or do they merely share χ? And is one
//! program the other with its updates reordered?
//!
//! Similarity by a permutation Π and a diagonal S means
//! $$P_b = S\,\Pi P_a \Pi^T S^{-1},\quad (P_b)_{ij} = \tfrac{s_i}{s_j} (P_a)_{\pi(i)\pi(j)},$$
//! so the diagonal must agree, the zero patterns must agree, and each
//! off-diagonal ratio must be one rational constant consistent along every
//! cycle of the pattern. Every permutation is tried (the methods have at
//! most a handful of slots).

use std::collections::VecDeque;

use crate::lang::method::Operand;
use crate::{Derivation, Method, Poly, PolyMatrix, Q};

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
    /// Only the characteristic polynomials are equal.
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
    let (da, db) = (&a.p_denominator, &b.p_denominator);
    let same_den = da == db;
    let cross = |m: &PolyMatrix, d: &Poly| if same_den { m.clone() } else { m.map(|e| e * d) };
    let (pa, pb) = (&cross(&a.transition_matrix, db), &cross(&b.transition_matrix, da));
    if pa == pb {
        return Relation::Equal;
    }
    let n = pa.rows();
    if pb.rows() == n && n <= 6 {
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
    }
    let same_charpoly =
        if same_den { a.charpoly == b.charpoly } else { &a.charpoly * db == &b.charpoly * da };
    if same_charpoly {
        Relation::SameCharpoly
    } else {
        Relation::Different
    }
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
    /// The strongest relation this method bears to `other` (equal P,
    /// similar by a signed permutation or scaling, updates reordered, or
    /// the same χ only).
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
    /// matrix with the same χ that no permutation or scaling reaches.
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
        assert_eq!(relate(&fe, &verlet), Relation::SameCharpoly);
        assert_eq!(relate(&fe, &euler), Relation::Different);
        // Reordered updates: the same two assignments, y first.
        let ab = Method::parse("a", "method a\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n").unwrap();
        let ba = Method::parse("b", "method b\nstate v y\ny = y + Phi*v\nv = v - Phi*y\n").unwrap();
        assert!(reordered_updates(&ab, &ba));
        assert!(!reordered_updates(&ab, &ab));
        let other =
            Method::parse("c", "method c\nstate v y\ny = y + Phi*v\nv = v - 2*Phi*y\n").unwrap();
        assert!(!reordered_updates(&ab, &other));
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
        let pa = &fe.transition_matrix;
        for i in 0..2 {
            for j in 0..2 {
                let rebuilt = pa[(perm[i], perm[j])].scale(&(&scale[i] / &scale[j]));
                assert_eq!(rebuilt, damped.transition_matrix[(i, j)], "({i}, {j})");
            }
        }
    }
}
