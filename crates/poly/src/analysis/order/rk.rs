//! The questions of a Runge–Kutta tableau beside its tree order: linear
//! order, stage order, algebraic stability, symplecticity and symmetry, with
//! the reductions (Dahlquist–Jeltsch and Stetter's S-reduction) that make
//! the last two exact.
//!
//! An irreducible method is symplectic exactly when M = BA + AᵀB − bbᵀ = 0
//! (Hairer–Lubich–Wanner VI.7), and two irreducible methods define the same
//! map exactly when their tableaux agree up to a permutation of stages
//! (Butcher), so both questions are asked of the reduced tableau: the
//! answer is then about the method, not about how it is written.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_traits::Zero;

use super::psd::positive_semidefinite;
use super::value::{over_common, Matrix, Value};
use crate::arith::int::{dot as int_dot, Int};
use crate::Q;

/// The entries a tableau's scale-free questions (reduction, symmetry,
/// M = 0, the sign of M's diagonal) are asked over: exact values, or the
/// integers of a rational tableau scaled by one common denominator (the
/// answers are the same, and no rational is reduced).
pub(crate) trait Entry: Clone + PartialEq {
    fn nil() -> Self;
    fn is_nil(&self) -> bool;
    fn plus(&self, o: &Self) -> Self;
    fn minus(&self, o: &Self) -> Self;
    fn times(&self, o: &Self) -> Self;
    fn signum(&self) -> Ordering;
}

impl Entry for Value {
    fn nil() -> Self {
        Value::zero()
    }
    fn is_nil(&self) -> bool {
        Value::is_zero(self)
    }
    fn plus(&self, o: &Self) -> Self {
        Value::add(self, o)
    }
    fn minus(&self, o: &Self) -> Self {
        Value::sub(self, o)
    }
    fn times(&self, o: &Self) -> Self {
        Value::mul(self, o)
    }
    fn signum(&self) -> Ordering {
        Value::sign(self)
    }
}

impl Entry for BigInt {
    fn nil() -> Self {
        Zero::zero()
    }
    fn is_nil(&self) -> bool {
        Zero::is_zero(self)
    }
    fn plus(&self, o: &Self) -> Self {
        self + o
    }
    fn minus(&self, o: &Self) -> Self {
        self - o
    }
    fn times(&self, o: &Self) -> Self {
        self * o
    }
    fn signum(&self) -> Ordering {
        self.cmp(&Zero::zero())
    }
}

fn sum<T: Entry>(xs: &[T]) -> T {
    xs.iter().fold(T::nil(), |s, x| s.plus(x))
}

/// A tableau's exact entries.
#[derive(Clone, Debug)]
pub(crate) struct Rk<T = Value> {
    pub(crate) a: Vec<Vec<T>>,
    pub(crate) b: Vec<T>,
}

/// A rational tableau on integers: Â = D·A and b̂ = D·b with D the least
/// common multiple of every denominator; `None` when an entry is
/// irrational.
pub(crate) fn scaled(rk: &Rk) -> Option<Rk<BigInt>> {
    let qs: Vec<&Q> =
        rk.a.iter().flatten().chain(&rk.b).map(Value::as_rational).collect::<Option<_>>()?;
    let (_, ints) = over_common(&qs);
    let s = rk.b.len();
    let mut it = ints.into_iter();
    Some(Rk { a: (0..s).map(|_| it.by_ref().take(s).collect()).collect(), b: it.collect() })
}

/// [`linear_order`] on integers, when A and b are rational: with A = Â/d,
/// b = b̂/d_b, bᵀA^(k−1)e = 1/k! is k!·b̂ᵀÂ^(k−1)e = d_b·d^(k−1).
fn linear_order_int(a: &Matrix, b: &[Value]) -> Option<usize> {
    let qa: Vec<&Q> = a.iter().flatten().map(Value::as_rational).collect::<Option<_>>()?;
    let qb: Vec<&Q> = b.iter().map(Value::as_rational).collect::<Option<_>>()?;
    let s = b.len();
    let (d, ai) = ints(&qa);
    let (db, bi) = ints(&qb);
    let rows: Vec<Vec<(usize, &Int)>> = (0..s)
        .map(|i| (0..s).map(|j| (j, &ai[i * s + j])).filter(|(_, x)| !x.is_zero()).collect())
        .collect();
    let mut v = vec![Int::ONE; s];
    let (mut fact, mut scale) = (Int::ONE, db);
    for k in 1..=2 * s + 2 {
        fact = fact.mul(&Int::from(k));
        if fact.mul(&int_dot(bi.iter().zip(&v))) != scale {
            return Some(k - 1);
        }
        v = rows.iter().map(|r| int_dot(r.iter().map(|(j, x)| (*x, &v[*j])))).collect();
        scale = scale.mul(&d);
    }
    Some(2 * s + 2)
}

/// [`over_common`] as [`Int`]s.
fn ints(xs: &[&Q]) -> (Int, Vec<Int>) {
    let (d, v) = over_common(xs);
    (Int::from_big(d), v.into_iter().map(Int::from_big).collect())
}

/// 1/k! as a value.
fn inverse_factorial(k: usize) -> Value {
    let f: num_bigint::BigInt = (1..=k as u64).map(num_bigint::BigInt::from).product();
    Value::from(Q::new(1.into(), f))
}

/// A·v.
pub(crate) fn mat_vec(a: &Matrix, v: &[Value]) -> Vec<Value> {
    a.iter()
        .map(|row| {
            row.iter()
                .zip(v)
                .filter(|(x, y)| !x.is_zero() && !y.is_zero())
                .fold(Value::zero(), |s, (x, y)| s.add(&x.mul(y)))
        })
        .collect()
}

/// u·v.
pub(crate) fn dot(u: &[Value], v: &[Value]) -> Value {
    u.iter()
        .zip(v)
        .filter(|(x, y)| !x.is_zero() && !y.is_zero())
        .fold(Value::zero(), |s, (x, y)| s.add(&x.mul(y)))
}

/// The order of R(z) = 1 + z bᵀ(I − zA)⁻¹e against e^z: the largest p with
/// bᵀA^(k−1)e = 1/k! for every k ≤ p. R is rational of type (s, s), so
/// p ≤ 2s and the loop always ends on a failure.
pub(crate) fn linear_order(a: &Matrix, b: &[Value]) -> usize {
    linear_order_int(a, b).unwrap_or_else(|| linear_order_values(a, b))
}

/// [`linear_order`] in exact values, for any field (the integer route's
/// oracle).
fn linear_order_values(a: &Matrix, b: &[Value]) -> usize {
    let mut v = vec![Value::one(); b.len()];
    for k in 1..=2 * b.len() + 2 {
        if dot(b, &v) != inverse_factorial(k) {
            return k - 1;
        }
        v = mat_vec(a, &v);
    }
    2 * b.len() + 2
}

impl Rk {
    pub(crate) fn row_sums(&self) -> Vec<Value> {
        self.a.iter().map(|row| Value::sum(row.iter())).collect()
    }

    /// The largest q with b·c^(k−1) = 1/k and A c^(k−1) = c^k/k for every
    /// k ≤ q (at most 2s: b·c^(k−1) = 1/k for k ≤ 2s + 1 is impossible).
    pub(crate) fn stage_order(&self, c: &[Value]) -> usize {
        self.stage_order_int(c).unwrap_or_else(|| self.stage_order_values(c))
    }

    /// [`Rk::stage_order`] in exact values, for any field (the integer
    /// route's oracle).
    fn stage_order_values(&self, c: &[Value]) -> usize {
        let mut ck1 = vec![Value::one(); self.stages()];
        for k in 1..=2 * self.stages() + 1 {
            let ck: Vec<Value> = ck1.iter().zip(c).map(|(x, y)| x.mul(y)).collect();
            let inv_k = Value::from(Q::new(1.into(), (k as u64).into()));
            let stage = mat_vec(&self.a, &ck1).iter().zip(&ck).all(|(l, r)| *l == r.mul(&inv_k));
            if dot(&self.b, &ck1) != inv_k || !stage {
                return k - 1;
            }
            ck1 = ck;
        }
        2 * self.stages() + 1
    }

    /// [`Rk::stage_order`] on integers, when A, b and c are rational: with
    /// A = Â/d, b = b̂/d_b, c = ĉ/d_c, b·c^(k−1) = 1/k is
    /// k·b̂·ĉ^(k−1) = d_b·d_c^(k−1), and A c^(k−1) = c^k/k is
    /// k·d_c·(Â ĉ^(k−1))_i = d·ĉ_i^k.
    fn stage_order_int(&self, c: &[Value]) -> Option<usize> {
        let qa: Vec<&Q> = self.a.iter().flatten().map(Value::as_rational).collect::<Option<_>>()?;
        let qb: Vec<&Q> = self.b.iter().map(Value::as_rational).collect::<Option<_>>()?;
        let qc: Vec<&Q> = c.iter().map(Value::as_rational).collect::<Option<_>>()?;
        let s = self.stages();
        let (d, ai) = ints(&qa);
        let (db, bi) = ints(&qb);
        let (dc, ci) = ints(&qc);
        let mut ck1 = vec![Int::ONE; s];
        let mut dck1 = Int::ONE;
        for k in 1..=2 * s + 1 {
            let kk = Int::from(k);
            let ck: Vec<Int> = ck1.iter().zip(&ci).map(|(x, y)| x.mul(y)).collect();
            let weights = kk.mul(&int_dot(bi.iter().zip(&ck1))) == db.mul(&dck1);
            let kdc = kk.mul(&dc);
            let stage = weights
                && (0..s).all(|i| {
                    let row = int_dot((0..s).map(|j| (&ai[i * s + j], &ck1[j])));
                    kdc.mul(&row) == d.mul(&ck[i])
                });
            if !stage {
                return Some(k - 1);
            }
            ck1 = ck;
            dck1 = dck1.mul(&dc);
        }
        Some(2 * s + 1)
    }

    /// b ≥ 0 and M positive semidefinite, decided exactly. A negative
    /// diagonal entry of M (M_ii = −b_i² on an explicit tableau) decides it
    /// before M is formed; a rational tableau is asked on integers.
    pub(crate) fn algebraically_stable(&self) -> bool {
        match scaled(self) {
            Some(int) => int.algebraically_stable_by(|m| {
                m.iter()
                    .map(|r| r.iter().map(|x| Value::from(Q::from_integer(x.clone()))).collect())
                    .collect()
            }),
            None => self.algebraically_stable_by(|m| m.to_vec()),
        }
    }
}

impl<T: Entry> Rk<T> {
    pub(crate) fn stages(&self) -> usize {
        self.b.len()
    }

    /// M_ij = b_i a_ij + b_j a_ji − b_i b_j.
    fn m_entry(&self, i: usize, j: usize) -> T {
        let (a, b) = (&self.a, &self.b);
        b[i].times(&a[i][j]).plus(&b[j].times(&a[j][i])).minus(&b[i].times(&b[j]))
    }

    /// M = BA + AᵀB − bbᵀ.
    pub(crate) fn m_matrix(&self) -> Vec<Vec<T>> {
        let s = self.stages();
        (0..s).map(|i| (0..s).map(|j| self.m_entry(i, j)).collect()).collect()
    }

    /// b ≥ 0 and M (read as values by `values`) positive semidefinite.
    fn algebraically_stable_by(&self, values: impl Fn(&[Vec<T>]) -> Matrix) -> bool {
        self.b.iter().all(|x| x.signum() != Ordering::Less)
            && (0..self.stages()).all(|i| self.m_entry(i, i).signum() != Ordering::Less)
            && positive_semidefinite(&values(&self.m_matrix())).expect("square")
    }

    /// The tableau with Dahlquist–Jeltsch reduction (stages no weighted
    /// stage depends on, dropped) and S-reduction (stages in one class of
    /// the coarsest partition with equal class row sums, merged) applied
    /// until neither changes it; `true` when anything was reduced.
    pub(crate) fn reduced(&self) -> (Rk<T>, bool) {
        let mut rk = self.clone();
        let mut changed = false;
        loop {
            let s = rk.stages();
            rk = rk.dj_reduced().s_reduced();
            if rk.stages() == s {
                return (rk, changed);
            }
            changed = true;
        }
    }

    fn dj_reduced(&self) -> Rk<T> {
        let s = self.stages();
        let mut needed: Vec<bool> = self.b.iter().map(|x| !x.is_nil()).collect();
        let mut stack: Vec<usize> = (0..s).filter(|&i| needed[i]).collect();
        while let Some(i) = stack.pop() {
            for (j, aij) in self.a[i].iter().enumerate() {
                if !needed[j] && !aij.is_nil() {
                    needed[j] = true;
                    stack.push(j);
                }
            }
        }
        let keep: Vec<usize> = (0..s).filter(|&i| needed[i]).collect();
        Rk {
            a: keep.iter().map(|&i| keep.iter().map(|&j| self.a[i][j].clone()).collect()).collect(),
            b: keep.iter().map(|&i| self.b[i].clone()).collect(),
        }
    }

    fn s_reduced(&self) -> Rk<T> {
        let s = self.stages();
        let mut class = vec![0usize; s];
        let mut count = 1;
        loop {
            let sig: Vec<(usize, Vec<T>)> = (0..s)
                .map(|i| {
                    let mut sums = vec![T::nil(); count];
                    for j in 0..s {
                        sums[class[j]] = sums[class[j]].plus(&self.a[i][j]);
                    }
                    (class[i], sums)
                })
                .collect();
            let mut reps: Vec<usize> = Vec::new();
            let mut next = vec![0usize; s];
            for i in 0..s {
                match reps.iter().position(|&r| sig[r] == sig[i]) {
                    Some(k) => next[i] = k,
                    None => {
                        next[i] = reps.len();
                        reps.push(i);
                    }
                }
            }
            let done = reps.len() == count;
            class = next;
            count = reps.len();
            if done {
                let a = reps
                    .iter()
                    .map(|&i| {
                        let mut row = vec![T::nil(); count];
                        for j in 0..s {
                            row[class[j]] = row[class[j]].plus(&self.a[i][j]);
                        }
                        row
                    })
                    .collect();
                let mut b = vec![T::nil(); count];
                for i in 0..s {
                    b[class[i]] = b[class[i]].plus(&self.b[i]);
                }
                return Rk { a, b };
            }
        }
    }

    /// M = 0 (asked of the reduced tableau by the caller).
    pub(crate) fn m_is_zero(&self) -> bool {
        let s = self.stages();
        (0..s).all(|i| (i..s).all(|j| self.m_entry(i, j).is_nil()))
    }

    /// The adjoint: a*_ij = b_(s+1−j) − a_(s+1−i, s+1−j), b*_i = b_(s+1−i).
    pub(crate) fn adjoint(&self) -> Rk<T> {
        let s = self.stages();
        let r = |i: usize| s - 1 - i;
        Rk {
            a: (0..s)
                .map(|i| (0..s).map(|j| self.b[r(j)].minus(&self.a[r(i)][r(j)])).collect())
                .collect(),
            b: (0..s).map(|i| self.b[r(i)].clone()).collect(),
        }
    }
}

/// Whether the methods `x` and `y` (one tableau per colour, sharing their
/// stages) are equal up to one permutation of the stages, by backtracking
/// over the stages whose weights, row sums and diagonal entries agree.
pub(crate) fn equal_up_to_permutation<T: Entry>(x: &[Rk<T>], y: &[Rk<T>]) -> bool {
    let s = x[0].stages();
    if y[0].stages() != s {
        return false;
    }
    let key = |m: &[Rk<T>], i: usize| -> Vec<T> {
        m.iter().flat_map(|rk| [rk.b[i].clone(), sum(&rk.a[i]), rk.a[i][i].clone()]).collect()
    };
    let kx: Vec<Vec<T>> = (0..s).map(|i| key(x, i)).collect();
    let ky: Vec<Vec<T>> = (0..s).map(|i| key(y, i)).collect();
    let candidates: Vec<Vec<usize>> =
        (0..s).map(|i| (0..s).filter(|&k| kx[i] == ky[k]).collect()).collect();
    let mut image = vec![usize::MAX; s];
    let mut used = vec![false; s];
    fn place<T: Entry>(
        i: usize,
        x: &[Rk<T>],
        y: &[Rk<T>],
        candidates: &[Vec<usize>],
        image: &mut [usize],
        used: &mut [bool],
    ) -> bool {
        if i == image.len() {
            return true;
        }
        for &k in &candidates[i] {
            if used[k] {
                continue;
            }
            let fits = (0..i).all(|j| {
                let l = image[j];
                x.iter().zip(y).all(|(p, q)| p.a[i][j] == q.a[k][l] && p.a[j][i] == q.a[l][k])
            });
            if fits {
                image[i] = k;
                used[k] = true;
                if place(i + 1, x, y, candidates, image, used) {
                    return true;
                }
                used[k] = false;
            }
        }
        false
    }
    place(0, x, y, &candidates, &mut image, &mut used)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn v(n: i64, d: i64) -> Value {
        Value::from(crate::q(n, d))
    }

    proptest! {
        /// The integer routes of the linear and stage orders, and of the
        /// scale-free questions, give what exact values give, on random
        /// rational tableaux of 1 to 4 stages (entries n/d with small n, d,
        /// often the consistent ones that make the orders large).
        #[test]
        fn integer_routes_match_values(
            s in 1usize..5,
            nums in proptest::collection::vec(-3i64..4, 25),
            dens in proptest::collection::vec(1i64..5, 25),
            rowsum_c in any::<bool>(),
        ) {
            let x = |k: usize| v(nums[k], dens[k]);
            // Explicit, or (a third of the time) a full implicit matrix.
            let full = nums[23] % 3 == 0;
            let a: Matrix = (0..s)
                .map(|i| {
                    (0..s).map(|j| if j < i || full { x(i * 4 + j) } else { Value::zero() }).collect()
                })
                .collect();
            // b summing to 1 half the time, so the orders are not all 0.
            let mut b: Vec<Value> = (0..s).map(|i| x(20 + i % 5)).collect();
            if nums[24] % 2 == 0 {
                let rest = Value::sum(b[1..].iter());
                b[0] = Value::one().sub(&rest);
            }
            let rk = Rk { a: a.clone(), b: b.clone() };
            let c: Vec<Value> = if rowsum_c { rk.row_sums() } else { (0..s).map(|i| x(16 + i)).collect() };
            prop_assert_eq!(linear_order_int(&a, &b), Some(linear_order_values(&a, &b)));
            prop_assert_eq!(rk.stage_order_int(&c), Some(rk.stage_order_values(&c)));
            let int = scaled(&rk).expect("rational");
            let (ri, ci) = int.reduced();
            let (rv, cv) = rk.reduced();
            prop_assert_eq!((ri.stages(), ci), (rv.stages(), cv));
            prop_assert_eq!(ri.m_is_zero(), rv.m_is_zero());
            prop_assert_eq!(
                equal_up_to_permutation(std::slice::from_ref(&ri), &[ri.adjoint()]),
                equal_up_to_permutation(std::slice::from_ref(&rv), &[rv.adjoint()])
            );
            prop_assert_eq!(rk.algebraically_stable(), rk.algebraically_stable_by(|m| m.to_vec()));
        }
    }

    /// RK4's classical tableau: linear order 4, stage order 1, on both
    /// routes.
    #[test]
    fn rk4_orders_on_both_routes() {
        let z = Value::zero;
        let a = vec![
            vec![z(), z(), z(), z()],
            vec![v(1, 2), z(), z(), z()],
            vec![z(), v(1, 2), z(), z()],
            vec![z(), z(), v(1, 1), z()],
        ];
        let b = vec![v(1, 6), v(1, 3), v(1, 3), v(1, 6)];
        let rk = Rk { a: a.clone(), b: b.clone() };
        let c = rk.row_sums();
        assert_eq!((linear_order_int(&a, &b), linear_order_values(&a, &b)), (Some(4), 4));
        assert_eq!((rk.stage_order_int(&c), rk.stage_order_values(&c)), (Some(1), 1));
    }

    /// A two-stage order-2 pair with 21-digit entries (c₂ = p/q, b₂ =
    /// 1/(2c₂)): past i128 at the first products, the integer route goes on
    /// in big integers and agrees with the values.
    #[test]
    fn big_entries_on_both_routes() {
        let c2 = Value::from(Q::new(
            "123456789012345678901".parse().unwrap(),
            "987654321098765432109".parse().unwrap(),
        ));
        let b2 = Value::one().mul(&c2.add(&c2).inverse().unwrap());
        let a = vec![vec![Value::zero(), Value::zero()], vec![c2.clone(), Value::zero()]];
        let b = vec![Value::one().sub(&b2), b2];
        let rk = Rk { a: a.clone(), b: b.clone() };
        let c = rk.row_sums();
        assert_eq!((linear_order_int(&a, &b), linear_order_values(&a, &b)), (Some(2), 2));
        assert_eq!((rk.stage_order_int(&c), rk.stage_order_values(&c)), (Some(1), 1));
    }
}
