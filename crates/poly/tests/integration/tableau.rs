//! Butcher tableaux through the library: a tableau read entry by entry
//! derives its built-in's χ (moved here from `lang/tableau.rs`, whose unit
//! tests may not reach up to `derive`).

use poly::advanced::tableau::{Exact, Tableau};

fn e(s: &str) -> Exact {
    Exact::parse(s).unwrap()
}

/// RK4's tableau gives the RK4 built-in's χ.
#[test]
fn rk4_tableau_is_the_builtin() {
    let z = || e("0");
    let a = vec![
        vec![z(), z(), z(), z()],
        vec![e("1/2"), z(), z(), z()],
        vec![z(), e("1/2"), z(), z()],
        vec![z(), z(), e("1"), z()],
    ];
    let b = vec![e("1/6"), e("1/3"), e("1/3"), e("1/6")];
    let c = Some(vec![z(), e("1/2"), e("1/2"), e("1")]);
    let t = Tableau::new("rk4", a, b, c).unwrap();
    assert!(t.is_explicit());
    assert_eq!(t.c_mismatch(), Some(&[][..]));
    let mine = poly::derive(&t.method(false).unwrap()).unwrap();
    let builtin = poly::derive(&poly::builtin("rk4").unwrap()).unwrap();
    assert_eq!(mine.charpoly, builtin.charpoly);
}
