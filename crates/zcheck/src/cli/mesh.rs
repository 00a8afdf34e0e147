//! `zcheck scene-from-mesh`: a scene TOML from a triangle mesh (OBJ).

use std::process::ExitCode;

use crate::error::Error;
use crate::scene::mesh::{scene_toml, MeshOptions};

/// Arguments of `zcheck scene-from-mesh`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// The mesh, an OBJ file (`v`, `f`, and `g`/`o` for groups).
    pub file: std::path::PathBuf,
    #[command(flatten)]
    pub mesh: MeshOptions,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let text = scene_toml(&args.file, &args.mesh)?;
    // The scene reads back before it is printed.
    crate::scene::file::SceneFile::parse(&format!("{} (as a scene)", args.file.display()), &text)?;
    super::output::emit(&text)?;
    Ok(ExitCode::SUCCESS)
}
