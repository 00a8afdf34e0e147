//! The determinant: Berkowitz's division-free algorithm against the Laplace
//! expansion oracle, the product rule det(AB) = det(A)·det(B), and the
//! characteristic polynomial against det(xI − A) expanded by Laplace.

use poly::{Poly, PolyMatrix, Sym};
use proptest::prelude::*;

use crate::common::{matrix, poly_in, transpose};

/// A size from 1 to 6 and a random matrix of that size.
fn sized_matrix(max: usize) -> impl Strategy<Value = PolyMatrix> {
    (1..=max).prop_flat_map(matrix)
}

/// det(zI − A) as a polynomial in z, from Berkowitz's coefficient list.
fn charpoly_from_berkowitz(a: &PolyMatrix) -> Poly {
    let mut c = a.charpoly_berkowitz();
    c.reverse();
    Poly::from_coeffs_in(Sym::z(), &c)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn berkowitz_matches_laplace(a in sized_matrix(6)) {
        prop_assert_eq!(a.det(), a.det_laplace());
    }

    /// Matrices in Phi alone (and constant ones) take the dense integer path
    /// of Berkowitz; Laplace runs on the sparse representation.
    #[test]
    fn dense_univariate_path_matches_laplace(
        a in (1usize..=6).prop_flat_map(|n| {
            let entry = prop_oneof![1 => Just(Poly::zero()), 3 => poly_in(1, 4)];
            proptest::collection::vec(entry, n * n).prop_map(move |d| {
                PolyMatrix::from_rows(d.chunks(n).map(<[Poly]>::to_vec).collect())
            })
        })
    ) {
        prop_assert_eq!(a.det(), a.det_laplace());
        prop_assert_eq!(charpoly_from_berkowitz(&a), a.char_matrix(&Poly::sym(Sym::z())).det_laplace());
    }

    /// Triangular matrices (a diagonally implicit step's system) take the
    /// product of the diagonal; Laplace expands them in full.
    #[test]
    fn triangular_matrices_match_laplace(a in sized_matrix(6), lower in any::<bool>()) {
        let n = a.rows();
        let rows = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| if (lower && j > i) || (!lower && j < i) { Poly::zero() } else { a[(i, j)].clone() })
                    .collect()
            })
            .collect();
        let t = PolyMatrix::from_rows(rows);
        prop_assert_eq!(t.det(), t.det_laplace());
    }

    #[test]
    fn transposing_keeps_the_determinant(a in sized_matrix(5)) {
        prop_assert_eq!(transpose(&a).det(), a.det());
    }

    #[test]
    fn charpoly_matches_laplace_of_the_characteristic_matrix(a in sized_matrix(5)) {
        let z = Poly::sym(Sym::z());
        let laplace = a.char_matrix(&z).det_laplace();
        let berkowitz = charpoly_from_berkowitz(&a);
        prop_assert_eq!(&berkowitz, &laplace);
        prop_assert_eq!(berkowitz.degree_in(Sym::z()) as usize, a.rows());
        prop_assert!(berkowitz.coeffs_in(Sym::z()).last().is_some_and(Poly::is_one), "monic");
        // The z⁰ coefficient is det(−A) = (−1)^n det A.
        let sign = if a.rows() % 2 == 0 { Poly::one() } else { Poly::int(-1) };
        prop_assert_eq!(berkowitz.coeffs_in(Sym::z())[0].clone(), &sign * &a.det());
    }

    #[test]
    fn determinant_of_a_product_is_the_product_of_determinants(
        (a, b) in (1usize..=4).prop_flat_map(|n| (matrix(n), matrix(n)))
    ) {
        prop_assert_eq!((&a * &b).det(), &a.det() * &b.det());
    }

    /// Swapping two rows negates the determinant; adding a polynomial
    /// multiple of one row to another keeps it.
    #[test]
    fn row_operations(a in (2usize..=5).prop_flat_map(matrix), k in poly_in(2, 2)) {
        let n = a.rows();
        let rows: Vec<Vec<Poly>> = (0..n).map(|i| a.row(i).to_vec()).collect();
        let mut swapped = rows.clone();
        swapped.swap(0, n - 1);
        prop_assert_eq!(PolyMatrix::from_rows(swapped).det(), -a.det());
        let mut added = rows;
        added[1] = added[1].iter().zip(a.row(0)).map(|(x, y)| x + &(&k * y)).collect();
        prop_assert_eq!(PolyMatrix::from_rows(added).det(), a.det());
    }
}

#[track_caller]
fn check_det(rows: &[&[&str]], expected: &str) {
    let m = PolyMatrix::from_rows(
        rows.iter()
            .map(|r| r.iter().map(|e| Poly::parse(e).expect("test entry parses")).collect())
            .collect(),
    );
    let expected = Poly::parse(expected).expect("expected value parses");
    assert_eq!(m.det(), expected, "Berkowitz");
    assert_eq!(m.det_laplace(), expected, "Laplace");
}

/// Hand-computed determinants, including the empty matrix and the paper's
/// Standard Euler characteristic matrix zI − P.
#[test]
fn known_determinants() {
    check_det(&[], "1");
    check_det(&[&["Phi - 3"]], "Phi - 3");
    check_det(&[&["a", "b"], &["c", "d"]], "a*d - b*c");
    check_det(&[&["z - 1", "Phi"], &["-Phi", "z - 1"]], "z^2 - 2*z + 1 + Phi^2");
    check_det(&[&["1", "2", "3"], &["4", "5", "6"], &["7", "8", "10"]], "-3");
    // Upper triangular: the product of the diagonal.
    check_det(
        &[&["Phi", "7", "D"], &["0", "1 - Phi", "Phi^9"], &["0", "0", "D^2"]],
        "Phi*(1 - Phi)*D^2",
    );
}

/// Entries near 2^100 overflow the dense `i128` path part-way; the sparse
/// path takes over and the result is still exact.
#[test]
fn overflowing_entries_fall_back_to_the_exact_path() {
    for n in 1..=5usize {
        let big = |i: usize, j: usize| {
            Poly::parse(&format!("{}*Phi^{} - {}/7", 1u128 << 100, (i + j) % 3, i * n + j + 1))
                .expect("parses")
        };
        let a =
            PolyMatrix::from_rows((0..n).map(|i| (0..n).map(|j| big(i, j)).collect()).collect());
        assert_eq!(a.det(), a.det_laplace(), "n = {n}");
        assert_eq!(
            charpoly_from_berkowitz(&a),
            a.char_matrix(&Poly::sym(Sym::z())).det_laplace(),
            "n = {n}"
        );
    }
}

/// The companion matrix of a monic polynomial has that polynomial as its
/// characteristic polynomial, for every degree up to 8.
#[test]
fn companion_matrices_recover_their_polynomial() {
    for n in 1..=8usize {
        // χ(z) = z^n + Σ_k (k + 1 - Phi*D^k) z^k.
        let coeff = |k: usize| Poly::parse(&format!("{} - Phi*D^{k}", k + 1)).expect("parses");
        let mut rows = vec![vec![Poly::zero(); n]; n];
        for (i, row) in rows.iter_mut().enumerate().skip(1) {
            row[i - 1] = Poly::one();
        }
        for (k, row) in rows.iter_mut().enumerate() {
            row[n - 1] = -coeff(k);
        }
        let a = PolyMatrix::from_rows(rows);
        let mut expected: Vec<Poly> = (0..n).map(coeff).collect();
        expected.push(Poly::one());
        assert_eq!(
            charpoly_from_berkowitz(&a),
            Poly::from_coeffs_in(Sym::z(), &expected),
            "n = {n}"
        );
    }
}

/// An n×n matrix over Phi, D and z with entries zero a third of the time,
/// coefficients up to `2^bits` (so the modular path needs several primes).
fn wide_matrix(n: usize, bits: u32) -> impl Strategy<Value = PolyMatrix> {
    let big = move |p: Poly, k: i64| {
        &p * &Poly::constant(poly::Q::from_integer(num_bigint::BigInt::from(k) << bits))
    };
    let entry = prop_oneof![1 => Just(Poly::zero()), 2 => (poly_in(3, 3), -3i64..=3).prop_map(move |(p, k)| &p + &big(p.clone(), k))];
    proptest::collection::vec(entry, n * n)
        .prop_map(move |d| PolyMatrix::from_rows(d.chunks(n).map(<[Poly]>::to_vec).collect()))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The modular path (evaluation, interpolation, CRT) against sparse
    /// Berkowitz, for determinants and characteristic polynomials in up to
    /// three symbols, with small coefficients and with coefficients near
    /// 2^70 and 2^200 (several primes).
    #[test]
    fn modular_path_matches_sparse_berkowitz(
        a in (1usize..=5, prop_oneof![Just(0u32), Just(70), Just(200)])
            .prop_flat_map(|(n, bits)| wide_matrix(n, bits))
    ) {
        let sparse = a.charpoly_berkowitz_sparse();
        let n = a.rows();
        let sign = if n % 2 == 0 { Poly::one() } else { Poly::int(-1) };
        prop_assert_eq!(a.det_modular().expect("small grid"), &sign * &sparse[n]);
        prop_assert_eq!(a.charpoly_modular().expect("small grid"), sparse);
    }
}

/// An n×n pencil A + w·B over Phi and D, w = `1/z` as the z route has it;
/// `unit` makes A the identity (the shape route (a) meets), else A is
/// random and often singular at some points (the fallback to values in w).
fn pencil(n: usize, unit: bool) -> impl Strategy<Value = PolyMatrix> {
    let entry = || prop_oneof![1 => Just(Poly::zero()), 2 => poly_in(2, 3)];
    (proptest::collection::vec(entry(), n * n), proptest::collection::vec(entry(), n * n)).prop_map(
        move |(a, b)| {
            let w = Poly::sym(poly::advanced::w());
            let rows = (0..n)
                .map(|i| {
                    (0..n)
                        .map(|j| {
                            let a = if unit {
                                Poly::int((i == j) as i64)
                            } else {
                                a[i * n + j].clone()
                            };
                            &a + &(&w * &b[i * n + j])
                        })
                        .collect()
                })
                .collect();
            PolyMatrix::from_rows(rows)
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The pencil job (coefficients in w from B₀⁻¹B₁) against Laplace.
    #[test]
    fn pencil_determinants_match_laplace(
        a in (1usize..=5, any::<bool>()).prop_flat_map(|(n, unit)| pencil(n, unit))
    ) {
        let laplace = a.det_laplace();
        prop_assert_eq!(a.det_pencil_modular(poly::advanced::w()).expect("small grid"), laplace.clone());
        prop_assert_eq!(a.det_pencil(poly::advanced::w()), laplace);
    }
}

/// The modular determinant against Laplace on matrices with a zero column
/// of pivots (singular modulo every prime at every point) and on the empty
/// matrix.
#[test]
fn modular_determinants_of_degenerate_matrices() {
    let parse = |rows: &[&[&str]]| {
        PolyMatrix::from_rows(
            rows.iter()
                .map(|r| r.iter().map(|e| Poly::parse(e).expect("parses")).collect())
                .collect(),
        )
    };
    for m in [
        parse(&[]),
        parse(&[&["0", "Phi"], &["0", "D"]]),
        parse(&[&["Phi", "D"], &["2*Phi", "2*D"]]),
        parse(&[&["0", "Phi*D", "1"], &["D", "0", "0"], &["1/3", "z", "Phi^3"]]),
    ] {
        assert_eq!(m.det_modular().expect("small grid"), m.det_laplace(), "{m}");
        let mut c = m.charpoly_modular().expect("small grid");
        c.reverse();
        let x = Sym::new("x");
        assert_eq!(Poly::from_coeffs_in(x, &c), m.char_matrix(&Poly::sym(x)).det_laplace(), "{m}");
    }
}
