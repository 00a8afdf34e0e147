//! Section 4, z-Transformation: the transition matrix, the characteristic
//! equation, the taxonomy of roots, samples per period and the p, q form.

use poly::{Poly, RootClass, Sym};

use super::common::*;
use super::ranges;
use crate::load::{builtin_derivation, try_builtin_derivation};
use crate::paper::claim::Claim;
use crate::paper::finding::{Finding, Scope};

pub(crate) fn claims() -> Vec<Claim> {
    let mut s = Section::new("4", "sec04");
    euler_transition(&mut s);
    delay_operator(&mut s);
    characteristic_equation(&mut s);
    eigenvalues_decide(&mut s);
    taxonomy_real(&mut s);
    taxonomy_complex(&mut s);
    psi_arctan(&mut s);
    samples_per_period(&mut s);
    double_roots(&mut s);
    approach_minus_one(&mut s);
    p_q_form(&mut s);
    method_identities(&mut s);
    s.finish()
}

fn euler_transition(s: &mut Section) {
    let plain = scheme_defect(
        &builtin_derivation("standard_euler"),
        &ode_matrix(OSCILLATOR),
        Scheme::Euler,
    );
    let damped = scheme_defect(
        &builtin_derivation("damped_euler_d"),
        &ode_matrix([["-2*D", "-1"], ["1", "0"]]),
        Scheme::Euler,
    );
    s.push(
        "euler_transition",
        "y_i = (I + TA) y_i z⁻¹ + TB x_i z⁻¹;  y = P y z⁻¹ + Q x z⁻¹ (P is the transition matrix)",
        format!(
            "standard_euler: P = {}; damped_euler_d: P = {}",
            matrix_text(builtin_derivation("standard_euler").transition_matrix()),
            matrix_text(builtin_derivation("damped_euler_d").transition_matrix())
        ),
        Finding::all([
            ("standard_euler: P − (I + ΦA) = 0", is_zero_matrix(&plain)),
            ("damped_euler_d: P − (I + ΦA) = 0", is_zero_matrix(&damped)),
        ]),
        "P = I + ΦA exactly for the oscillator A = [[0, −1], [1, 0]] (section 5) and for the damped \
         oscillator A = [[−2D, −1], [1, 0]] (section 6), with Φ = ω0·T",
    );
}

fn characteristic_equation(s: &mut Section) {
    // derive() fails when the z-domain determinant and det(zI − P) differ.
    let agree: Vec<(&str, bool)> = poly::advanced::builtins::paper_builtin_names()
        .map(|name| (name, try_builtin_derivation(name).is_ok()))
        .collect();
    let total = agree.len();
    let n_agree = agree.iter().filter(|(_, ok)| *ok).count();
    s.push(
        "characteristic_equation",
        "(Iz − P) y = 0;  det(Iz − P) = 0, an n-th order polynomial in z",
        format!("χ(z) = det(zI − P) for {n_agree} of {total} built-in methods"),
        Finding::all(agree),
        "for every built-in, the determinant of the z-domain equations of the program (z^N·det M(1/z)) \
         equals det(zI − P) of the transition matrix found by symbolic execution, exactly",
    );
}

/// Repeated roots on the unit circle: the same eigenvalues, different fates.
fn eigenvalues_decide(s: &mut Section) {
    let one = poly::q(1, 1);
    let identity = vec![vec![one.clone(), poly::q(0, 1)], vec![poly::q(0, 1), one.clone()]];
    let jordan = vec![vec![one.clone(), one.clone()], vec![poly::q(0, 1), one.clone()]];
    let x0 = [poly::q(0, 1), one.clone()];
    let n = 20;
    let still = iterate_exact(&identity, &x0, n);
    let grows = iterate_exact(&jordan, &[one.clone(), one.clone()], n);
    s.push(
        "eigenvalues_decide",
        "The stability of all solutions of the sample sequence ... is entirely described by the location of \
         the eigenvalues in the complex plane. Major result: the stability of a sample sequence for a \
         homogeneous test case can be predicted by the eigenvalues of the transition matrix.",
        "true when the roots on the unit circle are simple; a repeated root on the circle needs the Jordan \
         structure of P as well",
        Finding::scoped([
            (
                "defective double root 1 (a Jordan block, as the paper's methods have at their limits): \
                 grows, as the double-root rows predict from the location",
                !stays(&grows),
                Scope::Stated,
            ),
            (
                "diagonalisable double root 1 (P = I, the same location): grows as predicted",
                !stays(&still),
                scalar_p_scope(),
            ),
        ]),
        format!(
            "P = I and P = [[1, 1], [0, 1]] both have z1 = z2 = 1; exactly, after {n} steps the first keeps \
             (v, y) = ({}, {}) while the second has grown to ({}, {}) (linear growth). Section 4 itself \
             notes the double root at −1 is unstable; all roots strictly inside or simple on the circle \
             decide stability by location alone",
            still[n][0], still[n][1], grows[n][0], grows[n][1]
        ),
    );
}

/// Why the taxonomy's rows do not reach a root z1 ≤ 0.
const ROWS_ARE_POSITIVE: &str =
    "the three rows state 0 < z1 only; a root z1 ≤ 0 is covered by the \
                                 heading \"single real eigenvalues\", under no row";

/// The paper's methods whose P is a multiple of I at some Φ > 0: there the
/// off-diagonal entries and the difference of the diagonal ones vanish
/// together. An entry that holds another parameter (D) is left out, which
/// can only add candidate points.
fn scalar_p_methods() -> Vec<String> {
    let phi = Sym::phi();
    poly::advanced::builtins::paper_builtin_names()
        .filter(|name| {
            let p = builtin_derivation(name).transition_matrix().clone();
            let n = p.rows();
            let mut common = poly::UPoly::zero();
            for i in 0..n {
                for j in 0..n {
                    let e = if i == j { &p[(i, i)] - &p[(0, 0)] } else { p[(i, j)].clone() };
                    if let Some(u) = e.to_upoly(phi) {
                        common = common.gcd(&u);
                    }
                }
            }
            common.is_zero() || !ranges::positive_roots(&Poly::from_upoly(phi, &common)).is_empty()
        })
        .map(str::to_owned)
        .collect()
}

/// The scope of a diagonalisable repeated root on the circle (P = ±I):
/// stated if one of the paper's methods has such a P at some Φ > 0,
/// otherwise only the rows' wording covers it.
fn scalar_p_scope() -> Scope {
    let methods = scalar_p_methods();
    if methods.is_empty() {
        Scope::wording(
            "no method of the paper has P = ±I at a Φ > 0 (computed), so their repeated roots on the \
             circle are Jordan blocks; P = ±I fits only the words",
        )
    } else {
        Scope::Stated
    }
}

/// Whether an exact run never leaves the size of its start (largest
/// absolute entry).
fn stays(run: &[Vec<poly::Q>]) -> bool {
    use num_traits::Signed;
    let size = |x: &[poly::Q]| x.iter().map(|e| e.abs()).max().expect("non-empty state");
    let start = size(&run[0]);
    run.iter().all(|x| size(x) <= start)
}

/// The samples c·z^i of a single real root, exactly: (monotonic, decaying,
/// constant, growing) over `n` steps from c = 1.
fn real_root_samples(z: &poly::Q, n: usize) -> (bool, bool, bool, bool) {
    let xs = iterate_exact(&[vec![z.clone()]], &[poly::q(1, 1)], n);
    let x: Vec<&poly::Q> = xs.iter().map(|v| &v[0]).collect();
    let zero = poly::q(0, 1);
    let monotonic = x.iter().all(|v| **v > zero);
    let decaying = x.windows(2).all(|w| w[1] < w[0]);
    let constant = x.windows(2).all(|w| w[1] == w[0]);
    let growing = x.windows(2).all(|w| w[1] > w[0]);
    (monotonic, decaying, constant, growing)
}

fn taxonomy_real(s: &mut Section) {
    let paper_classes =
        [RootClass::MonotonicStable, RootClass::Constant, RootClass::MonotonicUnstable];
    let missing = ranges::classes_outside(&paper_classes_with_pairs(&paper_classes));
    let n = 12;
    let half = real_root_samples(&poly::q(1, 2), n);
    let one = real_root_samples(&poly::q(1, 1), n);
    let two = real_root_samples(&poly::q(2, 1), n);
    let minus_half = real_root_samples(&poly::q(-1, 2), n);
    s.push(
        "taxonomy_real",
        "Single real eigenvalues z1 = a1: 0 < z1 < 1 monotonic stable g(t); z1 = 1 constant g(t); 1 < z1 \
         monotonic unstable g(t)",
        "the three rows are right; the taxonomy omits z1 ≤ 0: z1 = 0 (deadbeat), −1 < z1 < 0 (alternating, \
         decaying), z1 = −1 (alternating, Ψ = π), z1 < −1 (alternating, growing)",
        Finding::scoped([
            ("z1 = 1/2: monotonic and decaying", half.0 && half.1, Scope::Stated),
            ("z1 = 1: constant", one.0 && one.2, Scope::Stated),
            ("z1 = 2: monotonic and growing", two.0 && two.3, Scope::Stated),
            (
                "z1 = −1/2 falls in one of the three rows (a monotonic sequence)",
                minus_half.0,
                Scope::wording(ROWS_ARE_POSITIVE),
            ),
            (
                "every real root the paper's methods reach is in one of the rows",
                missing == "none",
                Scope::wording(ROWS_ARE_POSITIVE),
            ),
        ]),
        format!(
            "a root z1 gives samples c·z1^i; for z1 < 0 they flip sign every step. Classes the paper's \
             methods reach (exact class maps over Φ > 0) that the taxonomy lacks: {missing}"
        ),
    );
}

fn paper_classes_with_pairs(real: &[RootClass]) -> Vec<RootClass> {
    let mut v = real.to_vec();
    v.extend([
        RootClass::Harmonic,
        RootClass::DampedOscillation,
        RootClass::UnstableOscillation,
        RootClass::DoubleRootOnCircle,
    ]);
    v
}

fn taxonomy_complex(s: &mut Section) {
    // r² = z·z̄ = q for the pair, and |z^i| = r^i.
    let a = Poly::var("a");
    let b = Poly::var("b");
    let re = &(&a * &a) - &(&b * &b);
    let im = (&a * &b).scale(&poly::q(2, 1));
    let modulus_sq_of_square = &(&re * &re) + &(&im * &im);
    let r2 = &(&a * &a) + &(&b * &b);
    let squared = &r2 * &r2;
    s.push(
        "taxonomy_complex",
        "Single pairs of conjugate complex eigenvalues z1/2 = a1 ± j b1: r1 = (a1² + b1²)^0.5; r1 = 1 \
         harmonic g(t); r1 < 1 damped oscillation g(t); r1 > 1 unstable oscillation g(t)",
        "samples are c·r1^i·cos(iΨ1 + φ): bounded and non-decaying iff r1 = 1",
        Finding::same(&modulus_sq_of_square, &squared),
        "|z^i| = |z|^i (checked exactly for i = 2: |(a + jb)²|² = (a² + b²)²), so the envelope is r1^i; \
         the class maps of sections 5–11 use exactly this rule",
    );
}

fn psi_arctan(s: &mut Section) {
    // Case 3 of the figure: Ψ = 150°, a1 = cos 150° < 0.
    let psi = 150f64.to_radians();
    let (a1, b1) = (psi.cos(), psi.sin());
    let arctan = (b1 / a1).atan().to_degrees();
    let atan2 = b1.atan2(a1).to_degrees();
    s.push(
        "psi_arctan",
        "Ψ1 = arctan(b1/a1) = Ω0·T, angle increment, 0 ... π",
        "true read as the quadrant-aware angle Ψ1 = atan2(b1, a1) ∈ (0, π), which the printed range \
         0 … π implies; the plain arctan(b1/a1) ∈ (−π/2, π/2) is wrong whenever a1 < 0",
        Finding::scoped([
            (
                format!("read as atan2(b1, a1), the angle in 0 … π: case 3 gives {}°", fixed(atan2, 1)),
                (atan2 - 150.0).abs() < 1e-9,
                Scope::Stated,
            ),
            (
                format!("read as the plain arctan(b1/a1): case 3 gives {}°", fixed(arctan, 1)),
                (arctan - 150.0).abs() < 1e-9,
                Scope::wording(
                    "the printed range 0 … π states the quadrant-aware angle; only the formula arctan(b1/a1), \
                     read literally, gives another",
                ),
            ),
        ]),
        format!(
            "the paper's own harmonic case 3 (Ψ1 = 150°, 2.4 samples) has a1 = cos 150° < 0: \
             arctan(b1/a1) = {}° but the angle is atan2(b1, a1) = {}°. The methods reach a1 = p < 0 with \
             complex roots: {}",
            fixed(arctan, 1),
            fixed(atan2, 1),
            ranges::negative_real_part_text()
        ),
    );
}

fn samples_per_period(s: &mut Section) {
    let rows = [(30, "12"), (90, "4"), (150, "2.4")];
    let mut derived = Vec::new();
    let mut computed = Vec::new();
    for (angle, _) in rows {
        let n = poly::q(360, angle);
        let text = q_decimal(&n, 1);
        computed.push(text.trim_end_matches('0').trim_end_matches('.').to_owned());
        let shown =
            if n.is_integer() { n.to_string() } else { format!("{n} = {}", q_decimal(&n, 1)) };
        derived.push(format!("360/{angle} = {shown} samples"));
    }
    s.push(
        "samples_per_period",
        "harmonic cases 1, 2, 3: 360/30 = 12 samples; 360/90 = 4 samples; 360/150 = 2.4 samples",
        derived.join("; "),
        Finding::same(rows.map(|(_, printed)| printed).join(", "), computed.join(", ")),
        "exact rational arithmetic; samples per period of g(t) = 2π/Ψ1 = 360°/Ψ1",
    );
}

fn double_roots(s: &mut Section) {
    let one = poly::q(1, 1);
    let zero = poly::q(0, 1);
    let minus = poly::q(-1, 1);
    let n = 20;
    let start = [one.clone(), one.clone()];
    let identity = iterate_exact(
        &[vec![one.clone(), zero.clone()], vec![zero.clone(), one.clone()]],
        &start,
        n,
    );
    let jordan = iterate_exact(
        &[vec![one.clone(), one.clone()], vec![zero.clone(), one.clone()]],
        &start,
        n,
    );
    s.push(
        "double_root_plus_one",
        "z1 = z2 = 1: monotonic unstable g(t)",
        "monotonic unstable only when the double root is defective (a Jordan block); P = I gives a constant g(t)",
        Finding::scoped([
            ("defective double root 1 (Jordan block): grows", !stays(&jordan), Scope::Stated),
            ("diagonalisable double root 1 (P = I): grows", !stays(&identity), scalar_p_scope()),
        ]),
        format!(
            "exact iteration from (1, 1): P = [[1, 1], [0, 1]] reaches {} after {n} steps (linear growth), \
             P = I stays at {}",
            jordan[n][0], identity[n][0]
        ),
    );
    let neg_identity = iterate_exact(
        &[vec![minus.clone(), zero.clone()], vec![zero.clone(), minus.clone()]],
        &start,
        n + 1,
    );
    let fe = builtin_derivation("false_euler");
    let p2 = matrix_at(fe.transition_matrix(), &poly::q(2, 1));
    let fe_run = iterate_exact(&p2, &[zero.clone(), one.clone()], n);
    s.push(
        "double_root_minus_one",
        "z1 = z2 = −1: unstable oscillation g(t)",
        "an unstable oscillation only when the double root is defective; P = −I alternates with bounded amplitude",
        Finding::scoped([
            ("defective double root −1 (False Euler at Φ = 2): grows", !stays(&fe_run), Scope::Stated),
            ("diagonalisable double root −1 (P = −I): grows", !stays(&neg_identity), scalar_p_scope()),
        ]),
        format!(
            "P = −I from (1, 1) is at {} after {} steps; False Euler at Φ = 2 has P = {} ≠ −I and y goes \
             from 1 to {} in {n} steps (exact)",
            neg_identity[n + 1][0],
            n + 1,
            matrix_text(fe.transition_matrix()),
            fe_run[n][1]
        ),
    );
}

fn approach_minus_one(s: &mut Section) {
    let fe = builtin_derivation("false_euler");
    let two = poly::q(2, 1);
    let p2 = matrix_at(fe.transition_matrix(), &two);
    let run = iterate_exact(&p2, &[poly::q(0, 1), poly::q(1, 1)], 40);
    let samples: Vec<String> =
        [10, 20, 40].iter().map(|&k| format!("y_{k} = {}", run[k][1])).collect();
    let chi2 = fe.charpoly().subs(Sym::phi(), &Poly::int(2));
    let double_minus_one = chi2 == Poly::parse("(z + 1)^2").expect("literal");
    let not_minus_identity = p2[0][1] != poly::q(0, 1);
    s.push(
        "approach_minus_one",
        "If ... a single pair of complex eigenvalues with r1 = 1 approaches z1 = z2 = −1, then the result is not \
         a harmonic oscillation with Ψ1 = π but an instable oscillation",
        format!(
            "False Euler at Φ = 2: χ = {}, P = [[{}, {}], [{}, {}]] is a Jordan block; {}",
            chi2,
            p2[0][0],
            p2[0][1],
            p2[1][0],
            p2[1][1],
            samples.join(", ")
        ),
        Finding::all([
            ("χ = (z + 1)² at Φ = 2", double_minus_one),
            ("P ≠ −I, so the double root is defective", not_minus_identity),
            ("the exact samples grow", !stays(&run)),
        ]),
        "χ(z) = (z + 1)² at Φ = 2 and P ≠ −I, so P has a single eigenvector and the samples grow linearly \
         with alternating sign (exact iteration from v0 = 0, y0 = 1)",
    );
}

fn p_q_form(s: &mut Section) {
    let p = Poly::var("p");
    let q = Poly::var("q");
    let t = Poly::var("t");
    let chi = |x: &Poly| &(&(x * x) - &(&(&p * x) * &Poly::int(2))) + &q;
    // Real roots: z = p + t solves χ iff t² = p² − q.
    let real = chi(&(&p + &t)) - (&(&t * &t) - &(&(&p * &p) - &q));
    // Complex roots: z = p + j t, with (a + jb)² = a² − b² + 2jab.
    let re = &(&(&(&p * &p) - &(&t * &t)) - &(&(&p * &p) * &Poly::int(2))) + &q;
    let im = &(&(&p * &t) * &Poly::int(2)) - &(&(&p * &t) * &Poly::int(2));
    let complex = &re - &(&(&q - &(&p * &p)) - &(&t * &t));
    let r2 = &(&p * &p) + &(&q - &(&p * &p));
    s.push(
        "p_q_roots",
        "z² − 2pz + q = 0;  z1/2 = p ± (−q + p²)^0.5 real;  z1/2 = p ± j(q − p²)^0.5 conjugate pair",
        "z = p + t is a root iff t² = p² − q; z = p + jt is a root iff t² = q − p² (and the imaginary part \
         vanishes identically)",
        Finding::all([
            ("χ(p + t) − (t² − (p² − q)) = 0", real.is_zero()),
            ("Re χ(p + jt) − (q − p² − t²) = 0", complex.is_zero()),
            ("Im χ(p + jt) = 0", im.is_zero()),
        ]),
        "substitution into χ with symbolic p, q, t: χ(p + t) = t² − (p² − q) and χ(p + jt) = (q − p² − t²) + \
         j·0, exactly",
    );
    s.push(
        "r_squared_q",
        "r1² = p² + (q − p²) = q. Therefore we can test the harmonic case r1 = 1 for conjugate pairs simply by q = 1",
        format!("p² + (q − p²) = {r2}"),
        Finding::same(&r2, &q),
        "exact polynomial identity; for a conjugate pair z1·z2 = |z1|² = q (Vieta)",
    );
}

/// z⁻¹ = e^(−sT): the shift by one sample is the Laplace delay. For the
/// oscillator (s = ±jω0) the exact one-step map is e^(ΦA); its eigenvalues
/// must be z = e^(sT) = e^(±jΦ): trace 2 cos Φ and determinant 1. Checked
/// exactly on the power series through Φ^12.
fn delay_operator(s: &mut Section) {
    const ORDER: usize = 12;
    let phi = Poly::sym(Sym::phi());
    let phi_a = ode_matrix(OSCILLATOR).map(|e| e * &phi);
    let mut term = poly::PolyMatrix::identity(2);
    let mut flow = poly::PolyMatrix::identity(2);
    for k in 1..=ORDER {
        term = (&term * &phi_a).map(|e| e.scale(&poly::q(1, k as i64)));
        for i in 0..2 {
            for j in 0..2 {
                flow[(i, j)] = &flow[(i, j)] + &term[(i, j)];
            }
        }
    }
    let trace = truncate(&(&flow[(0, 0)] + &flow[(1, 1)]), ORDER + 1);
    let det =
        truncate(&(&(&flow[(0, 0)] * &flow[(1, 1)]) - &(&flow[(0, 1)] * &flow[(1, 0)])), ORDER + 1);
    // 2 cos Φ = Σ 2 (−1)^k Φ^(2k) / (2k)!.
    let mut cos2 = Poly::zero();
    let mut factorial = poly::q(1, 1);
    for k in 0..=ORDER {
        if k > 0 {
            factorial *= poly::q(k as i64, 1);
        }
        if k % 2 == 0 {
            let sign = if (k / 2) % 2 == 0 { 2 } else { -2 };
            let c = poly::q(sign, 1) / &factorial;
            cos2 += &(&Poly::constant(c) * &Poly::sym(Sym::phi()).pow(k as u32));
        }
    }
    s.push(
        "delay_operator",
        "z⁻¹ = e^(−sT): this is the delay operator in the Laplace transformation",
        format!(
            "the exact one-step map of the oscillator, e^(ΦA) through Φ^{ORDER}, has trace {} = 2·cos Φ and \
             determinant {}: its eigenvalues are z = e^(±jΦ) = e^(sT) at s = ±jω0, so one sample of delay \
             multiplies by e^(−sT)",
            trace, det
        ),
        Finding::all([
            (format!("trace e^(ΦA) = 2 cos Φ through Φ^{ORDER}"), trace == cos2),
            (format!("det e^(ΦA) = 1 through Φ^{ORDER}"), det.is_one()),
        ]),
        "exact power series of the matrix exponential (poly, rationals) against the cosine series; a sampled \
         e^(st) shifted by one sample is e^(st)·e^(−sT), and the eigenvalues z of a step relate to s by z = e^(sT)",
    );
}

/// The identities between methods the paper states or implies, decided
/// exactly over every pair of built-ins (`poly::advanced::equiv`), and those it does
/// not state.
fn method_identities(s: &mut Section) {
    use poly::advanced::equiv::{self, Relation};
    let names: Vec<&str> = poly::advanced::builtins::paper_builtin_names().collect();
    let mut found: Vec<(&str, &str, Relation)> = Vec::new();
    for (i, a) in names.iter().enumerate() {
        for b in &names[i + 1..] {
            let r = equiv::relate(&builtin_derivation(a), &builtin_derivation(b));
            if r.shares_charpoly() {
                found.push((a, b, r));
            }
        }
    }
    let relation = |a: &str, b: &str| {
        found
            .iter()
            .find(|(x, y, _)| (*x == a && *y == b) || (*x == b && *y == a))
            .map(|(_, _, r)| r.clone())
            .unwrap_or(Relation::Different)
    };
    // What the paper states: §8 Verlet has False Euler's χ; Appendix A
    // gives Damped Euler and False Euler one tan Ψ (one χ); Appendix B's two
    // branches of every method compute the same step.
    let mut stated: Vec<(String, bool)> = vec![
        (
            "§8: Verlet has False Euler's χ".to_owned(),
            relation("false_euler", "verlet").shares_charpoly(),
        ),
        (
            "Appendix A: Damped Euler and False Euler have one χ".to_owned(),
            relation("damped_euler", "false_euler").shares_charpoly(),
        ),
    ];
    for matrix in names.iter().filter(|n| poly::advanced::builtins::direct_twin(n).is_some()) {
        let direct = poly::advanced::builtins::direct_twin(matrix).expect("filtered");
        stated.push((
            format!("Appendix B: {direct} and {matrix} have equal P"),
            relation(direct, matrix) == Relation::Equal,
        ));
    }
    let is_stated = |a: &str, b: &str| {
        let pair = |x: &str, y: &str| (a == x && b == y) || (a == y && b == x);
        pair("false_euler", "verlet")
            || pair("damped_euler", "false_euler")
            || poly::advanced::builtins::direct_twin(a) == Some(b)
            || poly::advanced::builtins::direct_twin(b) == Some(a)
    };
    let describe = |r: &Relation| match r {
        Relation::Equal => "equal P".to_owned(),
        Relation::Permutation { perm } => format!("similar by the permutation {perm:?}"),
        Relation::Scaling { scale } => format!(
            "similar by the scaling {}",
            scale.iter().map(ToString::to_string).collect::<Vec<_>>().join(", ")
        ),
        Relation::PermutationAndScaling { perm, scale } => format!(
            "similar by the permutation {perm:?} and the scaling ({})",
            scale.iter().map(ToString::to_string).collect::<Vec<_>>().join(", ")
        ),
        Relation::ChangeOfVariables(_) => "similar by a change of variables T(Φ)".to_owned(),
        Relation::SameCharpoly => "the same χ only".to_owned(),
        Relation::Different => "nothing".to_owned(),
    };
    let twin = |n: &str| n.ends_with("_matrix");
    let stronger: Vec<String> = found
        .iter()
        .filter(|(a, b, r)| {
            !twin(a)
                && !twin(b)
                && is_stated(a, b)
                && !matches!(r, Relation::SameCharpoly | Relation::Equal)
        })
        .map(|(a, b, r)| {
            format!("{a} and {b}: {} (the paper says only that they share χ)", describe(r))
        })
        .collect();
    let unstated: Vec<String> = found
        .iter()
        .filter(|(a, b, _)| !twin(a) && !twin(b) && !is_stated(a, b))
        .map(|(a, b, r)| format!("{a} and {b}: {}", describe(r)))
        .collect();
    s.push(
        "method_identities",
        "This is the characteristic equation of False Euler - Verlet is the same (§8); Accurate solution for \
         Damped Euler and False Euler (Appendix A); { Direct Integration } and { Transition matrix } (Appendix B)",
        format!(
            "{} of {} pairs of built-ins share χ; stronger than the paper says: {}; not stated by the paper: {}",
            found.len(),
            names.len() * (names.len() - 1) / 2,
            if stronger.is_empty() { "none".to_owned() } else { stronger.join("; ") },
            if unstated.is_empty() { "none".to_owned() } else { unstated.join("; ") },
        ),
        Finding::all(stated),
        "Derivation::relate on every pair of built-ins: equal P, similar by a permutation and/or a constant \
         diagonal scaling (exact, every permutation tried), similar by a change of variables T(Φ) (T·P_a = P_b·T \
         multiplied out), or only the same χ; the _matrix twins are \
         left out of the lists (Appendix B makes them equal to their direct branches)",
    );
}
