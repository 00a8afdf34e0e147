//! Reading a method: `.zm` text (or bytes) through the syntax and the
//! lowering to a checked [`Method`], refusing an implicit system that is
//! singular for every Φ.

use crate::error::Error;
use crate::lang::method::Method;
use crate::lang::system::system_determinant;

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
    let m = Method::lower(src)?;
    if !m.unknowns().is_empty() && system_determinant(&m).is_zero() {
        return Err(m.singular_error());
    }
    Ok(m)
}
