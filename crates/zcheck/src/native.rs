//! The native step by default: a method's step as emitted Rust ([`crate::emit`]),
//! compiled by the `rustc` at hand into a shared library and loaded.
//!
//! The cost that ranks methods (`tradeoff`, `advise`) is the time of this
//! step: the same source a user would paste into an engine, compiled by the
//! compiler that built the hand-written kernels, at the same optimisation
//! level, so the two are compared on equal terms. The emitted step performs
//! the interpreter's operations in the interpreter's order (no fused
//! multiply-add, no reassociation: rustc does neither), so its results are
//! bit for bit [`check::numeric::Step::advance`]'s (tested).
//!
//! - **Source.** Explicit methods are emitted with their parameters as
//!   arguments (so one library serves every Φ and D); implicit ones with
//!   the values folded (the solve of their stages depends on Φ). Each step
//!   gets a single-state loop and a struct-of-arrays batch loop, exported
//!   with the C ABI.
//! - **Cache.** The library is kept under `$ZCHECK_NATIVE_CACHE`, else
//!   `$XDG_CACHE_HOME/zcheck/native`, else `$HOME/.cache/zcheck/native`,
//!   named by a hash of its source and of `rustc -V`: a second run loads it
//!   in a millisecond. Several steps compile in one `rustc` call
//!   (`prepare`).
//! - **Fallback.** Without a `rustc` (or when it fails), callers time the
//!   specialised interpreter ([`check::kernel::Kernel`]) and say so.

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Arc, Mutex, OnceLock};

use check::numeric::{Params, ParamsF64, Step};
use poly::Method;

use crate::emit::{emit, Binding, Lang};
use crate::error::Error;

type SingleFn = unsafe extern "C" fn(*mut f64, *const f64, u64);
type BatchFn = unsafe extern "C" fn(*mut f64, u64, *const f64, u64);

/// A compiled step, loaded.
#[derive(Clone)]
pub struct NativeStep {
    lib: Arc<libloading::Library>,
    single: SingleFn,
    batch: BatchFn,
    slots: usize,
    args: Vec<f64>,
}

impl std::fmt::Debug for NativeStep {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "NativeStep({} slots, args {:?})", self.slots, self.args)
    }
}

impl NativeStep {
    /// The number of state slots (as [`Step::order`]'s state holds them).
    pub fn slots(&self) -> usize {
        self.slots
    }

    /// Advances one state `steps` times.
    ///
    /// # Panics
    /// When `slots` is not [`NativeStep::slots`] long.
    pub fn advance(&self, slots: &mut [f64], steps: u64) {
        assert_eq!(slots.len(), self.slots, "a state of {} slots", self.slots);
        let _keep = &self.lib;
        // SAFETY: the function reads and writes exactly `self.slots` values
        // at `slots` and reads `self.args.len()` values at `args`, the
        // lengths it was generated for; the library outlives the call.
        unsafe { (self.single)(slots.as_mut_ptr(), self.args.as_ptr(), steps) }
    }

    /// Advances a batch `steps` times: `soa` holds slot k of state i at
    /// `k * lanes + i`.
    ///
    /// # Panics
    /// When `soa` is not `slots × lanes` long.
    pub fn advance_batch(&self, soa: &mut [f64], lanes: usize, steps: u64) {
        assert_eq!(soa.len(), self.slots * lanes, "a batch of {} slots × lanes", self.slots);
        let _keep = &self.lib;
        // SAFETY: as `advance`, over `slots × lanes` values.
        unsafe { (self.batch)(soa.as_mut_ptr(), lanes as u64, self.args.as_ptr(), steps) }
    }
}

/// One step's generated source: the emitted function and its two loops.
struct Unit {
    source: String,
    slots: usize,
    args: Vec<f64>,
}

/// The source of `method`'s step at `params`, exported as
/// `zc_single_{id}` and `zc_batch_{id}`.
fn unit(method: &Method, params: &Params, id: usize) -> Result<Unit, Error> {
    let step = Step::compile(method, params)?;
    let slots = step.slot_names().len();
    let (code, args) = match emit(method, Lang::Rust, &Binding::Parametric) {
        Ok(code) => (code, params.values_for(method)?),
        Err(_) => {
            let values: Vec<(poly::Sym, poly::Q)> = method
                .params()
                .iter()
                .map(|&s| {
                    let v = params.value(s.name()).cloned().ok_or_else(|| {
                        Error::usage(format!("{}: no value for {}", method.name(), s.name()))
                    })?;
                    Ok((s, v))
                })
                .collect::<Result<_, Error>>()?;
            (emit(method, Lang::Rust, &Binding::Folded(values))?, Vec::new())
        }
    };
    let fn_name = code
        .lines()
        .find_map(|l| l.strip_prefix("pub fn ").and_then(|r| r.split('(').next()))
        .ok_or_else(|| Error::numeric("the emitted step has no function".to_owned()))?
        .to_owned();
    // The parameters as locals before the loops, so nothing is re-read per
    // step.
    let call_args: String = (0..args.len()).map(|i| format!(", a{i}")).collect();
    let locals: String = (0..args.len()).map(|i| format!("    let a{i} = p[{i}];\n")).collect();
    let mut s = String::new();
    let _ = writeln!(s, "mod m{id} {{\n{code}}}");
    let _ = writeln!(
        s,
        "#[no_mangle]\npub unsafe extern \"C\" fn zc_single_{id}(s: *mut f64, p: *const f64, steps: u64) {{\n    \
         let p = core::slice::from_raw_parts(p, {np});\n{locals}    let s = &mut *(s as *mut [f64; {slots}]);\n    \
         let mut st = *s;\n    for _ in 0..steps {{ m{id}::{fn_name}(&mut st{call_args}); }}\n    *s = st;\n}}",
        np = args.len()
    );
    // The batch: the loop over states innermost, each slot's values
    // contiguous, so the compiler vectorises it as it does the hand batch.
    let split: String =
        (0..slots).map(|k| format!("    let (s{k}, rest) = rest.split_at_mut(lanes);\n")).collect();
    let load: String = (0..slots).map(|k| format!("s{k}[i], ")).collect();
    let store: String = (0..slots).map(|k| format!("s{k}[i] = st[{k}]; ")).collect();
    let _ = writeln!(
        s,
        "#[no_mangle]\npub unsafe extern \"C\" fn zc_batch_{id}(s: *mut f64, lanes: u64, p: *const f64, steps: u64) {{\n    \
         let p = core::slice::from_raw_parts(p, {np});\n{locals}    let lanes = lanes as usize;\n    \
         let rest = core::slice::from_raw_parts_mut(s, {slots} * lanes);\n{split}    let _ = rest;\n    \
         for _ in 0..steps {{\n        for i in 0..lanes {{\n            let mut st = [{load}];\n            \
         m{id}::{fn_name}(&mut st{call_args});\n            {store}\n        }}\n    }}\n}}",
        np = args.len()
    );
    Ok(Unit { source: s, slots, args })
}

/// The rustc to call: `$RUSTC`, else `rustc` on the path.
fn rustc() -> PathBuf {
    std::env::var_os("RUSTC").map_or_else(|| PathBuf::from("rustc"), PathBuf::from)
}

/// `rustc -V`, once per process (`None`: no usable rustc).
fn rustc_version() -> Option<&'static str> {
    static V: OnceLock<Option<String>> = OnceLock::new();
    V.get_or_init(|| {
        let out = Command::new(rustc()).arg("-V").output().ok()?;
        out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_owned())
    })
    .as_deref()
}

/// Where compiled libraries are kept.
fn cache_dir() -> PathBuf {
    if let Some(d) = std::env::var_os("ZCHECK_NATIVE_CACHE") {
        return PathBuf::from(d);
    }
    if let Some(d) = std::env::var_os("XDG_CACHE_HOME") {
        return Path::new(&d).join("zcheck").join("native");
    }
    if let Some(h) = std::env::var_os("HOME") {
        return Path::new(&h).join(".cache").join("zcheck").join("native");
    }
    std::env::temp_dir().join("zcheck-native")
}

/// A stable 64-bit hash (FNV-1a) of the text.
fn fnv(text: &str) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    h
}

/// rustc's options for the library (part of the cache key). One state's
/// step is a dependency chain: packing its two or three independent
/// updates into one vector register (SLP) adds shuffles to the chain
/// (Standard Euler: 1.86 ns against 1.49 without, the hand kernel's code
/// the same). The batch loop is vectorised across states by the loop
/// vectoriser, which stays on.
const RUSTC_FLAGS: [&str; 14] = [
    "--edition",
    "2021",
    "--crate-type",
    "cdylib",
    "-C",
    "opt-level=3",
    "-C",
    "panic=abort",
    "-C",
    "debuginfo=0",
    "-C",
    "strip=debuginfo",
    "-C",
    "llvm-args=-vectorize-slp=false",
];

/// Compiles `source` into a shared library (or finds it in the cache) and
/// loads it.
fn build(source: &str) -> Result<Arc<libloading::Library>, Error> {
    let version = rustc_version().ok_or_else(|| {
        Error::numeric("no rustc found (set RUSTC, or put rustc on the PATH)".to_owned())
    })?;
    let key = format!(
        "{:016x}",
        fnv(&format!("{version}\n{}\n{}\n{source}", std::env::consts::ARCH, RUSTC_FLAGS.join(" ")))
    );
    let dir = cache_dir();
    let lib = dir.join(format!("zc_{key}{}", std::env::consts::DLL_SUFFIX));
    if !lib.exists() {
        std::fs::create_dir_all(&dir).map_err(|e| {
            Error::numeric(format!("cannot create the native cache {}: {e}", dir.display()))
        })?;
        let tag = format!("{key}_{}", std::process::id());
        let src = dir.join(format!("zc_{tag}.rs"));
        let tmp = dir.join(format!("zc_{tag}{}", std::env::consts::DLL_SUFFIX));
        std::fs::write(&src, source)
            .map_err(|e| Error::numeric(format!("cannot write {}: {e}", src.display())))?;
        let out = Command::new(rustc())
            .args(RUSTC_FLAGS)
            .args(["--cap-lints", "allow", "-o"])
            .arg(&tmp)
            .arg(&src)
            .output()
            .map_err(|e| Error::numeric(format!("cannot run rustc: {e}")))?;
        let _ = std::fs::remove_file(&src);
        if !out.status.success() {
            let _ = std::fs::remove_file(&tmp);
            return Err(Error::numeric(format!(
                "rustc failed on the emitted step: {}",
                String::from_utf8_lossy(&out.stderr).lines().take(6).collect::<Vec<_>>().join("; ")
            )));
        }
        // Another process may have won the race: either file is the same.
        std::fs::rename(&tmp, &lib)
            .map_err(|e| Error::numeric(format!("cannot place {}: {e}", lib.display())))?;
        prune(&dir, &lib);
    }
    // SAFETY: the library is our own generated source, compiled above (or
    // by an earlier run from the same source and compiler); loading it runs
    // no initialisers of its own.
    let loaded = unsafe { libloading::Library::new(&lib) }
        .map_err(|e| Error::numeric(format!("cannot load {}: {e}", lib.display())))?;
    Ok(Arc::new(loaded))
}

/// Most libraries kept in the cache; the least recently written go first.
const CACHE_KEEP: usize = 64;

/// Removes the oldest libraries past [`CACHE_KEEP`] (never `keep`).
fn prune(dir: &Path, keep: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    let mut libs: Vec<(std::time::SystemTime, PathBuf)> = entries
        .flatten()
        .map(|e| e.path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("zc_") && n.ends_with(std::env::consts::DLL_SUFFIX))
        })
        .filter_map(|p| Some((p.metadata().ok()?.modified().ok()?, p)))
        .collect();
    if libs.len() <= CACHE_KEEP {
        return;
    }
    libs.sort();
    for (_, p) in libs.iter().take(libs.len() - CACHE_KEEP) {
        if p != keep {
            let _ = std::fs::remove_file(p);
        }
    }
}

/// Steps compiled in this process, by their source.
fn loaded() -> &'static Mutex<HashMap<String, NativeStep>> {
    static L: OnceLock<Mutex<HashMap<String, NativeStep>>> = OnceLock::new();
    L.get_or_init(Default::default)
}

/// A key for a step: its source without the id.
fn key_of(method: &Method, params: &Params) -> Result<(String, Unit), Error> {
    let u = unit(method, params, 0)?;
    Ok((u.source.clone(), u))
}

/// Compiles the steps of every `(method, params)` not yet loaded in this
/// process, in one rustc call.
pub(crate) fn prepare(steps: &[(&Method, &Params)]) -> Result<(), Error> {
    let mut todo: Vec<(String, &Method, &Params)> = Vec::new();
    {
        let map = loaded().lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        for &(m, p) in steps {
            let (k, _) = key_of(m, p)?;
            if !map.contains_key(&k) && !todo.iter().any(|t| t.0 == k) {
                todo.push((k, m, p));
            }
        }
    }
    if todo.is_empty() {
        return Ok(());
    }
    // After one failed build (no writable cache, a broken toolchain) every
    // later step falls back at once instead of calling rustc again.
    static FAILED: OnceLock<String> = OnceLock::new();
    if let Some(why) = FAILED.get() {
        return Err(Error::numeric(why.clone()));
    }
    let units: Vec<Unit> =
        todo.iter().enumerate().map(|(i, t)| unit(t.1, t.2, i)).collect::<Result<_, _>>()?;
    let source: String = units.iter().map(|u| u.source.as_str()).collect();
    let lib = build(&source).inspect_err(|e| {
        let _ = FAILED.set(e.to_string());
    })?;
    let mut map = loaded().lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    for (i, (u, t)) in units.into_iter().zip(todo).enumerate() {
        // SAFETY: the symbols were generated with exactly these signatures.
        let (single, batch) = unsafe {
            let single: libloading::Symbol<SingleFn> = lib
                .get(format!("zc_single_{i}").as_bytes())
                .map_err(|e| Error::numeric(format!("native step: {e}")))?;
            let batch: libloading::Symbol<BatchFn> = lib
                .get(format!("zc_batch_{i}").as_bytes())
                .map_err(|e| Error::numeric(format!("native step: {e}")))?;
            (*single, *batch)
        };
        map.insert(
            t.0,
            NativeStep { lib: lib.clone(), single, batch, slots: u.slots, args: u.args },
        );
    }
    Ok(())
}

/// The native step of `method` at `params` (compiled now unless
/// `prepare` did it), with `params`' values as its arguments.
pub fn native_step(method: &Method, params: &Params) -> Result<NativeStep, Error> {
    let (k, u) = key_of(method, params)?;
    if let Some(s) = loaded().lock().unwrap_or_else(std::sync::PoisonError::into_inner).get(&k) {
        return Ok(NativeStep { args: u.args, ..s.clone() });
    }
    prepare(&[(method, params)])?;
    let map = loaded().lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let s = map.get(&k).ok_or_else(|| Error::numeric("native step not loaded".to_owned()))?;
    Ok(NativeStep { args: u.args, ..s.clone() })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bit for bit the interpreter, on one state and on a batch, for every
    /// built-in (implicit ones folded), at two values of Φ (and D).
    #[test]
    fn native_steps_are_the_interpreter_bit_for_bit() {
        let names: Vec<&str> = poly::advanced::builtins::builtin_names().collect();
        let cases: Vec<(Method, Params)> = names
            .iter()
            .flat_map(|n| {
                let m = poly::builtin(n).unwrap();
                [0.3, 0.017]
                    .into_iter()
                    .map(|phi| {
                        let mut p = Params::phi(phi);
                        for s in m.params() {
                            if s.name() != "Phi" {
                                p.set(s.name(), 0.125);
                            }
                        }
                        (m.clone(), p)
                    })
                    .collect::<Vec<_>>()
            })
            .collect();
        let refs: Vec<(&Method, &Params)> = cases.iter().map(|(m, p)| (m, p)).collect();
        if prepare(&refs).is_err() && rustc_version().is_none() {
            eprintln!("no rustc: the native step is not tested");
            return;
        }
        for (m, p) in &cases {
            let step = Step::compile(m, p).unwrap();
            let native = native_step(m, p).unwrap();
            let start: Vec<f64> = (0..step.order()).map(|i| 1.0 / (i as f64 + 1.5)).collect();
            let mut want = step.state(&start);
            step.advance(&mut want, 257);
            let mut got = step.state(&start).slots().to_vec();
            native.advance(&mut got, 257);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&got), bits(want.slots()), "{} {p}", m.name());
            // A batch of 5 states, each a scaled start.
            let lanes = 5;
            let n = native.slots();
            let mut soa = vec![0.0; n * lanes];
            for i in 0..lanes {
                for k in 0..n {
                    soa[k * lanes + i] = step.state(&start).slots()[k] * (i as f64 + 1.0);
                }
            }
            native.advance_batch(&mut soa, lanes, 33);
            for i in 0..lanes {
                let scaled: Vec<f64> = start.iter().map(|x| x * (i as f64 + 1.0)).collect();
                let mut s = step.state(&scaled);
                let slots0: Vec<f64> =
                    step.state(&start).slots().iter().map(|x| x * (i as f64 + 1.0)).collect();
                s.slots_mut().copy_from_slice(&slots0);
                step.advance(&mut s, 33);
                let lane: Vec<f64> = (0..n).map(|k| soa[k * lanes + i]).collect();
                assert_eq!(bits(&lane), bits(s.slots()), "{} {p} lane {i}", m.name());
            }
        }
    }
}
