//! `zcheck plot`: the paper's figures as SVG files (y(t) against the exact
//! cosine for the methods of sections 5–11, and the z-plane loci), and the
//! structural-dynamics figures of Hughes, ch. 9, for one method or several
//! overlaid: the spectral radius ρ(Φ), and the period elongation and
//! algorithmic damping against Φ/2π.

use check::numeric::ParamsF64;
use std::path::PathBuf;
use std::process::ExitCode;

use crate::error::Error;
use crate::load::LoadedMethod;
use crate::plot::{yt_figure, yt_grid, zplane_figure};
use crate::spectral;
use crate::values::{self, ParamArg};
use check::numeric::Params;
use check::witness::ExactCharpoly;

/// Arguments of `zcheck plot`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// What to draw: `yt` (one file per method plus `yt_all.svg`), `zplane`,
    /// `spectral-radius` (`spectral_radius.svg`), `period` (`period.svg`:
    /// period elongation and algorithmic damping), `all`, or `solvers`
    /// (`solvers.svg`, with --scene: the game-engine solvers' phase and
    /// amplitude error against cost over substeps x iterations).
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
    /// The largest Φ of the z-plane loci and of the period figure (2.5:
    /// Φ/2π up to 0.4).
    #[arg(long, default_value_t = 2.5)]
    phi_max: f64,
    /// Methods (built-in names, `.zm` files or tableaux), overlaid in one
    /// figure; default: sections 5–11.
    #[arg(long, value_delimiter = ',')]
    methods: Vec<String>,
    /// A parameter value, `NAME=VALUE`, bound in every method that declares
    /// it; repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    params: Vec<ParamArg>,
    /// The scene of `plot solvers` (TOML: masses and springs).
    #[arg(long)]
    scene: Option<PathBuf>,
    /// The solvers of `plot solvers` (comma-separated); default: xpbd,
    /// xpbd_jacobi, soft_step.
    #[arg(long, value_delimiter = ',')]
    solvers: Vec<String>,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum What {
    Yt,
    Zplane,
    SpectralRadius,
    Period,
    All,
    Solvers,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    if args.what == What::Solvers {
        return solvers(&args);
    }
    if args.scene.is_some() || !args.solvers.is_empty() {
        return Err(Error::usage("--scene and --solvers belong to `zcheck plot solvers`"));
    }
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
    let values = crate::load::values_of_args(&args.params);
    let methods =
        names.iter().map(|n| LoadedMethod::load_with(n, &values)).collect::<Result<Vec<_>, _>>()?;
    let params =
        crate::load::unclaimed(&args.params, |p| &p.name, &methods.iter().collect::<Vec<_>>());
    if matches!(args.what, What::Period | What::All)
        && !(args.phi_max > 0.0 && args.phi_max.is_finite())
    {
        return Err(Error::usage(format!(
            "--phi-max {}: expected a positive number (the period figure's largest Phi)",
            values::show_f64(args.phi_max)
        )));
    }
    let declared: Vec<&poly::Method> = methods.iter().map(|m| m.method()).collect();
    values::check_declared(&params, &declared)?;
    // Each method's own parameters, bound; a parameter left without a
    // value is named before anything is drawn.
    let bound: Vec<Params> = methods
        .iter()
        .map(|m| {
            let p = params
                .iter()
                .filter(|p| m.method().params().iter().any(|s| s.name() == p.name))
                .fold(Params::new(), |acc, p| acc.bind(&p.name, p.value.value.clone()));
            if let Some(missing) = m
                .method()
                .params()
                .iter()
                .find(|s| s.name() != "Phi" && p.value(s.name()).is_none())
            {
                return Err(Error::usage(format!(
                    "method {} has a parameter {missing} with no value: give --param {missing}=VALUE",
                    m.method().name()
                )));
            }
            Ok(p)
        })
        .collect::<Result<_, Error>>()?;
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Error::io(format!("{}: cannot create", args.out.display()), e))?;
    // Every --param, for y(t) and the z-plane (a method reads its own).
    let given =
        params.iter().fold(Params::new(), |acc, p| acc.bind(&p.name, p.value.value.clone()));
    let params = given.clone().try_with("Phi", args.phi)?;
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
        zplane_figure(&methods, &given, args.phi_max, 150, &path)?;
        written.push(path);
    }
    let shown = |m: &LoadedMethod, p: &Params| {
        let values: Vec<String> = p.iter().map(|(k, v)| format!("{k} = {v}")).collect();
        if values.is_empty() {
            m.display().to_owned()
        } else {
            format!("{} ({})", m.display(), values.join(", "))
        }
    };
    if matches!(args.what, What::SpectralRadius | What::All) {
        let phis = spectral::radius_phis();
        let series = methods
            .iter()
            .zip(&bound)
            .map(|(m, p)| {
                let chi = ExactCharpoly::from_derivation(m.derivation()?);
                Ok(spectral::Series {
                    name: shown(m, p),
                    points: spectral::spectral_radius(&chi, p, &phis),
                })
            })
            .collect::<Result<Vec<_>, Error>>()?;
        let path = args.out.join("spectral_radius.svg");
        spectral::radius_figure(&series, &path)?;
        written.push(path);
    }
    if matches!(args.what, What::Period | What::All) {
        let phis = spectral::period_phis(args.phi_max);
        let series = methods
            .iter()
            .zip(&bound)
            .map(|(m, p)| {
                let chi = ExactCharpoly::from_derivation(m.derivation()?);
                Ok(spectral::Series {
                    name: shown(m, p),
                    points: spectral::period_damping(&chi, p, &phis),
                })
            })
            .collect::<Result<Vec<_>, Error>>()?;
        let path = args.out.join("period.svg");
        spectral::period_figure(&series, args.phi_max, &path)?;
        written.push(path);
    }
    let list: String = written.iter().map(|p| format!("{}\n", p.display())).collect();
    super::output::emit(&list)?;
    Ok(ExitCode::SUCCESS)
}

/// `zcheck plot solvers --scene FILE --out DIR`: the figure, then the
/// small-steps comparison in words.
fn solvers(args: &Args) -> Result<ExitCode, Error> {
    use crate::scene::solvers::{figure, Solver};
    let Some(path) = &args.scene else {
        return Err(Error::usage("plot solvers: expected --scene FILE"));
    };
    if !args.methods.is_empty() || !args.params.is_empty() {
        return Err(Error::usage("plot solvers: --methods and --param are the method figures'"));
    }
    let solvers: Vec<Solver> = if args.solvers.is_empty() {
        vec![Solver::Xpbd, Solver::XpbdJacobi, Solver::SoftStep]
    } else {
        args.solvers.iter().map(|w| Solver::parse(w.trim())).collect::<Result<_, _>>()?
    };
    let scene = crate::scene::file::SceneFile::load(path)?;
    crate::interrupt::install();
    let all = figure::points(&scene, &solvers)?;
    std::fs::create_dir_all(&args.out)
        .map_err(|e| Error::io(format!("{}: cannot create", args.out.display()), e))?;
    let written = figure::draw(&args.out, &path.display().to_string(), &all)?;
    let mut text = format!("{}\n", written.display());
    let word = |b: bool| if b { "holds" } else { "fails" };
    for s in &all {
        for c in figure::small_steps(&s.points) {
            text += &format!(
                "small steps ({}): S x N = {:2}: {} substeps x 1 against 1 substep x {} iterations: \
                 phase {}, amplitude {}\n",
                s.solver.name(),
                c.units,
                c.units,
                c.units,
                word(c.phase_holds),
                word(c.amplitude_holds)
            );
        }
    }
    super::output::emit(&text)?;
    Ok(ExitCode::SUCCESS)
}
