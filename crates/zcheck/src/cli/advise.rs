//! `zcheck advise`: which method and how many substeps for a spring in a
//! (the arguments and the printing; the answer is `crate::answers::advice`)

use super::format::{Format, TEXT_JSON};
use crate::answers::advice::*;
use crate::error::Error;
use crate::load::LoadedMethod;
use crate::scene::advisor::{self, Options};
use crate::scene::file::SceneFile;
use crate::scene::modal::{self};
use crate::tradeoff::spring_advisor::{advise_spring, SpringScene};
use crate::tradeoff::{family, kernels, Rank};
use crate::values::Exact;
use std::process::ExitCode;
use std::time::Duration;

/// Arguments of `zcheck advise`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// The spring's natural frequency, Hz.
    #[arg(long, required_unless_present = "scene")]
    pub freq: Option<f64>,
    /// The simulation tick rate, Hz.
    #[arg(long, required_unless_present = "scene")]
    pub tick: Option<f64>,
    /// A scene file (TOML: masses and springs, or modes; see the README).
    #[arg(long, conflicts_with_all = ["freq", "tick", "damping"])]
    pub scene: Option<std::path::PathBuf>,
    /// Candidate methods for a scene (with --scene only): built-in names, `.zm` files or
    /// `.toml` tableaux (comma-separated or repeated); default: the seven direct methods.
    #[arg(long, value_delimiter = ',', requires = "scene")]
    pub methods: Vec<String>,
    /// A value for a parameter a tableau among --methods declares (`params
    /// = ["c"]`), `NAME=VALUE` (exact); repeatable.
    #[arg(
        long = "param",
        value_name = "NAME=VALUE",
        allow_hyphen_values = true,
        conflicts_with = "solver"
    )]
    pub params: Vec<crate::values::ParamArg>,
    /// Also analyse body-by-body (Gauss-Seidel) updates of the scene.
    #[arg(long, value_enum, requires = "scene")]
    pub sweep: Option<SweepArg>,
    /// How a mesh (`--scene FILE.obj`) becomes a scene.
    #[command(flatten)]
    pub mesh: crate::scene::mesh::MeshOptions,
    /// Skip the simulation that checks the prediction.
    #[arg(long)]
    pub no_simulate: bool,
    /// Check every candidate that meets the target by simulation; by
    /// default only the recommended one and those within 4x its cost per
    /// tick are simulated, and the others are named.
    #[arg(long, conflicts_with = "no_simulate")]
    pub simulate_all: bool,
    /// The eigensolver for a scene of masses and springs: dense (every
    /// mode) up to 400 degrees of freedom and sparse (the certified highest
    /// mode, the lowest or in-band modes, samples between) beyond, or forced.
    #[arg(long, value_enum, default_value_t = modal::Route::Auto, requires = "scene")]
    pub spectrum: modal::Route,
    /// How long the scene must stay within tolerance, seconds.
    #[arg(long, default_value_t = SpringScene::DEFAULT_DURATION_S)]
    pub duration: f64,
    /// Largest accumulated phase error over the duration, radians.
    #[arg(long, default_value_t = SpringScene::DEFAULT_PHASE_TOL)]
    pub phase_tol: f64,
    /// Largest relative amplitude error over the duration (0.01 = 1 %).
    #[arg(long, default_value_t = SpringScene::DEFAULT_AMP_TOL)]
    pub amp_tol: f64,
    /// Physical damping ratio D (0 <= D < 1), an exact decimal (`0.1` is
    /// 1/10); without it the spring is undamped.
    #[arg(long, allow_negative_numbers = true)]
    pub damping: Option<Exact>,
    /// A game-engine solver to analyse on the scene instead of the
    /// force-based methods: `xpbd` (Gauss-Seidel), `xpbd_jacobi` or
    /// `soft_step` (Box2D v3). With --substeps and --iterations, that one
    /// configuration; without, the search over 1..64 substeps and 1..16
    /// iterations. Its JSON is a document of its own (README).
    #[arg(long, requires = "scene")]
    pub solver: Option<String>,
    /// Families side by side on the scene, each at its cheapest passing
    /// configuration, ranked by exact operations per tick: `paper` (the
    /// force-based methods, or --methods), `xpbd`, `xpbd_jacobi`,
    /// `soft_step` (comma-separated).
    #[arg(long, value_delimiter = ',', requires = "scene", conflicts_with = "solver")]
    pub solvers: Vec<String>,
    /// Substeps per tick for --solver (with --iterations).
    #[arg(long, requires = "solver", requires = "iterations")]
    pub substeps: Option<u64>,
    /// Iterations per substep for --solver (with --substeps; 1 for soft_step).
    #[arg(long, requires = "solver", requires = "substeps")]
    pub iterations: Option<u64>,
    /// Jacobi's relaxation factor for --solver xpbd_jacobi (default 1: plain Jacobi).
    #[arg(long, requires = "solver")]
    pub relaxation: Option<f64>,
    /// What the recommendation is ranked by: `exact` operations per tick
    /// (the same answer on every machine; ties by name) or the ns
    /// `measured` on this machine.
    #[arg(long, value_parser = ["exact", "measured"], default_value = "exact")]
    pub rank: String,
    #[arg(long, value_parser = Format::parser(TEXT_JSON), default_value = "text")]
    pub format: Format,
}

/// Update orders `--sweep` can analyse.
#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum SweepArg {
    /// Bodies updated in sequence, each seeing those already updated.
    GaussSeidel,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    if let Some(path) = &args.scene {
        return run_scene(path, &args);
    }
    let (Some(freq_hz), Some(tick_hz)) = (args.freq, args.tick) else {
        return Err(Error::usage("expected --freq and --tick, or --scene FILE"));
    };
    // The one-spring table compares the seven direct methods (with
    // --damping, each on the damped spring); --methods would be ignored.
    if !args.methods.is_empty() {
        return Err(Error::usage(format!(
            "--methods {}: the candidates of a scene (--scene FILE); with --freq and --tick \
             zcheck advise compares the seven direct methods. Expected --scene FILE (a one-mode \
             scene is one body and one spring), or zcheck tradeoff --method {} to rank a method \
             of your own",
            args.methods.join(","),
            args.methods[0]
        )));
    }
    if let Some(p) = args.params.first() {
        return Err(Error::usage(format!(
            "--param {}={}: binds a parameter of a tableau among the candidates of a scene \
             (--scene FILE --methods FILE.toml); with --freq and --tick zcheck advise compares \
             the seven direct methods",
            p.name, p.value
        )));
    }
    let scene = SpringScene {
        freq_hz,
        tick_hz,
        duration_s: args.duration,
        phase_tol: args.phase_tol,
        amp_tol: args.amp_tol,
        damping: args.damping.as_ref().map(|d| d.to_f64("--damping")).transpose()?,
    };
    scene.validate()?;
    // The seven direct methods on the damped spring: the whole-scene
    // advisor's candidates below and, with --damping, the table's too,
    // derived once for both.
    let damped = LoadedMethod::damped_builtins()?;
    let cands = match &args.damping {
        Some(d) => family::damped_candidates(&damped, &d.value)?,
        None => family::undamped_family()?
            .into_iter()
            .filter(|c| poly::advanced::builtins::PAPER_METHODS.contains(&c.name.as_str()))
            .collect(),
    };
    let d = scene.damping.unwrap_or(0.0);
    let budget = Duration::from_millis(3);
    let ns: Vec<f64> =
        cands.iter().map(|c| super::tradeoff::measure(c, budget)).collect::<Result<_, Error>>()?;
    let mut k = 0;
    crate::interrupt::install();
    let by = Rank::parse(&args.rank).unwrap_or_default();
    let mut advice = advise_spring(&scene, &cands, by, |_| {
        k += 1;
        ns[k - 1]
    })?;
    // advise_spring keeps the candidates' order.
    for (m, c) in advice.methods.iter_mut().zip(&cands) {
        m.ns_per_step_hand = c.hand_kernel.and_then(|h| kernels::time_hand_kernel(h, d, budget));
    }
    // The same spring as a one-mode scene, through the whole-scene advisor:
    // its modes, candidates (with the simulation that checks the
    // prediction) and recommendation, in the scene JSON's keys.
    let one_mode =
        SceneFile::one_mode(freq_hz, d, tick_hz, args.duration, args.phase_tol, args.amp_tol);
    let simulate = !args.no_simulate;
    let modal = modal_of(&one_mode, simulate, modal::Route::Auto)?;
    let options = Options {
        simulate,
        simulate_all: args.simulate_all,
        gauss_seidel: false,
        route: modal::Route::Auto,
        rank: by,
    };
    let as_scene = advisor::advise(&one_mode, &modal, damped, options)?;
    match args.format {
        Format::Json => {
            let out = OneSpring {
                advice: &advice,
                modes: &as_scene.modes,
                candidates: &as_scene.candidates,
                recommended: &as_scene.recommended,
            };
            super::output::emitln(&serde_json::to_string_pretty(&out)?)?
        }
        _ => {
            let mut t = text(&advice);
            t += &format!(
                "as a one-mode scene (zcheck advise --scene): {}\n",
                match &as_scene.recommended {
                    Some(r) => format!("{} with {} substeps per tick", r.method, r.substeps),
                    None => "none meets the target".to_owned(),
                }
            );
            for c in &as_scene.candidates {
                if c.simulated.as_ref().is_some_and(|s| !s.agree) {
                    t += &format!("WARNING: {}: prediction and simulation disagree\n", c.method);
                }
            }
            super::output::emit(&t)?
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// `zcheck advise --scene FILE`.
fn run_scene(path: &std::path::Path, args: &Args) -> Result<ExitCode, Error> {
    let scene = if crate::scene::mesh::is_mesh(path) {
        let text = crate::scene::mesh::scene_toml(path, &args.mesh)?;
        SceneFile::parse(&format!("{} (as a scene)", path.display()), &text)?
    } else if args.mesh.any() {
        return Err(Error::usage(format!(
            "--density, --stiffness, --bending, --spring-ratio, --fix-group, --fix-box and --tick-hz describe a mesh: expected --scene FILE.obj, not {}",
            path.display()
        )));
    } else {
        SceneFile::load(path)?
    };
    if args.duration != SpringScene::DEFAULT_DURATION_S
        || args.phase_tol != SpringScene::DEFAULT_PHASE_TOL
        || args.amp_tol != SpringScene::DEFAULT_AMP_TOL
    {
        return Err(Error::usage(
            "--duration, --phase-tol and --amp-tol belong in the scene file with --scene \
             (duration_s, [accuracy])",
        ));
    }
    if !args.solvers.is_empty() {
        let families = crate::answers::families::parse_families(&args.solvers)?;
        let options = Options {
            simulate: !args.no_simulate,
            simulate_all: args.simulate_all,
            gauss_seidel: false,
            route: args.spectrum,
            rank: Rank::Exact,
        };
        crate::interrupt::install();
        let table = crate::answers::families::family_table(
            &scene,
            &families,
            &args.methods,
            &args.params,
            options,
        )?;
        match args.format {
            Format::Json => super::output::emitln(&serde_json::to_string_pretty(&table)?)?,
            _ => super::output::emit(&crate::answers::families::family_text(
                &path.display().to_string(),
                &table,
            ))?,
        }
        return Ok(ExitCode::SUCCESS);
    }
    if let Some(word) = &args.solver {
        let solver = crate::scene::solvers::Solver::parse(word)?;
        let config = args.substeps.zip(args.iterations);
        let advice = match args.relaxation {
            Some(factor) => {
                crate::scene::solvers::solver_advice_relaxed(&scene, solver, config, factor)?
            }
            None => crate::scene::solvers::solver_advice(&scene, solver, config)?,
        };
        match args.format {
            Format::Json => super::output::emitln(&serde_json::to_string_pretty(&advice)?)?,
            _ => super::output::emit(&crate::answers::advice::solver_text(
                &path.display().to_string(),
                &advice,
            ))?,
        }
        return Ok(ExitCode::SUCCESS);
    }
    let options = Options {
        simulate: !args.no_simulate,
        simulate_all: args.simulate_all,
        gauss_seidel: args.sweep.is_some(),
        route: args.spectrum,
        rank: Rank::parse(&args.rank).unwrap_or_default(),
    };
    crate::interrupt::install();
    let advice = scene_advice(&scene, &args.methods, &args.params, options)?;
    match args.format {
        Format::Json => super::output::emitln(&serde_json::to_string_pretty(&advice)?)?,
        _ => super::output::emit(&scene_text(&path.display().to_string(), &advice))?,
    }
    Ok(ExitCode::SUCCESS)
}
