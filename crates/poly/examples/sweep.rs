//! A parameter sweep: the exact stability limit Φ_max(D) of a method on the
//! damped spring, at rational damping ratios.
//!
//! `cargo run -p poly --example sweep -- false_euler_damped` (any built-in
//! with a parameter `D`; `zcheck methods` lists them).
use poly::{q, Params};

fn main() {
    let name = std::env::args().nth(1).unwrap_or_else(|| "damped_euler_damped".to_owned());
    if let Err(e) = run(&name) {
        eprintln!("error: {e}");
        std::process::exit(2);
    }
}

fn run(name: &str) -> Result<(), poly::Error> {
    let d = poly::derive(&poly::builtin(name)?)?; // derived once, asked many times
    for tenths in [0, 1, 2, 5, 10, 20] {
        let damping = q(tenths, 10);
        let report = d.stability(&Params::new().bind("D", damping.clone()))?;
        let limit = match report.phi_max() {
            Some(m) => format!("{m} = {}", m.to_decimal(6)),
            None => report.stability.name().to_owned(),
        };
        println!("D = {damping:<5} Phi_max = {limit}");
    }
    Ok(())
}
