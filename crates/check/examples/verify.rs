//! The exact answer checked by numbers: eigenvalues of P, roots of χ and a
//! long simulation must agree at each Φ, on either side of the limit.
//!
//! `cargo run -p check --example verify -- verlet` (any built-in name).
use check::ParamsF64; // Params::phi(f64): the f64 view of poly::Params

fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "verlet".to_owned());
    if let Err(e) = run(&name) {
        eprintln!("error: {e}");
        std::process::exit(2);
    }
}

fn run(name: &str) -> Result<(), Box<dyn std::error::Error>> {
    let d = poly::derive(&poly::builtin(name)?)?;
    let exact = d.stability(&poly::Params::new())?;
    println!("{name}: {} (exact)", exact.stability.name());
    for phi in [0.5, 1.0, 1.9, 2.1] {
        let point = check::verify(&d, &check::Params::phi(phi), 100_000)?;
        let agree = if point.agree() { "the witnesses agree" } else { "THE WITNESSES DISAGREE" };
        let below_limit = exact.is_stable_below(&poly::Q::from_float(phi).unwrap_or_default());
        println!("  Phi = {phi}: bounded up to here (exact): {below_limit}; {agree}");
    }
    Ok(())
}
