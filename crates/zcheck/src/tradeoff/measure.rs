//! The measured cost of any method: its compiled step, timed on this machine.
//!
//! A method, built-in or a user's `.zm` file, is emitted as Rust and
//! compiled by the rustc at hand ([`crate::native`]); that native step is
//! what is timed, on one state, with the same brief timer as the
//! hand-written kernels ([`super::kernels::time_ns_per_step`]), which stay
//! as a baseline column beside it. Without a rustc the specialised
//! interpreter ([`check::kernel::Kernel`]) is timed instead. Built with the
//! feature `jit`, the step timed is cranelift's ([`check::jit::JitStep`]).
//! All three are bit for bit the interpreter's operations.
//!
//! The state is renormalised between chunks of steps, so an unstable method
//! at a large Φ never reaches infinities or subnormal numbers (which would
//! time the floating-point unit's slow paths, not the method).

use std::hint::black_box;
use std::time::Duration;

use crate::error::Error;
#[cfg(not(feature = "jit"))]
use check::kernel::Kernel;
use check::numeric::{Params, Step};
use poly::Method;

use super::kernels::time_ns_per_step;

/// Steps between two renormalisations of the timed state.
const CHUNK: u64 = 1024;

/// Measured nanoseconds per step of `method`'s compiled step at `params`
/// (which must give every parameter of the method, Φ included), one state,
/// timed for about `budget`.
pub(crate) fn measure_ns_per_step_within(
    method: &Method,
    params: &Params,
    budget: Duration,
) -> Result<f64, Error> {
    #[cfg(not(feature = "jit"))]
    if let Ok(native) = crate::native::native_step(method, params) {
        let ones = vec![1.0; native.slots()];
        let mut slots = ones.clone();
        return Ok(time_chunked(budget, |k| {
            native.advance(black_box(&mut slots), k);
            renormalise(&mut slots, &ones);
        }));
    }
    let step = Step::compile(method, params)?;
    // The cranelift step (feature `jit`), else the specialised interpreter:
    // bit for bit the same operations.
    #[cfg(feature = "jit")]
    let kernel = check::jit::JitStep::compile(&step)?;
    #[cfg(not(feature = "jit"))]
    let kernel = Kernel::<f64>::new(&step);
    let ones = vec![1.0; step.order()];
    #[cfg(feature = "jit")]
    let mut state = step.state(&ones);
    #[cfg(not(feature = "jit"))]
    let mut state = kernel.state(&ones);
    Ok(time_chunked(budget, |k| {
        kernel.advance(black_box(&mut state), k);
        renormalise(state.slots_mut(), &ones);
    }))
}

/// ns per step of `advance(k)` (k steps, then a renormalisation), run in
/// chunks of at most [`CHUNK`] steps.
fn time_chunked(budget: Duration, mut advance: impl FnMut(u64)) -> f64 {
    time_ns_per_step(
        |n| {
            let mut left = n;
            while left > 0 {
                let k = left.min(CHUNK);
                advance(k);
                left -= k;
            }
        },
        budget,
    )
}

/// Scales the state back to size 1 when it has grown or shrunk far, and
/// restarts it when it is no longer finite (or is zero).
fn renormalise(slots: &mut [f64], start: &[f64]) {
    let big = slots.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if !big.is_finite() || big == 0.0 {
        slots.copy_from_slice(start);
    } else if !(1e-100..=1e100).contains(&big) {
        slots.iter_mut().for_each(|x| *x /= big);
    }
}
