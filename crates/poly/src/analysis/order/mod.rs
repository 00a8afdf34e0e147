//! Order conditions beyond y' = λy: the classical order of a Runge–Kutta
//! method by rooted trees, and the questions an analyst asks next (stage
//! order, algebraic stability, symplecticity, symmetry, the SSP
//! coefficient, embedded pairs, the modified equation), for Runge–Kutta
//! tableaux, partitioned Runge–Kutta pairs, splittings and linear multistep
//! methods, all decided exactly.
//!
//! One function per kind of input, each giving an [`OrderReport`]:
//! [`runge_kutta`] (a [`Tableau`], with `bhat` for an embedded pair),
//! [`partitioned`] (the `[q]` and `[p]` tableaux), [`splitting`] (drift and
//! kick coefficients) and [`multistep`]. The pieces are public too:
//! [`trees`], [`elementary_weights`], [`positive_semidefinite`],
//! [`ssp_coefficient`] and its oracle [`absolutely_monotone_at`].
//!
//! ```
//! use poly::advanced::tableau::{Exact, Tableau};
//! let e = |s: &str| Exact::parse(s).unwrap();
//! let rows = [["0", "0", "0", "0"], ["1", "0", "0", "0"], ["0", "1/2", "0", "0"], ["0", "0", "1/3", "0"]];
//! let a = rows.iter().map(|r| r.iter().map(|x| e(x)).collect()).collect();
//! let b = ["5/24", "7/24", "1/4", "1/4"].iter().map(|x| e(x)).collect();
//! let t = Tableau::new("issue35", a, b, None)?;
//! use poly::advanced::order::{runge_kutta, Options, Order};
//! let r = runge_kutta(&t, None, &Options::default())?;
//! assert_eq!(r.order, Order::Exact(2));
//! assert_eq!(r.linear_order, Order::Exact(4));
//! let failed = &r.failed_conditions.as_ref().unwrap()[0];
//! assert_eq!((failed.tree.as_str(), failed.residual.to_string()), ("[[][]]", "7/144".into()));
//! # Ok::<(), poly::Error>(())
//! ```

mod conditions;
mod modified;
mod partitioned;
mod psd;
mod report;
mod rk;
mod ssp;
mod trees;
mod value;

use crate::error::{Error, ErrorKind};
use crate::lang::multistep::Multistep;
use crate::lang::tableau::{Exact, Tableau};
use crate::Q;

use conditions::Weights;
use report::{bounded, shape, within};
use rk::Rk;
use trees::{forest, Kind as Forest};
use value::read_matrix;

pub use partitioned::{partitioned, splitting};
pub use psd::positive_semidefinite;
pub use report::{
    FailedCondition, Kind, ModifiedTerm, Options, Order, OrderReport, Ssp, ToleranceOrder,
};
pub use ssp::{absolutely_monotone_at, ssp_coefficient};
pub use trees::{trees, Tree, MAX_BICOLORED_ORDER, MAX_SEPARABLE_ORDER, MAX_TREE_ORDER};
pub use value::Value;

/// The order report of a Runge–Kutta tableau, or of an embedded pair when
/// `bhat` is given (one entry per stage).
pub fn runge_kutta(
    tableau: &Tableau,
    bhat: Option<&[Exact]>,
    options: &Options,
) -> Result<OrderReport, Error> {
    let (a_e, b_e, c_e) = tableau.entries();
    let s = b_e.len();
    if let Some(bh) = bhat {
        if bh.len() != s {
            return Err(shape(format!(
                "bhat has {} entries: expected {s}, one per stage",
                bh.len()
            )));
        }
    }
    let mut groups: Vec<(&str, &[Exact])> = vec![("b", b_e)];
    groups.extend(c_e.map(|c| ("c", c)));
    groups.extend(bhat.map(|bh| ("bhat", bh)));
    let (a, rest) = read_matrix(a_e, &groups)?;
    let b = rest[0].clone();
    let rk = Rk { a, b };
    let c = if c_e.is_some() { rest[1].clone() } else { rk.row_sums() };
    let bhat = bhat.map(|_| rest[rest.len() - 1].clone());
    let kind = if bhat.is_some() { Kind::EmbeddedPair } else { Kind::RungeKutta };

    let mut notes = Vec::new();
    let mut w = Weights::new(
        forest(Forest::Mono),
        std::slice::from_ref(&rk.a),
        std::slice::from_ref(&rk.b),
    );
    let (p, failing) = w.order();
    let order = bounded(p, &failing, "rooted-tree", &mut notes);
    let mut r = OrderReport::new(kind, order, Order::Exact(rk::linear_order(&rk.a, &rk.b)));
    let trees = &forest(Forest::Mono).trees;
    r.failed_conditions = Some(
        failing
            .iter()
            .map(|&t| FailedCondition {
                tree: trees[t].notation().to_owned(),
                differential: trees[t].differential().to_owned(),
                residual: w.residual(t),
            })
            .collect(),
    );
    if let Some(rows) = tableau.c_mismatch().filter(|r| !r.is_empty()) {
        notes.push(format!(
            "c differs from A's row sums in row(s) {rows:?}: the tree conditions read A alone \
             (an autonomous system never reads c); the stage order reads the given c"
        ));
    }
    r.stage_order = Some(rk.stage_order(&c));
    r.algebraically_stable = Some(rk.algebraically_stable());
    // Reduction, M = 0 and symmetry are scale-free: a rational tableau is
    // asked on integers.
    let (symplectic, symmetric, reduced_stages) = match rk::scaled(&rk) {
        Some(int) => reduced_questions(&int),
        None => reduced_questions(&rk),
    };
    let reducible = reduced_stages < rk.stages();
    r.symplectic = Some(symplectic);
    r.reducible = Some(reducible);
    if reducible {
        notes.push(format!(
            "the tableau is reducible ({} stages to {}): symplecticity and symmetry are decided \
             on the reduced tableau (M = 0 there; M = 0 on a reducible tableau is sufficient, \
             not necessary)",
            rk.stages(),
            reduced_stages
        ));
    }
    r.symmetric = Some(symmetric);
    match ssp::coefficient(&rk.a, &rk.b) {
        Ok(x) => r.ssp_coefficient = Some(x),
        Err(e) if e.kind() == ErrorKind::Unsupported => notes.push(e.message().to_owned()),
        Err(e) => return Err(e),
    }
    if let Some(bh) = &bhat {
        let mut we = Weights::new(
            forest(Forest::Mono),
            std::slice::from_ref(&rk.a),
            std::slice::from_ref(bh),
        );
        let (p, failing) = we.order();
        r.embedded_order = Some(bounded(p, &failing, "embedded rooted-tree", &mut notes));
        r.embedded_linear_order = Some(Order::Exact(rk::linear_order(&rk.a, bh)));
        r.embedded_order_within_tolerance = within(&mut we, options, "embedded rooted-tree");
    }
    if let Some(n) = options.modified {
        r.modified_equation = Some(modified::equation(&mut w, n)?);
    }
    r.order_within_tolerance = within(&mut w, options, "rooted-tree");
    r.notes = notes;
    Ok(r)
}

/// M = 0 and symmetry, asked of the reduced tableau, and its stage count.
fn reduced_questions<T: rk::Entry>(rk: &Rk<T>) -> (bool, bool, usize) {
    let (reduced, _) = rk.reduced();
    let symmetric =
        rk::equal_up_to_permutation(std::slice::from_ref(&reduced), &[reduced.adjoint()]);
    (reduced.m_is_zero(), symmetric, reduced.stages())
}

/// Φ(t) for every monocolored tree of order 1 to `max_order`, in the order
/// of [`trees`]: the B-series coefficients of the tableau's step,
/// y₁ = y₀ + Σ_t h^|t| Φ(t)/σ(t) F(t)(y₀).
pub fn elementary_weights(
    tableau: &Tableau,
    max_order: usize,
) -> Result<Vec<(&'static Tree, Value)>, Error> {
    trees(max_order)?;
    let (a_e, b_e, _) = tableau.entries();
    let (a, rest) = read_matrix(a_e, &[("b", b_e)])?;
    let f = forest(Forest::Mono);
    let mut w = Weights::new(f, &[a], &[rest[0].clone()]);
    Ok((1..=max_order).flat_map(|n| f.range(n)).map(|t| (&f.trees[t], w.phi(t))).collect())
}

/// The order report of a linear multistep method: the order by C_q = 0,
/// which is also its linear order.
pub fn multistep(method: &Multistep, options: &Options) -> Result<OrderReport, Error> {
    let _ = options;
    let (alpha, beta) = method.coefficients();
    let v = value::read(&[("alpha", alpha), ("beta", beta)])?;
    let (alpha, beta) = (&v[0], &v[1]);
    let k = alpha.len() - 1;
    // C_q ∝ Σ_j j^q α_j − q j^(q−1) β_j (0^0 = 1); a k-step method has
    // order at most 2k, so the loop ends on a failure.
    let mut p = 0;
    for q in 0..=2 * k + 2 {
        let mut c = Value::zero();
        for j in 0..=k {
            let jq = Value::from(Q::from_integer(num_traits::pow(num_bigint::BigInt::from(j), q)));
            c = c.add(&jq.mul(&alpha[j]));
            if q > 0 {
                let jq1 = Value::from(Q::from_integer(num_traits::pow(
                    num_bigint::BigInt::from(j),
                    q - 1,
                )));
                let qq = Value::from(Q::from_integer((q as u64).into()));
                c = c.sub(&qq.mul(&jq1).mul(&beta[j]));
            }
        }
        if !c.is_zero() {
            break;
        }
        p = q;
        if q == 2 * k + 2 {
            break;
        }
    }
    Ok(OrderReport::new(Kind::Multistep, Order::Exact(p), Order::Exact(p)))
}
