//! The report's one notation. `poly` writes polynomials as plain text for
//! programs (`1 - 1/2*Phi^2`, which the JSON report keeps); the Markdown
//! report writes them as the paper does (`1 − Φ²/2`). Text in code spans is
//! left as it is, so `Phi` appears only there.
//!
//! The rewrite is local: a run of the text that reads as an expression
//! (operands joined by `+ - * / ^`, parentheses, calls such as `sqrt(5)`)
//! and names Φ, τ or a power is rewritten token by token; everything else,
//! prose included, is copied.

/// One token of prose.
#[derive(Clone, Debug, PartialEq)]
enum Tok {
    /// A name: letters (Φ and ω too), digits, `_` and `@` (`y@1`), starting
    /// with a letter.
    Ident(String),
    /// A number: digits, a decimal part, an exponent.
    Num(String),
    /// One of `+ - * / ^`.
    Op(char),
    Open,
    Close,
    /// Spaces.
    Space(String),
    /// Anything else, copied.
    Other(char),
}

fn tokens(text: &str) -> Vec<Tok> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    let take = |i: &mut usize, ok: &dyn Fn(char) -> bool| {
        let start = *i;
        while *i < chars.len() && ok(chars[*i]) {
            *i += 1;
        }
        chars[start..*i].iter().collect::<String>()
    };
    while i < chars.len() {
        let c = chars[i];
        if c.is_alphabetic() || c == '_' {
            out.push(Tok::Ident(take(&mut i, &|c| c.is_alphanumeric() || c == '_' || c == '@')));
        } else if c.is_ascii_digit() {
            let mut s = take(&mut i, &|c| c.is_ascii_digit());
            if chars.get(i) == Some(&'.') && chars.get(i + 1).is_some_and(char::is_ascii_digit) {
                i += 1;
                s.push('.');
                s.push_str(&take(&mut i, &|c| c.is_ascii_digit()));
            }
            let sign = chars.get(i + 1).is_some_and(|&c| c == '-' || c == '+');
            let digit_at = |k: usize| chars.get(k).is_some_and(char::is_ascii_digit);
            if chars.get(i) == Some(&'e') && (digit_at(i + 1) || (sign && digit_at(i + 2))) {
                s.push('e');
                i += 1;
                if sign {
                    s.push(chars[i]);
                    i += 1;
                }
                s.push_str(&take(&mut i, &|c| c.is_ascii_digit()));
            }
            out.push(Tok::Num(s));
        } else if "+-*/^".contains(c) {
            out.push(Tok::Op(c));
            i += 1;
        } else if c == '(' {
            out.push(Tok::Open);
            i += 1;
        } else if c == ')' {
            out.push(Tok::Close);
            i += 1;
        } else if c == ' ' {
            out.push(Tok::Space(take(&mut i, &|c| c == ' ')));
        } else {
            out.push(Tok::Other(c));
            i += 1;
        }
    }
    out
}

/// The end of the expression starting at `i`, if one does.
fn expression(t: &[Tok], i: usize) -> Option<usize> {
    let mut j = operand(t, i)?;
    loop {
        let k = skip_spaces(t, j);
        let Some(Tok::Op(op)) = t.get(k) else { break };
        // `x -1` is a word and a negative number, not a difference: a
        // binary operator has spaces on both sides or on neither.
        let spaced_before = k > j;
        let spaced_after = matches!(t.get(k + 1), Some(Tok::Space(_)));
        if *op == '^' || spaced_before != spaced_after {
            break;
        }
        match operand(t, skip_spaces(t, k + 1)) {
            Some(end) => j = end,
            None => break,
        }
    }
    Some(j)
}

fn skip_spaces(t: &[Tok], mut i: usize) -> usize {
    while matches!(t.get(i), Some(Tok::Space(_))) {
        i += 1;
    }
    i
}

/// An operand: a signed name, number, call or parenthesised expression,
/// with an optional integer power.
fn operand(t: &[Tok], i: usize) -> Option<usize> {
    let mut j = match t.get(i)? {
        Tok::Op('-') => return operand(t, i + 1),
        Tok::Num(_) => i + 1,
        Tok::Ident(_) if t.get(i + 1) == Some(&Tok::Open) => group(t, i + 1)?,
        Tok::Ident(_) => i + 1,
        Tok::Open => group(t, i)?,
        _ => return None,
    };
    if t.get(j) == Some(&Tok::Op('^')) {
        let sign = usize::from(t.get(j + 1) == Some(&Tok::Op('-')));
        if let Some(Tok::Num(n)) = t.get(j + 1 + sign) {
            if n.chars().all(|c| c.is_ascii_digit()) {
                j += 2 + sign;
            }
        }
    }
    Some(j)
}

/// `( expression )` starting at the `(` at `i`: the index after `)`.
fn group(t: &[Tok], i: usize) -> Option<usize> {
    let end = expression(t, skip_spaces(t, i + 1))?;
    let close = skip_spaces(t, end);
    (t.get(close) == Some(&Tok::Close)).then_some(close + 1)
}

fn superscript(digits: &str) -> String {
    digits
        .chars()
        .map(|c| match c {
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

/// Whether the run is mathematics to rewrite: it names Φ, τ or a square
/// root, has a power, or is a negative number.
fn is_math(t: &[Tok]) -> bool {
    matches!(t, [Tok::Op('-'), Tok::Num(_), ..])
        || t.iter().any(|x| match x {
            Tok::Ident(n) => n == "Phi" || n == "tau" || n == "sqrt",
            Tok::Op('^') => true,
            _ => false,
        })
}

/// The terms of a run at depth 0: where a top-level binary `+` or `-`
/// begins a new one.
fn terms(t: &[Tok]) -> Vec<&[Tok]> {
    let mut out = Vec::new();
    let (mut depth, mut start, mut last_operand) = (0usize, 0usize, false);
    for (k, x) in t.iter().enumerate() {
        match x {
            Tok::Open => depth += 1,
            Tok::Close => depth = depth.saturating_sub(1),
            Tok::Op('+' | '-') if depth == 0 && last_operand => {
                out.push(&t[start..k]);
                start = k;
            }
            _ => {}
        }
        if !matches!(x, Tok::Space(_)) {
            last_operand = matches!(x, Tok::Ident(_) | Tok::Num(_) | Tok::Close);
        }
    }
    out.push(&t[start..]);
    out
}

fn render(t: &[Tok]) -> String {
    let mut out = String::new();
    for term in terms(t) {
        // `1/2*Phi^2` is written Φ²/2, `3/8*Phi*z` 3Φz/8.
        let lead = term.iter().position(|x| !matches!(x, Tok::Op('+' | '-') | Tok::Space(_)));
        let fraction = lead.and_then(|s| match &term[s..] {
            [Tok::Num(a), Tok::Op('/'), Tok::Num(b), Tok::Op('*'), rest @ ..] => {
                Some((s, a, b, rest))
            }
            _ => None,
        });
        match fraction {
            Some((s, a, b, rest)) => {
                let body = rest.len()
                    - rest.iter().rev().take_while(|x| matches!(x, Tok::Space(_))).count();
                out.push_str(&render_tokens(&term[..s]));
                if a != "1" {
                    out.push_str(a);
                }
                out.push_str(&render_tokens(&rest[..body]));
                out.push('/');
                out.push_str(b);
                out.push_str(&render_tokens(&rest[body..]));
            }
            None => out.push_str(&render_tokens(term)),
        }
    }
    out
}

/// The index of the `)` that closes the `(` at `open`.
fn closing(t: &[Tok], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (k, x) in t.iter().enumerate().skip(open) {
        match x {
            Tok::Open => depth += 1,
            Tok::Close => {
                depth -= 1;
                if depth == 0 {
                    return Some(k);
                }
            }
            _ => {}
        }
    }
    None
}

fn render_tokens(t: &[Tok]) -> String {
    let mut out = String::new();
    let mut k = 0;
    while k < t.len() {
        match &t[k] {
            // A parenthesised part is rendered as a run of its own, so its
            // terms are rewritten like the outer ones.
            Tok::Open if closing(t, k).is_some() => {
                let end = closing(t, k).expect("checked");
                out.push('(');
                out.push_str(&render(&t[k + 1..end]));
                out.push(')');
                k = end;
            }
            Tok::Ident(n) => out.push_str(match n.as_str() {
                "Phi" => "Φ",
                "tau" => "τ",
                "sqrt" => "√",
                other => other,
            }),
            Tok::Num(n) => out.push_str(n),
            Tok::Op('^') => match (t.get(k + 1), t.get(k + 2)) {
                (Some(Tok::Num(n)), _) => {
                    out.push_str(&superscript(n));
                    k += 1;
                }
                (Some(Tok::Op('-')), Some(Tok::Num(n))) => {
                    out.push('⁻');
                    out.push_str(&superscript(n));
                    k += 2;
                }
                _ => out.push('^'),
            },
            // A product is written by juxtaposition, but a number after a
            // factor keeps a dot: 2Φ, Φ·2.
            Tok::Op('*') => {
                if matches!(t.get(skip_spaces(t, k + 1)), Some(Tok::Num(_))) {
                    out.push('·');
                }
            }
            Tok::Op('-') => out.push('−'),
            Tok::Op(c) | Tok::Other(c) => out.push(*c),
            Tok::Open => out.push('('),
            Tok::Close => out.push(')'),
            Tok::Space(s) => out.push_str(s),
        }
        k += 1;
    }
    // √(5) is written √5.
    simplify_roots(&out)
}

fn simplify_roots(s: &str) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(k) = rest.find("√(") {
        out.push_str(&rest[..k]);
        let after = &rest[k + "√(".len()..];
        match after.find(')') {
            Some(end)
                if !after[..end].is_empty() && after[..end].chars().all(|c| c.is_ascii_digit()) =>
            {
                out.push('√');
                out.push_str(&after[..end]);
                rest = &after[end + 1..];
            }
            _ => {
                out.push_str("√(");
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

/// Prose outside code spans with its mathematics in the paper's notation.
fn prose(text: &str) -> String {
    let t = tokens(text);
    let mut out = String::new();
    let mut i = 0;
    while i < t.len() {
        // An expression starts at an operand that does not continue a name
        // or number just before it.
        let starts = matches!(t[i], Tok::Ident(_) | Tok::Num(_) | Tok::Open | Tok::Op('-'));
        if starts {
            if let Some(end) = expression(&t, i) {
                // An expression is rewritten whole or copied whole.
                if is_math(&t[i..end]) {
                    out.push_str(&render(&t[i..end]));
                } else {
                    out.extend(t[i..end].iter().map(render_plain));
                }
                i = end;
                continue;
            }
        }
        out.push_str(&render_plain(&t[i]));
        i += 1;
    }
    out
}

fn render_plain(t: &Tok) -> String {
    match t {
        Tok::Ident(s) | Tok::Num(s) | Tok::Space(s) => s.clone(),
        Tok::Op(c) | Tok::Other(c) => c.to_string(),
        Tok::Open => "(".to_owned(),
        Tok::Close => ")".to_owned(),
    }
}

/// `text` in the report's notation: its mathematics outside code spans
/// rewritten (`Phi^2*z` as `Φ²z`), code spans untouched.
pub(crate) fn math(text: &str) -> String {
    text.split('`')
        .enumerate()
        .map(|(k, part)| if k % 2 == 1 { format!("`{part}`") } else { prose(part) })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::math;

    /// poly's plain text in the paper's notation; prose, Pascal and code
    /// spans untouched.
    #[test]
    fn rewrites() {
        let check = |input: &str, want: &str| assert_eq!(math(input), want, "{input}");
        check("χ = z^2 - 2*z + Phi^2*z + 1", "χ = z² − 2z + Φ²z + 1");
        check("P = [[1 - 1/2*Phi^2, -Phi], [Phi, 1]]", "P = [[1 − Φ²/2, −Φ], [Φ, 1]]");
        check("y = y + Phi*v - 1/2*Phi^3*v + 3/8*Phi^4*y", "y = y + Φv − Φ³v/2 + 3Φ⁴y/8");
        check(
            "(the root of Phi^6 - 6*Phi^4 + 17*Phi^2 - 16)",
            "(the root of Φ⁶ − 6Φ⁴ + 17Φ² − 16)",
        );
        check("-1/2*tau^2*x1 + O(τ³)", "−τ²x1/2 + O(τ³)");
        check("T(Phi) at Phi = 2", "T(Φ) at Φ = 2");
        check("2*D*Phi*z and 2*(1 - Phi^2/2)", "2DΦz and 2(1 − Φ²/2)");
        check("limit sqrt(101)/5 - 1/5 at Phi*sqrt(5)", "limit √101/5 − 1/5 at Φ√5");
        check(
            "sqrt(2*sqrt(5) - 2) ≈ 1.5723, -30.0° and [[0, -1]]",
            "√(2√5 − 2) ≈ 1.5723, −30.0° and [[0, −1]]",
        );
        check(
            "v = (1 - 1/2*Phi^2) v z^-1 + (-Phi + 1/2*Phi^3) y z^-1",
            "v = (1 − Φ²/2) v z⁻¹ + (−Φ + Φ³/2) y z⁻¹",
        );
        check("v = (-y@1 + y)/Phi", "v = (−y@1 + y)/Φ");
        check("e.g. 5.44e-4 and x1o..y3o, second-order", "e.g. 5.44e-4 and x1o..y3o, second-order");
        check("the line `y = 2*y - Phi^2*y` and Phic", "the line `y = 2*y - Phi^2*y` and Phic");
        check("2*y0-y2+Sqr(dT)*(-wo*wo*y0)", "2*y0-y2+Sqr(dT)*(-wo*wo*y0)");
        check("Φ = 0.1, 1.2695 < Φ", "Φ = 0.1, 1.2695 < Φ");
        check("is at -1 after 21 steps, gives -30.0°", "is at −1 after 21 steps, gives −30.0°");
        check("Ψ − Φ = 1/24·Φ^3, 10^6 steps, sum(v^2/2)", "Ψ − Φ = 1/24·Φ³, 10⁶ steps, sum(v²/2)");
        check(
            "Derivation::stability(false_euler) at 10^-k",
            "Derivation::stability(false_euler) at 10^-k",
        );
    }
}
