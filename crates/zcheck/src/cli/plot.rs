//! `zcheck plot`: the paper's figures as SVG files (y(t) against the exact
//! cosine for the methods of sections 5–11, and the z-plane loci).

use check::numeric::ParamsF64;
use std::path::PathBuf;
use std::process::ExitCode;

use crate::error::Error;
use crate::load::LoadedMethod;
use crate::plot::{yt_figure, yt_grid, zplane_figure};
use check::numeric::Params;

/// Arguments of `zcheck plot`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// What to draw: `yt` (one file per method plus `yt_all.svg`), `zplane`,
    /// or `all`.
    #[arg(value_enum)]
    what: What,
    /// The directory to write into (created if missing).
    #[arg(long)]
    out: PathBuf,
    /// Φ for y(t).
    #[arg(long, default_value_t = 0.5)]
    phi: f64,
    /// The time span of y(t), in units of 1/ω₀.
    #[arg(long, default_value_t = 20.0)]
    t_max: f64,
    /// The largest Φ of the z-plane loci.
    #[arg(long, default_value_t = 2.5)]
    phi_max: f64,
    /// Methods (built-in names or `.zm` files); default: sections 5–11.
    #[arg(long, value_delimiter = ',')]
    methods: Vec<String>,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum What {
    Yt,
    Zplane,
    All,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    if !(args.phi > 0.0 && args.phi.is_finite()) {
        return Err(Error::usage(format!("--phi {}: expected a positive number", args.phi)));
    }
    if !(args.t_max > 0.0 && args.t_max / args.phi <= 1e6) {
        return Err(Error::usage(format!(
            "--t-max {}: expected a positive span of at most 1e6 steps",
            args.t_max
        )));
    }
    let names: Vec<String> = if args.methods.is_empty() {
        poly::advanced::builtins::PAPER_METHODS.iter().map(|s| s.to_string()).collect()
    } else {
        args.methods.clone()
    };
    let methods = names.iter().map(|n| LoadedMethod::load(n)).collect::<Result<Vec<_>, _>>()?;
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Error::io(format!("{}: cannot create", args.out.display()), e))?;
    let params = Params::new().try_with("Phi", args.phi)?;
    let mut written = Vec::new();
    if matches!(args.what, What::Yt | What::All) {
        for m in &methods {
            let path = args.out.join(format!("yt_{}.svg", m.method().name()));
            yt_figure(m.method(), &params, args.t_max, &path)?;
            written.push(path);
        }
        let path = args.out.join("yt_all.svg");
        yt_grid(&methods, &params, args.t_max, &path)?;
        written.push(path);
    }
    if matches!(args.what, What::Zplane | What::All) {
        let path = args.out.join("zplane.svg");
        zplane_figure(&methods, &Params::default(), args.phi_max, 150, &path)?;
        written.push(path);
    }
    let list: String = written.iter().map(|p| format!("{}\n", p.display())).collect();
    super::output::emit(&list)?;
    Ok(ExitCode::SUCCESS)
}
