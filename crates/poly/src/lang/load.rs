//! Reading a method: `.zm` text (or bytes) through the syntax and the
//! lowering to a checked [`Method`], refusing an implicit system that is
//! singular for every Φ, on the equation that makes it singular.

use crate::error::{Error, ErrorKind, Span};
use crate::lang::lower::lower;
use crate::lang::method::Method;
use crate::lang::system::{determinant, first_dependent_row, system};
use crate::{Poly, PolyMatrix};

impl Method {
    /// Parses and lowers a `.zm` program. `file` names the source in errors.
    ///
    /// ```
    /// let m = poly::Method::parse("fe.zm", "method fe\nstate v y\nv = v - Phi*y\ny = y + Phi*v\n")?;
    /// assert_eq!(m.state(), ["v", "y"]);
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn parse(file: &str, src: &str) -> Result<Method, Error> {
        // A byte-order mark some editors put first is not part of the text.
        let src = src.strip_prefix('\u{FEFF}').unwrap_or(src);
        read(src).map_err(|e| e.located(file, src))
    }

    /// [`Method::parse`] on raw bytes: bytes that are not UTF-8 are an
    /// [`ErrorKind::Encoding`](crate::ErrorKind::Encoding) error located at
    /// the first bad byte's line and column.
    pub fn parse_bytes(file: &str, bytes: &[u8]) -> Result<Method, Error> {
        match std::str::from_utf8(bytes) {
            Ok(src) => Method::parse(file, src),
            Err(e) => Err(Error::not_utf8(file, bytes, e)),
        }
    }
}

/// Lowers `src` and checks its implicit system.
fn read(src: &str) -> Result<Method, Error> {
    let m = lower(src)?;
    if m.is_implicit() {
        let a = system(&m).a;
        if determinant(&m, &a).is_zero() {
            return Err(singular_error(&m, &a, src));
        }
    }
    Ok(m)
}

/// The most earlier lines a message lists.
const LINES_LISTED: usize = 8;

/// The error for an implicit system A u = E s singular for every Φ,
/// located on the first equation (in file order) whose row of A depends on
/// the rows of the equations above it.
fn singular_error(m: &Method, a: &PolyMatrix, src: &str) -> Error {
    let mut in_file_order: Vec<_> = m.equations().iter().collect();
    in_file_order.sort_by_key(|e| e.line);
    let rows: Vec<Vec<Poly>> = in_file_order.iter().map(|e| a.row(e.unknown).to_vec()).collect();
    let k = first_dependent_row(m, &rows).unwrap_or(rows.len() - 1);
    let eq = in_file_order[k];
    let why = if rows[k].iter().all(Poly::is_zero) {
        "this equation determines no unknown (its row of the system is 0)".to_owned()
    } else {
        let mut lines: Vec<String> =
            in_file_order[..k].iter().take(LINES_LISTED).map(|e| e.line.to_string()).collect();
        if k > LINES_LISTED {
            lines.push("...".into());
        }
        format!(
            "this equation is a combination of the equations above it (line{} {})",
            if k == 1 { "" } else { "s" },
            lines.join(", ")
        )
    };
    // The caret goes under the equation's first character.
    let text = src.lines().nth(eq.line as usize - 1).unwrap_or("");
    let col = text.chars().take_while(|c| c.is_whitespace()).count() as u32 + 1;
    let names: Vec<&str> = m.unknowns().iter().map(|u| u.name.as_str()).collect();
    Error::new(
        ErrorKind::Singular,
        Span { line: eq.line, col, len: eq.text.chars().count().max(1) as u32 },
        format!("the implicit system in {} is singular for every Phi: its determinant det(I - d(right-hand sides)/d(unknowns)) is 0, and {why}; expected equations that determine every unknown", names.join(", ")),
    )
}
