//! The appendix scenes: three bodies (Appendices C and D) and an aircraft's
//! rotation (Appendix E), each with only the state, parameters and forces it
//! needs, a high-accuracy reference, and the invariants it is judged by.
//!
//! And a user's scene of masses and springs: [`file`](mod@file) reads it (TOML),
//! [`modal`] reduces it to modes, `vector` runs the paper's methods on the
//! whole system (all bodies at once, or Gauss–Seidel), and [`advisor`], the
//! whole-scene advisor, picks method and substeps from the exact (Φ, D)
//! regions.
//!
//! Names: `three_body_false_euler` (C), `three_body_euler` and
//! `three_body_euler_energy` (D), `aircraft` (E). Each scene's module says
//! where it departs from the paper's Pascal code and why.

pub mod advisor;
pub mod aircraft;
pub(crate) mod figure;
pub mod file;
pub mod mesh;
pub mod modal;
pub(crate) mod reference;
pub(crate) mod solvers;
pub(crate) mod sparse;
pub(crate) mod spectrum;
pub mod three_body;
pub(crate) mod track;
pub(crate) mod vector;

use crate::error::Error;
use aircraft::AircraftConfig;
use three_body::ThreeBodyConfig;

/// The scene names, in the paper's order.
pub(crate) const SCENES: [&str; 4] =
    ["three_body_false_euler", "three_body_euler", "three_body_euler_energy", "aircraft"];

/// A scene with its configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Scene {
    ThreeBody(ThreeBodyConfig),
    Aircraft(AircraftConfig),
}

impl Scene {
    /// The scene called `name`, configured as its appendix does.
    pub(crate) fn by_name(name: &str) -> Result<Scene, Error> {
        match name {
            "three_body_false_euler" => Ok(Scene::ThreeBody(ThreeBodyConfig::appendix_c())),
            "three_body_euler" => Ok(Scene::ThreeBody(ThreeBodyConfig::appendix_d())),
            "three_body_euler_energy" => Ok(Scene::ThreeBody(ThreeBodyConfig::appendix_d_energy())),
            "aircraft" => Ok(Scene::Aircraft(AircraftConfig::default())),
            _ => Err(Error::usage(format!(
                "unknown scene `{name}`, expected one of: {}",
                SCENES.join(", ")
            ))),
        }
    }

    /// The appendix the scene belongs to.
    pub(crate) fn appendix(name: &str) -> Option<&'static str> {
        match name {
            "three_body_false_euler" => Some("C"),
            "three_body_euler" | "three_body_euler_energy" => Some("D"),
            "aircraft" => Some("E"),
            _ => None,
        }
    }

    /// The default number of steps: 10^6 for C (its "ad infinitum"), the
    /// paper's 100,000 for D, 60 s of flight for E.
    pub(crate) fn default_steps(&self) -> u64 {
        match self {
            Scene::ThreeBody(c) if c.integrator == three_body::Integrator::FalseEuler => 1_000_000,
            Scene::ThreeBody(_) => 100_000,
            Scene::Aircraft(_) => 600,
        }
    }
}
