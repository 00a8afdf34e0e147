//! Section Appendix C (3 bodies, False Euler): three unit masses on the unit
//! circle, the paper's force (x2-x1)/r12 with r12 the squared distance,
//! False Euler at dT = 0.3. "The true trajectory is the averaged clover
//! leaf. [...] The solution is not accurate but stable ad infinitum."

use std::sync::OnceLock;

use zcheck::paper::Claim;
use zcheck::paper::Verdict::{self, *};
use zcheck::scene::three_body::{self, Bodies, FirstStep, ForceLaw, ThreeBodyConfig};

/// The appendix claims, computed once for all appendix test modules.
pub fn appendix_claims() -> &'static [Claim] {
    static CLAIMS: OnceLock<Vec<Claim>> = OnceLock::new();
    CLAIMS.get_or_init(zcheck::paper::appendix::claims)
}

#[track_caller]
pub fn check_verdicts(expected: &[(&str, Verdict)], section: &str) {
    let claims = appendix_claims();
    for (id, verdict) in expected {
        let c = claims.iter().find(|c| c.id == *id).unwrap_or_else(|| panic!("no claim {id}"));
        assert_eq!(c.verdict(), *verdict, "{id}: {}", c.derived);
        assert_eq!(c.section, section, "{id}");
        assert!(!c.statement.is_empty() && !c.derived.is_empty() && !c.evidence.is_empty(), "{id}");
    }
    let listed = claims.iter().filter(|c| c.section == section).count();
    assert_eq!(listed, expected.len(), "every claim of section {section} has a test");
}

pub const COVERED: &[(&str, Verdict)] = &[
    ("appC.stable_ad_infinitum", Confirmed),
    ("appC.averaged_clover_leaf", Refined),
    ("appC.velocity_reads_new_positions", Errata),
    ("appC.force_law", Refined),
    ("appC.update_order", Confirmed),
];

/// The update order read from the listing itself: velocities first from the
/// old positions, positions from the new velocities (False Euler); the same
/// reader on Appendix D's listing finds the old velocities (Standard Euler),
/// so the claim tells the two apart.
#[test]
fn update_order_is_read_from_the_listing() {
    let claims = appendix_claims();
    let derived = |id: &str| claims.iter().find(|c| c.id == id).expect("claim").derived.clone();
    let (c, d) = (derived("appC.update_order"), derived("appD.update_order"));
    assert!(c.contains("each position the new velocity") && c.contains("false_euler"), "{c}");
    assert!(d.contains("each position the old velocity") && d.contains("standard_euler"), "{d}");
    assert!(!c.contains("standard_euler") && !d.contains("false_euler"), "{c} | {d}");
}

#[test]
fn verdicts() {
    check_verdicts(COVERED, "C");
}

/// The Pascal loop of Appendix C transcribed statement by statement, with
/// `x1 .. y3` either zeroed (the printed code on fresh memory) or set to the
/// start positions (what the code means). Returns the positions after each
/// step.
fn pascal_appendix_c(n: usize, new_positions_zeroed: bool) -> Vec<Bodies> {
    let (si, co) = (0.5, 3f64.sqrt() / 2.0);
    let dt = 0.3;
    let (mut x1o, mut y1o, mut v1o, mut w1o) = (-co, -si, -si, co);
    let (mut x2o, mut y2o, mut v2o, mut w2o) = (co, -si, -si, -co);
    let (mut x3o, mut y3o, mut v3o, mut w3o) = (0.0, 1.0, 1.0, 0.0);
    let (mut x1, mut y1, mut x2, mut y2, mut x3, mut y3) = if new_positions_zeroed {
        (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    } else {
        (x1o, y1o, x2o, y2o, x3o, y3o)
    };
    let mut out = Vec::new();
    for _ in 0..n {
        let r12 = (x2o - x1o) * (x2o - x1o) + (y2o - y1o) * (y2o - y1o);
        let r13 = (x3o - x1o) * (x3o - x1o) + (y3o - y1o) * (y3o - y1o);
        let r23 = (x3o - x2o) * (x3o - x2o) + (y3o - y2o) * (y3o - y2o);
        let v1 = v1o + dt * ((x2 - x1) / r12 + (x3 - x1) / r13);
        let v2 = v2o + dt * ((x3 - x2) / r23 + (x1 - x2) / r12);
        let v3 = v3o + dt * ((x1 - x3) / r13 + (x2 - x3) / r23);
        let w1 = w1o + dt * ((y2 - y1) / r12 + (y3 - y1) / r13);
        let w2 = w2o + dt * ((y1 - y2) / r12 + (y3 - y2) / r23);
        let w3 = w3o + dt * ((y1 - y3) / r13 + (y2 - y3) / r23);
        x1 = x1o + dt * v1;
        y1 = y1o + dt * w1;
        x2 = x2o + dt * v2;
        y2 = y2o + dt * w2;
        x3 = x3o + dt * v3;
        y3 = y3o + dt * w3;
        (x1o, y1o, x2o, y2o, x3o, y3o) = (x1, y1, x2, y2, x3, y3);
        (v1o, w1o, v2o, w2o, v3o, w3o) = (v1, w1, v2, w2, v3, w3);
        out.push([[x1, y1], [x2, y2], [x3, y3]]);
    }
    out
}

fn scene_positions(config: &ThreeBodyConfig, n: usize) -> Vec<Bodies> {
    let mut state = config.initial_state();
    (1..=n)
        .map(|k| {
            three_body::step(config, &mut state, 0.0, k == 1);
            state.position
        })
        .collect()
}

/// The scene is the Pascal code bit for bit: with the printed first step
/// (zeroed x1..y3) as `FirstStep::ZeroedNewPositions`, and with x1..y3
/// holding the start positions as the intended `FirstStep::OldPositions`.
/// That the two variants differ only through step 1 is the misprint's
/// whole effect: `x1o:=x1` makes the new positions the old ones from step 2.
#[test]
fn scene_repeats_the_pascal_loop() {
    let c = ThreeBodyConfig::appendix_c();
    for (zeroed, first_step) in
        [(true, FirstStep::ZeroedNewPositions), (false, FirstStep::OldPositions)]
    {
        let scene = scene_positions(&ThreeBodyConfig { first_step, ..c }, 1000);
        assert_eq!(scene, pascal_appendix_c(1000, zeroed), "{first_step:?}");
    }
    // Step 1 without force moves each body by dT^2 * |a| = 0.09 (|a| = 1).
    let literal =
        scene_positions(&ThreeBodyConfig { first_step: FirstStep::ZeroedNewPositions, ..c }, 1);
    let intended = scene_positions(&c, 1);
    for b in 0..3 {
        let gap =
            (literal[0][b][0] - intended[0][b][0]).hypot(literal[0][b][1] - intended[0][b][1]);
        assert!((gap - 0.09).abs() <= 16.0 * f64::EPSILON, "body {b}: {gap}");
    }
}

/// The coded force has magnitude 1/r: on the start triangle (side sqrt 3)
/// each body is pulled to the centre with 2 (1/sqrt 3) cos 30° = 1, the
/// centripetal acceleration of unit speed on the unit circle. Newton's law
/// would give 1/sqrt 3.
#[test]
fn force_law_is_inverse_distance() {
    let state = ThreeBodyConfig::appendix_c().initial_state();
    for (law, expected) in
        [(ForceLaw::InverseDistance, 1.0), (ForceLaw::InverseSquare, 1.0 / 3f64.sqrt())]
    {
        let a = state.acceleration(law);
        for (b, (ab, pb)) in a.iter().zip(&state.position).enumerate() {
            let inward = -(ab[0] * pb[0] + ab[1] * pb[1]);
            assert!((inward - expected).abs() <= 8.0 * f64::EPSILON, "{law:?} body {b}: {inward}");
        }
    }
    // Under 1/r^2 the same start is no circle: the reference leaves r = 1 far behind.
    let newton =
        ThreeBodyConfig { force_law: ForceLaw::InverseSquare, ..ThreeBodyConfig::appendix_c() };
    let reference = three_body::reference(&newton, 100).expect("reference");
    let r_max = reference.iter().flat_map(|s| s.radii()).fold(0.0, f64::max);
    assert!(r_max > 2.0, "{r_max}");
}

/// The true trajectory (Dormand–Prince) is the circle r = 1 travelled at unit
/// angular speed: after 1000 steps (t = 300) every body is on the circle to
/// 1e-9 and at the angle -t.
#[test]
fn true_trajectory_is_the_circle() {
    let c = ThreeBodyConfig::appendix_c();
    let reference = three_body::reference(&c, 1000).expect("reference");
    for (k, s) in reference.iter().enumerate() {
        for r in s.radii() {
            assert!((r - 1.0).abs() <= 1e-9, "step {k}: r = {r}");
        }
    }
    let t = 1000.0 * c.dt;
    let p = reference[1000].position[2];
    // Body 3 starts at angle 90° and moves clockwise.
    let expected =
        [(std::f64::consts::FRAC_PI_2 - t).cos(), (std::f64::consts::FRAC_PI_2 - t).sin()];
    assert!((p[0] - expected[0]).hypot(p[1] - expected[1]) <= 1e-8, "{p:?} vs {expected:?}");
}

/// "Stable ad infinitum": over 10^6 steps (t = 300,000) the radii stay within
/// dT/2 of the circle, the second half of the run reaches no farther than the
/// first (no secular growth), the energy error stays bounded, and angular and
/// linear momentum are kept to rounding (symplectic Euler conserves them).
/// "Not accurate": after 100 steps the bodies are more than 0.1 off the
/// reference (a phase error).
#[test]
fn stable_ad_infinitum_but_not_accurate() {
    let c = ThreeBodyConfig::appendix_c();
    let half = three_body::simulate(&c, 500_000, &mut |_| {});
    let full = three_body::simulate(&c, 1_000_000, &mut |_| {});
    assert!(full.bounded());
    assert!(
        full.radius_min >= 1.0 - c.dt / 2.0 && full.radius_max <= 1.0 + c.dt / 2.0,
        "{} {}",
        full.radius_min,
        full.radius_max
    );
    assert!(
        full.radius_max <= half.radius_max * (1.0 + 1e-3)
            && full.radius_min >= half.radius_min * (1.0 - 1e-3)
    );
    let e = &full.energy_consistent;
    assert!(e.max_abs_drift <= half.energy_consistent.max_abs_drift * (1.0 + 1e-3));
    assert!(e.max_abs_drift / e.initial.abs() <= c.dt / 2.0, "{}", e.max_abs_drift);
    let rounding = 1e6 * 64.0 * f64::EPSILON;
    assert!(
        full.angular_momentum.max_abs_drift <= rounding,
        "{}",
        full.angular_momentum.max_abs_drift
    );
    assert!(full.momentum_x.max_abs_drift <= rounding && full.momentum_y.max_abs_drift <= rounding);
    let accuracy = three_body::accuracy(&c, 100).expect("reference");
    assert!(accuracy.max_position_error > 0.1, "{accuracy:?}");
}

/// "The true trajectory is the averaged clover leaf": the rosette's mean
/// radius is within dT/10 of the circle's, but not equal to it (it is a first
/// order effect), over 10^6 steps.
#[test]
fn circle_is_the_averaged_clover_leaf() {
    let c = ThreeBodyConfig::appendix_c();
    let run = three_body::simulate(&c, 1_000_000, &mut |_| {});
    let offset = run.radius_mean - 1.0;
    assert!(offset.abs() <= c.dt / 10.0 && offset.abs() >= 1e-3, "{offset}");
    // The literal first step draws the same annulus to 1e-3.
    let literal = three_body::simulate(
        &ThreeBodyConfig { first_step: FirstStep::ZeroedNewPositions, ..c },
        1_000_000,
        &mut |_| {},
    );
    assert!(
        (literal.radius_max - run.radius_max).abs() <= 1e-3
            && (literal.radius_min - run.radius_min).abs() <= 1e-3
    );
}

/// Under Newton's 1/r^2 the same False Euler run is not bounded.
#[test]
fn inverse_square_is_not_stable_at_this_step() {
    let newton =
        ThreeBodyConfig { force_law: ForceLaw::InverseSquare, ..ThreeBodyConfig::appendix_c() };
    let run = three_body::simulate(&newton, 100_000, &mut |_| {});
    assert!(!run.bounded(), "{}", run.radius_max);
}
