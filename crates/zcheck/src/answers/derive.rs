//! `zcheck derive`: a method's derivation as text, JSON or LaTeX.

use poly::{Derivation, Poly};
use serde_json::json;

/// The JSON document of a derivation (`routes_agree` is true: [`poly::derive`]
/// refuses to return a derivation whose routes disagree).
pub(crate) fn to_json(d: &Derivation) -> serde_json::Value {
    let m = &d.method();
    let rows = |mat: &poly::PolyMatrix, f: &dyn Fn(&Poly) -> String| -> Vec<Vec<String>> {
        (0..mat.rows()).map(|i| mat.row(i).iter().map(f).collect()).collect()
    };
    let reduced = d.z_matrix_reduced();
    let mut v = json!({
        "method": m.name(),
        "state": m.state(),
        "params": m.params().iter().map(|p| p.name()).collect::<Vec<_>>(),
        "state_size": m.state_size(),
        "slots": m.slots().iter().map(|&(v, l)| m.operand_name(poly::advanced::Operand::Start { var: v, lag: l })).collect::<Vec<_>>(),
        "program": m.to_string(),
        "z_matrix": rows(&reduced.matrix, &Derivation::z_entry_string),
        "z_matrix_labels": reduced.labels,
        "transition_matrix": rows(d.transition_matrix(), &|p| p.to_string()),
        "charpoly": d.charpoly().to_string(),
        "charpoly_coeffs": d.coeffs().iter().map(ToString::to_string).collect::<Vec<_>>(),
        "routes_agree": true,
        "gauss_seidel_reads": m.gauss_seidel_reads().iter().map(|r| json!({
            "line": r.line, "col": r.col, "name": r.name, "updated_on": r.updated_on,
        })).collect::<Vec<_>>(),
    });
    if m.is_implicit() {
        v["unknowns"] = json!(m.unknowns().iter().map(|u| u.name.clone()).collect::<Vec<_>>());
        v["p_denominator"] = json!(d.p_denominator().to_string());
    }
    if let Some((p, q)) = d.p_q() {
        v["p"] = json!(p.to_string());
        v["q"] = json!(q.to_string());
    }
    v
}

/// The human-readable derivation.
pub(crate) fn text(d: &Derivation, full: bool) -> String {
    use std::fmt::Write;
    let m = &d.method();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "method {}   state ({})   state size {}",
        m.name(),
        m.state().join(", "),
        m.state_size()
    );
    let _ = writeln!(s, "\nlowered step (%k = value of assignment k; bare names = start of step):");
    for line in m.to_string().lines().skip(3) {
        let _ = writeln!(s, "  {line}");
    }
    let reduced = d.z_matrix_reduced();
    let _ = writeln!(
        s,
        "\nM(z) on ({}), the temporaries eliminated (det M(z) is unchanged):",
        reduced.labels.join(", ")
    );
    for i in 0..reduced.matrix.rows() {
        let row: Vec<String> =
            reduced.matrix.row(i).iter().map(Derivation::z_entry_string).collect();
        let _ = writeln!(s, "  [{}]", row.join(", "));
    }
    if full {
        let _ = writeln!(s, "\nM(z), one equation per assignment:");
        for row in full_rows(d, &Derivation::z_entry_string) {
            let _ = writeln!(s, "  [{}]", row.join(", "));
        }
    }
    let slots: Vec<String> = m
        .slots()
        .iter()
        .map(|&(v, l)| m.operand_name(poly::advanced::Operand::Start { var: v, lag: l }))
        .collect();
    if d.p_denominator().is_one() {
        let _ = writeln!(s, "\nP, on ({}):", slots.join(", "));
    } else {
        let _ = writeln!(
            s,
            "\nP, on ({}), as d*P with d = det A = {} (the step solves A u = E s):",
            slots.join(", "),
            d.p_denominator()
        );
    }
    for i in 0..d.transition_matrix().rows() {
        let row: Vec<String> =
            d.transition_matrix().row(i).iter().map(ToString::to_string).collect();
        let _ = writeln!(s, "  [{}]", row.join(", "));
    }
    let _ = writeln!(s, "\nchi(z) = {}", d.charpoly());
    if let Some((p, q)) = d.p_q() {
        let _ = writeln!(s, "       = z^2 - 2*p*z + q   with p = {p},  q = {q}");
    }
    if d.method().is_implicit() {
        let _ = writeln!(s, "leading coefficient in z: det A = {}", d.p_denominator());
        let _ = writeln!(s, "routes agree: z^N det M(1/z) = det A * det(zI - P)");
    } else {
        let _ = writeln!(s, "routes agree: z^N det M(1/z) = det(zI - P)");
    }
    s += &gauss_seidel_text(m);
    s
}

/// Every read of a state variable that an earlier line of the same step has
/// already updated: a transcription meant to use the old values sees at
/// once that it does not.
pub(crate) fn gauss_seidel_text(m: &poly::Method) -> String {
    let reads = m.gauss_seidel_reads();
    if reads.is_empty() {
        return "\nGauss-Seidel reads: none (every line reads the values the step started from)\n"
            .into();
    }
    let mut s = String::from(
        "\nGauss-Seidel reads (a value an earlier line of this step already updated):\n",
    );
    for r in reads {
        s += &format!(
            "  line {}:{}: `{}` reads the value assigned on line {}\n",
            r.line, r.col, r.name, r.updated_on
        );
    }
    s
}

/// M(z) with one row per assignment, as strings.
pub(crate) fn full_rows(d: &Derivation, f: &dyn Fn(&Poly) -> String) -> Vec<Vec<String>> {
    (0..d.z_matrix().rows()).map(|i| d.z_matrix().row(i).iter().map(f).collect()).collect()
}

/// LaTeX source of the derivation.
pub(crate) fn latex(d: &Derivation, full: bool) -> String {
    use std::fmt::Write;
    let mat = |m: &poly::PolyMatrix, f: &dyn Fn(&Poly) -> String| -> String {
        let rows: Vec<String> =
            (0..m.rows()).map(|i| m.row(i).iter().map(f).collect::<Vec<_>>().join(" & ")).collect();
        format!("\\begin{{pmatrix}} {} \\end{{pmatrix}}", rows.join(" \\\\ "))
    };
    let mut s = String::new();
    let _ = writeln!(s, "% {}", d.method().name());
    let reduced = d.z_matrix_reduced();
    let _ = writeln!(s, "% M(z) on ({})", reduced.labels.join(", "));
    let _ = writeln!(s, "M(z) = {}", mat(&reduced.matrix, &Derivation::z_entry_latex));
    if full {
        let _ = writeln!(s, "% M(z), one equation per assignment");
        let _ = writeln!(s, "M(z) = {}", mat(&d.z_matrix().to_dense(), &Derivation::z_entry_latex));
    }
    let _ = writeln!(s, "\\mathbf{{P}} = {}", mat(d.transition_matrix(), &|p| p.latex()));
    let _ = writeln!(s, "\\det(zI - \\mathbf{{P}}) = {} = 0", d.charpoly().latex());
    if let Some((p, q)) = d.p_q() {
        let _ = writeln!(s, "p = {}, \\quad q = {}", p.latex(), q.latex());
    }
    s
}
