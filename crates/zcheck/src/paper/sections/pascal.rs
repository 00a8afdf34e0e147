//! The paper's Pascal listings (Appendices B–E), transcribed verbatim in
//! `paper/listings/*.pas`, and a small scanner over them: tokens without
//! comments, the comments, the declared names, the names a listing
//! assigns or reads before it assigns them, and the order in which a
//! loop's updates read each other (which value, old or new, each update of
//! a position and of its velocity reads).
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
                let rhs = right_side(&t, k + 1);
                for r in t[rhs.clone()].iter().filter_map(ident) {
                    let later = assigned.iter().any(|a| a == r);
                    if later && !written.contains(r) && !out.iter().any(|x| x == r) {
                        out.push(r.to_owned());
                    }
                }
                written.insert(n.to_owned());
                k = rhs.end;
                continue;
            }
        }
        k += 1;
    }
    out
}

/// A listing line with each name of `names` read as its old copy: `x1`
/// becomes `x1o` (case kept, everything else untouched).
pub(crate) fn with_old_copies(line: &str, names: &[String]) -> String {
    let mut out = String::new();
    let mut word = String::new();
    let flush = |word: &mut String, out: &mut String| {
        out.push_str(word);
        if names.iter().any(|n| *n == word.to_lowercase()) {
            out.push('o');
        }
        word.clear();
    };
    for c in line.chars() {
        if c.is_ascii_alphanumeric() || c == '_' {
            word.push(c);
        } else {
            flush(&mut word, &mut out);
            out.push(c);
        }
    }
    flush(&mut word, &mut out);
    out
}

/// The right side of the assignment whose `:=` is at `k`: its tokens up
/// to the next `;`, keyword or assignment.
fn right_side(t: &[Token], k: usize) -> std::ops::Range<usize> {
    let stop = |x: &Token| {
        is(x, ";")
            || is(x, ":=")
            || matches!(
                ident(x),
                Some("end" | "to" | "downto" | "do" | "then" | "else" | "begin" | "of")
            )
    };
    let mut j = k + 1;
    while j < t.len() && !stop(&t[j]) && !is(t.get(j + 1).unwrap_or(&t[j]), ":=") {
        j += 1;
    }
    k + 1..j
}

/// The assignments of the listing's first `For ... Do Begin ... End` loop,
/// in order: each target (lower-cased) with the names its right side reads.
pub(crate) fn loop_assignments(src: &str) -> Vec<(String, Vec<String>)> {
    let t = tokens(src);
    let Some(start) = t.iter().position(|x| ident(x) == Some("for")) else { return Vec::new() };
    let Some(begin) = (start..t.len()).find(|&k| ident(&t[k]) == Some("begin")) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let mut depth = 0usize;
    let mut k = begin;
    while k < t.len() {
        match ident(&t[k]) {
            // `ASM ... END` closes with an `end` of its own.
            Some("begin" | "asm") => depth += 1,
            Some("end") => {
                depth -= 1;
                if depth == 0 {
                    break;
                }
            }
            Some(name) if t.get(k + 1).is_some_and(|x| is(x, ":=")) => {
                let rhs = right_side(&t, k + 1);
                let reads = t[rhs.clone()].iter().filter_map(ident).map(str::to_owned).collect();
                out.push((name.to_owned(), reads));
                k = rhs.end;
                continue;
            }
            _ => {}
        }
        k += 1;
    }
    out
}

/// Which value of a variable an update reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Value {
    /// The value at the start of the pass: the old copy (`x1o`), or the
    /// variable before the pass assigns it.
    Old,
    /// The value this pass assigned earlier.
    New,
    /// Both, or the variable is not read at all.
    Unclear,
}

/// The order of one coordinate's updates in a loop: which is updated
/// first, and which value of the other each update reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Order {
    /// Whether the velocity is updated before the position.
    pub velocity_first: bool,
    /// The value of the position the velocity's update reads.
    pub velocity_reads: Value,
    /// The value of the velocity the position's update reads.
    pub position_reads: Value,
}

/// The order in which the loop updates `position` and its `velocity`
/// (names as the listing writes them, `x1` and `v1`): a read of `x1o`, or of
/// `x1` before the pass assigns it, is the old value; a read of `x1` after
/// is the new one. A temporary (`r12`) stands for what it reads. `None`
/// when the loop does not update both.
pub(crate) fn update_order(src: &str, position: &str, velocity: &str) -> Option<Order> {
    let body = loop_assignments(src);
    let first = |name: &str| body.iter().position(|(target, _)| target == name);
    let (p, v) = (first(position)?, first(velocity)?);
    // The values of `family` the assignment at `k` reads, through temporaries.
    fn reads(body: &[(String, Vec<String>)], k: usize, family: &str, seen: &mut Vec<Value>) {
        let old = format!("{family}o");
        for name in &body[k].1 {
            if *name == old {
                seen.push(Value::Old);
            } else if name == family {
                let earlier = body[..k].iter().any(|(t, _)| t == family);
                seen.push(if earlier { Value::New } else { Value::Old });
            } else if let Some(j) = body[..k].iter().rposition(|(t, _)| t == name) {
                reads(body, j, family, seen);
            }
        }
    }
    let value = |k: usize, family: &str| {
        let mut seen = Vec::new();
        reads(&body, k, family, &mut seen);
        match seen.first() {
            Some(&x) if seen.iter().all(|&y| y == x) => x,
            _ => Value::Unclear,
        }
    };
    Some(Order {
        velocity_first: v < p,
        velocity_reads: value(v, position),
        position_reads: value(p, velocity),
    })
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
        let loop_src = "Begin For k:=1 to 9 Do Begin r:=x1o-x2o; ASM FNINIT END; v1:=v1o+r+x1; \
                        x1:=x1o+v1; MapP(x1,y1); x1o:=x1; v1o:=v1; End; End;";
        let body = loop_assignments(loop_src);
        assert_eq!(
            body[1],
            ("v1".to_owned(), vec!["v1o".to_owned(), "r".to_owned(), "x1".to_owned()])
        );
        assert_eq!(body.len(), 5);
        let order = update_order(loop_src, "x1", "v1").expect("both updated");
        assert_eq!(
            order,
            Order { velocity_first: true, velocity_reads: Value::Old, position_reads: Value::New }
        );
        let standard = loop_src.replace("x1:=x1o+v1;", "x1:=x1o+v1o;");
        assert_eq!(update_order(&standard, "x1", "v1").map(|o| o.position_reads), Some(Value::Old));
        let mixed = loop_src.replace("x1:=x1o+v1;", "x1:=x1o+v1+v1o;");
        assert_eq!(
            update_order(&mixed, "x1", "v1").map(|o| o.position_reads),
            Some(Value::Unclear)
        );
        let old = ["x1".to_owned(), "y2".to_owned()];
        assert_eq!(with_old_copies("v1:=v1o+(X1-x12)*y2;", &old), "v1:=v1o+(X1o-x12)*y2o;");
    }
}
