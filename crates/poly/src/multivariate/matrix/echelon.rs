//! Linear algebra over the field of rational functions Q(Φ, D, ...) without
//! fractions: fraction-free Gauss–Jordan elimination over the polynomial
//! ring, for ranks, null spaces and solutions.
//!
//! Each step pivots on `p = a[r][c]` and replaces every other row by
//! $$a_{ij} \leftarrow (p\,a_{ij} - a_{ic}\,a_{rj}) / p_{\text{prev}},$$
//! a division that is exact: by Sylvester's identity every entry is then a
//! minor of the input (Bareiss's elimination, carried above the pivots as
//! well). At the end every pivot equals the last one, `d`, the determinant
//! of the pivot rows and columns up to sign, so the reduced matrix reads
//! `d·I` on the pivot columns and the solutions are polynomial.

use crate::Poly;

/// The fraction-free reduced row echelon form of a matrix.
pub(crate) struct Echelon {
    /// The reduced rows; the first `pivots.len()` are the pivot rows, the
    /// rest are zero.
    pub rows: Vec<Vec<Poly>>,
    /// The pivot column of each pivot row, increasing.
    pub pivots: Vec<usize>,
    /// The common value of every pivot (1 when there is none).
    pub d: Poly,
}

/// Fraction-free Gauss–Jordan elimination of `rows` (all of one length),
/// the rank over the field of fractions being `pivots.len()`.
pub(crate) fn reduce(mut rows: Vec<Vec<Poly>>) -> Echelon {
    let cols = rows.first().map_or(0, Vec::len);
    let mut prev = Poly::one();
    let mut pivots = Vec::new();
    for c in 0..cols {
        let r = pivots.len();
        // The sparsest nonzero entry keeps the minors small.
        let Some(best) =
            (r..rows.len()).filter(|&i| !rows[i][c].is_zero()).min_by_key(|&i| rows[i][c].len())
        else {
            continue;
        };
        rows.swap(r, best);
        let pivot_row = rows[r].clone();
        let p = pivot_row[c].clone();
        for (i, row) in rows.iter_mut().enumerate() {
            if i == r {
                continue;
            }
            let factor = row[c].clone();
            for (j, x) in row.iter_mut().enumerate() {
                let next = &(&p * &*x) - &(&factor * &pivot_row[j]);
                *x = next.div_exact(&prev).expect("Bareiss's division is exact");
            }
        }
        prev = p;
        pivots.push(c);
        if pivots.len() == rows.len() {
            break;
        }
    }
    Echelon { rows, pivots, d: prev }
}

impl Echelon {
    /// The rank over the field of fractions.
    pub fn rank(&self) -> usize {
        self.pivots.len()
    }

    /// A basis of the null space over the field of fractions, each vector
    /// polynomial: for a free column `f`, `x_f = d` and `x_c = −a[r][f]` on
    /// the pivot column `c` of row `r`.
    pub fn null_space(&self, cols: usize) -> Vec<Vec<Poly>> {
        (0..cols)
            .filter(|f| !self.pivots.contains(f))
            .map(|f| {
                let mut x = vec![Poly::zero(); cols];
                x[f] = self.d.clone();
                for (r, &c) in self.pivots.iter().enumerate() {
                    x[c] = -&self.rows[r][f];
                }
                x
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn phi() -> Poly {
        Poly::var("Phi")
    }

    fn dd() -> Poly {
        Poly::var("D")
    }

    fn int(n: i64) -> Poly {
        Poly::int(n)
    }

    /// Matrices over Q[Phi, D]: the rank is the field rank, and every null
    /// vector is one (the product with the matrix vanishes exactly).
    #[test]
    fn rank_and_null_space() {
        let (f, d) = (phi(), dd());
        let cases: Vec<(Vec<Vec<Poly>>, usize)> = vec![
            (vec![vec![int(1), f.clone()], vec![f.clone(), &f * &f]], 1),
            (
                vec![
                    vec![f.clone(), int(1), d.clone()],
                    vec![int(1), f.clone(), int(0)],
                    vec![&f + &int(1), &f + &int(1), d.clone()],
                ],
                2,
            ),
            (vec![vec![&f - &d, int(1)], vec![int(0), d.clone()]], 2),
            (vec![vec![int(0), int(0)], vec![int(0), int(0)]], 0),
        ];
        for (rows, rank) in cases {
            let cols = rows[0].len();
            let e = reduce(rows.clone());
            assert_eq!(e.rank(), rank, "{rows:?}");
            let null = e.null_space(cols);
            assert_eq!(null.len(), cols - rank, "{rows:?}");
            for x in &null {
                assert!(x.iter().any(|v| !v.is_zero()), "{rows:?}: a zero null vector");
                for row in &rows {
                    let dot = row.iter().zip(x).fold(Poly::zero(), |acc, (a, b)| &acc + &(a * b));
                    assert!(dot.is_zero(), "{rows:?}: {x:?} is not a null vector");
                }
            }
        }
    }

    /// The gcd of two products with a common factor is that factor, up to a
    /// constant, in one symbol and in two.
    #[test]
    fn gcd_finds_the_common_factor() {
        let (f, d) = (phi(), dd());
        let half = Poly::constant(crate::Q::new(1.into(), 2.into()));
        let cases = [
            (&f - &half, &f + &int(1), &(&f * &f) + &int(1)),
            (&(&d * &f) - &half, &f + &d, &f - &d),
            (&(&d * &f) - &half, f.clone(), &(&d * &d) + &f),
            (f.clone(), &d + &int(2), &d * &d),
            (int(1), &f + &d, &f - &d),
        ];
        for (g, a, b) in cases {
            let found = (&g * &a).gcd(&(&g * &b));
            let ratio =
                found.div_exact(&g).unwrap_or_else(|| panic!("{g} does not divide {found}"));
            assert!(ratio.as_constant().is_some_and(|c| c != crate::q(0, 1)), "{found} for {g}");
        }
        assert_eq!(Poly::zero().gcd(&Poly::zero()), Poly::zero());
    }

    /// Exact division undoes a product and refuses a non-divisor.
    #[test]
    fn exact_division() {
        let (f, d) = (phi(), dd());
        let half = Poly::constant(crate::Q::new(1.into(), 2.into()));
        for (a, b) in [
            (&(&(&f * &f) - &(&d * &f)) + &int(1), &f + &d),
            (&(&int(3) * &(&f * &(&d * &d))) - &half, &d - &f.pow(3)),
            (int(7), f.clone()),
            (d.pow(3), &d * &d),
        ] {
            assert_eq!((&a * &b).div_exact(&b), Some(a.clone()), "{a} {b}");
        }
        assert_eq!((&(&f * &f) + &int(1)).div_exact(&(&f + &int(1))), None);
        assert_eq!((&(&f * &d) + &int(1)).div_exact(&d), None);
        assert_eq!(f.div_exact(&(&f * &d)), None);
        assert_eq!(f.div_exact(&Poly::zero()), None);
    }
}
