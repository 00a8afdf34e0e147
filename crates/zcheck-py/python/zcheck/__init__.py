"""zcheck: exact stability of time integrators, from Python.

A method (a Butcher tableau, linear multistep coefficients, a ``.zm`` step
program, a built-in) becomes a :class:`Method`; its questions are answered
exactly by zcheck's Rust engine, with the same fields as the command line's
``--format json``. Exact numbers come as text (:class:`Exact`, a ``str``
with ``to_sympy()``), each with a float ``value`` beside it where the
command line gives one.

>>> import zcheck
>>> heun = zcheck.Method.from_tableau([[0, 0], [1, 0]], ["1/2", "1/2"])
>>> heun.region()["real_limit"]["exact"]
'2'
>>> heun.region()["order"]
2
>>> heun.order()["stage_order"]
1

Nothing here computes: this package converts Python values to exact text,
calls the engine and parses its JSON. numpy, SymPy and NodePy are optional,
each imported by the one function that needs it.
"""

import json as _json
import numbers as _numbers
import os as _os

from . import _native
from ._native import Error

__all__ = [
    "Error",
    "Exact",
    "Method",
    "advise",
    "design",
    "map",
    "paper",
    "to_sympy",
]

__version__ = "0.1.0"

# Fields of the engine's JSON that hold exact text (a number, a polynomial).
_EXACT_KEYS = frozenset(
    ["exact", "charpoly", "defining_poly", "leading_coefficient", "p", "q", "p_denominator"]
)


class Exact(str):
    """An exact number or polynomial as zcheck writes it (``"sqrt(6)"``,
    ``"z^2 - 2*z + Phi^2*z + 1"``, ``"root of r^3 - 4*r^2 + 12*r - 24 in
    [lo, hi]"``). It is a ``str``, equal to the command line's text."""

    __slots__ = ()

    def to_sympy(self):
        """This value as a SymPy expression (needs SymPy); see
        :func:`to_sympy`."""
        return to_sympy(self)


def to_sympy(text):
    """zcheck's exact text as a SymPy expression, exactly.

    Rationals and decimals stay exact (``0.1`` is 1/10); ``sqrt(n)``,
    ``cbrt(n)`` and ``root(k, n)`` become SymPy radicals; ``x^k`` is a
    power; a number written ``root of P in [lo, hi]`` becomes the
    ``CRootOf`` of P inside that interval. Names (``z``, ``Phi``, ``w``,
    parameters) become SymPy symbols. Needs SymPy.
    """
    import sympy

    text = str(text).strip()
    local = {
        "sqrt": sympy.sqrt,
        "cbrt": lambda n: sympy.root(n, 3),
        "root": lambda k, n: sympy.root(n, k),
        "atan": sympy.atan,
    }

    def expr(s):
        names = {}
        for tok in _identifiers(s):
            if tok not in local:
                names[tok] = sympy.Symbol(tok)
        return sympy.sympify(s.replace("^", "**"), locals={**local, **names}, rational=True)

    if text.startswith("root of ") and " in [" in text and text.endswith("]"):
        poly_text, interval = text[len("root of ") :].rsplit(" in [", 1)
        lo_text, hi_text = interval[:-1].split(",")
        p = expr(poly_text)
        (var,) = p.free_symbols
        lo, hi = sympy.Rational(lo_text.strip()), sympy.Rational(hi_text.strip())
        for r in sympy.Poly(p, var).real_roots():
            if lo <= r <= hi:
                return r
        raise Error(f"{text}: no real root of the polynomial in the interval")
    try:
        return expr(text)
    except (sympy.SympifyError, SyntaxError, TypeError) as e:
        raise Error(f"{text}: not an exact value zcheck writes ({e})") from None


def _identifiers(s):
    out, word = [], ""
    for ch in s + " ":
        if ch.isalnum() or ch == "_":
            word += ch
        else:
            if word and not word[0].isdigit():
                out.append(word)
            word = ""
    return out


def _tag_exact(d):
    for k, v in d.items():
        if isinstance(v, str) and (k in _EXACT_KEYS or k.endswith("_exact")):
            d[k] = Exact(v)
    return d


def _tag_number(d):
    # The order document's exact strings are only those of its numbers,
    # {"exact", "value"} (with "defining_poly" for an algebraic one): the
    # same tags as _tag_exact's, found without a scan of every key (a test
    # compares the two on every kind of method).
    v = d.get("exact")
    if v is not None:
        if v.__class__ is str:
            d["exact"] = Exact(v)
        p = d.get("defining_poly")
        if p.__class__ is str:
            d["defining_poly"] = Exact(p)
    return d


# Every key of the stability document that holds exact text: the native
# half builds that document as Python objects and makes the strings under
# these keys Exact (a test compares it with the text parsed by `_tag_exact`,
# which scans every key, on every built-in and catalogue method).
_STABILITY_EXACT_KEYS = _EXACT_KEYS | frozenset(
    ["phi_exact", "lo_exact", "hi_exact", "phi_max_exact", "practical_phi_max_exact"]
)


def _parse(text, exact=True, hook=_tag_exact):
    return _json.loads(text, object_hook=hook if exact else None)


def _sympy_rational(x):
    # Integer and Rational (NodePy's entries): p/q in lowest terms, q > 0,
    # without the general writer.
    return str(x.p) if x.q == 1 else f"{x.p}/{x.q}"


def _finite_float(x):
    # A float's shortest decimal when repr writes it positionally; None
    # (the slow path, which also names the entry in an error) otherwise:
    # NaN, infinity, and exponents.
    text = repr(float(x))
    return None if "e" in text or "n" in text else text


# A class lookup, then the converter: it gives the text, or None for a value
# the slow path must see. SymPy's rational classes and float's subclasses
# (numpy.float64) join on first sight.
_FAST = {str: str, int: str, float: _finite_float}


def _texts(xs, label):
    """The entry texts of a sequence; ``label(i)`` names entry i, and is
    called only for an entry off the fast path (so only for an error)."""
    out = []
    for i, x in enumerate(xs):
        f = _FAST.get(x.__class__)
        if f is _sympy_rational:
            # NodePy's entries, inline: the call costs as much as the text.
            q = x.q
            t = str(x.p) if q == 1 else f"{x.p}/{q}"
        else:
            t = None if f is None else f(x)
        out.append(t if t is not None else _entry(x, label(i)))
    return out


def _entry(x, where):
    """One exact number as zcheck's entry text; ``where`` names it in an
    error."""
    if isinstance(x, str):
        return x
    if isinstance(x, bool):
        raise Error(f"{where}: {x!r}: expected a number, not a bool")
    if type(x).__module__.split(".")[0] == "sympy":
        if getattr(x, "is_Rational", False) is True:
            _FAST[x.__class__] = _sympy_rational
            return _sympy_rational(x)
        from ._entries import sympy_entry

        return sympy_entry(x, where)
    if isinstance(x, _numbers.Integral):
        return str(int(x))
    if isinstance(x, _numbers.Rational):
        return f"{int(x.numerator)}/{int(x.denominator)}"
    if isinstance(x, _numbers.Real):
        from ._entries import float_entry

        if isinstance(x, float):
            _FAST[x.__class__] = _finite_float

        return float_entry(float(x), where)
    raise Error(
        f"{where}: {x!r}: expected an int, a fractions.Fraction, a float, a str "
        f"(such as '1/4 - sqrt(3)/6') or a SymPy number, got {type(x).__name__}"
    )


def _params(params):
    return [f"{k}={_entry(v, f'parameter {k}')}" for k, v in params.items()]


class Method:
    """A time integrator, derived exactly once and kept.

    Make one with :meth:`from_tableau`, :meth:`from_multistep`,
    :meth:`from_zm`, :meth:`from_file`, :meth:`builtin` or
    :meth:`from_nodepy`; then ask :meth:`stability`, :meth:`region`,
    :meth:`order`, :meth:`verify`, :attr:`charpoly`, :attr:`transition_matrix`.
    """

    __slots__ = ("_native",)

    def __init__(self, native):
        """Internal: use a ``from_*`` constructor or :meth:`builtin`."""
        if not isinstance(native, _native.NativeMethod):
            raise TypeError("use Method.from_tableau, from_multistep, from_zm, from_file or builtin")
        self._native = native

    # -- constructors --------------------------------------------------

    @classmethod
    def from_zm(cls, text, name="<string>"):
        """A method from ``.zm`` source text; ``name`` stands for the file
        in error locations (``<string>:3:5: ...``)."""
        return cls(_native.from_zm(str(name), text))

    @classmethod
    def from_file(cls, path):
        """A method from a file: ``.zm`` source, or ``.toml`` holding a
        Butcher tableau (``A``, ``b``, ``c``), multistep coefficients
        (``alpha``, ``beta``), a partitioned pair (``[q]``, ``[p]``) or a
        splitting (``drift``, ``kick``), read as ``zcheck`` reads it."""
        path = _os.fspath(path)
        if not path.endswith((".zm", ".toml")):
            raise Error(f"{path}: expected a .zm or .toml file (a built-in: Method.builtin)")
        return cls(_native.load(path))

    @classmethod
    def builtin(cls, name):
        """A built-in method by name (``zcheck methods`` lists them):
        ``"rk4"``, ``"false_euler"``, ``"ab3"``, ``"gauss_legendre_2"``, ..."""
        return cls(_native.builtin(name))

    @classmethod
    def from_tableau(cls, A, b, c=None, name="tableau", bhat=None):
        """A Runge–Kutta method from its Butcher tableau (``bhat``: the
        weights of an embedded estimator, for :meth:`order`).

        Entries are exact: an int, a ``fractions.Fraction``, a str such as
        ``"1/4 - sqrt(3)/6"`` (``+ - * / ^``, ``sqrt(n)``, ``cbrt(n)``,
        ``root(k, n)``), or a SymPy number; a float is read as the shortest
        decimal that prints it (``0.1`` is 1/10), and NaN or infinity is an
        error. Errors name the entry as the mathematics does, from 1:
        ``A[1][2]``, ``b[3]``, ``c[1]``.
        """
        rows = [list(row) for row in A]
        a = [_texts(r, lambda j, i=i: f"A[{i + 1}][{j + 1}]") for i, r in enumerate(rows)]
        bb = _texts(b, lambda i: f"b[{i + 1}]")
        cc = None if c is None else _texts(c, lambda i: f"c[{i + 1}]")
        bh = None if bhat is None else _texts(bhat, lambda i: f"bhat[{i + 1}]")
        return cls(_native.from_tableau(name, a, bb, cc, bh))

    @classmethod
    def from_multistep(cls, alpha, beta, name="multistep"):
        """A linear multistep method sum_j alpha_j y_(n+j) = h sum_j beta_j
        f_(n+j), lowest j first (NodePy's order). Entries as in
        :meth:`from_tableau`; errors name them from 0, as j is:
        ``alpha[0]``."""
        al = _texts(alpha, lambda j: f"alpha[{j}]")
        be = _texts(beta, lambda j: f"beta[{j}]")
        return cls(_native.from_multistep(name, al, be))

    @classmethod
    def from_nodepy(cls, method, name=None):
        """A method from a NodePy object: a Runge–Kutta method (its ``A``,
        ``b``, and ``bhat`` for an embedded pair) or a linear multistep
        method (its ``alpha``, ``beta``). NodePy's exact entries (SymPy) stay
        exact; its floats are read as their shortest decimals."""
        from ._entries import identifier

        label = name or identifier(getattr(method, "shortname", None) or getattr(method, "name", None) or "nodepy")
        # A NodePy RK method also has `alpha` and `beta` (its Shu-Osher
        # form): the tableau decides.
        if hasattr(method, "A") and hasattr(method, "b"):
            # NodePy's arrays are numpy arrays of objects: tolist() makes the
            # lists in C (a float array's become floats, read alike).
            def rows(x):
                return x.tolist() if hasattr(x, "tolist") else [list(r) for r in x]

            def row(x):
                return x.tolist() if hasattr(x, "tolist") else list(x)

            bhat = getattr(method, "bhat", None)
            bhat = None if bhat is None else row(bhat)
            return cls.from_tableau(rows(method.A), row(method.b), name=label, bhat=bhat)
        if hasattr(method, "alpha") and hasattr(method, "beta"):
            return cls.from_multistep(list(method.alpha), list(method.beta), name=label)
        raise Error(f"{type(method).__name__}: expected a NodePy Runge-Kutta (A, b) or linear multistep (alpha, beta) method")

    # -- questions -------------------------------------------------------

    @property
    def name(self):
        """The method's name."""
        return self._native.name

    @property
    def params(self):
        """The names of the method's parameters other than Phi."""
        return list(self._native.params)

    def derive(self):
        """``zcheck derive --format json``: M(z), the transition matrix P,
        chi(z), and for an implicit method P's denominator (P is given
        times it)."""
        return _parse(self._native.derive())

    @property
    def charpoly(self):
        """chi(z), the characteristic polynomial in z, Phi and the
        parameters (for an implicit method, det A times det(zI - P))."""
        return Exact(self.derive()["charpoly"])

    @property
    def transition_matrix(self):
        """P as a list of rows of exact entries (for an implicit method, P
        times ``derive()["p_denominator"]``)."""
        return [[Exact(x) for x in row] for row in self.derive()["transition_matrix"]]

    def stability(self, **params):
        """``zcheck stability --format json``: the exact stability limit in
        Phi, the boundary, every class change, rho_inf, the dispersion and
        dissipation orders. Keyword arguments bind the method's parameters
        (exact: ``D=Fraction(1, 10)``, ``D="1/10"`` or ``D=0.1``)."""
        return self._native.stability_object(_params(params), Exact, _STABILITY_EXACT_KEYS)

    def region(self, **params):
        """``zcheck region --format json``: the method on y' = lambda*y in the
        plane of w = h*lambda: order, error constant, the real and imaginary
        stability limits, A- and L-stability, A(alpha), rho_inf."""
        return _parse(self._native.region(_params(params)))

    def order(self, modified=None, tolerance=None):
        """``zcheck order --format json``: the classical order by rooted
        trees (``order``; ``order_at_least`` past the trees checked), the
        ``linear_order`` on y' = lambda*y, ``stage_order``,
        ``algebraically_stable``, ``symplectic``, ``symmetric``,
        ``ssp_coefficient``, the ``embedded_order`` of a pair, the
        ``failed_conditions`` of the next order with exact residuals, and
        with ``modified=N`` the modified equation up to h^N. ``tolerance``
        (exact, as entries are) adds ``order_within_tolerance`` (and, for a
        pair, ``embedded_order_within_tolerance``); it defaults
        to 1e-12 when an entry is a decimal of 10 or more significant
        digits. A method from ``.zm`` text has no nonlinear reading: an
        :class:`Error`."""
        tol = None if tolerance is None else _entry(tolerance, "tolerance")
        return _parse(self._native.order(None if modified is None else int(modified), tol), hook=_tag_number)

    def verify(self, phi, steps=100000, **params):
        """The numeric witnesses at ``phi`` (``check::verify``): eigenvalues
        by two libraries and a long simulation of ``steps`` steps, against
        the exact roots; ``agree`` says whether they all agree."""
        return _parse(self._native.verify(_entry(phi, "phi"), _params(params), int(steps)))

    def __repr__(self):
        return f"<zcheck.Method {self.name}>"


def map(method, phi=None, grid=40, samples=200, **params):
    """The exact stability map of ``zcheck map``, with its grid as numpy
    arrays (needs numpy).

    ``map(m, phi=(0, 3), D=(0, 2))``: over (Phi, D), each grid point's exact
    root class. ``map(m, beta=(0, 0.5), gamma=(0, 1))``: over two parameters,
    each point's exact Phi_max (inf where stability is unconditional, nan
    where there is none). A parameter given one value is bound to it.

    Returns the command line's JSON document, with ``grid`` replaced by a
    dict of 2-D arrays indexed [second axis, first axis], as
    ``matplotlib.pyplot.pcolormesh(X, Y, C)`` takes them.
    """
    import numpy as np

    def text(v, k):
        if isinstance(v, (tuple, list)):
            lo, hi = v
            return f"{_entry(lo, k)}..{_entry(hi, k)}"
        return _entry(v, k)

    phi_text = None if phi is None else text(phi, "phi")
    args = [f"{k}={text(v, f'parameter {k}')}" for k, v in params.items()]
    doc = _parse(method._native.map(phi_text, args, int(grid), int(samples)), exact=False)
    points = doc["grid"]
    ny = len(points) // max(1, doc["size"][0]) if points else 0
    shape = (ny, len(points) // max(1, ny)) if points else (0, 0)

    def arr(f, dtype=None):
        return np.array([f(p) for p in points], dtype=dtype).reshape(shape)

    a, b = doc["axes"]
    if "phi_max" in (points[0] if points else {}):
        inf, nan = float("inf"), float("nan")
        doc["grid"] = {
            a: arr(lambda p: p["values"][0], float),
            b: arr(lambda p: p["values"][1], float),
            "phi_max": arr(lambda p: inf if p["unconditional"] else (nan if p["phi_max"] is None else p["phi_max"]), float),
            "stability": arr(lambda p: p["stability"], object),
            "unconditional": arr(lambda p: p["unconditional"], bool),
            "witnesses_agree": arr(lambda p: p["witnesses_agree"], bool),
        }
    else:
        doc["grid"] = {
            a: arr(lambda p: p["phi"], float),
            b: arr(lambda p: p["value"], float),
            "class": arr(lambda p: p["class"], object),
            "witnesses_agree": arr(lambda p: p["witnesses_agree"], bool),
        }
    return doc


def design(method, maximize, min_order=None, per=None, **params):
    """``zcheck design --format json``: one or two free parameters of
    ``method`` chosen for the best exact objective, with a certificate.

    ``design(m, maximize="imag_limit", a3=(0, "1/2"))``: a tuple is a free
    parameter's exact range, a single value binds a parameter
    (``gamma="1/2"``). ``maximize`` is ``"phi_max"``, ``"real_limit"``,
    ``"imag_limit"`` or ``"ssp_coefficient"``; ``min_order=P`` keeps only
    the values where the (linear) order is at least P; ``per="stage"`` or
    ``"cost"`` divides the objective by the stage count or the step's
    multiplications. Returns the command line's document: ``optimum`` and
    each ``at`` value exact (``{"exact", "value"}``, +inf as ``"inf"``),
    ``attained``, the ``certificate`` lines and the exact ``grid_check``.
    A tableau whose entries name parameters is designed with the command
    line (``zcheck design FILE.toml``).
    """

    def text(v, k):
        if isinstance(v, (tuple, list)):
            lo, hi = v
            return f"{_entry(lo, k)}..{_entry(hi, k)}"
        return _entry(v, k)

    args = [f"{k}={text(v, f'parameter {k}')}" for k, v in params.items()]
    order = None if min_order is None else int(min_order)
    return _parse(method._native.design(str(maximize), args, order, None if per is None else str(per)))


def advise(scene, solver=None, substeps=None, iterations=None, solvers=None):
    """``zcheck advise --scene``: the method and substeps per tick for a
    scene of masses and springs (or modes), checked by simulation.
    ``scene`` is the TOML text (any str holding a newline or ``=``) or the
    path of a scene file.

    With ``solver`` (``"xpbd"``, ``"xpbd_jacobi"`` or ``"soft_step"``), the
    document of ``--solver``: one configuration with ``substeps`` and
    ``iterations``, or without them the search. With ``solvers`` (a list of
    ``"paper"`` and solver names), the table of ``--solvers``."""
    families = list(solvers or [])
    if isinstance(scene, str) and ("\n" in scene or "=" in scene):
        return _parse(
            _native.advise_text("<scene>", scene, solver, substeps, iterations, families)
        )
    return _parse(
        _native.advise_file(_os.fspath(scene), solver, substeps, iterations, families)
    )


def paper():
    """The claims of ``zcheck paper --format json`` (Hoffmann, "Simple
    Integration Algorithms"): a list of dicts, each with the statement, what
    zcheck derived, the evidence and the verdict."""
    return _parse(_native.paper())["claims"]
