//! Partitioned Runge–Kutta pairs and splittings, for q' = f(p), p' = g(q)
//! (and, for pairs, general partitioned systems q' = f(q, p), p' = g(q, p)).
//!
//! A pair's `[q]` tableau (A, b) integrates q and its `[p]` tableau (Â, b̂)
//! integrates p. On a bicolored tree, a q-vertex is f and a p-vertex g;
//! the root's colour picks b or b̂ and each child's colour picks A or Â
//! (Hairer–Lubich–Wanner III.2), and the order conditions are
//! Φ(t) = 1/γ(t) on every bicolored tree.
//!
//! A splitting drift(a₁h) kick(b₁h) … drift(a_s h) kick(b_s h), with
//! drift q += a h f(p) and kick p += b h g(q), is the pair with s + 1
//! stages Y_m = Q_(m−1), Z_m = P_(m−1) (the values before the m-th drift):
//! A_(m,i) = a_i for i < m, b = (a₁, …, a_s, 0); Â_(m,j+1) = b_j for
//! j < m, b̂ = (0, b₁, …, b_s). Its order is read on the trees whose
//! adjacent vertices alternate colour, the separable systems it is made
//! for; the tests hold both against Taylor expansions of the steps.

use super::conditions::Weights;
use super::report::{bounded, shape, within, Kind, Options, Order, OrderReport};
use super::rk::{self, equal_up_to_permutation, Rk};
use super::trees::{forest, Kind as Forest};
use super::value::{read, read_matrix, Matrix, Value};
use crate::error::Error;
use crate::lang::tableau::{Exact, Tableau};
use crate::Q;

/// The order on linear separable systems (the oscillator): the alternating
/// chains, whose conditions are b_c·M_(c')·M_c⋯e = 1/k! for the two root
/// colours c, checked up to `cap`.
fn linear_order(a: &[Matrix; 2], b: &[Vec<Value>; 2], cap: usize) -> Order {
    let s = b[0].len();
    // v[c] = M_c M_(c') ⋯ e with k − 1 matrices, the first of colour c.
    let mut v = [vec![Value::one(); s], vec![Value::one(); s]];
    let mut fact = Q::from_integer(1.into());
    for k in 1..=cap {
        fact *= Q::from_integer((k as u64).into());
        let target = Value::from(fact.recip());
        // Root colour c: b_c · (M_(1−c) M_c ⋯ e), the chain below the root
        // starting with the other colour.
        for c in 0..2 {
            if rk::dot(&b[c], &v[1 - c]) != target {
                return Order::Exact(k - 1);
            }
        }
        let next = [rk::mat_vec(&a[0], &v[1]), rk::mat_vec(&a[1], &v[0])];
        v = next;
    }
    Order::AtLeast(cap)
}

/// The order report of a partitioned Runge–Kutta pair: `q` integrates q
/// (HLW's a, b), `p` integrates p (â, b̂); both with the same number of
/// stages.
pub fn partitioned(q: &Tableau, p: &Tableau, options: &Options) -> Result<OrderReport, Error> {
    let (aq, bq, _) = q.entries();
    let (ap, bp, _) = p.entries();
    if ap.len() != aq.len() {
        return Err(shape(format!(
            "[p] has {} stages and [q] {}: expected the same number",
            ap.len(),
            aq.len()
        )));
    }
    let s = aq.len();
    let names: Vec<String> = (1..=s).map(|i| format!("p.A[{i}]")).collect();
    let mut groups: Vec<(&str, &[Exact])> =
        ap.iter().zip(&names).map(|(r, n)| (n.as_str(), r.as_slice())).collect();
    groups.push(("q.b", bq));
    groups.push(("p.b", bp));
    let (a_q, rest) = read_matrix(aq, &groups)?;
    let a_p: Matrix = rest[..s].to_vec();
    let (b_q, b_p) = (rest[s].clone(), rest[s + 1].clone());
    let mut r = report(Kind::Partitioned, Forest::Bicolored, [a_q, a_p], [b_q, b_p], options)?;
    Ok({
        r.notes.push(
            "the order is on general partitioned systems (all bicolored trees); the linear \
             order is on linear separable systems (the oscillator)"
                .to_owned(),
        );
        r
    })
}

/// The common part: order (on the forest), linear order, symplecticity and
/// symmetry of a pair.
fn report(
    kind: Kind,
    trees: Forest,
    a: [Matrix; 2],
    b: [Vec<Value>; 2],
    options: &Options,
) -> Result<OrderReport, Error> {
    let mut notes = Vec::new();
    let f = forest(trees);
    let mut w = Weights::new(f, &a, &b);
    let (p, failing) = w.order();
    let what = if trees == Forest::Bicolored { "bicolored-tree" } else { "alternating-tree" };
    let order = bounded(p, &failing, what, &mut notes);
    let cap = 4 * b[0].len() + 4;
    let mut r = OrderReport::new(kind, order, linear_order(&a, &b, cap));
    r.order_within_tolerance = within(&mut w, options, what);
    let [a_q, a_p] = &a;
    let [b_q, b_p] = &b;
    let s = b_q.len();
    let symplectic = b_q == b_p
        && (0..s).all(|i| {
            (0..s).all(|j| {
                b_q[i]
                    .mul(&a_p[i][j])
                    .add(&b_p[j].mul(&a_q[j][i]))
                    .sub(&b_q[i].mul(&b_p[j]))
                    .is_zero()
            })
        });
    r.symplectic = Some(symplectic);
    let x = [Rk { a: a_q.clone(), b: b_q.clone() }, Rk { a: a_p.clone(), b: b_p.clone() }];
    r.symmetric = Some(equal_up_to_permutation(&x, &[x[0].adjoint(), x[1].adjoint()]));
    r.notes = notes;
    Ok(r)
}

/// One flow of a splitting: drift (q) or kick (p), and its coefficient.
type Flow = (bool, Value);

/// The flow sequence with zero coefficients dropped and neighbours of one
/// kind merged, until neither changes it.
fn normal_flows(drift: &[Value], kick: &[Value]) -> Vec<Flow> {
    let mut flows: Vec<Flow> =
        drift.iter().zip(kick).flat_map(|(a, b)| [(true, a.clone()), (false, b.clone())]).collect();
    loop {
        let before = flows.len();
        flows.retain(|(_, c)| !c.is_zero());
        let mut merged: Vec<Flow> = Vec::new();
        for (kind, c) in flows {
            match merged.last_mut() {
                Some((k, last)) if *k == kind => *last = last.add(&c),
                _ => merged.push((kind, c)),
            }
        }
        flows = merged;
        if flows.len() == before {
            return flows;
        }
    }
}

/// The order report of a splitting drift(a₁h) kick(b₁h) … drift(a_s h)
/// kick(b_s h), with drift q += a h f(p) and kick p += b h g(q).
///
/// ```
/// use poly::advanced::tableau::Exact;
/// use poly::advanced::order::{splitting, Options, Order};
/// let e = |s: &str| Exact::parse(s).unwrap();
/// let verlet = splitting(&[e("1/2"), e("1/2")], &[e("1"), e("0")], &Options::default())?;
/// assert_eq!(verlet.order, Order::Exact(2));
/// assert_eq!((verlet.symplectic, verlet.symmetric), (Some(true), Some(true)));
/// # Ok::<(), poly::Error>(())
/// ```
pub fn splitting(drift: &[Exact], kick: &[Exact], options: &Options) -> Result<OrderReport, Error> {
    if drift.len() != kick.len() || drift.is_empty() {
        return Err(shape(format!(
            "drift has {} coefficients and kick {}: expected the same number, at least one",
            drift.len(),
            kick.len()
        )));
    }
    if drift.len() > crate::lang::tableau::MAX_STAGES {
        return Err(shape(format!(
            "{} flows of each kind: expected at most {}",
            drift.len(),
            crate::lang::tableau::MAX_STAGES
        )));
    }
    let v = read(&[("drift", drift), ("kick", kick)])?;
    let (d, k) = (&v[0], &v[1]);
    let s = d.len();
    let n = s + 1;
    let a_q: Matrix = (0..n)
        .map(|m| {
            (0..n).map(|i| if i < m && i < s { d[i].clone() } else { Value::zero() }).collect()
        })
        .collect();
    let a_p: Matrix = (0..n)
        .map(|m| {
            (0..n)
                .map(|c| if c >= 1 && c <= m { k[c - 1].clone() } else { Value::zero() })
                .collect()
        })
        .collect();
    let mut b_q = d.clone();
    b_q.push(Value::zero());
    let mut b_p = vec![Value::zero()];
    b_p.extend(k.iter().cloned());
    let mut r = report(Kind::Splitting, Forest::Alternating, [a_q, a_p], [b_q, b_p], options)?;
    r.symplectic = Some(true);
    let flows = normal_flows(d, k);
    let reversed: Vec<Flow> = flows.iter().rev().cloned().collect();
    r.symmetric = Some(flows == reversed);
    r.notes.push(
        "the order is on separable systems q' = f(p), p' = g(q) (bicolored trees whose adjacent \
         vertices alternate colour)"
            .to_owned(),
    );
    Ok(r)
}
