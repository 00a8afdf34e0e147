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
//! itself for a spring to ground or to a fixed mass). Every mistake is
//! reported with the line and column the TOML parser gives for the
//! offending value.
//!
//! Particles: when every mass carries `pos = [x, y]` or `pos = [x, y, z]`,
//! each has 2 or 3 degrees of freedom and a spring acts along its rest
//! direction (see `modal`); `fixed = true` pins a mass (in any scene).
//! `[accuracy] max_hz = F` applies the phase and amplitude targets only
//! to modes at or below F Hz; every mode must still be stable.

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
    /// The accuracy targets apply to modes at or below this frequency, Hz
    /// (`None`: to every mode).
    pub(crate) max_hz: Option<f64>,
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
        /// Degrees of freedom per mass: 1 (scalar), or 2 or 3 (`pos`).
        dim: usize,
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
    /// Its rest position (every mass has one, of the same length, or none
    /// has).
    pub pos: Option<Vec<f64>>,
    /// Whether it is pinned (its degrees of freedom removed).
    pub fixed: bool,
}

/// A linear spring with an optional viscous damper in parallel.
#[derive(Clone, Debug, PartialEq)]
pub struct Spring {
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
    max_hz: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMass {
    name: Spanned<String>,
    kg: Spanned<f64>,
    pos: Option<Spanned<Vec<f64>>>,
    fixed: Option<Spanned<bool>>,
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

/// Files above this size are parsed in chunks of about this size.
const CHUNK_BYTES: usize = 4 << 20;

/// The text cut into chunks of at least [`CHUNK_BYTES`] at lines that open
/// a `[[mass]]`, `[[spring]]` or `[[mode]]` table, each with its byte
/// offset; the whole text as one chunk when it is small or holds a
/// multi-line string (a header inside one is not a header).
fn chunks(text: &str) -> Vec<(usize, &str)> {
    chunks_of(text, CHUNK_BYTES)
}

/// [`chunks`] with the chunk size given (tests cut small files).
fn chunks_of(text: &str, chunk_bytes: usize) -> Vec<(usize, &str)> {
    if text.len() <= 2 * chunk_bytes || text.contains("\"\"\"") || text.contains("'''") {
        return vec![(0, text)];
    }
    let mut out = Vec::new();
    let mut start = 0;
    let mut line = 0;
    while line < text.len() {
        let end = text[line..].find('\n').map_or(text.len(), |i| line + i + 1);
        let head = text[line..end].trim_end();
        let header = ["[[mass]]", "[[spring]]", "[[mode]]"].iter().any(|h| {
            head == *h || head.strip_prefix(h).is_some_and(|r| r.trim_start().starts_with('#'))
        });
        if header && line - start >= chunk_bytes {
            out.push((start, &text[start..line]));
            start = line;
        }
        line = end;
    }
    out.push((start, &text[start..]));
    out
}

/// Defaults for a scene file that leaves them out.
pub const DEFAULT_DURATION_S: f64 = 1.0;
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
        // A large file is parsed in chunks cut at its `[[mass]]`,
        // `[[spring]]` and `[[mode]]` headers, so the parser's tree of one
        // chunk at a time is held, not the whole file's; each span is then
        // shifted by its chunk's offset.
        SceneFile::parse_chunks(path, text, chunks(text))
    }

    /// [`SceneFile::parse`] over the chunks given.
    fn parse_chunks(
        path: &str,
        text: &str,
        chunks: Vec<(usize, &str)>,
    ) -> Result<SceneFile, Error> {
        let err = |span: Option<Range<usize>>, message: String| {
            let (line, col) = line_col(text, span.map_or(0, |s| s.start));
            Error::file(path, line, col, &message)
        };
        let mut raws: Vec<(usize, Raw)> = Vec::new();
        for (off, chunk) in chunks {
            let raw: Raw = toml::from_str(chunk).map_err(|e| {
                err(
                    e.span().map(|s| s.start + off..s.end + off),
                    e.message().trim_end_matches('\n').replace('\n', "; ").to_string(),
                )
            })?;
            raws.push((off, raw));
        }
        let at = |off: usize, span: Range<usize>| Some(span.start + off..span.end + off);
        let positive = |off: usize, v: &Spanned<f64>, what: &str| {
            let x = *v.get_ref();
            if x.is_finite() && x > 0.0 {
                Ok(x)
            } else {
                Err(err(at(off, v.span()), format!("{what} = {x}: expected a finite number > 0")))
            }
        };
        let non_negative = |off: usize, v: &Spanned<f64>, what: &str| {
            let x = *v.get_ref();
            if x.is_finite() && x >= 0.0 {
                Ok(x)
            } else {
                Err(err(at(off, v.span()), format!("{what} = {x}: expected a finite number >= 0")))
            }
        };
        // Later chunks start at a table header, so only the first holds
        // top-level keys; [accuracy] may come anywhere, once.
        let raw = &raws[0].1;
        let mut accuracy: Option<(usize, &RawAccuracy)> = None;
        for (off, r) in &raws {
            if let Some(a) = &r.accuracy {
                if accuracy.is_some() {
                    return Err(err(at(*off, 0..0), "duplicate table [accuracy]".into()));
                }
                accuracy = Some((*off, a));
            }
        }
        let all_mass = || raws.iter().flat_map(|(off, r)| r.mass.iter().map(move |m| (*off, m)));
        let all_spring =
            || raws.iter().flat_map(|(off, r)| r.spring.iter().map(move |m| (*off, m)));
        let all_mode = || raws.iter().flat_map(|(off, r)| r.mode.iter().map(move |m| (*off, m)));
        let tick_hz =
            match &raw.tick_hz {
                Some(t) => positive(0, t, "tick_hz")?,
                None => return Err(err(
                    None,
                    "missing tick rate: expected `tick_hz = ...` (the simulation ticks per second)"
                        .into(),
                )),
            };
        let duration_s = match &raw.duration_s {
            Some(d) => positive(0, d, "duration_s")?,
            None => DEFAULT_DURATION_S,
        };
        let (mut phase_rad, mut amplitude) = (DEFAULT_PHASE_RAD, DEFAULT_AMPLITUDE);
        let mut max_hz = None;
        if let Some((off, acc)) = accuracy {
            if let Some(f) = &acc.max_hz {
                max_hz = Some(positive(off, f, "max_hz")?);
            }
            if let Some(p) = &acc.phase_rad {
                phase_rad = positive(off, p, "phase_rad")?;
            }
            if let Some(a) = &acc.amplitude {
                amplitude = positive(off, a, "amplitude")?;
            }
        }
        let body = if all_mode().next().is_some() {
            if let Some((off, m)) = all_mass().next() {
                return Err(err(
                    at(off, m.name.span()),
                    "a scene lists either [[mass]] and [[spring]] entries or [[mode]] entries, \
                     not both"
                        .into(),
                ));
            }
            let mut modes = Vec::new();
            for (off, m) in all_mode() {
                let hz = positive(off, &m.hz, "hz")?;
                let ratio = match &m.ratio {
                    Some(r) => non_negative(off, r, "ratio")?,
                    None => 0.0,
                };
                modes.push(ModeSpec { hz, ratio });
            }
            Body::Modes(modes)
        } else {
            let mut index: HashMap<String, usize> = HashMap::new();
            let mut masses = Vec::new();
            for (off, m) in all_mass() {
                let name = m.name.get_ref().clone();
                if name == GROUND {
                    return Err(err(
                        at(off, m.name.span()),
                        format!("mass name \"{GROUND}\" is reserved for the world"),
                    ));
                }
                if index.contains_key(&name) {
                    return Err(err(
                        at(off, m.name.span()),
                        format!("mass \"{name}\" is defined twice: expected unique names"),
                    ));
                }
                let kg = positive(off, &m.kg, "kg")?;
                let pos = match &m.pos {
                    Some(p) => {
                        let v = p.get_ref();
                        if !(2..=3).contains(&v.len()) || v.iter().any(|x| !x.is_finite()) {
                            return Err(err(
                                at(off, p.span()),
                                format!(
                                    "pos = {v:?}: expected [x, y] or [x, y, z] of finite numbers"
                                ),
                            ));
                        }
                        Some(v.clone())
                    }
                    None => None,
                };
                let fixed = m.fixed.as_ref().is_some_and(|f| *f.get_ref());
                index.insert(name.clone(), masses.len());
                masses.push(Mass { name, kg, pos, fixed });
            }
            // Either every mass has a position, all of one length, or none.
            let dim = match masses.iter().find(|m| m.pos.is_some()) {
                None => 1,
                Some(fm) => {
                    let d = fm.pos.as_ref().map_or(1, Vec::len);
                    for ((off, rm), m) in all_mass().zip(&masses) {
                        match (&rm.pos, &m.pos) {
                            (None, _) | (_, None) => {
                                return Err(err(
                                    at(off, rm.name.span()),
                                    format!(
                                        "mass \"{}\" has no pos but mass \"{}\" has: expected pos on every mass or on none",
                                        m.name, fm.name
                                    ),
                                ))
                            }
                            (Some(p), Some(v)) if v.len() != d => {
                                return Err(err(
                                    at(off, p.span()),
                                    format!(
                                        "pos has {} coordinates but mass \"{}\" has {d}: expected the same in every mass",
                                        v.len(),
                                        fm.name
                                    ),
                                ))
                            }
                            _ => {}
                        }
                    }
                    d
                }
            };
            let mut springs = Vec::new();
            for (off, s) in all_spring() {
                let s = s.get_ref();
                let ends = s.between.get_ref();
                if ends.len() != 2 {
                    return Err(err(
                        at(off, s.between.span()),
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
                            // At most eight names, so a large scene's
                            // message stays a line.
                            let known: Vec<&str> =
                                masses.iter().take(8).map(|m| m.name.as_str()).collect();
                            let more = masses.len().saturating_sub(8);
                            return Err(err(
                                at(off, e.span()),
                                format!(
                                    "unknown mass \"{name}\": expected one of {}{}{GROUND}",
                                    known.iter().map(|k| format!("{k}, ")).collect::<String>(),
                                    if more > 0 {
                                        format!("... ({more} more), ")
                                    } else {
                                        String::new()
                                    }
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
                            at(off, s.between.span()),
                            "a spring between ground and ground moves nothing: expected a mass at one end".into(),
                        ))
                    }
                };
                if b == Some(a) {
                    return Err(err(
                        at(off, s.between.span()),
                        "a spring from a mass to itself: expected two different ends".into(),
                    ));
                }
                if let (Some(b), Some(pa), Some(pb)) =
                    (b, &masses[a].pos, b.and_then(|b| masses[b].pos.as_ref()))
                {
                    let len2: f64 = pa.iter().zip(pb).map(|(x, y)| (y - x) * (y - x)).sum();
                    if !(len2.sqrt() > 0.0 && len2.is_finite()) {
                        let what = if len2.is_finite() {
                            "are at the same position: the spring has no direction; expected distinct positions"
                        } else {
                            "are too far apart for f64: expected a distance below 1e150"
                        };
                        return Err(err(
                            at(off, s.between.span()),
                            format!(
                                "masses \"{}\" and \"{}\" {what}",
                                masses[a].name, masses[b].name
                            ),
                        ));
                    }
                }
                let stiffness = positive(off, &s.stiffness, "stiffness")?;
                let damping = match (&s.damping, &s.ratio) {
                    (Some(_), Some(r)) => {
                        return Err(err(
                            at(off, r.span()),
                            "a spring gives either damping (N·s/m) or ratio, not both".into(),
                        ))
                    }
                    (Some(c), None) => non_negative(off, c, "damping")?,
                    (None, Some(r)) => {
                        let zeta = non_negative(off, r, "ratio")?;
                        let mu = match b {
                            None => masses[a].kg,
                            Some(b) if masses[b].fixed => masses[a].kg,
                            Some(b) if masses[a].fixed => masses[b].kg,
                            Some(b) => masses[a].kg * masses[b].kg / (masses[a].kg + masses[b].kg),
                        };
                        2.0 * zeta * (stiffness * mu).sqrt()
                    }
                    (None, None) => 0.0,
                };
                springs.push(Spring { a, b, stiffness, damping });
            }
            if masses.is_empty() {
                return Err(err(
                    None,
                    "empty scene: expected [[mass]] entries joined by [[spring]] entries, or [[mode]] entries"
                        .into(),
                ));
            }
            let first_name = all_mass().next().map(|(off, m)| (off, m.name.span()));
            let first_name = first_name.and_then(|(off, span)| at(off, span));
            if springs.is_empty() {
                return Err(err(
                    first_name.clone(),
                    "empty scene: the masses have no [[spring]]: expected at least one".into(),
                ));
            }
            if masses.iter().all(|m| m.fixed) {
                return Err(err(
                    first_name,
                    "every mass is fixed: nothing moves; expected at least one mass without `fixed = true`"
                        .into(),
                ));
            }
            Body::Springs { masses, springs, dim }
        };
        Ok(SceneFile { tick_hz, duration_s, phase_rad, amplitude, max_hz, body })
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
            max_hz: None,
            body: Body::Modes(vec![ModeSpec { hz, ratio }]),
        }
    }

    /// Degrees of freedom: per free mass, 1 (scalar) or its `pos`
    /// length; or modes.
    pub fn dof(&self) -> usize {
        match &self.body {
            Body::Springs { masses, dim, .. } => dim * masses.iter().filter(|m| !m.fixed).count(),
            Body::Modes(m) => m.len(),
        }
    }
}

#[cfg(test)]
mod tests {

    /// A file cut into chunks parses as it does whole, and an error in a
    /// later chunk is located in the whole file.
    #[test]
    fn chunked_parsing_is_whole_parsing() {
        let mut text = String::from("tick_hz = 60\nduration_s = 2\n");
        for i in 0..40 {
            text +=
                &format!("[[mass]]\nname = \"m{i}\"\nkg = {}\npos = [{i}, 0]\n", 1.0 + i as f64);
        }
        for i in 1..40 {
            text += &format!(
                "[[spring]] # link\nbetween = [\"m{}\", \"m{i}\"]\nstiffness = 7\n",
                i - 1
            );
        }
        text += "[accuracy]\nmax_hz = 3\n";
        let cut = chunks_of(&text, 300);
        assert!(cut.len() > 5, "{}", cut.len());
        assert_eq!(cut.iter().map(|c| c.1).collect::<String>(), text);
        let whole = SceneFile::parse_chunks("s.toml", &text, vec![(0, &text)]).unwrap();
        let chunked = SceneFile::parse_chunks("s.toml", &text, cut).unwrap();
        assert_eq!(whole, chunked);
        assert_eq!(chunked.max_hz, Some(3.0));
        // An unknown mass near the end.
        let bad = text.replace("between = [\"m37\", \"m38\"]", "between = [\"m37\", \"zz\"]");
        let line = bad.lines().position(|l| l.contains("zz")).unwrap() + 1;
        for cut in [vec![(0, bad.as_str())], chunks_of(&bad, 300)] {
            let e = SceneFile::parse_chunks("s.toml", &bad, cut).unwrap_err().to_string();
            assert!(e.contains(&format!("s.toml:{line}:")), "{e}");
        }
        // [accuracy] twice, in different chunks.
        let twice = format!(
            "{}[accuracy]\nphase_rad = 1\n",
            text.replace("[accuracy]\nmax_hz = 3\n", "").replacen(
                "[[spring]]",
                "[accuracy]\nmax_hz = 3\n[[spring]]",
                1
            )
        );
        let e = SceneFile::parse_chunks("s.toml", &twice, chunks_of(&twice, 300)).unwrap_err();
        assert!(e.to_string().contains("duplicate table [accuracy]"), "{e}");
    }
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

    /// The particle keys and `max_hz`: each mistake located at its value.
    #[test]
    fn bad_particles_are_located() {
        let two = |pa: &str, pb: &str, extra: &str| {
            format!(
                "tick_hz = 60\n[[mass]]\nname = \"a\"\nkg = 1.0\n{pa}[[mass]]\nname = \"b\"\nkg = 1.0\n{pb}{extra}[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 1.0\n"
            )
        };
        // Mixed lengths: at the second pos.
        bad(&two("pos = [0, 0]\n", "pos = [1, 0, 0]\n", ""), 9, 7, "pos has 3 coordinates");
        // pos on only some masses: at the name of one without.
        bad(&two("pos = [0, 0]\n", "", ""), 7, 8, "mass \"b\" has no pos");
        bad(&two("", "pos = [0, 0]\n", ""), 3, 8, "mass \"a\" has no pos");
        // One coordinate, or four, or not finite.
        bad(&two("pos = [0]\n", "pos = [1]\n", ""), 5, 7, "expected [x, y] or [x, y, z]");
        bad(&two("pos = [0, 0, 0, 0]\n", "pos = [1, 0, 0, 0]\n", ""), 5, 7, "expected [x, y]");
        bad(&two("pos = [0, nan]\n", "pos = [1, 0]\n", ""), 5, 7, "finite numbers");
        // Two masses at one position: the spring has no direction.
        bad(&two("pos = [0.5, 1]\n", "pos = [0.5, 1]\n", ""), 11, 11, "same position");
        // fixed must be a boolean.
        bad(&two("pos = [0, 0]\nfixed = 1\n", "pos = [1, 0]\n", ""), 6, 9, "boolean");
        // Every mass fixed: nothing moves.
        bad(&two("fixed = true\n", "fixed = true\n", ""), 3, 8, "every mass is fixed");
        // max_hz > 0 and finite.
        for (v, col) in [("0", 10), ("-3", 10), ("inf", 10), ("nan", 10)] {
            let text = format!("tick_hz = 60\n[accuracy]\nmax_hz = {v}\n[[mode]]\nhz = 1.0\n");
            bad(&text, 3, col, "max_hz");
        }
    }

    /// Positions give 2 or 3 degrees of freedom per free mass; `fixed`
    /// removes them; a ratio to a fixed mass uses the free mass.
    #[test]
    fn particles_are_read() {
        let s = SceneFile::parse(
            "s.toml",
            "tick_hz = 60\n[accuracy]\nmax_hz = 12.5\n[[mass]]\nname = \"a\"\nkg = 4.0\npos = [0, 0, 0]\nfixed = true\n[[mass]]\nname = \"b\"\nkg = 4.0\npos = [0, 0, 1]\n[[spring]]\nbetween = [\"a\", \"b\"]\nstiffness = 100.0\nratio = 0.5\n",
        )
        .unwrap();
        assert_eq!(s.max_hz, Some(12.5));
        assert_eq!(s.dof(), 3);
        let Body::Springs { springs, dim, masses } = s.body else { panic!("springs") };
        assert_eq!(dim, 3);
        assert!(masses[0].fixed && !masses[1].fixed);
        assert_eq!(springs[0].damping, 20.0);
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
