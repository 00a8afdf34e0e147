//! The paper's methods as embedded `.zm` files.
//!
//! Each method of sections 5–11 is written twice, as Appendix B prints it:
//! the "Direct Integration" branch (`false_euler`) and the "Transition
//! matrix" branch (`false_euler_matrix`). Verlet has only one program in the
//! paper; `damped_euler_d` frees the damping ratio D.
//!
//! [`DAMPED_BUILTINS`] applies each direct method to the damped spring
//! v' = −2Dv − y, y' = v (in units of ω₀), with the damping ratio D a free
//! parameter (`param D`): the test equation of the two-parameter (Φ, D)
//! analysis. At D = 0 each has its undamped method's χ. They are built-ins
//! like the others ([`builtin`] finds them) but not among
//! [`builtin_names`], which stays the paper's own programs.

use crate::{Error, Method};

/// `(name, source)` for every built-in method, in the paper's order.
pub const BUILTINS: &[(&str, &str)] = &[
    ("standard_euler", include_str!("../../methods/standard_euler.zm")),
    ("standard_euler_matrix", include_str!("../../methods/standard_euler_matrix.zm")),
    ("damped_euler", include_str!("../../methods/damped_euler.zm")),
    ("damped_euler_matrix", include_str!("../../methods/damped_euler_matrix.zm")),
    ("damped_euler_d", include_str!("../../methods/damped_euler_d.zm")),
    ("false_euler", include_str!("../../methods/false_euler.zm")),
    ("false_euler_matrix", include_str!("../../methods/false_euler_matrix.zm")),
    ("verlet", include_str!("../../methods/verlet.zm")),
    ("standard_heun", include_str!("../../methods/standard_heun.zm")),
    ("standard_heun_matrix", include_str!("../../methods/standard_heun_matrix.zm")),
    ("false_heun", include_str!("../../methods/false_heun.zm")),
    ("false_heun_matrix", include_str!("../../methods/false_heun_matrix.zm")),
    ("semi_false_heun", include_str!("../../methods/semi_false_heun.zm")),
    ("semi_false_heun_matrix", include_str!("../../methods/semi_false_heun_matrix.zm")),
    // Implicit and algebraic methods (not from the paper).
    ("trapezoidal", include_str!("../../methods/trapezoidal.zm")),
    ("implicit_midpoint", include_str!("../../methods/implicit_midpoint.zm")),
    ("backward_euler", include_str!("../../methods/backward_euler.zm")),
    ("bdf2", include_str!("../../methods/bdf2.zm")),
    ("newmark_average", include_str!("../../methods/newmark_average.zm")),
    ("newmark_linear", include_str!("../../methods/newmark_linear.zm")),
    ("gauss_legendre_2", include_str!("../../methods/gauss_legendre_2.zm")),
    ("radau_iia_2", include_str!("../../methods/radau_iia_2.zm")),
    ("sdirk2", include_str!("../../methods/sdirk2.zm")),
    ("forest_ruth", include_str!("../../methods/forest_ruth.zm")),
    ("soft_spring", include_str!("../../methods/soft_spring.zm")),
];

/// `(name, source)` for the multistep and explicit Runge–Kutta methods that
/// analysts compare (not from the paper): Adams–Bashforth 2–8, leapfrog
/// (Nyström 2) and Nyström 3–6, written with history reads (`v@1`), and
/// RK3, RK4, Merson 4(3) and Ketcheson's SSPRK(10,4). Each file derives its
/// coefficients in its comments. [`builtin`] finds them; they are not among
/// [`builtin_names`] (the paper's and the implicit programs), so the
/// every-built-in sweeps stay the paper's; [`comparison_builtin_names`]
/// lists them.
pub const COMPARISON_BUILTINS: &[(&str, &str)] = &[
    ("ab2", include_str!("../../methods/ab2.zm")),
    ("ab3", include_str!("../../methods/ab3.zm")),
    ("ab4", include_str!("../../methods/ab4.zm")),
    ("ab5", include_str!("../../methods/ab5.zm")),
    ("ab6", include_str!("../../methods/ab6.zm")),
    ("ab7", include_str!("../../methods/ab7.zm")),
    ("ab8", include_str!("../../methods/ab8.zm")),
    ("leapfrog", include_str!("../../methods/leapfrog.zm")),
    ("nystrom3", include_str!("../../methods/nystrom3.zm")),
    ("nystrom4", include_str!("../../methods/nystrom4.zm")),
    ("nystrom5", include_str!("../../methods/nystrom5.zm")),
    ("nystrom6", include_str!("../../methods/nystrom6.zm")),
    ("rk3", include_str!("../../methods/rk3.zm")),
    ("rk4", include_str!("../../methods/rk4.zm")),
    ("merson", include_str!("../../methods/merson.zm")),
    ("ssprk104", include_str!("../../methods/ssprk104.zm")),
];

/// The implicit and algebraic built-ins, beyond the paper's methods.
pub const IMPLICIT_METHODS: [&str; 11] = [
    "trapezoidal",
    "implicit_midpoint",
    "backward_euler",
    "bdf2",
    "newmark_average",
    "newmark_linear",
    "gauss_legendre_2",
    "radau_iia_2",
    "sdirk2",
    "forest_ruth",
    "soft_spring",
];

/// `(name, source)` for every damped-spring built-in (`param D`), in the
/// paper's order; Standard Euler's is `damped_euler_d` in [`BUILTINS`].
pub const DAMPED_BUILTINS: &[(&str, &str)] = &[
    ("damped_euler_damped", include_str!("../../methods/damped_euler_damped.zm")),
    ("false_euler_damped", include_str!("../../methods/false_euler_damped.zm")),
    ("verlet_damped", include_str!("../../methods/verlet_damped.zm")),
    ("standard_heun_damped", include_str!("../../methods/standard_heun_damped.zm")),
    ("false_heun_damped", include_str!("../../methods/false_heun_damped.zm")),
    ("semi_false_heun_damped", include_str!("../../methods/semi_false_heun_damped.zm")),
];

/// The seven direct methods of sections 5–11 on the damped spring, in the
/// paper's order: `damped_euler_d` (Standard Euler) and [`DAMPED_BUILTINS`].
pub const DAMPED_METHODS: [&str; 7] = [
    "damped_euler_d",
    "damped_euler_damped",
    "false_euler_damped",
    "verlet_damped",
    "standard_heun_damped",
    "false_heun_damped",
    "semi_false_heun_damped",
];

/// The direct-integration built-ins of sections 5–11, one per method the
/// paper analyses, in the paper's order (no `_matrix` twins, no free `D`).
pub const PAPER_METHODS: [&str; 7] = [
    "standard_euler",
    "damped_euler",
    "false_euler",
    "verlet",
    "standard_heun",
    "false_heun",
    "semi_false_heun",
];

/// The names of the built-in methods, in the paper's order.
pub fn builtin_names() -> impl Iterator<Item = &'static str> {
    BUILTINS.iter().map(|(n, _)| *n)
}

/// The names of the damped-spring built-ins ([`DAMPED_BUILTINS`]).
pub fn damped_builtin_names() -> impl Iterator<Item = &'static str> {
    DAMPED_BUILTINS.iter().map(|(n, _)| *n)
}

/// The names of the multistep and Runge–Kutta built-ins
/// ([`COMPARISON_BUILTINS`]).
pub fn comparison_builtin_names() -> impl Iterator<Item = &'static str> {
    COMPARISON_BUILTINS.iter().map(|(n, _)| *n)
}

/// Every built-in: the paper's and implicit programs, the damped-spring
/// ones, then the multistep and Runge–Kutta ones.
pub fn all_builtin_names() -> impl Iterator<Item = &'static str> {
    builtin_names().chain(damped_builtin_names()).chain(comparison_builtin_names())
}

/// The built-ins transcribed from the paper (sections 5–11 and Appendix B):
/// every built-in but [`IMPLICIT_METHODS`], in the paper's order.
pub fn paper_builtin_names() -> impl Iterator<Item = &'static str> {
    builtin_names().filter(|n| !IMPLICIT_METHODS.contains(n))
}

/// The source text of a built-in method (any of the tables).
pub fn builtin_source(name: &str) -> Option<&'static str> {
    BUILTINS
        .iter()
        .chain(DAMPED_BUILTINS)
        .chain(COMPARISON_BUILTINS)
        .find(|(n, _)| *n == name)
        .map(|(_, s)| *s)
}

/// Parses a built-in method; `None` when no built-in has that name.
pub fn builtin(name: &str) -> Result<Method, Error> {
    match builtin_source(name) {
        Some(src) => Method::parse(&format!("<builtin>/{name}.zm"), src),
        None => Err(Error::unknown_builtin(name, &all_builtin_names().collect::<Vec<_>>())),
    }
}

impl Method {
    /// The built-in method `name` (see `zcheck methods`): the same as
    /// [`builtin`](crate::builtin).
    pub fn builtin(name: &str) -> Result<Method, Error> {
        builtin(name)
    }
}

/// For a `_matrix` built-in, the direct-integration built-in it transcribes.
pub fn direct_twin(name: &str) -> Option<&'static str> {
    let base = name.strip_suffix("_matrix")?;
    builtin_names().find(|n| *n == base)
}
