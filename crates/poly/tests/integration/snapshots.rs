//! One snapshot per built-in: its source, the lowered step, M(z), P, χ(z)
//! and, for second-order methods, p and q of χ = z² − 2p·z + q. Each was
//! compared by hand with the equations the paper prints (sections 5–11 and
//! Appendix B); the differences are listed in the report of issue 2.

use poly::advanced::Operand;
use poly::Derivation;

/// The derivation of a built-in, as reviewed.
fn record(name: &str) -> String {
    let m = poly::builtin(name).unwrap_or_else(|e| panic!("{e}"));
    let d = poly::derive(&m).unwrap_or_else(|e| panic!("{e}"));
    let mut s = String::new();
    s += "source:\n";
    for line in poly::advanced::builtins::builtin_source(name).expect("built-in").lines() {
        s += &format!("  {line}\n");
    }
    s += "\nlowered step:\n";
    for line in m.to_string().lines() {
        s += &format!("  {line}\n");
    }
    s += "\nM(z) (one row per assignment, columns in the same order):\n";
    for i in 0..d.z_matrix().rows() {
        let row: Vec<String> = d.z_matrix().row(i).iter().map(Derivation::z_entry_string).collect();
        s += &format!("  [{}]\n", row.join(", "));
    }
    let slots: Vec<String> =
        m.slots().iter().map(|&(var, lag)| m.operand_name(Operand::Start { var, lag })).collect();
    if d.p_denominator().is_one() {
        s += &format!("\nP on ({}):\n", slots.join(", "));
    } else {
        s += &format!(
            "\nP on ({}), times its denominator d = det A = {}:\n",
            slots.join(", "),
            d.p_denominator()
        );
    }
    for i in 0..d.transition_matrix().rows() {
        let row: Vec<String> =
            d.transition_matrix().row(i).iter().map(ToString::to_string).collect();
        s += &format!("  [{}]\n", row.join(", "));
    }
    s += &format!("\nchi(z) = {}\n", d.charpoly());
    if let Some((p, q)) = d.p_q() {
        s += &format!("p = {p}\nq = {q}\n");
    }
    s
}

#[test]
fn builtin_derivations() {
    for name in poly::advanced::builtins::all_builtin_names() {
        let mut settings = crate::snapshot::in_dir("poly");
        settings.set_omit_expression(true);
        settings.bind(|| insta::assert_snapshot!(name, record(name)));
    }
}
