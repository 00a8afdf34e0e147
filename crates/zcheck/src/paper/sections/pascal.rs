//! The paper's Pascal listings (Appendices B–E), transcribed verbatim in
//! `paper/listings/*.pas`, and a small scanner over them: tokens without
//! comments, the comments, the declared names, and the names a listing
//! assigns or reads before it assigns them.
//!
//! This is not a Pascal compiler: it reads identifiers, `:=`, `;`,
//! comments `{ ... }` and strings `'...'`, which is all the checks need.

use std::collections::BTreeSet;

/// Appendix B, the seven methods, as printed.
pub(crate) const APPENDIX_B: &str = include_str!("../listings/appendix_b.pas");
/// Appendix C, three bodies by False Euler, as printed.
pub(crate) const APPENDIX_C: &str = include_str!("../listings/appendix_c.pas");
/// Appendix D, three bodies by Standard Euler with energy control.
pub(crate) const APPENDIX_D: &str = include_str!("../listings/appendix_d.pas");

/// One token of a listing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Token {
    /// An identifier, lower-cased (Pascal is case-insensitive).
    Ident(String),
    /// Anything else: a number, an operator, a string.
    Other(String),
}

/// The tokens of a listing, comments dropped.
pub(crate) fn tokens(src: &str) -> Vec<Token> {
    let chars: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c == '{' {
            while i < chars.len() && chars[i] != '}' {
                i += 1;
            }
            i += 1;
        } else if c == '\'' {
            let start = i;
            i += 1;
            while i < chars.len() && chars[i] != '\'' {
                i += 1;
            }
            i += 1;
            out.push(Token::Other(chars[start..i.min(chars.len())].iter().collect()));
        } else if c.is_ascii_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push(Token::Ident(chars[start..i].iter().collect::<String>().to_lowercase()));
        } else if c.is_ascii_digit() {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '.') {
                i += 1;
            }
            out.push(Token::Other(chars[start..i].iter().collect()));
        } else if c == ':' && chars.get(i + 1) == Some(&'=') {
            out.push(Token::Other(":=".to_owned()));
            i += 2;
        } else {
            out.push(Token::Other(c.to_string()));
            i += 1;
        }
    }
    out
}

/// The comments of a listing, trimmed, in order.
pub(crate) fn comments(src: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = src;
    while let Some(k) = rest.find('{') {
        let after = &rest[k + 1..];
        let end = after.find('}').unwrap_or(after.len());
        out.push(after[..end].trim().to_owned());
        rest = &after[(end + 1).min(after.len())..];
    }
    out
}

fn is(t: &Token, s: &str) -> bool {
    matches!(t, Token::Other(x) if x == s)
}

fn ident(t: &Token) -> Option<&str> {
    match t {
        Token::Ident(x) => Some(x),
        Token::Other(_) => None,
    }
}

/// The names a listing declares: its `Var` and `Const` sections and the
/// procedure's parameters.
pub(crate) fn declared(src: &str) -> BTreeSet<String> {
    let t = tokens(src);
    let mut out = BTreeSet::new();
    let mut k = 0;
    // Parameters: between the procedure's parentheses, the names before ':'.
    if let Some(open) = t.iter().position(|x| is(x, "(")) {
        if t[..open].iter().any(|x| ident(x) == Some("procedure")) {
            let mut names = Vec::new();
            k = open + 1;
            while k < t.len() && !is(&t[k], ")") {
                match &t[k] {
                    Token::Ident(n) => names.push(n.clone()),
                    Token::Other(s) if s == ":" => {
                        out.extend(names.drain(..));
                        // Skip the type name.
                        k += 1;
                    }
                    _ => {}
                }
                k += 1;
            }
        }
    }
    // Var and Const sections: until the first `begin`.
    let mut section = None;
    let mut names = Vec::new();
    while k < t.len() && ident(&t[k]) != Some("begin") {
        match &t[k] {
            Token::Ident(n) if n == "var" || n == "const" => {
                section = Some(n.clone());
                names.clear();
            }
            Token::Ident(n) if section.is_some() => names.push(n.clone()),
            Token::Other(s) if s == ":" && section.as_deref() == Some("var") => {
                out.extend(names.drain(..));
                // Skip to the end of the declaration.
                while k < t.len() && !is(&t[k], ";") {
                    k += 1;
                }
            }
            Token::Other(s) if s == "=" && section.as_deref() == Some("const") => {
                if let Some(n) = names.pop() {
                    out.insert(n);
                }
                names.clear();
                while k < t.len() && !is(&t[k], ";") {
                    k += 1;
                }
            }
            _ => {}
        }
        k += 1;
    }
    out
}

/// The names assigned with `:=`, in order of their first assignment.
pub(crate) fn assigned(src: &str) -> Vec<String> {
    let t = tokens(src);
    let mut out: Vec<String> = Vec::new();
    for w in t.windows(2) {
        if let (Some(n), true) = (ident(&w[0]), is(&w[1], ":=")) {
            if !out.iter().any(|x| x == n) {
                out.push(n.to_owned());
            }
        }
    }
    out
}

/// The names assigned with `:=` somewhere whose first use is a read on the
/// right-hand side of an earlier assignment: on the first pass they hold
/// whatever the memory held (Pascal leaves locals undefined).
pub(crate) fn read_before_written(src: &str) -> Vec<String> {
    let t = tokens(src);
    let assigned = assigned(src);
    let mut written: BTreeSet<String> = BTreeSet::new();
    let mut out: Vec<String> = Vec::new();
    let mut k = 0;
    while k < t.len() {
        if let (Some(n), Some(next)) = (ident(&t[k]), t.get(k + 1)) {
            if is(next, ":=") {
                // The right-hand side runs to the next ';', keyword or `:=`.
                let mut j = k + 2;
                let stop = |x: &Token| {
                    is(x, ";")
                        || is(x, ":=")
                        || matches!(
                            ident(x),
                            Some("end" | "to" | "downto" | "do" | "then" | "else" | "begin" | "of")
                        )
                };
                while j < t.len() && !stop(&t[j]) && !is(t.get(j + 1).unwrap_or(&t[j]), ":=") {
                    if let Some(r) = ident(&t[j]) {
                        let later = assigned.iter().any(|a| a == r);
                        if later && !written.contains(r) && !out.iter().any(|x| x == r) {
                            out.push(r.to_owned());
                        }
                    }
                    j += 1;
                }
                written.insert(n.to_owned());
                k = j;
                continue;
            }
        }
        k += 1;
    }
    out
}

/// The names assigned but never declared.
pub(crate) fn undeclared(src: &str) -> Vec<String> {
    let declared = declared(src);
    assigned(src).into_iter().filter(|n| !declared.contains(n)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scanner on a listing small enough to check by eye.
    #[test]
    fn scanner_on_a_small_listing() {
        let src = "Procedure P(a: Integer; b: Double);\n{ note }\nVar x, y: Double;\nConst c=1;\n\
                   Begin\n x := y + z; z := 1; w := x; For i := 1 to 3 Do u := 0; y := 2 End;";
        assert_eq!(comments(src), vec!["note".to_owned()]);
        let d: Vec<String> = declared(src).into_iter().collect();
        assert_eq!(d, ["a", "b", "c", "x", "y"]);
        assert_eq!(assigned(src), ["x", "z", "w", "i", "u", "y"]);
        assert_eq!(read_before_written(src), ["y", "z"]);
        assert_eq!(undeclared(src), ["z", "w", "i", "u"]);
        assert!(!tokens(src).contains(&Token::Ident("note".to_owned())));
    }
}
