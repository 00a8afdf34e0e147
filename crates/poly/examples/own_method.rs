//! A method of your own, from a `.zm` file, to its exact stability limit.
//!
//! `cargo run -p poly --example own_method -- my_method.zm` (without a file:
//! the symplectic Euler written below).
use poly::{Method, Params};

const DEFAULT: &str = "method symplectic_euler\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n";

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}"); // file:line:column: what was expected
        std::process::exit(2);
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let (file, src) = match std::env::args().nth(1) {
        Some(path) => (path.clone(), std::fs::read_to_string(&path)?),
        None => ("symplectic_euler.zm".to_owned(), DEFAULT.to_owned()),
    };
    let d = poly::derive(&Method::parse(&file, &src)?)?; // both routes, checked equal
    println!("chi(z) = {}", d.charpoly());
    let report = d.stability(&Params::new())?;
    match (report.phi_max(), report.bounded_at_phi_max()) {
        (Some(limit), Some(at)) => {
            let decimal = limit.to_decimal(6);
            println!("bounded for 0 < Phi < {limit} = {decimal}; at the limit itself: {at}");
        }
        _ => println!("{}", report.stability.name()),
    }
    Ok(())
}
