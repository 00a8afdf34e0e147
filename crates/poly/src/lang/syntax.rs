//! The `.zm` surface syntax: lexer and recursive-descent parser.
//!
//! ```text
//! file   := line*
//! line   := [ decl | NAME ['\''] '=' expr | expr '=' expr ] [ '#' comment ]
//! decl   := 'method' NAME | 'state' NAME+ | 'param' NAME+ | 'unknown' NAME+
//!         | 'const' NAME '=' cexpr
//! expr   := term (('+' | '-') term)*
//! term   := unary (('*' | '/') unary)*
//! unary  := ('-' | '+') unary | power
//! power  := atom [ '^' INT | '^' '(' INT ')' ]
//! atom   := NUMBER | NAME [ '@' INT | "'" ] | '(' expr ')'
//! cexpr  := expr, whose atoms may also be FUNC '(' INT [',' INT] ')'
//!           with FUNC one of sqrt, cbrt, root
//! ```
//!
//! A line whose left side is a name (`x = ...`, `x' = ...`) assigns or
//! defines that name; any other left side (`a' + 2*v' = ...`) makes the
//! line an equation in the unknowns, `left − right = 0`.
//!
//! Numbers are integers or decimals (`0.5`, `2.5e-3`), taken exactly. The
//! parser only checks the grammar; names, linearity and the other semantic
//! rules are checked when the program is lowered (see `lower.rs`).

use crate::error::{Error, ErrorKind, Span};
use crate::{Poly, Q};
use num_bigint::BigInt;
use num_traits::Zero;

/// The largest exponent `^n` accepted: far above any method's needs, and low
/// enough that a typo like `Phi^4000000000` is an error, not a hang.
pub(crate) const MAX_EXPONENT: u32 = 64;

/// The deepest history read `y@k` accepted; each level adds a row and a
/// column to the transition matrix.
pub(crate) const MAX_HISTORY: u32 = 32;

/// The most tokens one line may hold. It bounds the depth of the expression
/// tree, so that parsing and lowering (both recursive) cannot exhaust the
/// stack on a pathological line.
pub(crate) const MAX_TOKENS_PER_LINE: usize = 1000;

/// The most digits a number literal may have, and the largest power of ten
/// its `e` exponent may give: far beyond any coefficient a method needs, and
/// small enough that exact arithmetic on them stays fast.
const MAX_DIGITS: usize = 1000;
const MAX_DECIMAL_EXPONENT: i64 = 1000;

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Name(String),
    Num(Q),
    Int(u32),
    Sym(char),
    Newline,
    Eof,
}

#[derive(Clone, Debug)]
struct Token {
    tok: Tok,
    span: Span,
}

/// A parsed expression with its span.
#[derive(Clone, Debug)]
pub(crate) struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub(crate) enum ExprKind {
    Num(Q),
    Name(String),
    /// `name@k`.
    Hist(String, u32),
    /// `name'`: the value at the end of the step, an unknown.
    Primed(String),
    Neg(Box<Expr>),
    Bin(BinOp, Box<Expr>, Box<Expr>),
    Pow(Box<Expr>, u32),
    /// `sqrt(N)`, `cbrt(N)` or `root(K, N)`: only in a `const` line.
    Call {
        func: String,
        args: Vec<(Q, Span)>,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
}

/// One meaningful line of a `.zm` file.
#[derive(Clone, Debug)]
pub(crate) enum Item {
    Method(String, Span),
    State(Vec<(String, Span)>, Span),
    Param(Vec<(String, Span)>, Span),
    /// `NAME = expr` or `NAME' = expr`.
    Assign {
        target: String,
        target_span: Span,
        expr: Expr,
        line_text: String,
        primed: bool,
    },
    /// `lhs = rhs` with any other left side: an equation in the unknowns.
    Equation {
        lhs: Expr,
        rhs: Expr,
        line_text: String,
    },
    /// `unknown a b ...`.
    Unknown(Vec<(String, Span)>, Span),
    /// `const NAME = cexpr`.
    Const {
        name: String,
        span: Span,
        expr: Expr,
    },
}

fn lex(src: &str) -> Result<Vec<Token>, Error> {
    let mut out = Vec::new();
    for (li, line) in src.lines().enumerate() {
        let line_no = li as u32 + 1;
        let chars: Vec<char> = line.chars().collect();
        let mut i = 0;
        let line_start = out.len();
        while i < chars.len() {
            if out.len() - line_start > MAX_TOKENS_PER_LINE {
                return Err(Error::new(
                    ErrorKind::Syntax,
                    Span { line: line_no, col: 1, len: 1 },
                    format!("line too long: expected at most {MAX_TOKENS_PER_LINE} tokens (split the expression with temporaries)"),
                ));
            }
            let c = chars[i];
            let col = i as u32 + 1;
            let span = |len: usize| Span { line: line_no, col, len: len as u32 };
            if c == '#' {
                break;
            }
            if c == '\r' {
                return Err(Error::new(
                    ErrorKind::Syntax,
                    span(1),
                    "carriage return U+000D inside a line (old Mac line endings?): expected line feed (LF) or CRLF line endings",
                ));
            }
            if c == '\t' || (c.is_whitespace() && !c.is_control()) {
                i += 1;
                continue;
            }
            if c.is_ascii_alphabetic() || c == '_' {
                let start = i;
                while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
                let name: String = chars[start..i].iter().collect();
                out.push(Token { tok: Tok::Name(name), span: span(i - start) });
                continue;
            }
            if c.is_ascii_digit()
                || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit))
            {
                let start = i;
                let (tok, len) = lex_number(&chars[start..]).map_err(|msg| {
                    Error::new(ErrorKind::Syntax, Span { line: line_no, col, len: 1 }, msg)
                })?;
                i += len;
                out.push(Token { tok, span: span(len) });
                continue;
            }
            if "+-*/^()=@',".contains(c) {
                out.push(Token { tok: Tok::Sym(c), span: span(1) });
                i += 1;
                continue;
            }
            return Err(Error::new(
                ErrorKind::Syntax,
                span(1),
                format!("unexpected character {}: expected a name, a number, an operator (+ - * / ^), `=`, `@` or parentheses", describe_char(c)),
            ));
        }
        // An error at the end of the line points just after its last token,
        // not past trailing blanks or a comment.
        let end_col = match out.get(line_start..).and_then(<[Token]>::last) {
            Some(t) => t.span.col + t.span.len,
            None => 1,
        };
        out.push(Token { tok: Tok::Newline, span: Span { line: line_no, col: end_col, len: 1 } });
    }
    let last = src.lines().count() as u32;
    out.push(Token { tok: Tok::Eof, span: Span { line: last.max(1), col: 1, len: 1 } });
    Ok(out)
}

/// A character for a message: printable ASCII in backquotes; anything else
/// by its code point, with a hint for the look-alikes people paste.
fn describe_char(c: char) -> String {
    let hint = match c {
        '\u{2212}' | '\u{2013}' | '\u{2014}' => " (a dash: write the ASCII minus `-`)",
        '\u{00D7}' | '\u{22C5}' | '\u{00B7}' => " (a multiplication sign: write `*`)",
        '\u{00F7}' | '\u{2215}' => " (a division sign: write `/`)",
        '\u{FEFF}' => " (a byte-order mark)",
        '\u{200B}' => " (a zero-width space)",
        _ => "",
    };
    if c.is_ascii_graphic() {
        format!("`{c}`")
    } else if crate::error::is_invisible(c) {
        format!("U+{:04X}{hint}", c as u32)
    } else {
        format!("`{c}` U+{:04X}{hint}", c as u32)
    }
}

/// Lexes an exact decimal number; plain integers become `Tok::Int` so they can
/// serve as exponents and history depths.
fn lex_number(chars: &[char]) -> Result<(Tok, usize), String> {
    let mut i = 0;
    let mut digits = String::new();
    while i < chars.len() && chars[i].is_ascii_digit() {
        digits.push(chars[i]);
        i += 1;
    }
    let mut frac = String::new();
    let mut is_int = true;
    if i < chars.len() && chars[i] == '.' {
        is_int = false;
        i += 1;
        while i < chars.len() && chars[i].is_ascii_digit() {
            frac.push(chars[i]);
            i += 1;
        }
    }
    if i < chars.len() && chars[i] == '.' {
        let mut j = i;
        while j < chars.len() && (chars[j].is_ascii_digit() || chars[j] == '.') {
            j += 1;
        }
        return Err(format!(
            "malformed number `{}`: expected at most one decimal point",
            chars[..j].iter().collect::<String>()
        ));
    }
    if digits.len() + frac.len() > MAX_DIGITS {
        return Err(format!("number too long: expected at most {MAX_DIGITS} digits"));
    }
    let mut exp: i64 = 0;
    if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
        let mut j = i + 1;
        let mut sign = 1;
        if j < chars.len() && (chars[j] == '+' || chars[j] == '-') {
            if chars[j] == '-' {
                sign = -1;
            }
            j += 1;
        }
        let start = j;
        while j < chars.len() && chars[j].is_ascii_digit() {
            j += 1;
        }
        if j == start {
            return Err("malformed number: expected digits after the exponent `e`".into());
        }
        let e: String = chars[start..j].iter().collect();
        exp = match e.parse::<i64>() {
            Ok(e) if e <= MAX_DECIMAL_EXPONENT => sign * e,
            _ => {
                return Err(format!(
                    "exponent too large: expected at most {MAX_DECIMAL_EXPONENT} in magnitude"
                ))
            }
        };
        is_int = false;
        i = j;
    }
    if i < chars.len() && (chars[i].is_ascii_alphabetic() || chars[i] == '_') {
        return Err(format!(
            "malformed number: `{}` runs into a name; expected an operator between them",
            chars[..=i].iter().collect::<String>()
        ));
    }
    if is_int {
        if let Ok(n) = digits.parse::<u32>() {
            return Ok((Tok::Int(n), i));
        }
    }
    let scale = exp - frac.len() as i64;
    let q =
        small_decimal(&digits, &frac, scale).unwrap_or_else(|| big_decimal(&digits, &frac, scale));
    Ok((Tok::Num(q), i))
}

/// The decimal with digits `digits` `frac` (ASCII digits) times
/// 10^`scale`, in `u128` when the digits and the power of ten fit (every
/// tableau entry but a long one); `None` otherwise.
fn small_decimal(digits: &str, frac: &str, scale: i64) -> Option<Q> {
    // 38 digits stay below 10^38 < 2^128.
    if digits.len() + frac.len() > 38 {
        return None;
    }
    let mut m: u128 = 0;
    for d in digits.bytes().chain(frac.bytes()) {
        m = m * 10 + u128::from(d - b'0');
    }
    let p = 10u128.checked_pow(u32::try_from(scale.unsigned_abs()).ok()?)?;
    Some(if scale >= 0 {
        Q::from_integer(BigInt::from(m.checked_mul(p)?))
    } else {
        let g = num_integer::Integer::gcd(&m, &p);
        Q::new_raw(BigInt::from(m / g), BigInt::from(p / g))
    })
}

/// [`small_decimal`] for any length, in big integers: mantissa · 10^scale,
/// reduced once (by Lehmer's gcd). Its oracle in the tests.
fn big_decimal(digits: &str, frac: &str, scale: i64) -> Q {
    let mantissa: BigInt = format!("{digits}{frac}").parse().unwrap_or_else(|_| BigInt::zero());
    let factor = num_traits::pow(BigInt::from(10), scale.unsigned_abs() as usize);
    if scale >= 0 {
        Q::from_integer(mantissa * factor)
    } else {
        crate::arith::rational::ratio(mantissa, factor)
    }
}

/// Parses an exact number as a user types it outside a `.zm` file (a
/// command-line value): an optional sign, then a number literal of the `.zm`
/// language (`3`, `0.1`, `2.5e-3`, read by the same lexer, so `0.1` is
/// exactly 1/10), optionally followed by `/` and a second literal (`1/2`).
///
/// Errors carry the 1-based column in `text` (line 1, no file name).
///
/// ```
/// assert_eq!(poly::advanced::parse_number("0.1")?, poly::q(1, 10));
/// assert_eq!(poly::advanced::parse_number("-1/2")?, poly::q(-1, 2));
/// assert_eq!(poly::advanced::parse_number("2.5e-3")?, poly::q(1, 400));
/// assert!(poly::advanced::parse_number("1.2.3").is_err());
/// # Ok::<(), poly::Error>(())
/// ```
pub fn parse_number(text: &str) -> Result<Q, Error> {
    let chars: Vec<char> = text.chars().collect();
    let err = |at: usize, msg: String| {
        Error::new(ErrorKind::Syntax, Span { line: 1, col: at as u32 + 1, len: 1 }, msg)
            .located("", text)
    };
    let literal = |at: usize| -> Result<(Q, usize), Error> {
        let starts = chars.get(at).is_some_and(|c| {
            c.is_ascii_digit() || (*c == '.' && chars.get(at + 1).is_some_and(char::is_ascii_digit))
        });
        if !starts {
            let found = chars.get(at).map_or("the end".to_owned(), |&c| describe_char(c));
            return Err(err(
                at,
                format!("expected a number such as 3, 0.25, 1e-6 or 1/2, found {found}"),
            ));
        }
        let (tok, len) = lex_number(&chars[at..]).map_err(|msg| err(at, msg))?;
        let q = match tok {
            Tok::Num(q) => q,
            Tok::Int(n) => Q::from_integer(n.into()),
            _ => return Err(err(at, "expected a number".into())),
        };
        Ok((q, at + len))
    };
    let (negative, start) = match chars.first() {
        Some('-') => (true, 1),
        Some('+') => (false, 1),
        _ => (false, 0),
    };
    let (mut q, mut at) = literal(start)?;
    if chars.get(at) == Some(&'/') {
        let (den, end) = literal(at + 1)?;
        if den.is_zero() {
            return Err(err(at + 1, "division by zero: expected a nonzero denominator".into()));
        }
        // Both literals are non-negative, so den > 0; one reduction (by
        // Lehmer's gcd) of the cross products.
        q = crate::arith::rational::ratio(q.numer() * den.denom(), q.denom() * den.numer());
        at = end;
    }
    if let Some(&c) = chars.get(at) {
        return Err(err(
            at,
            format!("unexpected {} after the number: expected nothing more", describe_char(c)),
        ));
    }
    Ok(if negative { -q } else { q })
}

struct Parser {
    toks: Vec<Token>,
    pos: usize,
    /// Inside a `const` line, where root functions may be called.
    in_const: bool,
}

fn describe(t: &Tok) -> String {
    match t {
        Tok::Name(n) => format!("name `{n}`"),
        Tok::Num(q) => format!("number `{q}`"),
        Tok::Int(n) => format!("number `{n}`"),
        Tok::Sym(c) => format!("`{c}`"),
        Tok::Newline => "end of line".into(),
        Tok::Eof => "end of file".into(),
    }
}

const KEYWORDS: [&str; 3] = ["method", "state", "param"];

/// The functions a `const` line may call.
const ROOT_FUNCTIONS: [&str; 3] = ["sqrt", "cbrt", "root"];

impl Parser {
    fn peek(&self) -> &Token {
        &self.toks[self.pos]
    }

    fn bump(&mut self) -> Token {
        let t = self.toks[self.pos].clone();
        if self.pos + 1 < self.toks.len() {
            self.pos += 1;
        }
        t
    }

    fn err(&self, expected: &str) -> Error {
        let t = self.peek();
        Error::new(
            ErrorKind::Syntax,
            t.span,
            format!("expected {expected}, found {}", describe(&t.tok)),
        )
    }

    fn expect_sym(&mut self, c: char, expected: &str) -> Result<Span, Error> {
        if self.peek().tok == Tok::Sym(c) {
            Ok(self.bump().span)
        } else {
            Err(self.err(expected))
        }
    }

    fn end_of_line(&mut self) -> Result<(), Error> {
        match self.peek().tok {
            Tok::Newline => {
                self.bump();
                Ok(())
            }
            Tok::Eof => Ok(()),
            _ => Err(self.err("an operator or the end of the line")),
        }
    }

    fn names(&mut self, what: &str) -> Result<Vec<(String, Span)>, Error> {
        let mut v = Vec::new();
        while let Tok::Name(n) = &self.peek().tok {
            let n = n.clone();
            let s = self.bump().span;
            v.push((n, s));
        }
        if v.is_empty() {
            return Err(self.err(what));
        }
        Ok(v)
    }

    fn item(&mut self, src_lines: &[&str]) -> Result<Option<Item>, Error> {
        loop {
            match &self.peek().tok {
                Tok::Newline => {
                    self.bump();
                }
                Tok::Eof => return Ok(None),
                _ => break,
            }
        }
        let head = self.peek().clone();
        // `unknown` and `const` are keywords only before a name, so that
        // older programs may still use them as temporaries.
        let next_is_name =
            matches!(self.toks.get(self.pos + 1).map(|t| &t.tok), Some(Tok::Name(_)));
        let item = match &head.tok {
            Tok::Name(w) if w == "method" => {
                self.bump();
                let t = self.peek().clone();
                let Tok::Name(n) = t.tok else {
                    return Err(self.err("the method's name after `method`"));
                };
                self.bump();
                Item::Method(n, t.span)
            }
            Tok::Name(w) if w == "state" => {
                self.bump();
                Item::State(self.names("one or more state variable names")?, head.span)
            }
            Tok::Name(w) if w == "param" => {
                self.bump();
                Item::Param(self.names("one or more parameter names")?, head.span)
            }
            Tok::Name(w) if w == "unknown" && next_is_name => {
                self.bump();
                Item::Unknown(self.names("one or more unknown names")?, head.span)
            }
            Tok::Name(w) if w == "const" && next_is_name => {
                self.bump();
                self.constant()?
            }
            Tok::Name(_) | Tok::Num(_) | Tok::Int(_) | Tok::Sym('(' | '-' | '+') => {
                self.statement(src_lines)?
            }
            _ => {
                return Err(self
                    .err("`method`, `state`, `param`, an assignment `name = ...` or an equation"))
            }
        };
        self.end_of_line()?;
        Ok(Some(item))
    }

    /// `NAME = expr`, `NAME' = expr` or an equation `expr = expr`.
    fn statement(&mut self, src_lines: &[&str]) -> Result<Item, Error> {
        let lhs = self.expr()?;
        let named = match &lhs.kind {
            ExprKind::Name(n) => Some((n.clone(), false)),
            ExprKind::Primed(n) => Some((n.clone(), true)),
            _ => None,
        };
        if self.peek().tok != Tok::Sym('=') {
            return Err(self.err(if named.is_some() {
                "`=` after the assigned name"
            } else {
                "`=` or an operator"
            }));
        }
        self.bump();
        let rhs = self.expr()?;
        let line_text = src_lines
            .get(lhs.span.line as usize - 1)
            .map(|l| l.split('#').next().unwrap_or("").trim().to_owned())
            .unwrap_or_default();
        Ok(match named {
            Some((target, primed)) => {
                // The name alone, without a prime or parentheses around it.
                let target_span = Span { len: target.chars().count() as u32, ..lhs.span };
                Item::Assign { target, target_span, expr: rhs, line_text, primed }
            }
            None => Item::Equation { lhs, rhs, line_text },
        })
    }

    /// `const NAME = cexpr`, after the word `const`.
    fn constant(&mut self) -> Result<Item, Error> {
        let t = self.bump();
        let Tok::Name(name) = t.tok else { unreachable!("checked by the caller") };
        self.expect_sym('=', "`=` after the constant's name")?;
        self.in_const = true;
        let expr = self.expr();
        self.in_const = false;
        Ok(Item::Const { name, span: t.span, expr: expr? })
    }

    /// `FUNC(INT [, INT])` in a constant's expression, at the function's name.
    fn call(&mut self) -> Result<Expr, Error> {
        let f = self.bump();
        let func = match &f.tok {
            Tok::Name(n) if ROOT_FUNCTIONS.contains(&n.as_str()) => n.clone(),
            _ => {
                return Err(Error::new(
                    ErrorKind::BadConstant,
                    f.span,
                    format!(
                        "unknown function {}: expected `sqrt(N)`, `cbrt(N)` or `root(K, N)` with positive integers",
                        describe(&f.tok)
                    ),
                ))
            }
        };
        self.expect_sym('(', "`(` after the root function")?;
        let mut args = Vec::new();
        loop {
            let a = self.peek().clone();
            let q = match a.tok {
                Tok::Int(n) => Q::from_integer(n.into()),
                Tok::Num(q) => q,
                Tok::Sym('-') => {
                    return Err(Error::new(
                        ErrorKind::BadConstant,
                        a.span,
                        "a negative argument: expected a positive integer",
                    ))
                }
                _ => return Err(self.err("a positive integer argument")),
            };
            self.bump();
            args.push((q, a.span));
            if self.peek().tok == Tok::Sym(',') {
                self.bump();
                continue;
            }
            break;
        }
        let close = self.expect_sym(')', "`)` or `,` after the argument")?;
        Ok(Expr { kind: ExprKind::Call { func, args }, span: join(f.span, close) })
    }

    fn expr(&mut self) -> Result<Expr, Error> {
        let mut lhs = self.term()?;
        loop {
            let op = match self.peek().tok {
                Tok::Sym('+') => BinOp::Add,
                Tok::Sym('-') => BinOp::Sub,
                _ => return Ok(lhs),
            };
            self.bump();
            let rhs = self.term()?;
            lhs = bin(op, lhs, rhs);
        }
    }

    fn term(&mut self) -> Result<Expr, Error> {
        let mut lhs = self.unary()?;
        loop {
            let op = match self.peek().tok {
                Tok::Sym('*') => BinOp::Mul,
                Tok::Sym('/') => BinOp::Div,
                _ => return Ok(lhs),
            };
            self.bump();
            let rhs = self.unary()?;
            lhs = bin(op, lhs, rhs);
        }
    }

    fn unary(&mut self) -> Result<Expr, Error> {
        match self.peek().tok {
            Tok::Sym('-') => {
                let s = self.bump().span;
                let e = self.unary()?;
                let span = join(s, e.span);
                Ok(Expr { kind: ExprKind::Neg(Box::new(e)), span })
            }
            Tok::Sym('+') => {
                self.bump();
                self.unary()
            }
            _ => self.power(),
        }
    }

    fn power(&mut self) -> Result<Expr, Error> {
        let base = self.atom()?;
        if self.peek().tok != Tok::Sym('^') {
            return Ok(base);
        }
        let caret = self.bump().span;
        let paren = self.peek().tok == Tok::Sym('(');
        if paren {
            self.bump();
        }
        let t = self.peek().clone();
        let n = match &t.tok {
            Tok::Int(n) => *n,
            // An integer literal too large for `Tok::Int`.
            Tok::Num(q) if q.is_integer() => u32::MAX,
            _ => {
                return Err(Error::new(
                    ErrorKind::BadPower,
                    if matches!(t.tok, Tok::Newline | Tok::Eof) { caret } else { t.span },
                    format!(
                        "expected a non-negative integer exponent after `^` (exponents are integer literals such as `^2`), found {}",
                        describe(&t.tok)
                    ),
                ))
            }
        };
        if n > MAX_EXPONENT {
            let shown = match &t.tok {
                Tok::Num(q) => q.to_string(),
                _ => n.to_string(),
            };
            return Err(Error::new(
                ErrorKind::BadPower,
                t.span,
                format!("exponent {shown} is too large: expected at most {MAX_EXPONENT}"),
            ));
        }
        self.bump();
        let mut end = t.span;
        if paren {
            end = self.expect_sym(
                ')',
                "`)` after the exponent (exponents are integer literals: `Phi^(1/2)` is not allowed)",
            )?;
        }
        let span = join(base.span, end);
        Ok(Expr { kind: ExprKind::Pow(Box::new(base), n), span })
    }

    fn atom(&mut self) -> Result<Expr, Error> {
        let t = self.peek().clone();
        match t.tok {
            Tok::Int(n) => {
                self.bump();
                Ok(Expr { kind: ExprKind::Num(Q::from_integer(n.into())), span: t.span })
            }
            Tok::Num(q) => {
                self.bump();
                Ok(Expr { kind: ExprKind::Num(q), span: t.span })
            }
            Tok::Name(n) => {
                if KEYWORDS.contains(&n.as_str()) {
                    return Err(self.err("a value (`method`, `state` and `param` are keywords)"));
                }
                let next = self.toks.get(self.pos + 1).map(|t| &t.tok);
                if next == Some(&Tok::Sym('(')) {
                    if self.in_const {
                        return self.call();
                    }
                    if ROOT_FUNCTIONS.contains(&n.as_str()) {
                        return Err(Error::new(
                            ErrorKind::BadConstant,
                            t.span,
                            format!("`{n}(...)` outside a `const` line: expected `const c = {n}(...)` on a line above, then `c`"),
                        ));
                    }
                }
                self.bump();
                if self.peek().tok == Tok::Sym('@') {
                    self.bump();
                    let d = self.peek().clone();
                    let Tok::Int(k) = d.tok else {
                        return Err(self.err("a history depth (a non-negative integer) after `@`"));
                    };
                    if k > MAX_HISTORY {
                        return Err(Error::new(
                            ErrorKind::Syntax,
                            d.span,
                            format!(
                                "history depth {k} is too deep: expected at most {MAX_HISTORY}"
                            ),
                        ));
                    }
                    self.bump();
                    return Ok(Expr { kind: ExprKind::Hist(n, k), span: join(t.span, d.span) });
                }
                if self.peek().tok == Tok::Sym('\'') {
                    let prime = self.bump().span;
                    if self.peek().tok == Tok::Sym('@') {
                        return Err(Error::new(
                            ErrorKind::BadPrime,
                            join(t.span, self.peek().span),
                            format!("`{n}'@` primes a history read: expected either `{n}'` (the end-of-step unknown) or `{n}@k` (a past value), not both"),
                        ));
                    }
                    return Ok(Expr { kind: ExprKind::Primed(n), span: join(t.span, prime) });
                }
                Ok(Expr { kind: ExprKind::Name(n), span: t.span })
            }
            Tok::Sym('(') => {
                self.bump();
                let e = self.expr()?;
                let close = self.expect_sym(')', "`)` or an operator")?;
                Ok(Expr { kind: e.kind, span: join(t.span, close) })
            }
            _ => Err(self.err("a number, a name or `(`")),
        }
    }
}

fn join(a: Span, b: Span) -> Span {
    if a.line != b.line {
        return a;
    }
    Span { line: a.line, col: a.col, len: (b.col + b.len).saturating_sub(a.col).max(1) }
}

fn bin(op: BinOp, l: Expr, r: Expr) -> Expr {
    let span = join(l.span, r.span);
    Expr { kind: ExprKind::Bin(op, Box::new(l), Box::new(r)), span }
}

/// Parses a whole file into items; the first syntax error is returned.
pub(crate) fn parse(src: &str) -> Result<Vec<Item>, Error> {
    let toks = lex(src)?;
    let lines: Vec<&str> = src.lines().collect();
    let mut p = Parser { toks, pos: 0, in_const: false };
    let mut items = Vec::new();
    while let Some(item) = p.item(&lines)? {
        items.push(item);
    }
    Ok(items)
}

/// Parses a single polynomial expression (no statements): every name is a
/// symbol, `^` takes non-negative integer exponents and `/` nonzero
/// constants. Used to transcribe the paper's printed equations.
pub(crate) fn parse_poly(src: &str) -> Result<crate::Poly, Error> {
    let toks = lex(src)?;
    let mut p = Parser { toks, pos: 0, in_const: false };
    while p.peek().tok == Tok::Newline {
        p.bump();
    }
    let e = p.expr()?;
    while p.peek().tok == Tok::Newline {
        p.bump();
    }
    if p.peek().tok != Tok::Eof {
        return Err(p.err("an operator or the end of the expression"));
    }
    to_poly(&e)
}

fn to_poly(e: &Expr) -> Result<crate::Poly, Error> {
    use crate::Poly;
    Ok(match &e.kind {
        ExprKind::Num(q) => Poly::constant(q.clone()),
        ExprKind::Name(n) => Poly::var(n),
        ExprKind::Hist(..) | ExprKind::Primed(_) | ExprKind::Call { .. } => {
            return Err(Error::new(
                ErrorKind::Syntax,
                e.span,
                "expected a polynomial, found a history read `@`, a primed name or a function call",
            ))
        }
        ExprKind::Neg(x) => -to_poly(x)?,
        ExprKind::Pow(b, n) => to_poly(b)?.pow(*n),
        ExprKind::Bin(op, l, r) => {
            let (a, b) = (to_poly(l)?, to_poly(r)?);
            match op {
                BinOp::Add => a + b,
                BinOp::Sub => a - b,
                BinOp::Mul => a * b,
                BinOp::Div => match b.as_constant() {
                    Some(c) if !c.is_zero() => a.scale(&c.recip()),
                    _ => {
                        return Err(Error::new(
                            ErrorKind::BadDivision,
                            r.span,
                            "expected a nonzero constant divisor",
                        ))
                    }
                },
            }
        }
    })
}

impl Poly {
    /// Parses a polynomial written in the crate's plain-text form, e.g.
    /// `z^2 - 2*(1 - Phi^2/2)*z + 1`. Every name is a symbol.
    ///
    /// ```
    /// let p = poly::Poly::parse("(1 - Phi^2/2)^2")?;
    /// assert_eq!(p.to_string(), "1 - Phi^2 + 1/4*Phi^4");
    /// # Ok::<(), poly::Error>(())
    /// ```
    pub fn parse(src: &str) -> Result<Poly, crate::Error> {
        parse_poly(src).map_err(|e| e.located("<expression>", src))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The machine-word decimal against the big-integer one, its slow
        /// oracle: the same reduced rational wherever it answers, and it
        /// answers for every short literal.
        #[test]
        fn small_decimal_is_the_big_one(
            digits in "[0-9]{0,24}",
            frac in "[0-9]{0,24}",
            scale in -45i64..45,
        ) {
            prop_assume!(!(digits.is_empty() && frac.is_empty()));
            let big = big_decimal(&digits, &frac, scale);
            match small_decimal(&digits, &frac, scale) {
                Some(q) => {
                    prop_assert_eq!(q.numer(), big.numer());
                    prop_assert_eq!(q.denom(), big.denom());
                }
                None => prop_assert!(
                    digits.len() + frac.len() > 38 || scale.abs() > 38 || big.numer().bits() > 127
                ),
            }
            if digits.len() + frac.len() <= 18 && scale.abs() <= 18 {
                prop_assert!(small_decimal(&digits, &frac, scale).is_some());
            }
        }

        /// A fraction of two literals is the rational num-rational makes of
        /// them, its oracle.
        #[test]
        fn fractions_are_the_ratio(n in 0u128..u128::MAX, d in 1u128..u128::MAX, minus in any::<bool>()) {
            let text = format!("{}{n}/{d}", if minus { "-" } else { "" });
            let q = Q::new(BigInt::from(n), BigInt::from(d));
            prop_assert_eq!(parse_number(&text).unwrap(), if minus { -q } else { q });
        }
    }
}
