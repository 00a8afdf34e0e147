//! Section 12, Conclusions: the two recommendations, checked against the
//! exact stability limits and the frequency/amplitude series; the satellite
//! whose radius and phase "will drift away", checked on a Kepler orbit; and
//! "higher order Runge-Kutta with stepsize control (RK-Merson,
//! RK-Fehlberg)" for all other systems, checked on the appendix scenes with
//! RK-Merson (the `merson` built-in's tableau) and Dormand–Prince.

use std::cell::Cell;
use std::f64::consts::PI;

use super::common::*;
use super::exact::p_q;
use super::{advice, ranges};
use crate::load::builtin_derivation;
use crate::paper::claim::Claim;
use crate::paper::finding::{Finding, Scope};
use crate::scene::reference::{dopri5, embedded, rk4_step, EmbeddedPair, Tolerance};
use crate::scene::three_body::{self, ThreeBodyConfig};

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("12", "sec12");
    false_euler(&mut s);
    standard_heun(&mut s);
    professional_methods(&mut s);
    satellite(&mut s);
    s.finish()
}

fn false_euler(s: &mut Section) {
    // "Guaranteed stability" within the limit section 7 states (Φ² = 4).
    let (finding, map, failing) =
        ranges::always("false_euler", |c| c.bounded() == Some(true), Some("Phi^2 - 4"));
    let fe = advice::criteria("false_euler");
    let sh = advice::criteria("standard_heun");
    let Finding::Cases { mut cases } = finding else { unreachable!("always() gives cases") };
    cases.push(crate::paper::finding::Case {
        case: "low accuracy: a phase error Ψ − Φ ≠ 0".to_owned(),
        holds: fe.phase.is_some(),
        scope: Scope::Stated,
    });
    s.push(
        "use_false_euler",
        "Use False Euler for fast calculations for the specified simple systems, like particle motion, mass and \
         spring systems or celestial motions with low accuracy but guaranteed stability.",
        format!(
            "stable only for 0 < Φ < {}, i.e. more than π steps per period (classes: {map}); {}; {}",
            ranges::limit_text("false_euler"),
            advice::text(&fe),
            advice::text(&sh),
        ),
        Finding::Cases { cases },
        format!(
            "Derivation::stability(false_euler): bounded exactly below section 7's limit, unbounded for \
             {failing}: stability is guaranteed only under T < T0/π; Derivation::psi_series gives the errors"
        ),
    );
}

fn standard_heun(s: &mut Section) {
    let (_, q) = p_q(&builtin_derivation("standard_heun"));
    let limit = ranges::limit_of(&ranges::report("standard_heun"));
    let growth: Vec<(f64, f64)> = [10.0, 20.0, 50.0, 100.0]
        .iter()
        .map(|&n: &f64| {
            let phi = 2.0 * PI / n;
            (n, super::sec09::growth_per_period(eval_f64(&q, phi), phi))
        })
        .collect();
    let rows: Vec<String> = growth
        .iter()
        .map(|(n, g)| {
            format!(
                "{n} steps/period: ×{} per period, doubles in {} periods",
                fixed(*g, 5),
                fixed(2f64.ln() / g.ln(), 0)
            )
        })
        .collect();
    let sh = advice::criteria("standard_heun");
    let se = advice::criteria("standard_euler");
    let (better, _) = advice::compare(&sh, &se);
    s.push(
        "use_standard_heun",
        "Use Standard Heun for general systems with medium accuracy and medium speed, if a sufficiently small \
         timestep can be guaranteed.",
        format!(
            "no timestep makes it stable (Φ_max: {}); the amplitude grows by (r²)^(π/Φ) per period: {}",
            ranges::limit_text("standard_heun"),
            rows.join("; ")
        ),
        Finding::scoped([
            (
                format!("medium accuracy: better than Standard Euler on {}", better.join(", ")),
                better.contains(&"phase error") && better.contains(&"amplitude error"),
                Scope::Stated,
            ),
            (
                "a small step makes the growth per period small (it shrinks with the step)".to_owned(),
                growth.windows(2).all(|w| w[1].1 < w[0].1),
                Scope::Stated,
            ),
            (
                "no step is stable, as section 9 says (\"always an unstable oscillation\"), so \
                 \"sufficiently small\" is the weak instability of section 9"
                    .to_owned(),
                limit.is_none(),
                Scope::Stated,
            ),
        ]),
        "Derivation::stability(standard_heun): no stable Φ > 0; a small step only slows the growth. Section \
         9 states both (\"always an unstable oscillation. For sufficiently small timesteps the instability \
         is weak\"), so the recommendation asserts no stability, only a growth small against the run",
    );
}

/// A Kepler orbit (GM = 1, circular, r = 1, period 2π) over `orbits`
/// orbits at `per_orbit` fixed steps: the largest |r − 1| over the first and
/// the last tenth, and the phase error (angle behind or ahead of t) at the
/// middle and at the end.
struct Orbit {
    radius_early: f64,
    radius_late: f64,
    phase_middle: f64,
    phase_end: f64,
}

fn kepler(orbits: usize, per_orbit: usize, symplectic: bool) -> Orbit {
    let h = 2.0 * PI / per_orbit as f64;
    let f = |y: &[f64; 4]| {
        let r3 = (y[0] * y[0] + y[1] * y[1]).powf(1.5);
        [y[2], y[3], -y[0] / r3, -y[1] / r3]
    };
    let mut y = [1.0, 0.0, 0.0, 1.0];
    let n = orbits * per_orbit;
    let (mut early, mut late) = (0.0f64, 0.0f64);
    let mut angle = 0.0f64;
    let mut previous = 0.0f64;
    let mut phase_middle = 0.0;
    for k in 1..=n {
        if symplectic {
            // False Euler (symplectic Euler): velocity from the old position,
            // position from the new velocity.
            let a = f(&y);
            y[2] += h * a[2];
            y[3] += h * a[3];
            y[0] += h * y[2];
            y[1] += h * y[3];
        } else {
            y = rk4_step(&f, &y, h);
        }
        let r = y[0].hypot(y[1]);
        if k <= n / 10 {
            early = early.max((r - 1.0).abs());
        }
        if k > n - n / 10 {
            late = late.max((r - 1.0).abs());
        }
        // The unwrapped polar angle against the exact angle t = k·h.
        let theta = y[1].atan2(y[0]);
        let mut d = theta - previous;
        d -= 2.0 * PI * (d / (2.0 * PI)).round();
        angle += d;
        previous = theta;
        if k == n / 2 {
            phase_middle = angle - k as f64 * h;
        }
    }
    Orbit { radius_early: early, radius_late: late, phase_middle, phase_end: angle - n as f64 * h }
}

/// "The motion of a satellite (without drag) cannot be calculated by
/// straightforward high quality integration. The radius of the trajectory
/// and the phase angle will drift away."
fn satellite(s: &mut Section) {
    let (orbits, per_orbit) = (1000, 50);
    let rk = kepler(orbits, per_orbit, false);
    let fe = kepler(orbits, per_orbit, true);
    let secular = |o: &Orbit| o.radius_late > 5.0 * o.radius_early;
    let phase_grows = |o: &Orbit| o.phase_end.abs() > 1.5 * o.phase_middle.abs();
    let sig = |x: f64| format!("{x:.2e}");
    s.push(
        "satellite_drift",
        "For example the motion of a satellite (without drag) cannot be calculated by straightforward high \
         quality integration. The radius of the trajectory and the phase angle will drift away.",
        format!(
            "Kepler circle (GM = 1, r = 1), {per_orbit} fixed steps per orbit, {orbits} orbits; RK4: |r − 1| \
             at most {} in the first tenth of the run and {} in the last (secular drift); RK4's phase error: \
             {} rad at the middle, {} at the end; beyond the claim, False Euler (symplectic, not the \
             \"high quality integration\" meant) keeps |r − 1| {} (no drift) while its phase drifts ({} rad \
             at the end)",
            sig(rk.radius_early),
            sig(rk.radius_late),
            sig(rk.phase_middle),
            sig(rk.phase_end),
            if sig(fe.radius_late) == sig(fe.radius_early) {
                format!("at most {} early and late", sig(fe.radius_late))
            } else {
                format!("at most {} early and {} late", sig(fe.radius_early), sig(fe.radius_late))
            },
            sig(fe.phase_end),
        ),
        Finding::scoped([
            ("high-order fixed step (RK4): the radius drifts".to_owned(), secular(&rk), Scope::Stated),
            ("high-order fixed step (RK4): the phase drifts".to_owned(), phase_grows(&rk), Scope::Stated),
        ]),
        "fixed-step runs in f64 (scene::reference::rk4_step and a False Euler loop); secular = the late \
         deviation more than 5 times the early one; a drifting phase = its error at the end more than 1.5 times \
         that at the middle. The paper asserts the drift of \"straightforward high quality integration\" \
         only, so False Euler's bounded radius is reported, not judged",
    );
}

/// RK-Merson (Merson 1957) exactly: stages c = (0, 1/3, 1/3, 1/2, 1) and the
/// fourth-order weights b. Its third-order solution is the fifth stage's
/// argument (A's last row), and Merson's error estimate is a fifth of the
/// difference between the two.
const MERSON_A: [[&str; 5]; 5] = [
    ["0", "0", "0", "0", "0"],
    ["1/3", "0", "0", "0", "0"],
    ["1/6", "1/6", "0", "0", "0"],
    ["1/8", "0", "3/8", "0", "0"],
    ["1/2", "0", "-3/2", "2", "0"],
];
const MERSON_B: [&str; 5] = ["1/6", "0", "0", "2/3", "1/6"];

/// The Merson tableau, read exactly.
fn merson_exact() -> (Vec<Vec<poly::Q>>, Vec<poly::Q>) {
    let q = |e: &str| {
        poly::advanced::parse_number(e.trim_start_matches('-')).map(|x| {
            if e.starts_with('-') {
                -x
            } else {
                x
            }
        })
    };
    let a =
        MERSON_A.iter().map(|r| r.iter().map(|e| q(e).expect("a rational")).collect()).collect();
    let b = MERSON_B.iter().map(|e| q(e).expect("a rational")).collect();
    (a, b)
}

/// Whether the Merson tableau run here is the `merson` built-in: its
/// program on the oscillator (`poly::advanced::tableau`) has the built-in's
/// transition matrix exactly, up to the order of the state.
fn merson_is_the_builtin() -> bool {
    use poly::advanced::tableau::{Exact, Tableau};
    let exact = |e: &str| Exact::parse(e).expect("a rational entry");
    let a = MERSON_A.iter().map(|r| r.iter().map(|e| exact(e)).collect()).collect();
    let b = MERSON_B.iter().map(|e| exact(e)).collect();
    let Ok(method) = Tableau::new("merson_tableau", a, b, None).and_then(|t| t.method(false))
    else {
        return false;
    };
    // The tableau's program holds (v, y), the built-in (y, v).
    poly::derive(&method).is_ok_and(|d| {
        matches!(
            poly::advanced::equiv::relate(&d, &builtin_derivation("merson")),
            poly::Relation::Equal | poly::Relation::Permutation { .. }
        )
    })
}

/// The Merson pair in f64, from the exact tableau: the error weights are
/// (b − b̂)/5 with b̂ = A's last row.
fn merson_pair() -> EmbeddedPair {
    let (a, b) = merson_exact();
    let f = |q: &poly::Q| num_traits::ToPrimitive::to_f64(q).expect("a small rational");
    let b_hat = a[4].clone();
    let fifth = poly::q(1, 5);
    EmbeddedPair {
        a: a.iter().map(|r| r.iter().map(f).collect()).collect(),
        b: b.iter().map(f).collect(),
        e: b.iter().zip(&b_hat).map(|(x, y)| f(&((x - y) * &fifth))).collect(),
        order: 4,
    }
}

/// "All other systems should be integrated by professional methods like
/// higher order Runge-Kutta with stepsize control (RK-Merson, RK-Fehlberg)",
/// tried on the three-body scenes: RK-Merson with step control (its tableau
/// checked to be the `merson` built-in) and Dormand-Prince 5(4) (the
/// successor of Fehlberg's pair) against the paper's fixed-step method over
/// the same span, by force evaluations and the conserved energy.
fn professional_methods(s: &mut Section) {
    let mut cases = vec![(
        "the RK-Merson tableau run here is the merson built-in (the same transition matrix, state in \
         another order)"
            .to_owned(),
        merson_is_the_builtin(),
    )];
    let mut rows = Vec::new();
    let merson = merson_pair();
    // Appendix C is a "celestial motion with low accuracy", which the paper
    // gives to False Euler; Appendix D wants the energy kept, the paper's
    // case for something better than a plain fixed step.
    for (name, config, steps, in_scope) in [
        ("Appendix C (False Euler, dT = 0.3)", ThreeBodyConfig::appendix_c(), 1000u64, false),
        (
            "Appendix D (Standard Euler with energy control, dT = 0.01)",
            ThreeBodyConfig::appendix_d_energy(),
            100_000,
            true,
        ),
    ] {
        let run = three_body::simulate(&config, steps, &mut |_| {});
        let e = run.energy_consistent;
        let paper_drift = e.max_abs_drift / e.initial.abs().max(1.0);
        let span = steps as f64 * config.dt;
        let mut found = Vec::new();
        for (method, integrator) in [
            ("RK-Merson 4(3)", Integrator::Pair(&merson)),
            ("Dormand-Prince 5(4)", Integrator::DormandPrince),
        ] {
            // Tolerances 1e-2, 1e-3, ...: the most accurate run within the
            // paper's budget of force evaluations (one per fixed step). A
            // loose tolerance may fail or overspend at a close encounter; a
            // tighter one is tried all the same until one has finished
            // within the budget, after which tighter ones only cost more.
            let mut best: Option<(f64, u64, f64)> = None;
            for exponent in 2..=12 {
                let tolerance = 10f64.powi(-exponent);
                match adaptive(&config, span, tolerance, &integrator, steps) {
                    Run::Done(evals, drift) => best = Some((tolerance, evals, drift)),
                    Run::OverBudget if best.is_some() => break,
                    Run::OverBudget | Run::Failed => {}
                }
            }
            if in_scope {
                cases.push((
                    format!(
                        "{name}: {method} with step control keeps the energy closer for the same number \
                         of force evaluations"
                    ),
                    best.is_some_and(|(_, _, drift)| drift < paper_drift),
                ));
            }
            found.push(match best {
                Some((tolerance, evals, drift)) => format!(
                    "{method} at tolerance {tolerance:.0e}: {evals} evaluations, {drift:.1e}"
                ),
                None => format!("{method}: no tolerance within that budget"),
            });
        }
        rows.push(format!(
            "{name}{}: the paper's method, {steps} force evaluations, energy off by up to {paper_drift:.1e} \
             (relative); {}",
            if in_scope {
                ""
            } else {
                ", a low-accuracy celestial motion, which the paper gives to False Euler, not one of the \
                 \"other systems\""
            },
            found.join("; "),
        ));
    }
    s.push(
        "professional_methods",
        "All other systems should be integrated by professional methods like higher order Runge-Kutta with \
         stepsize control (RK-Merson, RK-Fehlberg).",
        rows.join("; "),
        Finding::all(cases),
        "scene::three_body::simulate for the paper's runs; RK-Merson from the exact tableau (the merson \
         built-in's P up to the state order, by Derivation::relate) with Merson's error estimate, by \
         scene::reference::embedded; Dormand-Prince by scene::reference::dopri5; both with step \
         control, on the uncontrolled equations over the same span, at the tightest tolerance 10^-k \
         whose force evaluations stay within the paper's; energy sum(v²/2) + sum(ln r) sampled 100 \
         times",
    );
}

/// An integrator with step control.
enum Integrator<'a> {
    Pair(&'a EmbeddedPair),
    DormandPrince,
}

/// How a run with step control ended.
enum Run {
    /// Force evaluations and the largest relative drift of the conserved
    /// energy over 100 samples.
    Done(u64, f64),
    /// More force evaluations than the budget: stopped there.
    OverBudget,
    /// The integrator gave up (a close encounter at a loose tolerance).
    Failed,
}

/// An integrator with step control on the scene's uncontrolled equations
/// over `span`, stopped once it spends more than `budget` force
/// evaluations (the force turns non-finite, which ends the run at once).
fn adaptive(
    config: &ThreeBodyConfig,
    span: f64,
    tolerance: f64,
    integrator: &Integrator,
    budget: u64,
) -> Run {
    let law = config.force_law;
    let evaluations = Cell::new(0u64);
    let f = |y: &[f64; 12]| {
        evaluations.set(evaluations.get() + 1);
        if evaluations.get() > budget {
            return [f64::NAN; 12];
        }
        three_body::derivative(y, law)
    };
    let start = config.initial_state();
    let e0 = start.energy_consistent(law);
    let mut y = state_array(&start);
    let mut h = 1e-3;
    let mut drift = 0.0f64;
    let tolerance = Tolerance { relative: tolerance, absolute: tolerance };
    for _ in 0..100 {
        let next = match integrator {
            Integrator::Pair(pair) => embedded(&f, &y, span / 100.0, tolerance, &mut h, pair),
            Integrator::DormandPrince => dopri5(&f, &y, span / 100.0, tolerance, &mut h),
        };
        match next {
            Ok(x) => y = x,
            Err(_) if evaluations.get() > budget => return Run::OverBudget,
            Err(_) => return Run::Failed,
        }
        drift = drift.max((energy_of(&y, law) - e0).abs() / e0.abs().max(1.0));
    }
    Run::Done(evaluations.get(), drift)
}

fn state_array(s: &three_body::State) -> [f64; 12] {
    let mut y = [0.0; 12];
    for b in 0..3 {
        y[2 * b..2 * b + 2].copy_from_slice(&s.position[b]);
        y[6 + 2 * b..6 + 2 * b + 2].copy_from_slice(&s.velocity[b]);
    }
    y
}

fn energy_of(y: &[f64; 12], law: three_body::ForceLaw) -> f64 {
    let mut s = three_body::State { position: [[0.0; 2]; 3], velocity: [[0.0; 2]; 3] };
    for b in 0..3 {
        s.position[b] = [y[2 * b], y[2 * b + 1]];
        s.velocity[b] = [y[6 + 2 * b], y[6 + 2 * b + 1]];
    }
    s.energy_consistent(law)
}
