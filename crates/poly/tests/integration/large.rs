//! Large programs: RK4 on spring chains and a chain of 100,000
//! temporaries derive by the fast paths (sparse M reduced by forward
//! substitution, modular determinants) exactly as by the slow ones.

use poly::{Method, Poly, Sym};

use testkit::programs;

fn parse(src: &str) -> Method {
    Method::parse("generated.zm", src).unwrap_or_else(|e| panic!("{e}"))
}

/// Both routes of the fast derivation against route (a) on the dense M
/// with sparse Berkowitz, and route (b) with sparse Berkowitz.
#[test]
fn rk4_chains_match_the_slow_routes() {
    for n in 1..=3 {
        let m = parse(&programs::rk4_chain(n));
        let d = poly::derive(&m).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            *d.charpoly(),
            poly::advanced::charpoly_z_route_dense(&m).expect("slow z route"),
            "n = {n}"
        );
        let mut c = d.transition_matrix().charpoly_berkowitz_sparse();
        c.reverse();
        assert_eq!(*d.charpoly(), Poly::from_coeffs_in(Sym::z(), &c), "n = {n}");
        assert_eq!(d.charpoly().degree_in(Sym::z()) as usize, 2 * n);
    }
}

/// One mass: RK4 on the oscillator, whose amplification factor is the
/// degree-4 Taylor polynomial R(iΦ) of e^(iΦ), so χ = z² − 2 Re R·z + |R|².
#[test]
fn one_mass_chain_is_rk4_on_the_oscillator() {
    let d = poly::derive(&parse(&programs::rk4_chain(1))).expect("derives");
    // ω = √2 (two unit springs to the walls), so Φ² enters as 2Φ².
    let re = Poly::parse("1 - (2*Phi^2)/2 + (2*Phi^2)^2/24").expect("parses");
    let im2 = Poly::parse("2*Phi^2*(1 - (2*Phi^2)/6)^2").expect("parses");
    let z = Poly::sym(Sym::z());
    let want = &(&z.pow(2) - &(&Poly::int(2) * &(&re * &z))) + &(&re.pow(2) + &im2);
    assert_eq!(*d.charpoly(), want);
}

/// The committed fixture is what the generator writes (the SymPy bench
/// script reads the fixtures).
#[test]
fn the_fixtures_are_the_generated_programs() {
    for n in [6, 8, 16] {
        let path = format!("{}/benches/fixtures/rk4_chain_{n}.zm", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        assert_eq!(text, programs::rk4_chain(n), "{path}");
    }
}

/// 100,000 temporaries in a chain derive (lowering, the sparse M and both
/// routes are linear in the program's length), to the two-line method they
/// spell out.
#[test]
fn a_chain_of_100_000_temporaries_derives() {
    let n = 100_000;
    let m = parse(&programs::temporary_chain(n));
    assert_eq!(m.assigns().len(), n + 2);
    let d = poly::derive(&m).unwrap_or_else(|e| panic!("{e}"));
    let short = parse("method se\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n");
    assert_eq!(*d.charpoly(), poly::advanced::charpoly(&short).expect("derives"));
    // M has one row per assignment and about two nonzeros per row.
    assert_eq!(d.z_matrix().rows(), n + 2);
    assert!(d.z_matrix().nonzeros() <= 3 * (n + 2), "{} nonzeros", d.z_matrix().nonzeros());
}

/// Short chains against the slow dense route (a).
#[test]
fn short_temporary_chains_match_the_slow_route() {
    for n in [2, 3, 10, 50] {
        let m = parse(&programs::temporary_chain(n));
        assert_eq!(
            poly::advanced::charpoly_z_route(&m).expect("fast"),
            poly::advanced::charpoly_z_route_dense(&m).expect("slow"),
            "n = {n}"
        );
    }
}

/// Issue 27's chains of `n` temporaries (the bench `chain/temporaries_10000`
/// times them at n = 10,000): copies of v, running sums `x_k = x_{k−1} +
/// Phi*y`, and copies of an implicit stage, each with the short program
/// it spells out.
fn issue_27_chains(n: usize) -> Vec<(String, String)> {
    let mut copies = String::from("method copies\nstate v y\nt1 = v\n");
    let mut sums = String::from("method sums\nstate v y\nx0 = v\n");
    let mut implicit =
        String::from("method implicit\nstate v y\nunknown k\nk = -(y + Phi*k/2)\nt1 = k\n");
    for k in 2..=n {
        copies += &format!("t{k} = t{}\n", k - 1);
        implicit += &format!("t{k} = t{}\n", k - 1);
    }
    for k in 1..=n {
        sums += &format!("x{k} = x{} + Phi*y\n", k - 1);
    }
    copies += &format!("v = t{n} - Phi*y\ny = y + Phi*v\n");
    sums += &format!("v = x{n}\ny = y + Phi*v\n");
    implicit += &format!("v = v + Phi*t{n}\ny = y + Phi*v\n");
    vec![
        (copies, "method s\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n".to_owned()),
        (sums, format!("method s\nstate v y\nv = v + {n}*Phi*y\ny = y + Phi*v\n")),
        (
            implicit,
            "method s\nstate v y\nunknown k\nk = -(y + Phi*k/2)\nv = v + Phi*k\ny = y + Phi*v\n"
                .to_owned(),
        ),
    ]
}

/// The chains of 10,000 temporaries derive the χ of the programs they
/// spell out, and short chains agree with the slow dense route (a).
#[test]
fn chains_of_10_000_temporaries_derive_their_short_programs() {
    for (long, short) in issue_27_chains(10_000) {
        let d = poly::derive(&parse(&long)).unwrap_or_else(|e| panic!("{e}"));
        let want = poly::derive(&parse(&short)).expect("derives");
        assert_eq!(d.charpoly(), want.charpoly(), "{short}");
        assert_eq!(d.p_denominator(), want.p_denominator(), "{short}");
    }
    for n in [2, 10, 50] {
        for (long, _) in issue_27_chains(n) {
            let m = parse(&long);
            assert_eq!(
                poly::advanced::charpoly_z_route(&m).expect("fast"),
                poly::advanced::charpoly_z_route_dense(&m).expect("slow"),
                "n = {n}"
            );
        }
    }
}
