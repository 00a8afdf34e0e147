"""Shared helpers for the NodePy peer scripts: exact SymPy values to zcheck's
entry syntax and back, shortest round-trip decimals, catalogue loading.

zcheck's tableau entries (crates/poly/src/lang/tableau.rs) are an integer or a
string in `+ - * / ^ ( )` with `sqrt(N)`, `cbrt(N)`, `root(K, N)` for positive
integer literals N, and decimals written positionally (no exponent: a letter
other than those three names is refused).
"""

import math
import os
import sys
import warnings

import numpy as np
import sympy

HERE = os.path.dirname(os.path.abspath(__file__))
CRATE = os.path.normpath(os.path.join(HERE, "..", ".."))
DATA = os.path.join(CRATE, "tests", "data", "nodepy")


class Inexact(Exception):
    """The value is not an exact number zcheck's entry syntax can write."""


def _paren(s):
    return "(" + s + ")"


def to_entry(e):
    """An exact SymPy number as a zcheck entry string; raises Inexact."""
    e = sympy.sympify(e)
    if e.is_Float:
        raise Inexact(f"binary float {e}")
    if e.is_Integer:
        return str(int(e))
    if e.is_Rational:
        return f"{e.p}/{e.q}"
    if e.is_Pow:
        base, ex = e.as_base_exp()
        if not (base.is_Integer and base > 0 and ex.is_Rational and not ex.is_Integer):
            raise Inexact(f"unsupported power {e}")
        n, p, q = int(base), int(ex.p), int(ex.q)
        rad = f"sqrt({n})" if q == 2 else f"cbrt({n})" if q == 3 else f"root({q}, {n})"
        if abs(p) != 1:
            rad = _paren(f"{rad}^{abs(p)}")
        return rad if p > 0 else _paren(f"1/{rad}")
    if e.is_Add:
        out = ""
        for i, t in enumerate(e.as_ordered_terms()):
            s = to_entry(t)
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
            s = to_entry(f)
            factors.append(_paren(s) if (f.is_Add or s.startswith("-")) else s)
        body = "*".join(factors)
        c = sympy.Rational(coeff)
        sign = "-" if c < 0 else ""
        c = abs(c)
        head = body if c.p == 1 else f"{c.p}*{body}"
        tail = "" if c.q == 1 else f"/{c.q}"
        return sign + head + tail
    raise Inexact(f"unsupported expression {e} ({type(e).__name__})")


def from_entry(s):
    """A zcheck entry string back to SymPy (for checking the round trip)."""
    loc = {
        "sqrt": sympy.sqrt,
        "cbrt": lambda n: sympy.root(n, 3),
        "root": lambda k, n: sympy.root(n, k),
    }
    return sympy.sympify(s.replace("^", "**"), locals=loc, rational=True)


def exact_equal(a, b):
    d = sympy.sympify(a) - sympy.sympify(b)
    if d == 0:
        return True
    d = sympy.simplify(d)
    if d == 0:
        return True
    return abs(sympy.N(d, 60)) < sympy.Float("1e-50")


def decimal(x):
    """The shortest positional decimal string that reads back as the float x."""
    x = float(x)
    if not math.isfinite(x):
        raise ValueError(f"non-finite {x}")
    s = np.format_float_positional(x, unique=True, trim="-")
    assert float(s) == x, (s, x)
    return s


def entry(v):
    """(string, exact?) for one NodePy coefficient. A Python/NumPy float
    with an integer value (NodePy writes alpha = 1.0) is that integer."""
    if isinstance(v, (float, np.floating)) and float(v).is_integer():
        return str(int(v)), True
    if isinstance(v, (int, np.integer)):
        return str(int(v)), True
    try:
        s = to_entry(v)
    except Inexact:
        return decimal(float(v)), False
    except (TypeError, ValueError, AttributeError):
        return decimal(float(v)), False
    back = from_entry(s)
    if not exact_equal(back, v):
        raise AssertionError(f"round trip failed: {v!r} -> {s!r} -> {back!r}")
    return s, True


def stem(key):
    """A file stem (and zcheck method identifier) for a NodePy key."""
    s = "".join(c if (c.isascii() and (c.isalnum() or c == "_")) else "_" for c in key)
    if not s or s[0].isdigit():
        s = "rk_" + s
    return s


def rk_catalogue():
    """NodePy's RK catalogue as {stem: (key, method)}; skips a duplicate
    spelling (Söderlind43 is Soderlind43). Embedded pairs keep their main
    method (NodePy's A and b are the main method's)."""
    from nodepy import runge_kutta_method as rk

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        d = rk.loadRKM("All")
    out = {}
    for key, m in d.items():
        if not key.isascii():
            plain = key.replace("ö", "o")
            if plain in d:
                continue  # the same method under its ASCII key
        out[stem(key)] = (key, m)
    return out


def lmm_catalogue():
    """The linear multistep methods NodePy constructs: {stem: (label, method)}."""
    from nodepy import linear_multistep_method as lm

    out = {}
    for k in range(1, 9):
        out[f"AB{k}"] = (f"Adams_Bashforth({k})", lm.Adams_Bashforth(k))
    for k in range(1, 8):
        out[f"AM{k}"] = (f"Adams_Moulton({k})", lm.Adams_Moulton(k))
    for k in range(1, 7):
        out[f"BDF{k}"] = (f"backward_difference_formula({k})", lm.backward_difference_formula(k))
    for k in range(2, 7):
        out[f"Nystrom{k}"] = (f"Nystrom({k})", lm.Nystrom(k))
    for k in range(2, 7):
        out[f"MilneSimpson{k}"] = (f"Milne_Simpson({k})", lm.Milne_Simpson(k))
    for k in range(2, 7):
        out[f"elm_ssp2_{k}"] = (f"elm_ssp2({k})", lm.elm_ssp2(k))
    for s in range(1, 4):
        out[f"sand_cc{s}"] = (f"sand_cc({s})", lm.sand_cc(s))
    d = lm.loadLMM("All")
    out["eBDF5"] = ("loadLMM('eBDF5')", d["eBDF5"])
    return out


def versions():
    import importlib.metadata as md

    import nodepy

    return {
        "python": sys.version.split()[0],
        "nodepy": md.version("nodepy"),
        "nodepy_module_version_attr": getattr(nodepy, "__version__", None),
        "sympy": sympy.__version__,
        "numpy": np.__version__,
    }
