//! Elementary weights and the order conditions Φ(t) = 1/γ(t), on any of the
//! cached forests, for one tableau (one colour) or a partitioned pair (two).
//!
//! The stage vector of a tree is g_t = ∏ over its children c of M_c·g_c
//! (componentwise), M_c the matrix of the child's colour (A for a q-vertex,
//! Â for a p-vertex), g = 1 for a leaf; the weight is Φ(t) = b·g_t with the
//! root's colour's weights. Each tree's M·g is kept for its parents, so a
//! tree costs one sparse matrix–vector product, and trees are computed one
//! order at a time, only as far as a question needs.
//!
//! Rational entries take an integer route: with A = Â/d and b = b̂/d_b over
//! common denominators, Φ(t) = b̂·ĝ_t / (d_b·d^(|t|−1)), so the condition is
//! one integer identity b̂·ĝ_t·γ(t) = d_b·d^(|t|−1) and no rational is
//! reduced per product. Entries with radicals take the field route.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

use super::trees::Forest;
use super::value::{all_rational, inverse_int, Matrix, Value};
use crate::Q;

/// What the element type needs: a commutative ring.
trait Ring: Clone {
    fn zero() -> Self;
    fn one() -> Self;
    fn is_zero(&self) -> bool;
    fn add_mul(&mut self, a: &Self, b: &Self);
    fn mul(&self, o: &Self) -> Self;
}

impl Ring for BigInt {
    fn zero() -> Self {
        Zero::zero()
    }
    fn one() -> Self {
        One::one()
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn add_mul(&mut self, a: &Self, b: &Self) {
        *self += a * b;
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
}

impl Ring for Value {
    fn zero() -> Self {
        Value::zero()
    }
    fn one() -> Self {
        Value::one()
    }
    fn is_zero(&self) -> bool {
        Value::is_zero(self)
    }
    fn add_mul(&mut self, a: &Self, b: &Self) {
        *self = self.add(&Value::mul(a, b));
    }
    fn mul(&self, o: &Self) -> Self {
        Value::mul(self, o)
    }
}

/// The recursion on one ring: per colour, A's nonzero entries row by row
/// and b; per tree computed, M·g and b·g.
struct Engine<R> {
    rows: Vec<Vec<Vec<(usize, R)>>>,
    b: Vec<Vec<R>>,
    mg: Vec<Vec<R>>,
    raw: Vec<R>,
}

impl<R: Ring> Engine<R> {
    fn new(a: Vec<Vec<Vec<R>>>, b: Vec<Vec<R>>) -> Engine<R> {
        let rows = a
            .into_iter()
            .map(|m| {
                m.into_iter()
                    .map(|row| row.into_iter().enumerate().filter(|(_, x)| !x.is_zero()).collect())
                    .collect()
            })
            .collect();
        Engine { rows, b, mg: Vec::new(), raw: Vec::new() }
    }

    /// Computes every tree of the forest up to index `end`.
    fn extend(&mut self, forest: &Forest, end: usize) {
        let s = self.b[0].len();
        for t in self.raw.len()..end {
            let tree = &forest.trees[t];
            let mut g = vec![R::one(); s];
            for &c in tree.children() {
                let mc = &self.mg[c as usize];
                for (gi, x) in g.iter_mut().zip(mc) {
                    *gi = gi.mul(x);
                }
            }
            let colour = tree.colour() as usize;
            let mut raw = R::zero();
            for (bi, gi) in self.b[colour].iter().zip(&g) {
                if !bi.is_zero() {
                    raw.add_mul(bi, gi);
                }
            }
            let mg = self.rows[colour]
                .iter()
                .map(|row| {
                    let mut acc = R::zero();
                    for (j, a) in row {
                        acc.add_mul(a, &g[*j]);
                    }
                    acc
                })
                .collect();
            self.mg.push(mg);
            self.raw.push(raw);
        }
    }
}

enum Route {
    /// A = Â/d, b = b̂/d_b; `scales[e]` = d_b·d^e, as far as asked.
    Integer {
        engine: Engine<BigInt>,
        d: BigInt,
        scales: Vec<BigInt>,
    },
    Field(Engine<Value>),
}

/// The elementary weights of one method on one forest, computed lazily.
pub(crate) struct Weights {
    forest: &'static Forest,
    route: Route,
}

/// The least common multiple of the denominators, and the integers scaled by it.
fn scale(values: &[&Value]) -> (BigInt, Vec<BigInt>) {
    let qs: Vec<&Q> = values.iter().map(|v| v.as_rational().expect("rational")).collect();
    let d = qs.iter().fold(<BigInt as One>::one(), |l, q| l.lcm(q.denom()));
    let ints = qs.iter().map(|q| q.numer() * (&d / q.denom())).collect();
    (d, ints)
}

/// d_b·d^e, from the powers kept so far.
fn scale_of<'a>(scales: &'a mut Vec<BigInt>, d: &BigInt, e: usize) -> &'a BigInt {
    while scales.len() <= e {
        let next = scales.last().expect("db") * d;
        scales.push(next);
    }
    &scales[e]
}

impl Weights {
    /// The weights of the method with `a[colour]` and `b[colour]` (one
    /// colour for a tableau, two for a partitioned pair: q then p).
    pub(crate) fn new(forest: &'static Forest, a: &[Matrix], b: &[Vec<Value>]) -> Weights {
        let rational =
            all_rational(a.iter().flatten().flatten()) && all_rational(b.iter().flatten());
        let route = if rational {
            let (d, flat_a) = scale(&a.iter().flatten().flatten().collect::<Vec<_>>());
            let (db, flat_b) = scale(&b.iter().flatten().collect::<Vec<_>>());
            let s = b[0].len();
            let mut it = flat_a.into_iter();
            let ma: Vec<Vec<Vec<BigInt>>> = a
                .iter()
                .map(|m| m.iter().map(|_| it.by_ref().take(s).collect()).collect())
                .collect();
            let mut it = flat_b.into_iter();
            let mb: Vec<Vec<BigInt>> = b.iter().map(|_| it.by_ref().take(s).collect()).collect();
            Route::Integer { engine: Engine::new(ma, mb), scales: vec![db], d }
        } else {
            Route::Field(Engine::new(a.to_vec(), b.to_vec()))
        };
        Weights { forest, route }
    }

    pub(crate) fn forest(&self) -> &'static Forest {
        self.forest
    }

    fn ensure(&mut self, t: usize) {
        let end = t + 1;
        match &mut self.route {
            Route::Integer { engine, .. } => {
                if engine.raw.len() < end {
                    engine.extend(self.forest, end)
                }
            }
            Route::Field(engine) => {
                if engine.raw.len() < end {
                    engine.extend(self.forest, end)
                }
            }
        }
    }

    /// Φ(t) for the tree of index `t`.
    pub(crate) fn phi(&mut self, t: usize) -> Value {
        self.ensure(t);
        let edges = self.forest.trees[t].order() - 1;
        match &mut self.route {
            Route::Integer { engine, d, scales } => {
                Value::from(Q::new(engine.raw[t].clone(), scale_of(scales, d, edges).clone()))
            }
            Route::Field(engine) => engine.raw[t].clone(),
        }
    }

    /// Φ(t) − 1/γ(t).
    pub(crate) fn residual(&mut self, t: usize) -> Value {
        let gamma = self.forest.trees[t].density();
        self.phi(t).sub(&inverse_int(gamma))
    }

    /// Whether Φ(t) = 1/γ(t).
    pub(crate) fn holds(&mut self, t: usize) -> bool {
        self.ensure(t);
        let tree = &self.forest.trees[t];
        match &mut self.route {
            Route::Integer { engine, d, scales, .. } => {
                let scale = scale_of(scales, d, tree.order() - 1);
                &engine.raw[t] * BigInt::from(tree.density()) == *scale
            }
            Route::Field(_) => self.residual(t).is_zero(),
        }
    }

    /// Whether |Φ(t) − 1/γ(t)| ≤ `tolerance`: on the integer route, the one
    /// identity q·|b̂·ĝ_t·γ − d_b·d^(|t|−1)| ≤ p·γ·d_b·d^(|t|−1) for
    /// tolerance = p/q, so no rational is reduced.
    pub(crate) fn holds_within(&mut self, t: usize, tolerance: &Q) -> bool {
        self.ensure(t);
        let tree = &self.forest.trees[t];
        match &mut self.route {
            Route::Integer { engine, d, scales, .. } => {
                let scale = scale_of(scales, d, tree.order() - 1);
                let gamma = BigInt::from(tree.density());
                let gap = (&engine.raw[t] * &gamma - scale).abs();
                gap * tolerance.denom() <= tolerance.numer() * gamma * scale
            }
            Route::Field(_) => self.residual(t).within(tolerance),
        }
    }

    /// The classical order on this forest: `(p, failing)` with every
    /// condition up to order p holding and `failing` the indices of the
    /// trees of order p + 1 that fail; `failing` is empty when every
    /// condition up to the forest's maximum holds (p is then that maximum,
    /// a lower bound).
    pub(crate) fn order(&mut self) -> (usize, Vec<usize>) {
        self.order_by(|w, t| w.holds(t))
    }

    /// The order whose conditions hold to within `tolerance`:
    /// |Φ(t) − 1/γ(t)| ≤ tolerance.
    pub(crate) fn order_within(&mut self, tolerance: &Q) -> (usize, Vec<usize>) {
        self.order_by(|w, t| w.holds_within(t, tolerance))
    }

    fn order_by(&mut self, mut ok: impl FnMut(&mut Weights, usize) -> bool) -> (usize, Vec<usize>) {
        let max = self.forest.max_order();
        for n in 1..=max {
            let failing: Vec<usize> = self.forest.range(n).filter(|&t| !ok(self, t)).collect();
            if !failing.is_empty() {
                return (n - 1, failing);
            }
        }
        (max, Vec::new())
    }
}

#[cfg(test)]
mod tests {
    use super::super::trees::{forest, Kind};
    use super::*;

    fn v(n: i64, d: i64) -> Value {
        Value::from(crate::q(n, d))
    }

    /// The issue's tableau: order 2, and of order 3 only [[][]] fails, by
    /// b·c² − 1/3 = 55/144 − 1/3 = 7/144.
    #[test]
    fn issue_tableau() {
        let z = || v(0, 1);
        let a = vec![
            vec![z(), z(), z(), z()],
            vec![v(1, 1), z(), z(), z()],
            vec![z(), v(1, 2), z(), z()],
            vec![z(), z(), v(1, 3), z()],
        ];
        let b = vec![v(5, 24), v(7, 24), v(1, 4), v(1, 4)];
        let mut w = Weights::new(forest(Kind::Mono), &[a], &[b]);
        let (p, failing) = w.order();
        assert_eq!(p, 2);
        let names: Vec<&str> =
            failing.iter().map(|&t| forest(Kind::Mono).trees[t].notation()).collect();
        assert_eq!(names, ["[[][]]"]);
        assert_eq!(w.residual(failing[0]), v(7, 144));
        assert_eq!(w.order_within(&crate::q(7, 144)).0, 3);
    }
}
