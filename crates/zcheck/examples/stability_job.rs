//! The stability bench's job a fixed number of times, for an instruction
//! count that repeats where wall time does not (DESIGN.md, "How is a
//! speed-up to an exact kernel judged?"): make the method from a NodePy
//! tableau's entries, then write its whole `zcheck stability` document.
//!
//! `valgrind --tool=callgrind --callgrind-out-file=/dev/null
//! target/release/examples/stability_job RK44 40` (BENCHMARKS.md).

#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let name = args.next().ok_or("usage: stability_job METHOD [ITERATIONS]")?;
    let iterations: usize = args.next().map_or(Ok(40), |n| n.parse())?;
    let path = format!("{}/tests/data/nodepy/rk/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    let text_of = std::fs::read_to_string(&path).map_err(|e| format!("{path}: {e}"))?;
    let table: toml::Table = text_of.parse()?;
    let text = |v: &toml::Value| match v {
        toml::Value::String(s) => Ok(s.clone()),
        toml::Value::Integer(i) => Ok(i.to_string()),
        other => Err(format!("{path}: an entry {other:?}: expected an integer or a string")),
    };
    let list = |v: &toml::Value| -> Result<Vec<String>, String> {
        v.as_array().ok_or(format!("{path}: expected an array"))?.iter().map(text).collect()
    };
    let a: Vec<Vec<String>> =
        table["A"].as_array().ok_or("A")?.iter().map(list).collect::<Result<_, _>>()?;
    let b = list(&table["b"])?;
    let a: Vec<Vec<&str>> = a.iter().map(|r| r.iter().map(String::as_str).collect()).collect();
    let b: Vec<&str> = b.iter().map(String::as_str).collect();
    let mut bytes = 0;
    for _ in 0..iterations {
        let m = zcheck::api::tableau(&name, &a, &b, None, None)?;
        bytes += serde_json::to_string(&zcheck::api::stability(&m, &[])?)?.len();
    }
    println!("{name}: {iterations} documents, {bytes} bytes");
    Ok(())
}
