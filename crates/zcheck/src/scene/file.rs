//! Scene files: a game scene as a TOML file of masses and springs, or of
//! modes, with its tick rate, duration and accuracy target.
//!
//! ```toml
//! tick_hz = 60
//! duration_s = 10
//! [accuracy]
//! phase_rad = 0.1      # largest phase error of any mode over the duration
//! amplitude = 0.01     # largest relative amplitude error of any mode
//! [[mass]]
//! name = "a"
//! kg = 1.0
//! [[spring]]
//! between = ["a", "ground"]
//! stiffness = 400.0    # N/m
//! ratio = 0.05         # or damping = 0.5 (N·s/m)
//! ```
//!
//! or `[[mode]]` entries with `hz` and `ratio`. A spring's `ratio` is
//! ζ = c / (2√(k·μ)) with μ the reduced mass of its two ends (the mass
//! itself for a spring to ground). Every mistake is reported with the line
//! and column the TOML parser gives for the offending value.

use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use crate::error::{line_col, Error};

/// The name that fixes a spring's end to the world.
pub(crate) const GROUND: &str = "ground";

/// A scene read from a file.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneFile {
    /// The simulation tick rate, Hz.
    pub(crate) tick_hz: f64,
    /// How long the scene must stay within the target, seconds.
    pub(crate) duration_s: f64,
    /// Largest phase error of any mode over the duration, radians.
    pub(crate) phase_rad: f64,
    /// Largest relative amplitude error of any mode over the duration.
    pub(crate) amplitude: f64,
    /// What moves.
    pub(crate) body: Body,
}

/// The moving parts of a scene.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Body {
    /// Point masses joined by springs.
    Springs {
        /// The masses, in file order.
        masses: Vec<Mass>,
        /// The springs.
        springs: Vec<Spring>,
    },
    /// Modes given directly.
    Modes(Vec<ModeSpec>),
}

/// A point mass.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Mass {
    /// Its name.
    pub name: String,
    /// Its mass, kg.
    pub kg: f64,
}

/// A linear spring with an optional viscous damper in parallel.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Spring {
    /// Index of the first end's mass.
    pub a: usize,
    /// Index of the second end's mass; `None` for the ground.
    pub b: Option<usize>,
    /// Stiffness, N/m.
    pub stiffness: f64,
    /// Damping coefficient, N·s/m (0 when undamped).
    pub damping: f64,
}

/// A mode given directly.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ModeSpec {
    /// Its undamped natural frequency, Hz.
    pub hz: f64,
    /// Its damping ratio ζ.
    pub ratio: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    tick_hz: Option<Spanned<f64>>,
    duration_s: Option<Spanned<f64>>,
    accuracy: Option<RawAccuracy>,
    #[serde(default)]
    mass: Vec<RawMass>,
    #[serde(default)]
    spring: Vec<Spanned<RawSpring>>,
    #[serde(default)]
    mode: Vec<RawMode>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAccuracy {
    phase_rad: Option<Spanned<f64>>,
    amplitude: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMass {
    name: Spanned<String>,
    kg: Spanned<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSpring {
    between: Spanned<Vec<Spanned<String>>>,
    stiffness: Spanned<f64>,
    damping: Option<Spanned<f64>>,
    ratio: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMode {
    hz: Spanned<f64>,
    ratio: Option<Spanned<f64>>,
}

/// Defaults for a scene file that leaves them out.
pub(crate) const DEFAULT_DURATION_S: f64 = 1.0;
/// Default phase target, radians.
pub(crate) const DEFAULT_PHASE_RAD: f64 = 0.1;
/// Default amplitude target.
pub(crate) const DEFAULT_AMPLITUDE: f64 = 0.01;

impl SceneFile {
    /// Reads and checks a scene file.
    pub(crate) fn load(path: &Path) -> Result<SceneFile, Error> {
        let shown = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| Error::file(&shown, 0, 0, &format!("cannot read the scene file: {e}")))?;
        SceneFile::parse(&shown, &text)
    }

    /// Parses and checks the text of a scene file; `path` names it in errors.
    pub fn parse(path: &str, text: &str) -> Result<SceneFile, Error> {
        let err = |span: Option<Range<usize>>, message: String| {
            let (line, col) = line_col(text, span.map_or(0, |s| s.start));
            Error::file(path, line, col, &message)
        };
        let raw: Raw = toml::from_str(text).map_err(|e| {
            err(e.span(), e.message().trim_end_matches('\n').replace('\n', "; ").to_string())
        })?;
        let positive = |v: &Spanned<f64>, what: &str| {
            let x = *v.get_ref();
            if x.is_finite() && x > 0.0 {
                Ok(x)
            } else {
                Err(err(Some(v.span()), format!("{what} = {x}: expected a finite number > 0")))
            }
        };
        let non_negative = |v: &Spanned<f64>, what: &str| {
            let x = *v.get_ref();
            if x.is_finite() && x >= 0.0 {
                Ok(x)
            } else {
                Err(err(Some(v.span()), format!("{what} = {x}: expected a finite number >= 0")))
            }
        };
        let tick_hz =
            match &raw.tick_hz {
                Some(t) => positive(t, "tick_hz")?,
                None => return Err(err(
                    None,
                    "missing tick rate: expected `tick_hz = ...` (the simulation ticks per second)"
                        .into(),
                )),
            };
        let duration_s = match &raw.duration_s {
            Some(d) => positive(d, "duration_s")?,
            None => DEFAULT_DURATION_S,
        };
        let (mut phase_rad, mut amplitude) = (DEFAULT_PHASE_RAD, DEFAULT_AMPLITUDE);
        if let Some(acc) = &raw.accuracy {
            if let Some(p) = &acc.phase_rad {
                phase_rad = positive(p, "phase_rad")?;
            }
            if let Some(a) = &acc.amplitude {
                amplitude = positive(a, "amplitude")?;
            }
        }
        let body = if !raw.mode.is_empty() {
            if let Some(m) = raw.mass.first() {
                return Err(err(
                    Some(m.name.span()),
                    "a scene lists either [[mass]] and [[spring]] entries or [[mode]] entries, \
                     not both"
                        .into(),
                ));
            }
            let mut modes = Vec::new();
            for m in &raw.mode {
                let hz = positive(&m.hz, "hz")?;
                let ratio = match &m.ratio {
                    Some(r) => non_negative(r, "ratio")?,
                    None => 0.0,
                };
                modes.push(ModeSpec { hz, ratio });
            }
            Body::Modes(modes)
        } else {
            let mut index: HashMap<String, usize> = HashMap::new();
            let mut masses = Vec::new();
            for m in &raw.mass {
                let name = m.name.get_ref().clone();
                if name == GROUND {
                    return Err(err(
                        Some(m.name.span()),
                        format!("mass name \"{GROUND}\" is reserved for the world"),
                    ));
                }
                if index.contains_key(&name) {
                    return Err(err(
                        Some(m.name.span()),
                        format!("mass \"{name}\" is defined twice: expected unique names"),
                    ));
                }
                let kg = positive(&m.kg, "kg")?;
                index.insert(name.clone(), masses.len());
                masses.push(Mass { name, kg });
            }
            let mut springs = Vec::new();
            for s in &raw.spring {
                let s_span = s.span();
                let s = s.get_ref();
                let ends = s.between.get_ref();
                if ends.len() != 2 {
                    return Err(err(
                        Some(s.between.span()),
                        format!(
                            "between has {} names: expected two, e.g. [\"a\", \"ground\"]",
                            ends.len()
                        ),
                    ));
                }
                let mut idx = [None, None];
                for (k, e) in ends.iter().enumerate() {
                    let name = e.get_ref();
                    if name == GROUND {
                        continue;
                    }
                    match index.get(name) {
                        Some(&i) => idx[k] = Some(i),
                        None => {
                            let known: Vec<&str> =
                                raw.mass.iter().map(|m| m.name.get_ref().as_str()).collect();
                            return Err(err(
                                Some(e.span()),
                                format!(
                                    "unknown mass \"{name}\": expected one of {}{GROUND}",
                                    known.iter().map(|k| format!("{k}, ")).collect::<String>()
                                ),
                            ));
                        }
                    }
                }
                let (a, b) = match idx {
                    [Some(a), b] => (a, b),
                    [None, Some(b)] => (b, None),
                    [None, None] => {
                        return Err(err(
                            Some(s.between.span()),
                            "a spring between ground and ground moves nothing: expected a mass at one end".into(),
                        ))
                    }
                };
                if b == Some(a) {
                    return Err(err(
                        Some(s.between.span()),
                        "a spring from a mass to itself: expected two different ends".into(),
                    ));
                }
                let stiffness = positive(&s.stiffness, "stiffness")?;
                let damping = match (&s.damping, &s.ratio) {
                    (Some(_), Some(r)) => {
                        return Err(err(
                            Some(r.span()),
                            "a spring gives either damping (N·s/m) or ratio, not both".into(),
                        ))
                    }
                    (Some(c), None) => non_negative(c, "damping")?,
                    (None, Some(r)) => {
                        let zeta = non_negative(r, "ratio")?;
                        let mu = match b {
                            None => masses[a].kg,
                            Some(b) => masses[a].kg * masses[b].kg / (masses[a].kg + masses[b].kg),
                        };
                        2.0 * zeta * (stiffness * mu).sqrt()
                    }
                    (None, None) => 0.0,
                };
                let _ = s_span;
                springs.push(Spring { a, b, stiffness, damping });
            }
            if masses.is_empty() {
                return Err(err(
                    None,
                    "empty scene: expected [[mass]] entries joined by [[spring]] entries, or [[mode]] entries"
                        .into(),
                ));
            }
            if springs.is_empty() {
                return Err(err(
                    Some(raw.mass[0].name.span()),
                    "empty scene: the masses have no [[spring]]: expected at least one".into(),
                ));
            }
            Body::Springs { masses, springs }
        };
        Ok(SceneFile { tick_hz, duration_s, phase_rad, amplitude, body })
    }

    /// A one-mode scene: a spring of `hz` with damping ratio `ratio`.
    pub(crate) fn one_mode(
        hz: f64,
        ratio: f64,
        tick_hz: f64,
        duration_s: f64,
        phase_rad: f64,
        amplitude: f64,
    ) -> SceneFile {
        SceneFile {
            tick_hz,
            duration_s,
            phase_rad,
            amplitude,
            body: Body::Modes(vec![ModeSpec { hz, ratio }]),
        }
    }

    /// Degrees of freedom: masses, or modes.
    pub fn dof(&self) -> usize {
        match &self.body {
            Body::Springs { masses, .. } => masses.len(),
            Body::Modes(m) => m.len(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Location;

    #[track_caller]
    fn bad(text: &str, line: usize, col: usize, needle: &str) {
        let e = SceneFile::parse("s.toml", text).expect_err("a bad scene");
        assert_eq!(e.location(), Some(Location { line, col }), "{e}");
        assert!(e.to_string().contains(needle), "{e}");
    }

    /// Each listed mistake is located at the offending value.
    #[test]
    fn bad_scenes_are_located() {
        let head = "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 1.0\n";
        bad(
            &format!("{head}[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 1.0\n"),
            6,
            17,
            "unknown mass \"b\"",
        );
        bad("tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = -1.0\n", 4, 6, "kg = -1");
        bad(
            &format!("{head}[[spring]]\nbetween = [\"a\", \"ground\"]\nstiffness = 0\n"),
            7,
            13,
            "stiffness = 0",
        );
        bad("[[mode]]\nhz = 1.0\n", 1, 1, "missing tick rate");
        bad("tick_hz = 60\n", 1, 1, "empty scene");
        bad("tick_hz = 60\n[[mode]]\nhz = 1.0\nfreq = 2\n", 4, 1, "unknown field");
        bad("tick_hz = \n", 1, 11, "");
    }

    /// A spring to ground given by its ratio gets c = 2ζ√(k m).
    #[test]
    fn ratio_to_ground() {
        let s = SceneFile::parse(
            "s.toml",
            "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 4.0\n[[spring]]\nbetween = [\"ground\", \"a\"]\nstiffness = 100.0\nratio = 0.5\n",
        )
        .unwrap();
        let Body::Springs { springs, .. } = s.body else { panic!("springs") };
        assert_eq!(springs[0], Spring { a: 0, b: None, stiffness: 100.0, damping: 20.0 });
    }
}
