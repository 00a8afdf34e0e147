"""Python numbers as zcheck's exact entry text (imported only when a float or
a SymPy number is given, so that ``import zcheck`` stays light).

zcheck reads an entry as an integer, a positional decimal (no exponent), a
fraction, or an expression in ``+ - * / ^ ( )`` with ``sqrt(n)``,
``cbrt(n)`` and ``root(k, n)`` of positive integers (``poly``'s tableau
entries). This module only writes that text; the engine reads it.
"""

import decimal
import functools
import math

from ._native import Error


def float_entry(x, where):
    """The shortest decimal that reads back as the float ``x``, written
    positionally (``1e-05`` as ``0.00001``); NaN and infinity are errors."""
    if not math.isfinite(x):
        raise Error(f"{where}: {x!r}: expected a finite number (NaN and infinity have no exact value)")
    text = repr(x)
    if "e" in text or "E" in text:
        text = format(decimal.Decimal(text), "f")
    return text


def sympy_entry(e, where):
    """An exact SymPy number as entry text; a SymPy Float is its decimal
    digits. Raises :class:`zcheck.Error` for anything else (a symbol, pi, a
    power zcheck cannot write)."""
    import sympy

    try:
        return _sympy(sympy.sympify(e))
    except _Unsupported as u:
        raise Error(f"{where}: {e}: {u}") from None


class _Unsupported(Exception):
    pass


def _paren(s):
    return "(" + s + ")"


def _sympy(e):
    import sympy

    if e.is_Float:
        if not e.is_finite:
            raise _Unsupported("expected a finite number")
        return format(decimal.Decimal(str(e)), "f")
    if e.is_Integer:
        return str(int(e))
    if e.is_Rational:
        return f"{e.p}/{e.q}"
    if e.is_Pow:
        base, ex = e.as_base_exp()
        if base.is_Integer and base > 0 and ex.is_Rational and not ex.is_Integer:
            n, p, q = int(base), int(ex.p), int(ex.q)
            rad = f"sqrt({n})" if q == 2 else f"cbrt({n})" if q == 3 else f"root({q}, {n})"
            if abs(p) != 1:
                rad = _paren(f"{rad}^{abs(p)}")
            return rad if p > 0 else _paren(f"1/{rad}")
        if ex.is_Integer:
            return _paren(f"{_paren(_sympy(base))}^{int(ex)}")
        raise _Unsupported(f"a power zcheck cannot write exactly ({e})")
    if e.is_Add:
        out = ""
        for i, t in enumerate(e.as_ordered_terms()):
            s = _sympy(t)
            if i == 0:
                out = s
            elif s.startswith("-"):
                out += " - " + s[1:]
            else:
                out += " + " + s
        return out
    if e.is_Mul:
        coeff, rest = e.as_coeff_Mul()
        factors = []
        for f in sympy.Mul.make_args(rest):
            s = _sympy(f)
            factors.append(_paren(s) if (f.is_Add or s.startswith("-")) else s)
        body = "*".join(factors)
        if coeff.is_Float:
            return f"{_sympy(coeff)}*{body}"
        c = sympy.Rational(coeff)
        sign = "-" if c < 0 else ""
        c = abs(c)
        head = body if c.p == 1 else f"{c.p}*{body}"
        tail = "" if c.q == 1 else f"/{c.q}"
        return sign + head + tail
    raise _Unsupported(
        "expected an exact number: a rational, or radicals sqrt/cbrt/root of positive integers"
    )


@functools.lru_cache(maxsize=256)
def _identifier(s):
    s = "".join(c if (c.isascii() and (c.isalnum() or c == "_")) else "_" for c in s)
    if not s or s[0].isdigit():
        s = "m_" + s
    return s


def identifier(s):
    """A ``.zm`` method name for a label: letters, digits and ``_``."""
    return _identifier(str(s))
