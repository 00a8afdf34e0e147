//! Hand-written Rust kernels of every built-in, and a brief in-process timer.
//!
//! Each kernel transcribes its `.zm` source line by line (and so Appendix B's
//! "Direct Integration" or "Transition matrix" branch), the way a game
//! programmer would write it: plain `f64` code, Φ passed in, no folding by
//! hand. The compiler hoists what depends on Φ only out of a loop. The
//! tests hold every kernel against the exact transition matrix, so a kernel
//! cannot drift from its definition; the benchmarks and `zcheck tradeoff`
//! time them.
//!
//! State layout: `(v, y)` for the two-variable methods, `(y, y_prev)` for
//! Verlet (`y_prev` is `y@1`).

use std::hint::black_box;
use std::time::{Duration, Instant};

/// Section 5: both updates read the start-of-step values.
#[inline]
pub(crate) fn standard_euler(v: &mut f64, y: &mut f64, phi: f64) {
    let v1 = *v - phi * *y;
    *y += phi * *v;
    *v = v1;
}

/// Section 6 with D = Φ/2 (Appendix B case 2).
#[inline]
pub(crate) fn damped_euler(v: &mut f64, y: &mut f64, phi: f64) {
    let d = 0.5 * phi;
    let v1 = *v - phi * (*y + 2.0 * d * *v);
    *y += phi * *v;
    *v = v1;
}

/// Section 7: the update of y reads the new v.
#[inline]
pub(crate) fn false_euler(v: &mut f64, y: &mut f64, phi: f64) {
    *v -= phi * *y;
    *y += phi * *v;
}

/// Section 8, Appendix B case 4: `y1:=2*y0-y2+Sqr(dT)*(-wo*wo*y0)`.
#[inline]
pub(crate) fn verlet(y: &mut f64, y_prev: &mut f64, phi: f64) {
    let y1 = 2.0 * *y - *y_prev - phi * phi * *y;
    *y_prev = *y;
    *y = y1;
}

/// Section 9, Appendix B case 5.
#[inline]
pub(crate) fn standard_heun(v: &mut f64, y: &mut f64, phi: f64) {
    let dv1 = -phi * *y;
    let v11 = *v + dv1;
    let dy1 = phi * *v;
    let y11 = *y + dy1;
    let dv2 = -phi * y11;
    let dy2 = phi * v11;
    *v += 0.5 * (dv1 + dv2);
    *y += 0.5 * (dy1 + dy2);
}

/// Section 10, Appendix B case 6.
#[inline]
pub(crate) fn false_heun(v: &mut f64, y: &mut f64, phi: f64) {
    let dv1 = -phi * *y;
    let v11 = *v + dv1;
    let dy1 = phi * v11;
    let y11 = *y + dy1;
    let dv2 = -phi * y11;
    let v12 = *v + dv2;
    let dy2 = phi * v12;
    *v += 0.5 * (dv1 + dv2);
    *y += 0.5 * (dy1 + dy2);
}

/// Section 11, Appendix B case 7 (whose `v11:= v0+dv1` is never read, so
/// it is left out here, as a compiler would).
#[inline]
pub(crate) fn semi_false_heun(v: &mut f64, y: &mut f64, phi: f64) {
    let dv1 = -phi * *y;
    let dy1 = phi * *v;
    let y11 = *y + dy1;
    let dv2 = -phi * y11;
    let v12 = *v + dv2;
    let dy2 = phi * v12;
    *v += 0.5 * (dv1 + dv2);
    *y += 0.5 * (dy1 + dy2);
}

/// Appendix B case 1, "Transition matrix".
#[inline]
pub(crate) fn standard_euler_matrix(v: &mut f64, y: &mut f64, phi: f64) {
    let v1 = *v - phi * *y;
    *y += phi * *v; // y1:= woT*v0 + y0 (IEEE addition commutes)
    *v = v1;
}

/// Appendix B case 2, "Transition matrix".
#[inline]
pub(crate) fn damped_euler_matrix(v: &mut f64, y: &mut f64, phi: f64) {
    let v1 = (1.0 - phi * phi) * *v - phi * *y;
    *y += phi * *v; // y1:= woT*v0 + y0 (IEEE addition commutes)
    *v = v1;
}

/// Appendix B case 3, "Transition matrix".
#[inline]
pub(crate) fn false_euler_matrix(v: &mut f64, y: &mut f64, phi: f64) {
    let v1 = *v - phi * *y;
    *y = phi * *v + (1.0 - phi * phi) * *y;
    *v = v1;
}

/// Appendix B case 5, "Transition matrix".
#[inline]
pub(crate) fn standard_heun_matrix(v: &mut f64, y: &mut f64, phi: f64) {
    let v1 = (1.0 - 0.5 * phi * phi) * *v - phi * *y;
    *y = phi * *v + (1.0 - 0.5 * phi * phi) * *y;
    *v = v1;
}

/// Appendix B case 6, "Transition matrix".
#[inline]
pub(crate) fn false_heun_matrix(v: &mut f64, y: &mut f64, phi: f64) {
    let phi2 = phi * phi;
    let v1 = (1.0 - 0.5 * phi2) * *v - phi * (1.0 - 0.5 * phi2) * *y;
    *y = phi * (1.0 - 0.5 * phi2) * *v + (1.0 - phi2 + 0.5 * phi2 * phi2) * *y;
    *v = v1;
}

/// Appendix B case 7, "Transition matrix".
#[inline]
pub(crate) fn semi_false_heun_matrix(v: &mut f64, y: &mut f64, phi: f64) {
    let phi2 = phi * phi;
    let v1 = (1.0 - 0.5 * phi2) * *v - phi * *y;
    *y = phi * (1.0 - 0.5 * phi2) * *v + (1.0 - 0.5 * phi2) * *y;
    *v = v1;
}

/// Standard Euler on the damped spring (`damped_euler_d`).
#[inline]
pub(crate) fn standard_euler_damped(v: &mut f64, y: &mut f64, phi: f64, d: f64) {
    let v1 = *v - phi * (2.0 * d * *v + *y);
    *y += phi * *v;
    *v = v1;
}

/// Damped Euler on the damped spring: physical D plus the artificial Φ/2.
#[inline]
pub(crate) fn damped_euler_damped(v: &mut f64, y: &mut f64, phi: f64, d: f64) {
    let e = d + 0.5 * phi;
    let v1 = *v - phi * (*y + 2.0 * e * *v);
    *y += phi * *v;
    *v = v1;
}

/// False Euler on the damped spring.
#[inline]
pub(crate) fn false_euler_damped(v: &mut f64, y: &mut f64, phi: f64, d: f64) {
    *v -= phi * (*y + 2.0 * d * *v);
    *y += phi * *v;
}

/// Verlet on the damped spring, the velocity taken as (y − y@1)/T.
#[inline]
pub(crate) fn verlet_damped(y: &mut f64, y_prev: &mut f64, phi: f64, d: f64) {
    let y1 = 2.0 * *y - *y_prev - phi * phi * *y - 2.0 * d * phi * (*y - *y_prev);
    *y_prev = *y;
    *y = y1;
}

/// Standard Heun on the damped spring.
#[inline]
pub(crate) fn standard_heun_damped(v: &mut f64, y: &mut f64, phi: f64, d: f64) {
    let dv1 = -phi * (*y + 2.0 * d * *v);
    let v11 = *v + dv1;
    let dy1 = phi * *v;
    let y11 = *y + dy1;
    let dv2 = -phi * (y11 + 2.0 * d * v11);
    let dy2 = phi * v11;
    *v += 0.5 * (dv1 + dv2);
    *y += 0.5 * (dy1 + dy2);
}

/// False Heun on the damped spring.
#[inline]
pub(crate) fn false_heun_damped(v: &mut f64, y: &mut f64, phi: f64, d: f64) {
    let dv1 = -phi * (*y + 2.0 * d * *v);
    let v11 = *v + dv1;
    let dy1 = phi * v11;
    let y11 = *y + dy1;
    let dv2 = -phi * (y11 + 2.0 * d * v11);
    let v12 = *v + dv2;
    let dy2 = phi * v12;
    *v += 0.5 * (dv1 + dv2);
    *y += 0.5 * (dy1 + dy2);
}

/// Semi-False Heun on the damped spring.
#[inline]
pub(crate) fn semi_false_heun_damped(v: &mut f64, y: &mut f64, phi: f64, d: f64) {
    let dv1 = -phi * (*y + 2.0 * d * *v);
    let v11 = *v + dv1;
    let dy1 = phi * *v;
    let y11 = *y + dy1;
    let dv2 = -phi * (y11 + 2.0 * d * v11);
    let v12 = *v + dv2;
    let dy2 = phi * v12;
    *v += 0.5 * (dv1 + dv2);
    *y += 0.5 * (dy1 + dy2);
}

/// Applies `step` to every state of a struct-of-arrays batch.
///
/// Panics when the slices differ in length (a programmer error).
#[inline]
#[track_caller]
pub(crate) fn for_each_state(
    a: &mut [f64],
    b: &mut [f64],
    mut step: impl FnMut(&mut f64, &mut f64),
) {
    assert_eq!(a.len(), b.len(), "batch slices differ in length");
    for (x, y) in a.iter_mut().zip(b.iter_mut()) {
        step(x, y);
    }
}

/// The names of every hand-written kernel: the built-ins and the damped
/// variants of [`super::family`].
pub(crate) fn hand_kernel_names() -> &'static [&'static str] {
    &[
        "standard_euler",
        "damped_euler",
        "false_euler",
        "verlet",
        "standard_heun",
        "false_heun",
        "semi_false_heun",
        "standard_euler_matrix",
        "damped_euler_matrix",
        "false_euler_matrix",
        "standard_heun_matrix",
        "false_heun_matrix",
        "semi_false_heun_matrix",
        "standard_euler_damped",
        "damped_euler_damped",
        "false_euler_damped",
        "verlet_damped",
        "standard_heun_damped",
        "false_heun_damped",
        "semi_false_heun_damped",
    ]
}

/// The one table from kernel name to kernel, shared by the single-state and
/// batch runners: `$go` is the runner's local loop macro.
macro_rules! dispatch {
    ($name:expr, $go:ident) => {
        match $name {
            "standard_euler" => $go!(standard_euler),
            "damped_euler" => $go!(damped_euler),
            "false_euler" => $go!(false_euler),
            "verlet" => $go!(verlet),
            "standard_heun" => $go!(standard_heun),
            "false_heun" => $go!(false_heun),
            "semi_false_heun" => $go!(semi_false_heun),
            "standard_euler_matrix" => $go!(standard_euler_matrix),
            "damped_euler_matrix" => $go!(damped_euler_matrix),
            "false_euler_matrix" => $go!(false_euler_matrix),
            "standard_heun_matrix" => $go!(standard_heun_matrix),
            "false_heun_matrix" => $go!(false_heun_matrix),
            "semi_false_heun_matrix" => $go!(semi_false_heun_matrix),
            "standard_euler_damped" => $go!(standard_euler_damped, damped),
            "damped_euler_damped" => $go!(damped_euler_damped, damped),
            "false_euler_damped" => $go!(false_euler_damped, damped),
            "verlet_damped" => $go!(verlet_damped, damped),
            "standard_heun_damped" => $go!(standard_heun_damped, damped),
            "false_heun_damped" => $go!(false_heun_damped, damped),
            "semi_false_heun_damped" => $go!(semi_false_heun_damped, damped),
            _ => false,
        }
    };
}

/// Applies kernel `name` `n_steps` times to `(a, b)` at `phi` (and damping
/// `d` for the `_damped` kernels); `false` when there is no kernel of that
/// name. Dispatch is one `match` outside the loop, so each arm's loop is
/// monomorphic and the kernel inlines into it.
pub fn run_hand_kernel(
    name: &str,
    a: &mut f64,
    b: &mut f64,
    phi: f64,
    d: f64,
    n_steps: u64,
) -> bool {
    macro_rules! go {
        ($k:expr) => {{
            for _ in 0..n_steps {
                $k(a, b, phi);
            }
            true
        }};
        ($k:expr, damped) => {{
            for _ in 0..n_steps {
                $k(a, b, phi, d);
            }
            true
        }};
    }
    dispatch!(name, go)
}

/// [`run_hand_kernel`] on a struct-of-arrays batch: every step advances
/// every state (`a[i]`, `b[i]`), the inner loop over states, which the
/// compiler vectorises. Panics when the slices differ in length.
#[track_caller]
pub fn run_hand_kernel_batch(
    name: &str,
    a: &mut [f64],
    b: &mut [f64],
    phi: f64,
    d: f64,
    n_steps: u64,
) -> bool {
    macro_rules! go {
        ($k:expr) => {{
            for _ in 0..n_steps {
                for_each_state(a, b, |x, y| $k(x, y, phi));
            }
            true
        }};
        ($k:expr, damped) => {{
            for _ in 0..n_steps {
                for_each_state(a, b, |x, y| $k(x, y, phi, d));
            }
            true
        }};
    }
    dispatch!(name, go)
}

/// The step used for timing: small enough that no kernel overflows or
/// reaches subnormal numbers within 2^20 steps from a unit state, even the
/// damped ones at D ≤ 1 (e^{−DΦn} ≥ e^{−105}).
pub const TIMING_PHI: f64 = 1e-4;

/// Times `run(n)` (which performs n steps from a fresh state) briefly and
/// returns the best nanoseconds per step: the count doubles from 1024 until
/// one run takes `budget / 8` (or 2^20 steps), then the best of five runs
/// of that count is kept. The minimum is the usual estimator for a quiet
/// loop: noise only ever adds time.
pub(crate) fn time_ns_per_step(mut run: impl FnMut(u64), budget: Duration) -> f64 {
    let mut n: u64 = 1024;
    loop {
        let start = Instant::now();
        run(n);
        if start.elapsed() >= budget / 8 || n >= 1 << 20 {
            break;
        }
        n *= 2;
    }
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let start = Instant::now();
        run(n);
        best = best.min(start.elapsed().as_secs_f64() * 1e9 / n as f64);
    }
    best
}

/// ns per step of hand kernel `name` on one state, timed briefly (about
/// `budget`); `None` when there is no kernel of that name.
pub(crate) fn time_hand_kernel(name: &str, d: f64, budget: Duration) -> Option<f64> {
    if !hand_kernel_names().contains(&name) {
        return None;
    }
    Some(time_ns_per_step(
        |n| {
            let (mut a, mut b) = (black_box(0.0), black_box(1.0));
            run_hand_kernel(name, &mut a, &mut b, black_box(TIMING_PHI), black_box(d), n);
            black_box((a, b));
        },
        budget,
    ))
}
