//! Claims of Appendices C–E, the scenes: three bodies by False Euler (C), by
//! Standard Euler with and without energy control (D), and the aircraft (E),
//! with the statements of section 12 that rest on Appendix D.
//!
//! Every number here is computed when the claims are built, from the scenes
//! in `crate::scene`, so it must stay cheap (`zcheck paper` runs it): C runs
//! its 10^6 False Euler steps (a few ms in release), D its 100,000 steps, the
//! references only short windows. The longer checks live in the proof tests.

use super::{Claim, Verdict};
use crate::scene::aircraft::{self, AircraftConfig};
use crate::scene::three_body::{
    self, EnergyControl, EnergyDefinition, FirstStep, ForceLaw, InitialVelocities, ThreeBodyConfig,
};

/// Steps of Appendix C's "ad infinitum" check in the report (the proof test
/// runs 10^6; a step costs ~0.2 µs with every invariant followed).
pub const C_STEPS: u64 = 100_000;
/// Steps of Appendix D, as printed.
pub const D_STEPS: u64 = 100_000;
/// Steps of the chaos check (two controlled runs 1e-9 apart).
pub const CHAOS_STEPS: u64 = 30_000;
/// Steps of the aircraft runs (30 s at dT = 0.1).
pub const E_STEPS: u64 = 300;

/// Four significant digits, in plain or scientific notation.
fn sig(x: f64) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    if a != 0.0 && !(1e-3..1e5).contains(&a) {
        format!("{x:.3e}")
    } else {
        let digits = if a == 0.0 { 0 } else { (3 - a.log10().floor() as i32).max(0) as usize };
        format!("{x:.digits$}")
    }
}

/// Relative change from the first to the last value.
fn end_drift(t: &crate::scene::Track) -> f64 {
    (t.last - t.initial) / t.initial.abs()
}

fn percent(x: f64) -> String {
    format!("{}%", sig(100.0 * x))
}

struct Claims(Vec<Claim>);

impl Claims {
    fn push(
        &mut self,
        section: &str,
        key: &str,
        statement: &str,
        derived: String,
        verdict: Verdict,
        evidence: String,
    ) {
        let prefix = format!("app{section}");
        self.0.push(Claim {
            id: format!("{prefix}.{key}"),
            section: section.to_owned(),
            statement: statement.to_owned(),
            derived,
            verdict,
            evidence,
        });
    }
}

/// The claims of Appendices C, D and E.
pub fn claims() -> Vec<Claim> {
    // The three appendices are independent: run them side by side, D (the
    // longest) alone, to keep `zcheck paper` fast.
    let section = |f: fn(&mut Claims)| {
        let mut claims = Claims(Vec::new());
        f(&mut claims);
        claims.0
    };
    std::thread::scope(|scope| {
        let d = scope.spawn(|| section(appendix_d));
        let mut all = section(appendix_c);
        let d = d.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic));
        all.extend(d);
        all.extend(section(appendix_e));
        all
    })
}

fn run(config: &ThreeBodyConfig, n: u64) -> three_body::ThreeBodyRun {
    three_body::simulate(config, n, &mut |_| {})
}

fn appendix_c(claims: &mut Claims) {
    let c = ThreeBodyConfig::appendix_c();
    let r = run(&c, C_STEPS);
    let e = r.energy_consistent.summary();
    let accuracy = three_body::accuracy(&c, 100).ok();
    let stable = r.bounded() && r.radius_min > 0.5 && r.radius_max < 2.0;
    claims.push(
        "C",
        "stable_ad_infinitum",
        "The solution is not accurate but stable ad infinitum.",
        format!(
            "stable: over {} steps (t = {}) every body stays between r = {} and {} from the centre; \
             not accurate: after 100 steps the bodies are up to {} away from the exact circle",
            C_STEPS,
            sig(C_STEPS as f64 * c.dt),
            sig(r.radius_min),
            sig(r.radius_max),
            accuracy.map_or("?".into(), |a| sig(a.max_position_error)),
        ),
        if stable { Verdict::Confirmed } else { Verdict::Errata },
        format!(
            "False Euler, dT = 0.3, 1/r force; energy sum(v^2/2) + sum(ln r) drifts at most {} (bounded, \
             it oscillates: symplectic Euler); angular momentum kept to {}; reference Dormand-Prince at \
             tolerance 1e-12",
            percent(e.max_rel_drift.unwrap_or(f64::NAN)),
            sig(r.angular_momentum.max_abs_drift),
        ),
    );
    let reference_radius = three_body::reference(&c, 100).ok().map(|states| {
        states
            .iter()
            .flat_map(|s| s.radii())
            .fold([f64::INFINITY, 0.0f64], |m, x| [m[0].min(x), m[1].max(x)])
    });
    claims.push(
        "C",
        "averaged_clover_leaf",
        "The initial conditions are symmetric. The true trajectory is the averaged clover leaf.",
        format!(
            "the true trajectory is Lagrange's equilateral circle r = 1 (unit speed balances the 1/r \
             force: v^2/r = 1); False Euler draws a rosette (the clover leaf) in r = [{}, {}] whose \
             mean radius is {}: the circle is the clover leaf averaged to {} (first order in dT)",
            sig(r.radius_min),
            sig(r.radius_max),
            sig(r.radius_mean),
            percent(r.radius_mean - 1.0),
        ),
        Verdict::Refined,
        format!(
            "reference over 100 steps: r in [{}, {}]; False Euler over {} steps",
            reference_radius.map_or("?".into(), |m| sig(m[0])),
            reference_radius.map_or("?".into(), |m| sig(m[1])),
            C_STEPS
        ),
    );
    let literal = ThreeBodyConfig { first_step: FirstStep::ZeroedNewPositions, ..c };
    let rl = run(&literal, 10_000);
    let first_gap = {
        let a = run(&c, 1).final_state;
        let b = run(&literal, 1).final_state;
        (0..3)
            .map(|i| {
                (a.position[i][0] - b.position[i][0]).hypot(a.position[i][1] - b.position[i][1])
            })
            .fold(0.0, f64::max)
    };
    claims.push(
        "C",
        "velocity_reads_new_positions",
        "v1:=v1o+dT*((x2-x1)/r12+(x3-x1)/r13);",
        format!(
            "misprint: the force reads the NEW positions x1..y3 (the loop's output) instead of x1o..y3o; \
             since x1o:=x1 closes the loop they agree from step 2 on, but step 1 reads uninitialised \
             variables (zeroed memory: no force on step 1). We use the old positions; the literal \
             first step moves the bodies {} off and leaves r in [{}, {}] over {} steps",
            sig(first_gap),
            sig(rl.radius_min),
            sig(rl.radius_max),
            10_000
        ),
        Verdict::Errata,
        "FirstStep::ZeroedNewPositions against FirstStep::OldPositions".into(),
    );
    let newton = ThreeBodyConfig { force_law: ForceLaw::InverseSquare, ..c };
    let rn = run(&newton, 10_000);
    let rn_ref = three_body::reference(&newton, 100)
        .ok()
        .map(|states| states.iter().flat_map(|s| s.radii()).fold(0.0f64, f64::max));
    claims.push(
        "C",
        "force_law",
        "Three 'celestial' bodies under the influence of gravitational forces in the xy plane.",
        format!(
            "the code's force (x2-x1)/r12 with r12 the squared distance has magnitude 1/r: gravity in \
             two dimensions (potential ln r), not Newton's 1/r^2. The clover leaf needs it: under 1/r^2 \
             the same start is an eccentric orbit (reference reaches r = {} within 100 steps) and False \
             Euler at dT = 0.3 reaches r = {} within 10,000 steps",
            rn_ref.map_or("?".into(), sig),
            sig(rn.radius_max)
        ),
        Verdict::Refined,
        "ForceLaw::InverseDistance (the code) against ForceLaw::InverseSquare".into(),
    );
}

fn appendix_d(claims: &mut Claims) {
    let plain = ThreeBodyConfig::appendix_d();
    let controlled = ThreeBodyConfig::appendix_d_energy();
    let as_printed = ThreeBodyConfig {
        control: Some(EnergyControl { factor: 0.3, energy: EnergyDefinition::Paper }),
        ..plain
    };
    // Seven long runs: half of them on a second thread.
    let nudged_config = ThreeBodyConfig { eps: controlled.eps + 1e-9, ..controlled };
    let tangential =
        ThreeBodyConfig { eps: 0.0, velocities: InitialVelocities::Tangential, ..controlled };
    let ((rp, rc, ra, controlled_short), (rn, symmetric_printed, circle, nudged)) =
        std::thread::scope(|scope| {
            let first = scope.spawn(|| {
                (
                    run(&plain, D_STEPS),
                    run(&controlled, D_STEPS),
                    run(&as_printed, D_STEPS),
                    run(&controlled, CHAOS_STEPS),
                )
            });
            let second = (
                run(&ThreeBodyConfig { force_law: ForceLaw::InverseSquare, ..as_printed }, D_STEPS),
                run(&ThreeBodyConfig { eps: 0.0, ..as_printed }, D_STEPS),
                run(&tangential, D_STEPS),
                run(&nudged_config, CHAOS_STEPS),
            );
            (first.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic)), second)
        });
    let growth = rp.energy_consistent.summary();
    claims.push(
        "D",
        "standard_euler_unstable",
        "Upper image: Standard Euler, unstable.",
        format!(
            "over 100,000 steps of dT = 0.01 the conserved energy grows from {} to {} and the bodies \
             drift out to r = {} (start r = 1)",
            sig(growth.initial),
            sig(growth.r#final),
            sig(rp.radius_max)
        ),
        if rp.energy_consistent.last > rp.energy_consistent.initial + 1.0 && !rp.bounded() {
            Verdict::Confirmed
        } else {
            Verdict::Errata
        },
        "energy sum(v^2/2) + sum(ln r), the one the coded 1/r force conserves".into(),
    );
    claims.push(
        "D",
        "energy_control_stable",
        "Lower image: Standard Euler with energy control, stable.",
        format!(
            "stable (bounded) over 100,000 steps for the coded 1/r force: r <= {} with the printed energy, \
             r <= {} with the consistent one (conserved energy off by {} at the end, {} at its peak, a close \
             encounter); but with Newton's 1/r^2 force, \
             to which the printed energy belongs, the same control {}",
            sig(ra.radius_max),
            sig(rc.radius_max),
            percent(end_drift(&rc.energy_consistent)),
            percent(rc.energy_consistent.summary().max_rel_drift.unwrap_or(f64::NAN)),
            match rn.first_nonfinite_step {
                Some(k) => format!("blows up (non-finite) at step {k}"),
                None => format!("reaches r = {}", sig(rn.radius_max)),
            }
        ),
        if ra.bounded() && rc.bounded() { Verdict::Refined } else { Verdict::Errata },
        "Cf = 0.3, eps = 0.01, the printed radial initial velocities".into(),
    );
    // The same first-step slip as Appendix C: the force reads x1..y3 before
    // the loop has set them.
    let literal = ThreeBodyConfig { first_step: FirstStep::ZeroedNewPositions, ..controlled };
    let first_gap = {
        let a = run(&controlled, 1).final_state;
        let b = run(&literal, 1).final_state;
        (0..3)
            .map(|i| {
                (a.velocity[i][0] - b.velocity[i][0]).hypot(a.velocity[i][1] - b.velocity[i][1])
            })
            .fold(0.0, f64::max)
    };
    claims.push(
        "D",
        "velocity_reads_new_positions",
        "v1:=v1o+dT*( (x2-x1)/r12+(x3-x1)/r13 - Cf*dEn*v1o );",
        format!(
            "misprint, as in Appendix C: the force reads the new positions x1..y3, unset on step 1 \
             (zeroed memory: no gravity on the first step); from step 2 on x1o:=x1 makes them equal to the \
             old ones. The first step's velocities then differ from the intended ones by up to {}; zcheck's scenes use \
             the old positions, and the literal version is FirstStep::ZeroedNewPositions",
            sig(first_gap)
        ),
        if first_gap > 0.0 { Verdict::Errata } else { Verdict::Confirmed },
        "one step of FirstStep::ZeroedNewPositions against FirstStep::OldPositions, dT = 0.01".into(),
    );
    let horizon = 2000;
    let acc = three_body::accuracy(&plain, horizon).ok();
    claims.push(
        "D",
        "energy_not_invariant",
        "Eno:=(sqr(v1o)+...)/2-Sqrt(1/r12)-Sqrt(1/r23)-Sqrt(1/r13);",
        format!(
            "not an invariant of the paper's own equations: along the reference solution of the coded \
             1/r force this \"total energy\" ranges over [{}, {}] in the first {} steps (it starts at {}), \
             while sum(v^2/2) + sum(ln r) stays within {}. The control therefore holds a quantity the \
             physics does not conserve",
            acc.map_or("?".into(), |a| sig(a.reference_energy_paper_range[0])),
            acc.map_or("?".into(), |a| sig(a.reference_energy_paper_range[1])),
            horizon,
            sig(rp.energy_paper.initial),
            acc.map_or("?".into(), |a| sig(a.reference_energy_drift)),
        ),
        Verdict::Errata,
        "Dormand-Prince at tolerance 1e-12 from Appendix D's initial state".into(),
    );
    claims.push(
        "D",
        "symmetric_circle",
        "For symmetric initial conditions we get a circle.",
        format!(
            "not with the printed initial velocities: v1o:=-co; w1o:=-si at (-co,-si) is RADIAL, so with \
             eps = 0 the angular momentum is {} and the bodies move on rays into a triple collision \
             ({}). With Appendix C's tangential velocities (the likely intent) and eps = 0 the controlled \
             run is a circle: r in [{}, {}] over 100,000 steps",
            sig(symmetric_printed.angular_momentum.initial),
            match symmetric_printed.first_nonfinite_step {
                Some(k) => format!("non-finite at step {k}"),
                None => format!("closest approach {}", sig(symmetric_printed.distance_min)),
            },
            sig(circle.radius_min),
            sig(circle.radius_max),
        ),
        Verdict::Errata,
        "InitialVelocities::Radial (printed) against InitialVelocities::Tangential".into(),
    );
    claims.push(
        "D",
        "control_by_partial_derivatives",
        "{ Control by partial derivatives dE/dv1 etc. }",
        "the term -Cf*dEn*v1o is -Cf*dEn*dE/dv1 (dE/dv1 = v1): a gradient (Baumgarte) control of the \
         energy integral; in continuous time d(dEn)/dt = -2*Cf*Ekin*dEn, so the energy error decays \
         while kinetic energy is positive"
            .into(),
        Verdict::Confirmed,
        format!(
            "with control the conserved energy ends {} off its start after 100,000 steps (the control \
             pulls it back after each close encounter), without it {}",
            percent(end_drift(&rc.energy_consistent)),
            percent(end_drift(&rp.energy_consistent)),
        ),
    );
    let separation = (0..3)
        .map(|i| {
            let (a, b) = (controlled_short.final_state.position[i], nudged.final_state.position[i]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        })
        .fold(0.0, f64::max);
    claims.push(
        "D",
        "sec12_chaotic_but_bounded",
        "The author had simulated three-body systems with chaotic but bounded solutions, introducing the \
         constant total energy, Appendix D.",
        format!(
            "chaotic: changing eps by 1e-9 moves the bodies {} apart after {} steps; bounded: r <= {}. \
             Boundedness is a gift of the 1/r force (its ln r potential confines every orbit of the exact \
             equations); angular momentum, another integral, is not controlled and goes from {} to {}, and \
             the control term -Cf*dEn*v scales the total momentum too (x momentum {} -> {})",
            sig(separation),
            CHAOS_STEPS,
            sig(rc.radius_max),
            sig(rc.angular_momentum.initial),
            sig(rc.angular_momentum.last),
            sig(rc.momentum_x.initial),
            sig(rc.momentum_x.last),
        ),
        Verdict::Refined,
        "energy-controlled Standard Euler, Cf = 0.3, consistent energy".into(),
    );
}

fn appendix_e(claims: &mut Claims) {
    let config = AircraftConfig::default();
    let r = aircraft::simulate(&config, E_STEPS, &mut |_| {});
    let pitch_only = AircraftConfig { phi_command: 0.0, ..config };
    let rp = aircraft::simulate(&pitch_only, E_STEPS, &mut |_| {});
    let steady = r.steady_turn;
    claims.push(
        "E",
        "commanded_attitude",
        "Simplified roll angle and pitch angle controller. Yaw rate by sine of roll angle.",
        match steady {
            Some(s) => format!(
                "with Phic = 30°, Thec = 10° the aircraft does not reach its command: it settles (roll and \
                 pitch within 0.1° {}) into a steady turn at Phi = {}°, The = {}°, yawing {}°/s; the \
                 yaw torque -sin(Phi)cos(The) keeps body rates the proportional controllers must \
                 balance. Without a roll command (Phic = 0) it reaches Thec = 10° (The = {}°)",
                r.settling_time.map_or("never".into(), |t| format!("after {} s", sig(t))),
                sig(s.phi),
                sig(s.theta),
                sig(s.yaw_rate),
                sig(rp.final_state.angles[1]),
            ),
            None => "no steady turn found".into(),
        },
        Verdict::Refined,
        format!(
            "steady turn by Newton on the continuous equations; False Euler ends at Phi = {}°, The = {}°, \
             the RK4 reference at {}°, {}°",
            sig(r.final_state.angles[0]),
            sig(r.final_state.angles[1]),
            sig(r.reference_final_state.angles[0]),
            sig(r.reference_final_state.angles[1]),
        ),
    );
    claims.push(
        "E",
        "false_euler_rigid_body",
        "The example shows the simple application of False Euler for a rigid body rotation.",
        format!(
            "False Euler at dT = 0.1 is stable and follows the reference to {}° in roll and {}° in pitch \
             during the transient; its fixed point is the continuous steady turn exactly",
            sig(r.max_angle_error[0]),
            sig(r.max_angle_error[1]),
        ),
        Verdict::Confirmed,
        format!("RK4 with 20 substeps per dT as reference, {} steps", E_STEPS),
    );
    claims.push(
        "E",
        "rotation_matrix",
        "{ Rotation matrix } o11:=+cpsi*cthe; ...",
        format!(
            "orthonormal by construction ({} at most over the run) and consistent with the Euler-angle \
             kinematics: a matrix integrated directly, dO/dt = O[w]x, agrees to {}. The code builds it from \
             the sines taken before the angle update (one step late) and from the clamped cThe near \
             gimbal lock",
            sig(r.orthonormality.max),
            sig(r.kinematics_error),
        ),
        Verdict::Confirmed,
        "|O^T O - I| entrywise".into(),
    );
    let lock = AircraftConfig { phi_command: 10.0, theta_command: 90.0, ..config };
    let rl = aircraft::simulate(&lock, E_STEPS, &mut |_| {});
    claims.push(
        "E",
        "gimbal_lock_guard",
        "{ Trap gimbal lock singularity } If Abs(cThe)<eps Then ...",
        format!(
            "the guard traps the singularity as its comment says: no division by zero, every value stays \
             finite. Beyond the claim, Euler-angle control still fails there: with \
             Phic = 10°, Thec = 90° the aircraft spins about its x axis (wx = {} rad/s after {} s) with \
             Phi stuck at {}° (reference: {}°). Also, the angle wrap While Phi>180 never ends on an \
             infinite angle",
            sig(rl.final_state.rates[0]),
            sig(E_STEPS as f64 * lock.dt),
            sig(rl.final_state.angles[0]),
            sig(rl.reference_final_state.angles[0]),
        ),
        Verdict::Confirmed,
        "same run and reference as the other Appendix E claims".into(),
    );
}
