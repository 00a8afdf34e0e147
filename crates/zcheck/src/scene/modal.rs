//! Modal reduction of a mass–spring scene: M ÿ + C ẏ + K y = 0.
//!
//! The generalised eigenproblem K φ = ω² M φ is solved in its symmetric
//! form: with K̃ = M^{-1/2} K M^{-1/2} (M is diagonal), K̃ u = ω² u and
//! φ = M^{-1/2} u, by faer's self-adjoint eigendecomposition. Each mode
//! q̈ + 2ζω q̇ + ω² q = 0 is then the test equation of the (Φ, D) analysis
//! with Φ = ωT and D = ζ.
//!
//! That holds exactly when the damping is *proportional*: C̃ = M^{-1/2} C
//! M^{-1/2} is diagonal in the same basis, which for symmetric K̃ and C̃ is
//! the commutation K̃C̃ = C̃K̃ (Caughey and O'Kelly). Rayleigh damping
//! C = αM + βK is the common case, with ζ = α/(2ω) + βω/2. Otherwise the
//! damping is *non-proportional*: the modes still get ζ = uᵀC̃u/(2ω) as a
//! description, but the advisor decides stability on the assembled
//! full-step matrix instead (see `vector`).
//!
//! Modes with ω = 0 (a free body, or a chain not tied to the ground) move
//! rigidly: Φ = 0 for every step, so they limit nothing and are dropped
//! (counted in `Modal::rigid`).
//!
//! Particles (every mass with `pos`, 2 or 3 degrees of freedom each): a
//! spring between masses i and j is linearised about the rest positions
//! with no pre-tension, so only the stretch along the rest direction d (the
//! unit vector from i to j) stores energy, ½k(d·(u_j − u_i))²: its
//! stiffness block is k·d·dᵀ (and −k·d·dᵀ off the diagonal), a damper's
//! c·d·dᵀ. A spring to ground holds every axis, k·I. A fixed mass has no
//! degrees of freedom; a spring to it is a spring to a point, k·d·dᵀ on
//! the other end only. Motion across every spring through a mass (the
//! out-of-plane motion of a flat cloth, the sideways motion of a straight
//! rope) has no stiffness: a zero mode.

use faer::Side;
use nalgebra::DMatrix;
use num_complex::Complex64 as C64;

use super::file::{Body, Mass, SceneFile, Spring};
pub(crate) use super::sparse::{Assembly, Sparse};
use super::spectrum;
pub(crate) use super::spectrum::Certificate;
use crate::error::Error;

/// M, K and C of a scene.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct System {
    /// The masses (M is diagonal).
    pub mass: Vec<f64>,
    /// Stiffness.
    pub k: Sparse,
    /// Damping.
    pub c: Sparse,
}

impl System {
    /// Assembles M, K, C from scalar masses (one degree of freedom each)
    /// and the springs of a scene.
    #[cfg(test)]
    pub(crate) fn assemble(masses: &[f64], springs: &[super::file::Spring]) -> System {
        let masses: Vec<Mass> = masses
            .iter()
            .map(|&kg| Mass { name: String::new(), kg, pos: None, fixed: false })
            .collect();
        System::of_scene(&masses, springs, 1)
    }

    /// Assembles M, K, C of a scene with `dim` degrees of freedom per free
    /// mass (1: scalar; 2 or 3: every mass has `pos`), in mass order,
    /// fixed masses left out (see the module's note on particles).
    pub(crate) fn of_scene(masses: &[Mass], springs: &[Spring], dim: usize) -> System {
        let mut base = vec![None; masses.len()];
        let mut mass = Vec::new();
        for (i, m) in masses.iter().enumerate() {
            if !m.fixed {
                base[i] = Some(mass.len());
                mass.extend(std::iter::repeat_n(m.kg, dim));
            }
        }
        let n = mass.len();
        let (mut k, mut c) = (Assembly::new(n), Assembly::new(n));
        for s in springs {
            let block = link_block(masses, s, dim);
            let (a, b) = (base[s.a], s.b.and_then(|b| base[b]));
            k.add_block(a, b, dim, &block, s.stiffness);
            if s.damping > 0.0 {
                c.add_block(a, b, dim, &block, s.damping);
            }
        }
        System { mass, k: k.finish(), c: c.finish() }
    }

    /// Degrees of freedom.
    pub(crate) fn n(&self) -> usize {
        self.mass.len()
    }
}

/// A spring's `dim`×`dim` block (row-major): d·dᵀ with d the unit rest
/// direction between two masses with positions, the identity for a
/// spring to ground or between scalar masses.
pub(crate) fn link_block(masses: &[Mass], s: &Spring, dim: usize) -> Vec<f64> {
    let identity = || (0..dim * dim).map(|i| if i % (dim + 1) == 0 { 1.0 } else { 0.0 }).collect();
    let Some(b) = s.b else { return identity() };
    let (Some(pa), Some(pb)) = (&masses[s.a].pos, &masses[b].pos) else { return identity() };
    let diff: Vec<f64> = pa.iter().zip(pb).map(|(x, y)| y - x).collect();
    let len = diff.iter().map(|x| x * x).sum::<f64>().sqrt();
    // The file reader refuses coincident ends, so len > 0.
    let d: Vec<f64> = diff.iter().map(|x| x / len).collect();
    (0..dim * dim).map(|i| d[i / dim] * d[i % dim]).collect()
}

/// How the scene's damping relates to its modes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub(crate) enum DampingKind {
    /// No damping at all.
    Undamped,
    /// C = αM + βK.
    Rayleigh {
        /// Mass coefficient α, 1/s.
        alpha: f64,
        /// Stiffness coefficient β, s.
        beta: f64,
    },
    /// C̃ commutes with K̃ but is not of Rayleigh form.
    Proportional,
    /// C̃ does not commute with K̃: the modes are coupled by the damping.
    NonProportional,
}

use serde::Serialize;

/// One mode of a scene.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Mode {
    /// Undamped natural frequency ω, rad/s.
    pub omega: f64,
    /// Damping ratio ζ (a description only when the damping is
    /// non-proportional).
    pub ratio: f64,
    /// φ = M^{-1/2} u with φᵀ M φ = 1, in physical coordinates (`None` for
    /// a scene given as modes).
    pub shape: Option<Vec<f64>>,
    /// Not an eigenvalue found but a sample of the unresolved part of a
    /// large scene's spectrum (see [`super::spectrum`]): a frequency some
    /// mode may have, with the damping ratio it would have.
    pub sampled: bool,
}

impl Mode {
    /// Frequency in Hz.
    pub(crate) fn hz(&self) -> f64 {
        self.omega / (2.0 * std::f64::consts::PI)
    }
}

/// A scene reduced to its modes.
#[derive(Clone, Debug)]
pub struct Modal {
    /// The assembled system (`None` for a scene given as modes).
    pub(crate) system: Option<System>,
    /// The modes with ω > 0, increasing ω.
    pub(crate) modes: Vec<Mode>,
    /// Rigid-body modes dropped (ω = 0).
    pub(crate) rigid: usize,
    /// With non-proportional damping, the system the full-step analysis
    /// runs on: the assembled one, or, when there are rigid modes, its
    /// restriction to the non-rigid modes (see [`reduce_system_with`]).
    pub(crate) full: Option<System>,
    /// The damping's structure.
    pub(crate) damping: DampingKind,
    /// A certified upper bound on the highest angular frequency, rad/s
    /// (Gershgorin on M^{-1/2} K M^{-1/2}, or on the sparse route the
    /// Cholesky certificate), independent of the dense eigensolver; `None`
    /// for a scene given as modes.
    pub(crate) omega_bound: Option<f64>,
    /// How the spectrum was found.
    pub(crate) route: RouteReport,
}

/// Which eigensolver reduced a scene, and what it found.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub(crate) struct RouteReport {
    /// `dense` (every mode) or `sparse` (the highest and the lowest or
    /// in-band modes; the rest sampled).
    pub route: &'static str,
    /// Degrees of freedom no spring or damper touches (zero modes, left
    /// out before the eigenproblem).
    pub untouched_dofs: usize,
    /// Modes computed as eigenpairs.
    pub computed: usize,
    /// Sampled frequencies standing for the unresolved modes.
    pub sampled: usize,
    /// The highest frequency's Ritz value, Hz (sparse route).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub highest_ritz_hz: Option<f64>,
    /// How the bound on the highest frequency is certified.
    pub certificate: Certificate,
    /// Lanczos steps for the highest frequency (sparse route).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lanczos_steps: Option<usize>,
    /// Whether every mode at or below `max_hz` was computed (sparse route
    /// with a band); otherwise samples cover the rest of the band.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub band_complete: Option<bool>,
}

/// Largest system (after untouched degrees of freedom are dropped) reduced
/// densely, every mode; larger ones take the sparse route.
pub(crate) const DENSE_MAX_DOF: usize = 400;

/// Samples spanning the unresolved part of a large scene's spectrum.
const SAMPLES: usize = 48;

/// Which eigensolver reduces a scene of masses and springs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Route {
    /// Dense up to 400 degrees of freedom (after those no spring touches
    /// are dropped), sparse beyond.
    #[default]
    Auto,
    /// Dense: every mode, whatever the size.
    Dense,
    /// Sparse: the highest mode, certified, and the lowest or in-band modes.
    Sparse,
}

/// Relative tolerance of the structural tests (Rayleigh fit, commutation,
/// rigid modes): a few hundred ulps of the largest entry.
const STRUCTURE_TOL: f64 = 1e-10;

/// Whether [`reduce_with`] computes mode shapes (eigenvectors): the check
/// by simulation needs them, and so do ratios under proportional but not
/// Rayleigh damping; frequencies alone need eigenvalues only.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shapes {
    /// Eigenvectors too.
    Compute,
    /// Only when the ratios need them.
    WhenNeeded,
}

/// Reduces a scene to its modes, by the eigensolver its size calls for.
pub fn reduce_with(scene: &SceneFile, shapes: Shapes) -> Result<Modal, Error> {
    reduce_with_route(scene, shapes, Route::Auto)
}

/// Reduces a scene to its modes by the eigensolver given.
pub(crate) fn reduce_with_route(
    scene: &SceneFile,
    shapes: Shapes,
    route: Route,
) -> Result<Modal, Error> {
    match &scene.body {
        Body::Modes(list) => {
            let mut modes: Vec<Mode> = list
                .iter()
                .map(|m| Mode {
                    omega: 2.0 * std::f64::consts::PI * m.hz,
                    ratio: m.ratio,
                    shape: None,
                    sampled: false,
                })
                .collect();
            modes.sort_by(|a, b| a.omega.total_cmp(&b.omega));
            let damping = if modes.iter().all(|m| m.ratio == 0.0) {
                DampingKind::Undamped
            } else {
                DampingKind::Proportional
            };
            let computed = modes.len();
            Ok(Modal {
                system: None,
                modes,
                rigid: 0,
                full: None,
                damping,
                omega_bound: None,
                route: RouteReport {
                    route: "given",
                    untouched_dofs: 0,
                    computed,
                    sampled: 0,
                    highest_ritz_hz: None,
                    certificate: Certificate::Gershgorin,
                    lanczos_steps: None,
                    band_complete: None,
                },
            })
        }
        Body::Springs { masses, springs, dim } => reduce_system_route(
            System::of_scene(masses, springs, *dim),
            shapes,
            scene.max_hz,
            route,
        ),
    }
}

/// Reduces an assembled system by the route given: dense when it is small
/// enough (after dropping the untouched degrees of freedom) and the route
/// is `Auto`, else sparse.
pub(crate) fn reduce_system_route(
    system: System,
    shapes: Shapes,
    max_hz: Option<f64>,
    route: Route,
) -> Result<Modal, Error> {
    let n = system.n();
    let touched = (0..n).filter(|&i| !(system.k.row_is_zero(i) && system.c.row_is_zero(i))).count();
    match route {
        Route::Dense => reduce_system_with(system, shapes),
        Route::Auto if touched <= DENSE_MAX_DOF => reduce_system_with(system, shapes),
        _ => reduce_sparse(system, max_hz),
    }
}

/// The sparse route (see [`super::spectrum`]).
fn reduce_sparse(system: System, max_hz: Option<f64>) -> Result<Modal, Error> {
    let n = system.n();
    let inv_sqrt: Vec<f64> = system.mass.iter().map(|m| 1.0 / m.sqrt()).collect();
    let keep: Vec<usize> =
        (0..n).filter(|&i| !(system.k.row_is_zero(i) && system.c.row_is_zero(i))).collect();
    let untouched = n - keep.len();
    let kt_all = system.k.scaled(&inv_sqrt);
    let ct_all = system.c.scaled(&inv_sqrt);
    let damping = damping_kind(&kt_all, &ct_all);
    let (kt, ct) = (kt_all.restricted(&keep), ct_all.restricted(&keep));
    let gershgorin = kt.gershgorin_upper();
    let top = spectrum::highest(&kt, gershgorin)?;
    let zero_tol = STRUCTURE_TOL * top.upper;
    let tau = max_hz.map(|f| (2.0 * std::f64::consts::PI * f).powi(2));
    let low = if keep.is_empty() {
        spectrum::Lowest::default()
    } else {
        spectrum::lowest(&kt, tau, 4, zero_tol, top.upper)?
    };
    let ratio_of = |omega: f64, u: Option<&[f64]>| match damping {
        DampingKind::Undamped => 0.0,
        DampingKind::Rayleigh { alpha, beta } => alpha / (2.0 * omega) + beta * omega / 2.0,
        _ => u.map_or(0.0, |u| ct.quad(u) / (2.0 * omega)),
    };
    let mut rigid = untouched;
    let mut modes = Vec::new();
    for (&l, u) in low.values.iter().zip(&low.vectors) {
        if l <= zero_tol {
            rigid += 1;
            continue;
        }
        let omega = l.sqrt();
        let mut shape = vec![0.0; n];
        for (&i, x) in keep.iter().zip(u) {
            shape[i] = x * inv_sqrt[i];
        }
        modes.push(Mode {
            omega,
            ratio: ratio_of(omega, Some(u)),
            shape: Some(shape),
            sampled: false,
        });
    }
    let computed = modes.len();
    // Samples from the highest computed mode (or the band's edge) up to the
    // certified bound, log-spaced, the bound itself last.
    let hi = top.upper.sqrt();
    let lo = match (tau, low.complete) {
        (Some(t), true) => t.sqrt(),
        _ => modes.last().map_or(hi * 1e-3, |m| m.omega),
    }
    .min(hi);
    // Under damping other than Rayleigh the ratio of an unresolved mode is
    // only bounded: 2ζω = uᵀC̃u ≤ λ_max(C̃), so each sample runs at both ends.
    let c_bound = ct.gershgorin_upper();
    let count = if lo < hi { SAMPLES } else { 1 };
    for k in 1..=count {
        let omega = lo * (hi / lo).powf(k as f64 / count as f64);
        if omega <= 0.0 || !omega.is_finite() {
            continue;
        }
        let ratios: Vec<f64> = match damping {
            DampingKind::Undamped | DampingKind::Rayleigh { .. } => vec![ratio_of(omega, None)],
            _ => vec![0.0, (c_bound / (2.0 * omega)).min(1.0)],
        };
        for ratio in ratios {
            modes.push(Mode { omega, ratio, shape: None, sampled: true });
        }
    }
    let sampled = modes.len() - computed;
    let route = RouteReport {
        route: "sparse",
        untouched_dofs: untouched,
        computed,
        sampled,
        highest_ritz_hz: Some(top.ritz.sqrt() / (2.0 * std::f64::consts::PI)),
        certificate: top.certificate,
        lanczos_steps: Some(top.steps),
        band_complete: tau.map(|_| low.complete),
    };
    Ok(Modal {
        system: Some(system),
        modes,
        rigid,
        full: None,
        damping,
        omega_bound: Some(hi),
        route,
    })
}

/// Reduces an assembled system to its modes.
pub(crate) fn reduce_system_with(system: System, shapes: Shapes) -> Result<Modal, Error> {
    let n = system.n();
    let inv_sqrt: Vec<f64> = system.mass.iter().map(|m| 1.0 / m.sqrt()).collect();
    let kt = system.k.scaled(&inv_sqrt);
    let ct = system.c.scaled(&inv_sqrt);
    let damping = damping_kind(&kt, &ct);
    // Ratios from eigenvectors are needed unless the damping is zero or
    // Rayleigh; the verification simulation needs shapes in any case.
    let mut dense = faer::Mat::<f64>::zeros(n, n);
    for i in 0..n {
        for (j, x) in kt.row(i) {
            dense[(i, j)] = x;
        }
    }
    let vectors = shapes == Shapes::Compute
        || matches!(damping, DampingKind::Proportional | DampingKind::NonProportional);
    let fail = |e: faer::linalg::evd::EvdError| {
        Error::numeric(format!("the eigenproblem K phi = w^2 M phi did not converge: {e:?}"))
    };
    let (s, u) = if vectors {
        let evd = dense.self_adjoint_eigen(Side::Lower).map_err(fail)?;
        let s: Vec<f64> = (0..n).map(|i| evd.S()[i]).collect();
        (s, Some(evd.U().to_owned()))
    } else {
        (dense.self_adjoint_eigenvalues(Side::Lower).map_err(fail)?, None)
    };
    let lambda_max = s.iter().copied().fold(0.0f64, f64::max);
    let mut modes = Vec::with_capacity(n);
    let mut rigid = 0;
    let mut kept = Vec::with_capacity(n);
    let mut col = vec![0.0; n];
    for i in 0..n {
        let lambda = s[i];
        if lambda <= STRUCTURE_TOL * lambda_max {
            rigid += 1;
            continue;
        }
        kept.push(i);
        let omega = lambda.sqrt();
        if let Some(u) = &u {
            for (r, c) in col.iter_mut().enumerate() {
                *c = u[(r, i)];
            }
        }
        let ratio = match damping {
            DampingKind::Undamped => 0.0,
            DampingKind::Rayleigh { alpha, beta } => alpha / (2.0 * omega) + beta * omega / 2.0,
            _ => ct.quad(&col) / (2.0 * omega),
        };
        let shape = u.is_some().then(|| col.iter().zip(&inv_sqrt).map(|(x, d)| x * d).collect());
        modes.push(Mode { omega, ratio, shape, sampled: false });
    }
    let mut full_system = None;
    if damping == DampingKind::NonProportional {
        // Coupled by the damping: the modes are the continuous system's
        // complex eigenvalues λ = −ζω ± jω√(1−ζ²), ω = |λ|, ζ = −Re λ/|λ|
        // (real λ, overdamped, count as ζ = 1).
        //
        // A rigid mode would be a double eigenvalue 0 here, and a Jordan
        // block at 1 in the full step, whose rounded eigenvalues leave the
        // unit circle by about √ε. Every damper lies along a spring, so
        // null(K) ⊆ null(C) and the rigid modes decouple exactly: the
        // analysis runs on the other modes' coordinates q = U_fᵀ M^{1/2} y,
        // with M = I, K = diag(ω²) and C = U_fᵀ C̃ U_f.
        let full = match &u {
            Some(u) if rigid > 0 => {
                let cols: Vec<Vec<f64>> =
                    kept.iter().map(|&i| (0..n).map(|r| u[(r, i)]).collect()).collect();
                let ct_cols: Vec<Vec<f64>> = cols
                    .iter()
                    .map(|c| (0..n).map(|r| ct.row(r).map(|(j, x)| x * c[j]).sum()).collect())
                    .collect();
                let kr: Vec<f64> = kept.iter().map(|&i| s[i]).collect();
                let mut cr = Assembly::new(kept.len());
                for (a, col) in cols.iter().enumerate() {
                    for (b, ct_col) in ct_cols.iter().enumerate() {
                        cr.add(a, b, col.iter().zip(ct_col).map(|(x, y)| x * y).sum());
                    }
                }
                System { mass: vec![1.0; kept.len()], k: Sparse::diagonal(&kr), c: cr.finish() }
            }
            _ => system.clone(),
        };
        let lambdas = continuous_eigenvalues(&full);
        modes = lambdas
            .iter()
            .filter(|l| l.norm() > 0.0)
            .map(|l| Mode {
                omega: l.norm(),
                ratio: if l.im > 0.0 { -l.re / l.norm() } else { 1.0 },
                shape: None,
                sampled: false,
            })
            .collect();
        full_system = Some(full);
    }
    let full = full_system.take();
    let omega_bound = Some(kt.gershgorin_upper().sqrt());
    let route = RouteReport {
        route: "dense",
        untouched_dofs: 0,
        computed: modes.len(),
        sampled: 0,
        highest_ritz_hz: None,
        certificate: Certificate::Gershgorin,
        lanczos_steps: None,
        band_complete: None,
    };
    Ok(Modal { system: Some(system), modes, rigid, full, damping, omega_bound, route })
}

/// Classifies the damping: zero, Rayleigh (C̃ = αI + βK̃, fitted on the
/// entries), commuting, or non-proportional.
fn damping_kind(kt: &Sparse, ct: &Sparse) -> DampingKind {
    if ct.is_zero() {
        return DampingKind::Undamped;
    }
    // β from the off-diagonal entries, α from the diagonal.
    let n = kt.n();
    let (mut num, mut den) = (0.0, 0.0);
    for i in 0..n {
        for (j, c) in ct.row(i) {
            if i != j {
                let k = kt.get(i, j);
                num += c * k;
                den += k * k;
            }
        }
    }
    let beta = if den > 0.0 { num / den } else { 0.0 };
    let diag = |a: &Sparse, i: usize| a.get(i, i);
    let alpha = (0..n).map(|i| diag(ct, i) - beta * diag(kt, i)).sum::<f64>() / n as f64;
    let scale = ct.max_abs();
    let fits = (0..n).all(|i| {
        let mut ok = true;
        let mut seen_diag = false;
        for (j, c) in ct.row(i) {
            let k = kt.get(i, j);
            let model = beta * k + if i == j { alpha } else { 0.0 };
            seen_diag |= i == j;
            ok &= (c - model).abs() <= STRUCTURE_TOL * scale;
        }
        for (j, k) in kt.row(i) {
            if !ct.row(i).any(|e| e.0 == j) {
                let model = beta * k + if i == j { alpha } else { 0.0 };
                ok &= model.abs() <= STRUCTURE_TOL * scale;
            }
        }
        if !seen_diag {
            ok &= (alpha + beta * diag(kt, i)).abs() <= STRUCTURE_TOL * scale;
        }
        ok
    });
    if fits && alpha >= -STRUCTURE_TOL * scale && beta >= 0.0 {
        return DampingKind::Rayleigh { alpha: alpha.max(0.0), beta };
    }
    if kt.commutes_with(ct, STRUCTURE_TOL) {
        DampingKind::Proportional
    } else {
        DampingKind::NonProportional
    }
}

/// The eigenvalues λ of the continuous system ẏ = v, v̇ = −M⁻¹(K y + C v)
/// with Im λ ≥ 0.
pub(crate) fn continuous_eigenvalues(sys: &System) -> Vec<C64> {
    let n = sys.n();
    let mut a = DMatrix::zeros(2 * n, 2 * n);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        for (j, k) in sys.k.row(i) {
            a[(n + i, j)] = -k / sys.mass[i];
        }
        for (j, c) in sys.c.row(i) {
            a[(n + i, n + j)] = -c / sys.mass[i];
        }
    }
    let mut l: Vec<C64> = check::witness::eigenvalues_nalgebra(&a)
        .unwrap_or_default()
        .into_iter()
        .filter(|z| z.im >= 0.0)
        .collect();
    l.sort_by(|x, y| x.norm().total_cmp(&y.norm()));
    l
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::file::SceneFile;

    fn chain(n: usize, tail: &str) -> String {
        let mut s = String::from("tick_hz = 60\n");
        for i in 0..n {
            s += &format!("[[mass]]\nname = \"m{i}\"\nkg = {}\n", 1.0 + i as f64);
        }
        for i in 0..n {
            let prev = if i == 0 { "ground".to_owned() } else { format!("m{}", i - 1) };
            s += &format!(
                "[[spring]]\nbetween = [\"{prev}\", \"m{i}\"]\nstiffness = {}\n{tail}",
                100.0 * (i + 1) as f64
            );
        }
        s
    }

    /// Each mode satisfies K φ = ω² M φ and φᵀ M φ = 1 (reconstruction, to
    /// a few hundred ulps of ‖K‖).
    #[test]
    fn modes_solve_the_generalised_problem() {
        for n in [1, 2, 3, 8] {
            let scene = SceneFile::parse("c.toml", &chain(n, "")).unwrap();
            let modal = reduce_with(&scene, Shapes::Compute).unwrap();
            let sys = modal.system.as_ref().unwrap();
            assert_eq!(modal.modes.len(), n);
            let scale = sys.k.max_abs();
            for m in &modal.modes {
                let phi = m.shape.as_ref().unwrap();
                // K φ, row by row.
                let kphi: Vec<f64> =
                    (0..n).map(|i| sys.k.row(i).map(|(j, a)| a * phi[j]).sum()).collect();
                for i in 0..n {
                    let r = kphi[i] - m.omega * m.omega * sys.mass[i] * phi[i];
                    assert!(r.abs() <= 500.0 * f64::EPSILON * scale, "n {n}: residual {r}");
                }
                let norm: f64 = phi.iter().zip(&sys.mass).map(|(x, m)| m * x * x).sum();
                assert!((norm - 1.0).abs() < 1e-12, "{norm}");
            }
        }
    }

    /// Dampers parallel to every spring, c = βk, are Rayleigh with α = 0;
    /// a lone damper on one link of a chain is non-proportional.
    #[test]
    fn damping_structure_is_detected() {
        let scene = SceneFile::parse("c.toml", &chain(4, "")).unwrap();
        let Body::Springs { masses, mut springs, .. } = scene.body else { panic!() };
        let m: Vec<f64> = masses.iter().map(|m| m.kg).collect();
        for s in &mut springs {
            s.damping = 0.01 * s.stiffness;
        }
        let r = reduce_system_with(System::assemble(&m, &springs), Shapes::Compute).unwrap();
        match r.damping {
            DampingKind::Rayleigh { alpha, beta } => {
                assert!(alpha.abs() < 1e-9 && (beta - 0.01).abs() < 1e-12, "{alpha} {beta}")
            }
            d => panic!("{d:?}"),
        }
        for m in &r.modes {
            assert!((m.ratio - 0.005 * m.omega).abs() < 1e-12);
        }
        for s in &mut springs {
            s.damping = 0.0;
        }
        springs[2].damping = 3.0;
        let r = reduce_system_with(System::assemble(&m, &springs), Shapes::Compute).unwrap();
        assert_eq!(r.damping, DampingKind::NonProportional);
    }

    /// A random particle scene: masses on a small integer grid (distinct
    /// positions), some fixed, springs between random pairs and to ground.
    fn particle_scene() -> impl proptest::strategy::Strategy<Value = (Vec<Mass>, Vec<Spring>, usize)>
    {
        use proptest::prelude::*;
        (2usize..=3, 2usize..=6).prop_flat_map(|(dim, n)| {
            let cells = proptest::sample::subsequence((0..64usize).collect::<Vec<_>>(), n);
            let kg = proptest::collection::vec(0.1f64..5.0, n);
            let fixed = proptest::collection::vec(proptest::bool::weighted(0.2), n);
            let springs =
                proptest::collection::vec((0..n, 0..=n, 1.0f64..1000.0, 0.0f64..3.0), 1..12);
            (Just(dim), cells, kg, fixed, springs).prop_map(|(dim, cells, kg, fixed, springs)| {
                let masses: Vec<Mass> = cells
                    .iter()
                    .zip(&kg)
                    .zip(&fixed)
                    .enumerate()
                    .map(|(i, ((&c, &kg), &fixed))| Mass {
                        name: format!("m{i}"),
                        kg,
                        // Cells of a 4×4×4 grid (the plane z = 0 in 2D
                        // when c < 16, else folded into it by the modulus).
                        pos: Some(
                            [(c % 4) as f64, ((c / 4) % 4) as f64, (c / 16) as f64][..dim].to_vec(),
                        ),
                        fixed,
                    })
                    .collect();
                let springs = springs
                    .into_iter()
                    .filter(|&(a, b, _, _)| a != b)
                    .filter(|&(a, b, _, _)| b == masses.len() || masses[a].pos != masses[b].pos)
                    .map(|(a, b, k, c)| Spring {
                        a,
                        b: (b < masses.len()).then_some(b),
                        stiffness: k,
                        damping: c,
                    })
                    .collect();
                (masses, springs, dim)
            })
        })
    }

    /// The spring energy ½k(d·(u_b − u_a))² (½k|u_a|² to ground), with the
    /// displacements of fixed masses zero; `u` lists the free masses'
    /// degrees of freedom in mass order.
    fn energy(masses: &[Mass], springs: &[Spring], dim: usize, u: &[f64]) -> f64 {
        let mut at = Vec::new();
        let mut next = 0;
        for m in masses {
            if m.fixed {
                at.push(vec![0.0; dim]);
            } else {
                at.push(u[next..next + dim].to_vec());
                next += dim;
            }
        }
        springs
            .iter()
            .map(|s| match s.b {
                None => 0.5 * s.stiffness * at[s.a].iter().map(|x| x * x).sum::<f64>(),
                Some(b) => {
                    let (pa, pb) =
                        (masses[s.a].pos.as_ref().unwrap(), masses[b].pos.as_ref().unwrap());
                    let d: Vec<f64> = pa.iter().zip(pb).map(|(x, y)| y - x).collect();
                    let len = d.iter().map(|x| x * x).sum::<f64>().sqrt();
                    let stretch: f64 = (0..dim).map(|p| d[p] / len * (at[b][p] - at[s.a][p])).sum();
                    0.5 * s.stiffness * stretch * stretch
                }
            })
            .sum()
    }

    fn dense(a: &Sparse) -> DMatrix<f64> {
        let mut m = DMatrix::zeros(a.n(), a.n());
        for i in 0..a.n() {
            for (j, x) in a.row(i) {
                m[(i, j)] += x;
            }
        }
        m
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(1000))]
        /// The certified bound on the highest frequency is never below the
        /// true one, on 1000 random particle scenes (2D and 3D, some masses
        /// fixed, springs to ground): the oracle is nalgebra's symmetric
        /// eigensolver on the dense M^{-1/2} K M^{-1/2}, independent of
        /// faer's, accurate to 1e-12 of the largest eigenvalue. The modal
        /// reduction reports the same bound.
        #[test]
        fn the_certified_bound_is_never_below_the_highest_frequency(scene in particle_scene()) {
            let (masses, springs, dim) = scene;
            proptest::prop_assume!(masses.iter().any(|m| !m.fixed));
            let sys = System::of_scene(&masses, &springs, dim);
            proptest::prop_assume!(sys.n() > 0);
            let inv_sqrt: Vec<f64> = sys.mass.iter().map(|m| 1.0 / m.sqrt()).collect();
            let kt = sys.k.scaled(&inv_sqrt);
            let lambda_max = dense(&kt).symmetric_eigen().eigenvalues.iter().copied().fold(0.0f64, f64::max);
            let bound = kt.gershgorin_upper();
            proptest::prop_assert!(lambda_max <= bound * (1.0 + 1e-12), "{lambda_max} > {bound}");
            let modal = reduce_system_with(sys, Shapes::WhenNeeded).unwrap();
            proptest::prop_assert_eq!(modal.omega_bound, Some(bound.sqrt()));
            if let Some(top) = modal.modes.iter().map(|m| m.omega).reduce(f64::max) {
                if modal.damping != DampingKind::NonProportional {
                    proptest::prop_assert!(top <= bound.sqrt() * (1.0 + 1e-12));
                }
            }
        }

        /// The sparse route's bound (a Lanczos value certified by a
        /// Cholesky factor, or Gershgorin) is never below the true highest
        /// eigenvalue, its Ritz value never above it, and a Cholesky
        /// certificate is within 10⁻⁶ of it, on the same 1000 scenes
        /// against nalgebra's dense eigensolver.
        #[test]
        fn the_sparse_certificate_is_never_below_the_highest_frequency(scene in particle_scene()) {
            let (masses, springs, dim) = scene;
            proptest::prop_assume!(masses.iter().any(|m| !m.fixed));
            let sys = System::of_scene(&masses, &springs, dim);
            proptest::prop_assume!(sys.n() > 0 && !sys.k.is_zero());
            let inv_sqrt: Vec<f64> = sys.mass.iter().map(|m| 1.0 / m.sqrt()).collect();
            let kt = sys.k.scaled(&inv_sqrt);
            let lambda_max = dense(&kt).symmetric_eigen().eigenvalues.iter().copied().fold(0.0f64, f64::max);
            let h = spectrum::highest(&kt, kt.gershgorin_upper()).unwrap();
            let slack = 1e-12 * lambda_max;
            proptest::prop_assert!(h.upper >= lambda_max - slack, "bound {} < {lambda_max}", h.upper);
            proptest::prop_assert!(h.ritz <= lambda_max + slack, "ritz {} > {lambda_max}", h.ritz);
            if h.certificate == Certificate::Cholesky {
                proptest::prop_assert!(h.upper <= lambda_max * (1.0 + 1e-6), "{} vs {lambda_max}", h.upper);
            }
        }
    }

    proptest::proptest! {
        /// The assembled K is the Hessian of the spring energy (by the
        /// four-point difference, exact for a quadratic up to rounding),
        /// symmetric and positive semi-definite, and its zero modes number
        /// n − rank(B), B the compatibility matrix (a row d per spring, the
        /// identity per spring to ground), by SVD; the modal reduction
        /// counts the same rigid modes. C likewise with the damping.
        #[test]
        fn stiffness_is_the_hessian_of_the_spring_energy(scene in particle_scene()) {
            let (masses, springs, dim) = scene;
            proptest::prop_assume!(masses.iter().any(|m| !m.fixed));
            proptest::prop_assume!(!springs.is_empty());
            let sys = System::of_scene(&masses, &springs, dim);
            let n = sys.n();
            proptest::prop_assert_eq!(n, dim * masses.iter().filter(|m| !m.fixed).count());
            let (k, c) = (dense(&sys.k), dense(&sys.c));
            let scale = springs.iter().map(|s| s.stiffness).fold(1.0, f64::max);
            let unit = |i: usize, x: f64| (0..n).map(|j| if j == i { x } else { 0.0 }).collect::<Vec<_>>();
            let e = |u: &[f64]| energy(&masses, &springs, dim, u);
            let damp: Vec<Spring> = springs.iter().map(|s| Spring { stiffness: s.damping, ..s.clone() }).collect();
            let ec = |u: &[f64]| energy(&masses, &damp, dim, u);
            for i in 0..n {
                for j in 0..n {
                    let add = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x + y).collect::<Vec<_>>();
                    let h = |f: &dyn Fn(&[f64]) -> f64| {
                        (f(&add(&unit(i, 1.0), &unit(j, 1.0))) - f(&add(&unit(i, 1.0), &unit(j, -1.0)))
                            - f(&add(&unit(i, -1.0), &unit(j, 1.0)))
                            + f(&add(&unit(i, -1.0), &unit(j, -1.0))))
                            / 4.0
                    };
                    proptest::prop_assert!((k[(i, j)] - h(&e)).abs() <= 1e-12 * scale * 64.0, "K[{},{}] = {} vs {}", i, j, k[(i, j)], h(&e));
                    proptest::prop_assert!((c[(i, j)] - h(&ec)).abs() <= 1e-12 * 64.0 * 3.0, "C[{},{}]", i, j);
                    proptest::prop_assert_eq!(k[(i, j)], k[(j, i)]);
                }
            }
            let lambda = k.clone().symmetric_eigenvalues();
            let lmax = lambda.max().max(0.0);
            proptest::prop_assert!(lambda.min() >= -1e-12 * lmax.max(1.0), "not PSD: {}", lambda.min());
            // B: √k·dᵀ rows on the free ends (√k·I to ground).
            let mut base = vec![None; masses.len()];
            let mut next = 0;
            for (i, m) in masses.iter().enumerate() {
                if !m.fixed { base[i] = Some(next); next += dim; }
            }
            let mut rows: Vec<Vec<f64>> = Vec::new();
            for s in &springs {
                let w = s.stiffness.sqrt();
                match s.b {
                    None => for p in 0..dim {
                        let mut r = vec![0.0; n];
                        if let Some(a) = base[s.a] { r[a + p] = w; }
                        rows.push(r);
                    },
                    Some(b) => {
                        let (pa, pb) = (masses[s.a].pos.as_ref().unwrap(), masses[b].pos.as_ref().unwrap());
                        let d: Vec<f64> = pa.iter().zip(pb).map(|(x, y)| y - x).collect();
                        let len = d.iter().map(|x| x * x).sum::<f64>().sqrt();
                        let mut r = vec![0.0; n];
                        for p in 0..dim {
                            if let Some(a) = base[s.a] { r[a + p] -= w * d[p] / len; }
                            if let Some(bb) = base[b] { r[bb + p] += w * d[p] / len; }
                        }
                        rows.push(r);
                    }
                }
            }
            let bm = DMatrix::from_fn(rows.len(), n, |i, j| rows[i][j]);
            let sv = bm.singular_values();
            let smax = sv.max();
            let rank = sv.iter().filter(|&&s| s > 1e-5 * smax).count();
            // K = BᵀB exactly.
            let ktb = bm.transpose() * &bm;
            proptest::prop_assert!((&ktb - &k).abs().max() <= 1e-12 * scale * 64.0);
            let zeros = lambda.iter().filter(|&&l| l <= 1e-10 * lmax).count();
            proptest::prop_assert_eq!(zeros, n - rank);
            // Undamped, so that every mode is a real ω (the damped reduction
            // may list an overdamped pair as two).
            let modal = reduce_system_with(System { c: Sparse::zeros(n), ..sys }, Shapes::WhenNeeded).unwrap();
            let expected_rigid = if lmax > 0.0 { n - rank } else { n };
            proptest::prop_assert_eq!(modal.rigid, expected_rigid);
            proptest::prop_assert_eq!(modal.rigid + modal.modes.len(), n);
            for m in &modal.modes {
                proptest::prop_assert!(m.omega.is_finite() && m.omega > 0.0 && m.ratio.is_finite());
            }
        }
    }

    /// Free frames: a triangle in 2D has 3 rigid modes (two translations,
    /// one rotation), a tetrahedron in 3D 6, a braced square flat in 3D 7
    /// (3 in its plane, one out of the plane per corner).
    #[test]
    fn free_frames_have_their_rigid_modes() {
        let mass =
            |p: &[f64]| Mass { name: String::new(), kg: 1.0, pos: Some(p.to_vec()), fixed: false };
        let spring = |a: usize, b: usize| Spring { a, b: Some(b), stiffness: 10.0, damping: 0.0 };
        let all = |n: usize| {
            (0..n)
                .flat_map(|a| (a + 1..n).map(move |b| (a, b)))
                .map(|(a, b)| spring(a, b))
                .collect::<Vec<_>>()
        };
        for (masses, dim, rigid) in [
            (vec![mass(&[0.0, 0.0]), mass(&[1.0, 0.0]), mass(&[0.3, 0.8])], 2, 3),
            (
                vec![
                    mass(&[0.0, 0.0, 0.0]),
                    mass(&[1.0, 0.0, 0.0]),
                    mass(&[0.0, 1.0, 0.0]),
                    mass(&[0.2, 0.3, 1.0]),
                ],
                3,
                6,
            ),
            (
                vec![
                    mass(&[0.0, 0.0, 0.0]),
                    mass(&[1.0, 0.0, 0.0]),
                    mass(&[0.0, 1.0, 0.0]),
                    mass(&[1.0, 1.0, 0.0]),
                ],
                3,
                7,
            ),
        ] {
            let springs = all(masses.len());
            let r = reduce_system_with(System::of_scene(&masses, &springs, dim), Shapes::Compute)
                .unwrap();
            assert_eq!(r.rigid, rigid, "{dim}D, {} masses", masses.len());
            assert_eq!(r.modes.len(), dim * masses.len() - rigid);
        }
    }
}
