//! The modified equation of a Runge–Kutta method (backward error analysis,
//! Hairer–Lubich–Wanner IX): the vector field ỹ' = f̃(ỹ) whose exact flow
//! over one step is the method's step, as a series in h.
//!
//! Coefficients here are of bare elementary differentials: the step is
//! y₁ = y₀ + Σ_t h^|t| α(t) F(t)(y₀) with α(t) = Φ(t)/σ(t), and the field
//! is h f̃ = Σ_t h^|t| β(t) F(t) with β(f) = 1. The flow of a field X over
//! time 1 is Σ_j L_X^j(id)/j!, and the Lie derivative of F(u) along
//! F(τ) is Σ_v F(u ∘_v τ), τ grafted onto each vertex v of u in turn. So
//! with (Dc)(t) = Σ_(u,τ,v: u∘_vτ = t) c(u)·β(τ),
//!
//!   α(t) = β(t) + Σ_(j≥2) (D^(j−1)β)(t) / j!,
//!
//! where the right-hand sum reads β on smaller trees only: β is solved one
//! order at a time. Explicit Euler gives −1/2 f'f, then 1/12 f''(f,f) and
//! 1/3 f'f'f (the tests hold it to HLW IX and to the Taylor expansion of
//! the modified flow on a polynomial system).

use std::collections::HashMap;

use super::conditions::Weights;
use super::report::ModifiedTerm;
use super::trees::{forest, Kind, MAX_TREE_ORDER};
use super::value::{inverse_int, Value};
use crate::error::{Error, ErrorKind};

/// The terms h^k·β(t)·F(t), k = 1..=n, of the modified equation of the
/// method whose weights are `w` (monocolored).
pub(crate) fn equation(w: &mut Weights, n: usize) -> Result<Vec<ModifiedTerm>, Error> {
    if n + 1 > MAX_TREE_ORDER {
        return Err(Error::analysis(
            ErrorKind::TreeOrder,
            format!(
                "the modified equation up to h^{n} needs trees of order {}: expected a power of \
                 at most {}",
                n + 1,
                MAX_TREE_ORDER - 1
            ),
        ));
    }
    let f = forest(Kind::Mono);
    debug_assert!(std::ptr::eq(f, w.forest()));
    let top = n + 1;
    // For each tree t: the (u, τ, count) with τ grafted onto `count`
    // vertices of u giving t.
    let mut grafts: HashMap<u32, Vec<(u32, u32, u64)>> = HashMap::new();
    for u in f.range(1).start..f.range(top - 1).end {
        let ou = f.trees[u].order();
        for tau in f.range(1).start..f.range(top - ou).end {
            let mut counts: HashMap<u32, u64> = HashMap::new();
            for t in f.graft_all(u as u32, tau as u32).into_iter().flatten() {
                *counts.entry(t).or_default() += 1;
            }
            for (t, c) in counts {
                grafts.entry(t).or_default().push((u as u32, tau as u32, c));
            }
        }
    }
    let total = f.range(top).end;
    // d[j][t] = (D^j β)(t); d[0] = β.
    let mut d: Vec<Vec<Value>> = vec![vec![Value::zero(); total]];
    d[0][0] = Value::one();
    let mut factorial = vec![1u64; top + 1];
    for k in 1..=top {
        factorial[k] = factorial[k - 1] * k as u64;
    }
    let mut out = Vec::new();
    for order in 2..=top {
        while d.len() < order {
            d.push(vec![Value::zero(); total]);
        }
        for t in f.range(order) {
            for j in 1..order {
                let mut acc = Value::zero();
                for &(u, tau, c) in grafts.get(&(t as u32)).map_or(&[][..], |v| v.as_slice()) {
                    let (x, y) = (&d[j - 1][u as usize], &d[0][tau as usize]);
                    if !x.is_zero() && !y.is_zero() {
                        acc =
                            acc.add(&x.mul(y).mul(&Value::from(crate::Q::from_integer(c.into()))));
                    }
                }
                d[j][t] = acc;
            }
            let tree = &f.trees[t];
            let alpha = w.phi(t).mul(&inverse_int(tree.symmetry()));
            let mut beta = alpha;
            for j in 1..order {
                beta = beta.sub(&d[j][t].mul(&inverse_int(factorial[j + 1])));
            }
            d[0][t] = beta.clone();
            out.push(ModifiedTerm {
                power: order - 1,
                tree: tree.notation().to_owned(),
                differential: tree.differential().to_owned(),
                coefficient: beta,
            });
        }
    }
    Ok(out)
}
