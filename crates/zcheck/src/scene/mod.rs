//! The appendix scenes: three bodies (Appendices C and D) and an aircraft's
//! rotation (Appendix E), each with only the state, parameters and forces it
//! needs, a high-accuracy reference, and the invariants it is judged by.
//!
//! And a user's scene of masses and springs: [`file`] reads it (TOML),
//! [`modal`] reduces it to modes, [`vector`] runs the paper's methods on the
//! whole system (all bodies at once, or Gauss–Seidel), and [`advisor`]
//! picks method and substeps from the exact (Φ, D) regions.
//!
//! Names: `three_body_false_euler` (C), `three_body_euler` and
//! `three_body_euler_energy` (D), `aircraft` (E). Each scene's module says
//! where it departs from the paper's Pascal code and why.

use std::fmt;

use serde::Serialize;

pub mod advisor;
pub mod aircraft;
pub mod figure;
pub mod file;
pub mod modal;
pub mod reference;
pub mod three_body;
pub mod vector;

use aircraft::AircraftConfig;
use three_body::ThreeBodyConfig;

/// The scene names, in the paper's order.
pub const SCENES: [&str; 4] =
    ["three_body_false_euler", "three_body_euler", "three_body_euler_energy", "aircraft"];

/// A scene with its configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scene {
    ThreeBody(ThreeBodyConfig),
    Aircraft(AircraftConfig),
}

impl Scene {
    /// The scene called `name`, configured as its appendix does.
    pub fn by_name(name: &str) -> Result<Scene, SceneError> {
        match name {
            "three_body_false_euler" => Ok(Scene::ThreeBody(ThreeBodyConfig::appendix_c())),
            "three_body_euler" => Ok(Scene::ThreeBody(ThreeBodyConfig::appendix_d())),
            "three_body_euler_energy" => Ok(Scene::ThreeBody(ThreeBodyConfig::appendix_d_energy())),
            "aircraft" => Ok(Scene::Aircraft(AircraftConfig::default())),
            _ => Err(SceneError::UnknownScene(name.to_string())),
        }
    }

    /// The appendix the scene belongs to.
    pub fn appendix(name: &str) -> Option<&'static str> {
        match name {
            "three_body_false_euler" => Some("C"),
            "three_body_euler" | "three_body_euler_energy" => Some("D"),
            "aircraft" => Some("E"),
            _ => None,
        }
    }

    /// The default number of steps: 10^6 for C (its "ad infinitum"), the
    /// paper's 100,000 for D, 60 s of flight for E.
    pub fn default_steps(&self) -> u64 {
        match self {
            Scene::ThreeBody(c) if c.integrator == three_body::Integrator::FalseEuler => 1_000_000,
            Scene::ThreeBody(_) => 100_000,
            Scene::Aircraft(_) => 600,
        }
    }
}

/// Errors of the scenes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SceneError {
    /// No scene has this name.
    UnknownScene(String),
    /// Newton's method found no steady turn of the aircraft.
    NoSteadyState,
    /// A figure could not be drawn or written.
    Figure(String),
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::UnknownScene(name) => {
                write!(f, "unknown scene `{name}`, expected one of: {}", SCENES.join(", "))
            }
            SceneError::NoSteadyState => {
                write!(f, "no steady turn found for the aircraft's command")
            }
            SceneError::Figure(message) => write!(f, "cannot draw figure {message}"),
        }
    }
}

impl std::error::Error for SceneError {}

/// A quantity followed over a run: its first and last value, its range and
/// its largest departure from the first value.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Track {
    pub initial: f64,
    pub last: f64,
    pub min: f64,
    pub max: f64,
    pub max_abs_drift: f64,
}

impl Track {
    /// Start following a quantity at `initial`.
    pub fn new(initial: f64) -> Self {
        Track { initial, last: initial, min: initial, max: initial, max_abs_drift: 0.0 }
    }

    /// Record the next value (a NaN makes the drift NaN, so it shows).
    pub fn push(&mut self, value: f64) {
        self.last = value;
        self.min = self.min.min(value);
        self.max = self.max.max(value);
        let drift = (value - self.initial).abs();
        self.max_abs_drift = if drift.is_nan() { f64::NAN } else { self.max_abs_drift.max(drift) };
    }

    /// The summary the JSON report carries.
    pub fn summary(&self) -> Summary {
        Summary {
            initial: self.initial,
            r#final: self.last,
            max_abs_drift: self.max_abs_drift,
            max_rel_drift: if self.initial != 0.0 {
                Some(self.max_abs_drift / self.initial.abs())
            } else {
                None
            },
        }
    }
}

/// An invariant over a run: initial and final value and the largest drift,
/// absolute and relative to |initial| (none when the initial value is 0).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Summary {
    pub initial: f64,
    pub r#final: f64,
    pub max_abs_drift: f64,
    pub max_rel_drift: Option<f64>,
}
