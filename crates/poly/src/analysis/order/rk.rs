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

use super::psd::positive_semidefinite;
use super::value::{Matrix, Value};
use crate::Q;

/// A tableau's exact entries.
#[derive(Clone, Debug)]
pub(crate) struct Rk {
    pub(crate) a: Matrix,
    pub(crate) b: Vec<Value>,
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
    pub(crate) fn stages(&self) -> usize {
        self.b.len()
    }

    pub(crate) fn row_sums(&self) -> Vec<Value> {
        self.a.iter().map(|row| Value::sum(row.iter())).collect()
    }

    /// The largest q with b·c^(k−1) = 1/k and A c^(k−1) = c^k/k for every
    /// k ≤ q (at most 2s: b·c^(k−1) = 1/k for k ≤ 2s + 1 is impossible).
    pub(crate) fn stage_order(&self, c: &[Value]) -> usize {
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

    /// M_ij = b_i a_ij + b_j a_ji − b_i b_j.
    fn m_entry(&self, i: usize, j: usize) -> Value {
        let (a, b) = (&self.a, &self.b);
        b[i].mul(&a[i][j]).add(&b[j].mul(&a[j][i])).sub(&b[i].mul(&b[j]))
    }

    /// M = BA + AᵀB − bbᵀ.
    pub(crate) fn m_matrix(&self) -> Matrix {
        let s = self.stages();
        (0..s).map(|i| (0..s).map(|j| self.m_entry(i, j)).collect()).collect()
    }

    /// b ≥ 0 and M positive semidefinite, decided exactly. A negative
    /// diagonal entry of M (M_ii = −b_i² on an explicit tableau) decides it
    /// before M is formed.
    pub(crate) fn algebraically_stable(&self) -> bool {
        self.b.iter().all(|x| x.sign() != Ordering::Less)
            && (0..self.stages()).all(|i| self.m_entry(i, i).sign() != Ordering::Less)
            && positive_semidefinite(&self.m_matrix()).expect("square")
    }

    /// The tableau with Dahlquist–Jeltsch reduction (stages no weighted
    /// stage depends on, dropped) and S-reduction (stages in one class of
    /// the coarsest partition with equal class row sums, merged) applied
    /// until neither changes it; `true` when anything was reduced.
    pub(crate) fn reduced(&self) -> (Rk, bool) {
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

    fn dj_reduced(&self) -> Rk {
        let s = self.stages();
        let mut needed: Vec<bool> = self.b.iter().map(|x| !x.is_zero()).collect();
        let mut stack: Vec<usize> = (0..s).filter(|&i| needed[i]).collect();
        while let Some(i) = stack.pop() {
            for (j, aij) in self.a[i].iter().enumerate() {
                if !needed[j] && !aij.is_zero() {
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

    fn s_reduced(&self) -> Rk {
        let s = self.stages();
        let mut class = vec![0usize; s];
        let mut count = 1;
        loop {
            let sig: Vec<(usize, Vec<Value>)> = (0..s)
                .map(|i| {
                    let mut sums = vec![Value::zero(); count];
                    for j in 0..s {
                        sums[class[j]] = sums[class[j]].add(&self.a[i][j]);
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
                        let mut row = vec![Value::zero(); count];
                        for j in 0..s {
                            row[class[j]] = row[class[j]].add(&self.a[i][j]);
                        }
                        row
                    })
                    .collect();
                let mut b = vec![Value::zero(); count];
                for i in 0..s {
                    b[class[i]] = b[class[i]].add(&self.b[i]);
                }
                return Rk { a, b };
            }
        }
    }

    /// M = 0 (asked of the reduced tableau by the caller).
    pub(crate) fn m_is_zero(&self) -> bool {
        let s = self.stages();
        (0..s).all(|i| (i..s).all(|j| self.m_entry(i, j).is_zero()))
    }

    /// The adjoint: a*_ij = b_(s+1−j) − a_(s+1−i, s+1−j), b*_i = b_(s+1−i).
    pub(crate) fn adjoint(&self) -> Rk {
        let s = self.stages();
        let r = |i: usize| s - 1 - i;
        Rk {
            a: (0..s)
                .map(|i| (0..s).map(|j| self.b[r(j)].sub(&self.a[r(i)][r(j)])).collect())
                .collect(),
            b: (0..s).map(|i| self.b[r(i)].clone()).collect(),
        }
    }
}

/// Whether the methods `x` and `y` (one tableau per colour, sharing their
/// stages) are equal up to one permutation of the stages, by backtracking
/// over the stages whose weights, row sums and diagonal entries agree.
pub(crate) fn equal_up_to_permutation(x: &[Rk], y: &[Rk]) -> bool {
    let s = x[0].stages();
    if y[0].stages() != s {
        return false;
    }
    let key = |m: &[Rk], i: usize| -> Vec<Value> {
        m.iter()
            .flat_map(|rk| [rk.b[i].clone(), Value::sum(&rk.a[i]), rk.a[i][i].clone()])
            .collect()
    };
    let kx: Vec<Vec<Value>> = (0..s).map(|i| key(x, i)).collect();
    let ky: Vec<Vec<Value>> = (0..s).map(|i| key(y, i)).collect();
    let candidates: Vec<Vec<usize>> =
        (0..s).map(|i| (0..s).filter(|&k| kx[i] == ky[k]).collect()).collect();
    let mut image = vec![usize::MAX; s];
    let mut used = vec![false; s];
    fn place(
        i: usize,
        x: &[Rk],
        y: &[Rk],
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
