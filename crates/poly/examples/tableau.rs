//! A Butcher tableau to its exact stability limit and its phase series.
//!
//! `cargo run -p poly --example tableau`: RK4, then Gauss–Legendre 2 with
//! its irrational entries.
use poly::{Method, Params};

fn main() -> Result<(), poly::Error> {
    let a = [
        ["0", "0", "0", "0"],
        ["1/2", "0", "0", "0"],
        ["0", "1/2", "0", "0"],
        ["0", "0", "1", "0"],
    ];
    let rk4 = Method::from_tableau(
        "rk4",
        &a.map(|row| row.to_vec()),
        &["1/6", "1/3", "1/3", "1/6"],
        Some(&["0", "1/2", "1/2", "1"]),
    )?;
    let gl2 = Method::from_tableau(
        "gauss_legendre_2",
        &[vec!["1/4", "1/4 - sqrt(3)/6"], vec!["1/4 + sqrt(3)/6", "1/4"]],
        &["1/2", "1/2"],
        None,
    )?;
    for method in [rk4, gl2] {
        let d = poly::derive(&method)?;
        let report = d.stability(&Params::new())?;
        let limit = report.phi_max().map_or("none".to_owned(), |m| m.to_string());
        println!("{}: {} (limit: {limit})", method.name(), report.stability.name());
        // Ψ(Φ) = Φ + c₃Φ³ + c₅Φ⁵ + …: the phase error per step.
        match d.psi_series(&Params::new(), 5) {
            Ok(psi) => println!("  Psi = {} + O(Phi^6)", poly::UPoly::new(psi).to_string_in("Phi")),
            Err(e) => println!("  no Psi series: {e}"),
        }
    }
    Ok(())
}
